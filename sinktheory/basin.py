"""The basin of a well around its minimum, found numerically: escape energy, reach, area.

For a well V(x, y) with its minimum at the centre, the *basin* at energy e is the
connected component of {V <= e} that holds the centre.  It is bounded up to the *escape
energy* e*, the lowest energy at which it reaches infinity (over a saddle, as for the
Henon-Heiles well) or a point where V is singular or undefined (a pole of V, as the
symmetric shape's D(x) = 0 for beta < 0): a particle below e* stays in a bounded,
regular region, and energies at or above e* are refused.  This module finds e* with a
certificate, and the basin's reach (bounds of |x|, |y|) and area A(e) below it, for any
V given as a SymPy expression (:class:`NumericWell`).

Escape energy (:func:`escape`)
------------------------------
On a square grid |x|, |y| <= R of (2 :data:`GRID` + 1)^2 nodes (the axes and diagonals
on it exactly), the nodes where V is finite and every guard holds (denominators of the
centre's sign, log arguments > 0, bases of non-integer powers >= 0) are *valid*; a valid
node on the box's edge or next to an invalid node is an *exit*.  The discrete escape
energy is the smallest node value e_hi at which the centre's 8-connected component of
{valid, V <= e} contains an exit; the next lower node value e_lo is the last at which it
does not.  That bracket, found by bisection over the sorted node values
(:func:`scipy.ndimage.label` at each step), is the certificate.  Where the component
first meets an exit decides what limits the basin:

* a node inside the box (not an exit): a **saddle**; Newton's method on grad V = 0 from
  that node must converge within two grid cells to a point where the Hessian has one
  negative eigenvalue, and its V is e* (to rounding);
* an exit next to an invalid node: a **singular** point; the grid is zoomed around the
  lowest such exit by 8 each time (33 x 33 nodes) until the cell is at rounding, and V
  at the last lowest exit is e* (the limit of V at the singular set from inside);
* the box's edge: the basin grows beyond the box, and the search is repeated with R
  doubled, from :data:`FIRST_BOX` x ``radius`` up to :data:`FAR_RADIUS`; there e* is
  reported as the lowest V on that box's edge (kind **box**: the basin is certified
  bounded only below it; +inf where V overflows there).

A basin whose bracket already opens at V(0, 0) is open at every energy: the well does
not confine (:class:`~sinktheory.errors.WellDefinitionError`).

The grid sees only its nodes: a pass narrower than a cell, or a saddle closer to the
centre than FIRST_BOX x ``radius`` / GRID, can be missed.

Reach (:func:`reach`) and area (:func:`star_area`)
--------------------------------------------------
The reach at energy e < e* is found on the smallest box (R doubled from a small one)
whose grid component of {V <= e} stays off the box's edge.  From the extreme nodes in
each direction (+-x, +-y) the bound is refined: the largest u (the coordinate) at which
the lowest V over the other coordinate, within four cells of those nodes, is <= e,
stepping out a cell at a time (a spike thinner than a cell) and then by bisection in u
to rounding; the lowest V by a scan and Brent's bounded method, which also handles the
flat-topped edges of the wall powers 2n >= 4.  When no such bracket is found, the last
step plus one cell is returned (``refined`` False: an estimate, not a proven bound).
The area is the ray quadrature A = 1/2 \\int r*(theta)^2 d theta over the first crossing
r*(theta) of V = e along each ray (bisection to rounding, a scan that checks the basin is
star-shaped from the centre), the trapezoid rule with the rays doubled until two sums
agree to :data:`AREA_RTOL`; :mod:`sinktheory.equilibrium.area` uses the same quadrature.

Small energies (:func:`leading_order`)
--------------------------------------
Near the centre V - V(0, 0) = lambda^d c(x, y) + o(lambda^d) on the points (lambda x,
lambda y), lambda -> 0, where d and the homogeneous form c are found symbolically (the
leading term in lambda, :meth:`sympy.Expr.as_leading_term`).  When c > 0 in every
direction the basin at small e is the region c < e scaled by e^(1/d), so
A(e) = A_c e^(2/d) (1 + o(1)): the exponent 2/d is what the equilibrium law needs.  A form
that vanishes along a direction (x^2 + y^4: leading x^2) has a basin that is not such a
scaling, and is refused.

Examples
--------
>>> from sinktheory.userwell import UserWell
>>> hh = NumericWell(UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {}).potential)
>>> e = escape(hh)
>>> e.kind, round(e.escape_potential * 6, 15), [round(c, 15) for c in e.point]  # 3 saddles at 1/6
('saddle', 1.0, [-0.866025403784439, -0.5])
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp
from scipy import ndimage, optimize

from .errors import NumericalError, ParameterError, WellDefinitionError
from .glossary import old_attribute, renamed
from .symbolic import AtomForm, gradient_in_ratios, hessian_in_ratios, lift_powers, x, y

__all__ = [
    "AREA_RTOL",
    "Basin",
    "Escape",
    "escape",
    "FAR_RADIUS",
    "FIRST_BOX",
    "FORM_DIRECTIONS",
    "GRID",
    "guards",
    "leading_order",
    "LeadingOrder",
    "MAX_RAYS",
    "RADIUS_RANGE",
    "NumericWell",
    "Reach",
    "SCAN_POINTS",
]

#: Nodes per half side of the search grid (a grid of (2 GRID + 1)^2 nodes).
GRID = 64
#: The first search box, in units of the ``radius`` of the well's neighbourhood.
FIRST_BOX = 2.0**-6
#: The largest search box |x|, |y| <= FAR_RADIUS.
FAR_RADIUS = 2.0**20
#: Zoom nodes per half side around a singular exit, and the zoom factor.
_ZOOM_NODES, _ZOOM = 16, 8
#: Relative agreement of two successive trapezoid sums (rays doubled) ending the area
#: quadrature; the error of the last sum is far below it (geometric convergence).
AREA_RTOL = 1e-13
#: Most rays over the integration range before the quadrature gives up.
MAX_RAYS = 2**16
#: Points of the scan along each ray that brackets the edge and checks V grows.
SCAN_POINTS = 48
_EIGHT = np.ones((3, 3), dtype=bool)
#: Points of the scan across an extreme of the reach, and most cells it steps outwards.
_SCAN, _REACH_STEPS = 65, 16
#: Most pass nodes of one grid from which Newton's method looks for the saddle.
_NEWTON_TRIES = 64


@dataclass(frozen=True)
class LeadingOrder:
    """V - V(0, 0) = lambda^degree form(x, y) + o(lambda^degree) on (lambda x, lambda y),
    with ``form`` > 0 in every direction (:func:`leading_order`)."""

    degree: sp.Rational
    form: sp.Expr

    @property
    def n(self) -> int | float:
        """Half the degree: the wall exponent n of a well homogeneous of degree 2n (1 for a
        positive definite Hessian at the centre), an int when whole."""
        half = self.degree / 2
        return int(half) if half.is_integer else float(half)

    @property
    def area_exponent(self) -> sp.Rational:
        """2 / degree: A(e) ~ e^(2/degree) as e -> 0."""
        return 2 / self.degree

    def describe(self) -> str:
        """One line: the leading term and what it gives."""
        return (
            f"V - V(0, 0) = lambda^{self.degree} ({self.form}) + o(lambda^{self.degree}) at "
            f"(lambda x, lambda y), the form > 0 in every direction: "
            f"A(e) ~ e^({self.area_exponent})"
        )


#: Directions on which the leading form must be positive (:func:`leading_order`).
FORM_DIRECTIONS = 256
#: The range of ``radius`` of :func:`escape` (that of :func:`sinktheory.userwell.check_well`,
#: which calls it): below, V on the first box underflows to V(0, 0) and the search doubles
#: its box hundreds of times (at 1e-300 every V was 0 on the checks' rings and the search
#: took 4-23 s); at 1e-140 the finest ring's (radius 2^-20) square stays a normal float.
RADIUS_RANGE = (1e-140, 1e300)


def _check_expression(V, values, name) -> dict:
    """``values`` as a dict after checking the arguments of :class:`NumericWell` and
    :func:`leading_order`: V a SymPy expression in x, y and the symbols of ``values``
    (None or a mapping of SymPy symbols to finite real numbers), ``name`` a string."""
    if not isinstance(name, str):
        raise ParameterError("name", name, "a string naming the well in messages")
    if values is not None and not isinstance(values, Mapping):
        raise ParameterError("values", values, "None or a mapping of SymPy symbols to numbers")
    values = dict(values or {})
    for key, value in values.items():
        try:
            number = float(value)
        except (TypeError, ValueError):
            number = math.nan
        if not isinstance(key, sp.Symbol) or not math.isfinite(number) or isinstance(value, bool):
            raise ParameterError(
                "values", f"{key} = {value}", "a mapping of SymPy symbols to finite real numbers"
            )
    if not isinstance(V, sp.Expr):
        raise ParameterError("V", V, "a SymPy expression in x, y (sinktheory.symbolic's)")
    unknown = V.free_symbols - {x, y} - set(values)
    if unknown:
        raise ParameterError(
            "V", str(V)[:40], f"an expression in x, y and the symbols of values, not "
            f"{', '.join(sorted(map(str, unknown)))}",
        )  # fmt: skip
    return values


def leading_order(V: sp.Expr, values: Mapping[sp.Symbol, sp.Expr] | None = None,
                  name: str = "V") -> LeadingOrder:  # fmt: skip
    """The leading term of V - V(0, 0) at the centre (module docstring), at ``values``.

    Raises
    ------
    WellDefinitionError
        SymPy cannot find the leading term, its degree is not a positive number, or the
        form is not positive in every direction (exactly for a polynomial form, else on
        :data:`FORM_DIRECTIONS` directions): A(e) is then not a power of e at small e.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> hh = UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})
    >>> order = leading_order(hh.potential)
    >>> order.degree, order.form, order.area_exponent
    (2, x**2/2 + y**2/2, 1)
    >>> leading_order(UserWell("q", "x**2 + y**4", {}).potential)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.WellDefinitionError: well V: 'x**2' is refused: the leading term ...
    """
    values = _check_expression(V, values, name)
    lam = sp.Dummy("lambda", positive=True)
    V = V.subs(values)
    where = f"well {name}"
    scaled = V.subs({x: lam * x, y: lam * y}, simultaneous=True) - V.subs({x: 0, y: 0})
    try:
        lead = scaled.as_leading_term(lam)
        # lambda L'/L constant: L = form lambda^degree (Euler), form = L at lambda = 1
        degree = sp.nsimplify(sp.simplify(lam * sp.diff(lead, lam) / lead))
        form = sp.simplify(lead.subs(lam, 1))
    except (NotImplementedError, ValueError, TypeError, ZeroDivisionError) as exc:
        raise WellDefinitionError(
            where, str(V)[:40], f"the leading term of V at the centre is not found ({exc})"
        ) from None
    if not (degree.is_Rational and degree > 0) or form.free_symbols - {x, y}:
        raise WellDefinitionError(
            where, str(lead.subs(lam, sp.Symbol("lambda"))), "the leading term of V at the "
            "centre is not a positive power of lambda times a form in x, y",
        )  # fmt: skip
    zero = _vanishing_direction(form)
    if zero is not None:
        raise WellDefinitionError(
            where, str(form), f"the leading term of V - V(0, 0) at the centre, of degree "
            f"{degree}, is not positive along the direction {zero}: the basin at small "
            "energy is not a scaled copy of one region, and A(e) not a power of e",
        )  # fmt: skip
    return LeadingOrder(degree, form)


def _sum_of_even_powers(form: sp.Expr) -> bool:
    """True when the polynomial ``form`` is a sum of terms c x^(2i) y^(2j), every c > 0,
    among them a power of x alone and one of y alone: then form >= c1 x^(2i) + c2 y^(2j)
    > 0 away from the origin, which decides at once what the real roots of a form of
    high degree (the flat well at n = 100: degree 200, minutes) would."""
    terms = sp.Poly(form, x, y).terms()
    return (
        all(c > 0 and i % 2 == 0 and j % 2 == 0 for (i, j), c in terms)
        and any(j == 0 for (_, j), _c in terms)
        and any(i == 0 for (i, _), _c in terms)
    )


def _vanishing_direction(form: sp.Expr) -> str | None:
    """A direction (x, y) where ``form`` is not > 0, as text, or None: exactly for a
    polynomial (a real root of form(t, 1), or form(1, 0) <= 0), else on
    :data:`FORM_DIRECTIONS` directions with the axes and diagonals exact."""
    if form.is_polynomial(x, y):
        if _sum_of_even_powers(form):
            return None
        t = sp.Dummy("t", real=True)
        if not form.subs({x: 1, y: 0}) > 0:
            return "(1, 0)"
        on_line = sp.Poly(sp.expand(form.subs({x: t, y: 1})), t)
        if on_line.is_zero:
            return "(t, 1)"
        roots = sp.real_roots(on_line)
        if roots:
            return f"({roots[0]}, 1)"
        if not form.subs({x: 0, y: 1}) > 0:
            return "(0, 1)"
        return None
    k = np.arange(FORM_DIRECTIONS)
    theta = 2 * np.pi * k / FORM_DIRECTIONS
    cos, sin = np.cos(theta), np.sin(theta)
    quarter = FORM_DIRECTIONS // 4
    cos[k % (2 * quarter) == quarter] = 0.0  # the y axis
    sin[k % (2 * quarter) == 0] = 0.0  # the x axis
    diagonal = k % quarter == quarter // 2
    cos[diagonal] = np.sign(cos[diagonal]) * np.sqrt(0.5)
    sin[diagonal] = np.sign(sin[diagonal]) * np.sqrt(0.5)
    bad = ~(numeric(form)(cos, sin) > 0)
    if bad.any():
        i = int(np.argmax(bad))
        return f"({cos[i]:.6g}, {sin[i]:.6g})"
    return None


def numeric(expr: sp.Expr, values: Mapping[sp.Symbol, sp.Expr] | None = None):
    """A NumPy function of real (x, y) arrays in float64, the parameters passed as
    ``values`` at call time so that a power is computed as written ((x/D)^(2n), not
    x^(2n) / D^(2n), whose parts overflow).  The expression must be one built by
    :mod:`sinktheory.userwell` or :mod:`sinktheory.symbolic`, so printing it runs nothing
    of a user's.  A value that is complex or undefined comes out NaN; one beyond float64
    range comes out +-inf."""
    values = dict(values or {})
    # the parameters renamed: one named like a name of the printed code (abs, numpy)
    # would shadow it in the generated function
    names = {s: sp.Symbol(f"par{i}_", real=True) for i, s in enumerate(values)}
    f = sp.lambdify((x, y, *names.values()), expr.xreplace(names), modules="numpy")
    args = [float(v) for v in values.values()]

    def call(xs, ys):
        xs = np.asarray(xs, dtype=float)
        ys = np.asarray(ys, dtype=float)
        with np.errstate(all="ignore"):
            value = np.asarray(f(xs, ys, *args), dtype=float)
        return np.broadcast_to(value, np.broadcast(xs, ys).shape)

    return call


def guards(expr: sp.Expr) -> list[tuple[sp.Expr, str]]:
    """Subexpressions of ``expr`` that must keep a sign: denominators, log arguments,
    bases of non-integer powers (each with the rule, as words)."""
    out = []
    for node in sp.preorder_traversal(expr):
        if isinstance(node, sp.Pow) and node.base.free_symbols:
            e = node.exp
            if not (e.is_Number and e.is_integer):
                out.append((node.base, "the base of a non-integer power, >= 0"))
            elif e.is_Number and e < 0:
                out.append((node.base, "a denominator, non-zero and of one sign"))
        elif isinstance(node, sp.log) and node.args[0].free_symbols:
            out.append((node.args[0], "the argument of log, > 0"))
    return out


class NumericWell:
    """V(x, y), its gradient and Hessian, and its guards as NumPy functions, at fixed
    parameter ``values``; ``name`` names it in messages.

    A denominator guard must keep the sign it has at the centre; the basin ends where a
    guard fails (or V is NaN or -inf): a singular point.
    """

    def __init__(self, V: sp.Expr, values: Mapping[sp.Symbol, sp.Expr] | None = None,
                 name: str = "V"):  # fmt: skip
        self.values = _check_expression(V, values, name)
        self.name = name
        self.expr = V
        self.f = numeric(V, self.values)
        # derivatives at the values by the chain rule through the bases of the powers
        # (symbolic.lift_powers): numbers of order one, finite where a base vanishes
        # (SymPy's own d((y/b)^2) is 2 (y/b)^2 / y, NaN at y = 0)
        atoms, lifted = lift_powers(V.subs(self.values))
        form = AtomForm(name, atoms, lifted, (), ())
        # |x|'' = 2 DiracDelta(x): zero away from the kink, where Newton's method works
        derivatives = [
            d.replace(sp.DiracDelta, lambda *a: sp.S.Zero)
            for d in (*gradient_in_ratios(form), *hessian_in_ratios(form))
        ]
        names = (x, y, *(a for a, _ in atoms))
        steps = [sp.lambdify(names[: 2 + i], d, "math") for i, (_, d) in enumerate(atoms)]
        outputs = sp.lambdify(names, derivatives, "math")

        def derivative_values(px: float, py: float) -> list[float]:
            args = [float(px), float(py)]
            try:
                for step in steps:
                    args.append(float(step(*args)))
                return [float(v) for v in outputs(*args)]
            except (ArithmeticError, ValueError):  # a pole or a root of a negative number
                return [math.nan] * 5

        self._derivatives = derivative_values
        self.guards = []
        # the exponents' values decide which powers need a guard ((x/D)^(2n) none)
        for guard, rule in guards(V.subs(self.values)):
            g = numeric(guard)
            sign = float(np.sign(g(0.0, 0.0)))
            self.guards.append((g, rule, sign))
        self.v0 = float(self.f(0.0, 0.0))
        if not math.isfinite(self.v0):
            raise WellDefinitionError(
                f"well {name}", f"V(0, 0) = {self.v0}", "V must be real and finite at the centre"
            )
        # the sum of |terms| of V: its rounding error is a few ulps of it (so a well
        # scaled by 1e-300 is not taken for one flat to rounding)
        self.magnitude = numeric(sum(abs(t) for t in sp.Add.make_args(V)), self.values)

    def _gradient(self, px: float, py: float) -> np.ndarray:
        return np.array(self._derivatives(px, py)[:2])

    def _hessian(self, px: float, py: float) -> np.ndarray:
        hxx, hxy, hyy = self._derivatives(px, py)[2:]
        return np.array([[hxx, hxy], [hxy, hyy]])

    def _valid(self, xs, ys, values=None) -> np.ndarray:
        """True where V is not NaN or -inf (+inf is float64 overflow: large, not singular)
        and every guard holds."""
        v = self.f(xs, ys) if values is None else values
        ok = ~np.isnan(v) & (v != -np.inf)
        for g, rule, sign in self.guards:
            gv = g(xs, ys)
            if "log" in rule:
                ok &= gv > 0
            elif "non-integer" in rule:
                ok &= gv >= 0
            else:
                ok &= np.sign(gv) == sign
        return ok


@renamed(energy="escape_potential")
@dataclass(frozen=True)
class Escape:
    """What limits the basin (module docstring).

    Attributes
    ----------
    escape_potential : float
        e*, the absolute V at the escape point: below it the basin is bounded and regular
        (+inf: bounded as far as float64 reaches on the largest box);
        :attr:`Basin.escape_energy` is it measured from V(0, 0).
    kind : str
        "saddle", "singular" or "box".
    point : (x, y)
        The saddle, the singular point approached, or the lowest node of the box's edge.
    bracket : (e_lo, e_hi)
        The grid's certificate: the centre's component of {V <= e_lo} meets no exit, that
        of {V <= e_hi} does.
    box, spacing : float
        The grid's half side R and its cell R / GRID.
    """

    escape_potential: float
    kind: str
    point: tuple[float, float]
    bracket: tuple[float, float]
    box: float
    spacing: float

    energy = old_attribute("escape_potential")

    def describe(self, v0: float = 0.0) -> str:
        """One line: what e* is and how it was found, the escape energy measured from
        ``v0`` = V(0, 0) (said when it is not 0; the grid bracket is of V itself)."""
        if isinstance(v0, bool) or not isinstance(v0, numbers.Real) or not math.isfinite(v0):
            raise ParameterError("v0", v0, "a finite real number (V(0, 0))")
        at = f"({self.point[0]:.6g}, {self.point[1]:.6g})"
        what = {
            "saddle": f"the saddle at {at} (Newton's method from the grid's pass)",
            "singular": f"a singular point of V at {at}, approached from inside",
            "box": f"the lowest V on the edge of the search box |x|, |y| <= {self.box:g}, "
            "beyond which the basin is not followed",
        }[self.kind]
        lo, hi = self.bracket
        return (
            f"escape energy {self.escape_potential - v0:.15g}"
            f"{'' if v0 == 0 else f' above V(0, 0) = {v0:.9g}'}: {what}; grid bracket "
            f"[{lo:.9g}, {hi:.9g}] with cell {self.spacing:.3g}"
        )


def _grid(R: float, m: int = GRID, centre=(0.0, 0.0)) -> tuple[np.ndarray, np.ndarray]:
    k = np.arange(-m, m + 1) / m
    return np.meshgrid(centre[0] + R * k, centre[1] + R * k, indexing="ij")


def _exits(valid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(edge, singular): valid nodes on the box's edge, valid nodes next to an invalid one."""
    edge = np.zeros_like(valid)
    edge[0, :] = edge[-1, :] = edge[:, 0] = edge[:, -1] = True
    near_invalid = ndimage.binary_dilation(~valid, structure=_EIGHT)
    return edge & valid, near_invalid & valid


