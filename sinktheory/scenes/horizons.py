"""How long the report's ensemble claims must run: horizons from measured relaxation.

A claim about the long-time state of an ensemble (its mean container energy against the
exact equilibrium law, its level against another set-up's) is judged only on a run of at
least :data:`FACTOR` settling times, over the window from one settling time on: there the
mean's excess over the law is below 5 % of the law and still falling, so what is left is
the run-to-run noise the verdict accounts for.  Where the paper's own horizon is shorter,
the claim gets a run of its own and the paper's figure still shows the paper's horizon.

The settling time t_f of a set-up is when its ensemble mean comes within 5 % of the law's
mean, read off the fitted tail of the approach
(:func:`sinktheory.equilibrium.measure_relaxation`).  :data:`SETTLING` holds the measured
t_f of every set-up the report judges, with the runs that measured it
(``python benchmarks/bench_horizons.py`` reprints them);
:func:`horizon` is the one place that turns a set-up into periods, so that a predicted
settling time can replace the table later.

Examples
--------
>>> horizon("flat", 0.5, 0.3, 4, 5)  # Fig. 8, five particles: 3 x 5241 periods
15750
>>> settling_time("flat", 0.5, 0.3, 4, 5).periods
5241
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["FACTOR", "MAX_HORIZON", "SETTLING", "Settling", "horizon",
           "settling_time"]  # fmt: skip

#: Settling times a claim's horizon must span.
FACTOR = 3
#: Longest horizon (periods) the report runs at paper fidelity: at the per-period cost of
#: Fig. 8's five particles (0.03 ms per run-period, docs/guide/equilibrium.rst), the 24 runs
#: of a long row cost about 15 s of CPU, so the main job stays within its budget (3
#: minutes on 2 cores).
MAX_HORIZON = 20000


@dataclass(frozen=True)
class Settling:
    """A measured settling time: periods (point estimate), its 95 % interval, whether the
    crossing was extrapolated beyond the record, and the runs x periods that measured it."""

    periods: int
    low: int
    high: int
    extrapolated: bool
    source: str


#: Measured settling times (5 % of the law's mean) per set-up (shape, alpha, beta, n, k),
#: m = 0.2, E0 = 0.5, tol 1e-8 unless said.
SETTLING = {
    # Fig. 5 (k = 1, n = 10): 16 runs x 3000 periods, benchmarks/bench_horizons.py
    ("flat", 0.5, -0.5, 10, 1): Settling(276, 83, 1042, False, "16 x 3000"),
    ("flat", 0.5, -0.3, 10, 1): Settling(160, 96, 298, False, "16 x 3000"),
    ("flat", 0.5, -0.2, 10, 1): Settling(72, 28, 262, False, "16 x 3000"),
    ("flat", 0.5, -0.14, 10, 1): Settling(206, 106, 2194, False, "16 x 3000"),
    ("flat", 0.5, 0.009, 10, 1): Settling(17050, 10244, 55243, True, "16 x 3000"),
    ("flat", 0.5, 0.3, 10, 1): Settling(347, 167, 799, False, "16 x 3000"),
    # Fig. 8 (beta = 0.3, n = 4): docs/guide/equilibrium.rst (k = 1: 16 x 3000;
    # k = 5: 192 x 8000 at tol 1e-6) and benchmarks/bench_horizons.py (k = 3)
    ("flat", 0.5, 0.3, 4, 1): Settling(657, 202, 1156, False, "16 x 3000"),
    ("flat", 0.5, 0.3, 4, 3): Settling(5349, 1006, 16774, False, "16 x 12000"),
    ("flat", 0.5, 0.3, 4, 5): Settling(5241, 4137, 6514, False, "192 x 8000"),
    # Fig. 12 (symmetric, alpha = 1, beta = 0.1, n = 6, k = 5): benchmarks/bench_horizons.py
    ("symmetric", 1.0, 0.1, 6, 5): Settling(172, 77, 383, False, "16 x 3000"),
}


def settling_time(shape: str, alpha: float, beta: float, n: int, k: int) -> Settling:
    """The measured settling time of a set-up (:data:`SETTLING`); KeyError if unmeasured."""
    return SETTLING[(shape, float(alpha), float(beta), int(n), int(k))]


def horizon(shape: str, alpha: float, beta: float, n: int, k: int) -> int:
    """Periods a long-time claim on this set-up must run: :data:`FACTOR` settling times,
    rounded up to a multiple of 50 periods (the relaxation windows)."""
    periods = FACTOR * settling_time(shape, alpha, beta, n, k).periods
    return 50 * math.ceil(periods / 50)
