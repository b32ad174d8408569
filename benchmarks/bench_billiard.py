"""Rigid-billiard engine: speed, the published laws at more statistics, and the paper's
billiard analogies (lambda_1 of the rigid limit against beta).

    python benchmarks/bench_billiard.py [--quick] [--plot FILE.png]

Prints (with the machine description):
1. impacts per second of the fixed and moving engines (flat well, alpha 0.5, beta 0.3,
   five particles) and of the Sinai table;
2. the Sinai disk-to-disk exponent at R = 0.1, 0.03, 1e-2, 3e-3, 1e-3 against
   Dahlqvist's -2 ln R + C (Nonlinearity 10, 159 (1997));
3. lambda_1 (fixed container, per unit time at unit speed, and per impact) and the
   moving-container lambda_1 and final <E> for the flat well, alpha = 0.5, beta from
   -0.45 to 0.45: the rigid-limit rows of the paper's billiard analogies (beta > 0
   dispersing, beta < 0 focusing);
4. with --soft, the container's <E> at t = 50 T and 100 T of soft-wall ensembles
   (``simulate``, tol 1e-8) at n = 4, 10, 20, 50 beside the rigid limit, same start
   (flat well, alpha 0.5, beta 0.3, k = 5, m = 0.2, 25 runs; each new n compiles its
   engine once, about a minute);
5. with --islands, the fixed-container rows of item 3 split into regular and chaotic runs
   (:func:`sinktheory.chaos.verdicts.split`) from two start distributions, the package's
   (positions uniform in the start box (-0.01, 0.01)^2 around the centre, seeded random
   directions) and positions uniform over the whole table (same directions): the fraction
   of regular runs and lambda_1 of each group, 200 runs x 300 periods per beta (about a
   minute); the moving container (k = 5) split at 25 runs x 300 periods;
6. with --plot, a PNG of item 3.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import time

import numpy as np
from scipy.special import zeta

from sinktheory.billiard import billiard, rigid_table, simulate_billiard, sinai_table
from sinktheory.billiard.run import start_directions
from sinktheory.chaos.verdicts import split
from sinktheory.model import RunSettings


def machine() -> str:
    return (
        f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, python "
        f"{platform.python_version()}; load average {os.getloadavg()[0]:.1f}"
    )


def directions(runs: int, seed: int = 0) -> np.ndarray:
    a = np.random.default_rng(seed).uniform(0, 2 * np.pi, runs)
    return np.stack([np.cos(a), np.sin(a)], -1)[:, None]


def speed(quick: bool) -> None:
    periods = 200 if quick else 1000
    billiard("flat", 0.5, 0.3, particles=5, settings=RunSettings(runs=1, periods=2))  # compile
    for fixed in (True, False):
        s = RunSettings(runs=10, periods=periods)
        t0 = time.perf_counter()
        r = billiard("flat", 0.5, 0.3, particles=5, settings=s, fixed=fixed, lyapunov=True)
        dt = time.perf_counter() - t0
        n = int(r.collisions.sum())
        print(
            f"  flat 0.5/0.3, k=5, {'fixed ' if fixed else 'moving'} + lambda_1: {n} impacts in "
            f"{dt:.2f} s = {n / dt:.3g} /s; max rel. energy error {r.max_relative_energy_error:.2g}"
        )
    t = sinai_table(0.1)
    pos = np.tile([0.3, 0.2], (10, 1))[:, None]
    t0 = time.perf_counter()
    r = simulate_billiard(t, pos, directions(10), periods=periods, lyapunov=True)
    dt = time.perf_counter() - t0
    n = int(r.collisions.sum())
    print(f"  Sinai R=0.1, tangent map: {n} impacts in {dt:.2f} s = {n / dt:.3g} /s")


def sinai(quick: bool) -> None:
    C = 1 - 4 * math.log(2) + 27 * zeta(3) / (2 * math.pi**2)
    print("   R       lambda/disk impact   +- se     -2 ln R + C    diff    R ln^2 R")
    for R in (0.1, 0.03, 1e-2, 3e-3, 1e-3):
        runs, periods = (8, 2000) if quick else (32, 8000)
        pos = np.tile([0.31, 0.17], (runs, 1))[:, None]
        r = simulate_billiard(
            sinai_table(R),
            pos,
            directions(runs, 1),
            periods=periods,
            lyapunov=True,
            discard=periods // 8,
        )
        disk = r.collisions[:, 2]
        lam = r.logs[:, -1].sum() / disk.sum()
        se = (r.logs[:, -1] / disk).std(ddof=1) / math.sqrt(runs)
        law = -2 * math.log(R) + C
        print(
            f"  {R:<7g} {lam:12.4f}        {se:8.4f}   {law:10.4f}   {lam - law:+.4f}   "
            f"{R * math.log(R) ** 2:.4f}"
        )


def analogies(quick: bool):
    betas = np.linspace(-0.45, 0.45, 7 if quick else 19)
    runs, periods = (8, 100) if quick else (25, 300)
    rows = []
    print("  beta   curvature   lambda fixed (/t)  per impact     lambda moving   <E>(end)")
    for b in betas:
        s = RunSettings(runs=runs, periods=periods)
        f = billiard("flat", 0.5, b, particles=1, settings=s, fixed=True, lyapunov=True)
        m = billiard("flat", 0.5, b, particles=5, settings=s, lyapunov=True)
        lf, lc, lm = f.lambda1, f.lambda1_per_collision, m.lambda1
        e_end = m.container_energy[:, -1]
        rows.append((b, lf.mean(), lf.std() / math.sqrt(runs), lm.mean(), e_end.mean()))
        print(
            f"  {b:+.3f}  {2 * b:+.2f}        {lf.mean():6.3f} +- {rows[-1][2]:.3f}"
            f"   {lc.mean():6.3f}      {lm.mean():6.3f} +- {lm.std() / math.sqrt(runs):.3f}"
            f"   {e_end.mean():.3f}   (fixed runs with lambda < 0.05: "
            f"{int((lf < 0.05).sum())}/{runs})"
        )
    return np.array(rows)


def soft_against_rigid() -> None:
    from sinktheory.model import Sink, Well
    from sinktheory.simulate import simulate

    s = RunSettings(runs=25, periods=100)
    print("   n      <E>(50 T)         <E>(100 T)        seconds")
    for n in (4, 10, 20, 50):
        t0 = time.perf_counter()
        r = simulate(Sink(Well(0.5, 0.3, n), 5, 0.2), s, tol=1e-8, progress=False)
        mean, se = r.ensemble_energy()
        dt = time.perf_counter() - t0
        print(
            f"  {n:<4d}  {mean[50]:.4f} +- {se[50]:.4f}   {mean[100]:.4f} +- {se[100]:.4f}   "
            f"{dt:.0f}"
        )
    t0 = time.perf_counter()
    r = billiard("flat", 0.5, 0.3, particles=5, mass=0.2, settings=s)
    e = r.container_energy
    se = e.std(axis=0, ddof=1) / math.sqrt(len(e))
    print(
        f"  oo    {e[:, 50].mean():.4f} +- {se[50]:.4f}   {e[:, 100].mean():.4f} +- "
        f"{se[100]:.4f}   {time.perf_counter() - t0:.1f}"
    )


def uniform_positions(table, runs: int, seed: int = 0) -> np.ndarray:
    """(runs, 1, 2) positions uniform over the table (rejection from its bounding box)."""
    rng = np.random.default_rng([seed, 33])
    bx, by = table.box
    out = []
    while len(out) < runs:
        x, y = rng.uniform(-bx, bx), rng.uniform(-by, by)
        if table.contains(x, y):
            out.append((x, y))
    return np.array(out)[:, None]


def _groups(s) -> str:
    def pm(m, se):
        return "--" if np.isnan(m) else f"{m:.4f} +- {se:.4f}"

    return (
        f"{s.regular:4d}/{s.runs} regular ({100 * s.fraction:4.1f} +- {100 * s.fraction_se:.1f} "
        f"%)  regular {pm(s.regular_mean, s.regular_se)}  chaotic "
        f"{pm(s.chaotic_mean, s.chaotic_se)}  gap {s.gap[0]:.3g} .. {s.gap[1]:.3g}"
    )


def islands(quick: bool) -> None:
    runs, periods = (40, 150) if quick else (200, 300)
    betas = (-0.45, -0.3, -0.1, 0.0, 0.1, 0.3, 0.45)
    cut = split([1.0], periods).threshold
    print(f"  fixed container, one particle, speed sqrt(2 E0 / m) = 2.236; {runs} runs x "
          f"{periods} periods; regular: lambda_1 <= 3 ln t / t = {cut:.4f}")  # fmt: skip
    for b in betas:
        s = RunSettings(runs=runs, periods=periods)
        box = billiard("flat", 0.5, b, particles=1, settings=s, fixed=True, lyapunov=True)
        table = rigid_table("flat", 0.5, b)
        speed = math.sqrt(2 * s.container_energy / 0.2)
        whole = simulate_billiard(table, uniform_positions(table, runs),
                                  speed * start_directions(s, 1), periods=periods,
                                  lyapunov=True)  # fmt: skip
        print(f"  {b:+.2f}  box 0.01: {_groups(split(box.lambda1, periods))}", flush=True)
        print(f"         table:    {_groups(split(whole.lambda1, periods))}", flush=True)
    print("  moving container, k = 5, m = 0.2, E0 = 0.5 (two trajectories)")
    for b in (-0.45, -0.3, -0.1, 0.0):
        s = RunSettings(runs=8 if quick else 25, periods=periods)
        m = billiard("flat", 0.5, b, particles=5, settings=s, lyapunov=True)
        print(f"  {b:+.2f}  box 0.01: {_groups(m.split())}", flush=True)


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="fewer runs (a minute)")
    p.add_argument("--soft", action="store_true", help="also soft-wall ensembles (minutes)")
    p.add_argument("--islands", action="store_true",
                   help="only item 5: regular and chaotic runs of the fixed table")  # fmt: skip
    p.add_argument("--plot", help="write the lambda_1(beta) chart to FILE.png")
    a = p.parse_args()
    if a.islands:
        print("5. regular and chaotic runs, flat rigid table, alpha = 0.5, two start distributions")
        islands(a.quick)
        return
    print(f"Machine: {machine()}")
    print("1. speed")
    speed(a.quick)
    print("2. Sinai billiard, exponent per disk collision (disk-to-disk map)")
    sinai(a.quick)
    print(
        "3. flat rigid table, alpha = 0.5: fixed container (one particle, speed from "
        "E0 = 0.5, m = 0.2) and moving (k = 5, m = 0.2, E0 = 0.5)"
    )
    rows = analogies(a.quick)
    if a.soft:
        print("4. soft walls against the rigid limit: container energy, flat 0.5/0.3, k = 5")
        soft_against_rigid()
    if a.plot:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(6, 4), layout="constrained")
        ax = fig.subplots()
        ax.errorbar(rows[:, 0], rows[:, 1], rows[:, 2], marker="o", label="fixed container")
        ax.plot(rows[:, 0], rows[:, 3], marker="s", label="moving container (k = 5)")
        ax.set_xlabel(r"$\beta$")
        ax.set_ylabel(r"$\lambda_1$ per unit time")
        ax.set_title(r"rigid flat table, $\alpha = 0.5$")
        ax.legend()
        fig.savefig(a.plot, dpi=120)
        print(f"wrote {a.plot}")


if __name__ == "__main__":
    main()
