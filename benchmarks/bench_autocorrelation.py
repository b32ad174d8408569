"""Coverage of the autocorrelation time's error (sinktheory.equilibrium.lifetime.
autocorrelation_time): how often tau +- 2 stderr holds the true tau.

Usage::

    python benchmarks/bench_autocorrelation.py [--seeds 1000]

Independent samples (normal, and Beta(1, 1.25), the circular well's law at k = 1) have
tau = 1; AR(1) samples with phi = 0.8 have tau = (1 + phi) / (1 - phi) = 9.  For records
of runs x samples from 2 x 21 (issue 34's record) up, over ``--seeds`` seeds (a quarter
of them for AR(1)): how many records measure tau at all (the others are too short for
Sokal's window) and the fraction of those whose interval covers the true tau.  A few
seconds.
"""

from __future__ import annotations

import argparse
import math

import numpy as np
from scipy import signal

from sinktheory.equilibrium.lifetime import autocorrelation_time


def ar1(rng, runs, samples, phi=0.8, burn=200):
    noise = rng.standard_normal((runs, samples + burn))
    return signal.lfilter([1.0], [1.0, -phi], noise, axis=1)[:, burn:]


SHORT = [(2, 21), (2, 50), (4, 200), (8, 1000)]
CASES = [
    ("normal", lambda rng, r, p: rng.standard_normal((r, p)), 1.0, SHORT),
    ("Beta(1, 1.25)", lambda rng, r, p: rng.beta(1, 1.25, (r, p)), 1.0, SHORT),
    ("AR(1) 0.8", ar1, 9.0, [(2, 200), (4, 500), (8, 2000)]),
]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=1000)
    args = parser.parse_args()
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    print(f"{'samples':<14s} {'true tau':>8s} {'runs x samples':>15s} {'measured':>9s} "
          f"{'covered by tau +- 2 se':>23s}")  # fmt: skip
    for name, draw, true, sizes in CASES:
        seeds = args.seeds if true == 1.0 else args.seeds // 4
        for runs, samples in sizes:
            hits = []
            for seed in range(seeds):
                x = draw(np.random.default_rng(seed), runs, samples)
                tau, stderr, _ = autocorrelation_time(x)
                if math.isfinite(tau):
                    hits.append(abs(tau - true) <= 2 * stderr)
            print(f"{name:<14s} {true:>8g} {f'{runs} x {samples}':>15s} "
                  f"{f'{len(hits)}/{seeds}':>9s} {np.mean(hits):>23.3f}")  # fmt: skip


if __name__ == "__main__":
    main()
