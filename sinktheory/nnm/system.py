"""The flow map of a generated engine system and its exact Jacobian (monodromy).

:class:`FlowSystem` wraps one compiled engine system (:mod:`sinktheory.engine`) for the
periodic-orbit analyses: the state is one vector z = (q, v) of length 2D in the engine's
coordinate order (for the sink: X, u_1..u_k, y_1..y_k, then their velocities, u absolute),
and the time-T map is N steps of size dt = T / N of the engine's symplectic splitting
scheme.  The deviation vectors of the engine start as the identity, with no
renormalisation, so they return the Jacobian dz(T)/dz(0) of *this discrete map* exactly
(round-off aside): Newton on the periodicity condition then sees the derivative of the
very map whose fixed point it seeks.  N is fixed along a branch so that the map is smooth
in T.

Derivatives that the tangent map does not give:

* d z(T) / dT: the vector field f(z(T)) of the continuous flow.  The discrete map is the
  time-T flow of a modified Hamiltonian whose vector field differs from f by O(dt^p)
  (p the order of the scheme), so Newton's Jacobian is that close to exact and the
  iteration still converges to round-off in a few steps.
* d z(T) / d(parameter): a central difference (two more runs).

Units: the engine's (for the sink the paper's: container mass 1, spring 1, T = 2 pi).

Examples
--------
>>> import numpy as np
>>> s = FlowSystem("duffing2", [])
>>> s.dim, s.masses.tolist()
(2, [1.0, 1.0])
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import validation as val
from ..engine.cache import engine_system
from ..engine.core import Ensemble
from ..errors import NumericalError, ParameterError
from ..glossary import old_attribute
from ..integrators import DEFAULT_SCHEME, get_scheme
from ..layout import SINK_PARAMS
from ..model import MAX_RUNS

__all__ = ["FlowSystem"]


def parameter_names(system: str) -> tuple[str, ...]:
    """Names of the runtime parameters of engine ``system``.

    Examples
    --------
    >>> parameter_names("sink_flat"), parameter_names("duffing2")
    (('alpha', 'beta', 'gamma', 'n', 'mu'), ())

    A user's well's engine (:func:`sinktheory.engine.cache.well_name`) takes the well's
    own parameters in declaration order, then mu.
    """
    from ..engine.cache import user_well

    well = user_well(system)
    if well is not None:
        return (*well.parameter_names, "mu")
    return SINK_PARAMS if system.startswith("sink_") else ()


@dataclass
class FlowSystem:
    """Time-T maps of an engine system with their Jacobians.

    Parameters
    ----------
    system : str
        Engine name, e.g. ``"sink_flat"`` or ``"duffing2"``.
    params : sequence of float
        The engine's runtime parameters (see :func:`parameter_names`).
    scheme : str
        Splitting scheme (:func:`sinktheory.integrators.get_scheme`).
    members : int
        Number of members (particles) for engines whose dimension is read from the
        state (the sink: D = 1 + 2 k); ignored for fixed-dimension systems.
    """

    system: str
    params: np.ndarray
    scheme: str = DEFAULT_SCHEME
    members: int = 0
    _scheme: object = field(init=False, repr=False)
    masses: np.ndarray = field(init=False)

    def __post_init__(self) -> None:
        self.system = engine_system("system", self.system)
        self.params = np.ascontiguousarray(val.real_array("params", self.params)).reshape(-1)
        self.members = val.positive_int("members", self.members, minimum=0, maximum=MAX_RUNS)
        names = parameter_names(self.system)
        if self.params.size != len(names) or not np.isfinite(self.params).all():
            raise ParameterError(
                "params",
                self.params.tolist(),
                f"{len(names)} finite values {names} for {self.system}",
            )
        self._scheme = get_scheme(self.scheme)
        from ..engine.cache import load

        self.module = load(self.system)
        D = self.dim
        # masses from the kinetic energy of unit velocities (q = 0)
        q = np.zeros((D, D + 1))
        v = np.zeros((D, D + 1))
        v[:, 1:] = np.eye(D)
        total = self.module.block_energies(q, v, self.module.table_of(self.params, D + 1))[0]
        self.masses = 2.0 * (total[1:] - total[0])

    @property
    def dim(self) -> int:
        """Number of coordinates D (the state has 2D components)."""
        mod = self.module
        if hasattr(mod, "DIM"):
            return int(mod.DIM)
        return int(mod.SHARED + getattr(mod, "MEMBER_COORDS", 0) * self.members)

    @property
    def parameter_names(self) -> tuple[str, ...]:
        return parameter_names(self.system)

    def with_param(self, name: str, value: float) -> FlowSystem:
        """A copy with parameter ``name`` set to ``value``."""
        p = self.params.copy()
        p[self.index(name)] = val.finite("value", value)
        return FlowSystem(self.system, p, self.scheme, self.members)

    def index(self, name: str) -> int:
        names = self.parameter_names
        if not isinstance(name, str) or name not in names:
            raise ParameterError("parameter", name, f"one of {names or '(none)'}")
        return names.index(name)

    # --- pointwise quantities -----------------------------------------------------
    def hamiltonian(self, z: np.ndarray, params: np.ndarray | None = None) -> float:
        """The Hamiltonian H(z): the total energy at the state z."""
        D = self.dim
        z = self._point("z", z, 2 * D)
        if params is not None:
            params = val.finite_array("params", params)
            if params.shape != self.params.shape:
                allowed = f"shape {self.params.shape}, the system's parameters"
                raise ParameterError("params", f"an array of shape {params.shape}", allowed)
        p = self.params if params is None else params
        table = self.module.table_of(p, 1)
        return float(self.module.block_energies(z[:D, None], z[D:, None], table)[0][0])

    energy = old_attribute("hamiltonian")

    def accelerations(self, q: np.ndarray) -> np.ndarray:
        """Accelerations (D,) at positions q (D,)."""
        table = self.module.table_of(self.params, 1)
        q = self._point("q", q, self.dim)
        a = self.module.block_accelerations(q[:, None], table)[:, 0]
        if not np.all(np.isfinite(a)):
            raise NumericalError(f"{self.system}: the accelerations overflow at q = {q.tolist()}")
        return a

    @staticmethod
    def _point(name: str, z, size: int) -> np.ndarray:
        """``z`` as a finite float vector of ``size`` components, else a ParameterError."""
        z = val.finite_array(name, z)
        if z.shape != (size,):
            raise ParameterError(name, f"an array of shape {z.shape}", f"shape ({size},)")
        return z

    def vector_field(self, z: np.ndarray) -> np.ndarray:
        """f(z) = (v, a(q))."""
        D = self.dim
        z = self._point("z", z, 2 * D)
        return np.concatenate([z[D:], self.accelerations(z[:D])])

    def gradient(self, z: np.ndarray) -> np.ndarray:
        """grad H(z) = (-M a(q), M v) in the (q, v) coordinates."""
        D = self.dim
        z = self._point("z", z, 2 * D)
        return np.concatenate([-self.masses * self.accelerations(z[:D]), self.masses * z[D:]])

    def stiffness(self, q: np.ndarray | None = None, h: float = 1e-6) -> np.ndarray:
        """-da/dq (D, D) at q (default 0) by central differences (for linear modes)."""
        D = self.dim
        q = np.zeros(D) if q is None else self._point("q", q, D)
        h = val.positive("h", h)
        K = np.empty((D, D))
        for j in range(D):
            e = np.zeros(D)
            e[j] = h
            K[:, j] = -(self.accelerations(q + e) - self.accelerations(q - e)) / (2 * h)
        return K

    # --- maps -----------------------------------------------------------------------
    def _propagate(
        self,
        z0: np.ndarray,
        T: float,
        *,
        steps: int,
        jacobian: bool = True,
        half: bool = False,
        params: np.ndarray | None = None,
    ):
        """z(T) after ``steps`` steps of size T / steps, and its Jacobian dz(T)/dz(0).

        Parameters
        ----------
        z0 : array (2D,) or (2D, R)
            Start state(s); columns are independent runs.
        T : float
            Time (> 0).
        steps : int
            N; with ``half`` it must be even and the map at T/2 is returned too.
        jacobian : bool
            Also return the monodromy (2D, 2D) (or (2D, 2D, R)).
        params : array, optional
            Parameters other than the system's (for finite differences).

        Returns
        -------
        zT, M  or, with ``half``, (zT, M, z_half, M_half).
        """
        if not (math.isfinite(T) and T > 0):
            raise ParameterError("T", T, "a finite positive period")
        steps = int(steps)
        if half and steps % 2:
            raise ParameterError("steps", steps, "even when the half-period map is wanted")
        D = self.dim
        z0 = np.asarray(z0, float)
        single = z0.ndim == 1
        Z = z0[:, None] if single else z0
        R = Z.shape[1]
        p = self.params if params is None else np.asarray(params, float)
        if jacobian:
            eye = np.repeat(np.eye(2 * D)[:, :, None], R, axis=2)
            dq, dv = eye[:D].copy(), eye[D:].copy()
        else:
            dq = dv = None
        # the engine advances its arrays in place: give it copies
        ens = Ensemble(self.system, Z[:D].copy(), Z[D:].copy(), p, dq=dq, dv=dv, tangent="none")
        dt = T / steps
        parts = (steps // 2, steps - steps // 2) if half else (steps,)
        states, jacobians = [], []
        for n in parts:
            ens.run(self._scheme, dt=dt, steps=n, segments=1, record=())
            zT = np.concatenate([ens.q, ens.v])
            states.append(zT[:, 0] if single else zT)
            if jacobian:
                M = np.concatenate([ens.dq, ens.dv])
                jacobians.append(M[:, :, 0] if single else M)
        res = []
        for k in range(len(parts) - 1, -1, -1):  # full period first, then the half
            res.append(states[k])
            if jacobian:
                res.append(jacobians[k])
        return tuple(res) if len(res) > 1 else res[0]

    def _param_derivative(
        self, z0: np.ndarray, T: float, name: str, *, steps: int, rel: float = 1e-6
    ) -> tuple[np.ndarray, float]:
        """(d z(T) / dp, dH(z0) / dp) for parameter ``name`` by central differences."""
        i = self.index(name)
        p0 = self.params
        h = rel * max(1.0, abs(p0[i]))
        out, energies = [], []
        for s in (1, -1):
            p = p0.copy()
            p[i] += s * h
            out.append(self._propagate(z0, T, steps=steps, jacobian=False, params=p))
            energies.append(self.hamiltonian(z0, p))
        return (out[0] - out[1]) / (2 * h), (energies[0] - energies[1]) / (2 * h)
