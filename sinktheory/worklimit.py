"""Work limits checked before anything runs, naming the parameter responsible.

Checks shared by the analyses that integrate ensembles (simulations, chaos indicators,
design points, sweep kinds, normal-mode continuation); the step they price comes from
:func:`sinktheory.stepsize.step_of`, which names the parameter of a well too stiff to
integrate:

* :func:`check_particle_steps` -- the work of a computation in particle steps, tangent
  vectors included (:func:`tangent_steps`), priced at the optimistic
  :data:`~sinktheory.model.SECONDS_PER_PARTICLE_STEP`, against the limit in force
  (:func:`max_seconds`); :func:`check_work` prices an ensemble the same way.

Two limits.  A computation that cannot resume (a simulation, ``chaos``, ``nnm``, any call
of the Python API) may start at most :data:`MAX_INTERACTIVE_SECONDS` (one day) of
estimated work: an interrupt or a crash loses all of it.  A sweep stores its points one by
one and ``--resume`` continues it, so its points are checked (in :mod:`sinktheory.sweep`,
inside :func:`resumable`) against the model's :data:`~sinktheory.model.MAX_SECONDS`
(30 days) each.  A refusal says both, and how to go bigger.

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> tangent_steps(particles=1, vectors=0), tangent_steps(particles=1, vectors=6)
(1.0, 2.8)
>>> max_seconds() / 86400
1.0
>>> with resumable():
...     max_seconds() / 86400
30.0
>>> settings, sink = RunSettings(runs=100, periods=10**6), Sink(Well(0.5, 0.3, 4))
>>> check_work(settings, sink, steps_per_period=10**5)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: periods = 1000000 is not allowed: must be smaller: at \
most 8.64e+11 particle steps (1 day) in a computation that cannot resume (...about 11.6 \
days); use fewer runs, periods or particles, or split the work into the points of a \
resumable `sinktheory sweep` (up to 30 days per point))
>>> with resumable():
...     check_work(settings, sink, steps_per_period=10**5)
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from contextvars import ContextVar

from .errors import ParameterError
from .limits import MAX_INTERACTIVE_SECONDS
from .model import MAX_SECONDS, SECONDS_PER_PARTICLE_STEP, RunSettings, Sink

__all__ = [
    "check_particle_steps",
    "check_work",
    "MAX_INTERACTIVE_SECONDS",
    "max_seconds",
    "resumable",
    "tangent_steps",
    "VECTOR_STEP",
]

#: Particle steps one deviation vector adds per particle and step, at least: the tangent
#: kick multiplies the vector by the particle's 2 x 2 Hessian block and the container
#: coupling (0.48 and 0.41 of a particle step measured for flat n = 4, k = 5 and 20 with
#: 22 and 82 vectors, by benchmarks/bench_worklimit.py at load 0.5); the lower value keeps
#: the limit optimistic.
VECTOR_STEP = 0.3


#: Whether the work being checked is a resumable sweep's (set by :func:`resumable`).
_RESUMABLE: ContextVar[bool] = ContextVar("sinktheory_resumable_work", default=False)


def tangent_steps(particles: int, vectors: int) -> float:
    """Particle steps of one integration step of one run with ``vectors`` deviation vectors.

    A vector has 2 (1 + 2k) components, so the vectors of a spectrum cost about the square
    of the dimension: ``k (1 + VECTOR_STEP x vectors)``.
    """
    return particles * (1.0 + VECTOR_STEP * vectors)


def max_seconds() -> float:
    """The work limit in force, in estimated seconds: :data:`MAX_INTERACTIVE_SECONDS`,
    or :data:`~sinktheory.model.MAX_SECONDS` inside :func:`resumable`."""
    return MAX_SECONDS if _RESUMABLE.get() else MAX_INTERACTIVE_SECONDS


@contextlib.contextmanager
def resumable() -> Iterator[None]:
    """Check work against the resumable limit (:data:`~sinktheory.model.MAX_SECONDS`)
    inside: for the points of a sweep, which are stored and resumed one by one."""
    token = _RESUMABLE.set(True)
    try:
        yield
    finally:
        _RESUMABLE.reset(token)


def _days(seconds: float) -> str:
    days = seconds / 86400
    return f"{days:.3g} day{'' if days == 1 else 's'}"


def check_particle_steps(name: str, value: object, steps: float, what: str) -> None:
    """Refuse ``value`` of ``name`` when ``steps`` particle steps (``what`` says of what)
    would take longer than the limit in force (:func:`max_seconds`) at the optimistic
    :data:`~sinktheory.model.SECONDS_PER_PARTICLE_STEP`; the message gives the estimate,
    the limit and the way to a larger job."""
    seconds = steps * SECONDS_PER_PARTICLE_STEP
    limit = max_seconds()
    if seconds <= limit:
        return
    if limit < MAX_SECONDS:
        where = "in a computation that cannot resume"
        bigger = (
            "use fewer runs, periods or particles, or split the work into the points of a "
            f"resumable `sinktheory sweep` (up to {_days(MAX_SECONDS)} per point)"
        )
    else:
        where = "per point of a sweep"
        bigger = "split it into more points (e.g. replica=0:9:10) or use fewer runs or periods"
    raise ParameterError(
        name,
        value,
        f"smaller: at most {limit / SECONDS_PER_PARTICLE_STEP:.3g} particle steps "
        f"({_days(limit)}) {where}",
        why=f"{what} is {steps:.3g} particle steps at {SECONDS_PER_PARTICLE_STEP:g} s each, "
        f"at least {seconds:.3g} s (about {_days(seconds)}); {bigger}",
    )


def check_work(settings: RunSettings, sink: Sink, steps_per_period: int) -> None:
    """Refuse an ensemble of ``settings`` over ``sink`` at ``steps_per_period`` that would
    exceed the work limit (:func:`check_particle_steps`), naming the larger of
    ``periods`` and ``runs``."""
    name = "periods" if settings.periods > settings.runs else "runs"
    check_particle_steps(
        name,
        getattr(settings, name),
        float(settings.runs) * settings.periods * steps_per_period * sink.particles,
        f"{settings.runs} run(s) x {settings.periods} period(s) x {steps_per_period} "
        f"step(s) x {sink.particles} particle(s)",
    )
