"""The NumPy version of the inelastic-contact splitting: the independent check of the
compiled integrator and the baseline of its benchmark.

:func:`simulate_inelastic_reference` integrates the same model with the same splitting
D(h/2) o S(h) o D(h/2) as :func:`sinktheory.damped.simulate_inelastic` (see
there for the model, the exact pair flows and the audit), written independently in NumPy:
a Python loop over steps, array operations over runs, the contact weight from the well's
own potential (:meth:`sinktheory.model.Well.potential`) instead of the generated energy
kernel.  It is kept only for that: ``tests/studies/test_design_inelastic.py`` compares the
compiled integrator with it, and ``benchmarks/bench_inelastic.py`` measures the speed-up
at equal accuracy.  It is too slow for design sweeps (a Python loop over steps).

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
>>> res = simulate_inelastic_reference(sink, RunSettings(runs=2, periods=1, seed=1),
...                                    damping=0.5, dt=0.02)
>>> bool(res.max_audit_error < 1e-8), bool((res.dissipated[:, -1] > 0).all())
(True, True)
"""

from __future__ import annotations

import numpy as np

from ..damped import InelasticResult, check_audit, result, setup
from ..glossary import renamed
from ..integrators import get_scheme
from ..model import RunSettings, Sink


def contact_weight(sink: Sink, q: np.ndarray) -> np.ndarray:
    """s_j = 2n V(x_j, y_j)/gamma of every particle, (k, R), from engine coordinates q."""
    k = sink.particles
    x = q[1 : 1 + k] - q[0]
    y = q[1 + k : 1 + 2 * k]
    w = sink.well
    return (2.0 * w.n / w.gamma) * np.asarray(w.potential(x, y), dtype=float)


def dissipate(sink: Sink, q, vel, damping: float, tau: float, kind: str = "contact"):
    """Apply D(tau) to the velocities ``vel`` (1 + 2k, R) in place; return the work (R,).

    Exact pair flows, particles 1..k over tau/2 then k..1 over tau/2, with the contact
    weight or (``kind`` = "viscous") the weight 1.  With ``damping`` = 0 every update
    adds an exact zero.
    """
    k, mu = sink.particles, sink.mu
    weight = contact_weight(sink, q) if kind == "contact" else np.ones((k, q.shape[1]))
    c = damping * weight  # (k, R)
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


@renamed(method="scheme")
def simulate_inelastic_reference(
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
) -> InelasticResult:
    """The NumPy integration of :func:`~sinktheory.damped.simulate_inelastic`
    (same parameters, same start states, same checks; no sampling, no progress bar)."""
    s = setup(sink, settings, damping, scheme, dt, tol, energy_bound, damping_kind, start)
    settings = RunSettings() if settings is None else settings
    q, vel, h0, engine, params = s.q, s.vel, s.h0, s.engine, s.params
    dt, steps = s.dt, s.steps
    a, b = get_scheme(s.scheme).arrays()
    runs, periods = q.shape[1], settings.periods
    e_c = np.empty((runs, periods + 1))
    h_t = np.empty((runs, periods + 1))
    w_t = np.zeros((runs, periods + 1))
    total, shared, _ = engine.block_energies(q, vel, params)
    e_c[:, 0], h_t[:, 0] = shared, total
    work = np.zeros(runs)
    integral = np.zeros(runs)  # trapezoid of E_c over the steps
    acc = engine.block_accelerations(q, params)
    ec_prev = 0.5 * (vel[0] * vel[0] + q[0] * q[0])
    for j in range(1, periods + 1):
        for _ in range(steps):
            if dissipative_stage:
                work += dissipate(sink, q, vel, s.damping, 0.5 * dt, s.kind)
            for i in range(len(a)):
                vel += (b[i] * dt) * acc
                q += (a[i] * dt) * vel
                acc = engine.block_accelerations(q, params)
            vel += (b[-1] * dt) * acc
            if dissipative_stage:
                work += dissipate(sink, q, vel, s.damping, 0.5 * dt, s.kind)
            ec = 0.5 * (vel[0] * vel[0] + q[0] * q[0])
            integral += 0.5 * dt * (ec + ec_prev)
            ec_prev = ec
        total, shared, _ = engine.block_energies(q, vel, params)
        e_c[:, j], h_t[:, j], w_t[:, j] = shared, total, work
        check_audit(total, work, h0, s.bound, j, dt, s.damping)
    return result(s, e_c, h_t, w_t, integral)


def solve_damped_ivp(sink: Sink, settings: RunSettings, damping: float, periods: int):
    """(E_c, W, integral of E_c dt) at t = ``periods`` T for run 0 of ``settings``: the
    damped equations of motion (contact weight) integrated by ``solve_ivp`` (DOP853, rtol
    1e-12) with W and the integral appended to the state -- an integrator independent of
    the splitting, for the tests and the benchmark."""
    from scipy.integrate import solve_ivp

    from ..ensemble import random_positions, start_state
    from ..simulate import first_order_rhs

    k, mu, w = sink.particles, sink.mu, sink.well
    f = first_order_rhs(sink)

    def rhs(t, z):
        dz = np.concatenate((f(t, z[:-2]), [0.0, 0.0]))
        X, Xd = z[0], z[1]
        u, y = z[2 : 2 + k], z[2 + k : 2 + 2 * k]
        ud, yd = z[2 + 2 * k : 2 + 3 * k], z[2 + 3 * k : 2 + 4 * k]
        c = damping * 2 * w.n * np.asarray(w.potential(u - X, y), float) / w.gamma
        rel = ud - Xd
        dz[2 + 2 * k : 2 + 3 * k] -= c * rel / mu
        dz[1] += np.sum(c * rel)
        dz[2 + 3 * k : 2 + 4 * k] -= c * yd / mu
        dz[-2] = np.sum(c * (rel**2 + yd**2))
        dz[-1] = 0.5 * (Xd**2 + X**2)
        return dz

    z0 = start_state(sink, settings.container_energy, random_positions(settings, k))[0]
    T = 2 * np.pi * periods
    sol = solve_ivp(rhs, (0, T), np.concatenate((z0, [0.0, 0.0])), "DOP853",
                    rtol=1e-12, atol=1e-14)  # fmt: skip
    z = sol.y[:, -1]
    return 0.5 * (z[1] ** 2 + z[0] ** 2), z[-2], z[-1]


__all__ = ["simulate_inelastic_reference", "solve_damped_ivp"]
