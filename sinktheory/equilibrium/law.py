"""The exact equilibrium law of the container energy E_c on the energy shell H = E.

In the separable coordinates (X, x_j = u_j - X) the Hamiltonian is the container
oscillator P^2/2 + X^2/2 plus k independent particles p_j^2/(2 mu) + V(x_j, y_j), and
the shift u_j -> x_j has Jacobian 1 (derivations/equilibrium.py).  On the shell the
microcanonical measure gives E_c the density

    rho(E_c) = G_k(E - E_c) / \\int_0^E G_k(e) de,

where the container's own density of states (2 pi, a constant) has cancelled and G_k is
the k-fold convolution of one particle's density of states g(e) = 2 pi mu A(e)
(:mod:`sinktheory.equilibrium.area`).  Constant factors cancel too: the law depends on
the well, k and E, not on the particles' mass.

Representation
--------------
Every shape has A(e) = t F(t) with t = (2 n e / gamma)^(1/n) and F smooth (constant for a
homogeneous well), so, with u = (e / E)^(1/n) in [0, 1],

    G_j(e) = e^(b_j - 1) exp(h_j(u)),     b_j = j (1 + 1/n),

where h_j is smooth in u.  h_1 = log F(t_E u) (up to a constant) and each convolution
G_a * G_b is computed at the Chebyshev points in u of h_(a+b): the integral over x in
(0, e) is split at e/2, and on each half the substitution x = e w^n (or e - x = e w^n)
leaves a smooth integrand times an integer power of w, integrated by Gauss-Legendre on
panels graded towards both ends.  h_(a+b) is then a Chebyshev series whose degree is
doubled until its trailing coefficients fall below :data:`CHEB_TOL`.  G_k comes from
binary powering (log2 k convolutions).  For a homogeneous well h_k is constant and the
law is exactly Beta(1, k (1 + 1/n)) in s = E_c / E.

The law's quantities are integrals of the same kind:

    P(E_c >= f E) = (1 - f)^(b_k) I(p, (1 - f)^(1/n)) / I(p, 1),
    I(p, a) = \\int_0^1 w^p exp(h_k(a w)) dw,  p = n b_k - 1 = k (n + 1) - 1,

and <E_c> / E = \\int_0^1 (1 - w^n) w^p exp(h_k(w)) dw / I(p, 1).

A user's well (:func:`well_law`) goes through the same computation: A(e) is the ray
quadrature over its basin (:class:`~sinktheory.equilibrium.area.WellArea`), energies
measured from V(0, 0), and n is half the degree of the leading term of V at the centre
(:func:`sinktheory.basin.leading_order`), so that A(e) / e^(1/n) is again smooth in
u = (e / E)^(1/n) -- exactly constant for an elliptic well, whose law is Beta(1, b_k).

Examples
--------
>>> from sinktheory.model import Sink, Well
>>> law = equilibrium_law(Sink(Well(0.5, 0.0, 4), particles=2), total_energy=0.5)
>>> round(law.mean_fraction * (1 + 2 * (1 + 1 / 4)), 12)  # Beta(1, 2.5): mean 1/3.5
1.0
>>> round(law.tail(0.5), 12) == round(0.5**2.5, 12)
True
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from numpy.polynomial import chebyshev as C

from .. import validation as v
from ..errors import NumericalError, ParameterError
from ..glossary import old_attribute, renamed
from ..model import Sink
from ..results import Result
from ..sinkstats import equipartition_container_energy
from ..twins import python_kernel
from .area import WellArea, area_ratio, scaled_energy

__all__ = [
    "CHEB_DEGREES",
    "CHEB_TOL",
    "check_fractions",
    "equilibrium_law",
    "EquilibriumLaw",
    "EquilibriumSummary",
    "FRACTIONS",
    "LEVELS",
    "PANEL_NODES",
    "well_law",
]

#: Largest trailing Chebyshev coefficient of a log density h_j accepted (absolute: an
#: error delta in h is a relative error delta in the density).
CHEB_TOL = 1e-12
#: Degrees tried for a Chebyshev series of h_j (doubling).
CHEB_DEGREES = (16, 32, 64, 128)
#: Gauss-Legendre nodes per panel.
PANEL_NODES = 20
#: Default fractions f of the total energy for the tail table, and quantile levels.
FRACTIONS = (0.1, 0.2, 0.3, 0.5, 0.8)
LEVELS = (0.05, 0.25, 0.5, 0.75, 0.95)
#: Most points of the summary's curves (each point one density and one tail).
MAX_POINTS = 100_000


def _panels(steepness: float) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on [0, 1], panels halving towards both ends down to
    a width below 1 / (8 steepness) (an integrand varying on that scale near an end)."""
    halvings = max(2, math.ceil(math.log2(8 * max(steepness, 1.0))))
    inner = [2.0**-i for i in range(halvings, 0, -1)]
    edges = np.array([0.0, *inner, *[1 - s for s in reversed(inner[:-1])], 1.0])
    x, w = np.polynomial.legendre.leggauss(PANEL_NODES)
    lo, hi = edges[:-1, None], edges[1:, None]
    nodes = (0.5 * (hi - lo) * (x + 1) + lo).ravel()
    weights = (0.5 * (hi - lo) * w).ravel()
    return nodes, weights


