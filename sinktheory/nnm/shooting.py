r"""Periodic orbits of a conservative system by shooting with Newton's method.

Unknowns and equations.  A periodic orbit is a start state z0 and a period T with
Phi_T(z0) = z0, Phi_T the time-T map of :class:`~sinktheory.nnm.system.FlowSystem`
(N steps of the symplectic scheme, the same N along a branch).  For a conservative
system these equations are degenerate twice over: every point of the orbit is a
solution (fixed by a *phase condition*), and the orbits come in one-parameter families
along which the energy varies, so Phi_T(z0) = z0 has one equation too many (energy
conservation makes one component redundant) and its Jacobian [M - I, f] is singular
even with a phase condition.  Following Munoz-Almaraz, Freire, Galan, Doedel and
Vanderbauwhede (Physica D 181, 2003, "Continuation of periodic orbits in conservative and
Hamiltonian systems") we add an *unfolding parameter* sigma:

    Phi_T(z0) - z0 + sigma grad H(z0) = 0        (2D equations; the solution has sigma = 0)
    c . (z0 - z_ref)                   = 0        (phase condition)
    H(z0) - h                          = 0        (energy constraint, h given)

Unknowns (z0, ln T, sigma): 2D + 2, square.  grad H(z0) spans the direction missing
from the range of M - I (g^T M = g^T on a periodic orbit, so g is a left null vector of
M - I), which makes the Jacobian regular at an isolated family member.  Any periodic
orbit forces sigma = 0 (a nonzero sigma would move the end point across energy levels
which the flow conserves), so |sigma| is reported as a check; it comes out at the
level of the energy error of the scheme over one period, not exactly 0, because the
discrete map conserves a modified energy (O(dt^p) away from H).  Muñoz-Almaraz et al.
add sigma grad H to the vector field; adding it to the end-point residual is the
first-order equivalent and needs no non-symplectic integration.

Phase conditions: ``"velocity"`` (default) sets the velocity of one coordinate
(default the first: the container X for the sink) to zero at t = 0, so orbits start at a
turning point; every synchronous normal mode passes through one.  ``"orthogonal"``
uses c = f(z_ref): the start lies on the hyperplane through a reference point normal
to the flow (the Poincaré section used between continuation steps).

Invariant subspaces: ``free`` lists the state indices that may move; the others keep
their start values (for the sink, ``subspace="plane"`` keeps y_j = 0, dy_j/dt = 0).  The
equations are then solved in the subspace only, so a transverse multiplier passing
through 1 (a symmetry-breaking bifurcation) does not make Newton singular; the transverse
multipliers still come from the full monodromy.

The period enters as ln T so that the unknowns are of order one whether T is 2 pi or
1e-4 (light particles oscillate fast).

Examples
--------
>>> import numpy as np
>>> from sinktheory.nnm.system import FlowSystem
>>> s = FlowSystem("duffing2", [])
>>> orbit = shoot(s, np.array([0.1, 0.1, 0, 0]), 2 * np.pi, steps=128, total_energy=0.01)
>>> round(orbit.frequency, 6), bool(abs(orbit.total_energy - 0.01) < 1e-14)
(1.000933, True)
>>> bool(orbit.residual < 1e-12 and abs(orbit.sigma) < 1e-10)
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import validation as v
from ..errors import NumericalError, ParameterError, ShootingError
from ..glossary import old_attribute, renamed
from .stability import Floquet, floquet
from .system import FlowSystem

__all__ = [
    "MAX_ITER",
    "MAX_SHOOT_STEPS",
    "MAX_STEP",
    "Orbit",
    "shoot",
    "XTOL",
]

#: Newton stops when the update's largest component is below this (ln T, z0 units).
XTOL = 1e-11
#: Newton iterations before giving up.
MAX_ITER = 25
#: Largest Newton update in scaled units (a damped step beyond it).
MAX_STEP = 0.25
#: Most integration steps per period of a shooting: the splitting schemes' error is at
#: round-off long before (sixth order: (h omega)^6 ~ 1e-16 near 500 steps per fastest
#: oscillation), and every Newton iteration carries 2D tangent vectors over them.
MAX_SHOOT_STEPS = 10**6


@renamed(parameter="continue_in", energy="total_energy")
@dataclass
class ShootingProblem:
    """The periodicity equations of one system, continued in ``continue_in``.

    Unknowns u = (z0[free], ln T, sigma, lam): lam is ln h for ``continue_in="energy"``
    (h the total energy), otherwise the value of the named system parameter at the fixed
    total energy ``total_energy``.  ``base`` holds the values of the state components that
    are not free.
    """

    system: FlowSystem
    steps: int
    free: np.ndarray
    base: np.ndarray
    continue_in: str = "energy"
    total_energy: float = math.nan
    phase: str = "velocity"
    phase_index: int = 0
    phase_ref: np.ndarray | None = None

    parameter = old_attribute("continue_in")
    energy = old_attribute("total_energy")

    def __post_init__(self) -> None:
        self.free = np.asarray(self.free, dtype=int)
        self.base = np.asarray(self.base, dtype=float).copy()
        if self.continue_in != "energy":
            self.system.index(self.continue_in)  # validates the name
        if self.phase not in ("velocity", "orthogonal"):
            raise ParameterError("phase", self.phase, "'velocity' or 'orthogonal'")
        D = self.system.dim
        if self.phase == "velocity" and D + self.phase_index not in set(self.free.tolist()):
            raise ParameterError(
                "phase_index", self.phase_index, "a coordinate whose velocity is free"
            )

    # --- packing ------------------------------------------------------------------
    def lam(self, system: FlowSystem, h: float) -> float:
        if self.continue_in == "energy":
            return math.log(h)
        return float(system.params[system.index(self.continue_in)])

    def pack(self, z0: np.ndarray, T: float, sigma: float, lam: float) -> np.ndarray:
        return np.concatenate([np.asarray(z0)[self.free], [math.log(T), sigma, lam]])

    def unpack(self, u: np.ndarray):
        z0 = self.base.copy()
        z0[self.free] = u[: self.free.size]
        return z0, math.exp(u[-3]), u[-2], u[-1]

    def system_at(self, lam: float) -> tuple[FlowSystem, float]:
        """(system, energy h) at continuation value lam."""
        if self.continue_in == "energy":
            return self.system, math.exp(lam)
        return self.system.with_param(self.continue_in, lam), self.total_energy

    def phase_vector(self, system: FlowSystem) -> tuple[np.ndarray, np.ndarray]:
        D = system.dim
        if self.phase == "velocity":
            c = np.zeros(2 * D)
            c[D + self.phase_index] = 1.0
            return c, np.zeros(2 * D)
        ref = self.base if self.phase_ref is None else self.phase_ref
        return system.vector_field(ref), ref

    # --- equations ----------------------------------------------------------------
    def evaluate(self, u: np.ndarray, *, lam_column: bool = True):
        """G(u) (nF + 2,), its Jacobian (nF + 2, nF + 3) and the orbit data at u."""
        z0, T, sigma, lam = self.unpack(u)
        system, h = self.system_at(lam)
        try:
            zT, M = system._propagate(z0, T, steps=self.steps)
        except NumericalError as err:  # the step is too large for a far-off iterate
            raise ShootingError(f"integration failed during Newton: {err}") from err
        F = self.free
        g = system.gradient(z0)
        fT = system.vector_field(zT)
        c, ref = self.phase_vector(system)
        G = np.concatenate([(zT - z0 + sigma * g)[F], [c @ (z0 - ref), system.hamiltonian(z0) - h]])
        n = F.size
        J = np.zeros((n + 2, n + 3))
        J[:n, :n] = (M - np.eye(M.shape[0]))[np.ix_(F, F)]
        J[:n, n] = T * fT[F]
        J[:n, n + 1] = g[F]
        J[n, :n] = c[F]
        J[n + 1, :n] = g[F]
        if lam_column:
            if self.continue_in == "energy":
                J[n + 1, n + 2] = -h
            else:
                dz, dH = system._param_derivative(z0, T, self.continue_in, steps=self.steps)
                J[:n, n + 2] = dz[F]
                J[n + 1, n + 2] = dH
        return G, J, (system, z0, T, sigma, zT, M)

    def orbit(self, u: np.ndarray, data, iterations: int) -> Orbit:
        system, z0, T, sigma, zT, M = data
        fl = floquet(M, system.vector_field(z0), system.gradient(z0), self.free)
        return Orbit(
            system=system,
            z0=z0,
            period=T,
            steps=self.steps,
            sigma=float(sigma),
            residual=float(np.max(np.abs(zT - z0))),
            iterations=iterations,
            monodromy=M,
            floquet=fl,
            free=tuple(int(i) for i in self.free),
            u=u.copy(),
        )

    def scales(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(unknown scales, equation scales) for equilibration and the stopping test.

        Positions scale with their largest component a, velocities with a omega
        (omega = 2 pi / T), ln T, sigma and lam with 1; the equations like the
        components they are residuals of, the phase row like a velocity (or like
        |c| a), the energy row like h.
        """
        z0, T, _, lam = self.unpack(u)
        system, h = self.system_at(lam)
        D = system.dim
        F = self.free
        a = max(float(np.max(np.abs(z0[:D]))), 1e-300)
        w = 2 * math.pi / T
        zs = np.where(F < D, a, a * w)
        c, _ = self.phase_vector(system)
        phase = float(np.abs(c[F]) @ zs) or 1.0
        gs = np.abs(system.gradient(z0)[F]) @ zs
        usc = np.concatenate([zs, [1.0, 1.0 / max(gs / max(zs.max(), 1e-300), 1e-300), 1.0]])
        gsc = np.concatenate([zs, [phase, max(abs(h), gs, 1e-300)]])
        return usc, gsc

    def newton(self, u: np.ndarray, *, extra=None, max_iter: int = MAX_ITER, xtol: float = XTOL):
        """Solve G(u) = 0 for u, with lam fixed (``extra`` None) or with one more equation
        ``extra = (t, u_pred)``: t . (u - u_pred) = 0 (pseudo-arclength).

        The linear systems are equilibrated with :meth:`scales`; Newton stops when every
        update component is below ``xtol`` times its scale, or when the scaled residual
        is at round-off level (1e-12) and stops decreasing (the map's own noise).
        """
        u = np.array(u, dtype=float)
        last = math.inf
        for it in range(1, max_iter + 1):
            G, J, data = self.evaluate(u, lam_column=extra is not None)
            usc, gsc = self.scales(u)
            if extra is None:
                A, b = J[:, :-1] * usc[:-1], -G
                rs = gsc
            else:
                t, up = extra
                A = np.vstack([J, t]) * usc
                b = -np.concatenate([G, [t @ (u - up)]])
                rs = np.concatenate([gsc, [1.0]])
            A, b = A / rs[:, None], b / rs
            res = float(np.max(np.abs(b)))
            if not np.all(np.isfinite(A)) or not np.all(np.isfinite(b)):
                raise ShootingError(f"non-finite residual or Jacobian at Newton iteration {it}")
            if res < 1e-12 and res >= 0.5 * last:
                return u, J, data, it - 1
            last = min(last, res)
            try:
                y = np.linalg.solve(A, b)
            except np.linalg.LinAlgError:
                y = np.linalg.lstsq(A, b, rcond=None)[0]
            big = float(np.max(np.abs(y)))
            if not math.isfinite(big):
                raise ShootingError(f"singular Newton matrix at Newton iteration {it}")
            if big > MAX_STEP:  # damped far from the solution (scaled units)
                y = y * (MAX_STEP / big)
            du = y * (usc[:-1] if extra is None else usc)
            if extra is None:
                du = np.concatenate([du, [0.0]])
            u = u + du
            if np.max(np.abs(y[:-1] if extra is None else y)) < xtol:
                G, J, data = self.evaluate(u, lam_column=True)
                return u, J, data, it

        raise ShootingError(
            f"Newton did not converge in {it} iterations (last scaled update "
            f"{np.max(np.abs(y)):.3g}, scaled residual {res:.3g})"
        )


