"""The 1-D vibro-impact attachment: a particle in a clearance, with a dashpot, exactly.

The rigid limit n -> oo of the well on its invariant line y = 0 is a particle of mass mu
moving freely in a clearance |x| <= D (D = alpha - beta, the wall distance) of the
container (mass 1, spring 1), meeting its walls in elastic impacts.  A linear dashpot c
acts on the particle's velocity relative to the container (force -c xdot on the
particle, +c xdot on the container), as the ``"viscous"`` damping of
:mod:`sinktheory.damped`.

Between impacts the motion is linear and solved exactly.  With w = xdot = udot - Xdot::

    X' = Xdot,   Xdot' = -X + c w,   w' = X - kappa w,   x' = w,   kappa = c (1 + mu)/mu,

so z = (X, Xdot, w) obeys z' = B z with a constant 3 x 3 matrix B and x is the integral
of w.  Its eigenvalues (roots of l^3 + kappa l^2 + l + c/mu) are distinct for every
c >= 0 (0 and +-i at c = 0; the discriminant keeps one sign for c > 0), so with
B = P diag(l) P^-1 (computed once; its condition number is checked)::

    z(s) = P (a * exp(l s)),   x(s) = x(0) + sum_k P[2, k] a_k phi(l_k, s),
    a = P^-1 z(0),             phi(l, s) = (exp(l s) - 1) / l   (= s at l = 0),

evaluated from the start of each flight (no error accumulates along a flight), with phi
by its Taylor series where |l s| < 1/2.  The damper's work over a flight is the exact
integral c int w^2 ds = c sum_jk b_j b_k phi(l_j + l_k, s), b_k = P[2, k] a_k, computed
from the solution and *not* from the energy, so the audit

    H(t) + W(t) = H(0),   H = (X^2 + Xdot^2)/2 + mu udot^2 / 2

checks the flights, the impacts and the work against each other; it is checked at every
period end (:class:`~sinktheory.errors.EnergyDriftError` naming the run and the time).

Impacts are the elastic impact law of the rigid billiards
(:func:`sinktheory.billiard.kernels.impact`, derived in :mod:`sinktheory.billiard.impact`)
with the wall normal n = (+-1, 0): the relative velocity reverses, momentum is kept.

Impact times by *conservative advancement*, as the billiard engine finds its hits: along
a flight g(s) = D -+ x(s) >= 0 has |g''| = |X - kappa w| <= M, with
M = sqrt(2 H)(1 + kappa (1 + mu^-1/2)) from the energy H at the flight's start (H does
not grow along a damped flight), so g(s + h) >= g + g' h - M h^2 / 2 and the largest h
keeping that lower bound positive is a step on which neither wall can be crossed.  The
steps converge quadratically onto a transversal crossing and cannot jump over a grazing
or a closely spaced impact; a hit is declared when g <= eps = 1e-12 D while the
particle approaches that wall.  A flight needing more than :data:`MAX_ITERATIONS` steps
stops the run with a :class:`~sinktheory.errors.NumericalError` naming run and time.

Units: the paper's (container mass 1, spring 1, period T = 2 pi).

Examples
--------
>>> import numpy as np
>>> start = np.array([[0.0, 1.0, 0.0, 0.0]])   # X, Xdot, u, udot: an impulse on X
>>> res = simulate_vibroimpact(start, clearance=0.2, mass=0.2, damping=0.05, periods=3)
>>> int(res.impacts[0]) > 0, bool(res.max_audit_error < 1e-10)
(True, True)
>>> bool(0 < res.dissipated[0, -1] < 0.5)
True
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

import numba
import numpy as np

from . import validation as v
from .billiard.kernels import impact
from .ensemble import ENERGY_BOUND
from .errors import EnergyDriftError, NonFiniteStateError, NumericalError, ParameterError
from .limits import SECONDS_PER_PARTICLE_STEP
from .results import Result
from .stepsize import PERIOD
from .worklimit import check_particle_steps

#: Impacts per unit time, over sqrt(A / D), of a particle driven from relative rest by a
#: container of amplitude A: 1/4 (one every 4 sqrt(D / a) at acceleration a) times the
#: mean of sqrt|cos t| over a period, Gamma(3/4) / (sqrt(pi) Gamma(5/4)) = 0.7628
#: (:func:`check_flights`).
DRIVEN_RATE = 0.25 * math.gamma(0.75) / (math.sqrt(math.pi) * math.gamma(1.25))

#: Conservative-advancement steps allowed in one flight before giving up.
MAX_ITERATIONS = 100_000
#: Hit tolerance relative to the clearance (g <= HIT_TOL D while approaching).
HIT_TOL = 1e-12
#: Largest condition number of the eigenvector matrix P accepted.
MAX_CONDITION = 1e8
#: Seconds of a run's period, of a sample interval and of an impact in the work estimate
#: (:func:`check_flights`).  Measured with :func:`simulate_vibroimpact` (4 runs from an
#: impulse X' = 1, mass 0.2, best of 2; 2-core AVX-512 Xeon, load 5.2, 2026-11-26): a
#: period with one sample and no impact 2.0e-6 s; a sample 2.2e-6 s undamped and 5e-6 s
#: with damping 0.05 (16 samples: 3.6e-5 and 8.2e-5 s a period); an impact 3.6-4.3e-6 s
#: (clearance 0.2, 0.05 and 0.01, 3e4-6e4 impacts).  The prices are the larger values
#: rounded up: the work took 0.36-0.85 of the estimate with 16 samples (0.22 with one).
FLIGHT_SECONDS = {"period": 3e-6, "sample": 6e-6, "impact": 5e-6}
_OK, _STUCK, _DRIFT, _NONFINITE = 0, 1, 2, 3


def modes(mass: float, damping: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(l (3,), P (3, 3), P^-1) of B, the matrix of z = (X, Xdot, w) between impacts.

    Examples
    --------
    >>> lam, P, Pinv = modes(0.2, 0.0)
    >>> sorted(np.round(lam.imag, 12).tolist())
    [-1.0, 0.0, 1.0]
    """
    mass, damping = v.positive("mass", mass), v.nonnegative("damping", damping)
    kappa = damping * (1.0 + mass) / mass
    if not math.isfinite(kappa):
        raise ParameterError("damping", damping, "small enough that c (1 + mu) / mu is finite")
    B = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, damping], [1.0, 0.0, -kappa]])
    lam, P = np.linalg.eig(B)
    lam, P = lam.astype(complex), P.astype(complex)
    cond = np.linalg.cond(P)
    if not cond < MAX_CONDITION:
        raise NumericalError(
            f"vibro-impact flow: the eigenvectors of the damped linear system are nearly "
            f"parallel (condition {cond:.3g}) at mass = {mass:g}, damping = {damping:g}"
        )
    return lam, P, np.linalg.inv(P)


