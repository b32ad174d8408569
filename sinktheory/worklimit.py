"""Work limits checked before anything runs, naming the parameter responsible.

Two checks shared by the analyses that integrate ensembles (chaos indicators, design
points, sweep kinds, normal-mode continuation):

* :func:`step_of` -- the step for a tolerance, as :func:`sinktheory.stepsize.resolve_step`
  picks it, except that a well too stiff to integrate within
  :data:`~sinktheory.validation.MAX_STEPS_PER_PERIOD` steps per period names the model
  parameter that makes it so (``gamma = 1e308``, a tiny ``mass``), not a tolerance the
  caller never gave;
* :func:`check_particle_steps` -- the work of a computation in particle steps, tangent
  vectors included (:func:`tangent_steps`), against the model's limit: no computation
  that could not finish within :data:`~sinktheory.model.MAX_SECONDS` (30 days) at the
  optimistic :data:`~sinktheory.model.SECONDS_PER_PARTICLE_STEP` is started.

Examples
--------
>>> from sinktheory import Sink, Well
>>> step_of(Sink(Well(0.5, 0.3, 4, gamma=1e308)), 0.5)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: gamma = 1e+308 is not allowed: must be small enough that \
the well can be integrated ... (with gamma = 1 it can)
>>> tangent_steps(particles=1, vectors=0), tangent_steps(particles=1, vectors=6)
(1.0, 2.8)
"""

from __future__ import annotations

from dataclasses import replace

from .errors import ParameterError
from .model import MAX_SECONDS, SECONDS_PER_PARTICLE_STEP, RunSettings, Sink, Well
from .stepsize import DEFAULT_TOL, resolve_step
from .validation import MAX_STEPS_PER_PERIOD

#: Particle steps one deviation vector adds per particle and step, at least: the tangent
#: kick multiplies the vector by the particle's 2 x 2 Hessian block and the container
#: coupling (0.48 and 0.41 of a particle step measured for flat n = 4, k = 5 and 20 with
#: 22 and 82 vectors, by benchmarks/bench_worklimit.py at load 0.5); the lower value keeps
#: the limit optimistic.
VECTOR_STEP = 0.3

#: Defaults a too-stiff well is tried with, in order, to find the parameter responsible.
_SUSPECTS = (("gamma", 1.0), ("mass", 0.2), ("energy", 0.5))


def check_settings(settings: RunSettings, sink: Sink) -> None:
    """:meth:`~sinktheory.model.RunSettings.check`, with a start box so far out that its
    wall ratio overflows float range (``box = 1e308``) refused naming ``box`` too."""
    try:
        settings.check(sink)
    except OverflowError:
        raise ParameterError(
            "box", settings.box, "a half-width whose start box lies inside the walls"
        ) from None


def tangent_steps(particles: int, vectors: int) -> float:
    """Particle steps of one integration step of one run with ``vectors`` deviation vectors.

    A vector has 2 (1 + 2k) components, so the vectors of a spectrum cost about the square
    of the dimension: ``k (1 + VECTOR_STEP x vectors)``.
    """
    return particles * (1.0 + VECTOR_STEP * vectors)


def check_particle_steps(name: str, value: object, steps: float, what: str) -> None:
    """Refuse ``value`` of ``name`` when ``steps`` particle steps (``what`` says of what)
    would take longer than the model's limit at its optimistic speed."""
    seconds = steps * SECONDS_PER_PARTICLE_STEP
    if seconds > MAX_SECONDS:
        raise ParameterError(
            name,
            value,
            f"smaller: at most {MAX_SECONDS / SECONDS_PER_PARTICLE_STEP:.3g} particle steps "
            f"({MAX_SECONDS / 86400:.0f} days at {SECONDS_PER_PARTICLE_STEP:g} s each)",
            why=f"{what} is {steps:.3g} particle steps, at least {seconds:.3g} s "
            f"(about {seconds / 86400:.3g} days)",
        )


def step_of(
    sink: Sink,
    energy: float,
    *,
    method: str | None = None,
    dt: float | None = None,
    tol: float | None = None,
    settings: RunSettings | None = None,
) -> tuple[str, float, int, float | None]:
    """(method, dt, steps per period, tol) as :func:`~sinktheory.stepsize.resolve_step`,
    but a well too stiff for any step within the limit names the parameter responsible.

    The suspects (gamma, mass, total energy) are set one at a time to their defaults;
    the first whose default lets the tolerance be reached is named.  When none does, the
    tolerance is named if the caller gave it, else the stiffest parameter left (n).  With
    ``settings`` (the runs' E0 and start box) each trial's total energy is the bound
    :meth:`~sinktheory.model.RunSettings.total_energy_bound` of its own well (the
    particles' start energy scales with gamma), and E0 is the suspect ``energy``.
    """
    try:
        return resolve_step(sink, energy, method=method, dt=dt, tol=tol)
    except ParameterError as e:
        if e.name != "tol" or dt is not None:
            raise
        error = e
    limit = tol if tol is not None else DEFAULT_TOL
    w = sink.well
    e0 = energy if settings is None else settings.energy
    for name, default in _SUSPECTS:
        given = {"gamma": w.gamma, "mass": sink.mass, "energy": e0}[name]
        if given == default:
            continue
        values = {"gamma": w.gamma, "mass": sink.mass, "energy": e0, name: default}
        well = Well(w.alpha, w.beta, w.n, gamma=values["gamma"], shape=w.shape)
        trial = Sink(well, particles=sink.particles, mass=values["mass"])
        total = values["energy"]
        if settings is not None:
            total = replace(settings, energy=total).total_energy_bound(trial)
        try:
            well.check_energy(total)
            resolve_step(trial, total, method=method, tol=limit)
        except ParameterError:
            continue
        raise ParameterError(
            name,
            given,
            f"small enough that the well can be integrated to tol = {limit:g} in at most "
            f"{MAX_STEPS_PER_PERIOD:.0e} steps per period",
            why=f"with {name} = {default:g} it can",
        ) from None
    if tol is not None:
        raise error
    raise ParameterError(
        "n",
        w.n,
        f"a wall soft enough to integrate to tol = {limit:g} in at most "
        f"{MAX_STEPS_PER_PERIOD:.0e} steps per period",
    ) from None
