"""How long a design sweep will take: a quick calibration of the per-point cost.

The cost of a point is dominated by the integration: (steps per period) x (periods)
steps of its runs, plus the same for the lambda_1 ensemble with its tangent vector.
:func:`estimate` times a short run (after a warm-up that compiles or loads the engine) at
the point with the most work, in this process on one thread, and scales it to every point
by the work limit's price of an ensemble (:func:`sinktheory.worklimit.ensemble_steps`:
the blocks' overhead, the particles, the vectors and the scheme's stages)

    work(point) = ensemble_steps(runs, steps x periods, k)
                  + TANGENT x ensemble_steps(lyapunov_runs, steps x lyapunov_periods, k, 1),

with the steps per period and the scheme from :func:`sinktheory.stepsize.choose` (no
integration needed) and ``TANGENT`` the measured cost of a chaos step relative to its
price; a design with contact damping (``damping`` > 0) or the 1-D NES attachment runs the
engine with its damping on instead (:mod:`sinktheory.damped`, no lambda_1), whose step
costs ``DISSIPATIVE`` plain steps (measured too when the grid has such designs), and the
vibro-impact attachment (exact flights) its periods and samples at
:data:`~sinktheory.vibroimpact.FLIGHT_SECONDS`, plus a fixed overhead per point (the
measures on data of the point's size, with their bootstrap and RQA, and the step choice),
timed as well.  Times are wall-clock, so the current load of
the machine is included; the total is divided by the number of workers.  It is an
estimate: the per-step cost depends on k and on the scheme.

Examples
--------
>>> from sinktheory.sweep.plan import Sweep
>>> s = Sweep.make("design", {"beta": 0.3, "n": 4, "particles": [1, 2], "runs": 2,
...                           "periods": 10, "lyapunov_runs": 0, "bootstrap": 5})
>>> est = estimate(s, workers=1, seconds=0.2)
>>> est.points, est.total_seconds > 0
(2, True)
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..engine.cache import COMPILE_SECONDS
from ..ensemble import engine_name, settings_of, sink_of
from ..errors import ParameterError
from ..limits import SECONDS_PER_PARTICLE_STEP
from ..stepsize import choose
from ..vibroimpact import FLIGHT_SECONDS
from ..worklimit import DISSIPATIVE, duration, ensemble_steps
from .point import SAMPLES, user_shape

#: Cost of a step with a tangent vector (chaos) relative to its price in
#: :func:`~sinktheory.worklimit.ensemble_steps` (which already counts the vector at
#: :data:`~sinktheory.worklimit.VECTOR_STEP`, measured by benchmarks/bench_worklimit.py):
#: 1 unless the calibration measures it, which it does when lambda_1 is asked for.
TANGENT = 1.0


@dataclass(frozen=True)
class Estimate:
    """Estimated time of a design sweep.

    Attributes
    ----------
    points : int
        Points to compute.
    total_seconds : float
        Estimated wall time on ``workers`` processes.
    per_point : ndarray
        Estimated seconds of each point on one core.
    seconds_per_unit : float
        Measured seconds per unit of work (a particle step as
        :func:`sinktheory.worklimit.ensemble_steps` counts it).
    overhead : float
        Measured seconds per point besides the integration (measures, step choice).
    compile_seconds : float
        :data:`~sinktheory.engine.cache.COMPILE_SECONDS` for each engine (well shape) not
        compiled yet (included in ``total_seconds``; a damped design runs the same
        engine).
    tangent : float
        Cost of a chaos step relative to a plain one (measured or :data:`TANGENT`).
    calibration_point : dict
        Where the cost was measured.
    calibration_seconds : float
        How long the calibration took (warm-up included).
    workers : int
    """

    points: int
    total_seconds: float
    per_point: np.ndarray
    seconds_per_unit: float
    overhead: float
    compile_seconds: float
    tangent: float
    calibration_point: dict
    calibration_seconds: float
    workers: int

    def describe(self) -> str:
        p = self.calibration_point
        where = ", ".join(f"{k} = {p[k]}" for k in ("shape", "beta", "n", "particles"))
        return (
            f"estimated {duration(self.total_seconds)} for {self.points} point(s) on "
            f"{self.workers} worker(s) (mean {self.per_point.mean():.3g} s per point on one "
            f"core; calibrated at {where} in {self.calibration_seconds:.1f} s"
            + (
                f"; includes {self.compile_seconds:.0f} s to compile new engines"
                if self.compile_seconds
                else ""
            )
            + ")"
        )


def work(point: dict, tangent: float = TANGENT, dissipative: float = DISSIPATIVE) -> float:
    """Units of work of a point (see the module docstring): particle steps as the work limit
    prices them."""
    attachment = point.get("attachment", "well")
    if attachment == "impact":  # exact flights: the vibro-impact's own price
        per_period = FLIGHT_SECONDS["period"] + SAMPLES * FLIGHT_SECONDS["sample"]
        return point["runs"] * point["periods"] * per_period / SECONDS_PER_PARTICLE_STEP
    choice = choose(sink_of(point), point["container_energy"], point["tol"])
    steps, scheme, k = choice.steps_per_period, choice.scheme, point["particles"]
    units = ensemble_steps(point["runs"], steps * point["periods"], k, scheme=scheme)
    if point["damping"] > 0 or attachment == "nes":  # the dissipative integrator
        return dissipative * units
    if point["lyapunov_runs"] and not user_shape(point):  # a user's well gets no lambda_1
        lyapunov = steps * point["lyapunov_periods"]
        units += tangent * ensemble_steps(point["lyapunov_runs"], lyapunov, k, 1, scheme)
    return units


def _units(p: dict, steps: int, vectors: int = 0) -> float:
    """The work limit's units of ``p``'s ensemble at ``steps`` steps per period."""
    scheme = choose(sink_of(p), p["container_energy"], p["tol"]).scheme
    return ensemble_steps(p["runs"], steps * p["periods"], p["particles"], vectors, scheme)


def _time_simulate(point: dict, runs: int, periods: int) -> tuple[float, float]:
    """(seconds, units) of a short ensemble at ``point``."""
    from ..simulate import simulate

    p = {**point, "runs": runs, "periods": periods}
    sink = sink_of(p)
    start = time.perf_counter()
    res = simulate(sink, settings_of(p, 0), tol=p["tol"], progress=False)
    seconds = time.perf_counter() - start
    return seconds, _units(p, res.steps_per_period)


def _time_inelastic(point: dict, runs: int, periods: int) -> tuple[float, float]:
    from ..damped import simulate_inelastic

    p = {**point, "runs": runs, "periods": periods}
    start = time.perf_counter()
    res = simulate_inelastic(sink_of(p), settings_of(p, 0), damping=p["damping"], tol=p["tol"])
    seconds = time.perf_counter() - start
    return seconds, _units(p, res.steps_per_period)


def _time_chaos(point: dict, runs: int, periods: int) -> tuple[float, float]:
    from ..chaos import chaos

    p = {**point, "runs": runs, "periods": periods}
    start = time.perf_counter()
    chaos(sink_of(p), settings_of(p, 0), progress=False)
    seconds = time.perf_counter() - start
    steps = choose(sink_of(p), p["container_energy"], p["tol"]).steps_per_period
    return seconds, _units(p, steps, vectors=1)


def uncompiled(points) -> list[str]:
    """The engines of design ``points`` whose compiled code is not in the engine cache
    yet: one per registered shape (it serves every n) and one per user's well on the
    shape axis (:func:`sinktheory.ensemble.engine_name`)."""
    from ..engine.cache import compiled

    one = {p["shape"]: p for p in points}.values()  # one engine per shape's name
    names = {engine_name(sink_of(p)) for p in one}
    return sorted(name for name in names if not compiled(name))


def _overhead(point: dict) -> float:
    """Seconds of a point's work besides the integration: the measures on synthetic data
    of the point's size, and the step choice (once more for lambda_1)."""
    from .measures import design_measures, horizons_of

    rng = np.random.default_rng(0)
    e = point["container_energy"] * (
        0.5 + 0.1 * rng.standard_normal((point["runs"], point["periods"] + 1))
    )
    start = time.perf_counter()
    design_measures(
        e,
        e0=point["container_energy"],
        total_energy=point["container_energy"],
        particles=point["particles"],
        n=point["n"],
        horizons=horizons_of(point["horizons"], point["periods"]),
        bootstrap=point["bootstrap"],
    )
    choose(sink_of(point), point["container_energy"], point["tol"])
    seconds = time.perf_counter() - start
    if point["lyapunov_runs"]:
        start = time.perf_counter()
        choose(sink_of(point), point["container_energy"], point["tol"])
        seconds += time.perf_counter() - start
    return seconds


