"""Work limits checked before anything runs, naming the parameter responsible.

Checks shared by the analyses that integrate ensembles (simulations, chaos indicators,
design points, sweep kinds, normal-mode continuation); the step they price comes from
:func:`sinktheory.stepsize.step_of`, which names the parameter of a well too stiff to
integrate:

* :func:`check_particle_steps` -- the work of a computation in particle steps (an
  ensemble's by :func:`ensemble_steps`, the one price of a step of R runs of k particles:
  its blocks' overhead, its particles and their tangent vectors), priced at
  :data:`~sinktheory.model.SECONDS_PER_PARTICLE_STEP` (calibrated by
  benchmarks/bench_estimates.py not to be optimistic), against the limit in force
  (:func:`max_seconds`); :func:`check_work` prices an ensemble the same way, plus
  :data:`~sinktheory.engine.cache.COMPILE_SECONDS` outside a sweep when its engine is not
  compiled yet.

Two limits.  A computation that cannot resume (a simulation, ``chaos``, ``nnm``, any call
of the Python API) may start at most :data:`MAX_INTERACTIVE_SECONDS` (one hour) of
estimated work: an interrupt or a crash loses all of it.  The user raises it, up to
:data:`~sinktheory.model.MAX_SECONDS`, with ``--max-hours`` on the command line or
:func:`interactive_limit` in Python.  A sweep stores its points one by one and
``--resume`` continues it, so its points are checked (in :mod:`sinktheory.sweep`, inside
:func:`resumable`) against :data:`~sinktheory.model.MAX_SECONDS` (30 days) each, and
:func:`tally` collects their estimates, which the sweep prints before it starts.  A
refusal says the estimate, the limit and how to go bigger.

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> tangent_steps(particles=1, vectors=0), tangent_steps(particles=5, vectors=1)
(1.0, 15.1)
>>> ensemble_steps(runs=2, steps=1, particles=1), ensemble_steps(runs=40, steps=1, particles=1)
(10.0, 64.0)
>>> max_seconds() / 3600
1.0
>>> with resumable():
...     max_seconds() / 86400
30.0
>>> settings, sink = RunSettings(runs=10, periods=10**5), Sink(Well(0.5, 0.3, 4))
>>> check_work(settings, sink, steps_per_period=10**5)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: periods = 100000 is not allowed: must be smaller: at most \
3e+10 particle steps (1 h) in a computation that cannot resume (...about 6 h); use \
fewer runs, periods or particles, raise the limit (--max-hours, or \
sinktheory.worklimit.interactive_limit; up to 720 h), or split the work into the points \
of a resumable `sinktheory sweep`)
>>> with interactive_limit(hours=12):
...     check_work(settings, sink, steps_per_period=10**5)
>>> with resumable(), tally() as estimates:
...     check_work(settings, sink, steps_per_period=10**5)
>>> duration(sum(estimates))
'6 h'
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator
from contextvars import ContextVar

from . import validation as v
from .errors import ParameterError
from .integrators import get_scheme
from .limits import _INTERACTIVE, _RESUMABLE, MAX_INTERACTIVE_SECONDS, max_seconds
from .model import MAX_SECONDS, SECONDS_PER_PARTICLE_STEP, RunSettings, Sink

__all__ = [
    "check_work",
    "BLOCK_RUNS",
    "BLOCK_STEP",
    "DISSIPATIVE",
    "interactive_limit",
    "MAX_INTERACTIVE_SECONDS",
    "max_seconds",
    "resumable",
    "scheme_factor",
    "tally",
    "TANGENT_OVERHEAD",
    "VECTOR_STEP",
]

#: Particle steps one deviation vector adds per particle and step: the tangent kick
#: multiplies the vector by the particle's 2 x 2 Hessian block and the container coupling.
#: benchmarks/bench_worklimit.py (one thread, load 7.8, 2026-11-26) measured a step with
#: m vectors at a + b m plain steps, b = 0.66 and 0.64 for flat n = 4, k = 5 and 20; the
#: larger value, rounded up, keeps the estimate from being optimistic.
VECTOR_STEP = 0.7
#: Particle steps a run's step with deviation vectors costs beyond its particles' and
#: vectors' (the same measurement: a = 2.33 plain steps at k = 5 and 1.07 at k = 20, i.e.
#: 6.6 and 1.4 particle steps; the larger is taken, so at k = 20 it is 1.2x pessimistic).
TANGENT_OVERHEAD = 6.6
#: Runs the engine steps side by side in one block (LLVM's vector body takes 16 runs at a
#: time, :mod:`sinktheory.engine.blocks`): a step of 1 to 16 runs of few particles costs
#: about the same.
BLOCK_RUNS = 16
#: Particle steps one block's step costs beyond its particles': the step's fixed work
#: (the container, the scheme's stages, the loop over the block).  On one thread at a
#: fixed dt (2-core AVX-512 Xeon, 2026-11-26, load 1-1.5, best of 3) a step of R = 1, 2
#: and 8 runs of 1 particle took 3.2e-7, 3.4e-7 and 4.0e-7 s, of 64 runs (4 blocks)
#: 1.0e-6 s, while a particle step of 20 or 100 particles took 2.2-4.4e-8 s: a block
#: costs about 7-14 particle steps at that price.  At the price of
#: :data:`~sinktheory.model.SECONDS_PER_PARTICLE_STEP` it is taken as 8 (9.6e-7 s, above
#: the 4.4e-7 s a step of 2 runs of 1 particle took at load 5): in
#: benchmarks/bench_estimates.py 1 particle x 2 runs, the case the price per particle
#: alone made 1.55x optimistic, took 0.47-0.81 of its estimate (load 5-9, same day).
BLOCK_STEP = 8.0
#: Cost of one step of the engine with damping on (:mod:`sinktheory.damped`: ``compare``'s
#: attachments, damped design points) relative to a plain step: measured 2.3, 2.5 and 2.8
#: for k = 1, 3, 5 (flat n = 4, 25 runs x 150 periods, damping 0.5, by
#: ``benchmarks/bench_inelastic.py --quick``, 2-core AVX-512 Xeon, load 0.8); the design
#: estimator measures it again when its grid has damped designs.
DISSIPATIVE = 2.5


#: The estimates (seconds) of the checks made inside :func:`tally`, or None outside it.
_TALLY: ContextVar[list[float] | None] = ContextVar("sinktheory_work_tally", default=None)


def tangent_steps(particles: int, vectors: int) -> float:
    """Particle steps of one integration step of one run with ``vectors`` deviation vectors.

    A vector has 2 (1 + 2k) components, so the vectors of a spectrum cost about the square
    of the dimension: ``k (1 + VECTOR_STEP x vectors) + TANGENT_OVERHEAD`` (no overhead
    without vectors).
    """
    return particles * (1.0 + VECTOR_STEP * vectors) + (TANGENT_OVERHEAD if vectors else 0.0)


def scheme_factor(scheme: str | None) -> float:
    """The cost of a step of splitting scheme ``scheme`` relative to a step of
    :data:`~sinktheory.limits.DEFAULT_SCHEME` (blanes-moan6, 11 stages), at which the
    prices here were measured: (stages + 1) / 12.  On one thread at a fixed dt (2-core
    AVX-512 Xeon, load 7.2, 2026-11-26; k = 1, 5 and 20) a step took 0.07-0.15 (verlet,
    1 stage), 0.26-0.31 (yoshida4, 3), 0.53-0.58 (blanes-moan4, 6), 0.63-0.73 (yoshida6,
    7) and 1.2-1.4 (suzuki-umeno8, 15) of a blanes-moan6 step.  None: blanes-moan6.

    >>> scheme_factor(None), scheme_factor("blanes-moan4"), scheme_factor("verlet")
    (1.0, 0.5833333333333334, 0.16666666666666666)
    """
    if scheme is None:
        return 1.0
    return get_scheme(scheme).relative_cost


def ensemble_steps(
    runs: int, steps: float, particles: int, vectors: int = 0, scheme: str | None = None
) -> float:
    """Particle steps of ``steps`` integration steps of ``runs`` runs of ``particles``
    particles with ``vectors`` deviation vectors each: every run's :func:`tangent_steps`
    and every block's overhead (:data:`BLOCK_STEP` per :data:`BLOCK_RUNS` runs or fewer),
    in steps of ``scheme`` (:func:`scheme_factor`).  The one price of an ensemble's work,
    used by every check of it."""
    blocks = math.ceil(runs / BLOCK_RUNS)
    per_step = runs * tangent_steps(particles, vectors) + blocks * BLOCK_STEP
    return float(steps) * per_step * scheme_factor(scheme)


@contextlib.contextmanager
def interactive_limit(hours: float | None) -> Iterator[None]:
    """Let computations that cannot resume start up to ``hours`` of estimated work inside
    (``--max-hours`` of the commands); None keeps :data:`MAX_INTERACTIVE_SECONDS`.

    ``hours`` may also lower the limit; at most :data:`~sinktheory.model.MAX_SECONDS`
    (720 h), the limit of a sweep's point.
    """
    seconds = MAX_INTERACTIVE_SECONDS
    if hours is not None:
        top = MAX_SECONDS / 3600
        allowed = f"a number of hours in (0, {top:.0f}]"
        try:
            seconds = 3600.0 * v.positive("max_hours", hours)
        except ParameterError:
            raise ParameterError("max_hours", hours, allowed) from None
        if seconds > MAX_SECONDS:
            raise ParameterError("max_hours", hours, allowed)
    token = _INTERACTIVE.set(seconds)
    try:
        yield
    finally:
        _INTERACTIVE.reset(token)


@contextlib.contextmanager
def resumable() -> Iterator[None]:
    """Check work against the resumable limit (:data:`~sinktheory.model.MAX_SECONDS`)
    inside: for the points of a sweep, which are stored and resumed one by one."""
    token = _RESUMABLE.set(True)
    try:
        yield
    finally:
        _RESUMABLE.reset(token)


@contextlib.contextmanager
def tally() -> Iterator[list[float]]:
    """Collect the estimate (seconds) of every work check made inside, in the list yielded:
    a sweep adds up its points' estimates this way to print them before it starts."""
    estimates: list[float] = []
    token = _TALLY.set(estimates)
    try:
        yield estimates
    finally:
        _TALLY.reset(token)


