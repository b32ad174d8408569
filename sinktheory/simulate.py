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
(:func:`sinktheory.stepsize.default_step` derives it from the energy); a step too large raises
:class:`~sinktheory.errors.EnergyDriftError` (or :class:`~sinktheory.errors.NonFiniteStateError`
when the state overflows) instead of returning numbers.  Individual trajectories are chaotic:
differences (round-off included) grow by a factor ~10-100 per period once the particles are
energised, so beyond a few periods a single trajectory is not reproducible by any other
integrator or step; ensemble means, the energy audit and the bitwise results for a given
seed, scheme and dt are.

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

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

import numpy as np

from . import validation as v
from .ensemble import (
    ENERGY_BOUND,
    RECORDS,
    SimulationResult,
    SimulationState,
    check_sink,
    engine_name,
    engine_params,
    join_values,
    prepare,
    run_parameters,
    settings_of,
    sink_of,
    split_values,
)
from .errors import ParameterError
from .glossary import renamed, stepper_or_scheme
from .integrators import get_scheme
from .layout import StateLayout
from .model import RunSettings, Sink
from .stepsize import PERIOD, check_tol, step_of
from .worklimit import check_work

__all__ = [
    "ENERGY_BOUND",
    "first_order_rhs",
    "RECORDS",
    "simulate",
    "SimulationResult",
    "SimulationState",
    "Stepper",
    "STEPPERS",
]


def first_order_rhs(sink: Sink):
    """f(t, z) of the same equations for general-purpose solvers (scipy.integrate.solve_ivp).

    z is a state row (2 + 4k,) as in :class:`SimulationState`; the accelerations come from
    the same generated engine kernel the splitting schemes use.  Used as the independent
    reference in the tests and the benchmark.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
    >>> from sinktheory.ensemble import start_state
    >>> f = first_order_rhs(sink)
    >>> f(0.0, start_state(sink, 0.5, np.zeros((1, 1, 2)))[0]).round(12).tolist()
    [0.0, -1.0, 0.0, 0.0, 0.0, 0.0]
    """
    from .engine.cache import load

    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.Sink")
    module = load(engine_name(sink))
    params = module.table_of(engine_params(sink), 1)
    L = StateLayout(sink.particles)

    def f(t: float, z: np.ndarray) -> np.ndarray:
        dz = np.empty_like(z)
        dz[L.q] = z[L.v]
        dz[L.v] = module.block_accelerations(z[L.q][:, None], params)[:, 0]
        return dz

    return f


@dataclass(frozen=True)
class Stepper:
    """One way of taking the steps of :func:`simulate` (an entry of :data:`STEPPERS`).

    Attributes
    ----------
    name : str
        The ``stepper`` value that picks it.
    options : tuple of str
        The keywords of :func:`simulate` only this stepper takes (given to another stepper
        they are refused, naming the keyword).
    run : callable
        Takes the sink and settings, the keywords record, initial, initial_state,
        energy_bound and progress, and the options; returns a :class:`SimulationResult`.
    summary : str
        One line for help texts.
    """

    name: str
    options: tuple[str, ...]
    run: Callable[..., SimulationResult]
    summary: str


def _run_adaptive(sink, settings, *, eps=None, **common) -> SimulationResult:
    from .adaptive import DEFAULT_EPS, simulate_adaptive  # SymPy-printed kernels: load late

    return simulate_adaptive(sink, settings, eps=DEFAULT_EPS if eps is None else eps, **common)


