"""Hill's equation along the power-law oscillator, integrated over a quarter period.

The normal mode y = 0 of the rescaled single-particle system (paper eqs. x-oscill and
y-oscill with mu -> 0) is governed by Hill's equation

    y'' + q(x(t)) y = 0,        x'' + x^(2n-1) = 0,

where x(t) is the periodic power-law oscillator of amplitude A0 started at a turning
point, x(0) = A0, x'(0) = 0.  This module integrates x together with the two
fundamental solutions y1 (y1(0) = 1, y1'(0) = 0) and y2 (y2(0) = 0, y2'(0) = 1) from
t = 0 to the quarter period Q = T_n / 4, where x first crosses zero.  The coefficient
is the same for every parameter value, so x is integrated once per step and applied to
many columns (parameter values) at once.

Normalisation to A0 = 1.  With x(t) = A0 X(s), s = A0^(n-1) t, the oscillator becomes
X'' + X^(2n-1) = 0 with X(0) = 1, and Hill's equation becomes

    d^2y/ds^2 + A0^(2-2n) q(A0 X(s)) y = 0.

For the pure equation q = Lam x^(2n) this is d^2y/ds^2 + (Lam A0^2) X^(2n) y = 0: only
Lam A0^2 matters.  The rescaling of time conjugates the monodromy matrix by
diag(1, A0^(n-1)), which leaves its trace (hence phi) unchanged.  All integrations here
run in the normalised variables.

Integrator: the Dormand-Prince 8(5,3) Runge-Kutta pair (tableau in
:mod:`sinktheory.dop853`) with adaptive steps.  Every step is accepted only if the worst
component of all columns (and of X) passes the error test, so all columns share one step
sequence.  Each solution pair (y, y') is renormalised by exact powers of two when it
grows past 2^400, so deeply unstable zones never overflow; the exponents are returned.

Two ways to run one loop.  The loop is written once, as plain Python over NumPy arrays.
Compiled by numba it is fast, but its first use in a process costs about 0.5 s (numba
loads its registry and LLVM, even from the on-disk cache).  Interpreted, with
pure-Python twins of the generated kernels (:func:`python_kernel`), it takes about 25 ms
for one parameter value and gives bitwise the compiled result (tested).
``implementation="auto"`` interprets the first few single-value integrations of a process, so a
one-point ``sinktheory floquet`` never loads numba's compiler; charts, scans and their
root finding run compiled.

Trustworthy range: ``rtol`` down to about 1e-14 (below that round-off dominates);
|q| large makes the step count grow like sqrt(max |q|) Q.  Stiff walls are handled by
the step control: an impact lasts a fraction of order 1/(4n) of the wall-to-wall flight,
the steps shrink there, and the step count stays near 60 for |Lam| <= 3 from n = 2 to
n = 1000 (errors measured against mpmath up to n = 200 stay below 1e-12, see
``benchmarks/bench_floquet.py``).

Examples
--------
>>> import numpy as np
>>> qp = integrate_quarter_period(2, np.array([0.0]))  # the pure equation, Lam = 0
>>> bool(abs(qp.y1[0] - 1.0) < 1e-12 and abs(qp.dy1[0]) < 1e-12)  # Lam = 0: y1 = 1
True
>>> bool(abs(qp.y2[0] - qp.quarter_period) < 1e-11)  # Lam = 0: y2 = s
True
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from . import dop853
from . import validation as v
from ._generated import oscillator as _osc
from ._generated._support import ipow
from ._generated.oscillator import oscillator_acceleration
from .dop853 import DEFAULT_RTOL
from .errors import HillIntegrationError, NonFiniteStateError, ParameterError
from .glossary import renamed
from .limits import MAX_DPS, MAX_N
from .twins import python_kernel

__all__ = [
    "check_amplitude",
    "integrate_quarter_period",
    "IMPLEMENTATIONS",
    "IVP_CALLS",
    "METHODS",
    "monodromy_solve_ivp",
    "MPMATH_MAX_LAM",
    "MPMATH_MAX_N",
    "PURE",
    "PYTHON_CALLS",
    "PYTHON_STEPS",
    "quarter_period_length",
    "quarter_period_mpmath",
    "QuarterPeriod",
    "RENORM_BITS",
]

#: Solution pairs are divided by 2^RENORM_BITS when their size exceeds 2^RENORM_BITS.
RENORM_BITS = 400
#: Bounds of the mpmath reference :func:`quarter_period_mpmath` (about a second at n = 10,
#: |lam| = 25; its Taylor steps shrink like 1 / sqrt(n) and 1 / sqrt|lam|).
MPMATH_MAX_N = 200
MPMATH_MAX_LAM = 1e4
#: Right-hand-side evaluations :func:`monodromy_solve_ivp` may use (tens of seconds).
IVP_CALLS = 2_000_000


#: What runs the loop of :func:`integrate_quarter_period` (its ``implementation``).
IMPLEMENTATIONS = ("auto", "compiled", "python")
#: The old name of IMPLEMENTATIONS, kept for one release.
METHODS = IMPLEMENTATIONS
#: ``implementation="auto"`` interprets at most this many single-value integrations per process
#: (about 25 ms each) before it loads the compiled loop (about 0.5 s once).
PYTHON_CALLS = 8
#: Step budget of an interpreted ``auto`` run (about 0.2 s); beyond it the integration
#: is redone by the compiled loop.
PYTHON_STEPS = 300

_A = np.ascontiguousarray(dop853.A)
_E3 = np.ascontiguousarray(dop853.E3)
_E5 = np.ascontiguousarray(dop853.E5)
#: The coefficient of the pure Hill equation, Lam x^(2n).
PURE = _osc.pure_hill_coefficient
_python_calls = [0]  # single-value integrations interpreted by implementation="auto" so far


def quarter_period_length(n: int) -> float:
    """Q = T_n(A0 = 1) / 4, the quarter period in the normalised time (generated formula).

    Examples
    --------
    >>> round(quarter_period_length(1), 12)  # pi / 2
    1.570796326795
    """
    return _quarter_period_length(v.positive_int("n", n, maximum=MAX_N))


@functools.cache
def _quarter_period_length(n: int) -> float:
    return float(python_kernel(_osc.period)(n, 1.0)) / 4.0


def check_amplitude(n: int, amplitude: float) -> float:
    """The amplitude A0 > 0, refused unless A0^(2n-2) and A0^2 are normal floats.

    The model's Hill coefficient is scaled by A0^(2-2n) and the pure equation's parameter
    by A0^2; an amplitude whose powers underflow or overflow would divide by zero or
    silently change the equation.

    Examples
    --------
    >>> check_amplitude(4, 2.0)
    2.0
    >>> check_amplitude(4, 1e-100)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: amplitude = 1e-100 is not allowed: must be in [1e-50, 1e+50] \