@dataclass(frozen=True)
class VibroImpactResult(Result):
    """What :func:`simulate_vibroimpact` recorded at t_i = i T / s (i = 0..P s).

    Attributes
    ----------
    sample_times : ndarray (S,)
    container_x, container_v : ndarray (R, S)
        X and Xdot.
    total_energy, dissipated : ndarray (R, S)
        H and the damper's work W since t = 0.
    initial_energy : ndarray (R,)
    impacts : ndarray (R,)
        Number of impacts of each run.
    audit_errors : ndarray (R,)
        max_i |H + W - H(0)| / H(0) over the samples.
    max_audit_error : float
    clearance, mass, damping : float
    """

    sample_times: np.ndarray
    container_x: np.ndarray
    container_v: np.ndarray
    total_energy: np.ndarray
    dissipated: np.ndarray
    initial_energy: np.ndarray
    impacts: np.ndarray
    audit_errors: np.ndarray
    max_audit_error: float
    clearance: float
    mass: float
    damping: float

    DIMS = {
        "container_x": ("run", "time"),
        "container_v": ("run", "time"),
        "total_energy": ("run", "time"),
        "dissipated": ("run", "time"),
        "initial_energy": ("run",),
        "impacts": ("run",),
        "audit_errors": ("run",),
    }
    COORDS = {"sample_times": "time"}


# --------------------------------------------------------------------------- kernels
@numba.njit(cache=True)
def _phi(z, s):
    """(exp(z s) - 1) / z (s at z = 0), complex z."""
    u = z * s
    if abs(u) < 0.5:
        term = s + 0j
        total = term
        for k in range(2, 24):
            term = term * u / k
            total += term
        return total
    return (cmath.exp(u) - 1.0) / z


