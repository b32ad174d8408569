"""Tolerance-driven choice of splitting scheme and step for the simulator.

The relative total-energy error of a symmetric splitting scheme of order p over a run of
the sink is modelled as

    err(h) = C_s (h omega_max)^p,    h omega_max <= cliff_s,

where omega_max is the fastest frequency the energy allows
(:func:`stiffness_frequency`).  C_s and the cliff (the largest product
before the high-order compositions lose their order near wall collisions, or resonate) are
measured by ``python benchmarks/calibrate_steps.py`` on the paper's workloads (flat
alpha = 1/2, beta in {-0.5, 0.3}, n in {4, 10}; symmetric alpha = 1, beta = 0.1, n = 6;
k in {1, 5}; m = 0.2; 2 runs x 300 periods): C_s is the largest err / (h omega)^p seen, an
envelope over the workloads rather than a fit, so the predicted error bounds what was
measured.  For a tolerance, every scheme gets the largest step its model allows, and the
scheme with the fewest force evaluations per period wins.

Where it stops being trustworthy: the calibration covers 1e-11 <= tol <= 1e-5 on wells of
the paper's kind over a few hundred to 1500 periods; outside (much longer runs, other
energies, k > 5, extreme n) the energy audit still guards every run, and a run over its
bound stops with :class:`~sinktheory.errors.EnergyDriftError` rather than returning numbers.

Examples
--------
>>> from sinktheory import Sink, Well
>>> c = choose(Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2), 0.5, 1e-8)
>>> c.scheme, c.steps_per_period > 100, bool(c.predicted_error <= 1e-8)
('blanes-moan6', True, True)
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from . import validation as v
from .errors import ParameterError
from .glossary import old_attribute, renamed
from .integrators import DEFAULT_SCHEME, SCHEMES, get_scheme
from .limits import DEFAULT_TOL, TOL_RANGE

__all__ = [
    "aligned_step",
    "CALIBRATION",
    "check_tol",
    "choose",
    "cost_table",
    "default_step",
    "DEFAULT_TOL",
    "LADDER_RUNGS",
    "ladder_step",
    "PERIOD",
    "resolve_step",
    "step_for",
    "step_of",
    "StepChoice",
    "stiffness_frequency",
    "TOL_RANGE",
]

if TYPE_CHECKING:
    from .model import RunSettings, Sink

#: The container's period T = 2 pi (mass 1, spring 1).
PERIOD = 2.0 * math.pi

#: (C_s, cliff_s) per scheme, from ``python benchmarks/calibrate_steps.py 300`` on the new
#: engine (2026-11-23, 2445 s on the 2-core development machine; the raw worst errors per
#: step x frequency product are printed by the script).
CALIBRATION: dict[str, tuple[float, float]] = {
    "verlet": (3.08e-2, 0.03),
    "yoshida4": (1.30e-2, 0.2),
    "blanes-moan4": (7.56e-6, 0.6),
    "yoshida6": (8.76e-4, 0.4),
    "blanes-moan6": (2.24e-7, 0.9),
    "suzuki-umeno8": (2.89e-6, 0.65),
}


@renamed(energy="total_energy")
def stiffness_frequency(sink: Sink, total_energy: float, *, angles: int = 46) -> float:
    """Fastest oscillation frequency the ``total_energy`` allows (an upper estimate;
    remembered per sink and energy, since every ``simulate`` call asks and the search
    costs about 10 ms).

    No particle can hold more potential energy than the total, so it stays in the basin
    V <= energy.  The deepest penetration of the wall is on the basin's boundary: along
    ``angles`` rays in the quadrant x, y >= 0 (V is even in x and in y) the first crossing
    V = energy is located (grid, then bisection), and there the largest eigenvalue of the
    Hessian (generated kernel) is taken.  The particle's relative coordinate oscillates
    with the reduced mass mu M/(mu + M), M = 1, so omega^2 = lambda_max (1/mu + 1).  The
    container's own frequency is 1.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> w = stiffness_frequency(Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2), 0.5)
    >>> 50 < w < 500
    True
    """
    from .model import Sink

    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    energy = v.positive("total_energy", total_energy)
    return _stiffness_frequency(sink, energy, v.positive_int("angles", angles, maximum=10**5))


@functools.lru_cache(maxsize=1024)
def _stiffness_frequency(sink: Sink, energy: float, angles: int) -> float:
    """:func:`stiffness_frequency` of checked arguments."""
    from .model import Well

    well = sink.well
    x_max, y_max = well.reach(energy)
    # a registered shape is even in x and in y: one quadrant; a user's well: every direction
    quadrant = isinstance(well, Well)
    theta = np.linspace(0.0, (0.5 if quadrant else 2.0) * math.pi, angles if quadrant
                        else 4 * angles)[:, None]  # fmt: skip
    radius = np.linspace(0.0, math.hypot(x_max, y_max), 400)[None, :]
    with np.errstate(over="ignore"):  # far out V overflows to inf: outside, as it should
        inside = well.potential(radius * np.cos(theta), radius * np.sin(theta)) <= energy
        first_out = np.argmin(inside, axis=1)  # the basin is star-shaped enough: first exit
        lo, hi = radius[0, first_out - 1], radius[0, first_out]
        for _ in range(40):
            mid = 0.5 * lo + 0.5 * hi  # the same bits as (lo + hi) / 2, without overflow
            x, y = mid * np.cos(theta[:, 0]), mid * np.sin(theta[:, 0])
            below = well.potential(x, y) <= energy
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
    largest = 0.0
    hessian = well.kernels.hessian if quadrant else None  # looked up once, not per ray
    for r, t in zip(hi, theta[:, 0], strict=True):
        if quadrant:
            vxx, vxy, vyy = hessian(
                r * math.cos(t), r * math.sin(t), well.alpha, well.beta, well.gamma, well.n
            )
            h = [[vxx, vxy], [vxy, vyy]]
        else:
            h = well.hessian_at(r * math.cos(t), r * math.sin(t))
        largest = max(largest, float(np.linalg.eigvalsh(h)[-1]))
    omega = math.sqrt(largest * (1.0 / sink.mu + 1.0))
    if not math.isfinite(omega):
        raise ParameterError("total_energy", energy, "an energy whose wall stiffness is finite")
    return max(1.0, omega)


def aligned_step(dt: float) -> tuple[float, int]:
    """The largest step <= dt dividing T = 2 pi evenly, and the number of steps per period."""
    steps = max(1, math.ceil(PERIOD / v.positive("dt", dt) - 1e-9))
    return PERIOD / steps, steps


#: Steps per period on the ladder of :func:`ladder_step` are ceil(2^(j / LADDER_RUNGS)).
LADDER_RUNGS = 8


def ladder_step(dt: float) -> tuple[float, int]:
    """The largest step <= dt whose number of steps per period is on a geometric ladder
    ceil(2^(j/8)), and that number.

    Points of a sweep whose stiffness differs a little then take the same step and can
    advance together as one ensemble (the chaos sweep does this); the ladder costs at most
    2^(1/8) - 1 = 9 % more steps than :func:`aligned_step`, never a larger step.

    Examples
    --------
    >>> [ladder_step(2 * math.pi / s)[1] for s in (100, 101, 108, 109)]  # 2^(54/8) = 107.6
    [108, 108, 108, 118]
    """
    needed = aligned_step(dt)[1]
    j = max(0, math.floor(LADDER_RUNGS * math.log2(needed)) - 1)
    while math.ceil(2.0 ** (j / LADDER_RUNGS)) < needed:
        j += 1
    steps = math.ceil(2.0 ** (j / LADDER_RUNGS))
    return PERIOD / steps, steps


@dataclass(frozen=True)
class StepChoice:
    """The scheme and step picked for a tolerance, with the model's predicted error."""

    scheme: str
    dt: float
    steps_per_period: int
    h_omega: float
    predicted_error: float
    force_evaluations_per_period: int

    method = old_attribute("scheme")