for n = 4 (A0^6 and A0^2 must stay within float range)
    """
    n = v.positive_int("n", n, maximum=MAX_N)
    a = v.positive("amplitude", amplitude)
    power = max(2, 2 * n - 2)
    bound = 10.0 ** (300 / power)
    if not 1.0 / bound <= a <= bound:
        raise ParameterError(
            "amplitude",
            amplitude,
            f"in [{1.0 / bound:.6g}, {bound:.6g}] for n = {n}",
            why=f"A0^{2 * n - 2} and A0^2 must stay within float range",
        )
    return a


@dataclass(frozen=True)
class QuarterPeriod:
    """Fundamental solutions of Hill's equation at the quarter period (normalised variables).

    The true values are ``y1 * 2**scale1``, ``dy1 * 2**scale1``, ``y2 * 2**scale2`` and
    ``dy2 * 2**scale2``; the scales are zero unless a solution grew past 2^400.

    Attributes
    ----------
    y1, dy1, y2, dy2 : ndarray
        Mantissas of y1(Q), y1'(Q), y2(Q), y2'(Q), one entry per parameter value.
    scale1, scale2 : ndarray of int
        Binary exponents of the two solutions.
    quarter_period : float
        Q = T_n(A0 = 1) / 4 in the normalised time s.
    steps, rejected : int
        Accepted and rejected Runge-Kutta steps.
    """

    y1: np.ndarray
    dy1: np.ndarray
    y2: np.ndarray
    dy2: np.ndarray
    scale1: np.ndarray
    scale2: np.ndarray
    quarter_period: float
    steps: int
    rejected: int


def _quarter_loop(q, n, amplitude, scale, alpha, params, q_end, rtol, max_steps, A, E3, E5):
    """The adaptive DOP853 loop over [0, Q]: compiled by :func:`_compiled_loop` or run as is.

    ``scale * q(amplitude * x, alpha, p, n)`` is the normalised coefficient.  Plain
    Python over NumPy arrays, so the interpreted run (:func:`python_kernel` of this
    function) does exactly the compiled run's floating-point operations.
    """
    m = params.size
    ns = E5.size  # 13 stages including the FSAL one
    kx = np.zeros(ns)
    kv = np.zeros(ns)
    ky = np.zeros((ns, m, 4))
    ys = np.zeros((m, 4))
    yn = np.zeros((m, 4))
    y = np.zeros((m, 4))
    expo = np.zeros((m, 2), dtype=np.int64)
    for j in range(m):
        y[j, 0] = 1.0
        y[j, 3] = 1.0
    x = 1.0
    vx = 0.0
    t = 0.0
    vscale = 1.0 / np.sqrt(n)  # speed of the normalised oscillator at x = 0
    h = min(q_end, 0.05 * vscale)
    big = 2.0**RENORM_BITS
    small = 2.0 ** (-RENORM_BITS)
    # first stage derivative
    kx[0] = vx
    kv[0] = oscillator_acceleration(x, n)
    for j in range(m):
        c = scale * q(amplitude * x, alpha, params[j], n)
        ky[0, j, 0] = y[j, 1]
        ky[0, j, 1] = -c * y[j, 0]
        ky[0, j, 2] = y[j, 3]
        ky[0, j, 3] = -c * y[j, 2]
    steps = 0
    rejected = 0
    status = 0
    while t < q_end:
        if steps + rejected >= max_steps:
            status = 1
            break
        last = False
        if t + h >= q_end * (1.0 - 1e-15):
            h = q_end - t
            last = True
        for s in range(1, ns):
            xs = x
            vs = vx
            for r in range(s):
                a = A[s, r]
                if a != 0.0:
                    xs += h * a * kx[r]
                    vs += h * a * kv[r]
            kx[s] = vs
            kv[s] = oscillator_acceleration(xs, n)
            for j in range(m):
                c = scale * q(amplitude * xs, alpha, params[j], n)
                for i in range(4):
                    acc = y[j, i]
                    for r in range(s):
                        a = A[s, r]
                        if a != 0.0:
                            acc += h * a * ky[r, j, i]
                    ys[j, i] = acc
                ky[s, j, 0] = ys[j, 1]
                ky[s, j, 1] = -c * ys[j, 0]
                ky[s, j, 2] = ys[j, 3]
                ky[s, j, 3] = -c * ys[j, 2]
                if s == ns - 1:
                    for i in range(4):
                        yn[j, i] = ys[j, i]
            if s == ns - 1:
                xn = xs
                vn = vs
        # error estimate (scipy's DOP853 norm, taken per component, worst one decides)
        err = 0.0
        e5 = 0.0
        e3 = 0.0
        for r in range(ns):
            e5 += E5[r] * kx[r]
            e3 += E3[r] * kx[r]
        e5 *= h / rtol
        e3 *= h / rtol
        d = e5 * e5 + 0.01 * e3 * e3
        if d > 0.0:
            err = max(err, e5 * e5 / np.sqrt(d))
        e5 = 0.0
        e3 = 0.0
        for r in range(ns):
            e5 += E5[r] * kv[r]
            e3 += E3[r] * kv[r]
        e5 *= h / (rtol * vscale)
        e3 *= h / (rtol * vscale)
        d = e5 * e5 + 0.01 * e3 * e3
        if d > 0.0:
            err = max(err, e5 * e5 / np.sqrt(d))
        for j in range(m):
            for pair in range(2):
                i0 = 2 * pair
                size = max(abs(y[j, i0]) + abs(y[j, i0 + 1]), abs(yn[j, i0]) + abs(yn[j, i0 + 1]))
                tol = rtol * size
                for i in range(i0, i0 + 2):
                    e5 = 0.0
                    e3 = 0.0
                    for r in range(ns):
                        e5 += E5[r] * ky[r, j, i]
                        e3 += E3[r] * ky[r, j, i]
                    e5 *= h / tol
                    e3 *= h / tol
                    d = e5 * e5 + 0.01 * e3 * e3
                    if d > 0.0:
                        err = max(err, e5 * e5 / np.sqrt(d))
        if not np.isfinite(err):
            status = 2
            break
        if err <= 1.0:
            steps += 1
            t = q_end if last else t + h
            x = xn
            vx = vn
            kx[0] = kx[ns - 1]
            kv[0] = kv[ns - 1]
            for j in range(m):
                for pair in range(2):
                    i0 = 2 * pair
                    f = 1.0
                    if abs(yn[j, i0]) + abs(yn[j, i0 + 1]) > big:
                        f = small
                        expo[j, pair] += RENORM_BITS
                    for i in range(i0, i0 + 2):
                        y[j, i] = yn[j, i] * f
                        ky[0, j, i] = ky[ns - 1, j, i] * f
            factor = 10.0 if err == 0.0 else min(10.0, 0.9 * err ** (-1.0 / 8.0))
        else:
            rejected += 1
            factor = max(0.2, 0.9 * err ** (-1.0 / 8.0))
        h *= factor
    return y, expo, steps, rejected, status


@functools.cache
def _compiled_loop():
    """:func:`_quarter_loop` compiled by numba (cached on disk; loading costs ~0.5 s).

    The coefficient is a first-class function argument, so one machine code serves
    every shape.
    """
    import numba
    from numba import types

    f64 = types.float64
    i64 = types.int64
    coefficient = types.FunctionType(f64(f64, f64, f64, i64))
    signature = types.Tuple((f64[:, ::1], i64[:, ::1], i64, i64, i64))(
        coefficient,
        i64,
        f64,
        f64,
        f64,
        f64[::1],
        f64,
        f64,
        i64,
        f64[:, ::1],
        f64[::1],
        f64[::1],
    )
    return numba.njit(signature, cache=True)(_quarter_loop)


def _run_loop(method, q, n, amplitude, alpha, params, q_end, rtol, max_steps):
    """Run the loop as ``method`` (the implementation) says; "auto" interprets a single
    value while the compiled loop is not loaded, for the first :data:`PYTHON_CALLS` such
    calls and at most :data:`PYTHON_STEPS` steps (then the compiled loop redoes it)."""
    scale = 1.0 / python_kernel(ipow)(amplitude, 2 * n - 2)  # A0^(2-2n) q(A0 x)
    args = (n, amplitude, scale, float(alpha), params, q_end, rtol)
    if method == "auto":
        if (
            params.size == 1
            and _compiled_loop.cache_info().currsize == 0
            and _python_calls[0] < PYTHON_CALLS
        ):
            _python_calls[0] += 1
            out = _interpret(q, args, min(max_steps, PYTHON_STEPS))
            if out[4] != 1 or max_steps <= PYTHON_STEPS:
                return out
        method = "compiled"
    if method == "python":
        return _interpret(q, args, max_steps)
    return _compiled_loop()(q, *args, max_steps, _A, _E3, _E5)


def _interpret(q, args, max_steps):
    """:func:`_quarter_loop` run by Python with the kernels' pure-Python twins."""
    with np.errstate(all="ignore"):  # overflow and inf - inf end the loop with status 2
        return python_kernel(_quarter_loop)(python_kernel(q), *args, max_steps, _A, _E3, _E5)


