"""How long the report's ensemble claims must run: horizons from measured or predicted relaxation.

A claim about the long-time state of an ensemble (its mean container energy against the
exact equilibrium law, its level against another set-up's) is judged only on a run of at
least :data:`FACTOR` settling times, over the window from one settling time on: there the
mean's excess over the law is below 5 % of the law and still falling, so what is left is
the run-to-run noise the verdict accounts for.  Where the paper's own horizon is shorter,
the claim gets a run of its own and the paper's figure still shows the paper's horizon.

The settling time t_f of a set-up is when its ensemble mean comes within 5 % of the law's
mean.  :data:`SETTLING` holds the t_f measured for every set-up the report judges, read
off the fitted tail of the approach (:func:`sinktheory.equilibrium.measure_relaxation`),
with the runs that measured it (``python benchmarks/bench_horizons.py`` reprints them).
:func:`settling_time` is the one place that turns a set-up into a settling time: the
measured one where it is stored, else the one
:func:`sinktheory.equilibrium.settling_periods` predicts (a few seconds; its interval
widened by the model's known error), each marked by its ``source``.  The stored set-ups
are not predicted again, which keeps the report's cost where it was.

Examples
--------
>>> horizon("flat", 0.5, 0.3, 4, 5)  # Fig. 8, five particles: 3 x 5241 periods
15750
>>> s = settling_time("flat", 0.5, 0.3, 4, 5)
>>> s.periods, s.source, describe(s)
(5241, 'measured', 'measured 5241 (4137-6514) on 192 x 8000 runs x periods')
"""

from __future__ import annotations

import functools
import math

from ..equilibrium.prediction import Settling

__all__ = ["describe", "E0", "FACTOR", "MASS", "MAX_HORIZON", "SETTLING", "horizon",
           "settling_time"]  # fmt: skip

#: The report's ensembles: container energy E0 and total particle mass m.
E0, MASS = 0.5, 0.2

#: Settling times a claim's horizon must span.
FACTOR = 3
#: Longest horizon (periods) the report runs at paper fidelity: at the per-period cost of
#: Fig. 8's five particles (0.03 ms per run-period, docs/guide/equilibrium.rst), the 24 runs
#: of a long row cost about 15 s of CPU, so the main job stays within its budget (3
#: minutes on 2 cores).
MAX_HORIZON = 20000


def _measured(periods: int, low: int, high: int, extrapolated: bool, runs: str) -> Settling:
    """A stored measurement: t_f, its 95 % interval, whether the crossing lies beyond the
    record, and the runs x periods that measured it."""
    return Settling(periods, low, high, "measured", extrapolated, 0.05,
                    f"{runs} runs x periods")  # fmt: skip


#: Measured settling times (5 % of the law's mean) per set-up (shape, alpha, beta, n, k),
#: m = 0.2, E0 = 0.5, tol 1e-8 unless said.
SETTLING = {
    # Fig. 5 (k = 1, n = 10): 16 runs x 3000 periods, benchmarks/bench_horizons.py
    ("flat", 0.5, -0.5, 10, 1): _measured(276, 83, 1042, False, "16 x 3000"),
    ("flat", 0.5, -0.3, 10, 1): _measured(160, 96, 298, False, "16 x 3000"),
    ("flat", 0.5, -0.2, 10, 1): _measured(72, 28, 262, False, "16 x 3000"),
    ("flat", 0.5, -0.14, 10, 1): _measured(206, 106, 2194, False, "16 x 3000"),
    ("flat", 0.5, 0.009, 10, 1): _measured(17050, 10244, 55243, True, "16 x 3000"),
    ("flat", 0.5, 0.3, 10, 1): _measured(347, 167, 799, False, "16 x 3000"),
    # Fig. 8 (beta = 0.3, n = 4): docs/guide/equilibrium.rst (k = 1: 16 x 3000;
    # k = 5: 192 x 8000 at tol 1e-6) and benchmarks/bench_horizons.py (k = 3)
    ("flat", 0.5, 0.3, 4, 1): _measured(657, 202, 1156, False, "16 x 3000"),
    ("flat", 0.5, 0.3, 4, 3): _measured(5349, 1006, 16774, False, "16 x 12000"),
    ("flat", 0.5, 0.3, 4, 5): _measured(5241, 4137, 6514, False, "192 x 8000"),
    # Fig. 12 (symmetric, alpha = 1, beta = 0.1, n = 6, k = 5): benchmarks/bench_horizons.py
    ("symmetric", 1.0, 0.1, 6, 5): _measured(172, 77, 383, False, "16 x 3000"),
}


def settling_time(shape: str, alpha: float, beta: float, n: int, k: int) -> Settling:
    """The settling time of a set-up (E0 = 0.5, m = 0.2): measured where :data:`SETTLING`
    holds it, else predicted (cached per set-up)."""
    key = (shape, float(alpha), float(beta), int(n), int(k))
    return SETTLING[key] if key in SETTLING else _predicted(*key)


@functools.lru_cache(maxsize=32)
def _predicted(shape: str, alpha: float, beta: float, n: int, k: int) -> Settling:
    from ..equilibrium import settling_periods
    from ..model import Sink, Well

    return settling_periods(Sink(Well(alpha, beta, n, shape=shape), particles=k, mass=MASS), E0)


def horizon(shape: str, alpha: float, beta: float, n: int, k: int) -> int:
    """Periods a long-time claim on this set-up must run: :data:`FACTOR` settling times,
    and for a predicted one at least the upper end of its interval; rounded up to a
    multiple of 50 periods (the relaxation windows)."""
    s = settling_time(shape, alpha, beta, n, k)
    periods = FACTOR * s.periods if s.source == "measured" else max(FACTOR * s.periods, s.high)
    return 50 * math.ceil(periods / 50)


def describe(s: Settling) -> str:
    """One phrase on a settling time and where it comes from."""
    if s.source == "measured":
        star = ", extrapolated beyond the record" if s.extrapolated else ""
        return f"measured {s.periods:.0f} ({s.low:.0f}-{s.high:.0f}{star}) on {s.note}"
    star = ", probably short: a slow relaxation" if s.extrapolated else ""
    return (f"predicted {s.periods:.0f} ({s.low:.0f}-{s.high:.0f}, the model's interval{star}; "
            "sinktheory.equilibrium.settling_periods)")  # fmt: skip