def estimate(sweep, *, workers: int | None = None, seconds: float = 3.0, todo=None) -> Estimate:
    """Estimate the time of ``sweep`` (a design :class:`~sinktheory.sweep.plan.Sweep`).

    Parameters
    ----------
    sweep : Sweep
        A checked design sweep.
    workers : int, optional
        Processes the sweep will use (default: all cores).
    seconds : float
        Rough seconds to spend timing each ensemble (after the warm-up).
    todo : array of int, optional
        Indices of the points still to compute (default: all).

    Returns
    -------
    Estimate
    """
    import numba

    from ..sweep.plan import Sweep

    if not isinstance(sweep, Sweep) or sweep.kind.name != "design":
        raise ParameterError("sweep", type(sweep).__name__, "a design Sweep (explorer.plan)")
    workers = None if workers is None else v.positive_int("workers", workers)
    seconds = v.positive("seconds", seconds)
    if seconds > 3600:
        raise ParameterError("seconds", seconds, "at most 3600 (seconds of timing)")
    size = sweep.grid.size
    if todo is not None:
        todo = np.atleast_1d(v.finite_array("todo", todo, f"indices of points in [0, {size})"))
        if todo.ndim > 1 or not np.all((todo >= 0) & (todo < size) & (todo == np.round(todo))):
            raise ParameterError("todo", f"{todo.size} value(s)", f"indices in [0, {size})")
    started = time.perf_counter()
    workers = workers or os.cpu_count() or 1
    todo = np.arange(size) if todo is None else todo.astype(int)
    points = [sweep.grid.point(int(i)) for i in todo]
    if not points:
        return Estimate(0, 0.0, np.zeros(0), 0.0, 0.0, 0.0, TANGENT, {}, 0.0, workers)
    units = np.array([work(p, 1.0, 1.0) for p in points])  # plain steps, to pick the point
    heaviest = {**points[int(np.argmax(units))], "damping": 0.0}
    damped = [p for p in points if p["damping"] > 0]
    threads = numba.get_num_threads()
    numba.set_num_threads(1)  # as in a sweep's worker processes
    try:
        # the engine is vectorised across runs: time the point's own number of runs
        runs = heaviest["runs"]
        _time_simulate(heaviest, 2, 1)  # warm-up: compiles or loads the engine
        t1, _ = _time_simulate(heaviest, runs, 1)
        periods = max(2, min(heaviest["periods"], int(seconds / max(t1, 1e-6))))
        t, u = _time_simulate(heaviest, runs, periods)
        per_unit = t / u
        tangent = TANGENT
        if heaviest["lyapunov_runs"] and not user_shape(heaviest):
            lruns = heaviest["lyapunov_runs"]
            _time_chaos(heaviest, 2, 1)
            lperiods = max(2, min(heaviest["lyapunov_periods"], periods))
            tc, uc = _time_chaos(heaviest, lruns, lperiods)
            tangent = (tc / uc) / per_unit
        dissipative = DISSIPATIVE
        if damped:
            heaviest_damped = {**heaviest, "damping": max(p["damping"] for p in damped)}
            _time_inelastic(heaviest_damped, 2, 1)  # warms the engine's damped path
            td, ud = _time_inelastic(heaviest_damped, runs, periods)
            dissipative = (td / ud) / per_unit
        overhead = _overhead(heaviest)
    finally:
        numba.set_num_threads(threads)
    per_point = np.array([work(p, tangent, dissipative) for p in points]) * per_unit + overhead
    # the work shared over the workers, but never less than the longest point
    busy = min(workers, len(points))
    total = max(float(per_point.sum()) / busy, float(per_point.max()))
    compiling = COMPILE_SECONDS * len(uncompiled(points))
    total += compiling
    return Estimate(
        points=len(points),
        total_seconds=total,
        per_point=per_point,
        seconds_per_unit=per_unit,
        overhead=overhead,
        compile_seconds=compiling,
        tangent=float(tangent),
        calibration_point=heaviest,
        calibration_seconds=time.perf_counter() - started,
        workers=workers,
    )


__all__ = ["DISSIPATIVE", "TANGENT", "Estimate", "estimate"]
