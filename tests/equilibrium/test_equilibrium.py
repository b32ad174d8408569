"""The equilibrium law of the container energy and the basin areas behind it.

References are independent of the code under test: scipy.stats.beta (homogeneous wells),
the flat well's law as an exact mixture of Beta(1, b) laws built here from the closed-form
area by a polynomial power, the superellipse and disc areas typed from their formulas,
Monte Carlo areas, and scipy.integrate.quad convolutions of the quadrature area.
"""

import math

import mpmath
import numpy as np
import pytest
from scipy import integrate, special, stats

from sinktheory.canonical import FIG8_WELL, SYMMETRIC_WELL
from sinktheory.equilibrium import area_quadrature, basin_area, equilibrium_law, scaled_energy
from sinktheory.errors import NumericalError, ParameterError
from sinktheory.model import Sink, Well
from sinktheory.sinkstats import equipartition_container_energy


def superellipse(n):
    """Area of |x|^(2n) + |y|^(2n) < 1."""
    return 4 * math.gamma(1 + 1 / (2 * n)) ** 2 / math.gamma(1 + 1 / n)


# --- areas ------------------------------------------------------------------------------
@pytest.mark.parametrize("n", [1, 2, 4, 10])
@pytest.mark.parametrize("shape", ["flat", "symmetric", "circular"])
def test_homogeneous_areas_are_the_closed_forms(shape, n):
    # beta = 0: the basins are superellipses of half-axes c = (2 n e / gamma)^(1/2n)
    # times (alpha, 1) (flat) or (alpha, alpha) (symmetric); the circular well's is a disc
    # of radius (alpha - beta) c.  The quadrature converges geometrically; 1e-12 leaves a margin of
    # 10 over its stopping rule (1e-13) for the bisection's rounding.
    alpha, gamma, e = 0.7, 1.3, 0.2
    well = Well(alpha, 0.0, n, gamma=gamma, shape=shape)
    c2 = (2 * n * e / gamma) ** (1 / n)
    scale = {"flat": alpha, "symmetric": alpha**2, "circular": math.pi * alpha**2}[shape]
    exact = scale * c2 * (1 if shape == "circular" else superellipse(n))
    assert area_quadrature(well, e) == pytest.approx(exact, rel=1e-12)
    assert basin_area(well, e) == pytest.approx(exact, rel=1e-12)


@pytest.mark.parametrize("beta,n", [(-0.3, 1), (-0.3, 4), (-0.3, 10), (0.3, 1), (0.3, 4)])
def test_flat_closed_form_equals_quadrature(beta, n):
    # two methods: the Beta-function closed form and the trapezoid rule over the rays
    well = Well(0.5, beta, n)
    for e in (0.01, 0.05):
        assert basin_area(well, e) == pytest.approx(area_quadrature(well, e), rel=1e-12)


def test_quadrature_refuses_a_basin_not_star_shaped():
    # flat, beta = 0.3, n = 10, e = 0.1: the inward walls make the basin a bow tie that
    # rays from the centre leave and re-enter; the closed form still applies
    well = Well(0.5, 0.3, 10)
    with pytest.raises(NumericalError, match="star-shaped"):
        area_quadrature(well, 0.1)
    assert basin_area(well, 0.1) > 0


def test_flat_closed_form_by_slices():
    # a third method: scipy's quad over y of the width 2 D(y) (c^2n - y^2n)^(1/2n)
    well, e = FIG8_WELL, 0.25
    c = (2 * 4 * e) ** (1 / 8)
    width = lambda y: 2 * (0.2 + 0.3 * y**2) * (c**8 - y**8) ** (1 / 8)  # noqa: E731
    ref, err = integrate.quad(width, -c, c, epsabs=0, epsrel=1e-13, limit=200)
    assert basin_area(well, e) == pytest.approx(ref, rel=1e-11)