@dataclass
class Orbit:
    """A periodic orbit found by :func:`shoot` or along a branch.

    Attributes
    ----------
    system : FlowSystem
        The system (with its parameters at this orbit).
    z0 : (2D,) start state (q, v); period : T; steps : N (dt = T / N).
    sigma : the unfolding parameter (0 on an exact periodic orbit; reported as a check).
    residual : max |Phi_T(z0) - z0|.
    monodromy : (2D, 2D) Jacobian of the time-T map at z0.
    floquet : :class:`~sinktheory.nnm.stability.Floquet`
    free : the free state indices (the invariant subspace holding the orbit).
    """

    system: FlowSystem
    z0: np.ndarray
    period: float
    steps: int
    sigma: float
    residual: float
    iterations: int
    monodromy: np.ndarray = field(repr=False)
    floquet: Floquet = field(repr=False)
    free: tuple[int, ...] = ()
    u: np.ndarray | None = field(default=None, repr=False)

    @property
    def frequency(self) -> float:
        """omega = 2 pi / T (rad per unit time)."""
        return 2 * math.pi / self.period

    @property
    def total_energy(self) -> float:
        """The orbit's total energy H(z0)."""
        return self.system.hamiltonian(self.z0)

    energy = old_attribute("total_energy")

    def trajectory(self, samples: int = 200) -> tuple[np.ndarray, np.ndarray]:
        """(t, z(t)) on ``samples`` + 1 equally spaced times over one period (same steps)."""
        per = max(1, self.steps // v.positive_int("samples", samples, maximum=10**6))
        n = self.steps // per
        dt = self.period / self.steps
        zs = [self.z0]
        z = self.z0
        for _ in range(n):
            z = self.system._propagate(z, dt * per, steps=per, jacobian=False)
            zs.append(z)
        return np.arange(n + 1) * per * dt, np.array(zs)

    def half_period(self) -> tuple[np.ndarray, np.ndarray, float]:
        """(z(T/2), Jacobian of the half-period map, symmetry error max|z(T/2) + z0|).

        For orbits odd under the half-period shift (the synchronous normal modes of the
        even potentials here), the transverse coefficient has period T/2 and the
        transverse monodromy is the square of the half-period block.
        """
        if self.steps % 2:
            raise ParameterError("steps", self.steps, "even for the half-period map")
        zT, M, zh, Mh = self.system._propagate(self.z0, self.period, steps=self.steps, half=True)
        return zh, Mh, float(np.max(np.abs(zh + self.z0)))

    def transverse_half_traces(self) -> np.ndarray:
        """phi_half = tr / 2 of each particle's (y_j, dy_j/dt) block of the half-period map.

        The sink's transverse directions decouple particle by particle on the plane
        y = 0 (V is even in y), so each 2 x 2 block is that particle's half-period map;
        it is the coupled-system counterpart of :attr:`sinktheory.floquet.FloquetChart.phi_half`
        (the paper's fixed-container normal mode).
        """
        D = self.system.dim
        other = [i for i in range(D) if i not in self.free]
        _, Mh, _ = self.half_period()
        out = []
        for i in other:
            block = Mh[np.ix_([i, D + i], [i, D + i])]
            out.append(0.5 * np.trace(block))
        return np.array(out)


def subspace_indices(system: FlowSystem, subspace: str | None) -> np.ndarray:
    """State indices free to move: all (``None``/``"full"``) or, for the sink, the plane
    y_j = 0 (``"plane"``): X, u_j and their velocities."""
    D = system.dim
    if subspace in (None, "full"):
        return np.arange(2 * D)
    if subspace == "plane":
        from ..engine.cache import user_well

        well = user_well(system.system)
        if well is None and not system.system.startswith("sink_"):
            raise ParameterError("subspace", subspace, "'full' for a system without particles")
        if well is not None:  # a user's well: y = 0 must be invariant at its values
            from ..userwell import y_invariant

            given = zip(well.parameter_names, system.params.tolist(), strict=False)  # mu last
            values = well.values(**dict(given))
            invariant, reason = y_invariant(well.potential.subs(values))
            if not invariant:
                raise ParameterError("subspace", subspace, f"'full' in the {well.name} well",
                                     why=f"y = 0 is not invariant: {reason}")  # fmt: skip
        k = (D - 1) // 2
        q = list(range(0, 1 + k))
        return np.array(q + [D + i for i in q])
    raise ParameterError("subspace", subspace, "'full' or 'plane'")


@renamed(energy="total_energy")
def checked_start(
    system, z0, total_energy=None, name: str = "total_energy"
) -> tuple[np.ndarray, float]:
    """(z0 as a float state, target total energy h): ParameterError unless ``system`` is
    a :class:`FlowSystem`, z0 a finite state of its length 2D and h (default: the total
    energy of z0) a finite positive number (refused naming ``name``)."""
    if not isinstance(system, FlowSystem):
        raise ParameterError("system", system, "a sinktheory.nnm.system.FlowSystem")
    z0 = v.real_array("z0", z0)
    if z0.shape != (2 * system.dim,) or not np.isfinite(z0).all():
        raise ParameterError("z0", z0.shape, f"a finite state of length {2 * system.dim}")
    h = v.positive(name, system.hamiltonian(z0) if total_energy is None else total_energy)
    return z0, h


def checked_steps(steps, T) -> tuple[int, float]:
    """(steps, T): steps per period an integer in [2, :data:`MAX_SHOOT_STEPS`], the
    period guess a finite number > 0.

    Examples
    --------
    >>> checked_steps(400, 6.28)
    (400, 6.28)
    >>> checked_steps(10**12, 6.28)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: steps = 1000000000000 is not allowed: must be an \
integer in [2, 1000000]
    """
    return v.positive_int("steps", steps, minimum=2, maximum=MAX_SHOOT_STEPS), v.positive("T", T)


@renamed(energy="total_energy")
def shoot(
    system: FlowSystem,
    z0,
    T: float,
    *,
    steps: int,
    total_energy: float | None = None,
    subspace: str | None = None,
    phase: str = "velocity",
    phase_index: int = 0,
) -> Orbit:
    """The periodic orbit near (z0, T) at total energy ``total_energy`` (default H(z0)).

    Parameters
    ----------
    system : FlowSystem
    z0 : array (2D,)
        Guess of the start state (q, v).
    T : float
        Guess of the period.
    steps : int
        Steps per period N (dt = T / N); choose dt small against the fastest motion.
    total_energy : float, optional
        The orbit's total energy h = H(z0, v0).
    subspace : None, "full" or "plane"
        Invariant subspace to stay in (see :func:`subspace_indices`).
    phase, phase_index
        Phase condition (see the module docstring).

    Returns
    -------
    Orbit

    Raises
    ------
    ShootingError
        If Newton does not converge.
    """
    z0, h = checked_start(system, z0, total_energy)
    steps, T = checked_steps(steps, T)
    free = subspace_indices(system, subspace)
    problem = ShootingProblem(
        system, steps, free, z0, "energy", h, phase, phase_index, phase_ref=z0.copy()
    )
    u = problem.pack(z0, T, 0.0, problem.lam(system, h))
    u, J, data, it = problem.newton(u)
    return problem.orbit(u, data, it)
