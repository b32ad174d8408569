"""Damped particles: the engine with its damping on, and an audited dissipation.

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

Implementation: the ensemble engine with its damping switched on
(:class:`sinktheory.engine.core.Ensemble`, ``damping=``): the same compiled stepper,
blocks and threads as :func:`sinktheory.simulate.simulate`, with the damping flow D and
the dissipated work printed per system from its declared
:class:`~sinktheory.engine.systems.Damping`.  Each run's arithmetic is independent of the
other runs, so a seed gives the same numbers whatever the number of runs around it.
:mod:`sinktheory.design.inelastic_reference` is the NumPy version of the same splitting:
the independent check in the tests and the baseline of ``benchmarks/bench_inelastic.py``.

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

from dataclasses import dataclass

import numpy as np

from . import validation as v
from .engine.cache import load
from .engine.core import Ensemble
from .ensemble import (
    check_sink,
    default_energy_bound,
    engine_name,
    engine_params,
    random_positions,
    split_values,
    start_state,
)
from .errors import EnergyDriftError, NonFiniteStateError, ParameterError
from .glossary import old_attribute, renamed
from .integrators import get_scheme
from .layout import StateLayout
from .model import DAMPING_KINDS, RunSettings, Sink
from .runstats import mean_stderr
from .stepsize import PERIOD, check_tol, resolve_step


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
    damping, dt, steps_per_period, scheme, tol, damping_kind
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
    scheme: str
    tol: float | None = None
    damping_kind: str = "contact"
    sample_times: np.ndarray | None = None
    container_x: np.ndarray | None = None
    container_v: np.ndarray | None = None
    sample_dissipated: np.ndarray | None = None
    transverse: np.ndarray | None = None

    method = old_attribute("scheme")

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
    damping: float
    bound: float
    scheme: str
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
    scheme: str | None,
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
    if scheme is not None:
        scheme = get_scheme(scheme).name
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
    top = float(np.max(h0))
    sink.well.check_energy(top, name="total_energy")
    scheme, dt, steps, tol = resolve_step(sink, top, scheme=scheme, dt=dt, tol=tol)
    stride = 0
    if samples:
        steps = -(-steps // samples) * samples
        dt, stride = PERIOD / steps, steps // samples
    return Setup(q, vel, h0, engine, params, damping, bound, scheme, dt, steps, tol, kind,
                 stride)  # fmt: skip


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
        scheme=s.scheme,
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
    ens = Ensemble(
        engine_name(sink), s.q, s.vel, engine_params(sink), reference_energy=s.h0,
        damping=s.damping if dissipative_stage else 0.0, damping_kind=s.kind,
    )  # fmt: skip
    out = ens.run(
        get_scheme(s.scheme), dt=s.dt, steps=s.steps, segments=settings.periods,
        record=("shared", "members", "work", "integral") + (("trajectory",) if s.stride else ()),
        stride=s.stride, bound=s.bound, progress=bool(progress), label="inelastic ",
        unit="period",
    )  # fmt: skip
    total = out.shared.copy()  # H in the order of the engine's energy kernel
    for j in range(sink.particles):
        total += out.members[:, :, j]
    samples = None
    if s.stride:
        rows = out.trajectory  # state rows, the columns of StateLayout
        far = np.abs(rows[..., StateLayout(sink.particles).y]).max(axis=2)
        samples = (rows[:, :, 0], rows[:, :, 1], out.work_samples, far)
    return result(s, out.shared, total, out.work, out.integral, samples)


__all__ = ["DAMPING_KINDS", "InelasticResult", "simulate_inelastic"]