def _check_coefficient(coefficient) -> None:
    """Refuse a coefficient that is not a compiled kernel (which the loop is typed for)."""
    if not hasattr(coefficient, "py_func"):
        raise ParameterError(
            "coefficient", coefficient,
            "a compiled kernel q(x, alpha, p, n): hill.PURE or a well's kernels.hill_coefficient",
        )  # fmt: skip


def _label(coefficient) -> str:
    """``<module>.<function>`` of a coefficient kernel, for messages (``flat.hill_coefficient``)."""
    return f"{coefficient.__module__.rsplit('.', 1)[-1]}.{coefficient.__name__}"


@renamed(method="implementation")
def integrate_quarter_period(
    n: int,
    params: np.ndarray,
    *,
    coefficient=PURE,
    amplitude: float = 1.0,
    alpha: float = 0.0,
    rtol: float = DEFAULT_RTOL,
    max_steps: int = 1_000_000,
    implementation: str = "auto",
) -> QuarterPeriod:
    """Integrate X and the fundamental solutions of Hill's equation over [0, Q].

    Parameters
    ----------
    n : int >= 1
        Exponent of the oscillator x'' + x^(2n-1) = 0.
    params : array of float
        One column per entry: the third argument p of ``coefficient`` (Lam A0^2 for
        :data:`PURE`, beta for a shape's ``hill_coefficient``).
    coefficient : compiled kernel q(x, alpha, p, n)
        :data:`PURE` (Lam x^(2n)) or a well's ``kernels.hill_coefficient``; evaluated
        at x = A0 X and scaled by A0^(2-2n).
    amplitude : float > 0
        A0 (leave 1 for :data:`PURE`, whose Lam A0^2 is folded into ``params``).
    alpha : float
        alpha of the well (unused by :data:`PURE`).
    rtol : float in [1e-15, 1e-3]
        Per-step relative tolerance of every solution pair (y, y') and of X.
    max_steps : int
        Budget of steps (accepted plus rejected).
    implementation : {"auto", "compiled", "python"}
        What runs the loop.  "compiled": the numba loop; "python": the same loop
        interpreted (about 25 ms per value, bitwise the compiled result); "auto" (default):
        interpreted for a single value until the compiled loop is loaded (see the module
        docstring), else compiled.

    Returns
    -------
    QuarterPeriod

    Raises
    ------
    HillIntegrationError
        The step budget ran out (huge |q| or n).
    NonFiniteStateError
        A non-finite value appeared (e.g. an overflowing coefficient).

    Examples
    --------
    >>> import numpy as np
    >>> qp = integrate_quarter_period(1, np.array([1.0]))  # y'' + cos(t)^2 y = 0
    >>> round(qp.quarter_period, 12)  # pi / 2
    1.570796326795
    """
    n = v.positive_int("n", n)
    amplitude = check_amplitude(n, amplitude)
    rtol = v.positive("rtol", rtol)
    if not 1e-15 <= rtol <= 1e-3:
        raise ParameterError("rtol", rtol, "in [1e-15, 1e-3]")
    # a fresh writable copy: the compiled loop is typed for writable arrays, and callers
    # may pass read-only views (frozen results)
    params = np.array(np.atleast_1d(v.real_array("params", params)), dtype=float)
    if params.ndim != 1 or not np.all(np.isfinite(params)):
        raise ParameterError("params", params, "a 1-d array of finite numbers")
    max_steps = v.positive_int("max_steps", max_steps)
    alpha = v.finite("alpha", alpha)
    _check_coefficient(coefficient)
    method = implementation
    if method not in IMPLEMENTATIONS:
        raise ParameterError("implementation", method, f"one of {', '.join(IMPLEMENTATIONS)}")
    q_end = quarter_period_length(n)
    y, expo, steps, rejected, status = _run_loop(
        method, coefficient, n, amplitude, alpha, params, q_end, rtol, max_steps
    )
    if status == 1:
        raise HillIntegrationError(
            f"Hill integration (n = {n}, {_label(coefficient)}) used its {max_steps} steps before "
            f"reaching the quarter period Q = {q_end:.6g}; |q| is too large for this budget"
        )
    if status == 2 or not np.all(np.isfinite(y)):
        raise NonFiniteStateError(
            f"Hill integration (n = {n}, {_label(coefficient)}) produced a non-finite state "
            f"before Q = {q_end:.6g}"
        )
    return QuarterPeriod(
        y1=y[:, 0],
        dy1=y[:, 1],
        y2=y[:, 2],
        dy2=y[:, 3],
        scale1=expo[:, 0],
        scale2=expo[:, 1],
        quarter_period=q_end,
        steps=int(steps),
        rejected=int(rejected),
    )


