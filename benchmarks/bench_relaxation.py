"""How fast the sink settles, measured so that the answer does not depend on the number of
runs; and Kac's lemma tested on the returns themselves.

Usage::

    python benchmarks/bench_relaxation.py [--quick] [--sets 40] [--runs 192] [--tol 1e-6]

1. Synthetic runs with a known mean curve 1 + 5 exp(-(t / 700)^0.8) and AR(1) noise
   (standard deviation 2, integrated correlation time 99 samples), 8001 samples
   (windows of 100 samples, 499 bootstrap resamples): over
   ``--sets`` independent sets of 64 runs, whose first 16 and 32 runs give the smaller
   ensembles, the coverage of the 95 % interval of the 5 % settling time (exact: 4722),
   the median interval width, and the mean and spread of the estimates per ensemble
   size.  Then a curve outside the fitted family (two exponentials, tau 200 and 1500):
   how far the fitted crossing lands from the curve's own.
2. Fig. 8 (flat, alpha 0.5, beta 0.3, n 4, m 0.2, E0 0.5), k = 5: ``--runs`` runs x
   8000 periods at ``--tol``, cut into disjoint ensembles of 16, 32 and 64 runs and the
   whole: settling time (* beyond the record), 95 % interval, tau, b, chi2, late z.
3. Kac's lemma for k = 1 on the Fig. 8 well (8 runs, and 32, x 3000 periods after 500,
   as bench_equilibrium.py): the censoring-corrected (Kaplan-Meier) mean return time,
   the mean of the returns seen whole and the occupation against the law's P and 1/P.

``--quick`` uses 4 synthetic sets and 64 runs (figures then only show that it runs).
Wall times depend on the machine's load, printed with them.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np
from scipy import optimize, signal

from sinktheory import RunSettings, Sink, Well
from sinktheory.equilibrium import compare_with_law, equilibrium_law, measure_relaxation
from sinktheory.simulate import simulate

FIG8 = Well(0.5, 0.3, 4)
SIZES = (16, 32, 64)


def synthetic(curve, runs: int, steps: int, rng, phi: float = 0.98, sigma: float = 2.0):
    """Runs with mean 1 + curve(t) and AR(1) noise (correlation time (1+phi)/(1-phi))."""
    t = np.arange(steps)
    noise = signal.lfilter([1.0], [1.0, -phi], rng.standard_normal((runs, steps)), axis=1)
    return 1 + curve(t) + sigma * math.sqrt(1 - phi**2) * noise


def coverage(curve, exact: float, sets: int, label: str) -> None:
    inside = {R: 0 for R in SIZES}
    widths, estimates, chi2 = ({R: [] for R in SIZES} for _ in range(3))
    t0 = time.perf_counter()
    for seed in range(sets):
        runs = synthetic(curve, 64, 8001, np.random.default_rng(seed))
        for R in SIZES:
            r = measure_relaxation(runs[:R], 1.0, window=100, resamples=499, seed=seed)
            inside[R] += r.settle_low <= exact <= r.settle_high
            widths[R].append(r.settle_high - r.settle_low)
            estimates[R].append(r.settle_time)
            chi2[R].append(r.chi2)
    print(f"   {label}: exact crossing {exact:.0f}; {sets} sets ({time.perf_counter() - t0:.0f} s)")
    print(
        "      R   coverage of 95 %   median width   mean estimate +- se   median   spread"
        "   chi2  beyond the record"
    )
    for R in SIZES:
        est = np.array(estimates[R])
        print(
            f"   {R:4d}   {inside[R] / sets:16.3f}   {np.median(widths[R]):12.0f}   "
            f"{np.mean(est):8.0f} +- {np.std(est, ddof=1) / math.sqrt(sets):<8.0f}"
            f"  {np.median(est):6.0f}  {np.std(est, ddof=1):6.0f}   {np.mean(chi2[R]):4.2f}"
            f"  {np.mean(est > 8000):6.3f}"
        )


def synthetic_tables(sets: int) -> None:
    print(
        "\n1. synthetic runs, 5 % settling time, 95 % run-bootstrap intervals "
        "(windows of 100, 499 resamples)"
    )

    def stretched(t):
        return 5 * np.exp(-((t / 700.0) ** 0.8))

    coverage(stretched, 700 * math.log(5 / 0.05) ** 1.25, sets, "stretched exponential")

    def two(t):
        return 3 * np.exp(-t / 200.0) + 2 * np.exp(-t / 1500.0)

    exact = optimize.brentq(lambda t: two(t) - 0.05, 0, 1e5)
    coverage(two, exact, max(sets // 2, 2), "two exponentials (outside the fitted family)")


def fig8(runs: int, tol: float, seed: int) -> None:
    sink = Sink(FIG8, particles=5, mass=0.2)
    t = time.perf_counter()
    sim = simulate(
        sink,
        RunSettings(container_energy=0.5, runs=runs, periods=8000, seed=seed),
        tol=tol,
        progress=False,
    )
    print(f"\n2. Fig. 8, k = 5: {sim.message} ({time.perf_counter() - t:.0f} s)")
    law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
    print(f"   law's mean {law.mean:.5f}; 5 % of it: {0.05 * law.mean:.5f}")
    print(
        "      R  set   settle   95 % interval    tau (tail)    b (whole)    chi2  late z"
        "  tail from"
    )
    e = sim.container_energy
    for R in sorted({*SIZES, runs}):
        for g in range(runs // R):
            r = measure_relaxation(e[g * R : (g + 1) * R], law.mean, seed=seed)
            print(
                f"   {R:4d}  {g:3d}   {r.settle_time:6.0f}{'*' if r.extrapolated else ' '}  "
                f"{r.settle_low:6.0f} - "
                f"{r.settle_high:<6.0f}  {r.rate_time:5.0f} +- {r.rate_stderr:<4.0f} "
                f"{r.stretch:4.2f} +- {r.stretch_stderr:<5.2f} {r.chi2:5.2f}  {r.late_z:+.2f}"
                f"  {r.tail_start:6.0f}"
            )


def kac(runs: int, seed: int) -> None:
    sink = Sink(FIG8, particles=1, mass=0.2)
    t = time.perf_counter()
    sim = simulate(
        sink, RunSettings(container_energy=0.5, runs=runs, periods=3500, seed=seed), progress=False
    )
    law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
    c = compare_with_law(
        sim.container_energy, law, transient=500, fractions=[0.2, 0.5, 0.8], seed=seed
    )
    print(
        f"\n3. Kac, k = 1: {runs} runs x {c.samples} periods after 500 "
        f"({time.perf_counter() - t:.0f} s)"
    )
    print("   f     P law    occupation        Kac 1/P   censored (KM)     z      seen whole")
    for i, f in enumerate(c.fractions):
        print(
            f"   {f:<4g}  {c.tails[i]:.4f}   {c.occupation[i]:.4f} +- {c.occupation_stderr[i]:.4f}"
            f"   {c.kac_periods[i]:7.3f}   {c.return_time[i]:.3f} +- "
            f"{c.return_time_stderr[i]:<6.3f}"
            f" {c.return_time_z()[i]:+5.2f}  {c.observed_return[i]:.3f} +- "
            f"{c.observed_return_stderr[i]:.3f}"
        )


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--sets", type=int, default=40, help="synthetic sets of 64 runs")
    parser.add_argument("--runs", type=int, default=192, help="Fig. 8 runs (a multiple of 64)")
    parser.add_argument("--tol", type=float, default=1e-6, help="Fig. 8 energy tolerance")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    sets, runs = (4, 64) if args.quick else (args.sets, args.runs)
    print(describe())
    synthetic_tables(sets)
    fig8(runs, args.tol, args.seed)
    for r in (8, 32):
        kac(r, args.seed)


if __name__ == "__main__":
    main()