def _component(inside: np.ndarray, m: int) -> np.ndarray:
    labels, _ = ndimage.label(inside, structure=_EIGHT)
    return labels == labels[m, m] if inside[m, m] else np.zeros_like(inside)


def _newton(func, jac, p, limit: float) -> np.ndarray | None:
    """Newton's method from p; None unless it converges (step at rounding) within
    ``limit`` (max norm) of p."""
    start = np.array(p, dtype=float)
    q = start.copy()
    for _ in range(60):
        try:
            step = np.linalg.solve(jac(*q), func(*q))
        except np.linalg.LinAlgError:
            return None
        if not np.all(np.isfinite(step)):
            return None
        q = q - step
        if np.max(np.abs(q - start)) > limit:
            return None
        if np.max(np.abs(step)) <= 4 * np.finfo(float).eps * max(1.0, np.max(np.abs(q))):
            return q
    return None


def _bottleneck(values, valid, exits, m):
    """(e_lo, e_hi, component at e_hi): the grid's bracket (module docstring); None if
    no exit is reached at all."""
    levels = np.unique(values[valid])
    levels = levels[levels >= values[m, m]]

    def reaches(e):
        comp = _component(valid & (values <= e), m)
        return comp, bool((comp & exits).any())

    comp, hit = reaches(levels[-1])
    if not hit:
        return None
    lo, hi = -1, len(levels) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        c, h = reaches(levels[mid])
        if h:
            hi, comp = mid, c
        else:
            lo = mid
    e_lo = levels[lo] if lo >= 0 else values[m, m]
    return float(e_lo), float(levels[hi]), comp


