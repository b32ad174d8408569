"""Area A(e) of the basin {V < e} of one well: closed forms and a quadrature over its edge.

A particle of mass mu and energy below e fills, in its four-dimensional phase space, the
volume Phi(e) = 2 pi mu \\int (e - V)_+ dx dy; its density of states is therefore
g(e) = Phi'(e) = 2 pi mu A(e), with A(e) the area of the basin of the well around the
centre (derivations/equilibrium.py).  This module computes A(e) for every shape of
:data:`sinktheory.symbolic.SHAPES`.

Closed forms (c = (2 n e / gamma)^(1/(2n)), t = c^2, L = alpha - beta)
------------------------------------------------------------------------
* circular well: A = pi L^2 t;
* flat well: the basin is |y| < c, |x| < D(y) (c^(2n) - y^(2n))^(1/(2n)) with
  D(y) = L + beta y^2, so A = 2 t (L J_0 + beta t J_2), with
  J_m = \\int_{-1}^{1} s^m (1 - s^(2n))^(1/(2n)) ds = B((m + 1)/(2n), 1 + 1/(2n)) / n;
  for beta = 0 it is the area 4 L t Gamma(1 + 1/(2n))^2 / Gamma(1 + 1/n) of a superellipse.

Quadrature (any shape; :func:`sinktheory.basin.star_area`)
-----------------------------------------------------------
Along each ray from the centre at angle theta the edge of the basin is the first radius
r*(theta) where V reaches e; A = 2 \\int_0^{pi/2} r*(theta)^2 d theta for a basin symmetric
under x -> -x and y -> -y (every registered shape is).  r* is found by bisection to
rounding (vectorised over the rays) after a scan that checks V grows along the ray up to
the edge (the basin is star-shaped from the centre; otherwise
:class:`~sinktheory.errors.NumericalError`); the theta integral is the trapezoid rule,
spectrally accurate for the smooth periodic r*(theta)^2, with the number of rays doubled
until two successive values agree to :data:`AREA_RTOL`.

Both refuse energies at or above the shape's escape energy, or where a wall denominator
vanishes within reach (:meth:`sinktheory.model.Well.check_energy`).

A user's well (:class:`WellArea`)
---------------------------------
For a :class:`~sinktheory.userwell.UserWell` at fixed parameter values, energies are
measured from V(0, 0) and A(e) is the same ray quadrature over the basin found by
:mod:`sinktheory.basin` (a full turn: no symmetry is assumed), below its certified escape
energy.  The scaled energy is t = e^(1/n) with 2n the degree of the leading term of V at
the centre (:func:`sinktheory.basin.leading_order`), so that A(e) / t tends to a constant
as e -> 0, as for the registered shapes (whose t differs by a constant factor, which
cancels from the law).

Examples
--------
>>> from sinktheory.model import Well
>>> well = Well(0.5, 0.3, 4)
>>> a = basin_area(well, 0.25)
>>> abs(area_quadrature(well, 0.25) / a - 1) < 1e-12
True
>>> import math
>>> round(basin_area(Well(0.5, 0.3, 2, shape="circular"), 0.25) / (math.pi * 0.2**2), 12)  # t = 1
1.0
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..basin import AREA_RTOL, MAX_RAYS, SCAN_POINTS, Basin, LeadingOrder, leading_order, star_area
from ..errors import ParameterError
from ..glossary import renamed
from ..model import Well
from ..twins import python_kernel

__all__ = [
    "area_quadrature",
    "area_ratio",
    "AREA_RTOL",
    "basin_area",
    "CLOSED_FORMS",
    "MAX_RAYS",
    "scaled_energy",
    "SCAN_POINTS",
    "WellArea",
]


@renamed(energy="particle_energy")
def scaled_energy(well: Well, particle_energy: float) -> float:
    """t = c^2 = (2 n e / gamma)^(1/n), the squared reach of energy e in units of the wall.

    Examples
    --------
    >>> scaled_energy(Well(0.5, 0.3, 4), 0.125)
    1.0
    """
    _check_well(well)
    ratio = 2 * well.n * v.positive("particle_energy", particle_energy) / well.gamma
    if not math.isfinite(ratio) or ratio == 0:  # (2 n e / gamma)^(1/n) would be inf or 0
        raise v.ParameterError(
            "particle_energy", particle_energy,
            f"with 2 n e / gamma a positive float (gamma = {well.gamma:g}, n = {well.n})",
        )  # fmt: skip
    return ratio ** (1.0 / well.n)


def _beta_function(a: float, b: float) -> float:
    return math.exp(math.lgamma(a) + math.lgamma(b) - math.lgamma(a + b))


def _flat_ratio(well: Well, t: np.ndarray) -> np.ndarray:
    """A / t of the flat well: 2 (L J_0 + beta t J_2) (module docstring)."""
    n = well.n
    j0 = _beta_function(1 / (2 * n), 1 + 1 / (2 * n)) / n
    j2 = _beta_function(3 / (2 * n), 1 + 1 / (2 * n)) / n
    return 2 * (well.wall_distance * j0 + well.beta * t * j2)


def _circular_ratio(well: Well, t: np.ndarray) -> np.ndarray:
    """A / t of the circular well: pi L^2."""
    return np.full_like(t, math.pi * well.wall_distance**2)


#: Shapes whose A(e) / t is known in closed form, as a function of (well, t).
CLOSED_FORMS = {"flat": _flat_ratio, "circular": _circular_ratio}


def _check_well(well: Well) -> None:
    if not isinstance(well, Well):
        raise v.ParameterError("well", well, "a sinktheory.model.Well")


def _check(well: Well, particle_energy: float) -> float:
    _check_well(well)
    e = v.positive("particle_energy", particle_energy)
    well.check_energy(e)
    return e


@renamed(energy="particle_energy")
def basin_area(well: Well, particle_energy: float) -> float:
    """A(e): area of the basin {V < e} around the centre (closed form where there is one,
    else :func:`area_quadrature`).

    Parameters
    ----------
    well : Well
    particle_energy : float
        e > 0, below the shape's escape energy.

    Returns
    -------
    float
        The area, in the squared length unit of x, y.

    Raises
    ------
    ParameterError
        e <= 0, at or above escape, or a vanishing wall denominator within reach.
    NumericalError
        The basin is not star-shaped from the centre or the quadrature does not converge.

    Examples
    --------
    >>> from sinktheory.model import Well
    >>> round(basin_area(Well(1.0, 0.0, 1), 0.5), 12)  # the unit disc (n = 1, beta = 0)
    3.14159265359
    """
    e = _check(well, particle_energy)
    closed = CLOSED_FORMS.get(well.shape)
    if closed is None:
        return area_quadrature(well, e)
    t = scaled_energy(well, e)
    return float(t * closed(well, np.array(t)))


def area_ratio(well: Well, t) -> np.ndarray:
    """A / t at scaled energies t (array), t = (2 n e / gamma)^(1/n) > 0: the smooth
    factor of the area (a constant for homogeneous wells).  The caller checks the
    largest energy (:meth:`Well.check_energy`); each point of a shape without closed form
    is one :func:`area_quadrature`.

    Examples
    --------
    >>> from sinktheory.model import Well
    >>> area_ratio(Well(0.5, 0.0, 4, shape="circular"), [0.5, 1.0]).round(12).tolist()
    [0.785398163397, 0.785398163397]
    """
    _check_well(well)
    t = v.real_array("t", t)
    if not np.all(np.isfinite(t) & (t > 0)):
        raise v.ParameterError("t", t.tolist(), "finite numbers > 0")
    closed = CLOSED_FORMS.get(well.shape)
    if closed is not None:
        return closed(well, t)
    energies = well.gamma * t**well.n / (2 * well.n)
    return np.array([_quadrature(well, e) for e in energies.ravel()]).reshape(t.shape) / t


@renamed(energy="particle_energy")
def area_quadrature(well: Well, particle_energy: float) -> float:
    """A(e) by the trapezoid rule over the rays from the centre (module docstring), for any
    shape; the closed forms are checked against it.

    Examples
    --------
    >>> from sinktheory.model import Well
    >>> well = Well(0.5, 0.0, 3, shape="symmetric")  # beta = 0: a superellipse of side 0.5
    >>> t = scaled_energy(well, 0.1)
    >>> exact = 4 * 0.25 * t * math.gamma(1 + 1 / 6) ** 2 / math.gamma(1 + 1 / 3)
    >>> abs(area_quadrature(well, 0.1) / exact - 1) < 1e-12
    True
    """
    return _quadrature(well, _check(well, particle_energy))


def _quadrature(well: Well, e: float) -> float:
    kernel = python_kernel(well.kernels.potential)
    args = (well.alpha, well.beta, well.gamma, well.n)
    x_max, y_max = well.reach(e)
    r_max = 1.000001 * math.hypot(x_max, y_max)
    return star_area(lambda x, y: kernel(x, y, *args), e, r_max, well.shape, quarter=True)


@dataclass(frozen=True)
class WellArea:
    """A(e) of a user's well at fixed parameter values, energies e measured from V(0, 0)
    (module docstring).

    Attributes
    ----------
    name : str
        The well's name.
    values : dict
        Its parameter values by name.
    basin : Basin
        Its basin (escape energy with certificate, reach, area).
    order : LeadingOrder
        The leading term of V at the centre, of degree 2n.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> ellipse = UserWell("ellipse", "((x/a)**2 + (y/b)**2)**2", {"a": 0.3, "b": 0.2})
    >>> area = WellArea.of(ellipse)
    >>> area.n, round(area.area(0.5) / (math.pi * 0.3 * 0.2 * 0.5**0.5), 12)
    (2, 1.0)
    """

    name: str
    values: dict
    basin: Basin
    order: LeadingOrder

    @classmethod
    def of(cls, well, values: Mapping[str, float] | None = None, well_check=None) -> WellArea:
        """The area function of ``well`` (a :class:`~sinktheory.userwell.UserWell`) at its
        parameter ``values`` by name (its defaults for the others), after
        :func:`~sinktheory.userwell.check_well` (``well_check``, its result when it has
        been run at those values already) and :func:`~sinktheory.basin.leading_order` (each raises
        :class:`~sinktheory.errors.WellDefinitionError` for a refused well)."""
        from ..userwell import UserWell, well_report

        if not isinstance(well, UserWell):
            raise ParameterError("well", well, "a sinktheory.userwell.UserWell")
        given, report = well_report(well, values, well_check)
        order = leading_order(well.potential, well.values(**given), well.name)
        values = {name: float(value) for name, value in report.values.items()}
        return cls(well.name, values, report.basin, order)

    @property
    def n(self) -> int | float:
        """Half the degree of V's leading term at the centre (the wall power 2n of an
        elliptic well; 1 for a well with a positive definite Hessian there)."""
        return self.order.n

    @renamed(energy="particle_energy")
    def check_energy(self, particle_energy: float, *, name: str = "particle_energy") -> float:
        """``particle_energy`` if it lies in (0, escape energy), measured from V(0, 0), else
        ParameterError naming ``name`` (:meth:`sinktheory.basin.Basin.check_energy`)."""
        return self.basin.check_energy(particle_energy, name=name)

    @renamed(energy="particle_energy")
    def rays(self, particle_energy: float) -> float:
        """A radius every ray from the centre crosses the edge of the basin at ``particle_energy``
        (and every lower energy) before (the reach, with a margin of 1e-6)."""
        r = self.basin.reach(self.basin.well.v0 + self.check_energy(particle_energy))
        return 1.000001 * math.hypot(r.x_max, r.y_max)

    @renamed(energy="particle_energy")
    def area(self, particle_energy: float, *, within: float | None = None) -> float:
        """A(e); ``within`` as in :meth:`sinktheory.basin.Basin.area` (default: the rays of
        this energy)."""
        e = self.check_energy(particle_energy)
        within = self.rays(e) if within is None else within
        return self.basin.area(self.basin.well.v0 + e, within=within)

    def ratio(self, t, within: float) -> np.ndarray:
        """A / t at scaled energies t = e^(1/n) (array), the rays ending at ``within``."""
        t = v.real_array("t", t)
        if not np.all((t > 0) & np.isfinite(t)):
            raise ParameterError("t", t.tolist(), "positive finite scaled energies e^(1/n)")
        energies = t**self.n
        areas = [self.basin.area(self.basin.well.v0 + e, within=within) for e in energies.ravel()]
        return np.array(areas).reshape(t.shape) / t
