"""Successive approximations of x'' + x^(2n-1) = 0 in powers of the triangle wave tau.

The paper (eqs. tau intro, X example, estimates) writes the T-periodic solution as

    x = U(tau) = A (tau - tau^(2n+1)/(2n+1) - R_2 - ...),   A0 = U(1),

with tau = tau(t/T) the triangle wave (:func:`triangle_wave`, re-exported from
:mod:`sinktheory.oscillator`).  This module builds the approximations to any order,
exactly (rational coefficients for an integer n, rational functions of n for a SymPy
symbol), checks the paper's bounds on R_i and compares with the exact solution.

The iteration
-------------
With t -> tau (x' = U' tau', x'' = U'' tau'^2, tau'^2 = (4/T)^2 a.e.), the equation
becomes U'' = -(T/4)^2 U^(2n-1) on [-1, 1]; periodicity needs U(0) = 0 and
U'(+-1) = 0.  Write U = A v with the slope v'(0) = 1 held fixed and
kappa = (T/4)^2 A^(2n-2), so v'' = -kappa v^(2n-1), v(0) = 0, v'(0) = 1, v'(1) = 0.
Embed it in the family (bookkeeping parameter eps, eps = 1 is the problem)

    v'' = -eps kappa(eps) v^(2n-1),   v(0) = 0,  v'(0) = 1,  v'(1) = 1 - eps,

and expand v = tau + sum_i eps^i v_i, kappa = sum_i eps^i kappa_i.  Order eps^i:

    v_i'' = -sum_{j<i} kappa_j [v^(2n-1)]_{i-1-j},  v_i(0) = v_i'(0) = 0,
    v_i'(1) = -1 (i = 1) or 0 (i > 1),

where [.]_m is the eps^m coefficient (J. C. P. Miller's recurrence for a power of a
series).  Integrating twice from tau = 0 gives v_i; the condition at tau = 1 fixes
kappa_{i-1}.  So every order keeps U'(0) = A, enforces U'(+-1) = 0 and yields the period
estimate T_i = 4 sqrt(kappa_0 + ... + kappa_{i-1}) / A^(n-1) with A = A0 / v(1).  Each
v_i = tau P_i(s), s = tau^(2n), with P_i a polynomial of degree i.  With R_i = -v_i:
R_1 = tau^(2n+1)/(2n+1), and R_2 is *exactly* the paper's
(1/2) (2n-1)/(2n+1) (tau^(2n+1)/(2n+1) - tau^(4n+1)/(4n+1)) (tested symbolically).
For n = 1 the family is solved by kappa(eps) = arccos(1 - eps)^2 / eps, whose branch
point at eps = 2 makes the series converge like 2^(-i): the paper's 2^(1-i).

The bounds (paper eq. estimates)
--------------------------------
0 < R_i < (2n-1) |tau|^(2n+1) / (2^(i-1) (2n+1)^2), checked by :func:`check_bounds`
(R_i / tau^(2n+1) is a polynomial in s = tau^(2n) of degree i-1; its extrema on [0, 1]
come from the roots of its derivative, the limit s -> 0 is compared in exact rationals).

* Where they hold: for n = 1 ... 200 (the brief asked n = 2 ... 20) and i = 2 ... 8 (asked
  2 ... 6), 0 < R_i(tau) < bound(tau) for every 0 < tau <= 1, and so
  0 < |R_i| < bound for 0 < |tau| <= 1 since R_i is odd.
* Where they do not: literally for tau < 0 (R_i < 0 there: read them as bounds on
  |R_i|); at tau = 0 (both sides vanish); for i = 1 (R_1 = tau^(2n+1)/(2n+1) exceeds
  the formula by the factor (2n+1)/(2n-1) -- the paper states it for the higher terms).
* How sharp: tight only as tau -> 0 for i = 2 (R_2 / bound -> 1) and as n -> oo; the
  sup of R_i / bound (always reached as tau -> 0) is 0.71 at n = 2, i = 3; 0.96 at
  n = 20, i = 3; 0.86 at n = 20, i = 8; 0.185 at n = 1, i = 6 (a factor 5.4 to spare).

Accuracy (``sinktheory series``, ``benchmarks/bench_series.py``)
----------------------------------------------------------------
Shape error max |U_i - x| / A0 over a period (U_i with A fixed by U_i(1) = A0, each
curve on its own period) and period error T_i / T_n - 1, orders i = 1 ... 6:

    n = 2    shape 2.7e-2 7.5e-3 2.5e-3 9.1e-4 3.5e-4 1.4e-4   period -14% ... -0.16%
    n = 10   shape 1.4e-2 4.6e-3 1.7e-3 6.7e-4 2.8e-4 1.2e-4   period -15% ... -0.44%
    n = 50   shape 3.6e-3 1.2e-3 4.8e-4 1.9e-4 8.2e-5 3.5e-5   period -14% ... -0.55%

The shape error falls by ~2.5-3 per order and improves with n (the "asymptotic of
large exponents"); the period estimate only halves its error per order and does *not*
improve with n (it always underestimates T_n).  The series is a cheap, smooth,
elementary approximation, not a precision tool: for accurate values use
:func:`sinktheory.oscillator.exact_solution`.  n = 1 works like any other n (the
series of sin(pi tau / 2) / (pi / 2) with the geometric rate above).

Examples
--------
>>> s = triangle_series(3, 2)
>>> s.remainder(2)
-5*tau**13/182 + 5*tau**7/98
>>> s.kappa
(Fraction(6, 1), Fraction(15, 7))
>>> round(float(s.shape(0.5)), 6)
0.597999
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

import mpmath
import numpy as np

from . import validation as v
from .errors import ParameterError
from .limits import MAX_ORDER
from .model import MAX_N
from .oscillator import exact_shape, period, triangle_wave, triangle_wave_derivative
from .results import Result

if TYPE_CHECKING:
    import sympy

__all__ = [
    "MAX_ORDER",
    "BoundCheck",
    "SeriesAccuracy",
    "SeriesError",
    "TriangleSeries",
    "accuracy",
    "bound",
    "check_bounds",
    "error_table",
    "triangle_series",
    "tau_symbol",  # noqa: F822 - provided by the module __getattr__ (SymPy on first use)
    "triangle_wave",
    "triangle_wave_derivative",
]


@functools.cache
def _tau():
    """The variable of the series' SymPy expressions (``tau_symbol``).  SymPy is imported
    only for the symbolic parts, so the numeric series and its refusals start fast."""
    import sympy

    return sympy.Symbol("tau", real=True)


def __getattr__(name: str):
    if name == "tau_symbol":  # the variable of the series' SymPy expressions
        return _tau()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


Poly = list  # coefficients c_m of sum_m c_m s^m, s = tau^(2n)


def _add(a: Poly, b: Poly) -> Poly:
    size = max(len(a), len(b))
    return [(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(size)]


def _mul(a: Poly, b: Poly) -> Poly:
    out = [0] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


@dataclass(frozen=True)
class TriangleSeries:
    """Successive approximations U_i(tau) = A (tau - R_1 - ... - R_i), i <= ``order``.

    Build with :func:`triangle_series`.  ``kappa[j]`` is kappa_j, ``corrections[i-1][m]``
    the coefficient of tau s^m (s = tau^(2n)) in v_i = -R_i.  Coefficients are
    :class:`fractions.Fraction` for an integer n, SymPy expressions for a symbolic n.
    """

    n: int | sympy.Symbol
    kappa: tuple
    corrections: tuple

    @property
    def order(self) -> int:
        return len(self.kappa)

    def _order(self, order: int | None) -> int:
        if order is None:
            return self.order
        return v.positive_int("order", order, maximum=self.order)

    def _sum(self, order: int | None) -> Poly:
        total: Poly = [1]
        for c in self.corrections[: self._order(order)]:
            total = _add(total, c)
        return total

    def remainder(self, i: int):
        """R_i(tau) as a SymPy expression (R_1 = tau^(2n+1)/(2n+1))."""
        c = self.corrections[v.positive_int("i", i, maximum=self.order) - 1]
        import sympy

        t, n = _tau(), self.n
        return -sum(sympy.sympify(cm) * t ** (2 * n * m + 1) for m, cm in enumerate(c))

    def shape_expr(self, order: int | None = None):
        """U_i / A = tau - R_1 - ... - R_i as a SymPy expression."""
        import sympy

        t, n = _tau(), self.n
        return sum(
            sympy.sympify(cm) * t ** (2 * n * m + 1) for m, cm in enumerate(self._sum(order))
        )

    def frequency_factor(self, order: int | None = None):
        """kappa_0 + ... + kappa_{i-1} = (T_i/4)^2 A^(2n-2), the order-i period factor."""
        return sum(self.kappa[: self._order(order)])

    def amplitude_ratio(self, order: int | None = None):
        """A0 / A = U_i(1) / A = 1 + sum_i P_i(1)."""
        return sum(self._sum(order))

    def shape(self, tau, order: int | None = None) -> np.ndarray:
        """U_i(tau) / A0 = v(tau) / v(1) in float64 (odd; 0 at tau = 0, 1 at tau = 1).

        Needs an integer n.  Powers |tau|^(2n m) only underflow to 0, never overflow.
        """
        if not isinstance(self.n, int):
            raise ParameterError("n", self.n, "an integer for numerical evaluation")
        tau = v.finite_array("tau", tau)
        if np.any(np.abs(tau) > 1):
            raise ParameterError(
                "tau", tau.tolist(), "phases in [-1, 1] (a quarter period each way)"
            )
        coeffs = [float(c) for c in self._sum(order)]
        with np.errstate(under="ignore"):
            s = np.abs(tau) ** (2 * self.n)
        return tau * np.polynomial.polynomial.polyval(s, coeffs) / sum(coeffs)

    def period_estimate(self, amplitude: object, order: int | None = None, *, dps: int = 30):
        """Order-i period T_i = 4 sqrt(frequency_factor) / A^(n-1), A = A0 / amplitude_ratio.

        Returned as an mpf with ``dps`` digits (no overflow for any n and A0 > 0).
        """
        v.positive("amplitude", amplitude)
        if not isinstance(self.n, int):
            raise ParameterError("n", self.n, "an integer for numerical evaluation")
        ratio, f = self.amplitude_ratio(order), self.frequency_factor(order)
        with mpmath.workdps(v.positive_int("dps", dps, maximum=10_000) + 10):
            a = mpmath.mpf(amplitude) * ratio.denominator / ratio.numerator  # A = A0 / U_i(1)
            t = 4 * mpmath.sqrt(mpmath.mpf(f.numerator) / f.denominator) / a ** (self.n - 1)
        with mpmath.workdps(dps):
            return +t


def triangle_series(n: int | sympy.Symbol, order: int) -> TriangleSeries:
    """Build the successive approximations up to ``order`` (see the module docstring).

    Parameters
    ----------
    n : int in [1, 1000], or a positive SymPy symbol
        Exponent of x^(2n-1).  An integer gives exact rationals; a symbol gives rational
        functions of n (slow beyond order 3).
    order : int in [1, MAX_ORDER]

    Returns
    -------
    TriangleSeries

    Examples
    --------
    >>> triangle_series(1, 3).kappa  # n = 1: arccos(1 - eps)^2 / eps = 2 + eps/3 + 4 eps^2/45
    (Fraction(2, 1), Fraction(1, 3), Fraction(4, 45))
    """
    order = v.positive_int("order", order, maximum=MAX_ORDER)
    sp = sys.modules.get("sympy")  # a SymPy symbol n means SymPy is loaded already
    if sp is not None and isinstance(n, sp.Symbol):
        one, simplify = sp.Integer(1), sp.factor
    else:
        n = v.positive_int("n", n, maximum=MAX_N)
        one, simplify = Fraction(1), lambda c: c
    p = 2 * n - 1

    def integrate_twice(g: Poly) -> Poly:
        # tau^(2n-1) s^m  ->  tau s^(m+1) / (2n(m+1) (2n(m+1) + 1))
        return [0] + [c * one / (2 * n * (m + 1) * (2 * n * (m + 1) + 1)) for m, c in enumerate(g)]

    def slope_at_one(g: Poly):
        # d/dtau of integrate_twice(g) at tau = 1: sum_m g_m / (2n (m+1))
        return sum((c * one / (2 * n * (m + 1)) for m, c in enumerate(g)), 0 * one)

    polys: list[Poly] = [[one]]  # P_0 = 1 (v_0 = tau)
    powers: list[Poly] = [[one]]  # [ (sum eps^j P_j)^(2n-1) ]_m, m = 0, 1, ...
    kappa: list = []
    for i in range(1, order + 1):
        known = sum((kappa[j] * slope_at_one(powers[i - 1 - j]) for j in range(i - 1)), 0 * one)
        kappa.append(simplify(2 * n * ((one if i == 1 else 0 * one) - known)))
        vi: Poly = [0 * one]
        for j in range(i):
            vi = _add(vi, [-kappa[j] * c for c in integrate_twice(powers[i - 1 - j])])
        polys.append([simplify(c) for c in vi])
        gi: Poly = [0 * one]
        for j in range(1, i + 1):  # Miller: g_i = (1/i) sum_j ((p+1) j - i) P_j g_{i-j}
            w = ((p + 1) * j - i) * one / i
            gi = _add(gi, [w * c for c in _mul(polys[j], powers[i - j])])
        powers.append([simplify(c) for c in gi])
    return TriangleSeries(n, tuple(kappa), tuple(tuple(c) for c in polys[1:]))


# --- the paper's bounds ---------------------------------------------------------------------
def _sequence(name: str, values) -> list:
    """``values`` as a non-empty list (ParameterError naming ``name`` otherwise)."""
    if isinstance(values, str | bytes) or not isinstance(values, Sequence | np.ndarray):
        raise ParameterError(name, values, "a non-empty list of integers")
    values = list(np.ravel(values)) if isinstance(values, np.ndarray) else list(values)
    if not values:
        raise ParameterError(name, "[]", "a non-empty list of integers")
    return values


def bound(tau, n: int, i: int) -> np.ndarray:
    """The paper's estimate (2n-1) |tau|^(2n+1) / (2^(i-1) (2n+1)^2) for |R_i|.

    Examples
    --------
    >>> float(bound(1.0, 1, 2))
    0.05555555555555555
    """
    n = v.positive_int("n", n, maximum=MAX_N)
    i = v.positive_int("i", i, maximum=MAX_ORDER)
    tau = v.finite_array("tau", tau, "values of the triangle wave, in [-1, 1]")
    if not np.all(np.abs(tau) <= 1):
        raise ParameterError("tau", f"values up to {np.abs(tau).max():g}", "values in [-1, 1]")
    with np.errstate(under="ignore"):
        return (2 * n - 1) * np.abs(tau) ** (2 * n + 1) / (2 ** (i - 1) * (2 * n + 1) ** 2)


@dataclass(frozen=True)
class BoundCheck(Result):
    """Outcome of the bound check for one (n, i) over 0 < tau <= 1.

    ``min_scaled`` = min R_i / tau^(2n+1) (positivity needs > 0); ``max_ratio`` =
    sup R_i / bound (the upper bound needs < 1, or = 1 only in the limit tau -> 0);
    ``holds`` is the verdict for every 0 < |tau| <= 1.
    """

    n: int
    i: int
    min_scaled: float
    max_ratio: float
    holds: bool


def check_bounds(n_values: Sequence[int], orders: Sequence[int]) -> list[BoundCheck]:
    """Check 0 < |R_i| < bound on 0 < |tau| <= 1 for each n and order i.

    The paper states the bound for the higher-order terms, i >= 2; at i = 1 it fails
    (R_1 = tau^(2n+1)/(2n+1) exceeds it by the factor (2n+1)/(2n-1)).

    R_i / tau^(2n+1) = Q(s) is a polynomial in s = tau^(2n) in (0, 1]; its extrema are at
    s = 0, s = 1 or a real root of Q' in (0, 1).  The limit s -> 0 is compared exactly
    (rational arithmetic), so the tight case R_2 / bound -> 1 is judged correctly.

    Examples
    --------
    >>> [(c.i, round(c.max_ratio, 4), c.holds) for c in check_bounds([2], [2, 3])]
    [(2, 1.0, True), (3, 0.7111, True)]
    """
    orders = [v.positive_int("orders", i, maximum=MAX_ORDER) for i in _sequence("orders", orders)]
    n_values = [
        v.positive_int("n_values", n, maximum=MAX_N) for n in _sequence("n_values", n_values)
    ]
    top = max(orders)
    out = []
    for n in n_values:
        series = triangle_series(n, top)
        for i in orders:
            q = [-c for c in series.corrections[i - 1][1:]]  # Q(s) coefficients, exact
            b = Fraction(2 * n - 1, 2 ** (i - 1) * (2 * n + 1) ** 2)
            qf = np.array([float(c) for c in q])
            crit = np.roots(np.polynomial.polynomial.polyder(qf)[::-1]) if len(q) > 1 else []
            s_pts = [1.0] + [r.real for r in crit if abs(r.imag) < 1e-12 and 0 < r.real < 1]
            inner = np.polynomial.polynomial.polyval(np.array(s_pts), qf)  # s in (0, 1]
            # at s -> 0 the exact limit q[0]; equality with b is allowed only as a limit,
            # with Q falling away from s = 0 (the case of R_2)
            below = q[0] < b or (q[0] == b and len(q) > 1 and q[1] < 0)
            holds = q[0] > 0 and bool(np.all(inner > 0)) and below and bool(np.all(inner < b))
            min_scaled = min(float(q[0]), float(inner.min()))
            max_ratio = max(float(q[0]), float(inner.max())) / float(b)
            out.append(BoundCheck(n, i, min_scaled, max_ratio, holds))
    return out


# --- accuracy against the exact solution ---------------------------------------------------
@dataclass(frozen=True)
class SeriesError(Result):
    """Accuracy of the order-i approximation for one n.

    ``shape_error`` = max over tau in [0, 1] of |U_i(tau) - x(tau)| / A0 (both curves with
    amplitude A0, each on its own period); ``period_estimate`` = T_i at A0 = 1;
    ``period_relative_error`` = T_i / T_n - 1 (independent of A0).
    """

    n: int
    order: int
    shape_error: float
    period_estimate: mpmath.mpf
    period_relative_error: float


def error_table(n: int, order: int, *, samples: int = 4001) -> list[SeriesError]:
    """Shape and period errors of the approximations of orders 1 ... ``order``.

    The exact reference is :func:`sinktheory.oscillator.exact_shape` (accurate to ~1e-15)
    on ``samples`` equally spaced tau in [0, 1] (odd symmetry covers [-1, 0]).

    Examples
    --------
    >>> rows = error_table(2, 3, samples=201)
    >>> [round(r.shape_error, 4) for r in rows]
    [0.0271, 0.0075, 0.0025]
    """
    n = v.positive_int("n", n, maximum=MAX_N)
    samples = v.positive_int("samples", samples, minimum=3, maximum=10**7)
    series = triangle_series(n, order)
    tau = np.linspace(0.0, 1.0, samples)
    exact = exact_shape(tau, n)
    t_exact = period(n, amplitude=1, dps=30)
    rows = []
    for i in range(1, series.order + 1):
        err = float(np.max(np.abs(series.shape(tau, i) - exact)))
        t_i = series.period_estimate(1, i, dps=30)
        rel = float(t_i / t_exact - 1)
        rows.append(SeriesError(n, i, err, t_i, rel))
    return rows


@dataclass(frozen=True)
class SeriesAccuracy(Result):
    """The errors of the orders 1 ... ``order`` for one n (:func:`error_table`) and the
    paper's bounds on R_i for i = 2 ... ``order`` (:func:`check_bounds`)."""

    n: int
    order: int
    errors: list[SeriesError]
    bounds: list[BoundCheck]


def accuracy(n: int, order: int, *, samples: int = 4001) -> SeriesAccuracy:
    """Shape and period errors of every order up to ``order`` and the bound checks.

    Examples
    --------
    >>> a = accuracy(2, 3, samples=201)
    >>> [e.order for e in a.errors], [b.i for b in a.bounds], a.as_dict()["bounds"][0]["holds"]
    ([1, 2, 3], [2, 3], True)
    """
    rows = error_table(n, order, samples=samples)
    n, order = rows[0].n, len(rows)
    bounds = check_bounds([n], range(2, order + 1)) if order >= 2 else []
    return SeriesAccuracy(n, order, rows, bounds)
