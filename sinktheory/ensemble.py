"""Ensemble set-up, shared by every stepper: where the runs start and what a run records.

The fixed-step simulator (:func:`sinktheory.simulate.simulate`) and the adaptive step
(:func:`sinktheory.adaptive.simulate_adaptive`) start their runs here, in one way: the
container at X = sqrt(2 E0) at rest and the particles at rest at seeded random (or given)
positions, or a previous result's :class:`SimulationState`; and they report through the
same :class:`SimulationResult` with the same ``parameters``.  The state rows and the
engine's (q, v) arrays convert through :class:`sinktheory.layout.StateLayout`.

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> sink = Sink(Well(alpha=0.5, beta=0.3, n=4), particles=2, mass=0.2)
>>> values, t0, h0 = initial_values(sink, RunSettings(runs=3, seed=1), None, None)
>>> values.shape, t0, bool(np.allclose(h0, 0.5))
((3, 10), 0.0, True)
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from . import validation as v
from .errors import ParameterError
from .glossary import old_attribute, renamed
from .integrators import get_scheme
from .layout import StateLayout, pack_params
from .model import RunSettings, Sink, Well
from .results import Result
from .runstats import ensemble_mean
from .stepsize import DEFAULT_TOL, check_tol
from .validation import real_array  # join_values has a parameter v

__all__ = [
    "check_sink",
    "ENERGY_BOUND",
    "engine_name",
    "engine_params",
    "join_values",
    "prepare",
    "random_positions",
    "RECORDS",
    "run_parameters",
    "SimulationResult",
    "SimulationState",
    "split_values",
    "Start",
    "start_state",
    "total_energy",
]

#: What :func:`sinktheory.simulate.simulate` can record.
RECORDS = ("container", "particles", "trajectory", "final")
#: Default bound on the relative total-energy error before a run is stopped.
ENERGY_BOUND = 1e-6


def default_energy_bound(tol: float | None) -> float:
    """The ``energy_bound`` of :func:`simulate` when none is given: :data:`ENERGY_BOUND`,
    or 100 tol when that is larger (tol None: the default tolerance).

    Examples
    --------
    >>> default_energy_bound(None), default_energy_bound(1e-5)
    (1e-06, 0.001)
    """
    return max(ENERGY_BOUND, 100.0 * (tol or DEFAULT_TOL))


def _method(result) -> str | None:
    """What ``method`` said before it was split: the stepper "adaptive", else the fixed
    stepper's scheme."""
    return "adaptive" if result.stepper == "adaptive" else result.scheme


