"""The power-law oscillator x'' + x^(2n-1) = 0: exact period and exact periodic solution.

This is the rescaled motion of a particle along the normal mode y = 0 (paper eq.
x-oscill with mu -> 0), in the paper's dimensionless units.  Energy
E_n = x'^2/2 + x^(2n)/(2n), amplitude A0 = (2 n E_n)^(1/(2n)).

Period
------
:func:`period` evaluates paper eq. (T) through the generated kernel ``period_mp`` at
any precision (guard digits inside :func:`mpmath.workdps`, result rounded to the
caller's ``dps``).  ``amplitude`` and ``energy`` are interchangeable; exactly one is
given.  For n > 1 the period diverges as A0 -> 0 (T ~ A0^(1-n)): a zero amplitude or
energy is refused with :class:`~sinktheory.errors.ParameterError`, and every positive
input gets its finite period (mpmath's exponent range is unbounded, so no overflow).

Exact periodic solution
-----------------------
On the first quarter period, starting at x = 0 with x' > 0, energy conservation gives
(z = x / A0, w = z^(2n), a = 1/(2n))::

    t(x) = sqrt(n) / A0^(n-1) * F(z),   F(z) = int_0^z dz / sqrt(1 - z^(2n))
         = (1 / (2n)) B(w; a, 1/2) = z 2F1(a, 1/2; 1 + a; w),

so the quarter period is T/4 = sqrt(n) K / A0^(n-1) with K = F(1), and the fraction
q = 4 t / T of the quarter period already elapsed is the regularised incomplete Beta
function q = I_w(a, 1/2).  Hence, with the paper's triangle wave tau (eq. tau intro,
:func:`triangle_wave`), the solution is *exactly*

    x(t) = A0 sign(tau) Z(|tau|),   Z(q) = I^{-1}(q; a, 1/2)^(1/(2n)),   tau = tau(t / T),

the triangle-wave substitution t -> tau being exact; only Z has to be computed.  Near
the turning point (w > 1/2) the complementary form is used instead: with u = 1 - w,
1 - q = I_u(1/2, a) = (2 / B(a, 1/2)) sqrt(u) 2F1(1/2, 1 - a; 3/2; u), and
z = (1 - u)^(1/(2n)); each branch then inverts a function whose derivative stays
bounded, so neither loses digits.

Phase convention: ``start="turning"`` (the default) gives x(0) = A0, x'(0) = 0 (the
initial condition of a Floquet computation); ``start="zero"`` gives x(0) = 0,
x'(0) > 0, which is the paper's tau(t/T) with tau(0) = 0.  They differ by T/4.

Two evaluators:

* :func:`exact_solution_mp` / :func:`exact_shape_mp` -- any precision: bracketing root
  search (:func:`mpmath.findroot`, Anderson) on the branch above, hypergeometric series
  for F (convergent fast since the argument is <= 1/2).
* :func:`exact_solution` / :func:`exact_shape` -- vectorised float64: scipy's
  ``betaincinv`` for a start, one Newton step with the forward ``betainc`` to polish it;
  for z^(2n) below 1e-17 the first-order form z = q K is already exact to double
  precision (this also avoids the underflow of w = z^(2n) for large n).  Measured
  against the mp path (``tests/oscillator/test_oscillator.py``, ``benchmarks/bench_series.py``):
  max |error| / A0 <= 8e-16 for n = 1 ... 1000 over the whole period (tested < 2e-15),
  including points within 1e-15 of the turning point and of x = 0.  Times are reduced
  to the phase t / T first, so a large |t| costs |t| eps / T in phase.  The float path
  needs the period itself in float64 range: when A0^(n-1) overflows or underflows
  (e.g. n = 200, A0 = 0.01), it raises :class:`PeriodOutOfRangeError`; use the mp path
  there (or rescale: x(t; A0) = A0 x(A0^(n-1) t; 1)).

Examples
--------
>>> mpmath.nstr(period(1, amplitude=3, dps=20), 20)
'6.2831853071795864769'
>>> mpmath.nstr(period(7, amplitude=1, dps=25), 25)
'11.59606471874714411038947'
>>> bool(period(2, energy="0.25", dps=25) == period(2, amplitude=1, dps=25))  # E = 1/(2n)
True
>>> [round(float(v), 12) for v in exact_solution([0.0, 1.0], 2, 1.5)]
[1.5, 0.375405388891]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import numpy as np

from . import validation as v
from .errors import BracketError, ParameterError, PeriodOutOfRangeError
from .limits import MAX_DPS
from .model import MAX_N
from .results import Result

__all__ = [
    "exact_shape",
    "exact_shape_mp",
    "exact_solution",
    "exact_solution_mp",
    "GUARD_DIGITS",
    "MAX_DPS",
    "Oscillator",
    "oscillator",
    "period",
    "significant",
    "STARTS",
    "triangle_wave",
    "triangle_wave_derivative",
]


def _generated():
    """The generated kernels (they import numba: loaded on first use, so the light commands
    and refusals stay fast)."""
    from ._generated import oscillator

    return oscillator


#: Extra decimal digits carried internally by the mp paths.
GUARD_DIGITS = 10
#: Phase conventions of the exact solution (see the module docstring).
STARTS = ("turning", "zero")
_PHASE_SHIFT = {"turning": 0.25, "zero": 0.0}
#: Below this value of z^(2n), F(z) = z to double precision (relative error < 1e-17).
_LINEAR_W = 1e-17


@dataclass(frozen=True)
class Oscillator(Result):
    """One orbit of x'' + x^(2n-1) = 0: amplitude, energy and exact period (mpf values).

    Build it with :func:`oscillator`; all three numbers carry ``dps`` significant digits.
    ``as_dict()`` (:mod:`sinktheory.results`) writes them as decimal strings of exactly
    ``dps`` significant digits (trailing zeros kept), which ``mpmath.mpf`` reads back.

    Examples
    --------
    >>> oscillator(1, amplitude=2, dps=12).as_dict()
    {'n': 1, 'amplitude': '2.00000000000', 'energy': '2.00000000000', \
'period': '6.28318530718', 'dps': 12}
    """

    n: int
    amplitude: mpmath.mpf
    energy: mpmath.mpf
    period: mpmath.mpf
    dps: int

    def items(self) -> dict:
        out = super().items()
        for name in ("amplitude", "energy", "period"):
            out[name] = significant(out[name], self.dps)
        return out


def significant(x: mpmath.mpf, digits: int) -> str:
    """``x`` as a decimal string of exactly ``digits`` significant digits (trailing zeros
    kept, no bare trailing point), fixed-point from 1e-4 up to 10**digits, else scientific.

    Examples
    --------
    >>> significant(mpmath.mpf(2), 3), significant(mpmath.mpf(2), 1)
    ('2.00', '2')
    >>> significant(mpmath.mpf(123456), 2), significant(mpmath.mpf("0.000012345"), 3)
    ('1.2e+5', '1.23e-5')
    """
    if not isinstance(x, mpmath.mpf) or not mpmath.isfinite(x):
        raise ParameterError("x", x, "a finite mpmath.mpf")
    digits = _check_dps(digits, "digits")
    text = mpmath.nstr(x, digits, strip_zeros=False, min_fixed=-4, max_fixed=digits)
    mantissa, e, exponent = text.partition("e")
    return mantissa.rstrip(".") + e + exponent


def _check_n(n: object) -> int:
    return v.positive_int("n", n, maximum=MAX_N)


def _check_dps(dps: object, name: str = "dps") -> int:
    return v.positive_int(
        name,
        dps,
        minimum=1,
        maximum=MAX_DPS,
        why=lambda d: f"mpmath's Gamma function would take minutes at {d} digits",
    )


def _check_start(start: str) -> str:
    return v.choice("start", start, STARTS)


def oscillator(
    n: int, amplitude: object = None, energy: object = None, *, dps: int = 30
) -> Oscillator:
    """The orbit of given amplitude *or* energy, with its exact period (paper eq. T).

    Parameters
    ----------
    n : int in [1, 1000]
        Exponent of the restoring force x^(2n-1).
    amplitude, energy : number or decimal string, > 0
        Exactly one of them.  Strings are read as exact decimals at the working
        precision (``"0.1"`` means 1/10, not the nearest binary double).  Values are
        validated through float64, so they must lie in its range (about 1e-308 to
        1e308; ``"1e-400"`` is refused as not > 0, never turned into a wrong period).
    dps : int
        Significant decimal digits of the results.

    Returns
    -------
    Oscillator
        n, amplitude A0, energy E_n = A0^(2n)/(2n) and period T_n as mpf values.

    Raises
    ------
    ParameterError
        Both or neither of amplitude/energy given, or a value that is not finite and > 0.

    Examples
    --------
    >>> o = oscillator(3, energy="0.5", dps=15)
    >>> mpmath.nstr(o.amplitude, 15), mpmath.nstr(o.period, 15)
    ('1.200936955176', '5.83331262852068')
    """
    n = _check_n(n)
    dps = _check_dps(dps)
    if (amplitude is None) == (energy is None):
        given = "both" if amplitude is not None else "neither"
        raise ParameterError("amplitude/energy", given, "exactly one of amplitude and energy")
    name, value = ("amplitude", amplitude) if amplitude is not None else ("energy", energy)
    v.positive(name, value)
    with mpmath.workdps(dps + GUARD_DIGITS):
        x = mpmath.mpf(value)
        if name == "amplitude":
            a0, e = x, _generated().energy_of_amplitude_mp(n, x)
        else:
            a0, e = _generated().amplitude_of_energy_mp(n, x), x
        t = _generated().period_mp(n, a0)
    with mpmath.workdps(dps):
        return Oscillator(n, +a0, +e, +t, dps)


def period(n: int, amplitude: object = None, energy: object = None, *, dps: int = 30):
    """Exact period T_n of x'' + x^(2n-1) = 0 (paper eq. T) as an mpf with ``dps`` digits.

    Same parameters as :func:`oscillator`; T_1 = 2 pi for every amplitude.

    Examples
    --------
    >>> mpmath.nstr(period(2, amplitude=1, dps=20), 20)  # mpf prints at mpmath.mp.dps: use nstr
    '7.4162987092054876737'
    """
    return oscillator(n, amplitude, energy, dps=dps).period


# --- triangle wave (paper eq. tau intro) ------------------------------------------------
def triangle_wave(phase):
    """tau(phase) = (2/pi) arcsin sin(2 pi phase), evaluated piecewise-linearly.

    The literal formula loses half the digits near |tau| = 1 (arcsin of a number close
    to 1); the piecewise form tau = 4p, 2 - 4p, 4p - 4 on the quarters of the reduced
    phase p = phase mod 1 is exact up to the rounding of p.  Works on floats/arrays and,
    for a scalar mpf, at the current mpmath precision.

    Examples
    --------
    >>> triangle_wave(np.array([0.0, 0.125, 0.25, 0.5, 0.75, 1.125])).tolist()
    [0.0, 0.5, 1.0, 0.0, -1.0, 0.5]
    """
    if isinstance(phase, mpmath.mpf):
        p = phase - mpmath.floor(phase)
        return 4 * p if p <= 0.25 else (2 - 4 * p if p <= 0.75 else 4 * p - 4)
    p = np.mod(v.finite_array("phase", phase), 1.0)
    return np.where(p <= 0.25, 4 * p, np.where(p <= 0.75, 2 - 4 * p, 4 * p - 4))


def triangle_wave_derivative(phase):
    """d tau / d phase: +4 on rising quarters, -4 on the falling half (a.e.; tau' ^2 = 16).

    With phase = t / T, d tau / dt = triangle_wave_derivative(t / T) / T.  At the corners
    (phase = 1/4, 3/4 mod 1) the one-sided value of the following interval is returned.

    Examples
    --------
    >>> triangle_wave_derivative(np.array([0.1, 0.3, 0.8])).tolist()
    [4.0, -4.0, 4.0]
    """
    p = np.mod(v.finite_array("phase", phase), 1.0)
    return np.where((p < 0.25) | (p >= 0.75), 4.0, -4.0)


# --- exact shape Z(q): float64 ------------------------------------------------------------
def _quarter_integral(n: int) -> float:
    """K = int_0^1 dz / sqrt(1 - z^(2n)) = T_n(A0 = 1) / (4 sqrt(n)) (generated kernel)."""
    return _generated().period(n, 1.0) / (4.0 * math.sqrt(n))


def exact_shape(tau, n: int) -> np.ndarray:
    """Unit-amplitude exact solution as a function of the triangle wave: x / A0 = Z(tau).

    Parameters
    ----------
    tau : array_like in [-1, 1]
        Values of the paper's triangle wave tau(t / T) (``start="zero"`` convention).
    n : int in [1, 1000]

    Returns
    -------
    ndarray
        sign(tau) Z(|tau|); odd, Z(0) = 0, Z(1) = 1.  Accuracy about 1e-15 absolute.

    Examples
    --------
    >>> exact_shape([0.0, 0.5, 1.0], 1).round(15).tolist()  # sin(pi tau / 2) for n = 1
    [0.0, 0.707106781186548, 1.0]
    """
    from scipy import special  # imported here: 0.4 s that ``sinktheory period`` need not pay

    n = _check_n(n)
    tau = v.real_array("tau", tau)
    if not np.all(np.abs(tau) <= 1.0):
        raise ParameterError("tau", "values outside [-1, 1]", "in [-1, 1]")
    q = np.abs(tau)
    a = 0.5 / n
    k = _quarter_integral(n)
    q_switch = special.betainc(a, 0.5, 0.5)  # q where w = z^(2n) = 1/2
    z = np.empty_like(q)

    low = q <= q_switch
    z_lin = q[low] * k
    with np.errstate(under="ignore"):
        w_lin = np.exp(2 * n * np.log(np.maximum(z_lin, 1e-300)))
    linear = w_lin < _LINEAR_W
    z_low = z_lin.copy()
    if np.any(~linear):
        ql = q[low][~linear]
        w = special.betaincinv(a, 0.5, ql)
        # Newton on I_w(a, 1/2) = q in w: dI/dw = w^(a-1) (1-w)^(-1/2) / B(a, 1/2).
        w = w - (special.betainc(a, 0.5, w) - ql) * (2 * n * k) * w ** (1 - a) * np.sqrt(1 - w)
        z_low[~linear] = w**a
    z[low] = z_low

    high = ~low
    if np.any(high):
        r = 1.0 - q[high]  # exact (Sterbenz) since q > q_switch >= 1/2
        u = special.betaincinv(0.5, a, r)
        # Newton on I_u(1/2, a) = 1 - q in u: dI/du = u^(-1/2) (1-u)^(a-1) / B(a, 1/2).
        u = u - (special.betainc(0.5, a, u) - r) * (2 * n * k) * np.sqrt(u) * (1 - u) ** (1 - a)
        z[high] = np.exp(np.log1p(-u) * a)
    return np.sign(tau) * z


def _float_period(n: int, amplitude: float) -> float:
    try:
        t = _generated().period(n, amplitude)
    except ZeroDivisionError:  # A0^(n-1) underflowed to 0 inside the kernel
        t = math.inf
    if not (math.isfinite(t) and t > 0 and math.isfinite(1.0 / t)):
        raise PeriodOutOfRangeError(
            f"period of n = {n}, amplitude = {amplitude!r} is outside float64 range "
            "(A0^(n-1) over/underflows); use exact_solution_mp"
        )
    return t


def exact_solution(t, n: int, amplitude: float, *, start: str = "turning") -> np.ndarray:
    """Exact x(t) of x'' + x^(2n-1) = 0 with amplitude A0, vectorised float64.

    Parameters
    ----------
    t : array_like
        Times (any real values; the solution is T_n-periodic).
    n : int in [1, 1000]
    amplitude : float > 0
    start : "turning" or "zero"
        x(0) = A0, x'(0) = 0 (default) or x(0) = 0, x'(0) > 0.

    Returns
    -------
    ndarray
        x(t), absolute error about 1e-15 A0 plus the phase rounding |t| eps / T.

    Raises
    ------
    PeriodOutOfRangeError
        When T_n is not representable in float64 (large n with A0 far from 1).

    Examples
    --------
    >>> x = exact_solution([0.0, float(period(3, amplitude=2)) / 4], 3, 2.0)
    >>> bool(np.abs(x - [2.0, 0.0]).max() < 1e-14)
    True
    """
    n = _check_n(n)
    a0 = v.positive("amplitude", amplitude)
    shift = _PHASE_SHIFT[_check_start(start)]
    t = v.real_array("t", t)
    if not np.all(np.isfinite(t)):
        raise ParameterError("t", "non-finite values", "finite times")
    tau = triangle_wave(t / _float_period(n, a0) + shift)
    return a0 * exact_shape(tau, n)


# --- exact shape Z(q): arbitrary precision ------------------------------------------------
def _shape_mp(q: mpmath.mpf, n: int) -> mpmath.mpf:
    """Z(q) for 0 <= q <= 1 at the current precision (see the module docstring)."""
    if q == 0 or q == 1:
        return q
    a = mpmath.mpf(1) / (2 * n)
    k = _generated().period_mp(n, mpmath.mpf(1)) / (4 * mpmath.sqrt(n))
    z_switch = mpmath.mpf(2) ** (-a)  # z^(2n) = 1/2

    def low(z):  # F(z) - q K, increasing in z
        return z * mpmath.hyp2f1(a, 0.5, 1 + a, z ** (2 * n)) - q * k

    def high(r):  # (K - F(z)) - (1 - q) K with u = r^2 = 1 - z^(2n), increasing in r
        return r * mpmath.hyp2f1(0.5, 1 - a, 1.5, r * r) / n - (1 - q) * k

    try:
        if low(z_switch) >= 0:
            return mpmath.findroot(low, (mpmath.mpf(0), z_switch), solver="anderson")
        r = mpmath.findroot(high, (mpmath.mpf(0), mpmath.sqrt(0.5)), solver="anderson")
    except (ValueError, ZeroDivisionError) as e:
        raise BracketError(f"exact_shape_mp: no convergence for n = {n}, q = {q}: {e}") from e
    return (1 - r * r) ** a


def exact_shape_mp(tau: object, n: int, *, dps: int = 30) -> mpmath.mpf:
    """Z(tau) of :func:`exact_shape` at ``dps`` digits (scalar, any precision).

    Examples
    --------
    >>> mpmath.nstr(exact_shape_mp("0.5", 1, dps=20), 20)  # sin(pi/4)
    '0.7071067811865475244'
    """
    n = _check_n(n)
    dps = _check_dps(dps)
    v.finite("tau", tau)
    with mpmath.workdps(dps + GUARD_DIGITS):
        tau = mpmath.mpf(tau)
        if abs(tau) > 1:
            raise ParameterError("tau", tau, "in [-1, 1]")
        z = mpmath.sign(tau) * _shape_mp(abs(tau), n)
    with mpmath.workdps(dps):
        return +z


def exact_solution_mp(
    t: object, n: int, amplitude: object, *, start: str = "turning", dps: int = 30
) -> mpmath.mpf:
    """Exact x(t) at ``dps`` digits (scalar); conventions as in :func:`exact_solution`.

    Examples
    --------
    >>> mpmath.nstr(exact_solution_mp(1, 2, "1.5", dps=20), 20)
    '0.37540538889082741086'
    """
    n = _check_n(n)
    dps = _check_dps(dps)
    shift = _PHASE_SHIFT[_check_start(start)]
    v.finite("t", t)
    with mpmath.workdps(dps + GUARD_DIGITS):
        o = oscillator(n, amplitude=amplitude, dps=dps + GUARD_DIGITS)
        tau = triangle_wave(mpmath.mpf(t) / o.period + shift)
        x = o.amplitude * mpmath.sign(tau) * _shape_mp(abs(tau), n)
    with mpmath.workdps(dps):
        return +x