def _zoom_singular(well: NumericWell, p: tuple[float, float], h: float) -> tuple[float, tuple]:
    """Lowest V at valid nodes next to invalid ones, zoomed around p down to rounding."""
    best_v, best = float(well.f(*p)), p
    width = 2 * h
    scale = max(abs(p[0]), abs(p[1]), h)
    while width > 8 * np.finfo(float).eps * scale:
        X, Y = _grid(width, _ZOOM_NODES, best)
        values = well.f(X, Y)
        valid = well._valid(X, Y, values)
        near = ndimage.binary_dilation(~valid, structure=_EIGHT) & valid
        if not near.any():
            break
        i = np.unravel_index(np.argmin(np.where(near, values, np.inf)), values.shape)
        best_v, best = float(values[i]), (float(X[i]), float(Y[i]))
        width /= _ZOOM
    return best_v, best


def escape(well: NumericWell, radius: float = 1.0) -> Escape:
    """The escape energy e* of ``well``'s basin around the centre, with its certificate
    (module docstring); ``radius`` sets the first box (FIRST_BOX x radius).

    Raises
    ------
    WellDefinitionError
        The basin is open at every energy above V(0, 0): the well does not confine.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> e = escape(NumericWell(UserWell("q", "x**2 + y**2 - x**4", {}).potential))
    >>> # the saddles at x^2 = 1/2, V = 1/4
    >>> e.kind, round(e.escape_potential, 15), round(abs(e.point[0]) - 0.5**0.5, 15)
    ('saddle', 0.25, 0.0)
    """
    if not isinstance(well, NumericWell):
        raise ParameterError("well", well, "a sinktheory.basin.NumericWell")
    lo, hi = RADIUS_RANGE
    try:
        ok = lo <= radius <= hi and not isinstance(radius, bool)
    except TypeError:
        ok = False
    if not ok:
        raise ParameterError("radius", radius, f"a number in [{lo:g}, {hi:g}]")
    R = FIRST_BOX * float(radius)
    m = GRID
    while True:
        X, Y = _grid(R)
        h = R / m
        values = well.f(X, Y)
        valid = well._valid(X, Y, values)
        edge, singular = _exits(valid)
        found = _bottleneck(values, valid, edge | singular, m)
        if found is None:  # only if the centre itself is invalid, which the checks refuse
            raise NumericalError(
                f"basin of {well.name}: no exit found on the box |x|, |y| <= {R:g}"
            )
        e_lo, e_hi, comp = found
        passes = comp & (values == e_hi)
        # V(pass) equals V(0, 0) to rounding: to a few ulps of the terms there
        scale = np.broadcast_to(well.magnitude(X, Y), values.shape)[passes]
        scale = np.max(scale[np.isfinite(scale)], initial=abs(well.v0))  # inf: V is not v0
        slack = 64 * np.finfo(float).eps * scale
        if e_hi <= well.v0 + slack:
            i = np.unravel_index(np.argmax(comp & (edge | singular)), values.shape)
            if edge[i] and 2 * R <= FAR_RADIUS:  # V flat to rounding near the centre
                R *= 2
                continue
            where = f"({X[i]:.6g}, {Y[i]:.6g})"
            raise WellDefinitionError(
                f"well {well.name}", f"V(0, 0) = {well.v0:.6g}",
                f"not confining: at every energy above V(0, 0) the basin reaches {where} "
                + ("on the edge of the box " + f"|x|, |y| <= {R:g}" if edge[i] else
                   "where V is singular or undefined"),
            )  # fmt: skip
        # a pass inside the box is a saddle, refined by Newton's method (V may be level
        # along a whole line through it, as Henon-Heiles' V = 1/6 on y = -1/2: the
        # nodes inside the box are tried before the exits)
        inner = passes & ~(edge | singular)
        for i in list(zip(*np.nonzero(inner), strict=True))[:_NEWTON_TRIES]:
            q = _newton(well._gradient, well._hessian, (X[i], Y[i]), 2 * h)
            if q is not None and np.linalg.slogdet(well._hessian(*q))[0] < 0:  # no underflow
                point = (float(q[0]) + 0.0, float(q[1]) + 0.0)
                return Escape(float(well.f(*q)), "saddle", point, (e_lo, e_hi), R, h)
        on_singular = passes & singular
        on_edge = passes & edge & ~singular
        if on_singular.any():
            i = np.unravel_index(np.argmax(on_singular), values.shape)
            energy, point = _zoom_singular(well, (float(X[i]), float(Y[i])), h)
            return Escape(energy, "singular", point, (e_lo, e_hi), R, h)
        if on_edge.any():
            if 2 * R <= FAR_RADIUS:
                R *= 2
                continue
            i = np.unravel_index(np.argmax(on_edge), values.shape)
            return Escape(e_hi, "box", (float(X[i]), float(Y[i])), (e_lo, e_hi), R, h)
        i = next(zip(*np.nonzero(passes), strict=True))
        raise NumericalError(
            f"basin of {well.name}: the grid's pass at ({X[i]:.6g}, {Y[i]:.6g}) (V between "
            f"{e_lo:.9g} and {e_hi:.9g}) is not refined to a saddle by Newton's method "
            "(a degenerate or non-smooth pass)"
        )


