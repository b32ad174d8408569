"""The cubic NES's threshold as a convention: the figures of the comparison guide.

    python docs/guide/make_nes_threshold.py [--quick] [--out DIR]

The guide's cubic NES (mass 0.2 on the line of the flat well alpha = 0.5, beta = 0.3,
n = 2: k3 = 625; dashpot c on the relative velocity) after an impulse E0 on the container.
Prints, and writes into DIR (default: this folder) as ``nes_threshold.inc`` with the chart
``../nes_windows.png`` beside it (the figure goes to docs/, where PNGs are kept):

1. the averaged flow's energies (:mod:`sinktheory.compare.threshold`): the fold of the
   slow invariant manifold at each c, the 1/2 crossing of the particle's largest share
   (the convention), where that share rises most steeply, and where it peaks (full
   exchange); the NNM backbone's localisation energy (:mod:`sinktheory.nnm.backbone`);
2. the fraction of E0 dissipated in a window of P periods on a fine grid of E0
   (:func:`sinktheory.attachments.impulse_response`, 4 runs per energy, seeded start
   offsets of 1 % of the amplitude): the Lanchester floor 1 - exp(-c P T), the plateau
   (the largest fraction on the grid), every energy where the fraction crosses half-way
   between them (the measured threshold: the first and last crossing bound it), and how
   many grid energies between the first crossing and the conventional threshold lie
   above half-way (captured within the window).

The full run takes about a minute on two cores (plus the kernels' compilation);
--quick takes seconds and writes nothing unless --out is given.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "benchmarks"))

from machine import describe  # noqa: E402

from sinktheory.attachments import Attachment, impulse_response  # noqa: E402
from sinktheory.compare.threshold import (  # noqa: E402
    averaged_share,
    fold_energy,
    full_exchange_energy,
    half_share_energy,
)
from sinktheory.nnm.backbone import inphase_backbone, localisation_energy  # noqa: E402

MU = 0.2
T = 2 * math.pi
#: Windows (periods) and dashpots measured; the guide's c is 0.002.
FULL = {
    "grid": (5e-6, 1.2e-4, 121),
    "runs": 4,
    "windows": (20, 100, 300),
    "dampings": (0.001, 0.002),
}
QUICK = {"grid": (1e-5, 8e-5, 9), "runs": 2, "windows": (20, 100), "dampings": (0.002,)}


def crossings(energies: np.ndarray, fraction: np.ndarray, level: float) -> list[float]:
    """Every energy where the fraction crosses ``level`` upwards (log-linear interpolation).

    Examples
    --------
    >>> x = crossings(np.array([1.0, 2.0, 4.0, 8.0]), np.array([0.0, 1.0, 0.0, 1.0]), 0.5)
    >>> [round(e, 6) for e in x]  # the geometric midpoints of the rising intervals
    [1.414214, 5.656854]
    """
    out = []
    for i in np.nonzero((fraction[:-1] < level) & (fraction[1:] >= level))[0]:
        x = np.log(energies[i : i + 2])
        out.append(float(np.exp(np.interp(level, fraction[i : i + 2], x))))
    return out


def window_scan(att, energies, c, periods, runs):
    """Mean fraction dissipated per energy (runs' spread is below 1e-2 here)."""
    return np.array([
        impulse_response(att, e, damping=c, periods=periods, runs=runs, tol=1e-6)
        .fraction_dissipated().mean()
        for e in energies
    ])  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="a coarse grid (seconds)")
    ap.add_argument("--out", help="directory for the .inc (default: this folder)")
    args = ap.parse_args()
    f = QUICK if args.quick else FULL
    out = Path(args.out) if args.out else (None if args.quick else HERE)
    machine = describe()
    print(machine, flush=True)
    start = time.perf_counter()

    att = Attachment("nes", n=2, mass=MU)
    k3 = att.well.gamma / att.clearance**4
    e_half = half_share_energy(MU, k3)
    grid = np.geomspace(e_half / 3, 10 * e_half, 400)
    share = averaged_share(MU, k3, grid)
    slope = np.diff(share) / np.diff(np.log(grid))
    e_steep = float(np.sqrt(grid[:-1] * grid[1:])[np.argmax(slope)])
    e_full, s_full = full_exchange_energy(MU, k3)
    e_loc = localisation_energy(inphase_backbone(att.sink, 1e-5, 1e-3, steps=100, ds=0.6))
    folds = {c: fold_energy(MU, k3, c) for c in f["dampings"]}
    below = grid < e_half
    estimates = [
        ("fold of the slow invariant manifold, c = "
         + ", ".join(f"{c:g}: {e:.3g}" for c, e in folds.items()), min(folds.values())),
        (f"largest share 1/2 (the convention; share {share[below][-1]:.2f} just below)", e_half),
        (f"steepest rise of the largest share ({slope.max():.2f} per unit ln E)", e_steep),
        ("NNM backbone half in the container (localisation)", e_loc),
        (f"full exchange: the largest share peaks ({s_full:.4f})", e_full),
    ]  # fmt: skip
    for what, e in estimates:
        print(f"  {e:.3g}  {what}", flush=True)

    energies = np.geomspace(*f["grid"])
    rows, curves = [], {}
    for c in f["dampings"]:
        for periods in f["windows"]:
            t0 = time.perf_counter()
            frac = window_scan(att, energies, c, periods, f["runs"])
            curves[c, periods] = frac
            floor = 1 - math.exp(-c * periods * T)
            plateau = float(frac.max())
            level = 0.5 * (floor + plateau)
            cross = crossings(energies, frac, level)
            # between the first half-way crossing and the convention: how often above it
            span = (energies >= cross[0]) & (energies < e_half) if cross else energies < 0
            above = int(np.sum(span & (frac >= level)))
            best = int(np.argmax(np.where(energies < e_half, frac, -1)))
            rows.append([
                f"{c:g}", str(periods), f"{floor:.3f}", f"{plateau:.3f}",
                (f"{cross[0]:.3g}" if len(cross) == 1 else
                 f"{len(cross)}: {cross[0]:.3g} .. {cross[-1]:.3g}" if cross else "none"),
                f"{above} of {int(span.sum())}" if span.any() else "--",
                f"{frac[best]:.2f} at {energies[best]:.3g}",
            ])  # fmt: skip
            print("  ".join(rows[-1]), f"({time.perf_counter() - t0:.0f} s)", flush=True)
    total = time.perf_counter() - start
    print(f"total: {total:.0f} s", flush=True)
    if out is None:
        return

    from matplotlib.figure import Figure

    fig = Figure(figsize=(9, 3.6), layout="constrained")
    ax = fig.subplots()
    for (c, periods), frac in curves.items():
        if c != 0.002:
            continue
        line = ax.plot(energies, frac, marker=".", ms=3, lw=0.8, label=f"{periods} periods")[0]
        ax.axhline(1 - math.exp(-c * periods * T), color=line.get_color(), lw=0.6, ls=":")
    for (what, e), style in zip(estimates, ("--", "-", "-.", ":", "--"), strict=True):
        ax.axvline(e, color="k", lw=0.7, ls=style, label=what.split(",")[0].split(" (")[0])
    ax.set_xscale("log")
    ax.set_xlabel("impulse energy E0")
    ax.set_ylabel("fraction of E0 dissipated")
    ax.set_title("cubic NES, m = 0.2, c = 0.002: dotted lines, the Lanchester floors", fontsize=9)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    figure = HERE.parent / "nes_windows.png" if args.out is None else out / "nes_windows.png"
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=70)
    lines = [
        f"Measured {time.strftime('%Y-%m-%d')} by ``python docs/guide/make_nes_threshold.py`` "
        f"({total:.0f} s): ``{machine}``",
        "",
        ".. list-table:: the averaged flow's energies (m = 0.2, k3 = 625)",
        "   :header-rows: 1",
        "",
        "   * - E0",
        "     - what",
    ]
    for what, e in estimates:
        lines += [f"   * - {e:.3g}", f"     - {what}"]
    lines += [
        "",
        f".. list-table:: the fraction of E0 dissipated in a window, {len(energies)} energies "
        f"{energies[0]:.2g} .. {energies[-1]:.2g} (log grid), {f['runs']} runs each",
        "   :header-rows: 1",
        "",
        "   * - c",
        "     - periods",
        "     - floor 1 - exp(-c t)",
        "     - plateau",
        "     - half-way crossings",
        f"     - grid energies from the first crossing to {e_half:.2g} above half-way",
        f"     - largest fraction below {e_half:.2g}",
    ]
    for row in rows:
        lines += [f"   * - {row[0]}"] + [f"     - {cell}" for cell in row[1:]]
    (out / "nes_threshold.inc").write_text("\n".join(lines) + "\n")
    print(f"wrote {out / 'nes_threshold.inc'} and {figure}")


if __name__ == "__main__":
    main()
