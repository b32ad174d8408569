"""Floquet multipliers of a periodic orbit: trivial pair, in-plane and transverse sets.

A periodic orbit of an autonomous Hamiltonian system always has the multiplier 1 twice
(the flow direction f and, through energy conservation, the direction across the energy
levels); it sits in a Jordan block, so the eigenvalues computed from a monodromy matrix
with relative error eps split by about sqrt(eps).  Their distance from 1 is reported as
``trivial_error`` (a check of the orbit and of the tangent map: ~1e-7 means the map and
its fixed point are good to ~1e-14).

The *nontrivial* multipliers are computed without that ill-conditioning, from the
monodromy reduced to the energy surface and a section transverse to the flow
(the Poincare map on the energy level): with f the vector field and g = grad H at z0, on
W = {d : f.d = 0, g.d = 0} the reduced map is R = B^T P M B, B an orthonormal basis of
W and P = I - f f^T / |f|^2 the projection along f.  (g^T M = g^T and M f = f at a
periodic orbit, so P M maps W into W.)

Orbits inside an invariant subspace (``free`` coordinates; for the sink the plane
y_j = 0, dy_j/dt = 0) have a block-diagonal monodromy: the in-plane block carries the
trivial pair and the reduction above, the transverse block's eigenvalues are the
transverse multipliers.

Bifurcation test functions (signs change where a real multiplier crosses a value):

* ``plus``: prod (mu - 1) over a multiplier set (a pair through +1: fold of the branch,
  or, for the transverse set, a symmetry-breaking (pitchfork) branch point);
* ``minus``: prod (mu + 1) (a pair through -1: period doubling).

A sign test at the ends of a step misses a pair that reaches -1 (or +1) and turns back
within the step.  :meth:`Floquet.margins` gives, per multiplier set, the signed distance
of the nearest pair from -1 and from +1 in half-trace units, min over pairs of
1 + c and 1 - c with c = Re (mu + 1/mu) / 2 (c = cos theta on the unit circle, c < -1 or
c > 1 for a real pair off it): it touches 0 where a pair touches -1 (+1) and dips below
0 over a window where a pair leaves the circle there and comes back.  The continuation
looks for such dips between its points (:mod:`sinktheory.nnm.continuation`), and
limits its steps so that no multiplier turns by more than a set angle (:func:`angles`)
per step, so a pair cannot swing through -1 or +1 and back unseen.

Examples
--------
>>> import numpy as np
>>> M = np.array([[1.0, 1.0, 0, 0], [0, 1.0, 0, 0], [0, 0, 0.0, 1.0], [0, 0, -1.0, 0]])
>>> f = np.array([1.0, 0, 0, 0]); g = np.array([0, 1.0, 0, 0])
>>> fl = floquet(M, f, g)
>>> np.round(fl.nontrivial, 12).tolist(), float(fl.trivial_error)
([-1j, 1j], 0.0)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..errors import ParameterError

__all__ = ["Floquet", "floquet", "STABILITY_TOL"]

#: |mu| <= 1 + STABILITY_TOL counts as on the unit circle.
STABILITY_TOL = 1e-6


@dataclass(frozen=True)
class Floquet:
    """Multipliers of one periodic orbit.

    Attributes
    ----------
    all : (2D,) complex
        Eigenvalues of the full monodromy matrix.
    nontrivial : complex
        Nontrivial in-plane multipliers (reduced map, 2(d - 1) of them for d free
        coordinates).
    transverse : complex
        Multipliers of the transverse block (empty without a subspace).
    trivial_error : float
        max |mu - 1| of the two eigenvalues of the (in-plane) monodromy nearest to 1.
    """

    all: np.ndarray
    nontrivial: np.ndarray
    transverse: np.ndarray
    trivial_error: float

    @property
    def stable_inplane(self) -> bool:
        return bool(np.all(np.abs(self.nontrivial) <= 1 + STABILITY_TOL))

    @property
    def stable_transverse(self) -> bool:
        return bool(np.all(np.abs(self.transverse) <= 1 + STABILITY_TOL))

    @property
    def stable(self) -> bool:
        """Linearly stable: every nontrivial multiplier on the unit circle."""
        return self.stable_inplane and self.stable_transverse

    def tests(self) -> dict[str, float]:
        """The bifurcation test functions (see the module docstring)."""
        return {
            "inplane_plus": _prod(self.nontrivial - 1),
            "inplane_minus": _prod(self.nontrivial + 1),
            "transverse_plus": _prod(self.transverse - 1),
            "transverse_minus": _prod(self.transverse + 1),
        }

    def margins(self) -> dict[str, float]:
        """Signed distances of the nearest pair from -1 (``*_minus``) and +1 (``*_plus``)
        in half-trace units (see the module docstring; +inf for an empty set).

        Examples
        --------
        >>> mu = np.exp(1j * np.array([-3.0, 3.0]))  # a pair near -1 on the unit circle
        >>> fl = Floquet(mu, mu, np.zeros(0, complex), 0.0)
        >>> round(fl.margins()["inplane_minus"], 6), fl.margins()["transverse_plus"]
        (0.010008, inf)
        """
        return {
            "inplane_plus": _margin(self.nontrivial, -1.0),
            "inplane_minus": _margin(self.nontrivial, 1.0),
            "transverse_plus": _margin(self.transverse, -1.0),
            "transverse_minus": _margin(self.transverse, 1.0),
        }


def angles(mu: np.ndarray) -> np.ndarray:
    """Sorted rotation angles of the multipliers: arccos c on the unit circle (0 at +1, pi
    at -1), -arccosh c beyond +1, pi + arccosh(-c) beyond -1 (c = Re (mu + 1/mu) / 2);
    continuous and decreasing in c, so a pair passing +1 or -1 moves it continuously.

    Examples
    --------
    >>> np.round(angles(np.array([1j, -1j, -2.0, -0.5])), 6).tolist()
    [1.570796, 1.570796, 3.83474, 3.83474]
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        c = np.real((mu + 1.0 / mu) / 2)
    out = np.where(
        c > 1,
        -np.arccosh(np.maximum(c, 1)),
        np.where(c < -1, np.pi + np.arccosh(np.maximum(-c, 1)), np.arccos(np.clip(c, -1, 1))),
    )
    return np.sort(out)


