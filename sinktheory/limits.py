"""Limits and defaults a user meets: the one place for the bounds every input is checked
against and the values used when an option is not given.

Numerical safeguards inside one algorithm (iteration caps of a root finder, step bounds
of a Newton method) stay beside that algorithm; what is here is what a user can ask for
and be refused, or leave out and get.  The modules that use a limit import it from here,
so ``sinktheory.model.MAX_N`` and ``sinktheory.limits.MAX_N`` are the same object.

Examples
--------
>>> MAX_N, DEFAULT_TOL, TOL_RANGE
(1000, 1e-08, (1e-12, 0.0001))
>>> MAX_INTERACTIVE_SECONDS < MAX_SECONDS
True
"""

from __future__ import annotations

from contextvars import ContextVar

__all__ = [
    "DEFAULT_EPS",
    "DEFAULT_RTOL",
    "DEFAULT_SCHEME",
    "DEFAULT_TOL",
    "MAX_DPS",
    "MAX_EPS",
    "MAX_INTERACTIVE_SECONDS",
    "MAX_N",
    "MAX_ORDER",
    "MAX_PERIODS",
    "MAX_RESAMPLES",
    "MAX_RUNS",
    "MAX_SECONDS",
    "MAX_STEPS_PER_PERIOD",
    "MAX_SWEEP_POINTS",
    "SECONDS_PER_PARTICLE_STEP",
    "TOL_RANGE",
]

# ----------------------------------------------------------------- the model's parameters
#: Largest wall stiffness accepted.  Kernels stay finite far beyond it; the limit keeps
#: integer powers s^(2n) of wall ratios |s| <= 1.5 well inside float64 range.
MAX_N = 1000

# ------------------------------------------------------------------ ensembles and work
#: Largest ensemble and run length: beyond them seeding the runs, or one energy record,
#: alone takes minutes or gigabytes.
MAX_RUNS = 10**7
MAX_PERIODS = 10**9
#: The estimated cost of one particle step, used to refuse work that could not finish
#: within MAX_SECONDS (30 days: a sweep's point) or MAX_INTERACTIVE_SECONDS (an hour: a
#: computation that cannot resume).  An ensemble's step also pays its blocks' overhead
#: (:data:`sinktheory.worklimit.BLOCK_STEP`, :func:`sinktheory.worklimit.ensemble_steps`).
#: benchmarks/bench_estimates.py (2-core AVX-512 Xeon, 2026-11-26, two runs at load 6-9)
#: timed the fixed-step engine's work at 0.14-0.47 and 0.33-0.82 of this estimate for
#: 1 particle x 2, 8, 4 and 64 runs and 5 x 2, 20 x 2 and 100 x 2 particles x runs (the
#: lowest for 64 runs of 1 particle, whose vector lanes share a block's work, and for 100
#: particles): the same work's time varies about 2x with the load (the earlier
#: calibration, 4e-7 s a particle step without the block's overhead, was made at load 6-8).
SECONDS_PER_PARTICLE_STEP = 1.2e-7
MAX_SECONDS = 30 * 86400.0
#: The longest estimated work (seconds at SECONDS_PER_PARTICLE_STEP) a computation that
#: cannot resume may start unless the user raises it (``--max-hours``,
#: :func:`sinktheory.worklimit.interactive_limit`).  The paper's largest jobs estimate
#: minutes (``sinktheory reproduce`` as a whole about 83 s measured); an hour keeps a
#: mistyped size from holding a machine for days, while a sweep goes up to MAX_SECONDS per
#: point.
MAX_INTERACTIVE_SECONDS = 3600.0
#: Most bootstrap resamples of a statistic (each redraws the runs: 1e5 already pins a
#: p-value to +-0.002 at p = 0.5; 1e12 asked for terabytes).
MAX_RESAMPLES = 100_000
#: Most points of one sweep (every point is checked before any work starts: about
#: 0.1 ms each, so 1e6 points take a couple of minutes just to check).
MAX_SWEEP_POINTS = 10**6

#: Whether the work being checked is a resumable sweep's (set by
#: :func:`sinktheory.worklimit.resumable`).
_RESUMABLE: ContextVar[bool] = ContextVar("sinktheory_resumable_work", default=False)
#: The limit of a computation that cannot resume, in seconds (set by
#: :func:`sinktheory.worklimit.interactive_limit`).
_INTERACTIVE: ContextVar[float] = ContextVar(
    "sinktheory_interactive_limit", default=MAX_INTERACTIVE_SECONDS
)


def max_seconds() -> float:
    """The work limit in force, in estimated seconds: :data:`MAX_INTERACTIVE_SECONDS` (or
    the limit :func:`sinktheory.worklimit.interactive_limit` set), or :data:`MAX_SECONDS`
    inside :func:`sinktheory.worklimit.resumable`.  Here, below the engine, so that the
    engine can check the work it is handed too; public as
    :func:`sinktheory.worklimit.max_seconds`."""
    return MAX_SECONDS if _RESUMABLE.get() else _INTERACTIVE.get()


# ------------------------------------------------------------------------- time steps
#: Most integration steps in one container period T = 2 pi (a step >= 6.3e-9).
MAX_STEPS_PER_PERIOD = 10**9
#: The default tolerance of :func:`sinktheory.simulate.simulate`.
DEFAULT_TOL = 1e-8
#: Tolerances the calibration supports (round-off floor below, no accuracy above).
TOL_RANGE = (1e-12, 1e-4)
#: The scheme used when a step ``dt`` is given without a method (with a tolerance, the
#: cheapest scheme is chosen by :func:`sinktheory.stepsize.choose`).
DEFAULT_SCHEME = "blanes-moan6"
#: The adaptive step's eps when none is given: |dH|/H0 <= 1e-8 over 40 periods of Fig. 8's
#: ensemble for n = 4..100, <= 4e-7 over 10^4 periods at n = 4, 10 and 100
#: (benchmarks/bench_adaptive_drift.py).
DEFAULT_EPS = 0.25
#: Largest eps accepted: 10^4 periods of Fig. 8's ensemble at n = 4, 10 and 100 held the
#: default energy bound up to it with a margin (3.8e-7 at most); eps 0.3 reached 7e-7 at
#: n = 10 and 9.8e-7 at n = 100, and the error grows fast with eps beyond
#: (docs/guide/billiard.rst, "Long runs").
MAX_EPS = 0.25
#: Default relative tolerance of one step of the Hill integration (:mod:`sinktheory.hill`);
#: gives phi to about 1e-11 (see tests).
DEFAULT_RTOL = 1e-13

# --------------------------------------------------------------- exact and series paths
#: Most significant digits of the oscillator's mp path.  mpmath's Gamma function is the
#: cost: with its pure-Python backend one Gamma value takes about 0.5 s at 300 digits,
#: 2-17 s at 1000 and minutes at 10000 (measured 2026-11 on the 2-core development machine).
MAX_DPS = 1000
#: Highest order of the triangle-wave series built (exact rational arithmetic grows like
#: order^4).
MAX_ORDER = 20
