"""The rigid billiard's work estimate against its work, over the container energy E0.

:func:`sinktheory.billiard.run.flight_seconds` prices the runs by the collisions a
particle of speed sqrt(2 E0 / m) is expected to have (the table's mean free path) and by
every particle's periods (:data:`~sinktheory.billiard.run.BILLIARD_SECONDS`).  This script
times :func:`sinktheory.billiard.billiard` (flat table alpha 0.5, beta 0.3, 2 runs) for
fixed and moving containers, k = 1 and 5 particles and E0 from 1e-6 to 5e9 (the work limit
refuses a period of 2 runs beyond about E0 = 1e14 at k = 5), each case as many periods as
take about 0.3 s (best of 2, after a first run that loads the kernels), and prints the
seconds per run and period, the collisions counted, the seconds per expected collision and
the ratio actual / estimated seconds (goal, issue 34: within [1/3, 1]).

Usage: ``python benchmarks/bench_billiard_estimate.py`` (about two minutes).
"""

from __future__ import annotations

import time

from machine import describe  # benchmarks/ is on sys.path when run as a script

from sinktheory.billiard import billiard
from sinktheory.billiard.run import expected_collisions, flight_seconds
from sinktheory.billiard.table import rigid_table
from sinktheory.ensemble import random_positions
from sinktheory.model import RunSettings

ENERGIES = (1e-6, 1e-3, 0.5, 50.0, 5e3, 5e5, 5e7, 5e9)


def estimate(settings: RunSettings, k: int, fixed: bool) -> tuple[float, float]:
    """(estimated seconds, expected collisions) of ``billiard`` with ``settings``, started
    as it starts them (the particles at rest in a moving container, else at speed
    sqrt(2 E0 / m))."""
    import numpy as np

    table, mass, e0 = rigid_table("flat", 0.5, 0.3), 0.2, settings.container_energy
    vel = np.zeros_like(random_positions(settings, k))
    container = None
    if fixed:
        vel[..., 0] = np.sqrt(2 * e0 / mass)  # the direction does not enter the estimate
    else:
        container = np.zeros((settings.runs, 2))
        container[:, 0] = np.sqrt(2 * e0)
    args = (table, vel, mass / k, container, settings.periods)
    return flight_seconds(*args), expected_collisions(*args)


def timed(e0: float, k: int, fixed: bool, periods: int):
    settings = RunSettings(container_energy=e0, runs=2, periods=periods)
    start = time.perf_counter()
    result = billiard("flat", 0.5, 0.3, particles=k, settings=settings, fixed=fixed)
    return time.perf_counter() - start, result, settings


def main() -> None:
    print(
        f"{'container':9s} {'k':>2s} {'E0':>8s} {'periods':>8s} {'s/run-period':>12s} "
        f"{'collisions':>10s} {'expected':>9s} {'s/expected':>10s} {'actual/est':>10s}"
    )
    ratios = []
    for fixed in (True, False):
        for k in (1, 5):
            for e0 in ENERGIES:
                periods = 1
                timed(e0, k, fixed, periods)  # loads the kernels
                seconds, result, settings = timed(e0, k, fixed, periods)
                while seconds < 0.3 and periods < 10**6:
                    periods *= 4
                    seconds, result, settings = timed(e0, k, fixed, periods)
                seconds = min(seconds, timed(e0, k, fixed, periods)[0])
                est, expected = estimate(settings, k, fixed)
                hits = result.collisions.sum()
                ratio = seconds / est
                ratios.append(ratio)
                print(f"{'fixed' if fixed else 'moving':9s} {k:2d} {e0:8.1e} {periods:8d} "
                      f"{seconds / (2 * periods):12.3g} {hits / 2 / periods:10.3g} "
                      f"{expected / 2 / periods:9.3g} {seconds / max(expected, 1e-300):10.3g} "
                      f"{ratio:10.2f}", flush=True)  # fmt: skip
    print(f"actual / estimated seconds: {min(ratios):.2f} .. {max(ratios):.2f} (goal [0.33, 1])")
    print(describe())


if __name__ == "__main__":
    main()
