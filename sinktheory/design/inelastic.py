"""Inelastic particle-wall contact: a reference integrator with an audited dissipation.

The paper notes that real absorption is enhanced by inelastic collisions.  Here the
contact of particle j with the soft wall dissipates through a viscous force on its
velocity *relative to the container*, with a coefficient that lives only where the wall
acts:

    F_j = -c0 s(x_j, y_j) (xdot_j, ydot_j),    s = 2n V(x_j, y_j) / gamma,

s being the wall term of the well (about 1 at the wall, (1/2)^(2n) half-way to it, so
the force vanishes in the free interior like a contact force), and the reaction -F_j,x
acting on the container (momentum is exchanged, never created).  c0 = 0 is the
conservative model.

Integration (Strang splitting of the conservative and the dissipative vector fields)::

    step(h) = D(h/2) o S(h) o D(h/2)

S is one step of the symplectic splitting scheme :mod:`sinktheory.integrators` uses for
the conservative system (separable coordinates: the container X and the particles'
absolute u_j = X + x_j, y_j).  D is the dissipative field with the positions frozen:
it is linear in the velocities and, particle by particle, exactly solvable -- the
relative velocity w = udot_j - Xdot decays as exp(-c (1 + mu)/mu t) with the total
momentum mu udot_j + Xdot kept, and ydot_j as exp(-c t/mu).  D(tau) is the symmetric
product of these exact pair flows (particles 1..k over tau/2, then k..1 over tau/2), so
the composed step is symmetric and of second order.  With c0 constant this is the
conformal-symplectic Strang splitting; with the contact weight s(q) it is a splitting
into exactly integrated sub-flows, justified by that, by its order (tested) and by the
audit below.

Audit: each exact pair flow removes exactly the kinetic energy it takes out (positions
are frozen), so the dissipated work W is accumulated without approximation and

    H(t) + W(t) = H(0)

holds to the conservative integrator's energy error; every run is checked at every
period end, and a run over ``energy_bound`` raises
:class:`~sinktheory.errors.EnergyDriftError`.  With c0 = 0 every velocity update adds
an exact zero, so the results are bitwise those of the same integrator without the
dissipative stage.

Equivalent damping ratio of the container: the zeta of a linear dashpot on the container
(omega = 1) that would dissipate the same work over the same time,

    zeta_eq = W(t) / (2 omega  integral_0^t E_c dt)

(for a lightly damped oscillator <Xdot^2> = E_c, whose dashpot power is 2 zeta omega
Xdot^2).

This is a NumPy reference (a Python loop over steps, vectorised over runs): fine for
tests and short studies, too slow for 1500-period design sweeps; the engine change that
would make it fast is described in the README's "Design explorer" section.

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
>>> res = simulate_inelastic(sink, RunSettings(runs=2, periods=1, seed=1), damping=0.5,
...                          dt=0.02)
>>> bool(res.max_audit_error < 1e-8), bool((res.dissipated[:, -1] > 0).all())
(True, True)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..engine.cache import load
from ..errors import EnergyDriftError, NonFiniteStateError, ParameterError
from ..integrators import get_scheme
from ..model import RunSettings, Sink
from ..simulate import (
    ENERGY_BOUND,
    default_step,
    engine_name,
    engine_params,
    random_positions,
    split_values,
    start_state,
)
from ..stepsize import aligned_step

#: Default scheme of the conservative stage: high order keeps the audit tight (it measures
#: the conservative stage's energy error); the splitting itself is of order 2.
INELASTIC_SCHEME = "blanes-moan6"
#: Default energy tolerance of the conservative stage's step.
INELASTIC_TOL = 1e-6


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
    damping, dt, steps_per_period, method
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


def contact_weight(sink: Sink, q: np.ndarray) -> np.ndarray:
    """s_j = 2n V(x_j, y_j)/gamma of every particle, (k, R), from engine coordinates q."""
    k = sink.particles
    x = q[1 : 1 + k] - q[0]
    y = q[1 + k : 1 + 2 * k]
    w = sink.well
    return 2.0 * w.n * np.asarray(w.potential(x, y), dtype=float) / w.gamma


def dissipate(sink: Sink, q, vel, damping: float, tau: float) -> np.ndarray:
    """Apply D(tau) to the velocities ``vel`` (1 + 2k, R) in place; return the work (R,).

    Exact pair flows, particles 1..k over tau/2 then k..1 over tau/2 (see the module
    docstring).  With ``damping`` = 0 every update adds an exact zero.
    """
    k, mu = sink.particles, sink.mu
    c = damping * contact_weight(sink, q)  # (k, R)
    work = np.zeros(vel.shape[1])
    half = 0.5 * tau
    for j in list(range(k)) + list(range(k - 1, -1, -1)):
        # x: relative velocity decays, total momentum mu udot + Xdot kept
        w = vel[1 + j] - vel[0]
        shrink = -np.expm1(-c[j] * (1.0 + mu) / mu * half)  # 1 - e, exactly 0 for c = 0
        dw = -shrink * w
        vel[1 + j] += dw / (1.0 + mu)
        vel[0] -= mu * dw / (1.0 + mu)
        w_new = w + dw
        # y: the container does not move in y
        yd = vel[1 + k + j].copy()  # (a view would see the update below)
        dy = np.expm1(-c[j] / mu * half) * yd  # (e - 1) ydot, exactly 0 for c = 0
        vel[1 + k + j] = yd + dy
        reduced = mu / (1.0 + mu)
        work += 0.5 * reduced * (w * w - w_new * w_new) + 0.5 * mu * (yd * yd - (yd + dy) ** 2)
    return work


def simulate_inelastic(
    sink: Sink,
    settings: RunSettings | None = None,
    *,
    damping: float = 0.0,
    method: str = INELASTIC_SCHEME,
    dt: float | None = None,
    dissipative_stage: bool = True,
    energy_bound: float = ENERGY_BOUND,
) -> InelasticResult:
    """Integrate the ensemble with inelastic wall contact (see the module docstring).

    Parameters
    ----------
    sink, settings
        As for :func:`sinktheory.simulate.simulate` (same start states for a seed).
    damping : float >= 0
        c0, the contact damping coefficient (force per relative velocity at the wall).
    method : str
        Scheme of the conservative stage S (the splitting is of order 2 whatever S is).
    dt : float, optional
        Step (default :func:`sinktheory.simulate.default_step` of ``method`` for an energy
        error of :data:`INELASTIC_TOL`), aligned so a period is a whole number of steps.
    dissipative_stage : bool
        False leaves D out altogether (the conservative reference of the bitwise check).
    energy_bound : float > 0
        Largest ``|H + W - H0| / H0`` tolerated at a period end.

    Returns
    -------
    InelasticResult
    """
    settings = RunSettings() if settings is None else settings
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    damping = v.nonnegative("damping", damping)
    bound = v.positive("energy_bound", energy_bound)
    scheme = get_scheme(method)
    settings.check(sink)
    values = start_state(sink, settings.energy, random_positions(settings, sink.particles))
    q, vel = split_values(values)
    engine = load(engine_name(sink))
    params = engine_params(sink)
    h0 = engine.block_energies(q, vel, params)[0]
    if dt is None:
        dt, steps = default_step(sink, float(np.max(h0)), scheme.name, INELASTIC_TOL)
    else:
        dt, steps = aligned_step(v.positive("dt", dt))
    a, b = scheme.arrays()
    runs, periods = q.shape[1], settings.periods
    e_c = np.empty((runs, periods + 1))
    h_t = np.empty((runs, periods + 1))
    w_t = np.zeros((runs, periods + 1))
    e_c[:, 0], h_t[:, 0] = 0.5 * (vel[0] ** 2 + q[0] ** 2), h0
    work = np.zeros(runs)
    integral = np.zeros(runs)  # trapezoid of E_c over the steps
    acc = engine.block_accelerations(q, params)
    ec_prev = 0.5 * (vel[0] ** 2 + q[0] ** 2)
    for j in range(1, periods + 1):
        for _ in range(steps):
            if dissipative_stage:
                work += dissipate(sink, q, vel, damping, 0.5 * dt)
            for i in range(len(a)):
                vel += (b[i] * dt) * acc
                q += (a[i] * dt) * vel
                acc = engine.block_accelerations(q, params)
            vel += (b[-1] * dt) * acc
            if dissipative_stage:
                work += dissipate(sink, q, vel, damping, 0.5 * dt)
            ec = 0.5 * (vel[0] ** 2 + q[0] ** 2)
            integral += 0.5 * dt * (ec + ec_prev)
            ec_prev = ec
        total = engine.block_energies(q, vel, params)[0]
        e_c[:, j], h_t[:, j], w_t[:, j] = ec_prev, total, work
        if not np.all(np.isfinite(total)):
            bad = int(np.flatnonzero(~np.isfinite(total))[0])
            raise NonFiniteStateError(f"run {bad}: non-finite state at t = {j} T")
        err = np.abs(total + work - h0) / h0
        if err.max() > bound:
            r = int(np.argmax(err))
            raise EnergyDriftError(
                f"run {r}: |H + W - H0|/H0 = {err[r]:.3g} > {bound:.3g} at t = {j} T "
                f"(dt = {dt:.4g}, damping = {damping:g})"
            )
    audit = np.max(np.abs(h_t + w_t - h0[:, None]) / h0[:, None], axis=1)
    zeta = np.where(integral > 0, work / (2.0 * np.where(integral > 0, integral, 1.0)), 0.0)
    return InelasticResult(
        container_energy=e_c,
        total_energy=h_t,
        dissipated=w_t,
        initial_energy=h0,
        audit_errors=audit,
        max_audit_error=float(audit.max()),
        damping_ratio=zeta,
        damping=damping,
        dt=dt,
        steps_per_period=steps,
        method=scheme.name,
    )


__all__ = ["InelasticResult", "contact_weight", "dissipate", "simulate_inelastic"]
