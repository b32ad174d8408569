"""Towards rigid walls: relaxation and the shell's conditional mean at n = 4, 10, 20, oo.

Usage::

    python benchmarks/bench_rigid_limit.py [--particles 3] [--mass 0.2] [--ns 4 10 20 0]
        [--runs 32] [--shell-runs 100] [--seed 0] [--measure-seed 1]

For Fig. 8's geometry (flat, alpha 0.5, beta 0.3), k = ``--particles`` of total mass
``--mass``, E0 = 0.5, and each wall exponent n (0 stands for rigid walls, n = oo: exact
billiards, sinktheory.billiard):

1. The shell: 12 energies x ``--shell-runs`` runs started on the energy shell (soft walls:
   measure_kramers_moyal; rigid: sinktheory.billiard.relaxation.rigid_shell_states, seed
   ``--seed``), recorded at lags 1, 2, 4, ..., 128 periods.  lambda(tau) is the slope of
   the conditional mean of s = E_c / E after tau periods against s(0) (log_lambdas: the
   fraction of a deviation of E_c left after tau), with bootstrap errors.  Beside it the
   kinetic theory of the rigid limit (sinktheory.billiard.kinetic: random impacts, friction
   rate 4 sqrt(2 mu e) W / (pi A) per particle of energy e): the same slope for its
   Fokker-Planck equation on the rigid law, started at the same s.
2. The slow-mode prediction from the lags 16-128 of those same runs (what
   predict_relaxation, and predict_rigid_relaxation for n = oo, return with these seeds),
   beside the settling time measured from the paper's start: ``--runs`` runs (seed
   ``--measure-seed``) over four times the predicted settling time (at least 3000
   periods), read by measure_relaxation; and the kinetic theory's settling time.

Prints the machine, then one block per n.
"""

from __future__ import annotations

import argparse
import math
import sys
import time

import numpy as np
from scipy import stats

from sinktheory.billiard.kinetic import kinetic_coefficients, kinetic_relaxation
from sinktheory.billiard.relaxation import measure_rigid_settling, rigid_shell_increments
from sinktheory.billiard.table import rigid_table
from sinktheory.equilibrium.kramers import measure_kramers_moyal
from sinktheory.equilibrium.law import equilibrium_law
from sinktheory.equilibrium.prediction import (
    law_chain,
    log_lambdas,
    measure_settling,
    shell_lags,
    shell_prediction,
    start_total_energy,
)
from sinktheory.model import Sink, Well

LAGS = [1, 2, 4, 8, 16, 32, 64, 128]
E0, POINTS, RESAMPLES = 0.5, 12, 199


def shell_runs(n, k, m, runs, seed):
    """(s, increments of s (point, lag, run), E, law pdf, law mean) of the shell runs."""
    if n:
        sink = Sink(Well(0.5, 0.3, n), particles=k, mass=m)
        total = start_total_energy(sink, E0, seed)
        law = equilibrium_law(sink, total)
        km = measure_kramers_moyal(sink, total, points=POINTS, lags=LAGS, runs=runs, seed=seed)
        return (km.container_energies / total, km.increments / total, total, law.pdf,
                law.mean_fraction)  # fmt: skip
    s, inc, _ = rigid_shell_increments(rigid_table("flat", 0.5, 0.3), k, m, E0, POINTS, runs,
                                       LAGS, seed)  # fmt: skip
    return s, inc, E0, stats.beta(1, k).pdf, 1 / (k + 1)


def kinetic_lambdas(k, m, s):
    """lambda(tau) of the kinetic Fokker-Planck equation started at the grid's s."""
    table = rigid_table("flat", 0.5, 0.3)
    fine = np.linspace(0.0, 1.0, 201)
    d1 = kinetic_coefficients(table, k, m, E0, E0 * fine)[0] / E0
    chain = law_chain(stats.beta(1, k).pdf, fine, d1, cells=300)
    means = np.array([chain.moments(si, np.array(LAGS, float))[0] for si in s])  # (point, lag)
    return np.array([1 + np.polyfit(s, means[:, j] - s, 1)[0] for j in range(len(LAGS))])


