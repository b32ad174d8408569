"""The equilibrium law: its cost and accuracy, and the Fig. 8 runs measured against it.

Usage::

    python benchmarks/bench_equilibrium.py [--quick] [--png FILE]

0. ``sinktheory equilibrium`` for the Fig. 8 well, k = 5, as a fresh process: wall and
   CPU time (best of 3; most of it is Python and numba's import).
1. Cost of a law (flat, circular, symmetric wells; k = 1, 5, 100, 1000); its accuracy is
   the test suite's business (tests/equilibrium/test_equilibrium.py).
2. Fig. 8 set-up (flat, alpha 0.5, beta 0.3, n 4, m 0.2, E0 0.5), k = 1 and 2: 8 runs x
   3000 periods after a transient (500 periods for k = 1, 1500 for k = 2), against the
   law: mean +- error across runs, KS distance and run-bootstrap p-value, occupation of
   {E_c >= f E} against P, mean return times against Kac's 1/P (jackknife z).
3. Relaxation of <E_c>(t) for k = 1..5 (16 runs; 3000 periods, 8000 for k = 5), then
   for k = 3 with one of m, beta, n changed: the 5 % settling time of the fitted
   stretched exponential with its run-bootstrap interval, tau and b
   (:mod:`sinktheory.equilibrium.relaxation`; ``bench_relaxation.py`` for more runs).
4. Kac's predicted return times 1/P(E_c >= f E) for k = 1..5: for which k and f the
   container stays drained longer than 10^4 periods on average.
5. The ergodicity maps over the beta ranges of Figs. 3 and 11 (lambda_1's runs split
   into regular and chaotic ones) are ``docs/guide/make_ergodicity.py``.

``--quick`` divides the periods by 5 (figures then only show that the script runs).
``--png`` writes the lifetime chart (Kac against f for k = 1..5 with the k = 1, 2
measured points).  Wall times depend on the machine's load, printed with them.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import time

import numpy as np

from sinktheory import RunSettings, Sink, Well
from sinktheory.equilibrium import compare_with_law, equilibrium_law, measure_relaxation
from sinktheory.simulate import simulate

FIG8 = Well(0.5, 0.3, 4)


def command_cost() -> None:
    import resource
    import subprocess
    import sys

    cmd = [
        sys.executable,
        "-m",
        "sinktheory",
        "equilibrium",
        "--alpha",
        "0.5",
        "--beta",
        "0.3",
        "--n",
        "4",
        "--particles",
        "5",
    ]
    best_wall, best_cpu = math.inf, math.inf
    for _ in range(3):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t = time.perf_counter()
        subprocess.run(cmd, check=True, capture_output=True)
        wall = time.perf_counter() - t
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
        best_wall, best_cpu = min(best_wall, wall), min(best_cpu, cpu)
    print(
        f"\n0. sinktheory equilibrium (Fig. 8 well, k = 5): wall {best_wall:.2f} s, "
        f"CPU {best_cpu:.2f} s (best of 3)"
    )


def law_costs() -> None:
    print("\n1. cost of a law (wall, best of 3)")
    print(f"   {'well':28s} {'k':>5s} {'ms':>8s}  <E_c>/E")
    wells = [
        ("flat 0.5 0.3 4", FIG8),
        ("circular 0.5 0.3 4", Well(0.5, 0.3, 4, shape="circular")),
        ("symmetric 1 0.1 6", Well(1.0, 0.1, 6, shape="symmetric")),
    ]
    for name, well in wells:
        for k in (1, 5, 100, 1000):
            best = math.inf
            for _ in range(3):
                t = time.perf_counter()
                law = equilibrium_law(Sink(well, particles=k), 0.5)
                best = min(best, time.perf_counter() - t)
            print(f"   {name:28s} {k:5d} {1e3 * best:8.1f}  {law.mean_fraction:.6g}")


def fig8_against_law(k: int, transient: int, periods: int, seed: int):
    sink = Sink(FIG8, particles=k, mass=0.2)
    settings = RunSettings(container_energy=0.5, runs=8, periods=transient + periods, seed=seed)
    t = time.perf_counter()
    sim = simulate(sink, settings, progress=False)
    seconds = time.perf_counter() - t
    law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
    c = compare_with_law(
        sim.container_energy, law, transient=transient, fractions=[0.2, 0.5, 0.8], seed=seed
    )
    print(f"\n2. Fig. 8, k = {k}: {sim.message} ({seconds:.1f} s)")
    print(
        f"   kept {c.runs} x {c.samples} periods after {c.transient}; autocorrelation time "
        f"{c.autocorrelation_time:.3g} +- {c.autocorrelation_time_stderr:.2g} periods, "
        f"{c.effective_samples:.3g} effective samples"
    )
    print(
        f"   <E_c> measured {c.mean:.5f} +- {c.mean_stderr:.5f}; law {law.mean:.5f} "
        f"(z {(c.mean - law.mean) / c.mean_stderr:+.2f}); homogeneous {law.homogeneous_mean:.5f}"
    )
    print(f"   KS distance {c.ks_distance:.4f}, run-bootstrap p-value {c.ks_pvalue:.3f}")
    print("   f     P law     occupation         Kac 1/P   return time        z")
    for i, f in enumerate(c.fractions):
        print(
            f"   {f:<4g}  {c.tails[i]:<8.4f}  {c.occupation[i]:.4f} +- {c.occupation_stderr[i]:.4f}"
            f"   {c.kac_periods[i]:<8.3f}  {c.return_time[i]:.3f} +- {c.return_time_stderr[i]:.3f}"
            f"  {c.return_time_z()[i]:+.2f}"
        )
    return c


#: Relaxation cases: (label, well, k, m, periods); the Fig. 8 well for k = 1..5, then one
#: parameter changed at a time from k = 3 (m, beta, n).
RELAXATION_CASES = [
    *[(f"k={k}", FIG8, k, 0.2, 8000 if k == 5 else 3000) for k in (1, 2, 3, 4, 5)],
    ("k=3 m=0.1", FIG8, 3, 0.1, 3000),
    ("k=3 m=0.4", FIG8, 3, 0.4, 3000),
    ("k=3 beta=0.1", Well(0.5, 0.1, 4), 3, 0.2, 3000),
    ("k=3 beta=-0.3", Well(0.5, -0.3, 4), 3, 0.2, 3000),
    ("k=3 n=10", Well(0.5, 0.3, 10), 3, 0.2, 3000),
]


def relaxation_table(periods_scale: float, seed: int) -> None:
    print(
        "\n3. relaxation of <E_c>(t) to the law's mean (16 runs, windows of 50 periods): "
        "5 % crossing of the fitted tail (* beyond the record), 95 % run-bootstrap interval"
    )
    print(
        f"   {'case':>13s} {'periods':>7s} {'s':>6s}  {'law mean':>9s}  {'settle':>6s} "
        f"{'interval':>13s}  {'tau (fit)':>12s}  {'b':>11s}  {'chi2':>5s}  late z"
    )
    for label, well, k, mass, periods in RELAXATION_CASES:
        periods = int(periods * periods_scale)
        sink = Sink(well, particles=k, mass=mass)
        t = time.perf_counter()
        sim = simulate(
            sink,
            RunSettings(container_energy=0.5, runs=16, periods=periods, seed=seed),
            progress=False,
        )
        seconds = time.perf_counter() - t
        law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
        r = measure_relaxation(sim.container_energy, law.mean, window=50, seed=seed)
        print(
            f"   {label:>13s} {periods:7d} {seconds:6.1f}  {law.mean:9.5f}  "
            f"{r.settle_time:6.0f}{'*' if r.extrapolated else ' '}"
            f"{r.settle_low:6.0f}-{r.settle_high:<6.0f}  "
            f"{r.rate_time:5.0f} +- {r.rate_stderr:<4.0f}  {r.stretch:4.2f} +- "
            f"{r.stretch_stderr:<4.2f}  {r.chi2:5.2f}  {r.late_z:+.2f}"
        )


def kac_table():
    print("\n4. Kac's mean return time 1/P(E_c >= f E) in periods (law; E = 0.5)")
    fractions = [0.3, 0.5, 0.7, 0.8, 0.9]
    print("   k   " + "".join(f"f={f:<9g}" for f in fractions))
    rows = []
    for k in (1, 2, 3, 4, 5):
        kac = equilibrium_law(Sink(FIG8, particles=k), 0.5).kac_periods(fractions)
        rows.append(kac)
        print(f"   {k}   " + "".join(f"{x:<11.4g}" for x in kac))
    held = [
        (k, f)
        for k, row in zip((1, 2, 3, 4, 5), rows, strict=True)
        for f, x in zip(fractions, row, strict=True)
        if x > 1e4
    ]
    print("   longer than 10^4 periods: " + ", ".join(f"k={k} f={f:g}" for k, f in held))


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--png", default=None)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    scale = 0.2 if args.quick else 1.0
    print(
        f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"load {os.getloadavg()[0]:.2f}; python {platform.python_version()}"
    )
    command_cost()
    law_costs()
    measured = []
    for k, transient in ((1, 500), (2, 1500)):
        c = fig8_against_law(k, int(transient * scale), int(3000 * scale), args.seed)
        measured += [
            (k, f, c.return_time[i], c.return_time_stderr[i])
            for i, f in enumerate(c.fractions)
            if np.isfinite(c.return_time[i])
        ]
    relaxation_table(scale, args.seed)
    kac_table()
    if args.png:
        from sinktheory.plot.equilibrium import plot_lifetimes

        grid = np.linspace(0.05, 0.95, 19)
        predicted = [
            equilibrium_law(Sink(FIG8, particles=k), 0.5).kac_periods(grid) for k in (1, 2, 3, 4, 5)
        ]
        plot_lifetimes(grid, [1, 2, 3, 4, 5], predicted, measured).savefig(args.png, dpi=150)
        print(f"\nwrote {args.png}")


if __name__ == "__main__":
    main()
