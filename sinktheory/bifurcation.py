"""Bifurcation (orbit) diagrams over beta for one particle (paper Figs. 3 and 11).

The section
-----------
For each beta the full coupled system (container + one particle, k = 1) is integrated
from the paper's start: container displaced to X = sqrt(2 E0) and released, particle at
rest at (x, y) = (0, 0.01) relative to the container (as in Fig. 4).  After a transient
of ``transient`` periods the stroboscopic section is sampled at t = jT (T = 2 pi, the
container's period) for ``count`` periods.  Two section quantities are offered:

* ``"y"`` (default): the particle's y relative to the container.  While the normal mode
  y = 0 is stable the particle stays near it and the section is a thin band around
  |y| <= 0.01; when the mode is unstable the particle wanders over the whole well and the
  section fills an interval of width ~ the well's reach.
* ``"energy"``: the container energy E(jT); regular motion returns few values, chaotic
  motion a cloud.

A diagram is a pure function of its parameters: the same input gives the same points.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from . import validation as v
from .ensemble import (
    ENERGY_BOUND,
    engine_name,
    engine_params,
    sink_of,
    split_values,
    start_state,
    total_energy,
)
from .errors import ParameterError
from .glossary import old_attribute, renamed
from .integrators import DEFAULT_SCHEME, get_scheme
from .layout import StateLayout
from .limits import MAX_PERIODS
from .model import RunSettings, Sink, Well
from .results import Result
from .simulate import simulate
from .stepsize import default_step, ladder_step, step_of
from .worklimit import check_particle_steps, check_work, ensemble_steps

__all__ = [
    "bifurcation",
    "BifurcationDiagram",
    "QUANTITIES",
    "sampled_run",
    "section",
    "section_step",
    "sections",
    "START",
    "well_bifurcation",
    "WellBifurcation",
]

QUANTITIES = ("y", "energy")
#: Start of the particle relative to the container (Fig. 4 of the paper).
START = (0.0, 0.01)


@renamed(energy="container_energy")
@dataclass(frozen=True)
class BifurcationDiagram(Result):
    """Section values (B, count) at each beta, with everything needed to redraw them
    (``to_dataset``: dims beta, sample); ``container_energy`` is E0 of every run."""

    beta: np.ndarray
    section: np.ndarray
    quantity: str
    alpha: float
    n: int
    gamma: float
    shape: str
    mass: float
    container_energy: float
    transient: int
    count: int

    energy = old_attribute("container_energy")

    DIMS = {"beta": ("beta",), "section": ("beta", "sample")}

    def coords(self) -> dict:
        """Samples are numbered from the end of the transient: j = transient + sample."""
        return {"sample": np.arange(1, self.count + 1)}


def sampled_run(sink: Sink, settings: RunSettings, start, *, per_period: int) -> np.ndarray:
    """One run from ``start`` = (x, y) (each particle at rest), its state sampled exactly
    ``per_period`` times per container period: rows (P * per_period + 1, 2 + 4k), columns
    as named by :class:`sinktheory.layout.StateLayout`.

    The step is the default one shortened so a period holds a multiple of
    ``per_period`` steps, so the samples fall on t = jT / per_period.
    """
    per_period = v.positive_int("per_period", per_period)
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    if not isinstance(settings, RunSettings):
        raise ParameterError("settings", settings, "a sinktheory.model.RunSettings")
    dt, steps = default_step(sink, settings.total_energy_bound(sink))
    steps = per_period * -(-steps // per_period)  # round up to a multiple
    res = simulate(
        sink,
        settings,
        initial=[start] * sink.particles,
        record=("trajectory",),
        dt=2 * np.pi / steps,
        stride=steps // per_period,
        progress=False,
    )
    if res.steps_per_period != steps:  # samples must fall exactly on t = jT / per_period
        raise AssertionError("trajectory stride does not match the period")
    return res.trajectory[0]


@renamed(energy="container_energy")
def section(
    sink: Sink,
    *,
    transient: int = 200,
    count: int = 200,
    quantity: str = "y",
    container_energy: float = 0.5,
) -> np.ndarray:
    """The stroboscopic section of one single-particle run (see the module docstring).

    Examples
    --------
    >>> s = section(Sink(Well(0.5, 0.3, 4), 1, 0.2), transient=2, count=3)
    >>> s.shape
    (3,)
    """
    return sections([sink], transient=transient, count=count, quantity=quantity,
                    container_energy=container_energy)[0]  # fmt: skip


@renamed(energy="container_energy")
def section_step(sink: Sink, container_energy: float = 0.5) -> tuple[float, int]:
    """(dt, steps per period) of a section run: the default scheme's step for the default
    tolerance at the start's energy, taken down to the ladder of
    :func:`sinktheory.stepsize.ladder_step` so that neighbouring betas share it."""
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    settings = RunSettings(container_energy=container_energy, runs=1, periods=1)
    bound = settings.total_energy_bound(sink)
    return ladder_step(default_step(sink, bound)[0])


def _check_work(sinks, steps, transient: int, count: int) -> None:
    """Refuse sections whose estimated work (``steps``: each well's steps per period)
    exceeds the limit of one computation (:func:`sinktheory.worklimit.check_particle_steps`)
    or whose record of states (6 numbers per run and period, with the inert runs a block
    plan may add: at most min(63, 3 R) per step count) exceeds the memory limit, naming
    ``count``."""
    periods = transient + count
    per_period, runs = np.unique(steps, return_counts=True)
    inert = int(np.minimum(63, 3 * runs).sum())
    rows = 48.0 * (len(sinks) + inert)  # bytes per recorded period
    v.fits_memory(
        "count",
        count,
        rows * (periods + 1),
        f"{len(sinks)} well(s) x {periods + 1} recorded period(s)",
        f"<= {max(1, int(v.memory_limit() // rows) - 1 - transient)} with transient = {transient}",
    )
    check_particle_steps(
        "count",
        count,
        sum(
            ensemble_steps(int(r), float(s) * periods, 1)
            for s, r in zip(per_period, runs, strict=True)
        ),
        f"{len(sinks)} well(s) x {periods} period(s) x up to {int(np.max(steps))} step(s) "
        "x 1 particle",
    )


@renamed(energy="container_energy")
def sections(
    sinks,
    *,
    transient: int = 200,
    count: int = 200,
    quantity: str = "y",
    container_energy: float = 0.5,
) -> np.ndarray:
    """Sections (B, count) of single-particle runs in several wells at once.

    The wells must share the engine (their shape; n may differ); the runs advance as one
    ensemble whose
    runs carry their own parameters and steps (:func:`section_step`), and each row is
    bitwise the section of its well alone.

    Examples
    --------
    >>> wells = [Sink(Well(0.5, b, 4), 1, 0.2) for b in (0.30, 0.301)]
    >>> both = sections(wells, transient=2, count=3)
    >>> bool((both[1] == section(wells[1], transient=2, count=3)).all())
    True
    """
    if isinstance(sinks, Sink) or not isinstance(sinks, Iterable):
        raise ParameterError("sinks", sinks, "a list of sinktheory.model.Sink objects")
    sinks = list(sinks)
    for sink in sinks:
        if not isinstance(sink, Sink):
            raise ParameterError("sinks", sink, "sinktheory.model.Sink objects")
        if sink.particles != 1:
            raise ParameterError("particles", sink.particles, "1 for a bifurcation diagram")
    transient = v.positive_int("transient", transient, minimum=0)
    count = v.positive_int("count", count)
    quantity = v.choice("quantity", quantity, QUANTITIES)
    if not sinks:
        raise ParameterError("sinks", "none", "at least one well")
    if len({engine_name(k) for k in sinks}) > 1:
        raise ParameterError("sinks", "wells of different shapes", "wells of one shape")
    energy = container_energy
    dt, steps = (np.array(x) for x in zip(*(section_step(k, energy) for k in sinks), strict=True))
    _check_work(sinks, steps, transient, count)
    values = [start_state(k, energy, np.array([[START]])) for k in sinks]
    for k, z in zip(sinks, values, strict=True):
        k.well.check_energy(float(total_energy(k, z)[0]), name="total_energy")
    q, vel = split_values(np.concatenate(values))
    params = np.stack([engine_params(k) for k in sinks], axis=1)
    from .engine.core import Ensemble  # numba loads when a section is computed

    ens = Ensemble(engine_name(sinks[0]), q, vel, params)
    rec = ens.run(
        get_scheme(DEFAULT_SCHEME),
        dt=dt,
        steps=steps,
        segments=transient + count,
        record=("trajectory",) if quantity == "y" else ("shared",),
        stride=steps,
        bound=ENERGY_BOUND,
        unit="period",
    )
    if quantity == "energy":
        return rec.shared[:, transient + 1 :]
    return rec.trajectory[:, transient + 1 :, StateLayout(1).y][:, :, 0]


@renamed(energy="container_energy")
def bifurcation(
    betas,
    *,
    alpha: float,
    n: int,
    gamma: float = 1.0,
    shape: str = "flat",
    mass: float = 0.2,
    container_energy: float = 0.5,
    transient: int = 200,
    count: int = 200,
    quantity: str = "y",
) -> BifurcationDiagram:
    """Sections for each beta in ``betas`` (one ensemble; see :mod:`sinktheory.sweep` for
    parallel and resumable sweeps), each run started with the container's energy
    ``container_energy`` (E0).

    Raises ParameterError naming ``beta`` if a value gives an invalid well.
    """
    betas = v.real_array("betas", betas, "a non-empty 1-D array of numbers")
    if betas.ndim != 1 or betas.size == 0:
        raise ParameterError("betas", f"array of shape {betas.shape}", "a non-empty 1-D array")
    sinks = [Sink(Well(alpha, b, n, gamma=gamma, shape=shape), 1, mass) for b in betas]
    energy = container_energy
    for s in sinks:  # refuse bad input before any long computation
        RunSettings(container_energy=energy, runs=1, periods=1).check(s)
    rows = sections(
        sinks, transient=transient, count=count, quantity=quantity, container_energy=energy
    )
    w = sinks[0].well
    return BifurcationDiagram(
        betas,
        rows,
        quantity,
        w.alpha,
        w.n,
        w.gamma,
        w.shape,
        mass,
        energy,
        transient,
        count,
    )


@dataclass(frozen=True)
class WellBifurcation(Result):
    """Sections (B, count) of a user's well over one of its own parameters
    (:func:`well_bifurcation`; ``to_dataset``: dims value, sample).

    Attributes
    ----------
    name : the well's name
    parameter : the parameter swept; ``value`` its values
    parameters : the other parameters' values (by name)
    section, quantity, mass, container_energy, transient, count : as in
        :class:`BifurcationDiagram`
    """

    name: str
    parameter: str
    value: np.ndarray
    section: np.ndarray
    parameters: dict
    quantity: str
    mass: float
    container_energy: float
    transient: int
    count: int

    DIMS = {"value": ("value",), "section": ("value", "sample")}

    def coords(self) -> dict:
        """Samples are numbered from the end of the transient: j = transient + sample."""
        return {"sample": np.arange(1, self.count + 1)}


def well_bifurcation(
    well,
    parameter: str,
    values,
    *,
    mass: float = 0.2,
    container_energy: float = 0.5,
    transient: int = 200,
    count: int = 200,
    quantity: str = "y",
) -> WellBifurcation:
    """Sections of a user's well (a :class:`~sinktheory.wellat.WellAt`) at each of
    ``values`` of its own parameter ``parameter`` (the others at the WellAt's values):
    the diagram :func:`bifurcation` draws over beta, from the same start, in one ensemble
    on the well's engine.  Each value is checked against the parameter's range and the
    well at it (a basin holding the start's energy) before anything runs.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> from sinktheory.wellat import WellAt
    >>> quartic = WellAt(UserWell("quartic", "(x**2 + y**2)/2 + c*(x**4 + y**4)", {"c": 1.0}))
    >>> well_bifurcation(quartic, "beta", [0.5, 1.0])
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: parameter = 'beta' is not allowed: must be one of 'c'

    ``well_bifurcation(quartic, "c", [0.5, 1.0])`` gives the sections (2, 200) at c = 0.5
    and 1 (its engine is compiled on the well's first use).
    """
    from .wellat import WellAt

    if not isinstance(well, WellAt):
        raise ParameterError("well", well, "a sinktheory.wellat.WellAt (a user's well at "
                             "its parameter values)")  # fmt: skip
    names = well.definition.parameter_names
    if not names:
        raise ParameterError("parameter", parameter, f"a parameter of the {well.shape} well",
                             why="it has none")  # fmt: skip
    parameter = v.choice("parameter", parameter, names)
    values = v.real_array("values", values, "a non-empty 1-D array of numbers")
    if values.ndim != 1 or values.size == 0:
        raise ParameterError("values", f"array of shape {values.shape}", "a non-empty 1-D array")
    fixed = {k: x for k, x in well.parameters.items() if k != parameter}
    sinks = [Sink(WellAt(well.definition, **fixed, **{parameter: float(x)}), 1, mass)
             for x in values]  # fmt: skip
    for s in sinks:  # refuse bad input before any long computation
        RunSettings(container_energy=container_energy, runs=1, periods=1).check(s)
    rows = sections(sinks, transient=transient, count=count, quantity=quantity,
                    container_energy=container_energy)  # fmt: skip
    return WellBifurcation(well.shape, parameter, values, rows, fixed, quantity,
                           sinks[0].mass, container_energy, transient, count)  # fmt: skip


# ----------------------------------------------------------------- sweep points
def check_point(p: dict) -> None:
    """Check a ``bifurcation`` sweep point (one particle; transient, count, quantity,
    energy) and its work."""
    sink = sink_of(p)
    if sink.particles != 1:
        raise ParameterError("particles", sink.particles, "1 for a bifurcation sweep")
    v.positive_int("transient", p["transient"], minimum=0, maximum=MAX_PERIODS)
    v.positive_int("count", p["count"], maximum=MAX_PERIODS)
    v.choice("quantity", p["quantity"], QUANTITIES)
    settings = RunSettings(
        container_energy=p["container_energy"], runs=1, periods=p["transient"] + p["count"]
    )
    settings.check(sink)
    # a well too stiff to integrate names the parameter responsible, and the section's
    # periods are checked against the work limit
    scheme, _, steps, _ = step_of(sink, p["container_energy"], settings=settings)
    check_work(settings, sink, steps, scheme)


def points(points: list) -> list[dict]:
    """Sections of a task's points, those sharing an engine and the section's settings as
    one ensemble whose runs carry their own parameters and steps
    (:func:`sinktheory.bifurcation.sections`)."""
    groups: dict[tuple, list[int]] = {}
    for i, (p, _) in enumerate(points):
        same = ("shape", "well", "n", "transient", "count", "quantity", "container_energy")
        key = tuple(p.get(name) for name in same)  # a user's well: its text, no shape
        groups.setdefault(key, []).append(i)
    out: list = [None] * len(points)
    for members in groups.values():
        first = points[members[0]][0]
        rows = sections(
            [sink_of(points[i][0]) for i in members],
            transient=first["transient"],
            count=first["count"],
            quantity=first["quantity"],
            container_energy=first["container_energy"],
        )
        for i, row in zip(members, rows, strict=True):
            out[i] = {"section": row}
    return out


from ._verbs import make_callable as _make_callable  # noqa: E402 (module complete here)

_make_callable(__name__, "bifurcation")
