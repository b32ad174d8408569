"""A user's well at given parameter values: what a :class:`~sinktheory.model.Sink` needs
of a well, so that ``simulate`` runs a well of your own.

:class:`WellAt` wraps a :class:`~sinktheory.userwell.UserWell` and the values of its
parameters.  It is checked once (:func:`~sinktheory.userwell.check_well`: real and finite
near the centre, a minimum there, a bounded basin up to a certified escape energy) and then
answers what the set-up asks of :class:`~sinktheory.model.Well`: V at points (measured
from V(0, 0), as every particle energy of a user's well is), its Hessian (for the step
choice), the reach of a particle energy, and whether a start position or an energy lies in
the basin.  The ensemble runs on the well's own compiled engine
(:func:`sinktheory.engine.cache.well_name`), whose parameters are the well's in declaration
order, then the particle mass.

Examples
--------
>>> from sinktheory.userwell import UserWell
>>> hh = WellAt(UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {}))
>>> round(hh.escape_energy * 6, 12), hh.parameters
(1.0, {})
>>> hh.check_energy(0.2)
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: particle_energy = 0.2 is not allowed: must be in (0, \
0.166666667): above V(0, 0) and below the escape energy of the hh well (measured from V(0, \
0)) (...)
"""

from __future__ import annotations

import functools
import math

import numpy as np

from . import validation as v
from .errors import NumericalError, ParameterError

__all__ = ["WellAt"]