@renamed(energy="particle_energy")
@dataclass(frozen=True)
class Reach:
    """Bounds of |x| and |y| over the basin at ``particle_energy``; ``refined`` says
    whether each is Newton's extreme point (True) or the grid's node plus one cell (False)."""

    particle_energy: float
    x_max: float
    y_max: float
    refined: tuple[bool, bool]
    spacing: float

    energy = old_attribute("particle_energy")


def _extreme(well: NumericWell, e: float, X, Y, comp, axis: int, h: float):
    """Largest |coordinate ``axis``| over the component (module docstring): from each
    side's extreme nodes, the largest u (that coordinate, times the side) at which the
    lowest V over the other coordinate near those nodes is <= e, by bisection in u; the
    lowest V by a scan of :data:`_SCAN` points and Brent's bounded method around the best
    (a degenerate, flat-topped edge and a spike thinner than a cell included)."""
    coord, other = (X, Y)[axis], (X, Y)[1 - axis]
    best, refined = 0.0, True
    for side in (1.0, -1.0):
        node = float(np.max(np.where(comp, side * coord, -np.inf)))
        ties = other[comp & (side * coord == node)]
        lo_o, hi_o = float(ties.min()) - 4 * h, float(ties.max()) + 4 * h
        scan = np.linspace(lo_o, hi_o, _SCAN)
        step = scan[1] - scan[0]

        def lowest(u, side=side, scan=scan, step=step):
            def v(o):
                p = (side * u, o) if axis == 0 else (o, side * u)
                return well.f(*p)

            values = v(scan)
            j = int(np.argmin(values))
            found = optimize.minimize_scalar(
                lambda o: float(v(o)), method="bounded", options={"xatol": 1e-12 * h},
                bounds=(scan[j] - step, scan[j] + step),
            )  # fmt: skip
            return min(float(found.fun), float(values[j]))

        lo, hi = node, node + h
        ok = lowest(lo) <= e
        for _ in range(_REACH_STEPS):  # a spike between the nodes reaches further out
            if not ok or lowest(hi) > e:
                break
            lo, hi = hi, hi + h
        ok = ok and lowest(hi) > e
        if ok:
            while True:
                mid = 0.5 * (lo + hi)
                if mid <= lo or mid >= hi:
                    break
                if lowest(mid) <= e:
                    lo = mid
                else:
                    hi = mid
        value = hi if ok else hi + h
        if value > best:
            best, refined = float(value), ok
    return best, refined


