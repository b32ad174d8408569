"""Billiard tables: the rigid limit n -> oo of each registered well, and test tables.

As n -> oo the well V = gamma/(2n) sum ratio_i^(2n) becomes 0 where every wall ratio of
the shape (:func:`sinktheory.symbolic.wall_ratios`) is below 1 in modulus and infinite
outside: a billiard table.  Each ratio num/den gives the wall function
f_i = den^2 - num^2 (>= 0 inside, a polynomial in x, y for the registered shapes) that
the engine (:mod:`.kernels`) tracks, and the wall itself as a graph (x = +-W(y) or
y = +-W(x)), solved from |ratio| = 1 by SymPy; for the first ratio W is the shape's
declared ``rigid_wall``.  Each graph runs from its axis until it meets another wall (a
corner) or its mirror image (W = 0); a wall that meets neither encloses nothing and the
table is refused.  Area (Green's formula), perimeter and curvature come from the graphs
by quadrature of the lambdified SymPy expressions; nothing is retyped.

Test tables built from segments and arcs: :func:`sinai_table` (unit square with a
central disk) and :func:`stadium_table` (Bunimovich stadium).

Examples
--------
>>> t = rigid_table("flat", 0.5, 0.3)
>>> round(t.area, 12), round(4 * 0.5 - 8 * 0.3 / 3, 12)   # 4 int_0^1 D(y) dy
(1.2, 1.2)
>>> t.contains(0.0, 0.0), t.contains(0.3, 0.0)
(True, False)
>>> round(sinai_table(0.25).perimeter, 12) == round(4 + 2 * 3.141592653589793 * 0.25, 12)
True
"""

from __future__ import annotations

import functools
import math
import numbers
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from .. import symbolic as S
from ..errors import NumericalError, ParameterError, WellDefinitionError
from ..model import Well
from ..results import Result
from ..validation import choice, finite, finite_array, flag, positive, positive_int
from .impact import real_expression
from .kernels import CAPSULE, POLYNOMIAL

__all__ = [
    "EPS_UNITS",
    "Piece",
    "polynomial_table",
    "rigid_table",
    "SCAN_EXTENT",
    "sinai_table",
    "stadium_table",
    "Table",
    "well_table",
]

_s = sp.Symbol("s", real=True)
#: Rounding units of a wall function below which a particle counts as on the wall.
EPS_UNITS = 64
#: Largest extent scanned along a wall looking for its corner, in units of
#: max(alpha, |beta|, 1): a wall that meets no other by then leaves the table open.
SCAN_EXTENT = 50.0
#: Largest |alpha| and |beta| of a rigid table: the bounds of its wall functions'
#: derivatives over the table grow like powers of its size up to the 12th (symmetric
#: well), which overflow double precision from about 1e25 (the container's amplitude is
#: of order 1: no particle meets a wall of a table this large anyway).
MAX_SCALE = 1e20