def _margin(mu: np.ndarray, sign: float) -> float:
    """min over the multipliers of 1 + sign Re (mu + 1/mu) / 2."""
    if not mu.size:
        return float("inf")
    with np.errstate(divide="ignore", invalid="ignore"):
        c = np.real((mu + 1.0 / mu) / 2)
    return float(np.min(1.0 + sign * c))


def _prod(x: np.ndarray) -> float:
    return float(np.real(np.prod(x))) if x.size else 1.0


def _sorted(mu: np.ndarray) -> np.ndarray:
    return mu[np.lexsort((np.imag(mu), np.real(mu)))]


def reduced_monodromy(M: np.ndarray, f: np.ndarray, g: np.ndarray) -> np.ndarray:
    """The monodromy on the energy surface modulo the flow (see the module docstring)."""
    n = M.shape[0]
    Q, _ = np.linalg.qr(np.column_stack([f, g, np.eye(n)]))
    B = Q[:, 2:n]
    P = np.eye(n) - np.outer(f, f) / (f @ f)
    return B.T @ P @ M @ B


def floquet(M: np.ndarray, f: np.ndarray, g: np.ndarray, free=None) -> Floquet:
    """Floquet data of a periodic orbit with monodromy M, vector field f, grad H g at z0.

    Parameters
    ----------
    M : (2D, 2D)
    f, g : (2D,)
    free : sequence of int, optional
        State indices of the invariant subspace holding the orbit (default: all).
    """
    M, f, g = (v.real_array(name, x) for name, x in (("M", M), ("f", f), ("g", g)))
    n = M.shape[0] if M.ndim == 2 else 0
    if M.shape != (n, n) or f.shape != (n,) or g.shape != (n,) or n == 0:
        raise ParameterError("M", f"arrays of shapes {M.shape}, {f.shape}, {g.shape}",
                             "a square (2D, 2D) monodromy with f and g of shape (2D,)")  # fmt: skip
    if not (np.isfinite(M).all() and np.isfinite(f).all() and np.isfinite(g).all()):
        raise ParameterError("M", "non-finite entries", "finite M, f and g")
    det = float(np.linalg.det(M))
    if not abs(det - 1.0) <= 0.5:  # singular, or no flow's: Liouville keeps volumes
        raise ParameterError("M", f"a matrix of determinant {det:.3g}",
                             "the monodromy of a Hamiltonian flow (determinant 1)")  # fmt: skip
    free = np.arange(n) if free is None else v.real_array("free", free).ravel()
    if (
        free.size < 2
        or np.any(free % 1)
        or np.any((free < 0) | (free >= n))
        or np.unique(free).size < free.size
    ):
        raise ParameterError("free", free.tolist(), f"two or more distinct indices in [0, {n})")
    free = free.astype(int)
    # an orbit, not an equilibrium: the flow and the energy's gradient do not vanish on it
    for name, vector in (("f", f[free]), ("g", g[free])):
        if not np.any(vector):
            raise ParameterError(name, "a zero vector on the orbit's subspace",
                                 "a non-zero vector (z0 on an orbit, not at rest)")  # fmt: skip
    other = np.setdiff1d(np.arange(n), free)
    Mi = M[np.ix_(free, free)]
    every = np.linalg.eigvals(M)
    inplane = np.linalg.eigvals(Mi)
    near = np.sort(np.abs(inplane - 1.0))[:2]
    nontrivial = np.linalg.eigvals(reduced_monodromy(Mi, f[free], g[free]))
    transverse = np.linalg.eigvals(M[np.ix_(other, other)]) if other.size else np.zeros(0, complex)
    return Floquet(
        all=_sorted(every.astype(complex)),
        nontrivial=_sorted(nontrivial.astype(complex)),
        transverse=_sorted(transverse.astype(complex)),
        trivial_error=float(near.max()),
    )


def classify(before: dict[str, float], after: dict[str, float], fold: bool) -> list[str]:
    """Names of the events between two points from the signs of their test functions.

    ``fold``: the continuation parameter turned back between them (a fold of the branch).
    """
    events = []
    for key, name in (
        ("inplane_minus", "period-doubling"),
        ("transverse_minus", "transverse-period-doubling"),
        ("transverse_plus", "symmetry-breaking"),
    ):
        if np.sign(before[key]) != np.sign(after[key]):
            events.append(name)
    if np.sign(before["inplane_plus"]) != np.sign(after["inplane_plus"]) and not fold:
        events.append("branch-point")
    if fold:
        events.append("fold")
    return events
