"""Settling times of the set-ups ``sinktheory reproduce`` judges at long times (measured).

The report judges every long-time claim on a run of FACTOR settling times
(:mod:`sinktheory.scenes.horizons`); this script measures the settling time of each set-up
of :data:`~sinktheory.scenes.horizons.SETTLING` (5 % of the law's mean, read off the
fitted tail by :func:`sinktheory.equilibrium.measure_relaxation`, 95 % interval from the
run bootstrap) and prints it beside the stored value, with the machine and the seconds.
Set-ups whose stored value comes from docs/guide/equilibrium.rst (``bench_relaxation.py``,
``bench_equilibrium.py``) are measured too, at this script's runs and periods.

    python benchmarks/bench_horizons.py [--runs 16] [--periods 3000] [--long 12000]
        [--seed S] [--only KEY ...]     (KEY as shape/alpha/beta/n/k, e.g. flat/0.5/0.3/4/3)

``--seed`` sets the ensemble's seed (default: the report's, ``scenes.ensembles.SEED``); a
settling time is stored only when another seed gives an overlapping interval.

``--long`` periods are used for set-ups whose stored settling time exceeds ``--periods``
/ 3 (there a shorter record only extrapolates the crossing).
"""

from __future__ import annotations

import argparse
import time


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    from sinktheory.equilibrium import equilibrium_law, measure_relaxation
    from sinktheory.model import RunSettings, Sink, Well
    from sinktheory.scenes.ensembles import E0, MASS, SEED
    from sinktheory.scenes.horizons import SETTLING, horizon
    from sinktheory.simulate import simulate

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=16)
    parser.add_argument("--periods", type=int, default=3000)
    parser.add_argument("--long", type=int, default=12000)
    parser.add_argument("--seed", type=int, default=SEED)
    parser.add_argument("--only", nargs="+", default=[], metavar="KEY")
    args = parser.parse_args()
    print(describe())
    print(f"seed {args.seed}")
    print(f"{'set-up':<28} {'runs x periods':>15} {'settles at (95 %)':>26} {'stored':>22}"
          f" {'horizon':>8} {'s':>6}")  # fmt: skip
    for key, stored in SETTLING.items():
        name = "/".join(map(str, key))
        if args.only and name not in args.only:
            continue
        shape, alpha, beta, n, k = key
        periods = args.long if 3 * stored.periods > args.periods else args.periods
        start = time.perf_counter()
        sink = Sink(Well(alpha, beta, n, shape=shape), particles=k, mass=MASS)
        settings = RunSettings(container_energy=E0, runs=args.runs, periods=periods, seed=args.seed)
        res = simulate(sink, settings, progress=False)
        law = equilibrium_law(sink, float(res.initial_energy.mean()))
        window = max(10, periods // 120)
        r = measure_relaxation(res.container_energy, law.mean, window=window, resamples=199)
        star = "*" if r.extrapolated else " "
        got = f"{r.settle_time:.0f}{star} ({r.settle_low:.0f}-{r.settle_high:.0f})"
        was = f"{stored.periods} ({stored.low}-{stored.high})"
        print(f"{name:<28} {f'{args.runs} x {periods}':>15} {got:>26} {was:>22} "
              f"{horizon(*key):>8} {time.perf_counter() - start:6.1f}", flush=True)  # fmt: skip
    print("* crossing beyond the record (extrapolated)")


if __name__ == "__main__":
    main()