def _logsumexp(a: np.ndarray, axis: int = -1) -> np.ndarray:
    top = np.max(a, axis=axis, keepdims=True)
    return np.squeeze(top, axis=axis) + np.log(np.sum(np.exp(a - top), axis=axis))


@dataclass(frozen=True)
class _Density:
    """G(e) = e^(b - 1) exp(h(u)), u = (e / E)^(1/n), h a Chebyshev series on [0, 1]
    (up to a constant factor, which cancels from the law)."""

    b: float
    h: C.Chebyshev


def _interpolate(func, what: str) -> C.Chebyshev:
    for deg in CHEB_DEGREES:
        series = C.Chebyshev.interpolate(func, deg, domain=[0.0, 1.0])
        if np.max(np.abs(series.coef[-3:])) <= CHEB_TOL:
            return series.trim(CHEB_TOL / 10)
    trailing = np.max(np.abs(series.coef[-3:]))
    raise NumericalError(
        f"equilibrium law: the Chebyshev series of {what} did not converge to {CHEB_TOL:g} "
        f"with degree {CHEB_DEGREES[-1]} (trailing coefficient {trailing:.3g})"
    )


def _convolve(f: _Density, g: _Density, n: int) -> _Density:
    """f * g, with the exponents b of both multiples of 1/n (module docstring).

    The result's h is normalised to h(0) = 0: the weights of the quadrature (powers of w,
    of 1 - w^n, and the Gauss weights) are the same at every u and are normalised once,
    so their rounding (terms of size n b) is a common factor that cancels from the law,
    instead of noise that would differ from one Chebyshev point to the next.
    """
    w0 = 2.0 ** (-1.0 / n)
    omega, weights = _panels(n * max(f.b, g.b))
    w = w0 * omega
    log_w = np.log(w)
    rest = np.log1p(-(w**n)) / n  # log of (1 - w^n)^(1/n)
    base = np.log(w0 * weights)
    # x = e w^n on [0, e/2]: n w^(n b1 - 1) (1 - w^n)^(b2 - 1) H1(u w) H2(u (1 - w^n)^(1/n))
    pairs = ((f, g), (g, f))
    log_weights = np.concatenate(
        [(n * a.b - 1) * log_w + n * (b.b - 1) * rest + base for a, b in pairs]
    )
    weights_all = np.exp(log_weights - log_weights.max())
    weights_all /= weights_all.sum()
    h0 = f.h(0.0) + g.h(0.0)

    def h(u: np.ndarray) -> np.ndarray:
        u = u[:, None]
        both = np.concatenate([a.h(u * w) + b.h(u * np.exp(rest)) - h0 for a, b in pairs], axis=1)
        return np.log(np.sum(weights_all * np.exp(both), axis=1))

    b = f.b + g.b
    return _Density(b, _interpolate(h, f"G_j with b = {b:.6g}"))


def _log_integral(density: _Density, n: int) -> float:
    """log of \\int_0^1 w^(n b - 1) exp(h(w)) dw: the normalisation of the density of s."""
    p = n * density.b - 1
    w, weights = _panels(p)
    return float(_logsumexp(p * np.log(w) + np.log(weights) + density.h(w)))


