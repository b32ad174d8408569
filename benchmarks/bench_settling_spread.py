"""Do measure_relaxation's intervals cover the spread between independent ensembles?

Usage::

    python benchmarks/bench_settling_spread.py [--particles 1] [--n 4] [--ensembles 20]
        [--runs 32] [--periods 3000] [--seed 7]

For Fig. 8's geometry (flat, alpha 0.5, beta 0.3, m = 0.2, E0 = 0.5) with k =
``--particles`` and wall exponent ``--n`` (0: rigid walls, exact billiards), one pool of
``--ensembles`` x ``--runs`` runs from the paper's start (seed ``--seed``) is cut into
disjoint ensembles of ``--runs`` runs, each read like a user's measurement
(sinktheory.equilibrium.prediction.read_settling: 5 % settling time and its 95 %
bootstrap interval, 199 resamples).  The whole pool gives the reference settling time.

Printed: each ensemble's settling time and interval; how many intervals hold the pool's
value (95 % of them should); the spread of ln t_f between ensembles against the standard
error each ensemble quotes (its interval's width in ln over 2 x 1.96; a ratio near 1 when
the intervals are honest); and, for each run, its mean E_c over the record's second half
against the law's mean (how unequal the runs are: a few runs far above the law carry the
slow tail).
"""

from __future__ import annotations

import argparse
import math
import sys
import time

import numpy as np


def pool(k: int, n: int, runs: int, periods: int, seed: int):
    """(container energies (runs, periods + 1), the law's mean <E_c>) of the pool."""
    from sinktheory.model import RunSettings, Sink, Well

    settings = RunSettings(container_energy=0.5, runs=runs, periods=periods, seed=seed)
    if n == 0:
        from sinktheory.billiard import billiard

        r = billiard("flat", 0.5, 0.3, particles=k, mass=0.2, settings=settings)
        return r.container_energy, float(np.mean(r.total_energy[:, 0])) / (k + 1)
    from sinktheory.equilibrium import equilibrium_law
    from sinktheory.simulate import simulate

    sink = Sink(Well(0.5, 0.3, n), particles=k, mass=0.2)
    sim = simulate(sink, settings, tol=1e-6, progress=False)
    return sim.container_energy, equilibrium_law(sink, float(np.mean(sim.initial_energy))).mean


def ln_se(r) -> float:
    """Standard error of ln t_f from the 95 % interval (inf when open)."""
    if r.settle_low <= 0 or not math.isfinite(r.settle_high):
        return math.inf
    return (math.log(r.settle_high) - math.log(r.settle_low)) / (2 * 1.96)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--particles", type=int, default=1)
    parser.add_argument("--n", type=int, default=4, help="wall exponent; 0 for rigid walls")
    parser.add_argument("--ensembles", type=int, default=20)
    parser.add_argument("--runs", type=int, default=32)
    parser.add_argument("--periods", type=int, default=3000)
    parser.add_argument("--seed", type=int, default=7)
    args = parser.parse_args()
    sys.path.insert(0, __file__.rsplit("/", 1)[0])
    from machine import describe

    from sinktheory.equilibrium.prediction import read_settling

    print(describe())
    k, R = args.particles, args.runs
    t0 = time.perf_counter()
    ec, target = pool(k, args.n, args.ensembles * R, args.periods, args.seed)
    name = f"n = {args.n}" if args.n else "n = oo (billiard)"
    print(
        f"Fig. 8's table, k = {k}, m = 0.2, {name}: {args.ensembles} x {R} runs x "
        f"{args.periods} periods (seed {args.seed}) in {time.perf_counter() - t0:.0f} s"
    )
    whole = read_settling(ec, target)
    print(
        f"pool of {ec.shape[0]} runs: settles at {whole.settle_time:.0f} "
        f"({whole.settle_low:.0f}-{whole.settle_high:.0f}), tail time {whole.rate_time:.0f}, "
        f"stretch {whole.stretch:.2f}, tail chi2 {whole.chi2:.2f}"
    )
    found = [read_settling(ec[i * R : (i + 1) * R], target) for i in range(args.ensembles)]
    for i, r in enumerate(found):
        print(
            f"  ensemble {i:2d}: {r.settle_time:6.0f} ({r.settle_low:.0f}-{r.settle_high:.0f})"
            f"{'*' if r.extrapolated else ''}  tail chi2 {r.chi2:.2f}"
        )
    inside = sum(r.settle_low <= whole.settle_time <= r.settle_high for r in found)
    logs = np.log([max(r.settle_time, 1.0) for r in found])
    quoted = np.median([ln_se(r) for r in found])
    print(f"intervals holding the pool's value: {inside} of {len(found)}")
    print(
        f"ln t_f between ensembles: sd {logs.std(ddof=1):.3f}; quoted se (median) "
        f"{quoted:.3f}; ratio {logs.std(ddof=1) / quoted:.2f}"
    )
    late = (ec[:, ec.shape[1] // 2 :].mean(axis=1) - target) / target
    q = np.quantile(late, [0.1, 0.5, 0.9])
    print(
        f"runs' late-half excess over the law: 10/50/90 % quantiles {q[0]:+.2f} "
        f"{q[1]:+.2f} {q[2]:+.2f}; runs above +0.5: {int(np.sum(late > 0.5))} of {late.size}"
    )


if __name__ == "__main__":
    main()
