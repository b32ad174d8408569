"""What one deviation vector costs, for the work limit of :mod:`sinktheory.worklimit`.

Times, on one thread, a plain ensemble (:func:`sinktheory.simulate.simulate`) and the
same runs with one deviation vector (lambda_1) and with the full spectrum (2 (1 + 2k)
vectors) of :func:`sinktheory.chaos.chaos`, at the same fixed step, and prints the cost
of one particle step and the particle steps one vector adds per particle and step
(``VECTOR_STEP`` is set at the largest value measured, rounded up, so the limit is not
optimistic).  Run: ``python benchmarks/bench_worklimit.py`` (about a minute).
"""

import os
import platform
import time

import numba

from sinktheory import RunSettings, Sink, Well
from sinktheory.chaos import chaos
from sinktheory.simulate import simulate
from sinktheory.worklimit import VECTOR_STEP


def timed(f, *args, **kwargs) -> float:
    start = time.perf_counter()
    f(*args, **kwargs)
    return time.perf_counter() - start


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    numba.set_num_threads(1)
    print(
        f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"load {os.getloadavg()[0]:.2f}; one thread; VECTOR_STEP = {VECTOR_STEP}"
    )
    print(" k  vectors  s per particle step  1 vector / plain  spectrum / plain  per vector")
    for k, periods in ((5, 20), (20, 5)):
        sink = Sink(Well(0.5, 0.3, 4), particles=k, mass=0.2)
        settings = RunSettings(runs=8, periods=periods, seed=1)
        small = RunSettings(runs=2, periods=1)
        simulate(sink, small, dt=0.01, progress=False)  # compile or load first
        chaos(sink, small, dt=0.01, spectrum=True, progress=False)
        plain = timed(simulate, sink, settings, dt=0.01, progress=False)
        one = timed(chaos, sink, settings, dt=0.01, progress=False)
        full = timed(chaos, sink, settings, dt=0.01, spectrum=True, progress=False)
        steps = settings.runs * periods * 629 * k  # dt = 0.01: 629 steps per period
        vectors = 2 * (1 + 2 * k)
        print(
            f"{k:2d}  {vectors:7d}  {plain / steps:19.3g}  {one / plain:16.2f}  "
            f"{full / plain:16.2f}  {(full / plain - 1) / vectors:10.3f}"
        )


if __name__ == "__main__":
    main()
