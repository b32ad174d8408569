r"""Floquet stability of the normal mode y = 0 (paper eq. y-oscill, Fig. 7).

Hill's equation y'' + q(x(t)) y = 0 has a coefficient of period T_n / 2, because q is
even in x and x(t + T_n/2) = -x(t).  With M(t) the fundamental matrix (columns y1, y2),
M(T_n) = M(T_n/2)^2, so

    phi_T = [y1(T) + y2'(T)] / 2 = 2 phi_half^2 - 1 >= -1,    phi_half = tr M(T/2) / 2.

phi_T alone cannot tell the two kinds of instability apart (both give phi_T > 1);
phi_half can: phi_half > 1 (multipliers real positive) and phi_half < -1 (real
negative).  The normal mode is stable iff |phi_half| < 1.  The multipliers over one
period are rho = phi_T +- sqrt(phi_T^2 - 1) = rho_half^2.

Quarter-period formulas.  Start x at a turning point, x(0) = A0, x'(0) = 0.  Then x is
even about t = 0 and odd about Q = T_n/4, so q(x(t)) is even about both 0 and Q.  Let
(y1, y1', y2, y2') be evaluated at Q.  Reversibility about Q: t -> 2Q - t maps
solutions to solutions, so the half-period map is M(2Q) = R M(Q)^{-1} R M(Q) with
R = diag(1, -1); with det M(Q) = y1 y2' - y2 y1' = 1 (Wronskian) this gives

    M(T/2) = [[y1 y2' + y2 y1',  2 y2 y2'],
              [2 y1 y1',         y1 y2' + y2 y1']],

    phi_half     = y1 y2' + y2 y1',
    phi_half - 1 = 2 y2 y1'     (use the Wronskian: y1 y2' = 1 + y2 y1'),
    phi_half + 1 = 2 y1 y2'.

So the stability boundaries phi_half = +1 are the zeros of y2(Q) or y1'(Q) and the
boundaries phi_half = -1 the zeros of y1(Q) or y2'(Q).  These factors are computed
without cancellation, so boundaries are located to near machine precision, and
stability is decided from their signs: stable iff y2 y1' < 0 < y1 y2'.  In deeply
unstable zones the products carry a common binary exponent (see
:mod:`sinktheory.hill`), so log|phi_half| stays accurate far beyond float range.

Rotation number.  In a stability zone rho = exp(+-i theta_T) with theta_T = 2 theta,
theta = arccos(phi_half) in [0, pi]; the rotation number per period T_n (modulo 1) is
theta / pi.  Strong resonances phi_T = -1 (rotation number 1/2) are the zeros of
phi_half inside stability zones; there M(T) = -I (coexistence), which the paper links to
the narrow chaotic windows of its bifurcation diagrams (Fig. 3).

Rigid-wall limit (n -> oo).  Take A0 = 1 (only Lam A0^2 matters).  The energy is
E = 1/(2n); away from the walls x^(2n) is negligible, x moves with constant speed
sqrt(2E) = 1/sqrt(n) and y'' = 0.  Near a wall x^(2n) is O(1) for a short impact, whose
weight follows from energy conservation, dt = dx / sqrt((1 - x^(2n))/n):

    int_impact x^(2n) dt = 2 sqrt(n) int_0^1 x^(2n) dx / sqrt(1 - x^(2n))
                         = B(1 + 1/(2n), 1/2) / sqrt(n)        (z = x^(2n))
                         -> 2 / sqrt(n).

In the time s = t / sqrt(n) the particle flies with unit speed, wall to wall in
2 units of s, and y_ss = -n Lam x^(2n) y; integrating over one impact gives the kick
dy/ds -> dy/ds - g y with g = Lam B(1 + 1/(2n), 1/2) -> 2 Lam.  So the coefficient tends
to a Kronig-Penney comb of delta kicks in a free medium.  One half period is one flight
and one kick, M(T/2) = [[1, 2], [0, 1]] [[1, 0], [-g, 1]], whose half-trace is

    phi_half -> 1 - g = 1 - 2 Lam A0^2         (n -> oo).

The limit has a single stability interval 0 < Lam A0^2 < 1; finite n adds the higher
bands at Lam A0^2 of order n, where the waves resolve the impact (which lasts a
fraction of order 1/(4n) of the flight).  At fixed Lam the corrections are O(1/n): the
kick weight B(1 + 1/(2n), 1/2) - 2 = O(1/n), the flight time T_n/(2 sqrt(n)) - 2 = O(1/n),
and the finite impact duration.

Accuracy (see tests): phi_half to 1e-10 relative to max(1, |phi_half|) with the
default tolerance, boundaries to 1e-10 in the parameter; log|rho| to 1e-10 relative in
deeply unstable zones.

Link to the full dynamics: in the simulator, a light particle (mu = 1e-4) on the
unstable normal mode grows its y at exactly this exponent times sqrt(gamma/mu)/(alpha -
beta) (tests/oscillator/test_floquet_vs_simulation.py, agreement 4e-6).  How far the intervals
predict the chaos of the oscillating container (mu = 0.2, Figs. 3 and 11) is measured
by ``sinktheory reproduce`` and stated in its report.

A user's well (:func:`well_floquet`).  When y = 0 is invariant (decided symbolically,
:func:`sinktheory.symbolic.normal_mode`), the orbit x'' = -dV/dx(x, 0) started at rest at
x = A and Hill's equation y'' + V_yy(x(t), 0) y = 0 are integrated together (DOP853 of
:func:`scipy.integrate.solve_ivp`, mass 1: the mass only rescales time).  The
reversibility argument above holds about every turning point, so without any symmetry
phi_T = y1 y2' + y2 y1' at the other turning point (half a period); when V(x, 0) and V_yy(x,
0) are both even in x (decided symbolically) the quarter-period formulas hold at x = 0
and give phi_half, as for the registered shapes.

Examples
--------
>>> chart = pure_hill([0.5], n=2)
>>> bool(chart.stable[0]), round(float(chart.phi_half[0]), 8)
(True, -0.00405143)
>>> c = model_hill(0.5, [-0.2], n=10)  # lambda = -2 beta (alpha - beta) = 0.28
>>> round(float(c.lam[0]), 12), bool(c.stable[0])
(0.28, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import validation as v
from ._generated import oscillator as _osc
from ._generated import shapes as _shapes
from .errors import BracketError, ParameterError
from .hill import (
    DEFAULT_RTOL,
    PURE,
    QuarterPeriod,
    check_amplitude,
    integrate_quarter_period,
)
from .model import MAX_N, Well
from .results import Result, plain
from .twins import python_kernel

__all__ = [
    "Boundary",
    "BOUNDARY_FACTORS",
    "FloquetChart",
    "HillProblem",
    "JSON_CAP",
    "LN2",
    "MAX_LAMBDA",
    "model_hill",
    "model_problem",
    "model_scan",
    "POINT_QUANTITIES",
    "pure_hill",
    "pure_problem",
    "pure_scan",
    "rigid_limit_phi_half",
    "ROOT_XTOL",
    "scan",
    "StabilityScan",
    "well_floquet",
    "well_hill",
    "WellFloquet",
    "WellHill",
    "well_scan",
    "WellScan",
]

#: Largest |lambda| A0^2 accepted: at 1e10 one quarter period takes about 1 s; at 1e12
#: it exceeds the integration's budget of 1e6 steps (measured, n = 4).
MAX_LAMBDA = 1e10

LN2 = math.log(2.0)
#: Tolerance in the parameter of every located boundary and resonance.
ROOT_XTOL = 1e-12
#: The quarter-period factors whose zeros are the stability boundaries, with the value of
#: phi_half there.
BOUNDARY_FACTORS = {"y2": 1.0, "dy1": 1.0, "y1": -1.0, "dy2": -1.0}
#: The order of the factors in :meth:`WellHill._factors`.
_FACTOR_ORDER = ("y1", "dy1", "y2", "dy2")
#: Magnitudes at or above this (or as small as its inverse) are written to JSON as decimal
#: strings built from their logarithms.
JSON_CAP = 1e300


def json_value(x: float, log_abs: float) -> float | str:
    """x as a JSON number, or as a decimal string built from ln|x| = ``log_abs`` when
    |x| >= 1e300 or 0 < |x| <= 1e-300 (beyond or near the end of float range).

    Examples
    --------
    >>> json_value(2.5, math.log(2.5))
    2.5
    >>> json_value(math.inf, 1000.0)
    '1.97007111e+434'
    >>> json_value(0.0, -1000.0)
    '5.07595890e-435'
    """
    if not math.isfinite(log_abs) or abs(log_abs) < math.log(JSON_CAP):
        return float(x)
    sign = "-" if x < 0 else ""
    log10 = log_abs / math.log(10.0)
    exponent = math.floor(log10)
    mantissa = 10.0 ** (log10 - exponent)
    return f"{sign}{mantissa:.8f}e{exponent:+d}"


@dataclass(frozen=True)
class HillProblem:
    """One family of Hill equations, parametrised by Lam (pure) or beta (model).

    Use :func:`pure_problem` / :func:`model_problem` to build it (they validate).

    Attributes
    ----------
    kind : "pure" or the name of a well shape (:data:`sinktheory.model.SHAPES`)
    n : int
    amplitude : float
        A0, the amplitude of x(t).
    alpha, gamma : float
        Well parameters (model kinds; gamma only enters through the time rescaling and
        so does not change phi).
    rtol : float
        Per-step tolerance of the integration.
    """

    kind: str
    n: int
    amplitude: float = 1.0
    alpha: float = 0.0
    gamma: float = 1.0
    rtol: float = DEFAULT_RTOL

    @property
    def parameter(self) -> str:
        """Name of the parameter: ``"lam"`` or ``"beta"``."""
        return "lam" if self.kind == "pure" else "beta"

    @property
    def coefficient(self):
        """The compiled coefficient q(x, alpha, p, n): Lam x^(2n), or the well shape's
        generated ``hill_coefficient``."""
        return PURE if self.kind == "pure" else _shapes.bundle(self.kind).hill_coefficient

    def _well(self, beta: float) -> Well:
        return Well(self.alpha, beta, self.n, gamma=self.gamma, shape=self.kind)

    def check(self, values) -> np.ndarray:
        """Validate parameter values; returns them as a 1-d float array.

        Besides the model's own checks: the amplitude must keep A0^(2n-2) and A0^2 in
        float range (:func:`sinktheory.hill.check_amplitude`), and the effective
        parameter |lambda| A0^2 must be <= :data:`MAX_LAMBDA`, beyond which the
        quarter-period integration cannot finish within its step budget.
        """
        try:
            arr = np.atleast_1d(np.asarray(values, dtype=float))
        except (TypeError, ValueError):
            raise ParameterError(
                self.parameter, values, "a non-empty 1-d list of numbers"
            ) from None
        if arr.ndim != 1 or arr.size == 0:
            raise ParameterError(self.parameter, values, "a non-empty 1-d list of numbers")
        check_amplitude(self.n, self.amplitude)
        for value in dict.fromkeys((arr.min(), arr.max())):  # one beta: checked once
            if self.kind == "pure":
                v.finite("lam", value)
            else:
                self._well(float(value))
            with np.errstate(over="ignore"):  # an overflow is inf, refused just below
                lam = float(self._lam(np.array([value]))[0])
            if abs(lam) * self.amplitude**2 > MAX_LAMBDA:
                raise ParameterError(
                    self.parameter,
                    float(value),
                    f"a value with |lambda| A0^2 <= {MAX_LAMBDA:g}",
                    why=f"lambda = {lam:.3g} at amplitude A0 = {self.amplitude:g}: the "
                    "quarter-period integration would exceed its step budget",
                )
        if self.kind != "pure":
            for beta in arr:
                self._check_denominators(float(beta))
        return arr

    def _check_denominators(self, beta: float) -> None:
        """The walls' denominators must stay positive along the orbit on y = 0.

        In physical units x reaches (alpha - beta) A0; each denominator is monotone in
        x^2, so it must stay positive at that end (else Hill's coefficient has a pole there:
        the symmetric well's D(x) for n = 1 and large A0).
        """
        well = self._well(beta)
        x_end = well.wall_distance * self.amplitude
        if not well.kernels.smallest_denominator(x_end, 0.0, self.alpha, beta) > 0:
            raise ParameterError(
                "amplitude",
                self.amplitude,
                f"smaller for beta = {beta!r} ({self.kind} well, n = {self.n})",
                why="a wall denominator vanishes inside the x-range, "
                "where Hill's coefficient has a pole",
            )

    def _lam(self, values: np.ndarray) -> np.ndarray:
        """lambda of eq. y-oscill: Lam itself, or the shape's generated ``hill_lambda``
        (Hill's coefficient at the turning point x = 1 for n >= 2: -2 beta (alpha - beta)
        for the paper's wells, 1 for the circular one)."""
        if self.kind == "pure":
            return np.asarray(values, dtype=float)
        hill_lambda = _shapes.bundle(self.kind).hill_lambda  # the well is checked already
        return np.array([hill_lambda(self.alpha, b) for b in values])

    def _quarter(self, values: np.ndarray) -> QuarterPeriod:
        """Fundamental solutions at Q for already validated parameter values."""
        pure = self.kind == "pure"
        return integrate_quarter_period(
            self.n,
            values * self.amplitude**2 if pure else values,
            coefficient=self.coefficient,
            amplitude=1.0 if pure else self.amplitude,
            alpha=self.alpha,
            rtol=self.rtol,
        )

    def evaluate(self, values) -> FloquetChart:
        """phi_half, multipliers and stability at each parameter value."""
        arr = self.check(values)
        return FloquetChart(self, arr, self._quarter(arr))


def pure_problem(n: int, amplitude: float = 1.0, *, rtol: float = DEFAULT_RTOL) -> HillProblem:
    """The pure Hill equation y'' + Lam x(t)^(2n) y = 0 as a family in Lam.

    Parameters
    ----------
    n : int in [1, 1000]
    amplitude : float > 0
        A0; only Lam A0^2 matters (see :mod:`sinktheory.hill`).
    rtol : float
        Per-step tolerance of the integration.

    Returns
    -------
    HillProblem

    Examples
    --------
    >>> p = pure_problem(4)
    >>> p.parameter, bool(p.evaluate([-1.0]).phi_half[0] > 1)  # Lam < 0: unstable
    ('lam', True)
    """
    return HillProblem(
        kind="pure",
        n=v.positive_int("n", n, maximum=MAX_N),
        amplitude=v.positive("amplitude", amplitude),
        rtol=v.positive("rtol", rtol),
    )


def model_problem(
    alpha: float,
    n: int,
    *,
    gamma: float = 1.0,
    shape: str = "flat",
    amplitude: float = 1.0,
    rtol: float = DEFAULT_RTOL,
) -> HillProblem:
    """Hill's equation of the model, linearised about y = 0, as a family in beta.

    The coefficient is the shape's generated ``hill_coefficient`` in the rescaled
    variables: lambda x^(2n) for n >= 2; for n = 1 an extra constant-plus-x^2 term
    (flat) or a rational function of x^2 (symmetric) that the paper's eq. y-oscill omits.
    The circular well gives x^(2n-2), the same for every beta: there y = eps x(t) (the
    orbit turned by a small angle) solves Hill's equation, so phi_half = -1 exactly, a
    neutral normal mode.  A shape whose line y = 0 is not an invariant power-law orbit
    is refused, naming why.

    Parameters
    ----------
    alpha : float > 0
    n : int in [1, 1000]
    gamma : float > 0
        Validated only: it is absorbed by the time rescaling and does not change phi.
    shape : one of :data:`sinktheory.model.SHAPES` (with a normal mode y = 0)
    amplitude : float > 0
        A0 of the rescaled oscillator x(t).
    rtol : float
        Per-step tolerance of the integration.

    Returns
    -------
    HillProblem

    Examples
    --------
    >>> p = model_problem(0.5, 2)
    >>> p.parameter, float(p._lam(np.array([-0.5]))[0])  # -2 beta (alpha - beta)
    ('beta', 1.0)
    """
    well = Well(alpha, 0.0, n, gamma=gamma, shape=shape)  # validates all but beta
    if well.kernels.NORMAL_MODE_REFUSAL:
        raise ParameterError(
            "shape",
            shape,
            "a shape with a normal mode y = 0 for Hill's analysis",
            why=well.kernels.NORMAL_MODE_REFUSAL,
        )
    return HillProblem(
        kind=well.shape,
        n=well.n,
        amplitude=v.positive("amplitude", amplitude),
        alpha=well.alpha,
        gamma=well.gamma,
        rtol=v.positive("rtol", rtol),
    )


def pure_hill(lam, n: int, amplitude: float = 1.0, *, rtol: float = DEFAULT_RTOL):
    """Floquet data of y'' + Lam x^(2n) y = 0 at each Lam.

    Parameters
    ----------
    lam : float or array of float
        Lam.  Only Lam A0^2 matters: rescaling t shows the equation with amplitude A0
        equals the one with amplitude 1 and Lam A0^2 (see :mod:`sinktheory.hill`).
    n : int in [1, 1000]
    amplitude : float > 0
        A0 (default 1).
    rtol : float
        Per-step tolerance (default 1e-13).

    Returns
    -------
    FloquetChart

    Examples
    --------
    >>> a = pure_hill([0.3], n=3, amplitude=2.0).phi_half[0]
    >>> b = pure_hill([1.2], n=3, amplitude=1.0).phi_half[0]
    >>> bool(abs(a - b) < 1e-11)
    True
    """
    return pure_problem(n, amplitude, rtol=rtol).evaluate(lam)


def model_hill(
    alpha: float,
    beta,
    n: int,
    *,
    gamma: float = 1.0,
    shape: str = "flat",
    amplitude: float = 1.0,
    rtol: float = DEFAULT_RTOL,
):
    """Floquet data of the model's Hill equation at each beta (validated by ``Well``).

    Examples
    --------
    >>> c = model_hill(0.5, [0.25], n=2)  # lambda = -0.125 < 0: phi_half > 1
    >>> bool(c.stable[0]), bool(c.phi_half[0] > 1)
    (False, True)
    """
    problem = model_problem(alpha, n, gamma=gamma, shape=shape, amplitude=amplitude, rtol=rtol)
    return problem.evaluate(beta)


_POINTWISE = (
    "lambda",
    "phi_half",
    "phi",
    "log_abs_phi_half",
    "log_abs_phi",
    "stable",
    "growth_per_period",
    "floquet_exponent",
    "rotation_number",
)


@dataclass(frozen=True)
class FloquetChart(Result):
    """Floquet data of a family of Hill equations at an array of parameter values.

    ``phi_half``, ``phi`` and ``multipliers`` are float arrays and become +-inf only
    where the value exceeds float64 range (about 1e308); the ``log_*`` attributes are
    always finite (except log|phi_half| = -inf where phi_half is exactly 0).  On the
    result protocol (:mod:`sinktheory.results`): ``to_dataset()`` has the dimension
    ``value`` (labelled by beta or lam), and ``as_dict()`` writes values beyond float
    range as decimal strings (:func:`json_value`).

    Examples
    --------
    >>> chart = pure_problem(1).evaluate([0.5, 2.0])
    >>> d = chart.as_dict()
    >>> d["lam"], d["stable"]
    ([0.5, 2.0], [True, False])
    >>> chart.as_dict(point=1)["lam"], chart.to_dataset().phi_half.dims
    (2.0, ('value',))
    """

    DIMS = {name: ("value",) for name in _POINTWISE} | {"multipliers": ("value", "multiplier")}
    COORDS = {"beta": "value", "lam": "value"}

    problem: HillProblem
    values: np.ndarray
    quarter: QuarterPeriod = field(repr=False)

    # --- result protocol ---------------------------------------------------------------
    def _head(self) -> dict:
        p = self.problem
        head = {"kind": p.kind, "n": p.n, "amplitude": p.amplitude}
        if p.kind != "pure":
            head.update(alpha=p.alpha, gamma=p.gamma, shape=p.kind)
        return head

    def items(self) -> dict:
        """The problem's parameters, the values and every pointwise quantity."""
        out = {**self._head(), self.problem.parameter: self.values}
        out.update(
            {name: getattr(self, "lam" if name == "lambda" else name) for name in _POINTWISE}
        )
        out["multipliers"] = self.multipliers
        out["period"] = self.period
        return out

    def _point(self, i: int) -> dict:
        """Value i as JSON-ready scalars (huge or tiny values as decimal strings)."""
        lh = float(self.log_abs_phi_half[i])
        lp = float(self.log_abs_phi[i])
        g = float(self.growth_per_period[i])
        rho = self.multipliers[i]
        if self.stable[i]:
            multipliers = [[float(r.real), float(r.imag)] for r in rho]
        else:
            multipliers = [
                [json_value(float(rho[0].real), g), 0.0],
                [json_value(float(rho[1].real), -g), 0.0],
            ]
        return {
            self.problem.parameter: float(self.values[i]),
            "lambda": float(self.lam[i]),
            "phi_half": json_value(float(self.phi_half[i]), lh),
            "phi": json_value(float(self.phi[i]), lp),
            "log_abs_phi_half": plain(lh),
            "log_abs_phi": plain(lp),
            "multipliers": multipliers,
            "stable": bool(self.stable[i]),
            "growth_per_period": g,
            "floquet_exponent": float(self.floquet_exponent[i]),
            "rotation_number": float(self.rotation_number[i]),
        }

    def as_dict(self, point: int | None = None) -> dict:
        """JSON-ready: per value a list (or, with ``point=i``, value i's scalars)."""
        if point is not None:
            last = len(self.values) - 1
            rows = self._point(v.positive_int("point", point, minimum=0, maximum=last))
        else:
            points = [self._point(i) for i in range(len(self.values))]
            rows = {key: [p[key] for p in points] for key in points[0]} if points else {}
        return {**self._head(), **rows, "period": self.period}

    # --- the four quarter-period factors and their products ---------------------------
    @property
    def lam(self) -> np.ndarray:
        """lambda of eq. y-oscill at each value."""
        return self.problem._lam(self.values)

    @property
    def _exponent(self) -> np.ndarray:
        return self.quarter.scale1 + self.quarter.scale2

    @property
    def _p(self) -> np.ndarray:  # y1 y2' (mantissa)
        return self.quarter.y1 * self.quarter.dy2

    @property
    def _r(self) -> np.ndarray:  # y2 y1' (mantissa)
        return self.quarter.y2 * self.quarter.dy1

    def factor(self, name: str) -> np.ndarray:
        """One of y1(Q), dy1(Q), y2(Q), dy2(Q), in the normalised variables (may be inf)."""
        q = self.quarter
        mant = {"y1": q.y1, "dy1": q.dy1, "y2": q.y2, "dy2": q.dy2}[
            v.choice("name", name, _FACTOR_ORDER)
        ]
        scale = q.scale1 if name in ("y1", "dy1") else q.scale2
        with np.errstate(over="ignore"):
            return np.ldexp(mant, scale)

    @property
    def stable(self) -> np.ndarray:
        """|phi_half| < 1, decided from the signs of the factors: y2 y1' < 0 < y1 y2'."""
        return (self._p > 0) & (self._r < 0)

    @property
    def phi_half(self) -> np.ndarray:
        """phi_{T/2} = y1 y2' + y2 y1' at Q (= half trace of M(T/2))."""
        with np.errstate(over="ignore"):
            return np.ldexp(self._p + self._r, self._exponent)

    @property
    def phi_half_minus_one(self) -> np.ndarray:
        """phi_half - 1 = 2 y2 y1', free of cancellation."""
        with np.errstate(over="ignore"):
            return np.ldexp(2 * self._r, self._exponent)

    @property
    def phi_half_plus_one(self) -> np.ndarray:
        """phi_half + 1 = 2 y1 y2', free of cancellation."""
        with np.errstate(over="ignore"):
            return np.ldexp(2 * self._p, self._exponent)

    @property
    def phi(self) -> np.ndarray:
        """phi_T = 2 phi_half^2 - 1 (the paper's phi; >= -1)."""
        h = self.phi_half
        with np.errstate(over="ignore"):
            return 2.0 * h * h - 1.0

    @property
    def log_abs_phi_half(self) -> np.ndarray:
        """ln|phi_half|, finite in deeply unstable zones."""
        with np.errstate(divide="ignore"):
            return np.log(np.abs(self._p + self._r)) + self._exponent * LN2

    @property
    def log_abs_phi(self) -> np.ndarray:
        """ln|phi_T|, finite in deeply unstable zones (ln(2 phi_half^2 - 1))."""
        lh = self.log_abs_phi_half
        h = self.phi_half
        with np.errstate(divide="ignore", over="ignore"):
            direct = np.log(np.abs(2.0 * h * h - 1.0))
        return np.where(lh > 300.0, LN2 + 2.0 * lh, direct)

    @property
    def rotation_number(self) -> np.ndarray:
        """theta/pi in [0, 1], theta = arccos(phi_half): rotation per period T_n, modulo 1
        (:func:`rotation_number` of the cancellation-free factors)."""
        return rotation_number(self.phi_half, self.phi_half_minus_one, self.phi_half_plus_one)

    @property
    def log_abs_rho_half(self) -> np.ndarray:
        """ln of the largest |multiplier| over T/2: arccosh|phi_half| (0 where stable;
        :func:`_arccosh_abs` of the cancellation-free factors)."""
        return _arccosh_abs(self.phi_half_minus_one, self.phi_half_plus_one, self.log_abs_phi_half)

    @property
    def growth_per_period(self) -> np.ndarray:
        """ln|rho|_max over one period T_n (= 2 arccosh|phi_half|; 0 where stable)."""
        return 2.0 * self.log_abs_rho_half

    @property
    def period(self) -> float:
        """T_n at the amplitude A0 (rescaled time of eq. x-oscill), generated kernel."""
        return float(python_kernel(_osc.period)(self.problem.n, self.problem.amplitude))

    @property
    def floquet_exponent(self) -> np.ndarray:
        """Largest Floquet exponent ln|rho| / T_n per unit rescaled time (0 where stable)."""
        return self.growth_per_period / self.period

    @property
    def multipliers(self) -> np.ndarray:
        """rho_{1,2} over T_n, shape (m, 2), complex: phi_T +- sqrt(phi_T^2 - 1).

        Stable: exp(+-2 i theta).  Unstable: exp(+-g), g = growth_per_period (positive
        real, since rho = rho_half^2); the large one becomes inf beyond float range.
        """
        return _multipliers(self.rotation_number, self.growth_per_period, self.stable)


def _arccosh_abs(minus, plus, log_abs) -> np.ndarray:
    """arccosh abs(c), the log of the larger abs(eigenvalue) of a unimodular 2x2 map of
    half trace c, from ``minus`` = c - 1 and ``plus`` = c + 1 as the quarter-period factors
    give them without cancellation (0 where abs(c) <= 1): log1p(d + sqrt(d (d + 2))),
    d = abs(c) - 1, keeps its relative accuracy as d -> 0, where it is sqrt(2 d); above
    ``log_abs`` = ln abs(c) = 20 (c may be beyond float range) it is ln 2 + ln abs(c),
    exact to e^-40.  The one formula of the registered charts
    (:attr:`FloquetChart.log_abs_rho_half`) and of a user's well (:class:`WellFloquet`)."""
    minus, plus = np.asarray(minus, dtype=float), np.asarray(plus, dtype=float)
    d = np.where(minus > 0, minus, np.where(plus < 0, -plus, 0.0))
    with np.errstate(over="ignore", invalid="ignore"):
        small = np.log1p(d + np.sqrt(d * (d + 2.0)))
    return np.where(np.asarray(log_abs) > 20.0, LN2 + log_abs, small)


def _multipliers(rotation, growth, stable, sign=1.0) -> np.ndarray:
    """The Floquet multipliers (rho_1, rho_2) over a period, last axis, complex:
    exp(+-2 i theta), theta = pi ``rotation``, where ``stable``; ``sign`` exp(+-``growth``)
    otherwise (the large one inf beyond float range).  rho_1 rho_2 = 1 by construction, and
    near abs(rho) = 1 each is as accurate as the rotation number or the growth it comes
    from (rho = c +- sqrt(c^2 - 1) loses half the digits of c there).  The one formula of
    the registered charts (:attr:`FloquetChart.multipliers`) and of a user's well
    (:class:`WellFloquet`)."""
    theta = np.pi * np.asarray(rotation, dtype=float)
    g = np.asarray(growth, dtype=float)
    with np.errstate(over="ignore"):
        big = np.exp(g)
    small = np.exp(-g)
    rho1 = np.where(stable, np.exp(2j * theta), sign * big + 0j)
    rho2 = np.where(stable, np.exp(-2j * theta), sign * small + 0j)
    return np.stack([rho1, rho2], axis=-1)


def rotation_number(phi_half, phi_half_minus_one, phi_half_plus_one) -> np.ndarray:
    """theta/pi in [0, 1], theta = arccos(phi_half): the rotation number per period,
    modulo 1, of a Hill equation whose half-period map has half trace ``phi_half``.

    0 where phi_half >= 1 and 1 where phi_half <= -1; 1/2 at the strong resonances
    phi_T = -1.  arccos has an infinite slope at +-1, so there theta comes from the
    differences phi_half - 1 and phi_half + 1 as the quarter-period factors give them
    without cancellation (2 y2 y1' and 2 y1 y2'): theta = 2 arcsin(sqrt((1 - phi_half)/2))
    where phi_half > 1/2, pi - 2 arcsin(sqrt((1 + phi_half)/2)) where phi_half < -1/2,
    arccos(phi_half) between.  The one formula of the registered charts
    (:attr:`FloquetChart.rotation_number`) and of a user's well
    (:attr:`WellFloquet.rotation_number`).

    Examples
    --------
    >>> d = -2e-12  # phi_half = 1 - 2e-12, which float64 cannot hold exactly
    >>> nu = float(rotation_number(1 + d, d, 2 + d))  # theta = 2e-6 (1 + O(d))
    >>> round(nu * math.pi / 2e-6, 12)
    1.0
    """
    h = np.asarray(phi_half, dtype=float)
    minus = np.asarray(phi_half_minus_one, dtype=float)
    plus = np.asarray(phi_half_plus_one, dtype=float)
    with np.errstate(invalid="ignore"):
        near_plus = np.sqrt(np.clip(-0.5 * minus, 0.0, 1.0))
        near_minus = np.sqrt(np.clip(0.5 * plus, 0.0, 1.0))
        theta = np.where(
            h > 0.5,
            2 * np.arcsin(near_plus),
            np.where(h < -0.5, np.pi - 2 * np.arcsin(near_minus),
                     np.arccos(np.clip(h, -1.0, 1.0))),
        )  # fmt: skip
    return theta / np.pi


# --- stability intervals ---------------------------------------------------------------


@dataclass(frozen=True)
class Boundary:
    """A located stability boundary: ``factor`` vanishes at ``value``; phi_half = ``phi_half``
    (for a user's well without symmetry the factor is taken at the half period and the value
    is phi's, :func:`well_scan`)."""

    value: float
    factor: str
    phi_half: float


@dataclass(frozen=True)
class StabilityScan(Result):
    """A grid chart with refined stability intervals and strong resonances.

    ``as_dict()`` is the chart's (:meth:`FloquetChart.as_dict`) with the intervals,
    boundaries and resonances added; ``to_dataset()`` nests the chart (``chart_*``).

    Attributes
    ----------
    chart : FloquetChart
        The grid values.
    boundaries : list of Boundary
        Every zero of a quarter-period factor in the range, located by brentq.
    stable_intervals : list of (lo, hi)
        Maximal stable intervals; an end equal to the range end is not a boundary.
    resonances : list of float
        Zeros of phi_half (phi_T = -1) inside stable intervals.
    """

    chart: FloquetChart
    boundaries: list[Boundary]
    stable_intervals: list[tuple[float, float]]
    resonances: list[float]

    def as_dict(self) -> dict:
        """The chart's JSON with the located intervals, boundaries and resonances."""
        out = self.chart.as_dict()
        out["stable_intervals"] = [[a, b] for a, b in self.stable_intervals]
        out["boundaries"] = plain(self.boundaries)
        out["resonances"] = plain(self.resonances)
        return out


def _scalar(chart_of, name: str):
    def f(value: float) -> float:
        out = chart_of(value)
        x = float(out.phi_half[0] if name == "phi_half" else out.factor(name)[0])
        return max(-1e300, min(1e300, x))

    return f


def _brentq(f, a: float, b: float, what: str) -> float:
    from scipy import optimize  # imported here: 0.3 s that one-point charts need not pay

    try:
        return float(optimize.brentq(f, a, b, xtol=ROOT_XTOL, rtol=4 * np.finfo(float).eps))
    except (ValueError, RuntimeError) as exc:
        raise BracketError(f"cannot locate the zero of {what} in [{a!r}, {b!r}]: {exc}") from None


def scan(problem: HillProblem, lo: float, hi: float, count: int) -> StabilityScan:
    """phi_half on a grid over [lo, hi], stability intervals with located boundaries.

    Each sign change of y1(Q), y1'(Q), y2(Q) or y2'(Q) between neighbouring grid points
    is refined by brentq to 1e-12 in the parameter.  A gap or a resonance narrower than
    the grid spacing is still found when each bounding factor changes sign once in a
    cell (the usual case), but two zeros of one factor within one cell are missed.

    Parameters
    ----------
    problem : HillProblem
    lo, hi : float
        Range of the parameter, lo < hi (model: both < alpha).
    count : int >= 2
        Number of grid points.

    Returns
    -------
    StabilityScan

    Examples
    --------
    >>> s = scan(pure_problem(1), 0.0, 3.0, 31)  # y'' + Lam cos(t)^2 y = 0
    >>> [(round(a, 9), round(b, 9)) for a, b in s.stable_intervals]
    [(0.0, 1.316022911)]
    """
    if not isinstance(problem, HillProblem):
        raise ParameterError(
            "problem", problem, "a HillProblem (from pure_problem or model_problem)"
        )
    lo = v.finite("lo", lo)
    hi = v.finite("hi", hi)
    count = v.positive_int("count", count, minimum=2, maximum=1_000_000)
    if not lo < hi:
        raise ParameterError("hi", hi, f"> lo = {lo!r}")
    grid = np.linspace(lo, hi, count)
    chart = problem.evaluate(grid)

    def one(value: float) -> FloquetChart:
        return FloquetChart(problem, np.array([value]), problem._quarter(np.array([value])))

    boundaries = _factor_boundaries(grid, chart.factor, lambda name: _scalar(one, name), "Q")
    intervals = _stable_intervals(
        lo, hi, [b.value for b in boundaries], lambda mids: problem.evaluate(mids).stable
    )
    resonances: list[float] = []
    f_phi = _scalar(one, "phi_half")
    h = chart.phi_half
    for a, b in intervals:
        inside = np.nonzero((grid >= a) & (grid <= b))[0]
        pts = [a] + [float(grid[i]) for i in inside if a < grid[i] < b] + [b]
        vals = [f_phi(a)] + [float(h[i]) for i in inside if a < grid[i] < b] + [f_phi(b)]
        for k in range(len(pts) - 1):
            if vals[k] * vals[k + 1] < 0:
                resonances.append(_brentq(f_phi, pts[k], pts[k + 1], "phi_half"))
    return StabilityScan(chart, boundaries, intervals, resonances)


def _factor_boundaries(grid, on_grid, function, where: str) -> list[Boundary]:
    """Every zero of the factors y1, y1', y2, y2' (:data:`BOUNDARY_FACTORS`, taken at the
    time ``where``) between neighbouring points of ``grid``, located by brentq to
    :data:`ROOT_XTOL`, sorted: ``on_grid(name)`` is a factor's values on the grid,
    ``function(name)`` the factor as a function of the parameter.  Each factor crosses
    zero at an edge with a slope of order 1 however narrow the gap, so the edge is located
    to the factor's own accuracy (trace -+ 1 is quadratic across a closed gap and has a
    slope of the gap's width at a narrow one).  Shared by :func:`scan` and
    :func:`well_scan`."""
    boundaries: list[Boundary] = []
    for name, phi_value in BOUNDARY_FACTORS.items():
        sign = np.sign(on_grid(name))
        f = function(name)
        for i in np.nonzero(sign[:-1] * sign[1:] <= 0)[0]:
            if sign[i] == 0 and i > 0:
                continue  # a zero on a grid point was found from the previous cell
            root = _brentq(f, grid[i], grid[i + 1], f"{name}({where})")
            boundaries.append(Boundary(root, name, phi_value))
    boundaries.sort(key=lambda b: b.value)
    return boundaries


def _stable_intervals(lo: float, hi: float, cuts, stable_at) -> list[tuple[float, float]]:
    """The maximal stable intervals of [lo, hi] cut at the boundaries ``cuts``, each piece
    decided at its midpoint by ``stable_at(midpoints)`` (an array of bools)."""
    cuts = sorted({lo, hi, *(c for c in cuts if lo < c < hi)})
    mids = np.array([(a + b) / 2 for a, b in zip(cuts[:-1], cuts[1:], strict=True)])
    stable_mid = stable_at(mids) if mids.size else np.zeros(0, bool)
    intervals: list[tuple[float, float]] = []
    for (a, b), ok in zip(zip(cuts[:-1], cuts[1:], strict=True), stable_mid, strict=True):
        if not ok:
            continue
        if intervals and intervals[-1][1] == a:
            intervals[-1] = (intervals[-1][0], b)
        else:
            intervals.append((a, b))
    return intervals


def pure_scan(
    lam_range, n: int, amplitude: float = 1.0, *, rtol: float = DEFAULT_RTOL
) -> StabilityScan:
    """:func:`scan` of y'' + Lam x^(2n) y = 0 over ``lam_range`` = (LO, HI, COUNT), as
    :func:`pure_hill` is its chart at given Lams (``floquet --lam-range``).

    Examples
    --------
    >>> [(round(a, 9), round(b, 9)) for a, b in pure_scan((0.0, 3.0, 31), 1).stable_intervals]
    [(0.0, 1.316022911)]
    """
    return scan(pure_problem(n, amplitude, rtol=rtol), *_grid("lam_range", lam_range))


def model_scan(
    alpha: float,
    beta_range,
    n: int,
    *,
    gamma: float = 1.0,
    shape: str = "flat",
    amplitude: float = 1.0,
    rtol: float = DEFAULT_RTOL,
) -> StabilityScan:
    """:func:`scan` of the model's Hill equation over ``beta_range`` = (LO, HI, COUNT), as
    :func:`model_hill` is its chart at given betas (``floquet --beta-range``).

    Examples
    --------
    >>> s = model_scan(0.5, (-0.4, 0.2, 7), 10)  # beta = 0 is lambda = 0, a boundary
    >>> [(round(a, 12), round(b, 12)) for a, b in s.stable_intervals]
    [(-0.4, 0.0)]
    """
    problem = model_problem(alpha, n, gamma=gamma, shape=shape, amplitude=amplitude, rtol=rtol)
    return scan(problem, *_grid("beta_range", beta_range))


def _grid(name: str, grid) -> tuple:
    """(LO, HI, COUNT) of a range, refused naming ``name`` unless it is three values."""
    try:
        lo, hi, count = grid
    except (TypeError, ValueError):
        raise ParameterError(name, grid, "three values LO, HI, COUNT") from None
    return lo, hi, count


def rigid_limit_phi_half(lam, amplitude: float = 1.0) -> np.ndarray:
    """phi_half of the rigid-wall limit n -> oo: 1 - 2 Lam A0^2 (see the module docstring).

    Examples
    --------
    >>> rigid_limit_phi_half([0.0, 0.5, 1.0]).tolist()
    [1.0, 0.0, -1.0]
    """
    a = v.positive("amplitude", amplitude)
    lam = v.finite_array("lam", lam)
    with np.errstate(over="ignore"):
        out = 1.0 - 2.0 * lam * a * a
    if not np.all(np.isfinite(out)):
        raise ParameterError("amplitude", amplitude, "an amplitude with 2 lam A0^2 finite")
    return out


# ----------------------------------------------------------------- one sweep point
#: What a ``floquet`` sweep stores per point (the chart's quantities at one beta; "lam"
#: is the chart's "lambda").
POINT_QUANTITIES = ("lam", "phi_half", "phi", "stable", "log_abs_phi_half", "rotation_number",
                    "floquet_exponent")  # fmt: skip


def check_point(p: dict) -> None:
    """Check a ``floquet`` sweep point (alpha, beta, n, gamma, shape, amplitude, rtol)
    with the model's own validators; a user's well's point (``well``, its text, and its
    parameters' values) is checked as :func:`well_hill` checks it: y = 0 invariant, or a
    ParameterError with the reason."""
    if "well" in p:
        well, values = _point_well(p)
        v.positive("amplitude", p["amplitude"])
        v.positive("rtol", p["rtol"])
        well_hill(well, values)
        return
    model_problem(
        p["alpha"],
        p["n"],
        gamma=p["gamma"],
        shape=p["shape"],
        amplitude=p["amplitude"],
        rtol=p["rtol"],
    ).check([p["beta"]])


def point(p: dict, seed: int) -> dict:
    """The :data:`POINT_QUANTITIES` of :func:`model_hill` at the point's one beta (the
    seed is not used: the chart is deterministic); of a user's well, :func:`_well_point`."""
    if "well" in p:
        return _well_point(*_point_well(p), p["amplitude"], p["rtol"])
    c = model_hill(
        p["alpha"],
        [p["beta"]],
        p["n"],
        gamma=p["gamma"],
        shape=p["shape"],
        amplitude=p["amplitude"],
        rtol=p["rtol"],
    )
    items = c.items()  # the chart's quantities (sinktheory.results protocol)
    return {name: items["lambda" if name == "lam" else name][0] for name in POINT_QUANTITIES}


def _point_well(p: dict):
    """(the user's well of a sweep point, its parameters' values by name)."""
    from .ensemble import well_of_text

    well = well_of_text(p["well"])
    return well, {name: p[name] for name in well.parameter_names if name in p}


def _well_point(well, values: dict, amplitude: float, rtol: float) -> dict:
    """The :data:`POINT_QUANTITIES` of a user's well at ``amplitude``
    (:func:`well_floquet`): lam is NaN (Hill's lambda of the paper's wells); phi_half, its
    log and the rotation number arccos(phi_half)/pi are NaN unless V is even in x (no
    half-period map); the Floquet exponent is the growth per period over the orbit's
    period for mass 1.  The rotation number is :func:`rotation_number` of the
    cancellation-free factors, as for the registered charts."""
    f = well_floquet(well, amplitude, values, rtol=rtol)
    half = f.phi_half
    with np.errstate(divide="ignore", invalid="ignore"):
        log_half = float(np.log(abs(half)))
    rotation = f.rotation_number
    return {
        "lam": math.nan,
        "phi_half": half,
        "phi": f.phi,
        "stable": bool(f.stable),
        "log_abs_phi_half": log_half,
        "rotation_number": rotation,
        "floquet_exponent": f.growth_per_period / f.period,
    }


# ----------------------------------------------------------------- a user's well
#: Per-step relative tolerance of :func:`well_floquet`'s integration.
WELL_RTOL = 1e-13
#: Points of the check that V(x, 0) grows from the centre to the amplitude.
_AXIS_POINTS = 1024


@dataclass(frozen=True)
class WellFloquet(Result):
    """Floquet data of the normal mode y = 0 of a user's well at one amplitude
    (:func:`well_floquet`).

    Attributes
    ----------
    name : the well's name
    parameters : its parameter values by name
    amplitude : A, the turning point x = A > 0 of the orbit on y = 0 (started at rest)
    particle_energy : V(A, 0) - V(0, 0)
    period : T of the orbit, for mass 1 (x'' = -dV/dx; a mass mu multiplies it by sqrt(mu)
        and changes no multiplier)
    hill_coefficient : q(x) = V_yy(x, 0), as text
    symmetric : V(x, 0) and q even in x (symbolic): the quarter-period formulas hold
    phi_half : half trace of M(T/2) (symmetric wells; NaN otherwise)
    phi_half_minus_one, phi_half_plus_one : phi_half - 1 = 2 y2 y1' and phi_half + 1 =
        2 y1 y2' at the quarter period, free of cancellation (symmetric wells; NaN
        otherwise)
    phi : half trace of M(T)
    stable : abs(phi_half) < 1 (symmetric), abs(phi) < 1 (otherwise), decided from the
        signs of the factors: y2 y1' < 0 < y1 y2'
    multipliers : rho_1, rho_2 over T (complex), exp(+-2 pi i rotation number) where stable,
        +-exp(+-growth) otherwise, by the registered charts' formula
        (:attr:`FloquetChart.multipliers`)
    growth_per_period : ln of the largest abs(rho) (0 where stable): 2 arccosh abs(phi_half)
        (symmetric) or arccosh abs(phi), from the factors as
        :attr:`FloquetChart.growth_per_period`

    Near abs(phi_half) = 1 (abs(phi) = 1) each of these comes from the factors without
    cancellation, so the multipliers' distance from 1 keeps the integration's relative
    accuracy instead of losing half the digits in sqrt(phi^2 - 1).
    """

    name: str
    parameters: dict
    amplitude: float
    particle_energy: float
    period: float
    hill_coefficient: str
    symmetric: bool
    phi_half: float
    phi_half_minus_one: float
    phi_half_plus_one: float
    phi: float
    stable: bool
    multipliers: np.ndarray
    growth_per_period: float

    @property
    def rotation_number(self) -> float:
        """arccos(phi_half)/pi (:func:`rotation_number`, accurate near abs(phi_half) = 1;
        NaN unless the well is symmetric)."""
        return float(rotation_number(self.phi_half, self.phi_half_minus_one,
                                     self.phi_half_plus_one))  # fmt: skip

    DIMS = {"multipliers": ("multiplier",)}

    def items(self) -> dict:
        """The fields and the rotation number."""
        return {**super().items(), "rotation_number": self.rotation_number}


def _even(expr) -> bool:
    """expr(-x) == expr(x) identically (SymPy)."""
    import sympy as sp

    from .symbolic import x

    return sp.simplify(expr.subs(x, -x) - expr) == 0


def well_floquet(
    well, amplitude: float, values=None, *, well_check=None, rtol: float = WELL_RTOL
) -> WellFloquet:
    """Floquet multipliers of the normal mode y = 0 of a user's well (a
    :class:`~sinktheory.userwell.UserWell` at its parameter ``values`` by name, defaults for
    the others; ``well_check``: its :func:`~sinktheory.userwell.check_well` there, if run)
    on the orbit with turning point x = ``amplitude`` (module docstring):
    ``well_hill(...).at(amplitude)``.

    Raises
    ------
    ParameterError
        y = 0 is not invariant (the reason is given), or the amplitude is not > 0, or its
        orbit does not stay in the basin (V(x, 0) must grow from the centre to it, below
        the escape energy); a refused well (WellDefinitionError).
    NumericalError
        The integration failed or the solutions left float range.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> ellipse = UserWell("ellipse", "(x**2 + 0.64*y**2)/2", {})  # x = A cos t
    >>> f = well_floquet(ellipse, 0.5)  # y'' + 0.64 y = 0: phi_half = cos(0.8 pi)
    >>> f.symmetric, round(f.phi_half, 10), round(math.cos(0.8 * math.pi), 10), f.stable
    (True, -0.8090169944, -0.8090169944, True)
    """
    return well_hill(well, values, well_check=well_check, rtol=rtol).at(amplitude)


def well_hill(well, values=None, *, well_check=None, rtol: float = WELL_RTOL) -> WellHill:
    """The :class:`WellHill` of a user's well: checked, y = 0 decided invariant (else a
    ParameterError with the reason), its symmetry decided, ready to be evaluated at
    amplitudes (arguments as :func:`well_floquet`)."""
    import sympy as sp

    from .symbolic import mu, normal_mode, y
    from .userwell import UserWell, well_report

    if not isinstance(well, UserWell):
        raise ParameterError("well", well, "a sinktheory.userwell.UserWell")
    given, report = well_report(well, values, well_check)
    exact = well.values(**given)
    mode = normal_mode(well, exact)
    if not mode.invariant:
        raise ParameterError(
            "well", well.name, "a well whose line y = 0 is invariant, for Floquet multipliers",
            why=mode.reason,
        )  # fmt: skip
    on_axis = well.potential.subs(exact).subs(y, 0)
    q = sp.simplify(mode.hill_coefficient.subs(exact) * mu)
    return WellHill(
        name=well.name,
        parameters={k.name: float(val) for k, val in exact.items()},
        basin=report.basin,
        hill_coefficient=str(q),
        symmetric=_even(on_axis) and _even(q),
        rtol=v.positive("rtol", rtol),
    )


@dataclass(frozen=True)
class WellHill:
    """Hill's equation on the normal mode y = 0 of a user's well, as a family in the
    amplitude (:func:`well_hill`; fields as in :class:`WellFloquet`, ``basin`` the well's
    :class:`~sinktheory.basin.Basin`)."""

    name: str
    parameters: dict
    basin: object
    hill_coefficient: str
    symmetric: bool
    rtol: float

    def _factors(self, amplitude) -> tuple[float, ...]:
        """(A, energy, time to the event, y1, y1', y2, y2' there) for a checked A."""
        from scipy.integrate import solve_ivp

        from .errors import NumericalError

        a = v.positive("amplitude", amplitude)
        well = self.basin.well
        xs = np.linspace(0.0, a, _AXIS_POINTS + 1)
        axis = well.f(xs, np.zeros_like(xs)) - well.v0
        energy = float(axis[-1])
        if not (np.all(np.diff(axis) > 0) and energy < self.basin.escape_energy):
            raise ParameterError(
                "amplitude", a, f"a turning point of an orbit on y = 0 inside the basin of "
                f"the {self.name} well (V(x, 0) growing from the centre to it, below the "
                f"escape energy {self.basin.escape_energy:.6g})",
                why=f"V(A, 0) - V(0, 0) = {energy:.6g}",
            )  # fmt: skip

        def rhs(t, s):
            gx = well._gradient(s[0], 0.0)[0]
            qx = well._hessian(s[0], 0.0)[1, 1]
            return [s[1], -gx, s[3], -qx * s[2], s[5], -qx * s[4]]

        if self.symmetric:  # x = 0: a quarter period

            def event(t, s):
                return s[0]

            event.direction = -1.0
        else:  # x' = 0 again: the other turning point, half a period

            def event(t, s):
                return s[1]

            event.direction = 1.0
        event.terminal = True
        start = [a, 0.0, 1.0, 0.0, 0.0, 1.0]
        # a bound of the time to the event: 1000 times the flight over 2 A at the speed
        # sqrt(2 e) of the centre (a power-law well takes less than 1.6 flights over A)
        horizon = 2e3 * a / math.sqrt(2.0 * energy)
        kwargs = dict(method="DOP853", rtol=self.rtol, atol=self.rtol * 1e-3)
        first = solve_ivp(rhs, (0.0, horizon), start, events=event, **kwargs)
        where = f"Floquet of the {self.name} well at amplitude {a:g}"
        if first.status != 1:
            raise NumericalError(
                f"{where}: the orbit on y = 0 did not reach "
                f"{'x = 0' if self.symmetric else 'its other turning point'} by t = "
                f"{horizon:.6g} ({first.message})"
            )
        t_event = float(first.t_events[0][0])
        # integrated again to that time, so that the last step ends on it (no interpolation)
        end = solve_ivp(rhs, (0.0, t_event), start, **kwargs).y[:, -1]
        if not np.all(np.isfinite(end)):
            raise NumericalError(f"{where}: the solutions left float range")
        return (a, energy, t_event, *(float(f) for f in end[2:]))

    def factor(self, name: str):
        """The factor ``name`` (one of :data:`BOUNDARY_FACTORS`: y1, dy1, y2, dy2 at the
        quarter period, or at the half period without symmetry) as a function of the
        amplitude: its zeros are the boundaries of stability."""
        k = 3 + _FACTOR_ORDER.index(v.choice("name", name, _FACTOR_ORDER))
        return lambda amplitude: self._factors(amplitude)[k]

    def at(self, amplitude: float) -> WellFloquet:
        """The :class:`WellFloquet` at ``amplitude``."""
        return self._floquet(*self._factors(amplitude))

    def _floquet(self, a, energy, t_event, y1, dy1, y2, dy2) -> WellFloquet:
        """The :class:`WellFloquet` of :meth:`_factors`'s values.  At the event (x = 0, or
        the other turning point) the half trace c of the map there and back is
        y1 y2' + y2 y1', and by the Wronskian y1 y2' - y2 y1' = 1, c - 1 = 2 y2 y1' and
        c + 1 = 2 y1 y2' (module docstring): c is phi_half with symmetry (the multipliers
        over T are the squares of those over T/2), phi without."""
        trace = y1 * dy2 + y2 * dy1
        minus, plus = 2.0 * y2 * dy1, 2.0 * y1 * dy2
        stable = bool(y2 * dy1 < 0 < y1 * dy2)
        with np.errstate(divide="ignore"):
            growth = float(_arccosh_abs(minus, plus, np.log(abs(trace))))
        rotation = float(rotation_number(trace, minus, plus))  # arccos(c)/pi
        if self.symmetric:
            phi_half, phi, period = trace, 2.0 * trace * trace - 1.0, 4.0 * t_event
            growth *= 2.0
            multipliers = _multipliers(rotation, growth, stable)
        else:  # theta_T = arccos(phi) = pi rotation, the multipliers' sign that of phi
            phi_half, phi, period = math.nan, trace, 2.0 * t_event
            multipliers = _multipliers(rotation / 2, growth, stable, math.copysign(1.0, phi))
            minus = plus = math.nan
        return WellFloquet(
            name=self.name,
            parameters=self.parameters,
            amplitude=a,
            particle_energy=energy,
            period=period,
            hill_coefficient=self.hill_coefficient,
            symmetric=self.symmetric,
            phi_half=phi_half,
            phi_half_minus_one=minus,
            phi_half_plus_one=plus,
            phi=phi,
            stable=stable,
            multipliers=multipliers,
            growth_per_period=growth,
        )


@dataclass(frozen=True)
class WellScan(Result):
    """A chart of a user's well's Floquet data over the amplitude (:func:`well_scan`).

    Attributes
    ----------
    name, parameters, symmetric : as in :class:`WellFloquet`
    amplitude : the grid of amplitudes A
    trace : phi_half (symmetric wells) or phi at each A
    stable : at each A
    boundaries : list of :class:`Boundary`, the zeros of the factors y1, y1', y2, y2'
        (:meth:`WellHill.factor`) located by brentq to :data:`ROOT_XTOL`, each with the
        factor and the trace's value there (+1 or -1)
    stable_intervals : maximal stable intervals of the range (an end equal to the range's
        end is not a boundary)
    """

    name: str
    parameters: dict
    symmetric: bool
    amplitude: np.ndarray
    trace: np.ndarray
    stable: np.ndarray
    boundaries: list
    stable_intervals: list

    DIMS = {"amplitude": ("amplitude",), "trace": ("amplitude",), "stable": ("amplitude",)}


def well_scan(hill: WellHill, amplitude_range) -> WellScan:
    """The Floquet chart of ``hill`` (:func:`well_hill`) on COUNT amplitudes over [LO, HI]
    (``amplitude_range`` = (LO, HI, COUNT), as ``floquet --amplitude-range``), with the
    stability boundaries between them located as :func:`scan` locates them: each sign
    change of y1, y1', y2 or y2' at the quarter period (at the half period without
    symmetry) between neighbouring grid points is refined by brentq, which finds the edges
    of a gap narrower than the grid, and of a closed one, to the factors' accuracy (two
    zeros of one factor within one cell are missed).

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> tilted = well_hill(UserWell("tilted", "(x**2 + 1.2*y**2)/2 + 0.3*x*y**2", {}))
    >>> chart = well_scan(tilted, (0.5, 1.5, 5))  # y'' + (1.2 + 0.6 A cos t) y = 0
    >>> [(round(a, 6), round(b, 6)) for a, b in chart.stable_intervals]
    [(0.5, 1.303935)]
    """
    if not isinstance(hill, WellHill):
        raise ParameterError("hill", hill, "a WellHill (from well_hill)")
    lo, hi, count = _grid("amplitude_range", amplitude_range)
    lo, hi = v.positive("lo", lo), v.finite("hi", hi)
    count = v.positive_int("count", count, minimum=2, maximum=10_000)
    if not lo < hi:
        raise ParameterError("hi", hi, f"> lo = {lo!r}")
    grid = np.linspace(lo, hi, count)
    values = [hill._factors(a) for a in grid]
    points = [hill._floquet(*row) for row in values]
    trace = np.array([p.phi_half if hill.symmetric else p.phi for p in points])
    table = {name: np.array([row[3 + k] for row in values])
             for k, name in enumerate(_FACTOR_ORDER)}  # fmt: skip
    boundaries = _factor_boundaries(
        grid, table.__getitem__, hill.factor, "Q" if hill.symmetric else "T/2"
    )
    intervals = _stable_intervals(
        lo, hi, [b.value for b in boundaries], lambda mids: [hill.at(m).stable for m in mids]
    )
    return WellScan(
        hill.name, hill.parameters, hill.symmetric, grid, trace,
        np.array([p.stable for p in points]), boundaries, intervals,
    )  # fmt: skip
