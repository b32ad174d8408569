"""Damped particles: a compiled integrator with an audited dissipation.

The paper notes that real absorption is enhanced by inelastic collisions.  Here particle
j dissipates through a viscous force on its velocity *relative to the container*,

    F_j = -c0 s(x_j, y_j) (xdot_j, ydot_j),

with the reaction -F_j,x acting on the container (momentum is exchanged, never created),
and one of two weights s (``damping_kind``):

* ``"contact"`` (the default): s = 2n V(x_j, y_j) / gamma, the wall term of the well
  (about 1 at the wall, (1/2)^(2n) half-way to it, so the force vanishes in the free
  interior like a contact force): inelastic wall contact;
* ``"viscous"``: s = 1 everywhere, a linear dashpot between each particle and the
  container, as in the classic damped attachments (:mod:`sinktheory.attachments`).

c0 = 0 is the conservative model.

Integration (Strang splitting of the conservative and the dissipative vector fields)::

    step(h) = D(h/2) o S(h) o D(h/2)

S is one step of the symplectic splitting scheme the simulator uses for the conservative
system (:func:`sinktheory.simulate.simulate`: same scheme, same step for a tolerance, the
same generated force kernel of :mod:`sinktheory.engine`, the same arithmetic), in the
separable coordinates (the container X and the particles' absolute u_j = X + x_j, y_j).
D is the dissipative field with the positions frozen: it is linear in the velocities
and, particle by particle, exactly solvable -- the relative velocity w = udot_j - Xdot
decays as exp(-c (1 + mu)/mu t) with the total momentum mu udot_j + Xdot kept, and
ydot_j as exp(-c t/mu).  D(tau) is the symmetric product of these exact pair flows
(particles 1..k over tau/2, then k..1 over tau/2), so the composed step is symmetric and
of second order.  With the viscous weight (c0 constant) this is the conformal-symplectic
Strang splitting, whose factors are computed once; with the contact weight s(q) it is a
splitting into exactly integrated sub-flows, justified by that, by its order (tested) and
by the audit below.  The contact weight is V(x_j, y_j) of the generated energy kernel
(evaluated with zero velocities, so it is the potential term exactly).

Audit: each exact pair flow removes exactly the kinetic energy it takes out (positions
are frozen), so the dissipated work W is accumulated without approximation and

    H(t) + W(t) = H(0)

holds to the conservative stage's energy error; every run is checked at every period end,
and a run over ``energy_bound`` raises :class:`~sinktheory.errors.EnergyDriftError`
naming the run and the time.  With c0 = 0 every velocity update adds an exact zero, so
the results are bitwise those of :func:`sinktheory.simulate.simulate` with the same seed,
scheme and step (tested).

Equivalent damping ratio of the container: the zeta of a linear dashpot on the container
(omega = 1) that would dissipate the same work over the same time,

    zeta_eq = W(t) / (2 omega  integral_0^t E_c dt)

(for a lightly damped oscillator <Xdot^2> = E_c, whose dashpot power is 2 zeta omega
Xdot^2); the integral is the trapezoid rule over the steps.

Implementation: one numba function (``error_model="numpy"``, single-threaded, vectorised
over runs: state arrays (coordinate, run), runs innermost) that calls the engine's
generated kernels of the system (``accelerations``, ``energies``, passed in as compiled
functions).  It is compiled once per process and engine (a few seconds; numba cannot
cache a function whose arguments are other compiled functions).  Each run's arithmetic
is independent of the other runs, so a seed gives the same numbers whatever the number
of runs around it.  :mod:`sinktheory.design.inelastic_reference` is the NumPy version of
the same splitting: the independent check of this kernel in the tests and the baseline
of ``benchmarks/bench_inelastic.py``.

Sampling within a period (``samples_per_period`` = s > 0, for time-frequency maps and
the time a share of the energy takes to go): the container's X and Xdot, the work W and
the largest |y_j| are kept at t = i T / s.  The step count per period is then rounded up
to a multiple of s (dt shortened accordingly); without sampling nothing changes.

Units: the paper's (container mass 1, spring 1, period T = 2 pi).

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
>>> res = simulate_inelastic(sink, RunSettings(runs=2, periods=1, seed=1), damping=0.5,
...                          dt=0.02)
>>> bool(res.max_audit_error < 1e-8), bool((res.dissipated[:, -1] > 0).all())
(True, True)
>>> zeta, se = res.equivalent_damping()
>>> bool(zeta > 0), bool(se >= 0)
(True, True)
>>> res = simulate_inelastic(sink, RunSettings(runs=2, periods=1, seed=1), damping=0.5,
...                          damping_kind="viscous", dt=0.02, samples_per_period=4)
>>> res.container_x.shape, res.sample_times.round(4).tolist()
((2, 5), [0.0, 1.5708, 3.1416, 4.7124, 6.2832])
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np

from .. import validation as v
from ..engine.cache import load
from ..ensemble import (
    check_sink,
    default_energy_bound,
    engine_name,
    engine_params,
    random_positions,
    split_values,
    start_state,
)
from ..errors import EnergyDriftError, NonFiniteStateError, ParameterError
from ..glossary import renamed
from ..integrators import get_scheme
from ..layout import StateLayout
from ..model import DAMPING_KINDS, RunSettings, Sink
from ..progress import ProgressBar
from ..runstats import mean_stderr
from ..stepsize import PERIOD, check_tol, resolve_step

_RUNNING, _DRIFT, _NONFINITE = 0, 1, 2


@dataclass(frozen=True)
class InelasticResult:
    """What :func:`simulate_inelastic` recorded, once per period (j = 0..P).

    Attributes
    ----------
    container_energy : ndarray (R, P + 1)
        E(jT) = (Xdot^2 + X^2)/2.
    total_energy : ndarray (R, P + 1)
        H(jT), the energy kept.
    dissipated : ndarray (R, P + 1)
        W(jT), the work dissipated in wall contact since t = 0.
    initial_energy : ndarray (R,)
        H(0).
    audit_errors : ndarray (R,)
        ``max_j |H + W - H(0)| / H(0)`` of each run.
    max_audit_error : float
    damping_ratio : ndarray (R,)
        zeta_eq of each run over the whole run (0 when nothing was dissipated).
    damping, dt, steps_per_period, method, tol, damping_kind
        What was integrated with (tol None when dt was given).
    sample_times : ndarray (S,) or None
        t_i = i T / s, i = 0..P s, with ``samples_per_period`` = s (None without sampling).
    container_x, container_v, sample_dissipated : ndarray (R, S) or None
        X, Xdot and W at the sample times.
    transverse : ndarray (R, S) or None
        max_j |y_j| at the sample times (how far the particles are from the line y = 0).
    """

    container_energy: np.ndarray
    total_energy: np.ndarray
    dissipated: np.ndarray
    initial_energy: np.ndarray
    audit_errors: np.ndarray
    max_audit_error: float
    damping_ratio: np.ndarray
    damping: float
    dt: float
    steps_per_period: int
    method: str
    tol: float | None = None
    damping_kind: str = "contact"
    sample_times: np.ndarray | None = None
    container_x: np.ndarray | None = None
    container_v: np.ndarray | None = None
    sample_dissipated: np.ndarray | None = None
    transverse: np.ndarray | None = None

    def equivalent_damping(self) -> tuple[float, float]:
        """zeta_eq of the container: mean over runs and its standard error (ddof = 1;
        NaN for one run)."""
        return mean_stderr(self.damping_ratio)


@dataclass(frozen=True)
class Setup:
    """Everything both integrators of the splitting start from (see :func:`setup`)."""

    q: np.ndarray
    vel: np.ndarray
    h0: np.ndarray
    engine: object
    params: np.ndarray
    scale: float
    damping: float
    bound: float
    method: str
    dt: float
    steps: int
    tol: float | None
    kind: str = "contact"
    stride: int = 0


def start_rows(sink: Sink, settings: RunSettings, start) -> np.ndarray:
    """The state rows (R, 2 + 4k) to start from: ``start`` checked (finite, the sink's
    width, ``settings.runs`` rows), or simulate's seeded start states when None."""
    if start is None:
        return start_state(
            sink, settings.container_energy, random_positions(settings, sink.particles)
        )
    k = sink.particles
    allowed = f"state rows of shape ({settings.runs}, {2 + 4 * k}), finite"
    values = v.real_array("start", start, allowed)
    if values.shape != (settings.runs, 2 + 4 * k) or not np.all(np.isfinite(values)):
        raise ParameterError("start", f"an array of shape {values.shape}", allowed)
    for x, y in StateLayout(k).relative_positions(values).reshape(-1, 2):
        sink.well.check_position("start", x, y)
    return values