def duration(seconds: float) -> str:
    """``seconds`` in the unit a reader takes in at a glance.

    >>> duration(42), duration(600), duration(3600), duration(86400 * 15.6)
    ('42 s', '10 min', '1 h', '15.6 days')
    """
    for unit, size in (("days", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= (2 * size if unit == "days" else size):
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.3g} s"


def check_particle_steps(
    name: str, value: object, steps: float, what: str, change: str = "smaller"
) -> None:
    """Refuse ``value`` of ``name`` when ``steps`` particle steps (``what`` says of what)
    would take longer than the limit in force (:func:`max_seconds`) at
    :data:`~sinktheory.model.SECONDS_PER_PARTICLE_STEP`; the message gives the estimate,
    the limit and the way to a larger job.  ``change`` says which way ``value`` must move
    ("larger" for a clearance, say)."""
    seconds = steps * SECONDS_PER_PARTICLE_STEP
    limit = max_seconds()
    if seconds <= limit:
        if (estimates := _TALLY.get()) is not None:
            estimates.append(seconds)
        return
    if not _RESUMABLE.get():
        where = "in a computation that cannot resume"
        bigger = (
            "use fewer runs, periods or particles, raise the limit (--max-hours, or "
            f"sinktheory.worklimit.interactive_limit; up to {MAX_SECONDS / 3600:.0f} h), or "
            "split the work into the points of a resumable `sinktheory sweep`"
        )
    else:
        where = "per point of a sweep"
        bigger = "split it into more points (e.g. replica=0:9:10) or use fewer runs or periods"
    raise ParameterError(
        name,
        value,
        f"{change}: at most {limit / SECONDS_PER_PARTICLE_STEP:.3g} particle steps "
        f"({duration(limit)}) {where}",
        why=f"{what} is {steps:.3g} particle steps at {SECONDS_PER_PARTICLE_STEP:g} s each, "
        f"estimated {seconds:.3g} s (about {duration(seconds)}); {bigger}",
    )


def check_work(
    settings: RunSettings, sink: Sink, steps_per_period: int, scheme: str | None = None
) -> None:
    """Refuse an ensemble of ``settings`` over ``sink`` at ``steps_per_period`` steps of
    ``scheme`` (None: blanes-moan6) that would exceed the work limit
    (:func:`check_particle_steps`), naming the larger of ``periods`` and ``runs``."""
    if not isinstance(settings, RunSettings):
        raise ParameterError("settings", settings, "a sinktheory.model.RunSettings")
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    steps_per_period = v.positive_int("steps_per_period", steps_per_period)
    name = "periods" if settings.periods > settings.runs else "runs"
    steps = ensemble_steps(
        settings.runs, float(settings.periods) * steps_per_period, sink.particles, scheme=scheme
    )
    seconds, compiling = (0.0, "") if _RESUMABLE.get() else _first_compilation(sink)
    steps += seconds / SECONDS_PER_PARTICLE_STEP
    check_particle_steps(
        name,
        getattr(settings, name),
        steps,
        f"{settings.runs} run(s) x {settings.periods} period(s) x {steps_per_period} "
        f"step(s) x {sink.particles} particle(s), with {BLOCK_STEP:g} per step of each block "
        f"of up to {BLOCK_RUNS} runs"
        + (f", x {scheme_factor(scheme):.3g} for {scheme}" if scheme_factor(scheme) != 1 else "")
        + compiling,
    )


def _first_compilation(sink: Sink) -> tuple[float, str]:
    """(seconds, ", plus compiling the engine NAME first (... s)") when the engine of
    ``sink`` is not compiled yet (:func:`sinktheory.engine.cache.compiled`;
    :data:`~sinktheory.engine.cache.COMPILE_SECONDS`), else (0, "").  A sweep's points
    leave it out: their sum would count the one compilation once a point."""
    from .engine.cache import COMPILE_SECONDS, compiled  # numba loads when first needed
    from .ensemble import engine_name

    name = engine_name(sink)
    if compiled(name):
        return 0.0, ""
    return COMPILE_SECONDS, f", plus compiling the engine {name} first ({COMPILE_SECONDS:g} s)"