def _moments(density: _Density, n: int, scales) -> np.ndarray:
    """\\int_0^1 w^(n b - 1) (1 - w^n)^j exp(h(a w)) dw over \\int_0^1 w^(n b - 1) exp(h(w)) dw,
    for each (a, j) in ``scales`` (the ratios the law needs; common rounding cancels)."""
    p = n * density.b - 1
    w, weights = _panels(p)
    log_weights = p * np.log(w) + np.log(weights)
    weights = np.exp(log_weights - log_weights.max())
    ref = density.h(w)
    top = ref.max()
    norm = np.sum(weights * np.exp(ref - top))
    out = []
    for a, j in scales:
        terms = density.h(a * w) - top
        if j:
            terms = terms + j * np.log1p(-(w**n))
        out.append(np.sum(weights * np.exp(terms)) / norm)
    return np.array(out)


@renamed(energy="total_energy")
@dataclass(frozen=True)
class EquilibriumLaw(Result):
    """The law of the container energy E_c on the shell H = E (module docstring).

    Attributes
    ----------
    shape, alpha, beta, n, gamma : the well (a user's well, :func:`well_law`: its name,
        NaN, n half the degree of V's leading term at the centre, which may be a
        half-integer, and NaN)
    particles : k
    total_energy : the total energy E
    exponent : b_k = k (1 + 1/n): the law is Beta(1, b_k) in E_c / E for a homogeneous well
    mean : <E_c>
    mean_fraction : <E_c> / E
    homogeneous_mean : E / (1 + k (1 + 1/n)), the estimate of
        :func:`~sinktheory.sinkstats.equipartition_container_energy`
    log_density : Chebyshev coefficients of h_k on u in [0, 1] (G_k = e^(b_k - 1) exp h_k)
    parameters : a user's well's parameter values by name (empty for a registered shape)

    Methods give the density, distribution function, tail and quantiles of s = E_c / E.
    """

    shape: str
    alpha: float
    beta: float
    n: int
    gamma: float
    particles: int
    total_energy: float
    exponent: float
    mean: float
    mean_fraction: float
    homogeneous_mean: float
    log_density: np.ndarray = field(repr=False)
    parameters: dict = field(default_factory=dict)

    DIMS = {"log_density": ("coefficient",)}

    energy = old_attribute("total_energy")

    @property
    def _density(self) -> _Density:
        return _Density(self.exponent, C.Chebyshev(self.log_density, domain=[0.0, 1.0]))

    @property
    def _log_norm(self) -> float:
        return _log_integral(self._density, self.n)

    def pdf(self, s) -> np.ndarray:
        """Density of s = E_c / E at s in [0, 1] (0 outside).

        Examples
        --------
        >>> from sinktheory.model import Sink, Well
        >>> law = equilibrium_law(Sink(Well(0.5, 0.0, 2, shape="circular")), 1.0)
        >>> law.pdf([0.0, 1.0]).round(12).tolist()  # Beta(1, 1.5): 1.5 (1 - s)^0.5
        [1.5, 0.0]
        """
        s = v.real_array("s", s)
        if not np.all(np.isfinite(s)):
            raise ParameterError("s", s.tolist(), "finite numbers (0 outside [0, 1])")
        inside = (s >= 0) & (s < 1)
        r = np.where(inside, 1 - s, 0.5)
        log = (self.exponent - 1) * np.log(r) + self._density.h(r ** (1 / self.n))
        out = np.exp(log - self._log_norm - math.log(self.n))
        return np.where(inside, out, 0.0)

    def tail(self, f) -> np.ndarray | float:
        """P(E_c >= f E) for fractions f in [0, 1] (0.0 where it is below float range:
        :meth:`log_tail` gives it).

        Examples
        --------
        >>> from sinktheory.model import Sink, Well
        >>> law = equilibrium_law(Sink(Well(0.5, 0.0, 4), particles=1), 0.5)
        >>> round(float(law.tail(0.8)), 12) == round(0.2**1.25, 12)
        True
        """
        out = np.exp(self.log_tail(f))
        return float(out) if np.ndim(out) == 0 else out

    def log_tail(self, f) -> np.ndarray | float:
        """log P(E_c >= f E) for fractions f in [0, 1] (-inf at f = 1): finite where the
        tail itself underflows (many particles, 0.5^1250 at k = 1000, n = 4).

        Examples
        --------
        >>> from sinktheory.model import Sink, Well
        >>> law = equilibrium_law(Sink(Well(0.5, 0.0, 4), particles=1000), 0.5)
        >>> round(float(law.log_tail(0.5)) / math.log(0.5), 9)  # Beta(1, 1250)
        1250.0
        """
        fs = v.real_array("fraction", f)
        if np.any(~((fs >= 0) & (fs <= 1))):
            raise ParameterError("fraction", f, "numbers in [0, 1]")
        flat = fs.ravel()
        ratios = _moments(self._density, self.n, [((1 - x) ** (1 / self.n), 0) for x in flat])
        with np.errstate(divide="ignore"):  # log 0 = -inf at f = 1
            out = (self.exponent * np.log1p(-flat) + np.log(ratios)).reshape(fs.shape)
        return float(out) if out.ndim == 0 else out

    def cdf(self, s) -> np.ndarray | float:
        """P(E_c / E <= s)."""
        s = v.real_array("s", s)
        if np.isnan(s).any():
            raise ParameterError("s", s.tolist(), "numbers (NaN has no probability)")
        return 1.0 - self.tail(np.clip(s, 0.0, 1.0))

    def quantile(self, level) -> np.ndarray | float:
        """s with P(E_c / E <= s) = level, for levels in (0, 1) (bisection on the tail to
        1e-14).

        Examples
        --------
        >>> from sinktheory.model import Sink, Well
        >>> law = equilibrium_law(Sink(Well(0.5, 0.0, 1), particles=1), 0.5)  # Beta(1, 2)
        >>> round(float(law.quantile(0.75)), 10)  # 1 - (1 - 0.75)^(1/2)
        0.5
        """
        levels = v.real_array("level", level)
        if np.any(~((levels > 0) & (levels < 1))):
            raise ParameterError("level", level, "numbers in (0, 1)")
        out = []
        for p in levels.ravel():
            lo, hi = 0.0, 1.0
            while hi - lo > 1e-14:
                mid = 0.5 * (lo + hi)
                if self.tail(mid) > 1 - p:
                    lo = mid
                else:
                    hi = mid
            out.append(0.5 * (lo + hi))
        arr = np.array(out).reshape(levels.shape)
        return float(arr) if arr.ndim == 0 else arr

    def kac_periods(self, f) -> np.ndarray | float:
        """Kac's mean return time, in periods T, of the period-sampled motion to the set
        {E_c >= f E}: 1 / P(E_c >= f E) (see :mod:`sinktheory.equilibrium.lifetime`), for
        fractions f in (0, 1).  NumericalError when it exceeds float range
        (:meth:`log10_kac_periods` gives it)."""
        logs = self.log10_kac_periods(f)
        if np.any(logs >= math.log10(np.finfo(float).max)):
            raise NumericalError(
                f"equilibrium law: Kac's return time to E_c >= f E reaches 10^"
                f"{np.max(logs):.1f} periods at f = {f}, beyond float range "
                "(log10_kac_periods gives it)"
            )
        return 1.0 / self.tail(f)

    def log10_kac_periods(self, f) -> np.ndarray | float:
        """log10 of Kac's mean return time (periods) to {E_c >= f E}, f in (0, 1)."""
        fs = check_fractions(f, name="f")
        out = -self.log_tail(fs) / math.log(10)
        return float(out[0]) if np.ndim(f) == 0 else out.reshape(np.shape(f))

    def summary(self, fractions=FRACTIONS, levels=LEVELS, points: int = 201) -> EquilibriumSummary:
        """The law's tables (tails, Kac return times, quantiles) and curves on a grid of
        ``points`` values of s (at most :data:`MAX_POINTS`).

        Examples
        --------
        >>> from sinktheory.model import Sink, Well
        >>> law = equilibrium_law(Sink(Well(0.5, 0.3, 4), particles=1), 0.5)
        >>> s = law.summary(fractions=[0.5])
        >>> s.fractions.tolist(), bool(abs(s.kac_periods[0] * s.tails[0] - 1) < 1e-15)
        ([0.5], True)
        """
        fractions = check_fractions(fractions)
        levels = v.real_array("level", levels)
        points = v.positive_int("points", points, minimum=2, maximum=MAX_POINTS)
        grid = np.linspace(0.0, 1.0, points)
        tails = np.atleast_1d(self.tail(fractions))
        with np.errstate(over="ignore", divide="ignore"):  # beyond float range: inf, and
            kac = 1.0 / tails  # log10_kac_periods gives it
        return EquilibriumSummary(
            law=self,
            fractions=fractions,
            tails=tails,
            kac_periods=kac,
            log10_kac_periods=np.atleast_1d(self.log10_kac_periods(fractions)),
            levels=levels,
            quantiles=np.atleast_1d(self.quantile(levels)) * self.total_energy,
            s=grid,
            pdf=self.pdf(grid),
            cdf=np.atleast_1d(self.cdf(grid)),
        )


