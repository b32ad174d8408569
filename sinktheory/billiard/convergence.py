"""Soft walls against their rigid limit: lambda_1, mean free time and container energy as
functions of the wall stiffness n, with the observed rate of convergence.

For one well (shape, alpha, beta), k particles of total mass m and container energy E0,
each stiffness n of the soft-wall sink and the rigid billiard n = oo (moving container,
same table, mass ratio and start: :func:`sinktheory.billiard.billiard`) run the same
seeded ensemble (positions of :func:`sinktheory.ensemble.random_positions`, particles at
rest, container at X = sqrt(2 E0) at rest).  Three figures per run:

* ``lambda1``: the largest Lyapunov exponent per unit time after ``transient`` periods
  (soft: the tangent map of :func:`sinktheory.chaos.chaos`; rigid: two nearby
  trajectories of the billiard engine);
* ``mean_free_time``: k t / (wall hits of all particles) over the whole run.  Rigid: the
  engine's impacts (a corner counts once per wall).  Soft: a hit of particle j on wall i
  is a strict local maximum in time, sampled at every integrator step, of the wall term
  w_i = gamma/(2n) |r_i|^(2n) (r_i the shape's wall ratios,
  :func:`sinktheory.symbolic.wall_ratios`; V is their sum) that exceeds
  :data:`HIT_FRACTION` of the particle's energy in the container frame,
  mu |v - (Xdot, 0)|^2 / 2 + V.  The threshold drops the shallow maxima of w_i that a
  particle far from a wall passes through (for n = 100 they need |r_i| > 0.98); it
  misses the hits whose normal kinetic energy is below that fraction, about
  HIT_FRACTION / 2 of them for incidence distributed as cos(angle);
* ``energy_average``: the time average of the container energy E(jT), j = 0..P, and
  ``energy_curve`` its ensemble mean at each jT.

Each with a standard error over the runs; lambda_1 also split into regular and chaotic
runs (:meth:`Convergence.split`, the rule of :func:`sinktheory.chaos.verdicts.split`), so
a mixed ensemble is seen as such.  :meth:`Convergence.rate` fits
|q(n) - q(oo)| ~ C n^(-p) over the stiffnesses whose difference from the rigid value
exceeds two standard errors (:func:`power_rate`).  :func:`lyapunov_chart` gives
lambda_1(beta) for several n and the rigid limit (the chart of
:mod:`sinktheory.plot.convergence`).  :func:`measure` is the API of ``--n inf``: one
stiffness, finite or ``math.inf``.

Examples
--------
>>> import math
>>> from sinktheory.model import RunSettings
>>> c = convergence("flat", 0.5, 0.3, ns=(4, 10), settings=RunSettings(runs=2, periods=4))
>>> c.lambda1.shape, c.rigid_lambda1.shape
((2, 2), (2,))
>>> soft, rigid = c.split()  # lambda_1 of each n in regular and chaotic runs
>>> [s.runs for s in soft], rigid.runs
([2, 2], 2)
>>> sorted(c.rate("mean_free_time"))
['C', 'above', 'below', 'fit_ns', 'limit', 'limit_stderr', 'p', 'p_stderr']
"""

from __future__ import annotations

import functools
import math
import sys
import time
from dataclasses import dataclass, replace
from typing import Any, ClassVar

import numpy as np
import sympy as sp

from .. import symbolic as S
from .. import validation as val
from ..chaos.verdicts import Split, split
from ..errors import ParameterError
from ..model import RunSettings, Sink, Well
from ..results import Result
from ..runstats import ensemble_mean
from .run import PERIOD, BilliardResult, _settings, billiard

__all__ = [
    "CHUNK_SAMPLES",
    "Convergence",
    "convergence",
    "HIT_FRACTION",
    "lyapunov_chart",
    "LyapunovChart",
    "measure",
    "Measurement",
    "NS",
    "power_rate",
    "QUANTITIES",
]

#: Stiffnesses measured by default.
NS = (4, 10, 20, 50, 100)
#: A maximum of a wall term counts as a hit when it exceeds this fraction of the
#: particle's energy in the container frame (module docstring).
HIT_FRACTION = 1e-3
#: Trajectory samples (runs x steps) held at once while counting hits.
CHUNK_SAMPLES = 2_000_000
#: The figures compared, in the order of the tables.
QUANTITIES = ("lambda1", "mean_free_time", "energy_average")