@numba.njit(cache=True)
def flight(z0, x0, s, lam, P, Pinv, c):
    """(X, Xdot, w, x, W) after a flight of duration s from z0 = (X, Xdot, w), x0;
    W = c int_0^s w^2 (module docstring)."""
    a = np.empty(3, np.complex128)
    for k in range(3):
        a[k] = Pinv[k, 0] * z0[0] + Pinv[k, 1] * z0[1] + Pinv[k, 2] * z0[2]
    X = 0j
    V = 0j
    w = 0j
    x = 0j
    for k in range(3):
        e = cmath.exp(lam[k] * s) * a[k]
        X += P[0, k] * e
        V += P[1, k] * e
        w += P[2, k] * e
        x += P[2, k] * a[k] * _phi(lam[k], s)
    W = 0j
    if c != 0.0:
        for j in range(3):
            for k in range(3):
                W += (P[2, j] * a[j]) * (P[2, k] * a[k]) * _phi(lam[j] + lam[k], s)
    return X.real, V.real, w.real, x0 + x.real, c * W.real


@numba.njit(cache=True)
def _energy(X, V, w, mu):
    """H = (X^2 + Xdot^2)/2 + mu udot^2 / 2 with udot = w + Xdot."""
    ud = w + V
    return 0.5 * (X * X + V * V) + 0.5 * mu * ud * ud


@numba.njit(cache=True)
def advancement_bound(X, V, w, mu, c):
    """M = sqrt(2 H)(1 + kappa (1 + mu^-1/2)), the bound on |x''| along the flight
    starting from (X, Xdot, w) that :func:`next_hit` takes (module docstring)."""
    kappa = c * (1.0 + mu) / mu
    return math.sqrt(2.0 * _energy(X, V, w, mu)) * (1.0 + kappa * (1.0 + 1.0 / math.sqrt(mu)))


@numba.njit(cache=True)
def next_hit(z0, x0, limit, lam, P, Pinv, c, mu, D, eps, M):
    """(s, side, status): the first impact within ``limit`` of the flight from (z0, x0)
    (side +1 at x = D, -1 at x = -D, 0 none: s = limit), by conservative advancement
    with |x''| <= M (module docstring)."""
    s = 0.0
    tiny = 4.0 * np.finfo(np.float64).eps
    for _ in range(MAX_ITERATIONS):
        _, _, w, x, _ = flight(z0, x0, s, lam, P, Pinv, c)
        gp = D - x  # right wall, g' = -w
        gm = D + x  # left wall, g' = w
        if gp <= eps and w > 0.0:
            return s, 1, _OK
        if gm <= eps and w < 0.0:
            return s, -1, _OK
        step = limit - s
        for g, dg in ((gp, -w), (gm, w)):
            g = max(g, 0.0)
            if M > 0.0:
                h = (dg + math.sqrt(dg * dg + 2.0 * M * g)) / M
            elif dg < 0.0:
                h = g / -dg
            else:
                h = step
            step = min(step, h)
        step = max(step, tiny * (s + limit))  # zero normal speed at a wall: move on
        if s + step >= limit:
            return limit, 0, _OK
        s += step
    return s, 0, _STUCK


@numba.njit(cache=True)
def _run(state, mu, c, D, lam, P, Pinv, stride_t, samples, per_period, bound, rec):
    """Advance the runs' state (R, 4) = [X, Xdot, x, w] in place over ``samples`` sample
    intervals of length stride_t, recording (X, Xdot, H, W) at each sample end into rec
    (4, R, samples + 1) (index 0 already filled).  Returns (status, run, sample, impacts)."""
    R = state.shape[0]
    eps = HIT_TOL * D
    z = np.empty(3)
    vel = np.zeros(2)
    cont = np.zeros(2)
    impacts = np.zeros(R, np.int64)
    for r in range(R):
        X, V, x, w = state[r, 0], state[r, 1], state[r, 2], state[r, 3]
        W = rec[3, r, 0]
        h0 = rec[2, r, 0]
        for i in range(1, samples + 1):
            left = stride_t
            while True:
                z[0], z[1], z[2] = X, V, w
                M = advancement_bound(X, V, w, mu, c)
                s, side, status = next_hit(z, x, left, lam, P, Pinv, c, mu, D, eps, M)
                if status != _OK:
                    return _STUCK, r, i, impacts
                X, V, w, x, dW = flight(z, x, s, lam, P, Pinv, c)
                W += dW
                if side == 0:
                    break
                left -= s
                vel[0] = w + V
                vel[1] = 0.0
                cont[0] = X
                cont[1] = V
                impact(vel, cont, mu, float(side), 0.0)
                V = cont[1]
                w = vel[0] - V
                impacts[r] += 1
            H = _energy(X, V, w, mu)
            rec[0, r, i] = X
            rec[1, r, i] = V
            rec[2, r, i] = H
            rec[3, r, i] = W
            if not (math.isfinite(H) and math.isfinite(W)):
                return _NONFINITE, r, i, impacts
            if i % per_period == 0 and abs(H + W - h0) > bound * h0:
                return _DRIFT, r, i, impacts
        state[r, 0], state[r, 1], state[r, 2], state[r, 3] = X, V, x, w
    return _OK, -1, samples, impacts