def check_tol(tol: float) -> float:
    """``tol`` as a float inside :data:`TOL_RANGE` (ParameterError naming ``tol`` otherwise)."""
    tol = v.positive("tol", tol)
    lo, hi = TOL_RANGE
    if not lo <= tol <= hi:
        raise ParameterError("tol", tol, f"between {lo:g} and {hi:g}")
    return tol


@renamed(method="scheme")
def step_for(scheme: str, omega: float, tol: float) -> StepChoice:
    """The largest step of ``scheme`` whose modelled error at ``omega`` is <= ``tol``."""
    scheme = get_scheme(scheme)
    omega, tol = v.positive("omega", omega), check_tol(tol)
    C, cliff = CALIBRATION[scheme.name]
    h_omega = min(cliff, (tol / C) ** (1.0 / scheme.order))
    if not math.isfinite(PERIOD * omega / h_omega):
        raise ParameterError("omega", omega, "a frequency whose steps per period are a float "
                             f"(at {h_omega:.3g} radians a step)")  # fmt: skip
    dt, steps = aligned_step(h_omega / omega)
    h_used = dt * omega
    return StepChoice(
        scheme.name,
        dt,
        steps,
        h_used,
        C * h_used**scheme.order,
        steps * scheme.stages,
    )


@renamed(method="scheme", energy="total_energy")
def default_step(
    sink: Sink, total_energy: float, scheme: str = DEFAULT_SCHEME, tol: float = DEFAULT_TOL
) -> tuple[float, int]:
    """(dt, steps per period) of ``scheme`` for relative energy error ``tol``.

    The step comes from the scheme's calibrated error model at the fastest frequency the
    ``total_energy`` allows (:func:`step_for`); dt is shortened so a
    period T = 2 pi is a whole number of steps and E(jT) is sampled exactly at t = jT.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> dt, steps = default_step(Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2), 0.5)
    >>> import math
    >>> abs(dt * steps - 2 * math.pi) < 1e-12
    True
    """
    choice = choose(sink, total_energy, tol, scheme)
    return choice.dt, choice.steps_per_period