@renamed(energy="particle_energy")
def reach(well: NumericWell, particle_energy: float, limit: Escape) -> Reach:
    """Bounds of |x|, |y| over the basin at ``particle_energy`` (below
    ``limit.escape_potential``, V at the escape point), refined by Newton's method (module
    docstring)."""
    e = float(particle_energy)
    if not (e > well.v0 and e < limit.escape_potential):
        raise WellDefinitionError(
            f"well {well.name}: particle_energy", e,
            f"must be above V(0, 0) = {well.v0:.9g} and below the escape energy "
            f"{limit.escape_potential:.9g} ({limit.kind})",
        )  # fmt: skip
    R, m = limit.box * 2.0**-40, GRID
    while R <= 2 * limit.box:
        X, Y = _grid(R)
        values = well.f(X, Y)
        comp = _component(well._valid(X, Y, values) & (values <= e), m)
        edge, singular = _exits(well._valid(X, Y, values))
        if (comp & singular).any():
            raise NumericalError(
                f"basin of {well.name}: at energy {e:.9g} the grid's basin meets a singular "
                f"point on the box |x|, |y| <= {R:g} (too close to the escape energy)"
            )
        if not (comp & edge).any():
            break
        R *= 2
    else:
        raise NumericalError(f"basin of {well.name}: the basin at {e:.9g} is not enclosed")
    h = R / m
    (xr, xok), (yr, yok) = (_extreme(well, e, X, Y, comp, a, h) for a in (0, 1))
    return Reach(e, xr, yr, (xok, yok), h)