# --------------------------------------------------------------------------- public API
def check_flights(
    rows: np.ndarray, clearance: float, mass: float, damping: float, periods: int, samples: int
) -> None:
    """Refuse runs from ``rows`` (R, 4) whose estimated work exceeds the limit
    (:func:`sinktheory.worklimit.check_particle_steps`), before any flight.

    The estimate (:data:`FLIGHT_SECONDS`) counts every period and sample interval of every
    run, and the impacts at the start's rate, for all periods without damping, else for
    the dashpot's relaxation time 1 / kappa (the start's relative motion decays on it).
    That rate is the larger of two: the relative speed |w| crosses the clearance 2 D every
    2 D / |w|; and the container's acceleration |X| = A |cos t| (A its amplitude at the
    start) drives the particle from relative rest, bouncing on one wall every
    4 sqrt(D / |X|) at most (a fall across the whole clearance), which averages to
    :data:`DRIVEN_RATE` sqrt(A / D) impacts per unit time (a particle at rest in a
    displaced container, w = 0, was counted no impact: clearance = 1e-300 hung).  Measured
    at mass 0.2 from such a start, 1.35 times that (D = 1e-5 to 0.5), so the estimate stays
    optimistic.  Names ``clearance`` when the impacts dominate, else ``periods``.

    Examples
    --------
    >>> check_flights(np.array([[0.0, 1.0, 0.0, 0.0]]), 1e-9, 0.2, 0.0, 10**4, 16 * 10**4)
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: clearance = 1e-09 is not allowed: must be larger: \
at most 3e+10 particle steps (1 h) in a computation that cannot resume (1 run(s) x \
10000 period(s), 160000 sample(s) and about 3.14e+13 impact(s) at the start's relative \
speed is 1.31e+15 particle steps at 1.2e-07 s each, estimated 1.57e+08 s (about 1.82e+03 \
days); use fewer runs, periods or particles, raise the limit (--max-hours, or \
sinktheory.worklimit.interactive_limit; up to 720 h), or split the work into the points \
of a resumable `sinktheory sweep`)
    """
    horizon = periods * PERIOD
    if damping > 0:
        horizon = min(horizon, mass / (damping * (1.0 + mass)))
    crossing = np.abs(rows[:, 3] - rows[:, 1]) / (2.0 * clearance)
    driven = DRIVEN_RATE * np.sqrt(np.hypot(rows[:, 0], rows[:, 1]) / clearance)
    impacts = float(np.maximum(crossing, driven).sum()) * horizon
    R = rows.shape[0]
    cost = FLIGHT_SECONDS
    runs = R * (periods * cost["period"] + samples * cost["sample"])
    name, value, change = (
        ("clearance", clearance, "larger") if impacts * cost["impact"] > runs
        else ("periods", periods, "smaller")
    )  # fmt: skip
    seconds = runs + impacts * cost["impact"]
    check_particle_steps(name, value, seconds / SECONDS_PER_PARTICLE_STEP,
                         f"{R} run(s) x {periods} period(s), {samples} sample(s) and about "
                         f"{impacts:.3g} impact(s) at the start's relative speed",
                         change)  # fmt: skip