@functools.cache
def _ratio_functions(shape: str):
    """numpy functions r_i(x, y, alpha, beta) of the shape's wall ratios."""
    return tuple(sp.lambdify((S.x, S.y, S.alpha, S.beta), r, "numpy") for r in S.wall_ratios(shape))


def wall_ratios(well: Well, x, y) -> np.ndarray:
    """|r_i(x, y)| of the well's wall ratios, stacked on a last axis."""
    x, y = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float))
    funcs = _ratio_functions(well.shape)
    return np.stack(
        [np.abs(np.broadcast_to(f(x, y, well.alpha, well.beta), x.shape)) for f in funcs], -1
    )


def wall_terms(well: Well, x, y) -> np.ndarray:
    """The wall terms gamma/(2n) |r_i(x, y)|^(2n) of the well, stacked on a last axis
    (their sum is the potential V).

    Examples
    --------
    >>> w = Well(0.5, 0.3, 4)
    >>> t = wall_terms(w, np.array([0.1]), np.array([0.5]))
    >>> bool(np.isclose(t.sum(axis=-1)[0], w.potential(0.1, 0.5)))
    True
    """
    return well.gamma / (2 * well.n) * wall_ratios(well, x, y) ** (2 * well.n)


def count_hits(sink: Sink, samples: np.ndarray, before: np.ndarray | None = None) -> np.ndarray:
    """Wall hits (module docstring) in consecutive states ``samples`` (R, S, 2 + 4k), columns
    as :class:`sinktheory.simulate.SimulationState`, per run and wall: (R, walls).

    ``before`` (R, 2 + 4k) is the state one step before ``samples[:, 0]`` (None at the
    start of a run); the last sample is not judged (it lacks its successor), so chunks
    that share their boundary sample are counted without gaps or repeats.  The maxima of
    a wall term are those of its |r_i| (a monotone function of it); the energy test is
    made at the maxima only.
    """
    k = sink.particles
    series = samples if before is None else np.concatenate([before[:, None], samples], axis=1)
    X = series[..., 0:1]
    ratios = wall_ratios(sink.well, series[..., 2 : 2 + k] - X, series[..., 2 + k : 2 + 2 * k])
    mid = ratios[:, 1:-1]
    run, step, j, wall = np.nonzero((mid > ratios[:, :-2]) & (mid >= ratios[:, 2:]))
    at = series[run, step + 1]  # (H, 2 + 4k): the states at the maxima
    h = np.arange(len(run))
    x = at[h, 2 + j] - at[:, 0]
    y = at[h, 2 + k + j]
    vx = at[h, 2 + 2 * k + j] - at[:, 1]
    vy = at[h, 2 + 3 * k + j]
    terms = wall_terms(sink.well, x, y)  # (H, walls)
    energy = 0.5 * sink.mu * (vx**2 + vy**2) + terms.sum(axis=-1)
    hit = terms[h, wall] > HIT_FRACTION * energy
    counts = np.zeros((series.shape[0], ratios.shape[-1]), dtype=np.int64)
    np.add.at(counts, (run[hit], wall[hit]), 1)
    return counts


@dataclass(frozen=True)
class Measurement(Result):
    """One stiffness: per-run lambda_1, mean free time, time-averaged container energy,
    and the container energy E(jT) of each run (module docstring)."""

    DIMS: ClassVar = {
        "lambda1": ("run",),
        "mean_free_time": ("run",),
        "energy_average": ("run",),
        "container_energy": ("run", "time"),
    }
    COORDS: ClassVar = {"times": "time"}

    n: float
    times: np.ndarray
    lambda1: np.ndarray | None
    mean_free_time: np.ndarray
    energy_average: np.ndarray
    container_energy: np.ndarray
    parameters: dict

    def items(self) -> dict[str, Any]:
        out = super().items()
        out["n"] = "inf" if self.n == math.inf else self.n
        for name in QUANTITIES:
            values = getattr(self, name)
            if values is not None:
                m, se = ensemble_mean(values[:, None])
                out[f"mean_{name}"] = {"mean": float(m[0]), "stderr": float(se[0])}
        return out


