"""The 1-D absorbers beside the 2-D sink: the chart and table of the comparison guide.

    python docs/guide/make_compare.py [--quick] [--out DIR]

Writes into DIR ``compare.png`` (the fraction of an impulse's
energy dissipated in the window against the initial container energy, with +-2 s.e.
bands, beside the 90 % times), ``compare_wavelet.png`` (wavelet maps of the container
after one impulse, the NES beside the 2-D well with the same wall),
``compare_nes_threshold.png`` (the cubic NES just above its threshold: the ridge over
its in-phase 1:1 backbone) and ``compare.inc``
(the tables included by compare.rst: efficiency and 90 % time per attachment and
energy, where each 2-D well beats each NES by more than 3 combined standard errors and
where it loses, and the machine and timings).  Set-up (:data:`SETUP`): alpha = 1/2,
beta = 0.3 (clearance 0.2), gamma = 1, total particle mass m = 0.2, dashpot c = 0.002
shared by the particles; on the line y = 0 the cubic NES (n = 2), the NES with the
well's own wall (n = 4) and the vibro-impact NES; the flat and symmetric wells with n = 4
and k = 1 or 5 particles; 10 energies from 1e-3 to 1, 8 seeded runs of 300 periods each.
The full run takes about a minute on two cores (plus the engines' compilation the first
time); --quick (3 energies, 2 runs of 30 periods) takes seconds and writes nothing unless
--out is given.  By default the figures go to docs/ (the only folder whose PNGs are kept
in the repository) and the tables to this folder.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "benchmarks"))

from machine import describe  # noqa: E402

from sinktheory.attachments import Attachment  # noqa: E402
from sinktheory.compare.efficiency import attachments_of, compare, energies_of  # noqa: E402
from sinktheory.compare.transfer import backbone, transfer_map  # noqa: E402
from sinktheory.plot.compare import plot_comparison, plot_transfer  # noqa: E402

#: The attachments' common set-up (see the module docstring).
SETUP = {"alpha": 0.5, "beta": 0.3, "n": 4, "nes_n": 2, "mass": 0.2}
DAMPING = 0.002
#: The impulse of the wavelet maps (where the two differ most in the full run).
WAVELET_ENERGY = 0.46
#: The cubic NES's threshold figure: an impulse 4x its threshold, followed this long.
THRESHOLD_ENERGY = 2e-4
THRESHOLD_PERIODS = 150
FULL = {"energies": (1e-3, 1.0, 10), "runs": 8, "periods": 300}
QUICK = {"energies": (1e-2, 1.0, 3), "runs": 2, "periods": 30}
#: A 2-D well beats (loses to) the NES where its efficiency is higher (lower) by more than
#: this many combined standard errors.
SIGMAS = 3.0


def verdicts(c) -> list[str]:
    """For each 2-D well and each NES: the energies where the well dissipates more, and
    where less, by more than :data:`SIGMAS` combined standard errors."""
    lines = []
    for k, nes in enumerate(c.attachment):
        if not nes.startswith("NES"):
            continue
        for i, name in enumerate(c.attachment):
            if not name.startswith("well"):
                continue
            diff = c.efficiency[i] - c.efficiency[k]
            se = np.hypot(c.efficiency_se[i], c.efficiency_se[k])
            win = c.container_energy[diff > SIGMAS * se]
            lose = c.container_energy[diff < -SIGMAS * se]
            lines.append(
                f"{name} against {nes}: more at E0 = {_list(win)}; less at E0 = "
                f"{_list(lose)}; difference {np.min(diff):+.3f} to {np.max(diff):+.3f}"
            )
    return lines


def _list(energies) -> str:
    return ", ".join(f"{e:.3g}" for e in energies) or "none"


def rst_table(head: list[str], rows: list[list[str]]) -> list[str]:
    """A simple reStructuredText table."""
    widths = [max(len(r[k]) for r in [head, *rows]) for k in range(len(head))]
    rule = "  ".join("=" * w for w in widths)

    def line(cells):
        return "  ".join(cell.ljust(w) for cell, w in zip(cells, widths, strict=True)).rstrip()

    return [rule, line(head), rule, *[line(r) for r in rows], rule]


def table(c, seconds: float, machine: str) -> str:
    """The reStructuredText tables of the efficiencies and the 90 % times, the verdicts
    and the machine."""
    head = ["E0", *c.attachment]
    cells = range(len(c.attachment))
    efficiency = [
        [f"{e:.3g}", *(f"{c.efficiency[i, j]:.3f} ± {c.efficiency_se[i, j]:.3f}" for i in cells)]
        for j, e in enumerate(c.container_energy)
    ]

    def t90(i, j):
        if not c.reached[i, j]:
            return "never"
        return f"{c.t90[i, j]:.0f} ({c.reached[i, j]}/{c.runs})"

    times = [[f"{e:.3g}", *(t90(i, j) for i in cells)] for j, e in enumerate(c.container_energy)]
    out = [
        ".. This file is written by docs/guide/make_compare.py; do not edit it by hand.",
        "",
        f"Fraction of the initial energy dissipated in {c.periods} periods (mean ± standard "
        f"error over {c.runs} seeded runs), dashpot c = {c.damping:g}:",
        "",
        *rst_table(head, efficiency),
        "",
        "Periods until 90 % is dissipated (mean over the runs that got there, and how many did):",
        "",
        *rst_table(head, times),
        "",
        f"Verdicts (difference beyond {SIGMAS:g} combined standard errors):",
        "",
        *[f"* {v}" for v in verdicts(c)],
        "",
        f"Largest audit error ``|H + W - H0| / H0``: {float(np.max(c.max_audit_error)):.1g}.  "
        f"Computed in {seconds:.0f} s on: {machine}.",
        "",
    ]
    return "\n".join(out)


def threshold_figure(run):
    """The cubic NES just above its threshold: the wavelet ridge over its in-phase
    backbone, with the energy where that family is half in the container marked."""
    from sinktheory.errors import ParameterError
    from sinktheory.nnm.backbone import localisation_energy

    cubic = Attachment("nes", alpha=SETUP["alpha"], beta=SETUP["beta"], n=SETUP["nes_n"],
                       mass=SETUP["mass"])  # fmt: skip
    start = time.perf_counter()
    periods = THRESHOLD_PERIODS if run is FULL else run["periods"]
    m = transfer_map(cubic, THRESHOLD_ENERGY, damping=DAMPING, periods=periods, seed=1,
                     omega=(0.3, 2.0, 80))  # fmt: skip
    branches, notes = backbone(cubic, 1e-6, 2 * THRESHOLD_ENERGY)
    e_loc = []
    for b in branches:
        if b.meta.get("mode") == "in-phase":
            try:
                e_loc.append(localisation_energy(b))
            except ParameterError:  # a piece that does not reach the half share
                pass
    print(f"cubic NES at E0 = {THRESHOLD_ENERGY:g}: in-phase family half in the container at "
          f"E = {e_loc[0] if e_loc else float('nan'):.3g} "
          f"({time.perf_counter() - start:.0f} s)", *notes, sep="\n")  # fmt: skip
    title = f"cubic NES after an impulse E0 = {THRESHOLD_ENERGY:g}, dashpot c = {DAMPING:g}"
    return plot_transfer([m], [branches], title=title)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a seconds-long smoke run")
    parser.add_argument("--out", default=None, help="folder to write into (default: here)")
    args = parser.parse_args(argv)
    run = QUICK if args.quick else FULL
    out = Path(args.out) if args.out else (None if args.quick else HERE)
    figures = out if args.out else HERE.parent
    machine = describe()
    print(machine)
    atts = attachments_of(
        ["nes", "impact", "well"], shapes=["flat", "symmetric"], particles=[1, 5], **SETUP
    )
    same_wall = Attachment("nes", alpha=SETUP["alpha"], beta=SETUP["beta"], n=SETUP["n"],
                           mass=SETUP["mass"])  # fmt: skip
    atts.insert(1, same_wall)
    start = time.perf_counter()
    c = compare(
        atts,
        energies_of(*run["energies"]),
        damping=DAMPING,
        periods=run["periods"],
        runs=run["runs"],
        seed=1,
    )
    seconds = time.perf_counter() - start
    text = table(c, seconds, machine)
    print(text)
    start = time.perf_counter()
    pair = [same_wall, atts[3]]  # the NES and the flat well k = 1, both n = 4
    energy = WAVELET_ENERGY if not args.quick else 0.1
    maps = [transfer_map(a, energy, damping=DAMPING, periods=run["periods"], seed=1)
            for a in pair]  # fmt: skip
    branches, notes = backbone(same_wall, 1e-3, 2 * energy)
    print(f"wavelet maps and backbone in {time.perf_counter() - start:.0f} s", *notes, sep="\n")
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        plot_comparison(c).savefig(figures / "compare.png", dpi=70)
        title = f"container after an impulse E0 = {energy:g}, dashpot c = {DAMPING:g}"
        plot_transfer(maps, [branches, branches], title=title).savefig(
            figures / "compare_wavelet.png", dpi=60
        )
        threshold_figure(run).savefig(figures / "compare_nes_threshold.png", dpi=60)
        (out / "compare.inc").write_text(text)
        print(f"wrote compare.png, compare_wavelet.png and compare_nes_threshold.png into "
              f"{figures}, compare.inc into {out}")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