def check_fractions(fractions, name: str = "fractions") -> np.ndarray:
    """Fractions f as a 1-D array, each in the open interval (0, 1) (ParameterError naming
    ``name`` otherwise)."""
    fs = np.atleast_1d(v.real_array(name, fractions)).ravel()
    if not fs.size:
        raise ParameterError(name, fractions, "one or more numbers in (0, 1)")
    for f in fs:
        if not (0 < f < 1):
            raise ParameterError(name, float(f), "each a number in (0, 1)")
    return fs


@dataclass(frozen=True)
class EquilibriumSummary(Result):
    """What ``sinktheory equilibrium`` prints: the law, its tails P(E_c >= f E) and Kac
    return times 1/P (periods) at ``fractions`` (with their log10, finite where the time
    exceeds float range and is inf), its quantiles (energies) at ``levels``,
    and its density and distribution function of s = E_c / E on the grid ``s``."""

    law: EquilibriumLaw
    fractions: np.ndarray
    tails: np.ndarray
    kac_periods: np.ndarray
    log10_kac_periods: np.ndarray
    levels: np.ndarray
    quantiles: np.ndarray
    s: np.ndarray
    pdf: np.ndarray
    cdf: np.ndarray

    DIMS = {
        "fractions": ("fraction",),
        "tails": ("fraction",),
        "kac_periods": ("fraction",),
        "log10_kac_periods": ("fraction",),
        "levels": ("level",),
        "quantiles": ("level",),
        "pdf": ("s",),
        "cdf": ("s",),
    }
    COORDS = {"fractions": "fraction", "levels": "level"}


