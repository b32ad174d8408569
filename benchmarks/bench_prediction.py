"""How long the predicted relaxation takes for Fig. 8's k = 1..5, beside the alternative a
user would otherwise pick: measuring the settling time from an ensemble.

Usage::

    python benchmarks/bench_prediction.py [--particles 1 2 3 4 5] [--measure 32] [--lag 128]

For each k (flat well, alpha 0.5, beta 0.3, n 4, m 0.2, E0 0.5, particles at rest):

1. ``sinktheory relaxation``'s prediction (predict_relaxation with its defaults: 12 points
   x 100 shell runs over ``--lag`` = 128 periods, tol 1e-6): wall time, settling time and interval,
   t_r and c, wall time and CPU time.  The target: all five k in under a minute on two
   cores.
2. With ``--measure R`` (0 skips it): R runs over four times the predicted settling time
   (at least 3000 periods) from the start, read by measure_relaxation: wall time and the
   measured settling time with its interval.

Wall times depend on the machine's load, printed with them.
"""

from __future__ import annotations

import argparse
import sys
import time

from sinktheory.canonical import FIG8_WELL
from sinktheory.equilibrium.prediction import measure_settling, predict_relaxation
from sinktheory.model import Sink


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--particles", type=int, nargs="+", default=[1, 2, 3, 4, 5])
    parser.add_argument("--measure", type=int, default=32)
    parser.add_argument("--lag", type=int, default=128, help="the prediction's largest lag")
    args = parser.parse_args()
    sys.path.insert(0, __file__.rsplit("/", 1)[0])
    from machine import describe

    print(describe())
    total = cpu = 0.0
    for k in args.particles:
        sink = Sink(FIG8_WELL, particles=k, mass=0.2)
        t0, c0 = time.perf_counter(), time.process_time()
        p = predict_relaxation(sink, 0.5, lag=args.lag)
        wall = time.perf_counter() - t0
        total += wall
        cpu += time.process_time() - c0
        print(f"k = {k}: predicted {p.settle_time:.0f} ({p.settle_low:.0f}-{p.settle_high:.0f}) "
              f"periods, t_r {p.rate_time:.0f}, c {p.visible:.2f}"
              + (" [t_r > 4 x lag]" if p.extrapolated else "") + f"  [{wall:.1f} s]",
              flush=True)  # fmt: skip
        if args.measure:
            periods = int(max(4 * p.settle_time, 3000))
            t0 = time.perf_counter()
            r, _ = measure_settling(sink, 0.5, (args.measure, periods), seed=1)
            star = "*" if r.extrapolated else ""
            print(f"       measured {r.settle_time:.0f}{star} ({r.settle_low:.0f}-"
                  f"{r.settle_high:.0f}) from {args.measure} runs x {periods} periods  "
                  f"[{time.perf_counter() - t0:.1f} s]", flush=True)  # fmt: skip
    print(f"prediction for k = {args.particles}: {total:.1f} s wall in all, {cpu:.1f} s of CPU "
          "(all threads; the wall time on a machine to ourselves is about the CPU time over "
          "the cores numba uses)")  # fmt: skip


if __name__ == "__main__":
    main()
