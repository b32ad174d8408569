"""Full dynamics of the container and its k particles: symplectic, ensemble-parallel, audited.

The engine integrates the Hamiltonian of paper eq. (Hamiltonian) in the separable canonical
coordinates of :func:`sinktheory.symbolic.separable_hamiltonian`: the container X (mass 1,
spring 1) and each particle's absolute coordinates u_j = X + x_j, y_j (mass mu = m/k), so
H = kinetic(momenta) + potential(coordinates) and the splitting schemes of
:mod:`sinktheory.integrators` apply.  The work is done by :class:`sinktheory.engine.core.
Ensemble`: an engine generated from the symbolic model for this well shape, exponent n and
number of particles k, vectorised across runs (structure of arrays) and spread over threads
in blocks.  Each run's arithmetic does not depend on the block size or the number of
threads, so a seed gives bitwise the same numbers on any machine configuration.

Units: the paper's (container mass 1, spring 1, period T = 2 pi).  Energies:

* container energy E = (Xdot^2 + X^2)/2 (what the paper plots);
* particle energy e_j = mu/2 (udot_j^2 + ydot_j^2) + V(x_j, y_j), with the particle's
  *absolute* velocity and its interaction energy with the well, so that
  E + sum_j e_j = H, the conserved total, exactly.

Where it stops being trustworthy: the step must resolve the fastest wall collision
(:func:`default_step` derives it from the energy); a step too large raises
:class:`~sinktheory.errors.EnergyDriftError` (or :class:`~sinktheory.errors.NonFiniteStateError`
when the state overflows) instead of returning numbers.  Individual trajectories are chaotic:
differences (round-off included) grow by a factor ~10-100 per period once the particles are
energised, so beyond a few periods a single trajectory is not reproducible by any other
integrator or step; ensemble means, the energy audit and the bitwise results for a given
seed, method and dt are.

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> sink = Sink(Well(alpha=0.5, beta=0.3, n=4), particles=2, mass=0.2)
>>> res = simulate(sink, RunSettings(runs=2, periods=2, seed=1))
>>> res.container_energy.shape, res.container_energy[:, 0]
((2, 3), array([0.5, 0.5]))
>>> bool(res.max_relative_energy_error < 1e-8)
True
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from . import validation as v
from .errors import ParameterError
from .integrators import DEFAULT_SCHEME, get_scheme
from .layout import StateLayout, pack_params
from .model import RunSettings, Sink
from .results import Result
from .sinkstats import ensemble_mean
from .stepsize import DEFAULT_TOL, PERIOD, check_tol, choose
from .worklimit import check_work, step_of

#: What :func:`simulate` can record.
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


# --------------------------------------------------------------------------- public API
@dataclass(frozen=True)
class SimulationState(Result):
    """The state of every run at one instant, enough to continue exactly where it stopped.

    ``values`` has shape (R, 2 + 4k), columns [X, Xdot, u_1..u_k, y_1..y_k, udot_1..udot_k,
    ydot_1..ydot_k] (u_j = X + x_j is the particle's absolute x; velocities are absolute),
    named by :class:`sinktheory.layout.StateLayout`.
    ``reference_energy`` is each run's total energy at the start of the whole simulation, so
    the energy audit of a continued run still measures the drift from the very beginning.
    """

    values: np.ndarray
    time: float
    reference_energy: np.ndarray
    dt: float
    method: str

    DIMS = {"values": ("run", "state"), "reference_energy": ("run",)}

    @property
    def layout(self) -> StateLayout:
        return StateLayout.of(self.values)

    @property
    def particles(self) -> int:
        return self.layout.particles

    def relative_positions(self) -> np.ndarray:
        """Particle positions (x_j, y_j) in the container's frame, shape (R, k, 2)."""
        return self.layout.relative_positions(self.values)

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
    method, dt, steps_per_period : the integrator used (dt = T / steps_per_period).
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
    method: str
    dt: float
    steps_per_period: int
    message: str
    tol: float | None = None
    parameters: dict = field(default_factory=dict)

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
        """Ensemble mean <E>(t_j) and its standard error (ddof = 1; zeros for one run)."""
        return ensemble_mean(self.container_energy)


def default_step(
    sink: Sink, energy: float, method: str = DEFAULT_SCHEME, tol: float = DEFAULT_TOL
) -> tuple[float, int]:
    """(dt, steps per period) of ``method`` for relative energy error ``tol``.

    The step comes from the scheme's calibrated error model at the fastest frequency the
    total ``energy`` allows (:func:`sinktheory.stepsize.step_for`); dt is shortened so a
    period T = 2 pi is a whole number of steps and E(jT) is sampled exactly at t = jT.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> dt, steps = default_step(Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2), 0.5)
    >>> abs(dt * steps - 2 * math.pi) < 1e-12
    True
    """
    choice = choose(sink, energy, tol, method)
    return choice.dt, choice.steps_per_period


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
    children = np.random.SeedSequence(settings.seed).spawn(settings.runs)
    return np.stack(
        [
            np.random.default_rng(c).uniform(-settings.box, settings.box, size=(particles, 2))
            for c in children
        ]
    )


def start_state(sink: Sink, energy: float, positions: np.ndarray) -> np.ndarray:
    """State rows (R, 2 + 4k): container at X = sqrt(2 E0) at rest, particles at rest at
    ``positions`` (R, k, 2) relative to the container."""
    return StateLayout(sink.particles).start(math.sqrt(2.0 * energy), positions)


def total_energy(sink: Sink, values: np.ndarray) -> np.ndarray:
    """Total energy H of each state row (R, 2 + 4k) (generated energy kernel)."""
    return _engine_energies(sink, np.asarray(values, dtype=float))[0]


def engine_name(sink: Sink) -> str:
    """Name of the generated engine of this sink (shape, n and k fixed in its code)."""
    from .engine.cache import sink_name  # the engine (numba) loads when first needed

    return sink_name(sink.well.shape, sink.well.n)


#: The engine's runtime parameters of a sink, packed (:data:`sinktheory.layout.SINK_PARAMS`).
engine_params = pack_params


def split_values(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """State rows (R, 2 + 4k) as the engine's (q, v), each (1 + 2k, R)."""
    return StateLayout.of(values).split(values)


def join_values(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The engine's (q, v) as state rows (R, 2 + 4k): [X, Xdot, u.., y.., udot.., ydot..]."""
    return StateLayout((q.shape[0] - 1) // 2).join(q, v)


def _engine_energies(sink: Sink, values: np.ndarray):
    """(total (R,), container (R,), particles (R, k)) from the generated energy kernel."""
    q, v = split_values(values)
    from .engine.core import Ensemble

    ens = Ensemble(engine_name(sink), q, v, engine_params(sink))
    total, shared, members = ens.energies()
    return total, shared, members.T


def first_order_rhs(sink: Sink):
    """f(t, z) of the same equations for general-purpose solvers (scipy.integrate.solve_ivp).

    z is a state row (2 + 4k,) as in :class:`SimulationState`; the accelerations come from
    the same generated engine kernel the splitting schemes use.  Used as the independent
    reference in the tests and the benchmark.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
    >>> f = first_order_rhs(sink)
    >>> f(0.0, start_state(sink, 0.5, np.zeros((1, 1, 2)))[0]).round(12).tolist()
    [0.0, -1.0, 0.0, 0.0, 0.0, 0.0]
    """
    from .engine.cache import load

    module = load(engine_name(sink))
    params = module.table_of(engine_params(sink), 1)
    L = StateLayout(sink.particles)

    def f(t: float, z: np.ndarray) -> np.ndarray:
        dz = np.empty_like(z)
        dz[L.q] = z[L.v]
        dz[L.v] = module.block_accelerations(z[L.q][:, None], params)[:, 0]
        return dz

    return f


def run_parameters(sink: Sink, settings: RunSettings, runs: int) -> dict:
    """What a simulation ran, as its result's ``parameters``: the well, k, m, E0, runs,
    periods, seed, box."""
    w = sink.well
    return {
        "shape": w.shape, "alpha": w.alpha, "beta": w.beta, "n": w.n, "gamma": w.gamma,
        "particles": sink.particles, "mass": sink.mass, "energy": settings.energy,
        "runs": runs, "periods": settings.periods, "seed": settings.seed, "box": settings.box,
    }  # fmt: skip


def _check_record(record: Sequence[str]) -> tuple[str, ...]:
    if isinstance(record, str):
        record = (record,)
    return tuple(v.choice("record", r, RECORDS) for r in record)


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


def _initial_values(sink, settings, initial, initial_state):
    """(values, t0, reference energy, runs) from exactly one of the three starting modes."""
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
        sink.well.check_energy(float(np.max(total_energy(sink, values))))
        return values, initial_state.time, np.array(initial_state.reference_energy)
    values = start_state(sink, settings.energy, start_positions(sink, settings, initial))
    h0 = total_energy(sink, values)
    sink.well.check_energy(float(np.max(h0)))
    return values, 0.0, h0


def simulate(
    sink: Sink,
    settings: RunSettings | None = None,
    *,
    method: str | None = None,
    dt: float | None = None,
    tol: float | None = None,
    record: Sequence[str] = ("container",),
    stride: int | None = None,
    initial: np.ndarray | None = None,
    initial_state: SimulationState | None = None,
    energy_bound: float | None = None,
    progress: bool | None = None,
    eps: float | None = None,
) -> SimulationResult:
    """Integrate an ensemble of the full container + particles system.

    Parameters
    ----------
    sink : Sink
        Well, number of particles k and their total mass m.
    settings : RunSettings, default RunSettings()
        Container energy E0 (X(0) = sqrt(2 E0), at rest), runs R, periods P, seed, box.
    method : str, optional
        Scheme name from :data:`sinktheory.integrators.SCHEMES`.  Default: the cheapest
        scheme for ``tol`` (with ``dt``: :data:`~sinktheory.integrators.DEFAULT_SCHEME`).
        ``"adaptive"``: each run takes its own steps (:func:`sinktheory.adaptive.
        simulate_adaptive`; cheaper than a fixed step for stiff walls, n >~ 10).
    dt : float > 0, optional
        Step, overriding ``tol``.  Always shortened to T / ceil(T / dt) so a period is a
        whole number of steps (the result reports the step used).
    tol : float, optional
        Relative total-energy error wanted over the run (1e-12 ... 1e-4; default
        :data:`~sinktheory.stepsize.DEFAULT_TOL` = 1e-8): the scheme and step come from the
        work-precision calibration of :mod:`sinktheory.stepsize`.
    record : sequence of {"container", "particles", "trajectory", "final"}
        What to keep (see :class:`SimulationResult`).  Default: container energy per period.
    stride : int >= 1, optional
        Steps between trajectory samples (default: about 32 samples per period).
    initial : array (k, 2) or (R, k, 2), optional
        Particle positions relative to the container instead of random ones (particles at
        rest); shape (k, 2) needs runs = 1.
    initial_state : SimulationState, optional
        Continue from a previous result's ``final_state`` (its dt and time are reused
        unless dt is given; R is taken from the state).
    energy_bound : float > 0, optional
        Largest relative total-energy error |H - H0|/H0 tolerated, checked every period
        (default: the larger of 1e-6 and 100 tol).
    progress : bool, optional
        Progress bar on stderr (only on a terminal, after 2 s); default on.
    eps : float in (0, 0.5], optional
        The adaptive method's step factor (default 0.25; dt, tol and stride do not apply
        to it).

    Returns
    -------
    SimulationResult

    Raises
    ------
    ParameterError
        Bad input (unknown method, dt <= 0, wrong shapes, energy the well cannot hold).
    EnergyDriftError, NonFiniteStateError
        A run's energy error exceeded ``energy_bound`` or its state became non-finite; the
        message names the run, the time and the values.

    Examples
    --------
    >>> from sinktheory import RunSettings, Sink, Well
    >>> sink = Sink(Well(alpha=0.5, beta=0.3, n=10), particles=1, mass=0.2)
    >>> res = simulate(sink, RunSettings(runs=1, periods=1), initial=[(0.0, 0.01)],
    ...                record=("container", "final"))
    >>> res.final_state.values.shape, res.steps_per_period == round(2 * math.pi / res.dt)
    ((1, 6), True)
    """
    settings = RunSettings() if settings is None else settings
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    if not isinstance(settings, RunSettings):
        raise ParameterError("settings", settings, "a sinktheory.model.RunSettings")
    continues = isinstance(initial_state, SimulationState) and initial_state.method == "adaptive"
    if method == "adaptive" or (method is None and dt is None and tol is None and continues):
        for name, value in (("dt", dt), ("tol", tol), ("stride", stride)):
            if value is not None:
                raise ParameterError(name, value, "None with method 'adaptive' (eps sets it)")
        from .adaptive import DEFAULT_EPS, simulate_adaptive

        eps = DEFAULT_EPS if eps is None else eps
        return simulate_adaptive(sink, settings, eps=eps, record=record,
                                 initial=initial, initial_state=initial_state,
                                 energy_bound=energy_bound, progress=progress)  # fmt: skip
    if eps is not None:
        raise ParameterError("eps", eps, "None unless method is 'adaptive'")
    if method is not None:
        method = get_scheme(method).name
    record = _check_record(record)
    settings.check_memory(sink, record)
    if tol is not None:
        tol = check_tol(tol)
    if energy_bound is None:
        energy_bound = default_energy_bound(tol)
    bound = v.positive("energy_bound", energy_bound)
    values, t0, h0 = _initial_values(sink, settings, initial, initial_state)
    runs, periods = values.shape[0], settings.periods
    if dt is None and tol is None and initial_state is not None:
        dt, method = initial_state.dt, method or initial_state.method
    # a well too stiff for any step names its parameter; work beyond the limit is refused
    drawn = settings if initial is None and initial_state is None else None
    method, dt, steps, tol = step_of(
        sink, float(np.max(h0)), method=method, dt=dt, tol=tol, settings=drawn
    )
    check_work(replace(settings, runs=runs), sink, steps)
    scheme = get_scheme(method)
    if "trajectory" in record:
        stride = max(1, steps // 32) if stride is None else v.positive_int("stride", stride)
        samples = periods * steps // stride + 1
    else:
        stride, samples = 0, 0

    q, vel = split_values(values)
    from .engine.core import Ensemble

    ens = Ensemble(engine_name(sink), q, vel, engine_params(sink), reference_energy=h0)
    ens.time = t0
    rec = ens.run(
        scheme,
        dt=dt,
        steps=steps,
        segments=periods,
        record=tuple(
            name
            for name, wanted in (
                ("shared", "container"),
                ("members", "particles"),
                ("trajectory", "trajectory"),
            )
            if wanted in record
        ),
        stride=stride,
        bound=bound,
        progress=progress,
        label="simulate ",
        unit="period",
    )
    values = join_values(ens.q, ens.v)
    max_error = rec.worst
    worst = float(max_error.max())
    final = (
        SimulationState(values, t0 + periods * PERIOD, h0, dt, scheme.name)
        if "final" in record
        else None
    )
    return SimulationResult(
        times=t0 + PERIOD * np.arange(periods + 1),
        container_energy=rec.shared,
        particle_energy=rec.members,
        trajectory=rec.trajectory,
        trajectory_times=t0 + dt * stride * np.arange(samples) if samples else None,
        final_state=final,
        initial_energy=h0,
        run_errors=max_error,
        max_relative_energy_error=worst,
        method=scheme.name,
        dt=dt,
        steps_per_period=steps,
        message=f"{runs} run(s) x {periods} period(s) with {scheme.name}, dt = {dt:.6g}"
        + (f" (for tol {tol:g})" if tol is not None else "")
        + f": max relative energy error {worst:.3g} <= {bound:.3g}",
        tol=tol,
        parameters=run_parameters(sink, settings, runs),
    )