class WellAt:
    """A user's ``well`` (:class:`~sinktheory.userwell.UserWell`) at its parameter values:
    the defaults, replaced by ``given`` (each within its declared range)."""

    def __init__(self, well, **given: float) -> None:
        from .userwell import UserWell, check_well

        if not isinstance(well, UserWell):
            raise ParameterError("well", well, "a sinktheory.userwell.UserWell")
        self.definition = well
        self.report = check_well(well, **given)
        self.basin = self.report.basin
        self._values = well.values(**given)
        self.parameters = {s.name: float(x) for s, x in self._values.items()}
        self._layer: float | None = None

    @property
    def shape(self) -> str:
        """The well's name (what the built-in wells call their shape)."""
        return self.definition.name

    @property
    def escape_energy(self) -> float:
        """The escape energy measured from V(0, 0) (inf: bounded as far as checked)."""
        return self.basin.escape_energy

    def potential(self, x, y) -> np.ndarray:
        """V(x, y) - V(0, 0) at arrays of finite points (relative to the container),
        broadcast together; +inf (or -inf on a well falling without bound) where V
        overflows float range beyond the basin, which callers read as outside it."""
        x, y = v.points(x, y)
        numeric = self.basin.well
        with np.errstate(all="ignore"):  # beyond the basin V may overflow: large, not inside
            return np.asarray(numeric.f(x, y), dtype=float) - numeric.v0

    def hessian_at(self, x: float, y: float) -> np.ndarray:
        """The 2 x 2 Hessian of V at (x, y)."""
        x, y = v.finite("x", x), v.finite("y", y)
        h = np.asarray(self.basin.well._hessian(x, y), dtype=float)
        if not np.all(np.isfinite(h)):
            raise NumericalError(
                f"{self.shape} well: the Hessian of V at ({x:g}, {y:g}) is not finite"
            )
        return h

    def reach(self, particle_energy: float, *, name: str = "particle_energy"):
        """Bounds (x_max, y_max) of |x|, |y| over the basin of a particle of energy
        ``particle_energy`` (from V(0, 0)); refused, naming ``name``, at or above the
        escape energy."""
        e = self.check_energy(particle_energy, name=name)
        r = self.basin.reach(self.basin.well.v0 + e)
        return r.x_max, r.y_max

    def check_energy(self, particle_energy: float, *, name: str = "particle_energy") -> float:
        """``particle_energy`` if a particle holding it stays in the basin, else a
        ParameterError naming ``name``."""
        return self.basin.check_energy(particle_energy, name=name)

    def check_position(self, name: str, x: float, y: float) -> None:
        """Raise ParameterError naming ``name`` unless (x, y) is a finite point of the
        basin: V - V(0, 0) below the escape energy all along the segment from the centre
        (65 points), so a point past a ridge, where V may fall again, is refused."""
        allowed = f"a point of the {self.shape} well's basin (V - V(0, 0) below its escape energy)"
        try:
            x, y = float(x), float(y)
        except (TypeError, ValueError):
            raise ParameterError(name, (x, y), allowed) from None
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ParameterError(name, (x, y), allowed)
        t = np.linspace(0.0, 1.0, 65)
        e = self.potential(t * x, t * y)
        e = np.where(np.isfinite(e), e, np.inf)
        if not np.all(e < self.escape_energy):
            worst = int(np.argmax(e >= self.escape_energy))
            at = f"({t[worst] * x:.6g}, {t[worst] * y:.6g})"
            why = f"V - V(0, 0) = {e[worst]:.6g} at {at} on the way"
            raise ParameterError(name, (x, y), allowed, why=why)

    def _box_edge(self, box: float) -> tuple[float, float, float]:
        """(largest V - V(0, 0), x, y) on a grid of the start box, 17 x 17 points, edge
        included (inf where V is not finite)."""
        box = v.positive("box", box)
        edge = np.linspace(-box, box, 17)
        xs, ys = (a.ravel() for a in np.meshgrid(edge, edge))
        e = self.potential(xs, ys)
        e = np.where(np.isfinite(e), e, np.inf)
        worst = int(np.argmax(e))
        return float(e[worst]), float(xs[worst]), float(ys[worst])

    def box_potential(self, box: float) -> float:
        """The largest V - V(0, 0) on a 17 x 17 grid of the start box (about the most a
        particle starting at rest in it holds); +inf where V overflows float range on it
        (a box reaching far beyond the basin)."""
        return self._box_edge(box)[0]

    def check_box(self, box: float) -> None:
        """Raise ParameterError naming ``box`` unless the start box (-box, box)^2 lies in
        the basin: V below the escape energy on a 17 x 17 grid of it."""
        e, x, y = self._box_edge(box)
        if not (e < self.escape_energy):
            raise ParameterError(
                "box", box, f"a start box inside the {self.shape} well's basin",
                why=f"V - V(0, 0) = {e:.6g} at ({x:g}, {y:g}), not below the escape energy "
                f"{self.escape_energy:.6g}",
            )  # fmt: skip

    def wall_layer(self) -> float:
        """The relative thickness of the soft wall, as the adaptive step's controller takes
        it: 1 / the largest q . grad V / (V - V(0, 0)) over 64 rays from the centre, each
        at the point q where it meets the rigid wall (the largest abs(r_i) of the wall
        ratios equal to 1).  For V proportional to w^(2n), w a wall ratio homogeneous of
        degree 1 (the elliptic well), it is 1/(2n), the layer a registered shape uses.
        0.5 for a well without wall ratios (the controller then has no wall to approach).

        Raises ParameterError naming ``wall_ratios`` if no ray meets the wall.

        Examples
        --------
        >>> from sinktheory.userwell import UserWell
        >>> ell = WellAt(UserWell("e", "((x/a)**2 + (y/b)**2)**n", {"a": 2, "b": 1, "n": 3},
        ...                       ["sqrt((x/a)**2 + (y/b)**2)"]))
        >>> round(ell.wall_layer() * 6, 12)
        1.0
        """
        if self._layer is None:
            self._layer = self._measured_layer()
        return self._layer

    def wall_distance(self, c: float, s: float, limit: float = 2.0**40) -> float:
        """The distance t from the centre along the unit direction (c, s) at which the
        largest abs(r_i) of the wall ratios reaches 1 (the rigid wall), located by brentq
        between powers of 2 up to ``limit``; inf if it does not within ``limit``, or
        without wall ratios.  ``c`` and ``s`` finite, ``limit`` > 0.

        Examples
        --------
        >>> from sinktheory.userwell import UserWell
        >>> e = WellAt(UserWell("e", "(x/a)**2 + (y/b)**2", {"a": 2, "b": 1},
        ...                     ["sqrt((x/a)**2 + (y/b)**2)"]))
        >>> round(e.wall_distance(1.0, 0.0), 12), round(e.wall_distance(0.0, -1.0), 12)
        (2.0, 1.0)
        """
        from scipy.optimize import brentq

        c, s, limit = v.finite("c", c), v.finite("s", s), v.positive("limit", limit)
        if not self._ratios:
            return math.inf
        scales = 2.0 ** np.arange(-20.0, 41.0)
        scales = np.append(scales[scales < limit], limit)

        def size(t):
            with np.errstate(all="ignore"):
                return np.max([np.abs(np.asarray(r(t * c, t * s), dtype=float))
                               for r in self._ratios], axis=0)  # fmt: skip

        beyond = np.nonzero(size(scales) >= 1.0)[0]
        if not len(beyond):
            return math.inf
        i = int(beyond[0])
        lo = 0.0 if i == 0 else scales[i - 1]
        return float(brentq(lambda t: float(size(t)) - 1.0, lo, scales[i], xtol=1e-14))

    @functools.cached_property
    def leading_order(self):
        """The leading term of V - V(0, 0) at the centre, its degree 2n
        (:func:`sinktheory.basin.leading_order`, a WellDefinitionError where it is not a
        positive form of x, y): what the law of E_c and the equipartition share read as the
        well's wall exponent n (a user's parameter named n need not be it).

        Examples
        --------
        >>> from sinktheory.userwell import UserWell
        >>> WellAt(UserWell("quartic", "x**n + y**n", {"n": 4})).leading_order.n
        2
        """
        from .basin import leading_order

        return leading_order(self.definition.potential, self._values, self.shape)

    @functools.cached_property
    def _ratios(self) -> list:
        """The wall ratios as NumPy functions of (x, y) at the well's values."""
        from .basin import numeric

        return [numeric(r, self._values) for r in self.definition.wall_ratios]

    def _measured_layer(self) -> float:
        if not self._ratios:
            return 0.5
        steepest = 0.0
        for angle in np.linspace(0.0, 2.0 * np.pi, 64, endpoint=False):
            c, s = math.cos(angle), math.sin(angle)
            t = self.wall_distance(c, s)
            if not math.isfinite(t):
                continue
            rise = float(self.potential(t * c, t * s))
            slope = float(np.dot(self.basin.well._gradient(t * c, t * s), (t * c, t * s)))
            if math.isfinite(rise) and math.isfinite(slope) and rise > 0:
                steepest = max(steepest, slope / rise)
        if not steepest > 0:
            raise ParameterError(
                "wall_ratios", [str(r) for r in self.definition.wall_ratios],
                "ratios whose level 1 (the rigid wall) some ray from the centre meets, with V "
                "rising there",
            )  # fmt: skip
        return 1.0 / steepest

    def __repr__(self) -> str:
        values = ", ".join(f"{k}={x:g}" for k, x in self.parameters.items())
        return f"WellAt({self.shape}{': ' if values else ''}{values})"