@renamed(methods="schemes", energy="total_energy")
def cost_table(sink: Sink, total_energy: float, tol: float, schemes=None) -> list[StepChoice]:
    """Each scheme's largest step for ``tol`` at ``total_energy`` in ``sink`` (of
    ``schemes``, default all), cheapest (fewest force evaluations per period) first."""
    tol = check_tol(tol)
    omega = stiffness_frequency(sink, total_energy)
    if schemes is not None and (isinstance(schemes, str) or not isinstance(schemes, list | tuple)):
        raise ParameterError("schemes", schemes, "None or a list of scheme names")
    options = [step_for(name, omega, tol) for name in (schemes or SCHEMES)]
    return sorted(options, key=lambda c: (c.force_evaluations_per_period, c.scheme))


@renamed(method="scheme", energy="total_energy")
def choose(sink: Sink, total_energy: float, tol: float, scheme: str | None = None) -> StepChoice:
    """The cheapest scheme and step reaching relative energy error ``tol`` (or the step of
    ``scheme`` if given), for ``total_energy`` in ``sink``."""
    return cost_table(sink, total_energy, tol, None if scheme is None else [scheme])[0]


@renamed(method="scheme", energy="total_energy")
def resolve_step(
    sink: Sink,
    total_energy: float,
    *,
    scheme: str | None = None,
    dt: float | None = None,
    tol: float | None = None,
) -> tuple[str, float, int, float | None]:
    """(scheme, dt, steps per period, tol) from what a caller asked for.

    ``dt`` overrides the tolerance (and then ``scheme`` defaults to
    :data:`~sinktheory.integrators.DEFAULT_SCHEME`, tol is None); otherwise ``tol``
    (default :data:`DEFAULT_TOL`) picks the step of ``scheme`` or, without one, the
    cheapest scheme.  Giving both ``dt`` and ``tol`` is refused.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> m, dt, steps, tol = resolve_step(Sink(Well(0.5, 0.3, 4), 5, 0.2), 0.5)
    >>> m, tol, abs(dt * steps - PERIOD) < 1e-12
    ('blanes-moan6', 1e-08, True)
    """
    if dt is not None and tol is not None:
        raise ParameterError("tol", tol, "None when dt is given (dt overrides the tolerance)")
    if dt is not None:
        dt, steps = aligned_step(v.time_step("dt", dt))
        return get_scheme(scheme or DEFAULT_SCHEME).name, dt, steps, None
    tol = DEFAULT_TOL if tol is None else check_tol(tol)
    choice = choose(sink, total_energy, tol, scheme)
    if choice.steps_per_period > v.MAX_STEPS_PER_PERIOD:
        raise ParameterError(
            "tol", tol, "a tolerance this well reaches in at most 1e9 steps per period"
        )
    return choice.scheme, choice.dt, choice.steps_per_period, tol


