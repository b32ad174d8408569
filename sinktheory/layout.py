"""Named columns of the simulator's state rows and the packed parameters of its engine.

A state row of a sink with k particles has 2 + 4k columns (paper units; u_j = X + x_j is
particle j's absolute x, velocities are absolute)::

    [X, Xdot, u_1 .. u_k, y_1 .. y_k, udot_1 .. udot_k, ydot_1 .. ydot_k]

The compiled engine (:mod:`sinktheory.engine`) holds the same numbers as coordinates and
velocities (q, v), each (1 + 2k, R): q = [X, u_1..u_k, y_1..y_k], v likewise.
:class:`StateLayout` names every block, so no code indexes a column by number, and
converts between the two forms.  :data:`SINK_PARAMS` names the packed parameter vector
the engine's kernels read.

Examples
--------
>>> import numpy as np
>>> L = StateLayout(2)
>>> L.width, L.names()
(10, ('X', 'Xdot', 'u_1', 'u_2', 'y_1', 'y_2', 'udot_1', 'udot_2', 'ydot_1', 'ydot_2'))
>>> rows = np.arange(10.0)[None]
>>> rows[:, L.y].tolist(), L.relative_positions(rows).tolist()
([[4.0, 5.0]], [[[2.0, 4.0], [3.0, 5.0]]])
>>> q, v = L.split(rows)
>>> q[:, 0].tolist(), bool((L.join(q, v) == rows).all())
([0.0, 2.0, 3.0, 4.0, 5.0], True)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .errors import ParameterError

__all__ = ["pack_params", "SINK_PARAMS", "StateLayout"]

#: The engine's runtime parameters of a sink, in the order its kernels read them (the
#: particle mass is mu = m / k).  The shape is compiled into the engine; k is read from
#: the state's size.
SINK_PARAMS = ("alpha", "beta", "gamma", "n", "mu")


def pack_params(sink) -> np.ndarray:
    """The packed parameter vector :data:`SINK_PARAMS` of ``sink`` for the engine.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> pack_params(Sink(Well(0.5, 0.3, 4), particles=2, mass=0.2)).tolist()
    [0.5, 0.3, 1.0, 4.0, 0.1]

    A user's well (:class:`~sinktheory.wellat.WellAt`) packs its own parameters, in
    declaration order, then mu.
    """
    from .model import Sink

    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    w = sink.well
    if hasattr(w, "definition"):  # a user's well
        return np.array([*w.parameters.values(), sink.mu], dtype=float)
    return np.array([w.alpha, w.beta, w.gamma, w.n, sink.mu], dtype=float)


@dataclass(frozen=True)
class StateLayout:
    """The columns of a state row with ``particles`` = k particles (module docstring)."""

    particles: int
    #: Column of the container's position X and velocity Xdot.
    X: ClassVar[int] = 0
    XDOT: ClassVar[int] = 1

    def __post_init__(self):
        from .validation import positive_int

        object.__setattr__(self, "particles", positive_int("particles", self.particles))

    @classmethod
    def of(cls, values) -> StateLayout:
        """The layout of state rows ``values`` (..., 2 + 4k), read from their width."""
        width = np.shape(values)[-1] if np.ndim(values) else 0
        if width < 6 or (width - 2) % 4:
            raise ParameterError("values", f"state rows of width {width}", "2 + 4k columns, k >= 1")
        return cls((width - 2) // 4)

    @property
    def width(self) -> int:
        return 2 + 4 * self.particles

    def _block(self, i: int) -> slice:
        k = self.particles
        return slice(2 + i * k, 2 + (i + 1) * k)

    @property
    def u(self) -> slice:
        """Absolute x positions u_j = X + x_j."""
        return self._block(0)

    @property
    def y(self) -> slice:
        """y positions (the same in both frames)."""
        return self._block(1)

    @property
    def udot(self) -> slice:
        return self._block(2)

    @property
    def ydot(self) -> slice:
        return self._block(3)

    @property
    def q(self) -> np.ndarray:
        """Columns of the engine's coordinates [X, u.., y..]."""
        return np.r_[self.X, 2 : 2 + 2 * self.particles]

    @property
    def v(self) -> np.ndarray:
        """Columns of the engine's velocities [Xdot, udot.., ydot..]."""
        return np.r_[self.XDOT, 2 + 2 * self.particles : self.width]

    def names(self) -> tuple[str, ...]:
        """Column names, e.g. for the ``state`` coordinate of a dataset."""
        ks = range(1, self.particles + 1)
        blocks = [[f"{c}_{j}" for j in ks] for c in ("u", "y", "udot", "ydot")]
        return ("X", "Xdot", *(name for block in blocks for name in block))

    def _rows(self, name: str, values, ndim: int | None = None) -> np.ndarray:
        """``values`` as float state rows (..., 2 + 4k) (``ndim`` dimensions if given),
        else a ParameterError naming ``name``."""
        from .validation import real_array

        rows = real_array(name, values)
        if rows.ndim < 1 or rows.shape[-1] != self.width or (ndim and rows.ndim != ndim):
            shape = "(R, 2 + 4k)" if ndim == 2 else "(..., 2 + 4k)"
            raise ParameterError(name, f"an array of shape {rows.shape}",
                                 f"state rows of shape {shape}, 2 + 4k = {self.width}")  # fmt: skip
        return rows

    def relative_positions(self, values: np.ndarray) -> np.ndarray:
        """Particle positions (x_j, y_j) in the container's frame, shape (..., k, 2)."""
        values = self._rows("values", values)
        x = values[..., self.u] - values[..., self.X, None]
        return np.stack([x, values[..., self.y]], -1)

    def start(self, X: float, positions: np.ndarray) -> np.ndarray:
        """Rows (R, 2 + 4k): container at ``X``, particles at ``positions`` (R, k, 2)
        relative to it, everything at rest."""
        from .validation import finite, finite_array

        X, positions = finite("X", X), finite_array("positions", positions)
        k = self.particles
        if positions.ndim != 3 or positions.shape[2] != 2 or positions.shape[1] not in (1, k):
            raise ParameterError(
                "positions",
                f"an array of shape {positions.shape}",
                f"shape (R, {k}, 2) (or (R, 1, 2): one position for every particle)",
            )
        values = np.zeros((positions.shape[0], self.width))
        values[:, self.X] = X
        values[:, self.u] = X + positions[:, :, 0]
        values[:, self.y] = positions[:, :, 1]
        return values

    def split(self, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Rows (R, 2 + 4k) as the engine's (q, v), each (1 + 2k, R), contiguous."""
        values = self._rows("values", values, ndim=2)
        return np.ascontiguousarray(values[:, self.q].T), np.ascontiguousarray(values[:, self.v].T)

    def join(self, q: np.ndarray, v: np.ndarray) -> np.ndarray:
        """The engine's (q, v) as rows (R, 2 + 4k)."""
        from .validation import real_array

        q, v = real_array("q", q), real_array("v", v)
        for name, a in (("q", q), ("v", v)):
            if a.ndim != 2 or a.shape != (1 + 2 * self.particles, q.shape[-1]):
                raise ParameterError(name, f"an array of shape {a.shape}",
                                     f"shape (1 + 2k, R) = ({1 + 2 * self.particles}, R), "
                                     "the same R for q and v")  # fmt: skip
        values = np.empty((q.shape[1], self.width))
        values[:, self.q] = q.T
        values[:, self.v] = v.T
        return values