@renamed(method="scheme")
@dataclass(frozen=True)
class SimulationState(Result):
    """The state of every run at one instant, enough to continue exactly where it stopped.

    ``values`` has shape (R, 2 + 4k), columns [X, Xdot, u_1..u_k, y_1..y_k, udot_1..udot_k,
    ydot_1..ydot_k] (u_j = X + x_j is the particle's absolute x; velocities are absolute),
    named by :class:`sinktheory.layout.StateLayout`.
    ``reference_energy`` is each run's total energy at the start of the whole simulation, so
    the energy audit of a continued run still measures the drift from the very beginning.
    ``scheme`` is the splitting scheme the runs were stepped with, ``stepper`` how (fixed
    or adaptive).  ``controller`` (R, 2), stepper "adaptive" only: each run's step rate rho
    and the part of a step still to take, so that a continued run takes the steps it would
    have taken.  A state made before ``method`` was split in two (``method="adaptive"``, or
    "adaptive" where the scheme now stands) is an adaptive state whose scheme was not
    recorded (None).  A state made by hand (a start on an energy shell) may give ``dt`` 0
    and ``scheme`` "": not stepped yet.  The fields are checked on construction
    (ParameterError naming the field); non-finite ``values`` are kept, for
    :func:`initial_values` to refuse as a start.
    """

    values: np.ndarray
    time: float
    reference_energy: np.ndarray
    dt: float
    scheme: str | None
    controller: np.ndarray | None = None
    stepper: str = "fixed"

    method = old_attribute("stepper", "scheme", read=_method)

    DIMS = {
        "values": ("run", "state"),
        "reference_energy": ("run",),
        "controller": ("run", "controller_value"),
    }

    @property
    def layout(self) -> StateLayout:
        return StateLayout.of(self.values)

    @property
    def particles(self) -> int:
        return self.layout.particles

    def relative_positions(self) -> np.ndarray:
        """Particle positions (x_j, y_j) in the container's frame, shape (R, k, 2)."""
        return self.layout.relative_positions(self.values)

    def __post_init__(self) -> None:
        if self.scheme == "adaptive":  # the stepper, as an old state's method named it
            object.__setattr__(self, "stepper", "adaptive")
            object.__setattr__(self, "scheme", None)
        values = real_array("values", self.values, "state rows (R, 2 + 4k)")
        if values.ndim != 2 or values.shape[0] < 1:
            raise ParameterError("values", f"an array of shape {values.shape}", "rows (R, 2 + 4k)")
        StateLayout.of(values)  # 2 + 4k columns
        runs = values.shape[0]
        reference = v.finite_array("reference_energy", self.reference_energy,
                                   f"{runs} finite energies, one per run", ndim=1)  # fmt: skip
        if reference.shape != (runs,):
            raise ParameterError(
                "reference_energy", f"an array of shape {reference.shape}", f"shape ({runs},)"
            )
        object.__setattr__(self, "values", values)
        object.__setattr__(self, "reference_energy", reference)
        object.__setattr__(self, "time", v.finite("time", self.time))
        object.__setattr__(self, "dt", v.nonnegative("dt", self.dt))
        if self.scheme not in (None, ""):
            get_scheme(self.scheme)
        v.choice("stepper", self.stepper, ("fixed", "adaptive"))
        if self.controller is not None:
            allowed = f"an array ({runs}, 2) of each run's rate and step part"
            controller = v.finite_array("controller", self.controller, allowed, ndim=2)
            if controller.shape != (runs, 2):
                raise ParameterError("controller", f"an array of shape {controller.shape}", allowed)
            object.__setattr__(self, "controller", controller)

    def coords(self) -> dict:
        return {"state": list(self.layout.names())}


