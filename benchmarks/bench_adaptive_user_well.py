"""The adaptive step on a user's well, with and without its wall ratios: how much the
ratios (the controller's anticipation of the wall) buy as the wall stiffens.

The elliptic well V = gamma/(2n) ((x/a)^2 + (y/b)^2)^n (a 0.3, b 0.2, gamma 1) with k = 3
particles of mass 0.2, E0 = 0.5: ``--runs`` runs x ``--periods`` periods per seed, for
each n and eps, once with the wall ratio sqrt((x/a)^2 + (y/b)^2) declared and once
without.  Printed per row: the largest relative energy error over the runs, the steps per
period and the controller's resets per run-period (from the run's message), the seconds,
and the machine.  A run that crosses the audit's bound (1e-6) prints FAIL with the
error's message::

    python benchmarks/bench_adaptive_user_well.py                 # seeds 1 2, n 4 10 30
    python benchmarks/bench_adaptive_user_well.py --n 100 --eps 0.1

The figures in docs/guide/user_wells.rst ("In the engine") come from it.  The first use
of each variant compiles the well's engine and adaptive module (about a minute each).
"""

from __future__ import annotations

import argparse
import time

from machine import describe

ELLIPTIC = "gamma/(2*n) * ((x/a)**2 + (y/b)**2)**n"
RATIO = "sqrt((x/a)**2 + (y/b)**2)"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[4, 10, 30])
    parser.add_argument("--eps", type=float, nargs="+", default=[0.25, 0.1])
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--runs", type=int, default=8)
    parser.add_argument("--periods", type=int, default=50)
    args = parser.parse_args()

    from sinktheory import RunSettings, Sink
    from sinktheory.adaptive import simulate_adaptive
    from sinktheory.errors import NumericalError
    from sinktheory.userwell import UserWell
    from sinktheory.wellat import WellAt

    print(describe())
    params = {"a": 0.3, "b": 0.2, "gamma": 1.0, "n": (4, (1, 1000))}
    print("ratios  n     eps   seed  max |dH|/H0  steps/period  resets  seconds")
    for ratios in ([RATIO], []):
        for n in args.n:
            sink = Sink(WellAt(UserWell("elliptic", ELLIPTIC, params, ratios), n=n), 3, 0.2)
            for eps in args.eps:
                for seed in args.seeds:
                    settings = RunSettings(runs=args.runs, periods=args.periods, seed=seed)
                    start = time.perf_counter()
                    head = f"{'yes' if ratios else 'no':6s}  {n:<4d}  {eps:<4g}  {seed:<4d}"
                    try:
                        res = simulate_adaptive(sink, settings, eps=eps, progress=False)
                    except NumericalError as error:
                        print(f"{head}  FAIL {str(error)[:100]}", flush=True)
                        continue
                    words = res.message.split(": ")[1].split()
                    resets = float(words[6].lstrip("("))
                    seconds = time.perf_counter() - start
                    print(f"{head}  {res.max_relative_energy_error:11.2e}  {words[0]:>12s}  "
                          f"{resets:6.3g}  {seconds:7.1f}", flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