def _near_escape(e: float, escape: float, what: str, error: NumericalError) -> Exception:
    """The error to raise when the one-particle series failed at total energy ``e`` below
    the escape energy ``escape`` (``what`` says what it is): there the basin's area is
    singular (at a saddle its derivative grows like log(E_s - e)) and no series of degree
    128 converges, so a ParameterError naming the total energy."""
    return ParameterError(
        "total_energy", e, f"< {escape:.6g}, {what}, and far enough below it for the law's "
        "series to converge",
        why=f"{100 * (1 - e / escape):.2g} % below it: the basin's area is singular there, "
        f"and {error}",
    )  # fmt: skip


def _shape_near_escape(well, e: float, error: NumericalError) -> Exception:
    """:func:`_near_escape` for a registered shape with an escape saddle; else ``error``."""
    k = well.kernels
    if not k.ESCAPE_NAME:
        return error
    escape = float(python_kernel(k.escape_energy)(well.alpha, well.beta, well.gamma, well.n))
    return _near_escape(
        e, escape, f"the height of {k.ESCAPE_NAME} of this {well.shape} well", error
    )


def _law(ratio, n: float, k: int, near_escape) -> tuple[_Density, float]:
    """G_k and <E_c> / E from ``ratio(u)``, A / t at u = (e / E)^(1/n) (up to a constant
    factor): the one computation behind :func:`equilibrium_law` and :func:`well_law`.
    ``near_escape(error)`` is the exception raised when the one-particle series fails."""

    def h1(u: np.ndarray) -> np.ndarray:
        # t = 0 (u = 0) is the limit A / t -> F(0): evaluated a hair inside
        return np.log(ratio(np.maximum(u, 1e-300)))

    try:
        one = _Density(1 + 1 / n, _interpolate(h1, "log A(e) / t"))
    except NumericalError as error:
        raise near_escape(error) from None
    result, base, bits = None, one, k
    while bits:
        if bits & 1:
            result = base if result is None else _convolve(result, base, n)
        bits >>= 1
        if bits:
            base = _convolve(base, base, n)
    return result, float(_moments(result, n, [(1.0, 1)])[0])