def _soft(sink, settings, lyapunov, transient, tol) -> Measurement:
    from ..chaos import chaos
    from ..chaos.sink import start_energy
    from ..ensemble import default_energy_bound
    from ..simulate import simulate
    from ..stepsize import resolve_step

    periods, runs = settings.periods, settings.runs
    # the step simulate would choose for tol, fixed for every chunk
    method, dt, steps, _ = resolve_step(sink, start_energy(sink, settings), tol=tol)
    bound = default_energy_bound(tol)
    chunk = max(1, min(periods, CHUNK_SAMPLES // (steps * runs)))
    hits = np.zeros(runs, dtype=np.int64)
    energy, state, before, done = [], None, None, 0
    while done < periods:
        part = min(chunk, periods - done)
        res = simulate(
            sink, replace(settings, periods=part), scheme=method, dt=dt, energy_bound=bound,
            record=("container", "trajectory", "final"), stride=1, initial_state=state,
            progress=False,
        )  # fmt: skip
        hits += count_hits(sink, res.trajectory, before).sum(axis=1)
        energy.append(res.container_energy[:, (1 if state else 0) :])
        before, state = res.trajectory[:, -2], res.final_state
        done += part
    cont = np.concatenate(energy, axis=1)
    mft = sink.particles * periods * PERIOD / np.maximum(hits, 1)
    mft[hits == 0] = np.inf
    lam = None
    if lyapunov:
        lam = chaos(sink, settings, tol=tol, transient=transient, progress=False).lambda1
    return Measurement(sink.well.n, PERIOD * np.arange(periods + 1), lam, mft,
                       cont.mean(axis=1), cont, {"dt": dt, "method": method})  # fmt: skip


def lambda_after(result: BilliardResult, transient: int) -> np.ndarray:
    """(R,) lambda_1 of a billiard ensemble from t = transient T on: the growth of its
    accumulated logs over the rest of the run."""
    transient = val.positive_int("transient", transient, minimum=0,
                                 maximum=len(result.times) - 2)  # fmt: skip
    if result.logs is None:
        raise ParameterError("result", "a run without lambda_1", "a run with lyapunov=True")
    span = result.duration - result.times[transient]
    return (result.logs[:, -1] - result.logs[:, transient]) / span


def _rigid(shape, alpha, beta, particles, mass, settings, lyapunov, transient) -> Measurement:
    r = billiard(shape, alpha, beta, particles=particles, mass=mass, settings=settings,
                 lyapunov=lyapunov)  # fmt: skip
    lam = lambda_after(r, transient) if lyapunov else None
    cont = r.container_energy
    return Measurement(math.inf, r.times, lam, r.mean_free_time, cont.mean(axis=1), cont,
                       {"method": r.lyapunov_method})  # fmt: skip


def measure(
    shape: str,
    alpha: float,
    beta: float,
    n,
    *,
    particles: int = 1,
    mass: float = 0.2,
    gamma: float = 1.0,
    settings: RunSettings | None = None,
    lyapunov: bool = True,
    transient: int = 0,
    tol: float | None = None,
) -> Measurement:
    """lambda_1, mean free time and container energy of one stiffness n (an integer, or
    ``math.inf`` for the rigid billiard; gamma plays no part there).

    Parameters
    ----------
    shape, alpha, beta, n, gamma : the well (:class:`sinktheory.model.Well`)
    particles, mass : k particles of total mass m
    settings : energy E0, runs, periods, seed, box (:class:`RunSettings`)
    lyapunov : also lambda_1 (the soft wall integrates a second time, with tangents)
    transient : periods left out of lambda_1, fewer than ``periods``
    tol : relative energy error the soft wall's step is chosen for (default 1e-8)

    Examples
    --------
    >>> m = measure("flat", 0.5, 0.3, math.inf, settings=RunSettings(runs=2, periods=3))
    >>> m.n, m.container_energy.shape
    (inf, (2, 4))
    """
    settings = _settings(settings)
    n = val.stiffness("n", n)
    transient = val.positive_int("transient", transient, minimum=0,
                                 maximum=max(0, settings.periods - 1))  # fmt: skip
    lyapunov = val.flag("lyapunov", lyapunov)
    if tol is not None:  # checked also where the rigid billiard has no use for it
        val.positive("tol", tol)
    if n == math.inf:
        val.positive("gamma", gamma)
        return _rigid(shape, alpha, beta, particles, mass, settings, lyapunov, transient)
    sink = Sink(Well(alpha, beta, n, gamma=gamma, shape=shape), particles=particles, mass=mass)
    return _soft(sink, settings, lyapunov, transient, tol)


def power_rate(ns, means, ses, limit: float, limit_se: float, n_min: float = 1) -> dict[str, Any]:
    """Fit |q(n) - q(oo)| ~ C n^(-p) by weighted least squares in log-log.

    Only stiffnesses n >= ``n_min`` (the tail, where the approach is monotone) whose
    difference d exceeds two standard errors
    s = sqrt(se(n)^2 + se(oo)^2) enter (the others are within noise of the limit); each
    log|d| has the weight (d / s)^2.  Returns p, its standard error (from the weights; nan
    with two points, which fit exactly), C, the stiffnesses used, the limit, and
    ``below`` / ``above``: the resolved stiffnesses on each side of the limit.  When
    those lie on both sides the approach is not a power law (q crosses the limit and
    overshoots it): p, its error and C are then nan.

    Examples
    --------
    >>> r = power_rate([10, 20, 40], [1.1, 1.05, 1.025], [1e-3] * 3, 1.0, 0.0)
    >>> round(r["p"], 9), r["fit_ns"]
    (1.0, [10, 20, 40])
    >>> math.isnan(power_rate([10, 20], [1.0, 1.0], [0.1, 0.1], 1.0, 0.1)["p"])
    True
    >>> r = power_rate([10, 20, 100], [0.9, 0.99, 1.1], [1e-3] * 3, 1.0, 0.0)  # crosses
    >>> math.isnan(r["p"]), r["below"], r["above"]
    (True, [10, 20], [100])
    """
    ns, means, ses, limit, limit_se, n_min = _rate_inputs(ns, means, ses, limit, limit_se,
                                                          n_min)  # fmt: skip
    d = np.abs(means - limit)
    s = np.hypot(ses, limit_se)
    with np.errstate(invalid="ignore", over="ignore"):  # a non-finite d or s is not used
        use = np.isfinite(d) & np.isfinite(s) & (d > 2 * s) & (ns >= n_min)
    side = means - limit
    out: dict[str, Any] = {"limit": limit, "limit_stderr": limit_se,
                           "fit_ns": [int(n) for n in ns[use]],
                           "below": [int(n) for n in ns[use & (side < 0)]],
                           "above": [int(n) for n in ns[use & (side > 0)]]}  # fmt: skip
    if use.sum() < 2 or (out["below"] and out["above"]):
        return out | {"p": math.nan, "p_stderr": math.nan, "C": math.nan}
    A = np.column_stack([np.ones(use.sum()), -np.log(ns[use])])
    # weights (d / s)^2, the inverse variances of log d: 1e12 where s = 0 (exact values),
    # capped where d / s would overflow the square
    with np.errstate(over="ignore"):
        ratio = np.divide(d[use], s[use], out=np.full(int(use.sum()), 1e6), where=s[use] > 0)
    w = np.minimum(ratio, 1e150) ** 2
    cov = np.linalg.inv(A.T @ (A * w[:, None]))
    coef = cov @ (A.T @ (w * np.log(d[use])))
    p_se = math.sqrt(cov[1, 1]) if use.sum() > 2 else math.nan
    return out | {"p": float(coef[1]), "p_stderr": p_se, "C": float(math.exp(coef[0]))}


def _rate_inputs(ns, means, ses, limit, limit_se, n_min):
    """The checked inputs of :func:`power_rate`: distinct stiffnesses (integers >= 1), one
    mean and one standard error >= 0 of each (real numbers; a non-finite one is not
    used), a finite limit and its finite standard error >= 0, a finite n_min."""
    grid = val.finite_array("ns", ns, "a non-empty sequence of distinct integers >= 1", ndim=1)
    if grid.size == 0 or len(set(grid.tolist())) != grid.size:
        raise ParameterError("ns", grid.tolist(), "a non-empty sequence of distinct integers >= 1")
    grid = np.array([val.positive_int("ns", n) for n in grid.tolist()], dtype=float)
    out = []
    for name, values in (("means", means), ("ses", ses)):
        a = val.real_array(name, values, f"{grid.size} real numbers, one per n")
        if a.shape != grid.shape or (name == "ses" and np.any(a < 0)):
            raise ParameterError(name, f"an array of shape {a.shape}",
                                 f"{grid.size} {'numbers >= 0' if name == 'ses' else 'numbers'},"
                                 " one per n")  # fmt: skip
        out.append(a)
    return (grid, *out, val.finite("limit", limit), val.nonnegative("limit_se", limit_se),
            val.finite("n_min", n_min))  # fmt: skip


@dataclass(frozen=True)
class Convergence(Result):
    """The soft-wall figures for each n beside the rigid ones (module docstring).

    Attributes
    ----------
    ns : (N,) soft stiffnesses
    times : (P + 1,) t = j T
    lambda1, mean_free_time, energy_average : (N, R) per run
    energy_curve : (N, P + 1) ensemble mean of E(jT)
    rigid_lambda1, rigid_mean_free_time, rigid_energy_average : (R,)
    rigid_energy_curve : (P + 1,)
    parameters : the well, the ensemble, transient, tol
    """

    DIMS: ClassVar = {
        "lambda1": ("n", "run"),
        "mean_free_time": ("n", "run"),
        "energy_average": ("n", "run"),
        "energy_curve": ("n", "time"),
        "rigid_lambda1": ("run",),
        "rigid_mean_free_time": ("run",),
        "rigid_energy_average": ("run",),
        "rigid_energy_curve": ("time",),
    }
    COORDS: ClassVar = {"ns": "n", "times": "time"}

    ns: np.ndarray
    times: np.ndarray
    lambda1: np.ndarray
    mean_free_time: np.ndarray
    energy_average: np.ndarray
    energy_curve: np.ndarray
    rigid_lambda1: np.ndarray
    rigid_mean_free_time: np.ndarray
    rigid_energy_average: np.ndarray
    rigid_energy_curve: np.ndarray
    parameters: dict

    def summary(self, quantity: str) -> tuple[np.ndarray, np.ndarray, float, float]:
        """(means (N,), standard errors (N,), rigid mean, rigid standard error)."""
        val.choice("quantity", quantity, QUANTITIES)
        m, se = ensemble_mean(getattr(self, quantity).T)
        rm, rse = ensemble_mean(getattr(self, f"rigid_{quantity}")[:, None])
        return m, se, float(rm[0]), float(rse[0])

    def rate(self, quantity: str, n_min: float = 1) -> dict[str, Any]:
        """:func:`power_rate` of one of :data:`QUANTITIES` over n >= ``n_min``."""
        n_min = val.real_array("n_min", n_min, "a number (inf allowed)")
        if n_min.ndim or np.isnan(n_min):
            raise ParameterError("n_min", n_min.tolist(), "a number (inf allowed)")
        return power_rate(self.ns, *self.summary(quantity), n_min=n_min)

    def split(self) -> tuple[list[Split], Split]:
        """lambda_1 of each soft n, and of the rigid limit, split into regular and chaotic
        runs (:func:`sinktheory.chaos.verdicts.split`, over the periods after the
        transient); the starts are those of the module docstring."""
        p = self.parameters
        span = p["periods"] - p["transient"]
        starts = (f"particles at rest, uniform in (-{p['box']:g}, {p['box']:g})^2 around the "
                  "centre; container at X = sqrt(2 E0) at rest")  # fmt: skip
        return ([split(lam, span, starts) for lam in self.lambda1],
                split(self.rigid_lambda1, span, starts))  # fmt: skip

    def items(self) -> dict[str, Any]:
        out = super().items()
        soft, rigid = self.split()
        out["split_lambda1"] = {"soft": [s.as_dict() for s in soft], "rigid": rigid.as_dict()}
        for q in QUANTITIES:
            m, se, rm, rse = self.summary(q)
            out[f"mean_{q}"] = {"mean": m, "stderr": se, "rigid": rm, "rigid_stderr": rse}
            out[f"rate_{q}"] = self.rate(q)
        return out


def convergence(
    shape: str,
    alpha: float,
    beta: float,
    *,
    ns=NS,
    particles: int = 1,
    mass: float = 0.2,
    gamma: float = 1.0,
    settings: RunSettings | None = None,
    transient: int = 0,
    tol: float | None = None,
    progress: bool = False,
) -> Convergence:
    """:func:`measure` at every soft n of ``ns`` and at n = oo, gathered (module docstring).

    Each finite n compiles its engine once (about 15 s the first time on a new machine);
    ``progress`` prints a line to stderr as each stiffness is done.  A run that meets no
    wall (a container amplitude too small for the table, or runs too short) has no mean
    free time, and the study is refused (ParameterError naming ``settings``).
    """
    settings = _settings(settings)
    grid = val.real_array("ns", ns, "a sequence of integers >= 1")
    if grid.ndim != 1 or grid.size == 0:
        raise ParameterError("ns", ns, "a non-empty sequence of integers >= 1")
    soft = sorted({val.stiffness("ns", n) for n in grid.tolist()} - {math.inf})
    if not soft:
        raise ParameterError("ns", ns, "at least one finite integer >= 1 (oo is always run)")
    kw = dict(particles=particles, mass=mass, gamma=gamma, settings=settings, transient=transient)
    progress = val.flag("progress", progress)

    def timed(n, **extra):
        t0 = time.perf_counter()
        m = measure(shape, alpha, beta, n, **kw, **extra)
        if progress:
            print(f"  beta = {beta:+g}, n = {n}: {settings.runs} runs in "
                  f"{time.perf_counter() - t0:.0f} s", file=sys.stderr, flush=True)  # fmt: skip
        return m

    rigid = _check_hits(math.inf, timed(math.inf), settings)
    runs = [_check_hits(n, timed(n, tol=tol), settings) for n in soft]
    return Convergence(
        np.array(soft),
        rigid.times,
        np.stack([m.lambda1 for m in runs]),
        np.stack([m.mean_free_time for m in runs]),
        np.stack([m.energy_average for m in runs]),
        np.stack([m.container_energy.mean(axis=0) for m in runs]),
        rigid.lambda1,
        rigid.mean_free_time,
        rigid.energy_average,
        rigid.container_energy.mean(axis=0),
        {"shape": shape, "alpha": alpha, "beta": beta, "gamma": gamma, "particles": particles,
         "mass": mass, "container_energy": settings.container_energy, "runs": settings.runs,
         "periods": settings.periods, "seed": settings.seed, "box": settings.box,
         "transient": transient, "tol": tol, "hit_fraction": HIT_FRACTION},
    )  # fmt: skip


def _check_hits(n, m: Measurement, settings: RunSettings) -> Measurement:
    """``m``, unless a run of it met no wall: its mean free time (inf) is not defined,
    nor the comparison of the means with it, and the convergence study is refused."""
    missed = np.flatnonzero(~np.isfinite(m.mean_free_time))
    if missed.size:
        raise ParameterError(
            "settings", f"{settings.runs} run(s) x {settings.periods} period(s)",
            "runs in which the particles meet the walls",
            why=f"run {int(missed[0])} at n = {n} met no wall, so its mean free time is not "
            "defined: the container's amplitude is too small for the table or the runs too "
            "short",
        )  # fmt: skip
    return m


@dataclass(frozen=True)
class LyapunovChart(Result):
    """lambda_1(beta) for soft stiffnesses ``ns`` and the rigid limit: means and standard
    errors over the runs (rows of ``lambda1`` follow ``ns``), and how many of the runs are
    regular (:func:`sinktheory.chaos.verdicts.split`), so that a mixed point is seen."""

    DIMS: ClassVar = {
        "lambda1": ("n", "beta"),
        "lambda1_se": ("n", "beta"),
        "regular": ("n", "beta"),
        "rigid_lambda1": ("beta",),
        "rigid_lambda1_se": ("beta",),
        "rigid_regular": ("beta",),
    }
    COORDS: ClassVar = {"ns": "n", "betas": "beta"}

    ns: np.ndarray
    betas: np.ndarray
    lambda1: np.ndarray
    lambda1_se: np.ndarray
    regular: np.ndarray
    rigid_lambda1: np.ndarray
    rigid_lambda1_se: np.ndarray
    rigid_regular: np.ndarray
    parameters: dict

    def pooled_rate(self, lo: float = -math.inf, hi: float = math.inf) -> dict[str, Any]:
        """:func:`power_rate` of lambda_1 averaged over the betas in [lo, hi]: the mean over
        those betas for each n against the rigid mean (standard errors combined as for a
        mean of independent estimates).  Pooling many betas resolves differences that
        one beta's ensemble cannot, where they share a sign."""
        for name, bound in (("lo", lo), ("hi", hi)):
            bound = val.real_array(name, bound, "a number (+-inf allowed)")
            if bound.ndim or np.isnan(bound):
                raise ParameterError(name, bound.tolist(), "a number (+-inf allowed)")
        pick = (self.betas >= lo) & (self.betas <= hi)
        if not pick.any():
            raise ParameterError("lo, hi", (lo, hi), "an interval holding at least one beta")
        count = int(pick.sum())

        def pooled(se):
            return np.sqrt(np.sum(se[..., pick] ** 2, axis=-1)) / count

        span = [float(self.betas[pick].min()), float(self.betas[pick].max()), count]
        return power_rate(
            self.ns, self.lambda1[:, pick].mean(axis=1), pooled(self.lambda1_se),
            float(self.rigid_lambda1[pick].mean()), float(pooled(self.rigid_lambda1_se)),
        ) | {"betas": span}  # fmt: skip


def lyapunov_chart(
    alpha: float,
    betas,
    *,
    ns=(4, 10, 20),
    shape: str = "flat",
    particles: int = 1,
    mass: float = 0.2,
    settings: RunSettings | None = None,
    transient: int = 0,
) -> LyapunovChart:
    """lambda_1 over ``betas`` for each soft n (all betas of one n as one ensemble,
    :func:`sinktheory.chaos.chaos_batch`, at the smallest of their default steps) and for
    the rigid billiard; every beta starts the same seeded runs.

    Examples
    --------
    >>> c = lyapunov_chart(0.5, [-0.3, 0.3], ns=(4,), settings=RunSettings(runs=2, periods=3))
    >>> c.lambda1.shape, c.rigid_lambda1.shape, c.regular.shape
    ((1, 2), (2,), (1, 2))
    """
    from ..chaos import chaos_batch
    from ..chaos.sink import start_energy
    from ..stepsize import resolve_step

    settings = _settings(settings)
    grid = val.real_array("betas", betas, "a sequence of betas")
    if grid.ndim != 1 or grid.size == 0:
        raise ParameterError("betas", betas, "a non-empty sequence of betas")
    soft = [val.stiffness("ns", n) for n in np.atleast_1d(ns).tolist()]
    if math.inf in soft or len(set(soft)) != len(soft):
        raise ParameterError("ns", ns, "distinct finite integers >= 1 (the rigid row is "
                             "always drawn)")  # fmt: skip
    transient = val.positive_int("transient", transient, minimum=0,
                                 maximum=max(0, settings.periods - 1))  # fmt: skip
    lam = np.zeros((len(soft), grid.size))
    lam_se = np.zeros_like(lam)
    regular = np.zeros(lam.shape, dtype=np.int64)
    for i, n in enumerate(soft):
        sinks = [Sink(Well(alpha, b, n, shape=shape), particles, mass) for b in grid]
        dt = min(resolve_step(s, start_energy(s, settings))[1] for s in sinks)
        results = chaos_batch(sinks, [settings] * len(sinks), dt=dt, progress=False)
        for j, res in enumerate(results):
            res = replace(res, transient=transient)
            m, se = res.mean("lambda1")
            lam[i, j], lam_se[i, j] = float(m), float(se)
            regular[i, j] = res.split().regular
    rigid = [
        measure(shape, alpha, b, math.inf, particles=particles, mass=mass, settings=settings,
                transient=transient).lambda1
        for b in grid
    ]  # fmt: skip
    span = settings.periods - transient
    return LyapunovChart(
        np.array(soft), grid, lam, lam_se, regular,
        np.array([r.mean() for r in rigid]),
        np.array([ensemble_mean(r[:, None])[1][0] for r in rigid]),
        np.array([split(r, span).regular for r in rigid]),
        {"shape": shape, "alpha": alpha, "particles": particles, "mass": mass,
         "container_energy": settings.container_energy, "runs": settings.runs,
         "periods": settings.periods, "seed": settings.seed, "transient": transient},
    )  # fmt: skip