#: Defaults a too-stiff well is tried with, in order, to find the parameter responsible.
_SUSPECTS = (("gamma", 1.0), ("mass", 0.2), ("total_energy", 0.5))


@renamed(method="scheme", energy="total_energy")
def step_of(
    sink: Sink,
    total_energy: float,
    *,
    scheme: str | None = None,
    dt: float | None = None,
    tol: float | None = None,
    settings: RunSettings | None = None,
) -> tuple[str, float, int, float | None]:
    """(scheme, dt, steps per period, tol) as :func:`~sinktheory.stepsize.resolve_step`,
    but a well too stiff for any step within the limit names the parameter responsible.

    The suspects (gamma, mass, total energy) are set one at a time to their defaults;
    the first whose default lets the tolerance be reached is named.  When none does, the
    tolerance is named if the caller gave it, else the stiffest parameter left (n).  With
    ``settings`` (the runs' E0 and start box) each trial's total energy is the bound
    :meth:`~sinktheory.model.RunSettings.total_energy_bound` of its own well (the
    particles' start energy scales with gamma), and E0 is the suspect, named
    ``container_energy``.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> step_of(Sink(Well(0.5, 0.3, 4, gamma=1e308)), 0.5)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: gamma = 1e+308 is not allowed: must be small enough \
that the well can be integrated ... (with gamma = 1 it can)
    """
    from .model import Sink, Well  # the model's kernels load only for a diagnosis

    try:
        return resolve_step(sink, total_energy, scheme=scheme, dt=dt, tol=tol)
    except ParameterError as e:
        if e.name not in ("tol", "omega") or dt is not None or not isinstance(sink.well, Well):
            raise  # (a user's well: its parameters are its own, no suspects to try)
        error = e
    limit = tol if tol is not None else DEFAULT_TOL
    w = sink.well
    e0 = total_energy if settings is None else settings.container_energy
    for name, default in _SUSPECTS:
        given = {"gamma": w.gamma, "mass": sink.mass, "total_energy": e0}[name]
        if given == default:
            continue
        values = {"gamma": w.gamma, "mass": sink.mass, "total_energy": e0, name: default}
        well = Well(w.alpha, w.beta, w.n, gamma=values["gamma"], shape=w.shape)
        trial = Sink(well, particles=sink.particles, mass=values["mass"])
        total = values["total_energy"]
        if settings is not None:
            total = replace(settings, container_energy=total).total_energy_bound(trial)
        try:
            well.check_energy(total)
            resolve_step(trial, total, scheme=scheme, tol=limit)
        except ParameterError:
            continue
        if name == "total_energy" and settings is not None:
            name = "container_energy"  # E0, as the runs' settings and a sweep name it
        raise ParameterError(
            name,
            given,
            f"small enough that the well can be integrated to tol = {limit:g} in at most "
            f"{v.MAX_STEPS_PER_PERIOD:.0e} steps per period",
            why=f"with {name} = {default:g} it can",
        ) from None
    if tol is not None:
        raise error
    raise ParameterError(
        "n",
        w.n,
        f"a wall soft enough to integrate to tol = {limit:g} in at most "
        f"{v.MAX_STEPS_PER_PERIOD:.0e} steps per period",
    ) from None