# --- independent reference paths (slow; for tests and benchmarks) ----------------------


def quarter_period_mpmath(n: int, lam: float, *, dps: int = 30) -> tuple:
    """Reference (y1, y1', y2, y2') at Q for y'' + lam X^(2n) y = 0, at ``dps`` digits.

    Integrates X'' = -X^(2n-1) (X(0) = 1) with the fundamental solutions by mpmath's
    Taylor-series ODE solver (``mpmath.odefun``) at ``dps`` significant digits, up to
    Q = T_n / 4 from the generated ``period_mp``.  Independent of the float path: other
    method, other arithmetic, Q from the Gamma-function formula.  ``lam`` is Lam A0^2
    (normalised variables); for the model with n >= 2 it is lambda A0^2.  Costs about a
    second for n = 10; the Taylor steps shrink like 1/sqrt(n), so keep n below ~100.

    Returns
    -------
    tuple of mpmath.mpf
        (y1(Q), y1'(Q), y2(Q), y2'(Q), Q), rounded to ``dps`` digits.

    Examples
    --------
    >>> y1, dy1, y2, dy2, Q = quarter_period_mpmath(2, 0.0, dps=20)
    >>> float(y2 - Q), float(dy1)
    (0.0, 0.0)
    """
    import mpmath

    n = v.positive_int("n", n, maximum=MPMATH_MAX_N)
    lam_f = v.finite("lam", lam)
    if abs(lam_f) > MPMATH_MAX_LAM:
        raise ParameterError(
            "lam", lam, f"in [-{MPMATH_MAX_LAM:g}, {MPMATH_MAX_LAM:g}]",
            why="the Taylor steps shrink like 1 / sqrt|lam|: a reference, not a survey",
        )  # fmt: skip
    dps = v.positive_int("dps", dps, minimum=15, maximum=MAX_DPS)
    with mpmath.workdps(dps + 10):
        lam_mp = mpmath.mpf(lam_f)
        q_end = _osc.period_mp(n, mpmath.mpf(1)) / 4

        def rhs(_t, u):
            c = lam_mp * _osc.hill_shape_mp(u[0], n)
            acc = _osc.oscillator_acceleration_mp(u[0], n)
            return [u[1], acc, u[3], -c * u[2], u[5], -c * u[4]]

        sol = mpmath.odefun(rhs, 0, [mpmath.mpf(1), 0, 1, 0, 0, 1])(q_end)
        out = tuple(+x for x in sol[2:]) + (q_end,)
    with mpmath.workdps(dps):
        return tuple(+x for x in out)