def simulate_vibroimpact(
    start,
    *,
    clearance: float,
    mass: float,
    damping: float,
    periods: int,
    samples_per_period: int = 16,
    energy_bound: float | None = None,
) -> VibroImpactResult:
    """Integrate R runs of the 1-D vibro-impact attachment exactly (module docstring).

    Parameters
    ----------
    start : array (R, 4)
        Rows [X, Xdot, u, udot] (u = X + x the particle's absolute position), with
        |x| < clearance.
    clearance : float > 0
        D: the particle moves in |x| <= D.
    mass : float > 0
        mu, the particle's mass (container 1).
    damping : float >= 0
        c of the dashpot on the relative velocity.
    periods : int >= 1
    samples_per_period : int >= 1
        Records at t = i T / samples_per_period.
    energy_bound : float > 0, optional
        Largest |H + W - H0| / H0 tolerated at a period end (default 1e-6, as simulate).

    Returns
    -------
    VibroImpactResult

    Raises
    ------
    ParameterError
        Bad input, naming the parameter.
    EnergyDriftError, NonFiniteStateError, NumericalError
        The audit failed, or an impact search did not converge (run and time named).
    """
    D = v.positive("clearance", clearance)
    mu = v.positive("mass", mass)
    c = v.nonnegative("damping", damping)
    periods = v.positive_int("periods", periods, maximum=10**7)
    per = v.positive_int("samples_per_period", samples_per_period, maximum=100_000)
    bound = v.positive("energy_bound", ENERGY_BOUND if energy_bound is None else energy_bound)
    allowed = "rows [X, Xdot, u, udot] of shape (R, 4), finite, |u - X| < clearance"
    rows = v.real_array("start", start, allowed)
    if rows.ndim != 2 or rows.shape[1] != 4 or not np.all(np.isfinite(rows)):
        raise ParameterError("start", f"an array of shape {rows.shape}", allowed)
    x = rows[:, 2] - rows[:, 0]
    if not np.all(np.abs(x) < D):
        raise ParameterError("start", f"|u - X| up to {np.abs(x).max():.6g}", allowed)
    R, samples = rows.shape[0], periods * per
    v.fits_memory("periods", periods, 32.0 * R * (samples + 1), f"{R} run(s) x {samples} "
                  "samples", "smaller")  # fmt: skip
    check_flights(rows, D, mu, c, periods, samples)
    lam, P, Pinv = modes(mu, c)
    state = np.stack([rows[:, 0], rows[:, 1], x, rows[:, 3] - rows[:, 1]], axis=1)
    rec = np.zeros((4, R, samples + 1))
    rec[0, :, 0], rec[1, :, 0] = rows[:, 0], rows[:, 1]
    h0 = 0.5 * (rows[:, 0] ** 2 + rows[:, 1] ** 2) + 0.5 * mu * rows[:, 3] ** 2
    if not np.all(h0 > 0):
        raise ParameterError("start", "a state at rest", "a state with energy > 0")
    rec[2, :, 0] = h0
    status, r, i, impacts = _run(state, mu, c, D, lam, P, Pinv, PERIOD / per, samples, per,
                                 bound, rec)  # fmt: skip
    t = i / per
    where = f"run {r} at t = {t:.6g} T (clearance = {D:g}, mass = {mu:g}, damping = {c:g})"
    if status == _STUCK:
        raise NumericalError(f"{where}: the impact search did not converge in "
                             f"{MAX_ITERATIONS} steps")  # fmt: skip
    if status == _NONFINITE:
        raise NonFiniteStateError(f"{where}: non-finite state")
    err = np.abs(rec[2] + rec[3] - h0[:, None]) / h0[:, None]
    if status == _DRIFT:
        raise EnergyDriftError(f"{where}: |H + W - H0|/H0 = {err[r, i]:.3g} > {bound:.3g}")
    audit = err.max(axis=1)
    return VibroImpactResult(
        sample_times=PERIOD / per * np.arange(samples + 1),
        container_x=rec[0],
        container_v=rec[1],
        total_energy=rec[2],
        dissipated=rec[3],
        initial_energy=h0,
        impacts=impacts,
        audit_errors=audit,
        max_audit_error=float(audit.max()),
        clearance=D,
        mass=mu,
        damping=c,
    )


__all__ = [
    "VibroImpactResult",
    "DRIVEN_RATE",
    "FLIGHT_SECONDS",
    "modes",
    "simulate_vibroimpact",
]