def star_area(potential: Callable, e: float, r_max: float, what: str, *,
              quarter: bool = False) -> float:  # fmt: skip
    """Area of the basin {V < e} by the ray quadrature (module docstring).

    ``potential(x, y)`` takes arrays; every ray must reach V >= e before ``r_max``.
    ``quarter``: the basin is symmetric under x -> -x and y -> -y and the rays cover a
    quarter turn (A = 2 \\int_0^(pi/2) r*^2 d theta); otherwise a full turn
    (A = 1/2 \\int_0^(2 pi) r*^2 d theta, the periodic trapezoid rule).  ``what`` names
    the basin in messages.

    Examples
    --------
    >>> round(star_area(lambda x, y: x**2 + 4 * y**2, 1.0, 2.0, "an ellipse") / math.pi, 12)
    0.5
    """

    def edge(theta: np.ndarray) -> np.ndarray:
        cos, sin = np.cos(theta), np.sin(theta)
        scan = np.linspace(0.0, r_max, SCAN_POINTS)[:, None]
        values = potential(scan * cos, scan * sin)
        above = values >= e
        if not np.all(above.any(axis=0)):
            bad = float(theta[~above.any(axis=0)][0])
            raise NumericalError(f"area: V < e = {e:.6g} up to the reach along theta = {bad:.6g}")
        first = above.argmax(axis=0)
        inside = np.arange(SCAN_POINTS)[:, None] < first
        falls = (np.diff(values, axis=0) <= 0) & inside[1:]
        if falls.any():
            bad = float(theta[falls.any(axis=0)][0])
            raise NumericalError(
                f"area: the basin of e = {e:.6g} is not star-shaped from the centre "
                f"(V falls along theta = {bad:.6g})"
            )
        lo, hi = scan[first - 1, 0], scan[first, 0]
        while True:
            mid = 0.5 * (lo + hi)
            done = (mid <= lo) | (mid >= hi)
            if done.all():
                return hi
            out = potential(mid * cos, mid * sin) >= e
            hi = np.where(out & ~done, mid, hi)
            lo = np.where(~out & ~done, mid, lo)

    rays = 16
    if quarter:
        r2 = edge(np.linspace(0.0, math.pi / 2, rays + 1)) ** 2
        total = 2 * (math.pi / 2 / rays) * (r2.sum() - 0.5 * (r2[0] + r2[-1]))
        span, factor = math.pi / 2, 2.0
    else:
        r2 = edge(np.linspace(0.0, 2 * math.pi, rays + 1)[:-1]) ** 2
        total = 0.5 * (2 * math.pi / rays) * r2.sum()
        span, factor = 2 * math.pi, 0.5
    while rays < MAX_RAYS:
        rays *= 2
        mid = edge(np.linspace(0.0, span, rays + 1)[1::2]) ** 2
        new = 0.5 * total + factor * (span / rays) * mid.sum()
        if abs(new - total) <= AREA_RTOL * new:
            return float(new)
        total = new
    raise NumericalError(
        f"area: the quadrature of the {what} basin at e = {e:.6g} did not converge to "
        f"{AREA_RTOL:g} with {MAX_RAYS} rays per {'quarter' if quarter else 'full'} turn"
    )


