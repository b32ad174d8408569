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

from .. import validation as v
from ..damped import InelasticResult, check_audit, result, setup
from ..ensemble import check_sink
from ..errors import ParameterError
from ..glossary import renamed
from ..integrators import get_scheme
from ..model import SECONDS_PER_PARTICLE_STEP, RunSettings, Sink, Well
from ..worklimit import check_particle_steps, scheme_factor

#: Seconds of one step of :func:`simulate_inelastic_reference` (a Python loop over the
#: scheme's stages, NumPy over runs): STEP_SECONDS[0] + STEP_SECONDS[1] k per step, plus
#: STEP_SECONDS[2] k R, times the scheme's stage factor.  Measured on the 2-core machine
#: (flat n = 4, dt = 0.05, damping 0.5, 2026-11-26, load about 7): 0.82 and 1.47 ms per step
#: at k = 1 and 5 with R = 2 runs, 1.34 and 2.96 ms with R = 512; the constants are rounded
#: up so that the estimate is not optimistic.
STEP_SECONDS = (6e-4, 2e-4, 1e-6)
#: Seconds of one right-hand side of :func:`solve_damped_ivp` (0.29-0.32 ms measured at
#: k = 1 and 5, n = 2, 4 and 10, same machine and day), and its evaluations per period:
#: IVP_EVALUATIONS[0] + IVP_EVALUATIONS[1] x the engine's steps per period at tol 1e-8
#: (measured 3019-4171 evaluations against 267-1588 engine steps), plus what DOP853's
#: stability needs against the damping's rate (:func:`_ivp_evaluations`).
IVP_SECONDS = 3.5e-4
IVP_EVALUATIONS = (2000.0, 4.0)


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
    _registered(sink)
    v.flag("dissipative_stage", dissipative_stage)
    q, vel, h0, engine, params = s.q, s.vel, s.h0, s.engine, s.params
    dt, steps = s.dt, s.steps
    a, b = get_scheme(s.scheme).arrays()
    runs, periods = q.shape[1], settings.periods
    k = sink.particles
    per_step = STEP_SECONDS[0] + STEP_SECONDS[1] * k + STEP_SECONDS[2] * k * runs
    seconds = float(periods) * steps * per_step * scheme_factor(s.scheme)
    check_particle_steps("periods", periods, seconds / SECONDS_PER_PARTICLE_STEP,
                         f"{runs} run(s) x {periods} period(s) x {steps} step(s) of the "
                         "NumPy reference")  # fmt: skip
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

    settings = check_sink(sink, settings)
    _registered(sink)
    damping = v.nonnegative("damping", damping)
    periods = v.positive_int("periods", periods)
    settings.check(sink)
    plain, damped = _ivp_evaluations(sink, settings, damping)
    name, value = ("damping", damping) if damped > plain else ("periods", periods)
    seconds = (plain + damped) * IVP_SECONDS * periods
    check_particle_steps(name, value, seconds / SECONDS_PER_PARTICLE_STEP,
                         f"{periods} period(s) of DOP853 at rtol 1e-12, about "
                         f"{plain + damped:.3g} evaluations each")  # fmt: skip
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


def _registered(sink: Sink) -> None:
    """The contact weight here reads a registered shape's n and gamma: refuse a user's well."""
    if not isinstance(sink.well, Well):
        raise ParameterError("sink", sink, "a Sink of a registered shape (a sinktheory.Well)",
                             why="the NumPy reference reads the well's n and gamma")  # fmt: skip


def _ivp_evaluations(sink: Sink, settings: RunSettings, damping: float) -> tuple[float, float]:
    """Estimated right-hand sides of one period of :func:`solve_damped_ivp`: those of
    :data:`IVP_EVALUATIONS`, and those DOP853's stability would need against the fastest
    damping rate, c s (1 + mu)/mu with the contact weight s = 2n V/gamma at most 2n
    E/gamma (E the total energy's bound): a step h with h rate <= 3.3, 12 evaluations a
    step.  An upper bound: at damping 5 and 20 (flat n = 4, k = 1) DOP853 took 3638 and
    3458 evaluations against 7042 and 15267 estimated, the particles spending most of a
    period away from the wall."""
    from ..stepsize import choose

    energy = settings.total_energy_bound(sink)
    steps = choose(sink, energy, 1e-8).steps_per_period
    w, mu = sink.well, sink.mu
    rate = damping * (2.0 * w.n * energy / w.gamma) * (1.0 + mu) / mu
    return IVP_EVALUATIONS[0] + IVP_EVALUATIONS[1] * steps, 12 * 2 * np.pi * rate / 3.3


__all__ = ["simulate_inelastic_reference", "solve_damped_ivp"]