def setup(
    sink: Sink,
    settings: RunSettings | None,
    damping: float,
    method: str | None,
    dt: float | None,
    tol: float | None,
    energy_bound: float | None,
    kind: str = "contact",
    start=None,
    samples_per_period: int = 0,
) -> Setup:
    """Check the input and build the start state, the step and the audit bound exactly
    as :func:`sinktheory.simulate.simulate` does (ParameterError for bad input); with
    ``samples_per_period`` > 0 the steps per period are rounded up to a multiple of it."""
    settings = check_sink(sink, settings)
    damping = v.nonnegative("damping", damping)
    kind = v.choice("damping_kind", kind, DAMPING_KINDS)
    samples = v.positive_int("samples_per_period", samples_per_period, minimum=0,
                             maximum=100_000)  # fmt: skip
    if method is not None:
        method = get_scheme(method).name
    if tol is not None:
        tol = check_tol(tol)
    if energy_bound is None:
        energy_bound = default_energy_bound(tol)
    bound = v.positive("energy_bound", energy_bound)
    settings.check(sink)
    q, vel = split_values(start_rows(sink, settings, start))
    engine = load(engine_name(sink))
    params = engine.table_of(engine_params(sink), q.shape[1])
    h0 = engine.block_energies(q, vel, params)[0]
    sink.well.check_energy(float(np.max(h0)), name="total_energy")
    method, dt, steps, tol = resolve_step(sink, float(np.max(h0)), method=method, dt=dt, tol=tol)
    stride = 0
    if samples:
        steps = -(-steps // samples) * samples
        dt, stride = PERIOD / steps, steps // samples
    w = sink.well
    return Setup(q, vel, h0, engine, params, 2.0 * w.n / w.gamma, damping, bound, method, dt,
                 steps, tol, kind, stride)  # fmt: skip


def check_audit(total, work, h0, bound: float, period: int, dt: float, damping: float):
    """Raise NonFiniteStateError / EnergyDriftError for the worst run at ``period``."""
    if not np.all(np.isfinite(total)):
        bad = int(np.flatnonzero(~np.isfinite(total))[0])
        raise NonFiniteStateError(
            f"run {bad}: non-finite state at t = {period} T (dt = {dt:.4g}, damping = "
            f"{damping:g}); the step is too large for this stiffness"
        )
    err = np.abs(total + work - h0) / h0
    if err.max() > bound:
        r = int(np.argmax(err))
        raise EnergyDriftError(
            f"run {r}: |H + W - H0|/H0 = {err[r]:.3g} > {bound:.3g} at t = {period} T "
            f"(dt = {dt:.4g}, damping = {damping:g}); use a smaller dt or tolerance"
        )


def result(s: Setup, e_c, h_t, w_t, integral, samples=None) -> InelasticResult:
    """The :class:`InelasticResult` of the recorded arrays (``integral``: of E_c dt;
    ``samples``: (X, Xdot, W, max |y|) at the sample times, each (R, S))."""
    h0 = s.h0
    audit = np.max(np.abs(h_t + w_t - h0[:, None]) / h0[:, None], axis=1)
    work = w_t[:, -1]
    positive = integral > 0
    zeta = np.where(positive, work / (2.0 * np.where(positive, integral, 1.0)), 0.0)
    return InelasticResult(
        container_energy=e_c,
        total_energy=h_t,
        dissipated=w_t,
        initial_energy=h0,
        audit_errors=audit,
        max_audit_error=float(audit.max()),
        damping_ratio=zeta,
        damping=s.damping,
        dt=s.dt,
        steps_per_period=s.steps,
        method=s.method,
        tol=s.tol,
        damping_kind=s.kind,
        **_sampled(s, samples),
    )


def _sampled(s: Setup, samples) -> dict:
    if samples is None:
        return {}
    xs, vs, ws, ys = samples
    times = s.dt * s.stride * np.arange(xs.shape[1])
    return {"sample_times": times, "container_x": xs, "container_v": vs,
            "sample_dissipated": ws, "transverse": ys}  # fmt: skip


# --------------------------------------------------------------------------- compiled kernel
@numba.njit(error_model="numpy")
def _factors(c, mu, half, ex, ey):
    """Decay factors of the exact pair flows over ``half`` for contact coefficients c
    (K, R): ex = 1 - exp(-c (1 + mu)/mu half) of the relative x velocity, ey =
    exp(-c/mu half) - 1 of ydot (both exactly 0 for c = 0)."""
    K, R = c.shape
    rel = 1.0 + mu
    for j in range(K):
        for r in range(R):
            ex[j, r] = -math.expm1(-c[j, r] * rel / mu * half)
            ey[j, r] = math.expm1(-c[j, r] / mu * half)


@numba.njit(error_model="numpy")
def _weights(energies, q, zero, P, scale, damping, c, total, shared, members):
    """c[j, r] = damping * s_j: the contact coefficients at positions q (zero velocities
    make the members' energies the potential terms exactly)."""
    energies(q, zero, P, total, shared, members)
    K, R = members.shape
    for j in range(K):
        for r in range(R):
            c[j, r] = damping * (scale * members[j, r])


@numba.njit(error_model="numpy")
def _dissipate(v, ex, ey, mu, work):
    """D(tau) on the velocities v (D, R) in place, ex and ey the :func:`_factors` of the
    positions over tau/2; the work of each run into ``work`` (set, not added).  Exact pair
    flows, particles 1..K over tau/2 then K..1 over tau/2."""
    K, R = ex.shape
    rel = 1.0 + mu
    reduced = mu / rel
    for r in range(R):
        work[r] = 0.0
    for jj in range(2 * K):
        j = jj if jj < K else 2 * K - 1 - jj
        for r in range(R):
            # x: relative velocity decays, total momentum mu udot + Xdot kept
            w = v[1 + j, r] - v[0, r]
            dw = -ex[j, r] * w
            v[1 + j, r] += dw / rel
            v[0, r] -= mu * dw / rel
            w_new = w + dw
            # y: the container does not move in y
            yd = v[1 + K + j, r]
            dy = ey[j, r] * yd
            v[1 + K + j, r] = yd + dy
            work[r] += 0.5 * reduced * (w * w - w_new * w_new) + 0.5 * mu * (
                yd * yd - (yd + dy) ** 2
            )


@numba.njit(error_model="numpy")
def _advance(accelerations, energies, q, v, P, scheme, dissipation, j0, j1, audit, rec,
             sampling):  # fmt: skip
    """Advance every run over periods j0+1..j1 in place; record at each period end.

    scheme = (a, b, dt, steps); dissipation = (on, damping, scale, mu, weighted) (the
    contact weight when weighted, else the constant coefficient damping); audit = (h0,
    bound, work, integral, ec_prev) (the last three carried between calls);
    rec = (e_c, h_t, w_t) indexed [run, period]; sampling = (stride, xs, vs, ws, ys)
    indexed [run, sample], sample i after i * stride steps (stride 0: none).  Returns
    (status, period, run) of the first period with a failing run (the worst one), or
    (0, j1, -1).
    """
    ah, bh, dt, steps = scheme
    on, damping, scale, mu, weighted = dissipation
    h0, bound, work, integral, ec_prev = audit
    e_c, h_t, w_t = rec
    stride, xs, vs, ws, ys = sampling
    D, R = q.shape
    K = (D - 1) // 2
    S = ah.shape[0]
    acc = np.empty((D, R))
    zero = np.zeros((D, R))
    c = np.empty((K, R))
    total = np.empty(R)
    shared = np.empty(R)
    members = np.empty((K, R))
    ex = np.empty((K, R))
    ey = np.empty((K, R))
    local = np.empty(R)
    half = 0.5 * (0.5 * dt)  # D(dt/2): pair flows over dt/4 each way
    accelerations(q, acc, P)
    if on:
        if weighted:
            _weights(energies, q, zero, P, scale, damping, c, total, shared, members)
        else:
            c[:, :] = damping
        _factors(c, mu, half, ex, ey)
    for j in range(j0 + 1, j1 + 1):
        for i_step in range(steps):
            if on:  # the factors of the positions at the end of the previous step
                _dissipate(v, ex, ey, mu, local)
                for r in range(R):
                    work[r] += local[r]
            for stage in range(S):
                ck = bh[stage] * dt
                cd = ah[stage] * dt
                for i in range(D):
                    for r in range(R):
                        v[i, r] += ck * acc[i, r]
                        q[i, r] += cd * v[i, r]
                accelerations(q, acc, P)
            ck = bh[S] * dt
            for i in range(D):
                for r in range(R):
                    v[i, r] += ck * acc[i, r]
            if on:
                if weighted:
                    _weights(energies, q, zero, P, scale, damping, c, total, shared, members)
                    _factors(c, mu, half, ex, ey)
                _dissipate(v, ex, ey, mu, local)
                for r in range(R):
                    work[r] += local[r]
            for r in range(R):
                ec = 0.5 * (v[0, r] * v[0, r] + q[0, r] * q[0, r])
                integral[r] += 0.5 * dt * (ec + ec_prev[r])
                ec_prev[r] = ec
            if stride and (i_step + 1) % stride == 0:
                i = ((j - 1) * steps + i_step + 1) // stride
                for r in range(R):
                    xs[r, i] = q[0, r]
                    vs[r, i] = v[0, r]
                    ws[r, i] = work[r]
                    far = 0.0
                    for m in range(K):
                        far = max(far, abs(q[1 + K + m, r]))
                    ys[r, i] = far
        energies(q, v, P, total, shared, members)
        worst = -1
        status = _RUNNING
        largest = -1.0
        for r in range(R):
            e_c[r, j] = shared[r]
            h_t[r, j] = total[r]
            w_t[r, j] = work[r]
            if not math.isfinite(total[r]):
                if status != _NONFINITE:
                    status, worst = _NONFINITE, r
            elif status != _NONFINITE:
                err = abs(total[r] + work[r] - h0[r]) / h0[r]
                if err > bound and err > largest:
                    status, worst, largest = _DRIFT, r, err
        if status != _RUNNING:
            return status, j, worst
    return _RUNNING, j1, -1


@renamed(method="scheme")
def simulate_inelastic(
    sink: Sink,
    settings: RunSettings | None = None,
    *,
    damping: float = 0.0,
    damping_kind: str = "contact",
    scheme: str | None = None,
    dt: float | None = None,
    tol: float | None = None,
    dissipative_stage: bool = True,
    energy_bound: float | None = None,
    start=None,
    samples_per_period: int = 0,
    progress: bool | None = False,
) -> InelasticResult:
    """Integrate the ensemble with damped particles (see the module docstring).

    Parameters
    ----------
    sink, settings
        As for :func:`sinktheory.simulate.simulate` (same start states for a seed).
    damping : float >= 0
        c0, the damping coefficient of each particle (force per relative velocity; for
        ``"contact"`` at the wall).
    damping_kind : {"contact", "viscous"}
        The weight of the damping force: the wall term (inelastic contact) or 1 (a
        dashpot between each particle and the container).
    scheme, dt, tol
        The conservative stage S, as for :func:`sinktheory.simulate.simulate`: the
        scheme and step for the energy tolerance ``tol`` (default 1e-8), or ``dt`` (and
        ``scheme``) directly.  The splitting is of order 2 whatever S is.
    dissipative_stage : bool
        False leaves D out altogether (the conservative integrator itself).
    energy_bound : float > 0, optional
        Largest ``|H + W - H0| / H0`` tolerated at a period end (default as simulate:
        the larger of 1e-6 and 100 tol).
    start : array (R, 2 + 4k), optional
        State rows to start from (columns of :class:`sinktheory.layout.StateLayout`, R =
        ``settings.runs``, particles inside the walls) instead of simulate's start states.
    samples_per_period : int >= 0
        Samples of X, Xdot, W and max |y_j| per period (0: none; module docstring).
    progress : bool, optional
        Progress bar on stderr (only on a terminal, after 2 s); default off.

    Returns
    -------
    InelasticResult

    Raises
    ------
    ParameterError
        Bad input (damping < 0, unknown scheme, dt <= 0, both dt and tol, ...).
    EnergyDriftError, NonFiniteStateError
        The audit failed: the message names the run and the period.
    """
    s = setup(sink, settings, damping, scheme, dt, tol, energy_bound, damping_kind, start,
              samples_per_period)  # fmt: skip
    settings = RunSettings() if settings is None else settings
    q, vel, h0 = s.q, s.vel, s.h0
    runs, periods = q.shape[1], settings.periods
    count = periods * s.steps // s.stride + 1 if s.stride else 1
    samples = tuple(np.zeros((runs, count)) for _ in range(4))
    samples[0][:, 0], samples[1][:, 0] = q[0], vel[0]
    samples[3][:, 0] = np.abs(q[1 + sink.particles :]).max(axis=0)
    e_c = np.empty((runs, periods + 1))
    h_t = np.empty((runs, periods + 1))
    w_t = np.zeros((runs, periods + 1))
    total, shared, _ = s.engine.block_energies(q, vel, s.params)
    e_c[:, 0], h_t[:, 0] = shared, total
    work, integral = np.zeros(runs), np.zeros(runs)
    ec_prev = 0.5 * (vel[0] * vel[0] + q[0] * q[0])
    a, b = get_scheme(s.method).arrays()
    scheme = (a, b, float(s.dt), int(s.steps))
    dissipation = (bool(dissipative_stage), s.damping, s.scale, float(sink.mu),
                   s.kind == "contact")  # fmt: skip
    audit = (h0, s.bound, work, integral, ec_prev)
    chunk = max(1, math.ceil(periods / 100))
    bar = ProgressBar(periods, enabled=bool(progress), label="inelastic ")
    try:
        for first in range(0, periods, chunk):
            stop = min(periods, first + chunk)
            status, j, r = _advance(
                s.engine.accelerations, s.engine.energies, q, vel, s.params, scheme,
                dissipation, first, stop, audit, (e_c, h_t, w_t), (s.stride, *samples),
            )  # fmt: skip
            if status != _RUNNING:
                check_audit(h_t[:, j], w_t[:, j], h0, s.bound, j, s.dt, s.damping)
            bar.update(stop - first)
    finally:
        bar.close()
    return result(s, e_c, h_t, w_t, integral, samples if s.stride else None)


__all__ = ["DAMPING_KINDS", "InelasticResult", "simulate_inelastic"]
