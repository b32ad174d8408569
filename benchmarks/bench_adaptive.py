"""Cost against the wall stiffness n: the package's adaptive step, the fixed step and the
rigid billiard engine on Fig. 8's ensemble (issue 22 item 5).

The fixed-step simulator resolves every wall contact, whose duration shrinks like 1/n, in
every step, so its steps per period grow like n.  :mod:`sinktheory.adaptive` gives each run
its own step from a time-reversible controller on a rate that follows the particles (the
wall's local frequency, the approach to each wall, the crossing of the well); this
measures both, and the rigid billiard (n = inf) from the same starts, in one run, one
thread, best of ``--repeat`` timings of each row::

    python benchmarks/bench_adaptive.py --n 4 10 20 50 100 --eps 0.35 0.25 0.15 \\
        --periods 40 --chart docs/guide/adaptive_cost.png

prints the machine, then per n: steps per period, ms per run-period and the largest
relative energy error of each integrator (and the adaptive controller's resets per
run-period); the table and chart in docs/guide/billiard.rst, "Cost against the wall
stiffness", come from it.  Compilation (a new n: about 20 s for the engine and 15 s for
the adaptive module, cached afterwards) is done before timing.

What the prototype of this step (the file's former self, ``adaptive_prototype.py``) learnt
on the way: a rate of the positions alone (Mikkola-Aarseth time-transformed leapfrog)
must assume a top speed and over-resolves particles resting at a wall (15x the steps at
n = 20); the total wall ratio (the 2n-norm of all walls) hides a second wall approached
while the first dominates (energy jumps of 1e-5); without the crossing term a fast
particle at the centre of a narrow well reaches the wall in one step (NaN at n = 100).
"""

from __future__ import annotations

import argparse
import math
import re

import numba
import numpy as np
from machine import best_of, describe


def _sink(n: int, shape: str):
    from sinktheory import Sink, Well

    return Sink(Well(0.5, 0.3, n, shape=shape), particles=5, mass=0.2)


def _adaptive(n, eps, args, periods, repeat=1):
    """(seconds, steps per period, max |dH|/H0, controller resets per run-period)."""
    from sinktheory import RunSettings
    from sinktheory.simulate import simulate
    from sinktheory.stepsize import PERIOD

    settings = RunSettings(runs=args.runs, periods=periods, seed=0)
    seconds, res = best_of(
        lambda: simulate(
            _sink(n, args.shape),
            settings,
            stepper="adaptive",
            eps=eps,
            energy_bound=1.0,
            progress=False,
        ),  # fmt: skip
        repeat,
    )
    resets = float(re.search(r"\(([0-9.e+-]+) controller resets\)", res.message).group(1))
    return seconds, PERIOD / res.dt, res.max_relative_energy_error, resets


def _fixed(n, args, periods, repeat=1):
    """(seconds, steps per period, max |dH|/H0) of the package's fixed step at tol 1e-8."""
    from sinktheory import RunSettings
    from sinktheory.simulate import simulate

    settings = RunSettings(runs=args.runs, periods=periods, seed=0)
    seconds, res = best_of(
        lambda: simulate(_sink(n, args.shape), settings, tol=1e-8, progress=False), repeat
    )
    return seconds, res.steps_per_period, res.max_relative_energy_error


def _rigid(args, periods, repeat=1):
    """Seconds of the rigid billiard engine (moving container) from the same starts."""
    from sinktheory import RunSettings
    from sinktheory.billiard.convergence import measure

    settings = RunSettings(runs=args.runs, periods=periods, seed=0)
    return best_of(
        lambda: measure(
            args.shape, 0.5, 0.3, math.inf, particles=5, mass=0.2, lyapunov=False, settings=settings
        ),  # fmt: skip
        repeat,
    )[0]


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, nargs="+", default=[4, 10, 20, 50, 100])
    p.add_argument("--eps", type=float, nargs="+", default=[0.25])
    p.add_argument("--shape", default="flat", help="well shape (default flat: Fig. 8)")
    p.add_argument("--chart", help="PNG of ms per run-period against n")
    p.add_argument("--runs", type=int, default=25)
    p.add_argument("--periods", type=int, default=40)
    p.add_argument("--repeat", type=int, default=2, help="timings per row (best is kept)")
    args = p.parse_args(argv)
    numba.set_num_threads(1)
    print(describe(), flush=True)
    work = args.runs * args.periods
    rows = []
    for n in args.n:
        _fixed(n, args, 1)  # compile and warm up
        _adaptive(n, args.eps[0], args, 1)
        fixed = _fixed(n, args, args.periods, args.repeat)
        print(f"fixed    n={n:4d} steps/period={fixed[1]:8d}  max |dH|/H0={fixed[2]:.1e}  "
              f"{1e3 * fixed[0] / work:.3f} ms per run-period", flush=True)  # fmt: skip
        for eps in args.eps:
            wall, steps, err, resets = _adaptive(n, eps, args, args.periods, args.repeat)
            print(f"adaptive n={n:4d} eps={eps:.3g} steps/period={steps:8.1f}  max |dH|/H0="
                  f"{err:.1e}  {1e3 * wall / work:.3f} ms per run-period  {resets:.3g} "
                  "controller resets per run-period", flush=True)  # fmt: skip
            rows.append((n, eps, fixed[0] / work, wall / work, fixed[2], err))
    _rigid(args, 1)
    rigid = _rigid(args, args.periods, args.repeat) / work
    print(f"rigid billiard engine: {1e3 * rigid:.3f} ms per run-period", flush=True)
    if args.chart:
        _chart(args.chart, rows, rigid)


def _chart(path, rows, rigid) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.5, 4.2), layout="constrained")
    ns = sorted({r[0] for r in rows})
    fixed = [next(r[2] for r in rows if r[0] == n) for n in ns]
    ax.loglog(ns, 1e3 * np.array(fixed), "o-", label="fixed step (tol 1e-8)")
    for eps in sorted({r[1] for r in rows}):
        sel = [r for r in rows if r[1] == eps]
        ax.loglog([r[0] for r in sel], [1e3 * r[3] for r in sel], "s-",
                  label=f"adaptive, eps {eps:g}")  # fmt: skip
    ax.axhline(1e3 * rigid, color="k", ls="--", label="rigid billiard (n = inf)")
    ax.set_xlabel("wall exponent n")
    ax.set_ylabel("ms per run and period (1 thread)")
    ax.set_title("Fig. 8 ensemble (flat, k = 5): cost against wall stiffness", fontsize=10)
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    print(f"chart: {path}")


if __name__ == "__main__":
    main()