@pytest.mark.parametrize(
    "well,e",
    [
        (FIG8_WELL, 0.25),
        (SYMMETRIC_WELL, 0.5),
        (Well(0.5, 0.3, 2, shape="symmetric"), 1.0),
        (Well(1.0, -0.1, 6, shape="symmetric"), 0.5),
    ],
)
def test_area_against_monte_carlo(well, e):
    # uniform points in the reach box; the fraction inside is binomial: 5 standard errors
    rng = np.random.default_rng(7)
    x_max, y_max = well.reach(e)
    N = 400_000
    x = rng.uniform(-x_max, x_max, N)
    y = rng.uniform(-y_max, y_max, N)
    inside = well.potential(x, y) < e
    p = inside.mean()
    box = 4 * x_max * y_max
    se = box * math.sqrt(p * (1 - p) / N)
    assert abs(basin_area(well, e) - box * p) < 5 * se


def test_area_refuses_energy_at_escape_and_bad_input():
    well = Well(0.5, 0.3, 2, shape="symmetric")  # escape (1/(4 0.3 0.2))^2 / 2 = 8.68
    escape = (1 / (4 * 0.3 * 0.2)) ** 2 / 2
    with pytest.raises(ParameterError, match="energy"):
        basin_area(well, escape)
    with pytest.raises(ParameterError, match="energy"):
        basin_area(well, -1.0)
    with pytest.raises(ParameterError, match="well"):
        basin_area("flat", 0.1)


# --- the law ----------------------------------------------------------------------------
@pytest.mark.parametrize("shape", ["flat", "symmetric", "circular"])
@pytest.mark.parametrize("k", [1, 2, 5, 30])
@pytest.mark.parametrize("n", [1, 4])
def test_homogeneous_law_is_beta(shape, k, n):
    # beta = 0: s = E_c / E ~ Beta(1, k (1 + 1/n)).  Only rounding separates the two
    # (the convolution of powers is exact by the quadrature): 1e-12.
    law = equilibrium_law(Sink(Well(0.5, 0.0, n, shape=shape), particles=k), 0.3)
    ref = stats.beta(1, k * (1 + 1 / n))
    s = np.array([0.0, 0.01, 0.2, 0.5, 0.9])
    assert law.pdf(s) == pytest.approx(ref.pdf(s), rel=1e-12)
    assert law.cdf(s) == pytest.approx(ref.cdf(s), rel=1e-12, abs=1e-15)
    assert law.tail(s) == pytest.approx(ref.sf(s), rel=1e-12)
    assert law.mean_fraction == pytest.approx(ref.mean(), rel=1e-12)
    assert law.mean == pytest.approx(equipartition_container_energy(0.3, k, n), rel=1e-12)
    assert law.quantile([0.1, 0.5, 0.99]) == pytest.approx(ref.ppf([0.1, 0.5, 0.99]), rel=1e-10)


def beta_mixture(well, k, energy):
    """The flat well's law as a mixture of Beta(1, b_m): A(e) = a1 e^(1/n) + a2 e^(2/n)
    (its two terms read off the area at two energies), so g^(*k) is a sum of powers whose
    coefficients are those of a polynomial's k-th power (exact convolution of powers)."""
    n = well.n
    u1, u2 = 0.5, 1.0  # A = a1 u + a2 u^2 with u = (e / E)^(1/n): solve from two areas
    A1, A2 = basin_area(well, energy * u1**n), basin_area(well, energy * u2**n)
    a2 = (A2 / u2 - A1 / u1) / (u2 - u1)
    a1 = A1 / u1 - a2 * u1
    p = np.array([0.0, a1 * math.gamma(1 + 1 / n), a2 * math.gamma(1 + 2 / n)])
    P = np.array([1.0])
    for _ in range(k):
        P = np.convolve(P, p)
    m = np.arange(P.size)[1:]
    b = k + m / n
    keep = P[1:] != 0  # the first k - 1 powers of the polynomial vanish
    logw = np.log(np.abs(P[1:][keep])) - special.gammaln(b[keep] + 1)
    w = np.sign(P[1:][keep]) * np.exp(logw - logw.max())
    return b[keep], w / w.sum()