def monodromy_solve_ivp(
    n: int,
    param: float,
    *,
    coefficient=PURE,
    amplitude: float = 1.0,
    alpha: float = 0.0,
    half_periods: int = 1,
    rtol: float = 1e-13,
) -> np.ndarray:
    """Second method: M over ``half_periods`` * T_n/2 by scipy's DOP853 (solve_ivp).

    Integrates the augmented system (X, X', y1, y1', y2, y2') in the normalised variables
    from the turning point over whole half periods, without the quarter-period symmetry.
    Slow (Python right-hand side); ``rtol`` 1e-13 with ``atol`` 1e-15 gives about 1e-11.
    ``coefficient`` and ``param`` (Lam A0^2 for :data:`PURE`, beta for a shape) are as in
    :func:`integrate_quarter_period`.

    Returns
    -------
    ndarray, shape (2, 2)
        [[y1, y2], [y1', y2']] at the end time.

    Examples
    --------
    >>> m = monodromy_solve_ivp(1, 0.0)  # y'' = 0 over pi: [[1, pi], [0, 1]]
    >>> bool(abs(m[0, 1] - np.pi) < 1e-10 and abs(m[1, 0]) < 1e-12)
    True
    """
    from scipy.integrate import solve_ivp

    n = v.positive_int("n", n)
    amplitude = check_amplitude(n, amplitude)
    scale = amplitude ** (2 - 2 * n)
    param = v.finite("param", param)
    alpha = v.finite("alpha", alpha)
    _check_coefficient(coefficient)
    half_periods = v.positive_int("half_periods", half_periods, maximum=10**4)
    rtol = v.positive("rtol", rtol)
    if not 1e-15 <= rtol <= 1e-3:
        raise ParameterError("rtol", rtol, "in [1e-15, 1e-3]")
    t_end = half_periods * float(_osc.period(n, 1.0)) / 2.0
    calls = [0]

    def rhs(t, u):
        calls[0] += 1
        if calls[0] > IVP_CALLS:
            raise HillIntegrationError(
                f"solve_ivp used its {IVP_CALLS} evaluations at t = {t:.6g} of {t_end:.6g} "
                f"(n = {n}, param = {param:g}): |q| is too large for this reference"
            )
        c = scale * coefficient(amplitude * u[0], alpha, param, n)
        acc = _osc.oscillator_acceleration(u[0], n)
        return [u[1], acc, u[3], -c * u[2], u[5], -c * u[4]]

    sol = solve_ivp(
        rhs, (0.0, t_end), [1.0, 0.0, 1.0, 0.0, 0.0, 1.0], method="DOP853", rtol=rtol, atol=1e-15
    )
    if not sol.success:
        raise HillIntegrationError(f"solve_ivp failed before t = {t_end:.6g}: {sol.message}")
    y = sol.y[:, -1]
    return np.array([[y[2], y[4]], [y[3], y[5]]])