def measured(n, k, m, runs, periods, seed):
    """measure_relaxation of ``runs`` runs from the paper's start."""
    if n:
        return measure_settling(Sink(Well(0.5, 0.3, n), particles=k, mass=m), E0,
                                (runs, periods), seed=seed)[0]  # fmt: skip
    return measure_rigid_settling(
        "flat",
        0.5,
        0.3,
        (runs, periods),
        particles=k,
        mass=m,
        container_energy=E0,
        seed=seed,
        resamples=RESAMPLES,
    )[0]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--particles", type=int, default=3)
    parser.add_argument("--mass", type=float, default=0.2)
    parser.add_argument("--ns", type=int, nargs="+", default=[4, 10, 20, 0])
    parser.add_argument("--runs", type=int, default=32)
    parser.add_argument("--shell-runs", type=int, default=100)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--measure-seed", type=int, default=1)
    args = parser.parse_args()
    sys.path.insert(0, __file__.rsplit("/", 1)[0])
    from machine import describe

    print(describe())
    k, m = args.particles, args.mass
    kin_settle, kin_rate = kinetic_relaxation(rigid_table("flat", 0.5, 0.3), k, m, E0)
    print(
        f"flat, alpha 0.5, beta 0.3, k = {k}, m = {m}, E0 = {E0}; shell: {POINTS} x "
        f"{args.shell_runs} runs, seed {args.seed}; kinetic theory (rigid): settles in "
        f"{kin_settle:.2f} periods, slowest relaxation time {kin_rate:.3f} periods"
    )
    print("lags:           " + " ".join(f"{x:>6d}" for x in LAGS))
    for n in args.ns:
        name = f"n = {n}" if n else "n = oo"
        t0 = time.perf_counter()
        s, inc, total, pdf, mu = shell_runs(n, k, m, args.shell_runs, args.seed)
        t1 = time.perf_counter()
        runs = inc.shape[2]
        spread = np.maximum(inc.std(axis=2, ddof=1), 1e-12) / math.sqrt(runs)
        lam = np.exp(log_lambdas(s, inc, spread))
        rng = np.random.default_rng([args.seed, 2])
        boot = np.exp([log_lambdas(s, np.take_along_axis(
            inc, rng.integers(0, runs, (POINTS, 1, runs)), 2), spread)
            for _ in range(RESAMPLES)])  # fmt: skip
        se = np.nanstd(boot, axis=0, ddof=1)
        print(f"{name:7s} lambda: " + " ".join(f"{x:6.3f}" for x in lam)
              + f"   [{t1 - t0:.0f} s]")  # fmt: skip
        print("        +-      " + " ".join(f"{x:6.3f}" for x in se))
        if n == args.ns[0]:
            print("kinetic lambda: " + " ".join(f"{x:6.3f}" for x in kinetic_lambdas(k, m, s)))
        use = [LAGS.index(x) for x in shell_lags(LAGS[-1])]
        p = shell_prediction(s, inc[:, use], np.array(LAGS)[use], pdf, mu, start=E0,
                             total=total, particles=k, mass=m, lag=LAGS[-1], coefficients="",
                             seed=args.seed)  # fmt: skip
        periods = int(min(max(4 * p.settle_time, 3000), 20000))
        t2 = time.perf_counter()
        r = measured(n, k, m, args.runs, periods, args.measure_seed)
        star = "*" if r.extrapolated else ""
        print(f"        slow mode t_r {p.rate_time:.0f} ({p.rate_low:.0f}-{p.rate_high:.0f}), "
              f"c {p.visible:.2f}; predicted settling {p.settle_time:.0f} "
              f"({p.settle_low:.0f}-{p.settle_high:.0f}){'+' if p.extrapolated else ''}; "
              f"measured {r.settle_time:.0f}{star} ({r.settle_low:.0f}-{r.settle_high:.0f}) "
              f"from {args.runs} x {periods} (seed {args.measure_seed}), ratio "
              f"{p.settle_time / r.settle_time:.2f}  [{time.perf_counter() - t2:.0f} s]",
              flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