@pytest.mark.parametrize("beta,energy", [(0.3, 0.5), (-0.3, 0.05), (0.1, 1.0)])
@pytest.mark.parametrize("k", [1, 2, 5, 20])
def test_flat_law_is_the_exact_beta_mixture(beta, energy, k):
    # independent exact law; the convolution quadrature and Chebyshev series agree with
    # it to ~1e-13 (measured); 1e-10 is the accuracy the law promises.
    well = Well(0.5, beta, 4)
    law = equilibrium_law(Sink(well, particles=k), energy)
    b, w = beta_mixture(well, k, energy)
    fs = np.array([0.001, 0.05, 0.2, 0.5, 0.8])
    assert law.tail(fs) == pytest.approx([(w * (1 - f) ** b).sum() for f in fs], rel=1e-10)
    assert law.mean_fraction == pytest.approx((w / (1 + b)).sum(), rel=1e-10)
    assert law.pdf(fs) == pytest.approx([(w * b * (1 - f) ** (b - 1)).sum() for f in fs], rel=1e-10)


def test_one_particle_law_is_the_area():
    # k = 1: rho(E_c) is proportional to A(E - E_c) (quadrature areas of the symmetric well)
    well, E = SYMMETRIC_WELL, 0.5
    law = equilibrium_law(Sink(well, particles=1), E)
    s = np.array([0.0, 0.3, 0.7, 0.95])
    areas = np.array([area_quadrature(well, E * (1 - x)) for x in s])
    assert law.pdf(s) / law.pdf(0.0) == pytest.approx(areas / areas[0], rel=1e-10)


def test_two_particle_law_against_tanh_sinh_convolution():
    # k = 2, symmetric well: G_2(e) = int_0^e A(x) A(e - x) dx by mpmath's tanh-sinh rule
    # (indifferent to the end behaviour x^(1/n) times a series in x^(1/n); its error
    # estimate is ~1e-23, so the quadrature areas' 1e-13 dominate); the law agrees to 1e-10.
    well, E = SYMMETRIC_WELL, 0.5
    law = equilibrium_law(Sink(well, particles=2), E)

    def G2(e):
        def f(x):
            a, b = float(x), float(mpmath.mpf(e) - x)
            return area_quadrature(well, a) * area_quadrature(well, b) if a > 0 < b else 0.0

        with mpmath.workdps(15):
            return float(mpmath.quad(f, [0, e / 2, e], maxdegree=8))

    s = np.array([0.1, 0.6])
    ratio = G2(E * (1 - s[1])) / G2(E * (1 - s[0]))
    assert law.pdf(s[1]) / law.pdf(s[0]) == pytest.approx(ratio, rel=1e-10)


def test_law_does_not_depend_on_the_mass():
    well = FIG8_WELL
    a = equilibrium_law(Sink(well, particles=3, mass=0.2), 0.5)
    b = equilibrium_law(Sink(well, particles=3, mass=7.0), 0.5)
    assert a.mean == b.mean and a.tail(0.5) == b.tail(0.5)


def test_law_refusals():
    with pytest.raises(ParameterError, match="particles"):
        equilibrium_law(Sink(FIG8_WELL, particles=0), 0.5)
    well = Well(0.5, 0.3, 2, shape="symmetric")
    with pytest.raises(ParameterError, match="energy"):
        equilibrium_law(Sink(well), 10.0)  # above the corner saddle 8.68
    law = equilibrium_law(Sink(FIG8_WELL), 0.5)
    for bad in (0.0, 1.0, -0.2, 1.5, float("nan")):
        with pytest.raises(ParameterError, match="fraction"):
            law.summary(fractions=[bad])


def test_summary_protocol():
    law = equilibrium_law(Sink(FIG8_WELL, particles=2), 0.5)
    s = law.summary(fractions=[0.2, 0.8], levels=[0.5])
    d = s.as_dict()
    assert d["law"]["particles"] == 2 and d["fractions"] == [0.2, 0.8]
    assert d["kac_periods"][1] == pytest.approx(1 / law.tail(0.8), rel=1e-15)
    assert s.quantiles[0] == pytest.approx(law.quantile(0.5) * 0.5, rel=1e-15)
    ds = s.to_dataset()
    assert ds.tails.dims == ("fraction",) and ds.pdf.dims == ("s",)
    # the density integrates to one (trapezoid on 201 points: error ~ 1e-4 of the curvature)
    assert np.trapezoid(s.pdf, s.s) == pytest.approx(1.0, abs=2e-3)
    assert scaled_energy(law_well := FIG8_WELL, 0.125) == pytest.approx(1.0)
    assert law_well.n == 4
