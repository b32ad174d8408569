"""Ergodicity maps over the beta ranges of Figs. 3 and 11: the chart and table of the
equilibrium guide, with the Lyapunov runs split into regular and chaotic ones.

    python docs/guide/make_ergodicity.py [--quick] [--seed 1] [--out DIR]

Three panels: Fig. 3 (flat well, alpha = 0.5, n = 2 and n = 10, beta in [-0.7, 0.45]) and
Fig. 11 (symmetric, alpha = 1, n = 6, the confining beta); k = 1, m = 0.2, E0 = 0.5, 12
beta per panel (a 0.01 margin from the edges of validity).  At each beta
(:func:`sinktheory.equilibrium.ergodicity.ergodicity_map`): 8 runs x 2000 periods, the
first 500 left out, against the exact law (KS distance and p-value, verdict 2 / 1 / 0),
and lambda_1 from 8 runs x 200 periods started in the same box.  The Lyapunov runs are
split run by run (:func:`sinktheory.chaos.verdicts.split`: regular when lambda_1 <=
3 ln t / t = 0.017 at t = 200 T): a point whose runs split is given as its regular count
and each group's lambda_1, since its mean lambda_1 is set by how many runs start in an
island.

Writes into DIR (default: this folder) ``ergodicity.png`` (the charts; crosses mark each
group's lambda_1 where a point is mixed) and ``ergodicity.inc`` (the table, included by
equilibrium.rst), with the machine's description.  About 12 minutes of CPU (36 points);
``--quick`` divides the periods by 10 and writes nothing unless --out is given.  A point
the toolkit refuses is listed under the table with its reason; a point whose start box
would put its runs on different energy shells (beta = 0.99 of Fig. 11, next to the
corner saddle) runs in the largest box that does not, noted under the table.
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "benchmarks"))

from machine import describe  # noqa: E402

from sinktheory.equilibrium.ergodicity import ErgodicityMap, ergodicity_map  # noqa: E402
from sinktheory.equilibrium.lifetime import one_shell_box  # noqa: E402
from sinktheory.errors import ParameterError  # noqa: E402
from sinktheory.model import RunSettings, Sink, Well, confining_betas  # noqa: E402
from sinktheory.runstats import plus_minus  # noqa: E402

PANELS = [
    ("Fig. 3a, flat, n = 2", {"alpha": 0.5, "n": 2, "shape": "flat"}, (-0.7, 0.45)),
    ("Fig. 3b, flat, n = 10", {"alpha": 0.5, "n": 10, "shape": "flat"}, (-0.7, 0.45)),
    ("Fig. 11, symmetric, n = 6", {"alpha": 1.0, "n": 6, "shape": "symmetric"}, (-0.6, 1.0)),
]
#: Points per panel, shared among the confining intervals in proportion to their length.
POINTS = 12
RUN = dict(runs=8, periods=2000, transient=500, lyapunov_runs=8, lyapunov_periods=200)
#: The start box (particles at rest, uniform in (-box, box)^2), except where it would put
#: the runs on different energy shells (then the largest box that does not,
#: :func:`sinktheory.equilibrium.lifetime.one_shell_box`, noted under the table).
RUN_BOX = 0.01


def betas_of(well: dict, lo: float, hi: float) -> np.ndarray:
    """POINTS betas over the confining part of [lo, hi], 0.01 from its edges."""
    valid = confining_betas(well["alpha"], well["n"], 0.5, shape=well["shape"], lo=lo, hi=hi)
    total = sum(b - a for a, b in valid)
    return np.concatenate(
        [np.linspace(a + 0.01, b - 0.01, max(2, round(POINTS * (b - a) / total))) for a, b in valid]
    )


def join(maps: list) -> ErgodicityMap:
    """One map from single-beta maps of the same set-up (in order)."""
    first = maps[0]
    return dataclasses.replace(first, **{
        f.name: np.concatenate([getattr(m, f.name) for m in maps])
        for f in dataclasses.fields(first) if f.name not in ("fractions", "parameters")
    })  # fmt: skip


def rows_of(name: str, m) -> list[tuple[str, ...]]:
    """One table row per beta: KS, p, mean lambda_1, and the split of its runs."""
    runs = int(m.parameters["lyapunov_runs"])
    out = []
    for j, beta in enumerate(m.beta):
        reg = int(m.regular_runs[j])
        out.append((
            name if j == 0 else "", f"{beta:.3f}", f"{m.ks_distance[j]:.3f}",
            f"{m.ks_pvalue[j]:.3f}", plus_minus(m.lambda1[j], m.lambda1_se[j], ".3f", ".1g"),
            f"{reg} of {runs}",
            plus_minus(m.lambda1_regular[j], m.lambda1_regular_se[j], ".4f", ".1g")
            if reg else "",
            plus_minus(m.lambda1_chaotic[j], m.lambda1_chaotic_se[j], ".3f", ".1g")
            if reg < runs else "",
            str(int(m.verdict[j])),
        ))  # fmt: skip
    return out


def table(rows: list[tuple[str, ...]], machine: str, seed: int, scale: float) -> str:
    head = ("panel", "beta", "KS", "p", "mean lambda_1", "regular runs", "regular lambda_1",
            "chaotic lambda_1", "verdict")  # fmt: skip
    widths = [max(len(r[i]) for r in [head, *rows]) for i in range(len(head))]
    rule = "  ".join("=" * w for w in widths)

    def line(r):
        return "  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()

    return "\n".join([
        f".. Written by docs/guide/make_ergodicity.py (seed {seed}, periods x {scale:g}) on "
        f"{machine}", "", rule, line(head), rule, *map(line, rows), rule, "",
    ])  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    scale = 0.1 if args.quick else 1.0
    out = Path(args.out) if args.out else (None if args.quick else HERE)
    machine = describe()
    print(machine, flush=True)
    run = {**RUN, "periods": int(RUN["periods"] * scale),
           "transient": int(RUN["transient"] * scale)}  # fmt: skip
    maps, rows, notes = [], [], []
    for name, well, (lo, hi) in PANELS:
        t = time.perf_counter()
        done, refused = [], []
        for beta in betas_of(well, lo, hi):  # one point at a time: a refusal is reported
            try:
                done.append(ergodicity_map([beta], seed=args.seed, progress=False, box=RUN_BOX,
                                           **run, **well))  # fmt: skip
            except ParameterError as error:
                if error.name != "box":
                    refused.append(f"{name}, beta = {beta:.3f}: refused ({error})")
                    continue
                # the box reaches high up the well: start in the largest box that keeps
                # the runs on one energy shell, and say so
                sink = Sink(Well(well["alpha"], beta, well["n"], shape=well["shape"]))
                box = one_shell_box(sink, RunSettings(box=RUN_BOX))
                done.append(ergodicity_map([beta], seed=args.seed, progress=False, box=box,
                                           **run, **well))  # fmt: skip
                refused.append(f"{name}, beta = {beta:.3f}: start box {box:.3g}, since the "
                               f"default {RUN_BOX:g} was refused ({error})")  # fmt: skip
        m = join(done)
        maps.append((name, m))
        rows += rows_of(name, m)
        notes += refused
        print(f"{name}: {time.perf_counter() - t:.0f} s", *refused, sep="\n", flush=True)
    text = table(rows, machine, args.seed, scale) + "".join(f"\n{n}\n" for n in notes)
    print(text)
    if out is None:
        return
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from sinktheory.plot.equilibrium import plot_ergodicity

    fig = Figure(figsize=(4.6 * len(maps), 5.0), layout="constrained")
    axes = fig.subplots(2, len(maps), sharex="col")
    for j, (name, m) in enumerate(maps):
        plot_ergodicity(m, ax=(axes[0, j], axes[1, j]))
        axes[0, j].set_title(name, fontsize=9)
    fig.savefig(out / "ergodicity.png", dpi=80)
    (out / "ergodicity.inc").write_text(text)
    print(f"wrote {out / 'ergodicity.png'} and {out / 'ergodicity.inc'}")


if __name__ == "__main__":
    main()
