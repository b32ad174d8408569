"""The tangent map of the splitting step: monodromy matrices and their checks.

The engine (:class:`sinktheory.engine.core.Ensemble`) carries deviation vectors through
the exact derivative of each splitting step.  Started from the identity columns and left
raw (``tangent="none"``) they give the Jacobian M of the discrete flow map over any
number of steps, in the engine's coordinates z = (q, v).  In the canonical coordinates
w = (q, p), p = m v, it is S M S^-1 with S = diag(1, m), and a symplectic map satisfies
M_w^T J M_w = J, J = [[0, I], [-I, 0]].

Examples
--------
>>> import numpy as np
>>> q, v = np.array([[0.0], [-0.25]]), np.array([[0.42081], [0.0]])
>>> M = monodromy("henon_heiles", q, v, [], dt=0.01, steps=100)
>>> M.shape
(1, 4, 4)
>>> bool(symplectic_defect(M, np.ones(2))[0] < 1e-14)
True
>>> F = finite_difference_jacobian("henon_heiles", q, v, [], dt=0.01, steps=100)
>>> bool(np.abs(F - M).max() < 1e-7 * np.abs(M).max())
True
"""

from __future__ import annotations

import numpy as np

from .. import validation as val
from ..errors import ParameterError
from ..glossary import renamed
from ..integrators import DEFAULT_SCHEME, get_scheme
from .general import check_block, check_params, check_run

__all__ = ["canonical", "finite_difference_jacobian", "monodromy", "symplectic_defect"]


@renamed(method="scheme")
def monodromy(
    system: str,
    q,
    v,
    params,
    *,
    dt: float,
    steps: int,
    segments: int = 1,
    scheme: str = DEFAULT_SCHEME,
    block: int | None = None,
) -> np.ndarray:
    """Jacobian of ``segments`` x ``steps`` steps of the splitting map at each run's state.

    Parameters
    ----------
    system : str
        Engine system name (e.g. ``sink_flat``, ``henon_heiles``).
    q, v : arrays (D, R)
        Start states (the engine's coordinates: positions and velocities).
    params : sequence of float
        The system's runtime parameters.
    dt, steps, segments : float, int, int
        Step, steps per segment, segments.

    Returns
    -------
    ndarray (R, 2D, 2D)
        M[r] maps (dq, dv) at the start to (dq, dv) at the end, in (q, v) coordinates.
    """
    system, q, v, dt, steps, segments = check_run(system, q, v, dt, steps, segments)
    params = check_params(system, params)
    block = check_block(block)
    q = q.copy()  # the engine advances its arrays in place
    D, R = q.shape
    eye = np.broadcast_to(np.eye(2 * D)[:, :, None], (2 * D, 2 * D, R))
    from ..engine.core import Ensemble  # numba loads with the first run

    ens = Ensemble(
        system, q, np.array(v, float), params, dq=eye[:D].copy(), dv=eye[D:].copy(), tangent="none"
    )
    ens.run(get_scheme(scheme), dt=dt, steps=steps, segments=segments, record=(), block=block)
    return np.concatenate([ens.dq, ens.dv]).transpose(2, 0, 1)


def canonical(M: np.ndarray, masses) -> np.ndarray:
    """M in (q, v) coordinates -> S M S^-1 in canonical (q, p = m v) coordinates."""
    masses = val.finite_array("masses", masses, "the D masses (finite numbers > 0)", ndim=1)
    if not (masses.size and np.all(masses > 0)):
        raise ParameterError("masses", masses.tolist(), "the D masses (finite numbers > 0)")
    D = masses.size
    M = val.finite_array("M", M, f"matrices (..., {2 * D}, {2 * D}) of finite numbers (D = "
                         f"{D} masses)")  # fmt: skip
    if M.ndim < 2 or M.shape[-2:] != (2 * D, 2 * D):
        raise ParameterError("M", f"shape {M.shape}", f"matrices (..., {2 * D}, {2 * D}) "
                                 f"(D = {D} masses)")  # fmt: skip
    s = np.concatenate([np.ones(D), masses])
    return M * s[:, None] / s[None, :]


def symplectic_defect(M: np.ndarray, masses) -> np.ndarray:
    """max |M_w^T J M_w - J| / max(1, ||M_w||_2^2) per run, M_w = :func:`canonical` (M).

    Round-off in the product is of order eps ||M_w||^2, hence the scale.
    """
    W = canonical(M, masses)
    if W.ndim != 3:
        raise ParameterError("M", f"shape {W.shape}", "matrices (runs, 2D, 2D), one a run")
    D = W.shape[-1] // 2
    J = np.block([[np.zeros((D, D)), np.eye(D)], [-np.eye(D), np.zeros((D, D))]])
    E = np.einsum("rji,jk,rkl->ril", W, J, W) - J
    scale = np.maximum(1.0, np.linalg.norm(W, 2, axis=(1, 2)) ** 2)
    return np.abs(E).max(axis=(1, 2)) / scale


@renamed(method="scheme")
def finite_difference_jacobian(
    system: str,
    q,
    v,
    params,
    *,
    dt: float,
    steps: int,
    segments: int = 1,
    scheme: str = DEFAULT_SCHEME,
    h: float = 1e-6,
) -> np.ndarray:
    """Central-difference Jacobian of the same discrete flow map (no tangent vectors).

    Each of the 2D coordinates of each run is displaced by +-h (times max(1, |z_i|)); the
    4 D R displaced states run as one ensemble.  Truncation error O(h^2), round-off
    O(eps |M| / h); for one period of the sink about 1e-8 |M| at h = 1e-6.

    Returns
    -------
    ndarray (R, 2D, 2D), as :func:`monodromy`.
    """
    system, q, v, dt, steps, segments = check_run(system, q, v, dt, steps, segments)
    params = check_params(system, params)
    h = val.positive("h", h)
    D, R = q.shape
    z = np.concatenate([q, v])  # (2D, R)
    step = h * np.maximum(1.0, np.abs(z))  # (2D, R)
    cols = []
    for sign in (1.0, -1.0):
        for i in range(2 * D):
            zz = z.copy()
            zz[i] += sign * step[i]
            cols.append(zz)
    Z = np.concatenate(cols, axis=1)  # (2D, 2 * 2D * R), column block (sign, i) has R runs
    from ..engine.core import Ensemble  # numba loads with the first run

    ens = Ensemble(system, Z[:D], Z[D:], params)
    ens.run(get_scheme(scheme), dt=dt, steps=steps, segments=segments, record=())
    out = np.concatenate([ens.q, ens.v]).reshape(2 * D, 2, 2 * D, R)  # (j, sign, i, r)
    F = (out[:, 0] - out[:, 1]) / (2.0 * step[None])  # (j, i, r)
    return F.transpose(2, 0, 1)