@dataclass(frozen=True)
class Piece:
    """One boundary piece, a graph: ``axis`` "x" means x = sign W(s) with s = y, "y"
    means y = sign W(s) with s = x, for s in [lo, hi]; ``hole`` marks the boundary of an
    obstacle inside the table (traversed the other way, curvature sign flipped).  The
    fields are checked: ``expr`` a real SymPy expression in at most one symbol (the
    graph's variable), lo < hi finite.

    Examples
    --------
    >>> s = sp.Symbol("s")
    >>> Piece("x", 1, sp.sqrt(1 - s**2), -1, 1).points(3).round(12).tolist()
    [[0.0, -1.0], [1.0, 0.0], [0.0, 1.0]]
    >>> Piece("x", 1, sp.sqrt(1 - s**2), 1, -1)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: hi = -1 is not allowed: must be a finite number > lo = 1.0
    """

    axis: str
    sign: int
    expr: sp.Expr
    lo: float
    hi: float
    hole: bool = False

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        set_(self, "axis", choice("axis", self.axis, ("x", "y")))
        if (
            not isinstance(self.sign, numbers.Real)
            or isinstance(self.sign, bool | np.bool_)
            or self.sign not in (1, -1)
        ):
            raise ParameterError("sign", self.sign, "1 or -1")
        set_(self, "sign", int(self.sign))
        expr = real_expression("expr", self.expr)
        if len(expr.free_symbols) > 1:
            raise ParameterError("expr", str(expr), "an expression in one symbol (the graph's)")
        set_(self, "expr", expr)
        set_(self, "lo", finite("lo", self.lo))
        hi = finite("hi", self.hi)
        if not hi > self.lo:
            raise ParameterError("hi", self.hi, f"a finite number > lo = {self.lo!r}")
        set_(self, "hi", hi)
        set_(self, "hole", flag("hole", self.hole))

    @functools.cached_property
    def _funcs(self):
        d1 = sp.diff(self.expr, _s)
        return tuple(sp.lambdify(_s, e, "numpy") for e in (self.expr, d1, sp.diff(d1, _s)))

    def values(self, s) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(W, W', W'') at s in [lo, hi] (broadcast to arrays)."""
        s = finite_array("s", s)
        if np.any((s < self.lo) | (s > self.hi)):
            raise ParameterError("s", s.tolist(), f"numbers in [{self.lo:.9g}, {self.hi:.9g}]")
        with np.errstate(divide="ignore", invalid="ignore"):  # arcs are vertical at ends
            out = [np.asarray(f(s), dtype=float) for f in self._funcs]
        return tuple(np.broadcast_to(v, s.shape) for v in out)

    def points(self, count: int = 200) -> np.ndarray:
        """(count, 2) points along the piece."""
        s = np.linspace(self.lo, self.hi, positive_int("count", count, maximum=10**7))
        w = self.sign * self.values(s)[0]
        return np.column_stack((w, s) if self.axis == "x" else (s, w))

    def curvature(self, s) -> np.ndarray:
        """Curvature W'' / (1 + W'^2)^(3/2), > 0 where the wall disperses (bulges into the
        table), as :func:`sinktheory.symbolic.rigid_wall_curvature`."""
        _, d1, d2 = self.values(s)
        return (-1 if self.hole else 1) * d2 / (1 + d1**2) ** 1.5


def _quad(f, lo, hi) -> float:
    """The integral of ``f`` over [lo, hi] to about 1e-12.  QUADPACK's warning that
    rounding keeps it from that tolerance (a graph piece with an infinite slope at its
    end, as the ellipse's perimeter has) would reach the user's terminal: its error
    estimate is checked instead, and one above 1e-10 of the value is a NumericalError."""
    from scipy.integrate import quad

    value, err, *_ = quad(f, lo, hi, limit=200, epsabs=1e-13, epsrel=1e-12, full_output=1)
    if not err <= 1e-10 * max(abs(value), 1.0):
        raise NumericalError(f"the table's quadrature over [{lo:.6g}, {hi:.6g}]: error estimate "
                             f"{err:.2g} for the value {value:.6g}")  # fmt: skip
    return float(value)


def _poly_bound(c: np.ndarray, bx: float, by: float) -> float:
    """Sum |c_ab| bx^a by^b: a bound of |p(x, y)| over |x| <= bx, |y| <= by."""
    a, b = np.indices(c.shape)
    return float(np.sum(np.abs(c) * bx**a * by**b))


def _poly_lower(c: np.ndarray, bx: float, by: float) -> float:
    """A lower bound of p(x, y) over the box: its constant term minus the bound of the rest."""
    return float(c[0, 0]) - (_poly_bound(c, bx, by) - abs(float(c[0, 0])))


def _dx(c: np.ndarray) -> np.ndarray:
    out = np.zeros_like(c)
    out[:-1] = c[1:] * np.arange(1, c.shape[0])[:, None]
    return out


def _dy(c: np.ndarray) -> np.ndarray:
    return _dx(c.T).T


def poly_eval(c: np.ndarray, x, y) -> np.ndarray:
    """p(x, y) = sum c_ab x^a y^b (vectorised)."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    out = np.zeros(np.broadcast(x, y).shape)
    for a, b in zip(*np.nonzero(c), strict=True):
        out += c[a, b] * x**a * y**b
    return out


@dataclass(frozen=True)
class Table(Result):
    """A billiard table: wall functions for the engine and boundary pieces for geometry.

    Attributes
    ----------
    name : str
    parameters : dict of the numbers that define it
    pieces : the boundary as graphs (:class:`Piece`)
    kinds, coef, cap : the wall functions f_i >= 0 (inside) for :mod:`.kernels`
    area, perimeter : float
    box : (X, Y), half-widths of a box around the table
    hneg, gx, eps, reach : the engine's bounds (see :func:`_bounds`)
    """

    name: str
    parameters: dict
    pieces: tuple[Piece, ...] = field(repr=False)
    kinds: np.ndarray = field(repr=False)
    coef: np.ndarray = field(repr=False)
    cap: np.ndarray = field(repr=False)
    area: float = 0.0
    perimeter: float = 0.0
    box: tuple[float, float] = (0.0, 0.0)
    hneg: np.ndarray = field(default=None, repr=False)
    gx: np.ndarray = field(default=None, repr=False)
    eps: np.ndarray = field(default=None, repr=False)
    reach: float = 0.0

    @property
    def mean_free_path(self) -> float:
        """Santalo's formula pi A / P: the mean chord between collisions."""
        return math.pi * self.area / self.perimeter

    def curvature_range(self) -> tuple[float, float]:
        """Smallest and largest boundary curvature (> 0 dispersing, < 0 focusing)."""
        inner = 0.5 - 0.5 * np.cos(np.linspace(0.0, np.pi, 403)[1:-1])  # ends excluded
        ks = np.concatenate([p.curvature(p.lo + (p.hi - p.lo) * inner) for p in self.pieces])
        return float(np.nanmin(ks)), float(np.nanmax(ks))

    def wall_values(self, x, y) -> np.ndarray:
        """(walls, ...) values of the wall functions at points x, y (>= 0 inside)."""
        x, y = finite_array("x", x), finite_array("y", y)
        for name, z in (("x", x), ("y", y)):  # beyond, the wall polynomials overflow
            if np.abs(z).max(initial=0.0) > 1e100:
                raise ParameterError(name, f"{np.abs(z).max():g}", "coordinates within +-1e100")
        out = []
        for kind, c, cap in zip(self.kinds, self.coef, self.cap, strict=True):
            if kind == CAPSULE:
                d = np.maximum(np.abs(x) - cap[0], 0.0)
                out.append(cap[1] ** 2 - y**2 - d**2)
            else:
                out.append(poly_eval(c, x, y))
        return np.array(out)

    def contains(self, x: float, y: float) -> bool:
        """True if (x, y) lies strictly inside every wall."""
        x, y = finite("x", x), finite("y", y)
        return bool(np.all(self.wall_values(x, y) > 0))

    def check_positions(self, name: str, positions: np.ndarray) -> None:
        """Raise ParameterError naming ``name`` if a position (..., 2) is not inside."""
        p = finite_array(name, positions)
        if p.ndim < 1 or p.shape[-1] != 2:
            raise ParameterError(name, f"an array of shape {p.shape}", "positions (..., 2)")
        p = p.reshape(-1, 2)
        inside = np.all(self.wall_values(p[:, 0], p[:, 1]) > 0, axis=0)
        if not inside.all():
            x, y = p[np.argmin(inside)]
            raise ParameterError(
                name, f"a particle at ({x:.6g}, {y:.6g})", f"positions inside the {self.name} table"
            )

    def items(self) -> dict[str, Any]:
        kmin, kmax = self.curvature_range()
        return {
            "name": self.name,
            "parameters": self.parameters,
            "area": self.area,
            "perimeter": self.perimeter,
            "mean_free_path": self.mean_free_path,
            "curvature_min": kmin,
            "curvature_max": kmax,
            "walls": len(self.kinds),
            "box": self.box,
        }


def _bounds(kinds, coef, cap, bx: float, by: float):
    """Per wall over the box: hneg >= max(0, -lowest Hessian eigenvalue) (Gershgorin on
    bounds of the expanded polynomials), gx >= |f_x|, eps = rounding scale of f."""
    hneg, gx, eps = [], [], []
    for kind, c, cp in zip(kinds, coef, cap, strict=True):
        if kind == CAPSULE:
            hneg.append(2.0)
            gx.append(2.0 * bx)
            scale = cp[1] ** 2 + bx**2 + by**2
        else:
            cxx, cxy, cyy = _dx(_dx(c)), _dx(_dy(c)), _dy(_dy(c))
            off = _poly_bound(cxy, bx, by)
            low = min(_poly_lower(cxx, bx, by), _poly_lower(cyy, bx, by)) - off
            hneg.append(max(0.0, -low))
            gx.append(_poly_bound(_dx(c), bx, by))
            scale = _poly_bound(c, bx, by)
        eps.append(EPS_UNITS * np.finfo(float).eps * scale)
    return np.array(hneg), np.array(gx), np.array(eps)


def _assemble(name, parameters, pieces, kinds, coef, cap) -> Table:
    kinds = np.asarray(kinds, dtype=np.int64)
    deg = max(c.shape[0] for c in coef)
    padded = np.zeros((len(coef), deg, deg))
    for i, c in enumerate(coef):
        padded[i, : c.shape[0], : c.shape[1]] = c
    cap = np.asarray(cap, dtype=float).reshape(len(kinds), 2)
    pts = np.concatenate([p.points(801) for p in pieces])
    bx, by = (float(v) * 1.02 for v in np.abs(pts).max(axis=0))
    reach = 0.25 * max(bx, by)
    hneg, gx, eps = _bounds(kinds, padded, cap, bx + reach, by + reach)
    area = sum(
        (-1 if p.hole else 1)
        * _quad(lambda s, p=p: 0.5 * (p.values(s)[0] - s * p.values(s)[1]), p.lo, p.hi)
        for p in pieces
    )
    perimeter = sum(
        _quad(lambda s, p=p: math.hypot(1.0, p.values(s)[1]), p.lo, p.hi) for p in pieces
    )
    return Table(
        name, parameters, tuple(pieces), kinds, padded, cap, area, perimeter, (bx, by),
        hneg, gx, eps, reach,
    )  # fmt: skip


def _coefficients(f: sp.Expr) -> tuple[list[tuple[int, int]], list[sp.Expr]]:
    poly = sp.Poly(sp.expand(f), S.x, S.y)
    monoms, coeffs = zip(*poly.terms(), strict=True)
    return list(monoms), list(coeffs)


def _coef_array(monoms, values) -> np.ndarray:
    deg = max(max(m) for m in monoms) + 1
    c = np.zeros((deg, deg))
    for (a, b), v in zip(monoms, values, strict=True):
        c[a, b] = float(v)
    return c


@functools.cache
def _shape_walls(shape: str):
    """Per wall ratio of ``shape``: (monomials, lambdified coefficients in alpha, beta,
    axis, graph W(s) as SymPy in s, alpha, beta)."""
    definition = S.shape_definition(shape)
    walls = []
    sample = {S.alpha: sp.Rational(1, 2), S.beta: sp.Rational(1, 10)}
    for i, ratio in enumerate(definition.wall_ratios):
        num, den = sp.fraction(sp.together(ratio))
        f = sp.expand(den**2 - num**2)
        monoms, coeffs = _coefficients(f)
        lam = sp.lambdify((S.alpha, S.beta), coeffs, "math")
        options = []
        for var, other in ((S.x, S.y), (S.y, S.x)):
            if not f.has(var):
                continue
            for sol in sp.solve(sp.Eq(num**2, den**2), var):
                if sp.N(sol.subs(sample).subs(other, 0)).is_positive:
                    options.append((sp.count_ops(sol), var.name, sol.subs(other, _s)))
        _, axis, graph = min(options, key=lambda o: o[0])
        if i == 0:  # the shape's declared rigid wall x = D(y): check it and use it
            declared = definition.rigid_wall.subs(S.y, _s)
            if axis != "x" or sp.simplify(graph - declared) != 0:
                raise AssertionError(f"{shape}: rigid_wall is not the wall of {ratio}")
            graph = declared
        walls.append((monoms, lam, axis, graph))
    return tuple(walls), definition.denominators


def _first_failure(ok, hi: float) -> float | None:
    """Smallest s in (0, hi] where ok(s) turns False (grid, then bisection); None if never."""
    grid = np.linspace(0.0, hi, 20001)
    good = ok(grid)
    if good.all():
        return None
    j = int(np.argmin(good))
    lo, up = grid[j - 1], grid[j]
    for _ in range(200):
        mid = 0.5 * (lo + up)
        if mid in (lo, up):
            break
        if ok(np.array([mid]))[0]:
            lo = mid
        else:
            up = mid
    return float(lo)


def rigid_table(shape: str, alpha: float, beta: float) -> Table:
    """The rigid (n -> oo) table of a registered well shape (module docstring).

    Parameters are validated as for :class:`sinktheory.model.Well` (n plays no part);
    a table whose walls do not close around the centre, or whose wall denominators vanish
    inside it, is refused with a :class:`~sinktheory.errors.ParameterError` naming beta.

    Examples
    --------
    >>> t = rigid_table("circular", 0.5, 0.3)
    >>> round(t.area / (3.141592653589793 * 0.2**2), 9), t.curvature_range()[1] < 0
    (1.0, True)
    >>> rigid_table("symmetric", 2.0, 1.0)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: beta = 1.0 is not allowed: must be a value for which ...
    """
    well = Well(alpha, beta, 1, shape=shape)
    alpha, beta = well.alpha, well.beta
    name, value = ("beta", beta) if abs(beta) > alpha else ("alpha", alpha)
    if abs(value) > MAX_SCALE:
        raise ParameterError(
            name, value, f"at most {MAX_SCALE:g} in magnitude for a rigid table",
            why="the bounds of the wall functions over a larger table overflow double "
            "precision",
        )  # fmt: skip
    walls, denominators = _shape_walls(shape)
    at = {S.alpha: alpha, S.beta: beta}
    coefs = [_coef_array(m, lam(alpha, beta)) for m, lam, _, _ in walls]
    graphs = [(axis, graph.subs(at)) for _, _, axis, graph in walls]
    allowed = f"a value for which the rigid walls of the {shape} well close around the centre"

    def refuse(why: str) -> None:
        raise ParameterError("beta", beta, allowed, why=why)

    extent = SCAN_EXTENT * max(alpha, abs(beta), 1.0)
    dens = [d.subs(at) for d in denominators]
    return _walled_table(shape, {"alpha": alpha, "beta": beta}, graphs, coefs, dens, extent,
                         refuse)  # fmt: skip


def _walled_table(name, parameters, graphs, coefs, denominators, extent, refuse) -> Table:
    """The table bounded by the walls f_i = coefs[i] >= 0, each drawn as the graph
    (axis, W(s)) of ``graphs`` from its axis to where it meets another wall, checked to
    close with every denominator (SymPy in x, y) > 0 on it; ``refuse(why)`` raises."""
    pieces = []
    for i, (axis, graph) in enumerate(graphs):
        W = sp.lambdify(_s, graph, "numpy")

        def point(s, W=W, axis=axis):
            with np.errstate(invalid="ignore"):
                w = np.broadcast_to(np.asarray(W(s), dtype=float), np.shape(s))
            return (w, s) if axis == "x" else (s, w)

        def ok(s, i=i, point=point, axis=axis):
            px, py = point(s)
            good = np.isfinite(px) & np.isfinite(py) & ((px if axis == "x" else py) > 0)
            for j, c in enumerate(coefs):
                if j != i:
                    with np.errstate(invalid="ignore"):
                        good &= poly_eval(c, np.nan_to_num(px), np.nan_to_num(py)) >= 0
            return good

        end = _first_failure(ok, extent)
        if end is None:
            refuse(f"the wall {axis} = {graph} meets no other wall")
        pieces += [Piece(axis, sign, graph, -end, end) for sign in (1, -1)]
    table = _assemble(
        name, parameters, pieces, [POLYNOMIAL] * len(coefs), coefs, np.zeros((len(coefs), 2))
    )
    _check_closed(table, refuse)
    dens = [sp.lambdify((S.x, S.y), d, "numpy") for d in denominators]
    pts = np.concatenate([p.points(801) for p in pieces])
    for d in dens:
        if not np.all(np.asarray(d(pts[:, 0], pts[:, 1])) > 0):
            refuse("a wall denominator D vanishes on the rigid table")
    return table


def well_table(well, **given: float) -> Table:
    """The rigid table of a user's well (:class:`sinktheory.userwell.UserWell`) at its
    parameter values (defaults unless ``given``): the region where every wall ratio is
    below 1 in size, each ratio num/den giving the wall function den^2 - num^2, which must
    be a polynomial in x, y at those values, and its graph solved by SymPy as for the
    registered shapes.  A well without wall ratios, a wall that is not polynomial, or
    walls that do not close around the centre are refused
    (:class:`~sinktheory.errors.WellDefinitionError`).

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> ellipse = UserWell("ellipse", "((x/a)**2 + (y/b)**2)**4", {"a": 0.3, "b": 0.2},
    ...                    wall_ratios=["sqrt((x/a)**2 + (y/b)**2)"])
    >>> round(well_table(ellipse).area / (math.pi * 0.3 * 0.2), 12)
    1.0
    """
    from ..userwell import UserWell

    if not isinstance(well, UserWell):
        raise ParameterError("well", well, "a sinktheory.userwell.UserWell")
    values = well.values(**given)
    where = f"well {well.name}: wall_ratios"
    if not well.wall_ratios:
        raise WellDefinitionError(where, "[]", "a rigid table needs the wall ratios")

    def refuse(why: str) -> None:
        raise WellDefinitionError(where, values_text, f"the rigid walls do not close ({why})")

    values_text = ", ".join(f"{k} = {v}" for k, v in values.items()) or "no parameters"
    graphs, coefs, dens = [], [], []
    for i, ratio in enumerate(well.wall_ratios):
        num, den = sp.fraction(sp.together(ratio.subs(values)))
        f = sp.expand(den**2 - num**2)
        try:
            monoms, coeffs = _coefficients(f)
        except sp.PolynomialError:
            raise WellDefinitionError(
                f"{where}[{i}]", str(ratio), "its wall den^2 - num^2 is not a polynomial in x, y"
            ) from None
        coefs.append(_coef_array(monoms, coeffs))
        options = []
        for var, other in ((S.x, S.y), (S.y, S.x)):
            if f.has(var):
                for sol in sp.solve(sp.Eq(num**2, den**2), var):
                    at_axis = sp.N(sol.subs(other, 0))
                    if at_axis.is_real and at_axis.is_positive:
                        options.append((sp.count_ops(sol), var.name, sol.subs(other, _s)))
        if not options:
            raise WellDefinitionError(
                f"{where}[{i}]", str(ratio), "its level 1 crosses no axis on the positive side"
            )
        _, axis, graph = min(options, key=lambda o: o[0])
        graphs.append((axis, graph))
        if den.free_symbols:
            dens.append(den)
    # the walls' distances from the centre on their axes set the scale scanned for corners
    crossings = [abs(float(graph.subs(_s, 0))) for _, graph in graphs]
    extent = SCAN_EXTENT * max(1.0, *crossings)
    parameters = {k.name: float(v) for k, v in values.items()}
    return _walled_table(well.name, parameters, graphs, coefs, dens, extent, refuse)


def _check_closed(table: Table, refuse) -> None:
    """Every piece's end must meet another piece's end: the boundary closes."""
    ends = []
    for p in table.pieces:
        pts = p.points(2)
        ends += [pts[0], pts[-1]]
    ends = np.array(ends)
    tol = 1e-7 * max(table.box)
    for i, e in enumerate(ends):
        d = np.hypot(*(ends - e).T)
        d[i] = np.inf
        d[i ^ 1] = np.inf  # the other end of the same piece
        if d.min() > tol:
            refuse(f"the boundary is open at {e.round(6)}")


def sinai_table(radius: float) -> Table:
    """The Sinai billiard: the unit square |x|, |y| <= 1/2 with a disk of ``radius`` at
    its centre (0 < radius < 1/2).

    Examples
    --------
    >>> t = sinai_table(0.1)
    >>> round(t.area, 12) == round(1 - 3.141592653589793 * 0.01, 12), t.contains(0, 0)
    (True, False)
    """
    r = positive("radius", radius)
    if r >= 0.5:
        raise ParameterError("radius", radius, "a number in (0, 0.5)")
    h = sp.Rational(1, 2)
    disk = sp.sqrt((r - _s) * (r + _s))
    pieces = [Piece(a, sg, h + 0 * _s, -0.5, 0.5) for a in "xy" for sg in (1, -1)]
    pieces += [Piece("x", sg, disk, -r, r, hole=True) for sg in (1, -1)]
    walls = [h**2 - S.x**2, h**2 - S.y**2, S.x**2 + S.y**2 - r**2]
    return polynomial_table("sinai", walls, pieces, {"radius": r})


def polynomial_table(
    name: str, walls, pieces, parameters: dict | None = None, *, symbol: sp.Symbol = _s
) -> Table:
    """A table from wall functions and boundary pieces given by the caller.

    Parameters
    ----------
    walls : SymPy polynomials in :data:`sinktheory.symbolic.x`, ``y``, >= 0 inside, each
        vanishing on its part of the boundary (e.g. 1/4 - x**2 for the walls x = +-1/2)
    pieces : the boundary as :class:`Piece` graphs in ``symbol`` (for area, perimeter,
        curvature and drawing); they must close
    parameters : recorded with the table

    Examples
    --------
    >>> s = sp.Symbol("s")
    >>> sq = [Piece(a, g, sp.Integer(1) + 0 * s, -1, 1) for a in "xy" for g in (1, -1)]
    >>> t = polynomial_table("square", [1 - S.x**2, 1 - S.y**2], sq, symbol=s)
    >>> round(t.area, 12), round(t.perimeter, 12)
    (4.0, 8.0)
    """
    if not isinstance(name, str):
        raise ParameterError("name", name, "a string (the table's name)")
    if not isinstance(symbol, sp.Symbol):
        raise ParameterError("symbol", symbol, "a SymPy Symbol (the pieces' variable)")
    if parameters is not None and not isinstance(parameters, dict):
        raise ParameterError("parameters", parameters, "a dict or None")
    pieces = _sequence("pieces", pieces, "a non-empty sequence of Piece")
    if not all(isinstance(p, Piece) for p in pieces):
        raise ParameterError("pieces", [type(p).__name__ for p in pieces],
                             "a non-empty sequence of Piece")  # fmt: skip
    pieces = [Piece(p.axis, p.sign, p.expr.subs(symbol, _s), p.lo, p.hi, p.hole) for p in pieces]
    strays = set().union(*(p.expr.free_symbols for p in pieces)) - {_s}
    if strays:
        raise ParameterError(
            "symbol", symbol, f"the pieces' variable (they use {sorted(map(str, strays))})"
        )
    walls = _sequence("walls", walls, "a non-empty sequence of polynomials in x, y")
    coefs = []
    for f in walls:
        f = real_expression("walls", f, (S.x, S.y))
        try:
            coefs.append(_coef_array(*_coefficients(f)))
        except sp.PolynomialError:
            raise ParameterError("walls", str(f), "polynomials in x, y") from None
    table = _assemble(
        name, parameters or {}, pieces, [POLYNOMIAL] * len(coefs), coefs,
        np.zeros((len(coefs), 2)),
    )  # fmt: skip

    def refuse(why: str) -> None:
        raise ParameterError("pieces", f"{len(pieces)} pieces", "a closed boundary", why=why)

    _check_closed(table, refuse)
    _check_on_walls(table)
    return table


def _sequence(name: str, value: object, allowed: str) -> list:
    """``value`` as a non-empty list (a string, a mapping or a SymPy object is not one)."""
    if isinstance(value, str | dict | sp.Basic) or not hasattr(value, "__iter__"):
        raise ParameterError(name, value, allowed)
    items = list(value)
    if not items:
        raise ParameterError(name, items, allowed)
    return items


def _check_on_walls(table: Table) -> None:
    """The pieces must lie where the wall functions say the boundary is: at each point of
    a piece every wall function >= 0 and one of them 0, to 1e-9 of its size over the box
    (the graphs are the walls' zero sets, so rounding alone separates them)."""
    pts = np.concatenate([p.points(101) for p in table.pieces])
    values = table.wall_values(pts[:, 0], pts[:, 1])  # (walls, points)
    bx, by = table.box
    scale = np.array([_poly_bound(c, bx, by) for c in table.coef])[:, None]
    tol = 1e-9 * np.maximum(scale, np.finfo(float).tiny)
    on = np.any(np.abs(values) <= tol, axis=0) & np.all(values >= -tol, axis=0)
    if not on.all():
        x, y = pts[np.argmin(on)]
        raise ParameterError(
            "walls", f"{len(table.kinds)} wall function(s)",
            "functions >= 0 inside the table that vanish on its boundary pieces",
            why=f"none vanishes at the piece's point ({x:.6g}, {y:.6g})",
        )  # fmt: skip


def stadium_table(half_length: float, radius: float) -> Table:
    """The Bunimovich stadium: the points within ``radius`` of the segment
    |x| <= ``half_length``, y = 0 (two segments of length 2 a and two half circles).

    Examples
    --------
    >>> t = stadium_table(1.0, 1.0)
    >>> round(t.area, 10) == round(4 + 3.141592653589793, 10)
    True
    """
    a = positive("half_length", half_length)
    r = positive("radius", radius)
    for name, value in (("half_length", a), ("radius", r)):
        if value > MAX_SCALE:  # the box and the engine's bounds overflow beyond
            raise ParameterError(name, value, f"a number in (0, {MAX_SCALE:g}]")
    cap_ = a + sp.sqrt((r - _s) * (r + _s))
    pieces = [Piece("y", sg, r + 0 * _s, -a, a) for sg in (1, -1)]
    pieces += [Piece("x", sg, cap_, -r, r) for sg in (1, -1)]
    return _assemble(
        "stadium", {"half_length": a, "radius": r}, pieces, [CAPSULE], [np.zeros((1, 1))],
        [[a, r]],
    )  # fmt: skip
