"""Kinetic theory of the rigid limit against rigid billiards: how fast the container
relaxes with rigid walls, predicted from random impacts and measured.

Usage::

    python benchmarks/bench_kinetic.py [--runs 16] [--quick]

For Fig. 8's table (flat, alpha 0.5, beta 0.3, rigid walls: sinktheory.billiard.run) and
E0 = 0.5, particles at rest: k = 1, 3, 5 with m = 0.2, then k = 3 with m = 0.1 and 0.4.

* kinetic: the Fokker-Planck equation with the kinetic drift of
  sinktheory.billiard.kinetic (derivations/rigid_friction.py) on the rigid law
  Beta(1, k): 5 % settling time and slowest relaxation time, in periods;
* measured: ``--runs`` exact billiard runs (seed 1) over ``periods`` periods, read by
  measure_relaxation: settling time (95 %), tail time, and the ensemble mean after 1 and
  2 periods (the first exchange).

``--quick``: 8 runs, k = 1 only.
"""

from __future__ import annotations

import argparse
import sys
import time

from sinktheory.billiard.kinetic import kinetic_relaxation, wall_moment
from sinktheory.billiard.run import billiard
from sinktheory.billiard.table import rigid_table
from sinktheory.equilibrium.relaxation import measure_relaxation
from sinktheory.model import RunSettings

CASES = [(1, 0.2, 2000), (3, 0.2, 4000), (5, 0.2, 6000), (3, 0.1, 6000), (3, 0.4, 3000)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=16)
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    cases = [(1, 0.2, 600)] if args.quick else CASES
    runs = 8 if args.quick else args.runs
    sys.path.insert(0, __file__.rsplit("/", 1)[0])
    from machine import describe

    print(describe())
    table = rigid_table("flat", 0.5, 0.3)
    print(f"table: area {table.area:.4f}, perimeter {table.perimeter:.4f}, "
          f"W = oint n_x^2 ds = {wall_moment(table):.4f}")  # fmt: skip
    print("k  m    | kinetic: settles  t_r    | measured: settles (95 %)     tail    "
          "<E_c>(1), (2) | ratio settles")  # fmt: skip
    for k, m, periods in cases:
        t_f, t_r = kinetic_relaxation(table, k, m, 0.5)
        t0 = time.perf_counter()
        r = billiard("flat", 0.5, 0.3, particles=k, mass=m,
                     settings=RunSettings(runs=runs, periods=periods, seed=1))  # fmt: skip
        rel = measure_relaxation(r.container_energy, 0.5 / (k + 1), resamples=199, seed=1)
        mean = r.container_energy.mean(axis=0)
        star = "*" if rel.extrapolated else ""
        print(f"{k}  {m:<4g} | {t_f:16.2f}  {t_r:5.2f}  | {rel.settle_time:7.0f}{star} "
              f"({rel.settle_low:.0f}-{rel.settle_high:.0f})  {rel.rate_time:6.0f}  "
              f"{mean[1]:.3f}, {mean[2]:.3f}  | {rel.settle_time / t_f:7.0f}"
              f"  [{runs} x {periods}, {time.perf_counter() - t0:.0f} s]", flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