@dataclass(frozen=True)
class SimulationResult(Result):
    """What :func:`simulate` recorded (``as_dict`` / ``to_dataset``: dims run, time,
    particle, sample, state; the ensemble mean and standard error included).

    Attributes
    ----------
    times : ndarray (P + 1,)
        t_j = t_0 + j T, the instants of the per-period records.
    container_energy : ndarray (R, P + 1) or None
        E(t_j) = (Xdot^2 + X^2)/2 of every run (record "container").
    particle_energy : ndarray (R, P + 1, k) or None
        e_j(t_j) = mu/2 |absolute velocity|^2 + V(x_j, y_j) (record "particles"); container +
        particles = the conserved total energy.
    trajectory : ndarray (R, S, 2 + 4k) or None
        States every ``stride`` steps, columns as in :class:`SimulationState` (record
        "trajectory"); ``trajectory_times`` gives their times.
    final_state : SimulationState or None
        State at the end (record "final"); pass it as ``initial_state`` to continue.
    initial_energy : ndarray (R,)
        Total energy H of each run at the start of the simulation (audit reference).
    run_errors : ndarray (R,)
        Largest relative total-energy error of each run, checked at every period end.
    max_relative_energy_error : float
        Largest of ``run_errors``.
    stepper, scheme, dt, steps_per_period : the integrator used: the stepper (fixed or
        adaptive), its splitting scheme and the step (dt = T / steps_per_period; the mean
        step for the adaptive stepper).
    message : str
        One line summarising the run and its audit.
    tol : float or None
        The tolerance the step was chosen for (None when ``dt`` was given).
    parameters : dict
        What was run: the well, k, m, E0, runs, periods, seed, box.
    """

    times: np.ndarray
    container_energy: np.ndarray | None
    particle_energy: np.ndarray | None
    trajectory: np.ndarray | None
    trajectory_times: np.ndarray | None
    final_state: SimulationState | None
    initial_energy: np.ndarray
    run_errors: np.ndarray
    max_relative_energy_error: float
    stepper: str
    scheme: str
    dt: float
    steps_per_period: int
    message: str
    tol: float | None = None
    parameters: dict = field(default_factory=dict)

    method = old_attribute("stepper", "scheme", read=_method)

    DIMS = {
        "container_energy": ("run", "time"),
        "particle_energy": ("run", "time", "particle"),
        "trajectory": ("run", "sample", "state"),
        "initial_energy": ("run",),
        "run_errors": ("run",),
        "mean_energy": ("time",),
        "stderr": ("time",),
    }
    COORDS = {"times": "time", "trajectory_times": "sample"}

    def items(self) -> dict:
        out = super().items()
        if self.container_energy is not None:
            out["mean_energy"], out["stderr"] = self.ensemble_energy()
        return out

    def coords(self) -> dict:
        out = {"run": np.arange(self.run_errors.size)}
        if self.particle_energy is not None:
            out["particle"] = np.arange(1, self.particle_energy.shape[-1] + 1)
        if self.trajectory is not None:
            out["state"] = list(StateLayout.of(self.trajectory).names())
        return out

    def ensemble_energy(self) -> tuple[np.ndarray, np.ndarray]:
        """Ensemble mean <E>(t_j) and its standard error (ddof = 1; NaN for one run:
        :mod:`sinktheory.runstats`)."""
        return ensemble_mean(self.container_energy)


def random_positions(settings: RunSettings, particles: int) -> np.ndarray:
    """Starting positions (R, k, 2), uniform in (-box, box)^2, one child seed per run.

    Run r always gets ``SeedSequence(seed).spawn(R)[r]``, so its positions depend only on the
    seed and r, not on how runs are later spread over threads.

    Examples
    --------
    >>> p = random_positions(RunSettings(runs=3, seed=7), 2)
    >>> p.shape, bool(np.all(np.abs(p) < 0.01))
    ((3, 2, 2), True)
    """
    settings = _settings(settings)
    particles = v.positive_int("particles", particles, maximum=1000)  # as a Sink's
    v.fits_memory("particles", particles, 16.0 * settings.runs * particles,
                  "the starting positions", "fewer particles or runs")  # fmt: skip
    children = np.random.SeedSequence(settings.seed).spawn(settings.runs)
    return np.stack(
        [
            np.random.default_rng(c).uniform(-settings.box, settings.box, size=(particles, 2))
            for c in children
        ]
    )


@renamed(energy="container_energy")
def start_state(sink: Sink, container_energy: float, positions: np.ndarray) -> np.ndarray:
    """State rows (R, 2 + 4k): container at X = sqrt(2 E0) at rest (E0 =
    ``container_energy``), particles at rest at ``positions`` (R, k, 2) relative to the
    container ((R, 1, 2): every particle of a run at one place)."""
    k = _sink(sink).particles
    e0 = v.positive("container_energy", container_energy)
    if not math.isfinite(2.0 * e0):
        raise ParameterError("container_energy", container_energy, "a number > 0 with 2 E0 finite")
    positions = v.finite_array("positions", positions, "finite positions of shape (R, k, 2)")
    if positions.ndim != 3 or positions.shape[1:] not in ((k, 2), (1, 2)) or not positions.size:
        raise ParameterError(
            "positions", f"an array of shape {positions.shape}", f"shape (R, {k}, 2) or (R, 1, 2)"
        )
    return StateLayout(k).start(math.sqrt(2.0 * e0), positions)


def total_energy(sink: Sink, values: np.ndarray) -> np.ndarray:
    """Total energy H of each state row (R, 2 + 4k) (generated energy kernel)."""
    return _engine_energies(sink, _rows(sink, values))[0]


