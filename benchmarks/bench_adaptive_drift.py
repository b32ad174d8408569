"""Long runs of the adaptive step: does its energy error stay within the bound over 10^4
periods (issue 34 item 4), and what does it cost against the fixed step at the same
accuracy?

For each wall exponent n, particle count k and eps, ``--runs`` runs of Fig. 8's well
(flat, alpha 0.5, beta 0.3, m 0.2, E0 0.5, seed 0) go ``--periods`` periods with the
adaptive step, in two legs (the first tenth, then the rest continued from its final
state, which continues exactly), with the audit's bound lifted so that every run
finishes.  Printed per row: the largest relative energy error of every run after the
first leg and after all periods (their growth is the drift), the steps per period,
the controller's resets per run-period and the seconds (one thread).  The fixed step is
timed on the same starts over ``--fixed-periods`` periods at the tolerances ``--tol``
(its error is bounded, so a short run shows it); the cheapest one whose error is below the
adaptive step's is the alternative at the same accuracy::

    python benchmarks/bench_adaptive_drift.py                      # n 4 10 100, k 5
    python benchmarks/bench_adaptive_drift.py --n 4 --particles 1  # the command's default k

The figures in docs/guide/billiard.rst ("Long runs") come from it.
"""

from __future__ import annotations

import argparse
import re
import time

import numba
import numpy as np
from machine import describe

BOUND = 1e-6  # the audit's default bound (sinktheory.ensemble.ENERGY_BOUND)


def _sink(n: int, k: int):
    from sinktheory import Sink, Well

    return Sink(Well(0.5, 0.3, n), particles=k, mass=0.2)


def _adaptive(n, k, eps, args):
    """(seconds, max error after the first leg, per-run max errors at the end, steps per
    period, resets per run-period)."""
    from sinktheory import RunSettings
    from sinktheory.simulate import simulate

    sink, first = _sink(n, k), max(1, args.periods // 10)
    common = {"stepper": "adaptive", "eps": eps, "energy_bound": 1.0, "progress": False,
              "record": ("final",)}  # fmt: skip
    t0 = time.perf_counter()
    a = simulate(sink, RunSettings(runs=args.runs, periods=first, seed=args.seed), **common)
    b = simulate(sink, RunSettings(runs=args.runs, periods=args.periods - first),
                 initial_state=a.final_state, **common)  # fmt: skip
    seconds = time.perf_counter() - t0
    steps = (first * 2 * np.pi / a.dt + (args.periods - first) * 2 * np.pi / b.dt) / args.periods
    resets = [float(re.search(r"\(([0-9.e+-]+) controller resets\)", r.message).group(1))
              for r in (a, b)]  # fmt: skip
    resets = (resets[0] * first + resets[1] * (args.periods - first)) / args.periods
    return seconds, a.max_relative_energy_error, b.run_errors, steps, resets


def _fixed(n, k, tol, args):
    """(seconds, max error, steps per period) of the fixed step at ``tol``."""
    from sinktheory import RunSettings
    from sinktheory.simulate import simulate

    settings = RunSettings(runs=args.runs, periods=args.fixed_periods, seed=args.seed)
    t0 = time.perf_counter()
    res = simulate(_sink(n, k), settings, tol=tol, energy_bound=1.0, progress=False,
                   record=("final",))  # fmt: skip
    return time.perf_counter() - t0, res.max_relative_energy_error, res.steps_per_period


def main(argv=None) -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, nargs="+", default=[4, 10, 100])
    p.add_argument("--particles", type=int, nargs="+", default=[5])
    p.add_argument("--eps", type=float, nargs="+", default=[0.25])
    p.add_argument("--runs", type=int, default=8)
    p.add_argument("--periods", type=int, default=10_000)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--fixed-periods", type=int, default=200)
    p.add_argument("--tol", type=float, nargs="*", default=[1e-8, 1e-6, 1e-4],
                   help="tolerances of the fixed step to time (empty: none)")  # fmt: skip
    args = p.parse_args(argv)
    numba.set_num_threads(1)
    print(describe(), flush=True)
    print(f"{args.runs} runs x {args.periods} periods (adaptive), {args.fixed_periods} "
          f"(fixed); seed {args.seed}; one thread", flush=True)  # fmt: skip
    for n in args.n:
        for k in args.particles:
            for tol in args.tol:
                _fixed(n, k, tol, argparse.Namespace(**{**vars(args), "fixed_periods": 1}))
            fixed = [(tol, *_fixed(n, k, tol, args)) for tol in args.tol]
            for tol, sec, err, steps in fixed:
                ms = 1e3 * sec / (args.runs * args.fixed_periods)
                print(f"  fixed    n={n:3d} k={k} tol={tol:.0e}: {steps:6d} steps/period, "
                      f"{ms:.3f} ms per run-period, max |dH|/H0 {err:.1e}", flush=True)  # fmt: skip
            for eps in args.eps:
                _adaptive(n, k, eps, argparse.Namespace(**{**vars(args), "periods": 2}))
                sec, early, errs, steps, resets = _adaptive(n, k, eps, args)
                ms = 1e3 * sec / (args.runs * args.periods)
                worst = float(errs.max())
                verdict = "holds" if worst <= BOUND else "FAILS"
                print(f"  adaptive n={n:3d} k={k} eps={eps:g}: {steps:6.0f} steps/period, "
                      f"{ms:.3f} ms per run-period, {resets:.3g} resets per run-period; "
                      f"max |dH|/H0 {early:.2e} after {max(1, args.periods // 10)} periods, "
                      f"{worst:.2e} after {args.periods} (median run {np.median(errs):.1e}): "
                      f"{verdict} the bound {BOUND:g}", flush=True)  # fmt: skip
                same = [f for f in fixed if f[2] <= worst]
                if same:
                    tol, fsec, ferr, fsteps = min(same, key=lambda f: f[1])
                    fms = 1e3 * fsec / (args.runs * args.fixed_periods)
                    print(f"    at the same accuracy: fixed step tol {tol:.0e} ({ferr:.1e}) "
                          f"{fms:.3f} ms, adaptive {ms:.3f} ms per run-period: "
                          f"{fms / ms:.2g}x", flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