@renamed(energy="total_energy")
def equilibrium_law(sink: Sink, total_energy: float) -> EquilibriumLaw:
    """The law of E_c for ``sink`` (well and k; the mass cancels) at total energy E.

    Parameters
    ----------
    sink : Sink
        Its well a registered shape's :class:`~sinktheory.model.Well` or a user's
        :class:`~sinktheory.wellat.WellAt` (then :func:`well_law` at its values).
    total_energy : float
        Total energy E > 0 (in a run: E0 plus the particles' initial potential energy),
        below the escape energy of one particle holding all of it.

    Raises
    ------
    ParameterError
        Bad sink or energy (<= 0, at or above escape, beyond the well's regular part).
    NumericalError
        The area quadrature or a Chebyshev series did not converge.
    """
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    well, k = sink.well, sink.particles
    if hasattr(well, "definition"):  # a user's well at its values (WellAt)
        return well_law(well.definition, k, total_energy, well.parameters,
                        well_check=well.report)  # fmt: skip
    e = v.positive("total_energy", total_energy)
    well.check_energy(e, name="total_energy")
    n = well.n
    t_e = scaled_energy(well, e)
    result, mean_fraction = _law(
        lambda u: area_ratio(well, t_e * u), n, k,
        lambda error: _shape_near_escape(well, e, error),
    )  # fmt: skip
    return EquilibriumLaw(
        shape=well.shape,
        alpha=well.alpha,
        beta=well.beta,
        n=n,
        gamma=well.gamma,
        particles=k,
        total_energy=e,
        exponent=result.b,
        mean=mean_fraction * e,
        mean_fraction=mean_fraction,
        homogeneous_mean=equipartition_container_energy(e, k, n),
        log_density=result.h.coef,
    )


def well_law(
    well, particles: int, total_energy: float, values: Mapping[str, float] | None = None,
    *, well_check=None,
) -> EquilibriumLaw:  # fmt: skip
    """The law of E_c for k = ``particles`` particles in a user's well (a
    :class:`~sinktheory.userwell.UserWell` at its parameter ``values`` by name, defaults
    for the others) at total energy E, the particles' energies measured from V(0, 0);
    ``well_check``: the well's :func:`~sinktheory.userwell.check_well` at those values, if
    already run.

    The same computation as :func:`equilibrium_law`, with A(e) from
    :class:`~sinktheory.equilibrium.area.WellArea` and n half the degree of V's leading term
    at the centre (A(e) ~ e^(1/n)); ``alpha``, ``beta``, ``gamma`` of the result are NaN and
    ``parameters`` holds the well's values.

    Raises
    ------
    ParameterError
        A refused well (WellDefinitionError), particles not in [1, 1000], E <= 0 or at or
        above the escape energy (or so near it that the series does not converge).
    NumericalError
        The area quadrature or a Chebyshev series did not converge.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> hh = UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})
    >>> law = well_law(hh, 1, 0.01)
    >>> law.n, round(law.mean_fraction, 3)  # close to Beta(1, 2) at low energy: 1/3
    (1, 0.333)
    """
    area = WellArea.of(well, values, well_check)
    k = v.positive_int("particles", particles, maximum=1000)
    e = area.check_energy(total_energy, name="total_energy")
    n = area.n
    within = area.rays(e)
    t_e = e ** (1 / n)

    def near_escape(error: NumericalError) -> Exception:
        if area.basin.escape.kind == "box":
            return error
        return _near_escape(e, area.basin.escape_energy, f"the escape energy of the {area.name} "
                            f"well ({area.basin.escape.kind})", error)  # fmt: skip

    result, mean_fraction = _law(lambda u: area.ratio(t_e * u, within), n, k, near_escape)
    return EquilibriumLaw(
        shape=area.name,
        alpha=math.nan,
        beta=math.nan,
        n=n,
        gamma=math.nan,
        particles=k,
        total_energy=e,
        exponent=result.b,
        mean=mean_fraction * e,
        mean_fraction=mean_fraction,
        homogeneous_mean=e / (1 + result.b),
        log_density=result.h.coef,
        parameters=area.values,
    )
