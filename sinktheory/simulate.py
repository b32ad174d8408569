"""Full dynamics of the container and its k particles: symplectic, ensemble-parallel, audited.

The engine integrates the Hamiltonian of paper eq. (Hamiltonian) in the separable canonical
coordinates of :func:`sinktheory.symbolic.separable_hamiltonian`: the container X (mass 1,
spring 1) and each particle's absolute coordinates u_j = X + x_j, y_j (mass mu = m/k), so
H = kinetic(momenta) + potential(coordinates) and the splitting schemes of
:mod:`sinktheory.integrators` apply.  Forces and energies come from the generated kernels
:func:`sinktheory._generated.dynamics.accelerations_flat` (and ``_symmetric``) and
``energy_*``; the stepping loop is compiled with numba and runs all members of an ensemble in
one call, in parallel over runs.  Each run's arithmetic does not depend on the number of
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
from dataclasses import dataclass

import numba
import numpy as np

from . import validation as v
from ._generated import dynamics as _dyn
from ._generated import well as _well
from .errors import EnergyDriftError, NonFiniteStateError, ParameterError
from .integrators import DEFAULT_SCHEME, get_scheme
from .model import RunSettings, Sink
from .progress import ProgressBar
from .sinkstats import ensemble_mean

#: The container's period T = 2 pi (mass 1, spring 1).
PERIOD = 2.0 * math.pi
#: What :func:`simulate` can record.
RECORDS = ("container", "particles", "trajectory", "final")
#: Default bound on the relative total-energy error before a run is stopped.
ENERGY_BOUND = 1e-6

_HESSIAN = {"flat": _well.hessian_flat, "symmetric": _well.hessian_symmetric}
_ENERGY = {"flat": _dyn.energy_flat, "symmetric": _dyn.energy_symmetric}

# status codes of a run inside the compiled loop
_RUNNING, _DRIFT, _NONFINITE = 0, 1, 2


# --------------------------------------------------------------------------- compiled core
@numba.njit(cache=True)
def _energy(symmetric, X, PX, u, yy, pu, py, alpha, beta, gamma, n, mu):
    if symmetric:
        return _dyn.energy_symmetric(X, PX, u, yy, pu, py, alpha, beta, gamma, n, mu)
    return _dyn.energy_flat(X, PX, u, yy, pu, py, alpha, beta, gamma, n, mu)


@numba.njit(cache=True)
def _run(
    row,
    r,
    start,
    stop,
    steps,
    ah,
    bh,
    symmetric,
    alpha,
    beta,
    gamma,
    n,
    mu,
    h0,
    bound,
    container,
    particles,
    trajectory,
    stride,
):
    """Advance one run (state ``row``) over periods [start, stop); audit at every period end.

    Returns (status, last period reached, offending energy, largest relative error).
    """
    k = (row.shape[0] - 2) // 4
    X = row[0]
    vX = row[1]
    u = row[2 : 2 + k].copy()
    yy = row[2 + k : 2 + 2 * k].copy()
    vu = row[2 + 2 * k : 2 + 3 * k].copy()
    vy = row[2 + 3 * k : 2 + 4 * k].copy()
    au = np.empty(k)
    ay = np.empty(k)
    pu = np.empty(k)
    py = np.empty(k)
    none = np.empty(0)
    one = np.empty(1)
    s = ah.shape[0]
    aX = _dyn.accelerations(symmetric, X, u, yy, alpha, beta, gamma, n, mu, au, ay)
    status = _RUNNING
    worst = 0.0
    H = h0
    p = start
    while p < stop and status == _RUNNING:
        for step in range(steps):
            for i in range(s):
                c = bh[i]
                vX += c * aX
                for j in range(k):
                    vu[j] += c * au[j]
                    vy[j] += c * ay[j]
                c = ah[i]
                X += c * vX
                for j in range(k):
                    u[j] += c * vu[j]
                    yy[j] += c * vy[j]
                aX = _dyn.accelerations(symmetric, X, u, yy, alpha, beta, gamma, n, mu, au, ay)
            c = bh[s]
            vX += c * aX
            for j in range(k):
                vu[j] += c * au[j]
                vy[j] += c * ay[j]
            if stride > 0:
                g = p * steps + step + 1
                if g % stride == 0:
                    out = trajectory[r, g // stride]
                    out[0] = X
                    out[1] = vX
                    out[2 : 2 + k] = u
                    out[2 + k : 2 + 2 * k] = yy
                    out[2 + 2 * k : 2 + 3 * k] = vu
                    out[2 + 3 * k : 2 + 4 * k] = vy
        p += 1
        for j in range(k):
            pu[j] = mu * vu[j]
            py[j] = mu * vy[j]
        H = _energy(symmetric, X, vX, u, yy, pu, py, alpha, beta, gamma, n, mu)
        if not math.isfinite(H):
            status = _NONFINITE
            break
        err = abs(H - h0) / abs(h0)
        worst = max(worst, err)
        if err > bound:
            status = _DRIFT
            break
        if container.shape[1] > 0:
            container[r, p] = _energy(
                symmetric, X, vX, none, none, none, none, alpha, beta, gamma, n, mu
            )
        if particles.shape[1] > 0:
            for j in range(k):
                one[0] = u[j] - X
                particles[r, p, j] = _energy(
                    symmetric,
                    0.0,
                    0.0,
                    one,
                    yy[j : j + 1],
                    pu[j : j + 1],
                    py[j : j + 1],
                    alpha,
                    beta,
                    gamma,
                    n,
                    mu,
                )
    row[0] = X
    row[1] = vX
    row[2 : 2 + k] = u
    row[2 + k : 2 + 2 * k] = yy
    row[2 + 2 * k : 2 + 3 * k] = vu
    row[2 + 3 * k : 2 + 4 * k] = vy
    return status, p, H, worst


@numba.njit(cache=True, parallel=True)
def _advance(
    state,
    start,
    stop,
    steps,
    ah,
    bh,
    symmetric,
    alpha,
    beta,
    gamma,
    n,
    mu,
    h0,
    bound,
    container,
    particles,
    trajectory,
    stride,
    status,
    fail_period,
    fail_energy,
    max_error,
):
    """All runs over periods [start, stop), one thread per run (runs already stopped skip)."""
    for r in numba.prange(state.shape[0]):
        if status[r] != _RUNNING:
            continue
        st, p, H, worst = _run(
            state[r],
            r,
            start,
            stop,
            steps,
            ah,
            bh,
            symmetric,
            alpha,
            beta,
            gamma,
            n,
            mu,
            h0[r],
            bound,
            container,
            particles,
            trajectory,
            stride,
        )
        status[r] = st
        fail_period[r] = p
        fail_energy[r] = H
        max_error[r] = max(max_error[r], worst)


# --------------------------------------------------------------------------- public API
@dataclass(frozen=True)
class SimulationState:
    """The state of every run at one instant, enough to continue exactly where it stopped.

    ``values`` has shape (R, 2 + 4k), columns [X, Xdot, u_1..u_k, y_1..y_k, udot_1..udot_k,
    ydot_1..ydot_k] (u_j = X + x_j is the particle's absolute x; velocities are absolute).
    ``reference_energy`` is each run's total energy at the start of the whole simulation, so
    the energy audit of a continued run still measures the drift from the very beginning.
    """

    values: np.ndarray
    time: float
    reference_energy: np.ndarray
    dt: float
    method: str

    @property
    def particles(self) -> int:
        return (self.values.shape[1] - 2) // 4

    def relative_positions(self) -> np.ndarray:
        """Particle positions (x_j, y_j) in the container's frame, shape (R, k, 2)."""
        k = self.particles
        X = self.values[:, :1]
        return np.stack([self.values[:, 2 : 2 + k] - X, self.values[:, 2 + k : 2 + 2 * k]], -1)


@dataclass(frozen=True)
class SimulationResult:
    """What :func:`simulate` recorded.

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

    def ensemble_energy(self) -> tuple[np.ndarray, np.ndarray]:
        """Ensemble mean <E>(t_j) and its standard error (ddof = 1; zeros for one run)."""
        return ensemble_mean(self.container_energy)


def stiffness_frequency(sink: Sink, energy: float, *, angles: int = 46) -> float:
    """Fastest oscillation frequency the total ``energy`` allows (an upper estimate).

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
    well = sink.well
    x_max, y_max = well.reach(energy)
    theta = np.linspace(0.0, 0.5 * math.pi, angles)[:, None]
    radius = np.linspace(0.0, math.hypot(x_max, y_max), 400)[None, :]
    inside = well.potential(radius * np.cos(theta), radius * np.sin(theta)) <= energy
    first_out = np.argmin(inside, axis=1)  # the basin is star-shaped enough: first exit
    lo, hi = radius[0, first_out - 1], radius[0, first_out]
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        below = well.potential(mid * np.cos(theta[:, 0]), mid * np.sin(theta[:, 0])) <= energy
        lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
    hessian = _HESSIAN[well.shape]
    largest = 0.0
    for r, t in zip(hi, theta[:, 0], strict=True):
        vxx, vxy, vyy = hessian(r * math.cos(t), r * math.sin(t), *_params(well))
        largest = max(largest, float(np.linalg.eigvalsh([[vxx, vxy], [vxy, vyy]])[-1]))
    return max(1.0, math.sqrt(largest * (1.0 / sink.mu + 1.0)))


def _params(well) -> tuple[float, float, float, int]:
    return well.alpha, well.beta, well.gamma, well.n


def default_step(sink: Sink, energy: float, method: str = DEFAULT_SCHEME) -> tuple[float, int]:
    """(dt, steps per period) chosen from the stiffness: dt <= h_omega / omega_max.

    omega_max is :func:`stiffness_frequency` at the total ``energy``; ``h_omega`` is the
    scheme's calibrated step x frequency product (see
    :class:`~sinktheory.integrators.SplittingScheme`).  dt is then shortened so a period
    T = 2 pi is a whole number of steps and E(jT) is sampled exactly at t = jT.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> dt, steps = default_step(Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2), 0.5)
    >>> abs(dt * steps - 2 * math.pi) < 1e-12
    True
    """
    return aligned_step(get_scheme(method).h_omega / stiffness_frequency(sink, energy))


def aligned_step(dt: float) -> tuple[float, int]:
    """The largest step <= dt dividing T = 2 pi evenly, and the number of steps per period."""
    steps = max(1, math.ceil(PERIOD / v.positive("dt", dt) - 1e-9))
    return PERIOD / steps, steps


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
    runs, k = positions.shape[0], sink.particles
    values = np.zeros((runs, 2 + 4 * k))
    X = math.sqrt(2.0 * energy)
    values[:, 0] = X
    values[:, 2 : 2 + k] = X + positions[:, :, 0]
    values[:, 2 + k : 2 + 2 * k] = positions[:, :, 1]
    return values


def total_energy(sink: Sink, values: np.ndarray) -> np.ndarray:
    """Total energy H of each state row (R, 2 + 4k) (generated energy kernel)."""
    return _energies(sink.well, sink.mu, np.asarray(values, dtype=float))


def _energies(well, mu: float, values: np.ndarray) -> np.ndarray:
    """The energy kernel on each row of ``values``; k is read from the number of columns."""
    k = (values.shape[1] - 2) // 4
    energy = _ENERGY[well.shape]
    out = np.empty(values.shape[0])
    for r, row in enumerate(values):
        out[r] = energy(
            row[0],
            row[1],
            row[2 : 2 + k],
            row[2 + k : 2 + 2 * k],
            mu * row[2 + 2 * k : 2 + 3 * k],
            mu * row[2 + 3 * k : 2 + 4 * k],
            well.alpha,
            well.beta,
            well.gamma,
            well.n,
            mu,
        )
    return out


def first_order_rhs(sink: Sink):
    """f(t, z) of the same equations for general-purpose solvers (scipy.integrate.solve_ivp).

    z is a state row (2 + 4k,) as in :class:`SimulationState`; the accelerations come from
    the same generated kernel the splitting schemes use.  Used as the independent reference
    in the tests and the benchmark.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
    >>> f = first_order_rhs(sink)
    >>> f(0.0, start_state(sink, 0.5, np.zeros((1, 1, 2)))[0]).round(12).tolist()
    [0.0, -1.0, 0.0, 0.0, -0.0, -0.0]
    """
    w, k, mu = sink.well, sink.particles, sink.mu
    accelerations = (
        _dyn.accelerations_symmetric if w.shape == "symmetric" else _dyn.accelerations_flat
    )

    def f(t: float, z: np.ndarray) -> np.ndarray:
        au, ay = np.empty(k), np.empty(k)
        aX = accelerations(
            z[0], z[2 : 2 + k].copy(), z[2 + k : 2 + 2 * k].copy(), *_params(w), mu, au, ay
        )
        return np.concatenate(([z[1], aX], z[2 + 2 * k :], au, ay))

    return f


def _check_record(record: Sequence[str]) -> tuple[str, ...]:
    if isinstance(record, str):
        record = (record,)
    return tuple(v.choice("record", r, RECORDS) for r in record)


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
    if initial is None:
        settings.check(sink)
        positions = random_positions(settings, k)
    else:
        positions = np.asarray(initial, dtype=float)
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
    values = start_state(sink, settings.energy, positions)
    h0 = total_energy(sink, values)
    sink.well.check_energy(float(np.max(h0)))
    return values, 0.0, h0


def simulate(
    sink: Sink,
    settings: RunSettings | None = None,
    *,
    method: str = DEFAULT_SCHEME,
    dt: float | None = None,
    record: Sequence[str] = ("container",),
    stride: int | None = None,
    initial: np.ndarray | None = None,
    initial_state: SimulationState | None = None,
    energy_bound: float = ENERGY_BOUND,
    progress: bool | None = None,
) -> SimulationResult:
    """Integrate an ensemble of the full container + particles system.

    Parameters
    ----------
    sink : Sink
        Well, number of particles k and their total mass m.
    settings : RunSettings, default RunSettings()
        Container energy E0 (X(0) = sqrt(2 E0), at rest), runs R, periods P, seed, box.
    method : str
        Scheme name from :data:`sinktheory.integrators.SCHEMES`.
    dt : float > 0, optional
        Step; default from :func:`default_step`.  Always shortened to T / ceil(T / dt) so a
        period is a whole number of steps (the result reports the step used).
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
    energy_bound : float > 0
        Largest relative total-energy error |H - H0|/H0 tolerated, checked every period.
    progress : bool, optional
        Progress bar on stderr (only on a terminal, after 2 s); default on.

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
    scheme = get_scheme(method)
    record = _check_record(record)
    bound = v.positive("energy_bound", energy_bound)
    values, t0, h0 = _initial_values(sink, settings, initial, initial_state)
    runs, k, periods = values.shape[0], sink.particles, settings.periods
    if dt is None and initial_state is not None:
        dt = initial_state.dt
    if dt is None:
        dt, steps = default_step(sink, float(np.max(h0)), scheme.name)
    else:
        dt, steps = aligned_step(dt)
    if "trajectory" in record:
        stride = max(1, steps // 32) if stride is None else v.positive_int("stride", stride)
        samples = periods * steps // stride + 1
    else:
        stride, samples = 0, 0

    w = sink.well
    container = np.zeros((runs, periods + 1 if "container" in record else 0))
    particles = np.zeros((runs, periods + 1 if "particles" in record else 0, k))
    trajectory = np.zeros((runs, samples, values.shape[1]))
    if container.shape[1]:
        container[:, 0] = _container_energies(sink, values)
    if particles.shape[1]:
        particles[:, 0] = _particle_energies(sink, values)
    if samples:
        trajectory[:, 0] = values
    status = np.zeros(runs, dtype=np.int64)
    fail_period = np.zeros(runs, dtype=np.int64)
    fail_energy = np.zeros(runs)
    max_error = np.zeros(runs)
    a, b = scheme.arrays()
    chunk = max(1, math.ceil(periods / 100))
    bar = ProgressBar(periods, enabled=progress is not False, label="simulate ")
    # Runs are spread over numba threads; more threads than runs only costs hand-offs
    # (one run on 2 threads measured ~9x slower than on one).  A run's arithmetic does
    # not depend on the thread count, so the numbers are the same.
    threads = numba.get_num_threads()
    numba.set_num_threads(max(1, min(runs, threads)))
    try:
        for start in range(0, periods, chunk):
            stop = min(periods, start + chunk)
            _advance(
                values,
                start,
                stop,
                steps,
                a * dt,
                b * dt,
                w.shape == "symmetric",
                w.alpha,
                w.beta,
                w.gamma,
                w.n,
                sink.mu,
                h0,
                bound,
                container,
                particles,
                trajectory,
                stride,
                status,
                fail_period,
                fail_energy,
                max_error,
            )
            _raise_on_failure(status, fail_period, fail_energy, h0, max_error, t0, bound)
            bar.update(stop - start)
    finally:
        numba.set_num_threads(threads)
        bar.close()

    worst = float(max_error.max())
    final = (
        SimulationState(values, t0 + periods * PERIOD, h0, dt, scheme.name)
        if "final" in record
        else None
    )
    return SimulationResult(
        times=t0 + PERIOD * np.arange(periods + 1),
        container_energy=container if "container" in record else None,
        particle_energy=particles if "particles" in record else None,
        trajectory=trajectory if samples else None,
        trajectory_times=t0 + dt * stride * np.arange(samples) if samples else None,
        final_state=final,
        initial_energy=h0,
        run_errors=max_error,
        max_relative_energy_error=worst,
        method=scheme.name,
        dt=dt,
        steps_per_period=steps,
        message=f"{runs} run(s) x {periods} period(s) with {scheme.name}, dt = {dt:.6g}: "
        f"max relative energy error {worst:.3g} <= {bound:.3g}",
    )


def _container_energies(sink: Sink, values: np.ndarray) -> np.ndarray:
    """E = (Xdot^2 + X^2)/2 for each row: the energy kernel with no particles."""
    return _energies(sink.well, sink.mu, values[:, :2])


def _particle_energies(sink: Sink, values: np.ndarray) -> np.ndarray:
    """e_j for each row (R, k): the energy kernel of one particle with the container at rest
    at the origin (so only the particle's kinetic and well energy remain)."""
    k, w = sink.particles, sink.well
    out = np.empty((values.shape[0], k))
    for j in range(k):
        single = np.zeros((values.shape[0], 6))
        single[:, 2] = values[:, 2 + j] - values[:, 0]
        single[:, 3] = values[:, 2 + k + j]
        single[:, 4] = values[:, 2 + 2 * k + j]
        single[:, 5] = values[:, 2 + 3 * k + j]
        out[:, j] = _energies(w, sink.mu, single)
    return out


def _raise_on_failure(status, fail_period, fail_energy, h0, max_error, t0, bound) -> None:
    """Raise for the lowest-numbered failed run (deterministic whatever the threads)."""
    failed = np.flatnonzero(status != _RUNNING)
    if failed.size == 0:
        return
    r = int(failed[0])
    t = t0 + int(fail_period[r]) * PERIOD
    where = f"run {r} at t = {t:.6g} (period {int(fail_period[r])})"
    if status[r] == _NONFINITE:
        raise NonFiniteStateError(
            f"{where}: the state became non-finite (total energy {float(fail_energy[r])!r}, "
            f"started at {float(h0[r])!r}); the step is too large for this stiffness"
        )
    err = abs(fail_energy[r] - h0[r]) / abs(h0[r])
    raise EnergyDriftError(
        f"{where}: relative total-energy error {err:.3g} > bound {bound:.3g} "
        f"(H = {float(fail_energy[r])!r}, H0 = {float(h0[r])!r}); use a smaller dt"
    )
