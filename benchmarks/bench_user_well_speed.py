"""The engine of a user's well against the registry's: the paper's flat well typed as a
user's expression (SymPy's derivatives of the text) and the registered flat shape (its
hand-declared atoms), Fig. 8's ensemble (alpha 0.5, beta 0.3, n 4, k 5, m 0.2), 25 runs x
300 periods at tol 1e-8, each timed in turn, best of ``--repeats``; the largest relative
energy error of each, and whether their container-energy histories are identical::

    python benchmarks/bench_user_well_speed.py [--repeats 3]

Issue 36's goal: the same engine speed within 10 %.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from machine import describe

FLAT = "gamma/(2*n) * ((x/(alpha + beta*(y**2 - 1)))**(2*n) + y**(2*n))"
PAPER = {"alpha": 0.5, "beta": (0.3, (-5.0, 0.45)), "gamma": 1.0, "n": (4, (1, 1000))}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    from sinktheory import RunSettings, Sink, Well
    from sinktheory.simulate import simulate
    from sinktheory.userwell import UserWell
    from sinktheory.wellat import WellAt

    print(describe())
    sinks = {
        "registered flat shape": Sink(Well(0.5, 0.3, 4), 5, 0.2),
        "flat typed by a user": Sink(WellAt(UserWell("paperflat", FLAT, PAPER)), 5, 0.2),
    }
    for sink in sinks.values():  # compile or load, outside the timing
        simulate(sink, RunSettings(runs=2, periods=2), progress=False)
    settings = RunSettings(runs=25, periods=300, seed=1)
    best, results = dict.fromkeys(sinks, np.inf), {}
    for _ in range(args.repeats):
        for name, sink in sinks.items():
            start = time.perf_counter()
            results[name] = simulate(sink, settings, tol=1e-8, progress=False)
            best[name] = min(best[name], time.perf_counter() - start)
    for name in sinks:
        print(f"{name:24s} best of {args.repeats}: {best[name]:.3f} s, max relative energy "
              f"error {results[name].max_relative_energy_error:.2e}")  # fmt: skip
    registry, user = (results[k].container_energy for k in sinks)
    ratio = best["flat typed by a user"] / best["registered flat shape"]
    print(
        f"ratio user / registry {ratio:.3f} (goal <= 1.10); identical histories: "
        f"{np.array_equal(user, registry)}"
    )


if __name__ == "__main__":
    main()