@dataclass(frozen=True)
class Basin:
    """A well's basin at fixed parameter values: its escape energy (with certificate),
    and the reach and area below it.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> well = UserWell("ellipse", "(x/a)**2 + (y/b)**2", {"a": 0.3, "b": 0.2})
    >>> basin = Basin.of(well.potential, well.values(), well.name)
    >>> round(basin.area(1.0) / (math.pi * 0.3 * 0.2), 12), basin.escape.kind
    (1.0, 'box')
    >>> r = basin.reach(1.0)
    >>> round(float(r.x_max), 15), round(float(r.y_max), 15), r.refined
    (0.3, 0.2, (True, True))
    """

    well: NumericWell
    escape: Escape

    @classmethod
    def of(cls, V: sp.Expr, values: Mapping[sp.Symbol, sp.Expr] | None = None,
           name: str = "V", radius: float = 1.0) -> Basin:  # fmt: skip
        """Search the basin of V at ``values`` (:func:`escape`)."""
        if not isinstance(V, sp.Expr):
            raise ParameterError("V", type(V).__name__, "a SymPy expression in x and y")
        if values is not None and not isinstance(values, Mapping):
            raise ParameterError("values", values, "a mapping of parameter symbols to values")
        if not 0 < cls._number("radius", radius) < math.inf:
            raise ParameterError("radius", radius, "a finite radius > 0")
        well = NumericWell(V, values, name)
        return cls(well, escape(well, radius))

    @renamed(energy="particle_energy")
    def reach(self, particle_energy: float) -> Reach:
        """Bounds of |x|, |y| over the basin at ``particle_energy`` (:func:`reach`)."""
        return reach(self.well, self._number("particle_energy", particle_energy), self.escape)

    @staticmethod
    def _number(name: str, value: object) -> float:
        """``value`` as a float if it is a real number (not a bool, not NaN), else a
        ParameterError naming ``name`` (the model layer's validators sit above this one)."""
        if isinstance(value, bool | np.bool_) or not isinstance(value, int | float | np.number):
            raise ParameterError(name, value, "a real number")
        if isinstance(value, complex | np.complexfloating) or math.isnan(value):
            raise ParameterError(name, value, "a real number")
        return float(value)

    @property
    def escape_energy(self) -> float:
        """The escape energy measured from V(0, 0) (inf: bounded as far as float64 reaches)."""
        return self.escape.escape_potential - self.well.v0

    @renamed(energy="particle_energy")
    def check_energy(self, particle_energy: float, *, name: str = "particle_energy") -> float:
        """``particle_energy``, measured from V(0, 0), if it lies in (0,
        :attr:`escape_energy`); else a ParameterError naming ``name``."""
        try:
            e = float(particle_energy)
        except (TypeError, ValueError):
            e = math.nan
        if not (e > 0 and e < self.escape_energy) or isinstance(particle_energy, bool):
            raise ParameterError(
                name, particle_energy, f"in (0, {self.escape_energy:.9g}): above V(0, 0) and "
                f"below the escape energy of the {self.well.name} well (measured from V(0, 0))",
                why=self.escape.describe(self.well.v0),
            )  # fmt: skip
        return e

    @renamed(energy="particle_energy")
    def area(self, particle_energy: float, *, within: float | None = None) -> float:
        """A(e), the area of the basin at ``particle_energy`` (:func:`star_area`, a full
        turn).

        ``within``: the rays end at that radius instead of past this energy's reach (for
        many energies below one whose reach has been found once: the basins nest)."""
        e = particle_energy
        if within is None:
            r = self.reach(e)
            within, e = 1.000001 * math.hypot(r.x_max, r.y_max), r.particle_energy
        else:
            e = self._number("particle_energy", e)
            if not 0 < self._number("within", within) < math.inf:
                raise ParameterError("within", within, "a radius > 0")
        return star_area(self.well.f, e, within, f"{self.well.name}")