@renamed(method=stepper_or_scheme)
def simulate(
    sink: Sink,
    settings: RunSettings | None = None,
    *,
    stepper: str | None = None,
    scheme: str | None = None,
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
    stepper : {"fixed", "adaptive"}, optional
        A key of :data:`STEPPERS`, the registry of ways to take steps.  ``"fixed"`` (the
        default; with ``initial_state`` the state's own): one step for the whole ensemble,
        from ``tol`` or ``dt``.  ``"adaptive"``: each run takes its own steps, set by
        ``eps`` (:func:`sinktheory.adaptive.simulate_adaptive`; cheaper than a fixed step
        for stiff walls, n >~ 10).  A keyword that only another stepper takes is refused.
    scheme : str, optional
        Splitting scheme of the fixed stepper, from :data:`sinktheory.integrators.SCHEMES`.
        Default: the cheapest scheme for ``tol`` (with ``dt``:
        :data:`~sinktheory.integrators.DEFAULT_SCHEME`).
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
    eps : float in (0, 0.25], optional
        The adaptive stepper's step factor (default 0.25; dt, tol and stride do not apply
        to it).

    Returns
    -------
    SimulationResult

    Raises
    ------
    ParameterError
        Bad input (unknown stepper or scheme, dt <= 0, wrong shapes, energy the well cannot hold).
    EnergyDriftError, NonFiniteStateError
        A run's energy error exceeded ``energy_bound`` or its state became non-finite; the
        message names the run, the time and the values.

    Examples
    --------
    >>> from sinktheory import RunSettings, Sink, Well
    >>> sink = Sink(Well(alpha=0.5, beta=0.3, n=10), particles=1, mass=0.2)
    >>> res = simulate(sink, RunSettings(runs=1, periods=1), initial=[(0.0, 0.01)],
    ...                record=("container", "final"))
    >>> res.final_state.values.shape, res.steps_per_period == round(2 * np.pi / res.dt)
    ((1, 6), True)
    """
    settings = check_sink(sink, settings)
    given = {"scheme": scheme, "dt": dt, "tol": tol, "stride": stride, "eps": eps}
    if stepper is None:  # a continued adaptive run stays adaptive unless told otherwise
        continues = (
            isinstance(initial_state, SimulationState) and initial_state.stepper == "adaptive"
        )
        fixed_given = any(given[name] is not None for name in STEPPERS["fixed"].options)
        stepper = "adaptive" if continues and not fixed_given else "fixed"
    chosen = STEPPERS[v.choice("stepper", stepper, tuple(STEPPERS))]
    for name, value in given.items():
        if value is not None and name not in chosen.options:
            raise ParameterError(name, value, f"None with stepper {chosen.name!r} (it takes "
                                 f"{', '.join(chosen.options)})")  # fmt: skip
    options = {name: given[name] for name in chosen.options}
    return chosen.run(sink, settings, record=record, initial=initial,
                      initial_state=initial_state, energy_bound=energy_bound,
                      progress=progress, **options)  # fmt: skip


def _run_fixed(sink, settings, *, scheme, dt, tol, stride, record, initial, initial_state,
               energy_bound, progress) -> SimulationResult:  # fmt: skip
    """The fixed stepper: the compiled engine, one step (from ``tol`` or ``dt``) for the
    whole ensemble."""
    name = None if scheme is None else get_scheme(scheme).name
    if tol is not None:
        tol = check_tol(tol)
    begun = prepare(sink, settings, record, initial=initial, initial_state=initial_state,
                    energy_bound=energy_bound, tol=tol)  # fmt: skip
    record, bound, values = begun.record, begun.bound, begun.values
    t0, h0, runs, periods = begun.time, begun.reference_energy, begun.runs, settings.periods
    if dt is None and tol is None and initial_state is not None:
        dt, name = initial_state.dt, name or initial_state.scheme
    # a well too stiff for any step names its parameter; work beyond the limit is refused
    drawn = settings if initial is None and initial_state is None else None
    name, dt, steps, tol = step_of(
        sink, float(np.max(h0)), scheme=name, dt=dt, tol=tol, settings=drawn
    )
    check_work(replace(settings, runs=runs), sink, steps, name)
    scheme = get_scheme(name)
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
        stepper="fixed",
        scheme=scheme.name,
        dt=dt,
        steps_per_period=steps,
        message=f"{runs} run(s) x {periods} period(s) with {scheme.name}, dt = {dt:.6g}"
        + (f" (for tol {tol:g})" if tol is not None else "")
        + f": max relative energy error {worst:.3g} <= {bound:.3g}",
        tol=tol,
        parameters=run_parameters(sink, settings, runs),
    )


#: The steppers of :func:`simulate`, by name, as scipy's ``solve_ivp`` keeps its METHODS:
#: one entry per way of taking steps, with the keywords only it takes.
STEPPERS: dict[str, Stepper] = {
    "fixed": Stepper(
        "fixed", ("scheme", "dt", "tol", "stride"), _run_fixed,
        "one step for the whole ensemble, from tol or dt (the compiled engine)",
    ),
    "adaptive": Stepper(
        "adaptive", ("eps",), _run_adaptive,
        "each run its own step, time-reversibly controlled (stiff walls, n >~ 10)",
    ),
}  # fmt: skip


# ----------------------------------------------------------------- sweep points
def check_point(p: dict) -> int:
    """Check an ensemble point; its steps per period (a well too stiff for any step
    names the parameter responsible, and the work is checked against the limit)."""
    sink, settings = sink_of(p), settings_of(p, 0)
    settings.check(sink)
    get_scheme(p["scheme"])
    if p["dt"] is not None:
        v.time_step("dt", p["dt"])
    v.positive("energy_bound", p["energy_bound"])
    v.positive_int("replica", p.get("replica", 0), minimum=0)
    energy = settings.total_energy_bound(sink)
    name, _, steps, _ = step_of(sink, energy, scheme=p["scheme"], dt=p["dt"], settings=settings)
    check_work(settings, sink, steps, name)
    return steps


def point(p: dict, seed: int) -> dict:
    """An ``ensemble`` sweep point: the mean container energy per period and its
    standard error over runs seeded with the point's seed, the audit and the step."""
    res = simulate(
        sink_of(p),
        settings_of(p, seed),
        scheme=p["scheme"],
        dt=p["dt"],
        record=("container",),
        energy_bound=p["energy_bound"],
        progress=False,
    )
    r = res.items()  # the result's own fields and ensemble mean (sinktheory.results)
    return {
        "mean_energy": r["mean_energy"],
        "stderr": r["stderr"],
        "max_relative_energy_error": r["max_relative_energy_error"],
        "dt_used": r["dt"],
    }


from ._verbs import make_callable as _make_callable  # noqa: E402 (module complete here)

_make_callable(__name__, "simulate")