def engine_name(sink: Sink) -> str:
    """Name of the generated engine of this sink's well: its shape's, or a user's well's
    (:func:`sinktheory.engine.cache.well_name`); n, k and the rest are run-time values."""
    from .engine.cache import sink_name, well_name  # numba loads when first needed

    if isinstance(_sink(sink).well, Well):
        return sink_name(sink.well.shape)
    return well_name(sink.well.definition)


#: The engine's runtime parameters of a sink, packed (:data:`sinktheory.layout.SINK_PARAMS`).
engine_params = pack_params


def split_values(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """State rows (R, 2 + 4k) as the engine's (q, v), each (1 + 2k, R)."""
    return StateLayout.of(values).split(values)


def join_values(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The engine's (q, v) as state rows (R, 2 + 4k): [X, Xdot, u.., y.., udot.., ydot..]."""
    allowed = "an array (1 + 2k, R) of real numbers, k >= 1, R >= 1"  # a state that blew
    q = real_array("q", q, allowed)  # up is joined as it is, for the audit to report
    if q.ndim != 2 or q.shape[0] < 3 or q.shape[0] % 2 == 0 or q.shape[1] < 1:
        raise ParameterError("q", f"an array of shape {q.shape}", allowed)
    velocities = real_array("v", v, f"an array of shape {q.shape} (as q)")
    if velocities.shape != q.shape:
        raise ParameterError(
            "v", f"an array of shape {velocities.shape}", f"shape {q.shape} (as q)"
        )
    return StateLayout((q.shape[0] - 1) // 2).join(q, velocities)


def _engine_energies(sink: Sink, values: np.ndarray):
    """(total (R,), container (R,), particles (R, k)) from the generated energy kernel."""
    q, v = split_values(values)
    from .engine.core import Ensemble

    ens = Ensemble(engine_name(sink), q, v, engine_params(sink))
    total, shared, members = ens.energies()
    return total, shared, members.T


def run_parameters(sink: Sink, settings: RunSettings, runs: int) -> dict:
    """What a simulation ran, as its result's ``parameters``: the well, k, m, E0, runs,
    periods, seed, box."""
    w, settings = _sink(sink).well, _settings(settings)
    runs = v.positive_int("runs", runs)
    well = ({"alpha": w.alpha, "beta": w.beta, "n": w.n, "gamma": w.gamma}
            if isinstance(w, Well) else dict(w.parameters))  # fmt: skip
    return {
        "shape": w.shape, **well,
        "particles": sink.particles, "mass": sink.mass,
        "container_energy": settings.container_energy, "runs": runs,
        "periods": settings.periods, "seed": settings.seed, "box": settings.box,
    }  # fmt: skip


def check_record(record: Sequence[str], allowed: tuple[str, ...] = RECORDS) -> tuple[str, ...]:
    """``record`` as a tuple of names from ``allowed`` (one name may be given alone)."""
    if isinstance(record, str):
        record = (record,)
    try:
        names = tuple(record)
    except TypeError:
        raise ParameterError("record", record, f"names from {', '.join(allowed)}") from None
    return tuple(v.choice("record", r, allowed) for r in names)


def start_positions(sink: Sink, settings: RunSettings, initial=None) -> np.ndarray:
    """Particle positions (R, k, 2) relative to the container: ``initial`` if given (shape
    (k, 2) for one run or (R, k, 2)), else the seeded random ones of
    :func:`random_positions`.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> start_positions(Sink(Well(0.5, 0.3, 4), 2, 0.2), RunSettings(runs=1), [(0, 0.01)] * 2)
    array([[[0.  , 0.01],
            [0.  , 0.01]]])
    """
    k = sink.particles
    if initial is None:
        settings.check(sink)
        return random_positions(settings, k)
    positions = v.real_array("initial", initial)
    if positions.shape == (k, 2):
        positions = positions[None]
    if positions.shape != (settings.runs, k, 2):
        raise ParameterError(
            "initial",
            f"an array of shape {positions.shape}",
            f"positions of shape ({k}, 2) (for runs = 1) or ({settings.runs}, {k}, 2)",
        )
    if not np.all(np.isfinite(positions)):
        raise ParameterError("initial", "non-finite positions", "finite numbers")
    for x, y in positions.reshape(-1, 2):  # as the command line checks --initial
        sink.well.check_position("initial", x, y)
    return positions


def initial_values(sink, settings, initial, initial_state):
    """(values, t0, reference energy) from exactly one of the three starting modes: seeded
    random positions, given positions ``initial``, or a previous ``initial_state``."""
    k = sink.particles
    if initial is not None and initial_state is not None:
        raise ParameterError("initial", "positions", "None when initial_state is given")
    if initial_state is not None:
        if not isinstance(initial_state, SimulationState):
            raise ParameterError("initial_state", initial_state, "a SimulationState")
        if initial_state.particles != k:
            raise ParameterError(
                "initial_state",
                f"{initial_state.particles} particle(s)",
                f"a state with {k} particle(s), as the sink has",
            )
        values = np.array(initial_state.values, dtype=float)
        if not np.all(np.isfinite(values)):
            raise ParameterError("initial_state", "a state with non-finite values", "finite")
        sink.well.check_energy(float(np.max(total_energy(sink, values))), name="total_energy")
        return values, initial_state.time, np.array(initial_state.reference_energy)
    values = start_state(sink, settings.container_energy, start_positions(sink, settings, initial))
    h0 = total_energy(sink, values)
    sink.well.check_energy(float(np.max(h0)), name="total_energy")
    return values, 0.0, h0


@dataclass(frozen=True)
class Start:
    """An ensemble checked and placed at its start (:func:`prepare`).

    ``values`` (R, 2 + 4k) are the state rows at time ``time``; ``reference_energy`` (R,)
    is each run's total energy at the start of the whole simulation (the audit's
    reference); ``bound`` the relative energy error tolerated; ``record`` what to keep.
    """

    settings: RunSettings
    record: tuple[str, ...]
    bound: float
    values: np.ndarray
    time: float
    reference_energy: np.ndarray

    @property
    def runs(self) -> int:
        return self.values.shape[0]


def check_sink(sink, settings) -> RunSettings:
    """``settings`` (a new :class:`RunSettings` when None) after checking both types."""
    _sink(sink)
    return _settings(RunSettings() if settings is None else settings)


def _sink(sink) -> Sink:
    """``sink`` if it is a :class:`~sinktheory.model.Sink`, else a ParameterError."""
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    return sink


def _settings(settings) -> RunSettings:
    """``settings`` if it is a :class:`~sinktheory.model.RunSettings`, else a ParameterError."""
    if not isinstance(settings, RunSettings):
        raise ParameterError("settings", settings, "a sinktheory.model.RunSettings")
    return settings


def _rows(sink: Sink, values) -> np.ndarray:
    """``values`` as state rows (R, 2 + 4k) of finite numbers for ``sink``'s k particles,
    else a ParameterError naming ``values``."""
    width = 2 + 4 * _sink(sink).particles
    allowed = f"state rows (R, {width}) of finite numbers, R >= 1"
    rows = v.finite_array("values", values, allowed, ndim=2)
    if rows.shape[1] != width or rows.shape[0] < 1:
        raise ParameterError("values", f"an array of shape {rows.shape}", allowed)
    return rows


def prepare(
    sink: Sink,
    settings: RunSettings | None,
    record: Sequence[str],
    *,
    initial=None,
    initial_state=None,
    energy_bound: float | None = None,
    tol: float | None = None,
    allowed: tuple[str, ...] = RECORDS,
) -> Start:
    """Check what every stepper checks and place the runs at their start.

    The sink and settings, the records (from ``allowed``) and their memory, ``tol`` (None
    or in :data:`~sinktheory.limits.TOL_RANGE`), the energy bound (default
    :func:`default_energy_bound` of ``tol``), then the starting state from
    :func:`initial_values`.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> s = prepare(Sink(Well(0.5, 0.3, 4), 1, 0.2), RunSettings(runs=2), "container")
    >>> s.runs, s.record, s.bound, s.time
    (2, ('container',), 1e-06, 0.0)
    """
    settings = check_sink(sink, settings)
    if not (isinstance(allowed, tuple) and allowed and set(allowed) <= set(RECORDS)):
        raise ParameterError("allowed", allowed, f"a tuple of names from {', '.join(RECORDS)}")
    record = check_record(record, allowed)
    tol = None if tol is None else check_tol(tol)
    settings.check_memory(sink, record)
    bound = v.positive(
        "energy_bound", default_energy_bound(tol) if energy_bound is None else energy_bound
    )
    values, t0, h0 = initial_values(sink, settings, initial, initial_state)
    return Start(settings, record, bound, values, t0, h0)


def sink_of(p: Mapping) -> Sink:
    """The :class:`~sinktheory.model.Sink` of a sweep point (a dict with the well's
    alpha, beta, n, gamma, shape and the sink's particles, mass).

    Examples
    --------
    >>> p = dict(alpha=0.5, beta=0.3, n=4, gamma=1.0, shape="flat", particles=5, mass=0.2)
    >>> sink_of(p).particles, sink_of(p).well.n
    (5, 4)

    A point of a user's well holds the well's text (``well``, see
    :func:`sinktheory.userwell.well_text`) and its parameters' values by name instead (a
    design point: ``wells``, the texts of the users' wells on its shape axis by name;
    the well's parameters named like alpha, beta, n, gamma take the point's values):

    >>> from sinktheory.userwell import UserWell, well_text
    >>> bowl = well_text(UserWell("bowl", "k*(x**2 + y**2)/2", {"k": 1}))
    >>> sink_of(dict(well=bowl, k=2.0, particles=1, mass=0.2)).well
    WellAt(bowl: k=2)
    """
    shape = p.get("shape")  # not text: the Well of a registered shape refuses it
    wells = _shape_wells(p.get("wells")) if isinstance(shape, str) else {}
    text = p["well"] if "well" in p else wells.get(shape) if wells else None
    if text is None:
        well = Well(p["alpha"], p["beta"], p["n"], gamma=p["gamma"], shape=p["shape"])
    else:
        names = well_of_text(text).parameter_names
        well = _well_at(text, tuple((k, p[k]) for k in names if k in p))
    return Sink(well, particles=p["particles"], mass=p["mass"])


@functools.lru_cache(maxsize=16)
def _shape_wells(wells: str | None) -> dict[str, str]:
    """A point's users' wells on its shape axis (``wells``: JSON, name -> text), by name."""
    import json

    return {} if wells is None else json.loads(wells)


@functools.lru_cache(maxsize=16)
def well_of_text(text: str):
    """The :class:`~sinktheory.userwell.UserWell` of a well's text as a sweep point holds it
    (:func:`sinktheory.userwell.well_text`), parsed once a process."""
    from .userwell import read_well

    return read_well(text)


@functools.lru_cache(maxsize=256)
def _well_at(text: str, values: tuple):
    """The checked :class:`~sinktheory.wellat.WellAt` of a well's text at ``values``
    ((name, value) pairs): a point's check and its computation share one check."""
    from .wellat import WellAt

    return WellAt(well_of_text(text), **dict(values))


def settings_of(p: Mapping, seed: int) -> RunSettings:
    """The :class:`~sinktheory.model.RunSettings` of a sweep point's ensemble (container
    energy, runs, periods, box), seeded with the point's seed."""
    return RunSettings(
        container_energy=p["container_energy"],
        runs=p["runs"],
        periods=p["periods"],
        seed=seed,
        box=p["box"],
    )
