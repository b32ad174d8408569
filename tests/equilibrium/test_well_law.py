"""The equilibrium law of a user's well (well_law) against closed forms and the registry:
the elliptic well's exact Beta law and area, the Henon-Heiles area and law from an
independent one-dimensional quadrature, and the built-in shapes typed as expressions
against the registry's law."""

import math

import numpy as np
import pytest
from _cli import BUILT_IN, ELLIPTIC, HH, PAPER
from scipy import integrate, optimize

from sinktheory.basin import leading_order
from sinktheory.equilibrium import equilibrium_law, well_law
from sinktheory.equilibrium.area import WellArea
from sinktheory.errors import ParameterError, WellDefinitionError
from sinktheory.model import Sink, Well
from sinktheory.userwell import UserWell

ELLIPSE = {"a": 0.3, "b": 0.2, "gamma": 2.0, "n": (4, (1, 20))}


# --- the leading order at the centre ------------------------------------------------------
@pytest.mark.parametrize(
    "potential,degree",
    [(ELLIPTIC, 8), (HH, 2), ("Abs(x)**3 + Abs(y)**3 + x**4", 3), ("exp(x**2 + y**2) - 1", 2)],
)
def test_the_leading_degree_is_the_homogeneous_order_at_the_centre(potential, degree):
    well = UserWell("w", potential, ELLIPSE if potential == ELLIPTIC else {})
    assert leading_order(well.potential, well.values()).degree == degree


@pytest.mark.parametrize(
    "potential", ["x**2 + y**4", "x**2 + y**4 + x*y**3", "(x - y)**2 + x**4 + y**4"]
)
def test_a_leading_form_vanishing_along_a_direction_is_refused(potential):
    with pytest.raises(WellDefinitionError, match="not positive along the direction"):
        leading_order(UserWell("w", potential, {}).potential)


# --- the elliptic well: exact area and exact Beta law -------------------------------------
def test_the_elliptic_area_is_exact():
    area = WellArea.of(UserWell("ellipse", ELLIPTIC, ELLIPSE))
    for e in (1e-6, 0.01, 0.5, 3.0):
        c2 = (2 * 4 * e / 2.0) ** (1 / 4)  # (x/a)^2 + (y/b)^2 < c^2
        assert area.area(e) == pytest.approx(math.pi * 0.3 * 0.2 * c2, rel=1e-12)


@pytest.mark.parametrize("k,n", [(3, 4), (2, 1), (5, 7)])
def test_the_elliptic_law_is_beta_one_k_one_plus_one_over_n(k, n):
    law = well_law(UserWell("ellipse", ELLIPTIC, ELLIPSE), k, 0.5, {"n": n})
    b = k * (1 + 1 / n)
    assert law.n == n and law.exponent == pytest.approx(b, rel=1e-15)
    assert law.mean_fraction == pytest.approx(1 / (1 + b), rel=1e-12)
    assert float(law.tail(0.3)) == pytest.approx(0.7**b, rel=1e-11)
    assert law.pdf([0.4])[0] == pytest.approx(b * 0.6 ** (b - 1), rel=1e-11)
    assert law.homogeneous_mean == pytest.approx(0.5 / (1 + b), rel=1e-15)
    assert law.parameters == {"a": 0.3, "b": 0.2, "gamma": 2.0, "n": float(n)}
    assert math.isnan(law.alpha) and math.isnan(law.beta) and math.isnan(law.gamma)


# --- Henon-Heiles: an independent quadrature of the area ----------------------------------
def hh_area(e: float) -> float:
    """A(e) of Henon-Heiles by rows: for fixed y, V < e is x^2 < (e - y^2/2 + y^3/3) /
    (1/2 + y), so A = int 2 sqrt(that) dy between the roots of e = y^2/2 - y^3/3 around 0
    (y = mid - half cos(phi) removes the square-root ends)."""
    lo = optimize.brentq(lambda y: y * y / 2 - y**3 / 3 - e, -1.0, 0.0, xtol=1e-16)
    hi = optimize.brentq(lambda y: y * y / 2 - y**3 / 3 - e, 0.0, 1.0, xtol=1e-16)
    mid, half = (hi + lo) / 2, (hi - lo) / 2

    def row(phi):
        y = mid - half * math.cos(phi)
        width = 2 * math.sqrt(max(e - y * y / 2 + y**3 / 3, 0.0) / (0.5 + y))
        return width * half * math.sin(phi)

    value, err = integrate.quad(row, 0.0, math.pi, epsabs=0, epsrel=1e-13, limit=200)
    return value


def test_the_henon_heiles_area_is_the_row_quadrature():
    area = WellArea.of(UserWell("hh", HH, {}))
    assert area.n == 1
    for e in (1e-4, 0.05, 0.12, 0.16):
        assert area.area(e) == pytest.approx(hh_area(e), rel=1e-12)


def test_the_henon_heiles_law_is_the_area_for_one_particle():
    # k = 1: rho(E_c) is proportional to A(E - E_c); its mean is a ratio of quadratures
    E = 0.1
    law = well_law(UserWell("hh", HH, {}), 1, E)
    s = np.array([0.0, 0.2, 0.5, 0.9])
    areas = np.array([hh_area(E * (1 - v)) for v in s])
    assert law.pdf(s) / law.pdf(0.0) == pytest.approx(areas / areas[0], rel=1e-11)
    num = integrate.quad(lambda v: v * hh_area(E * (1 - v)), 0, 1, epsrel=1e-12)[0]
    den = integrate.quad(lambda v: hh_area(E * (1 - v)), 0, 1, epsrel=1e-12)[0]
    assert law.mean_fraction == pytest.approx(num / den, rel=1e-12)
    # below the homogeneous 1/3: the cubic terms widen the basin as e grows
    assert law.mean_fraction < 1 / 3


def test_energies_at_or_above_the_henon_heiles_saddle_are_refused():
    with pytest.raises(ParameterError, match="total_energy"):
        well_law(UserWell("hh", HH, {}), 1, 1 / 6)


# --- the built-in shapes typed as expressions ---------------------------------------------
@pytest.mark.parametrize(
    "shape,beta,n,k,E",
    [
        ("flat", -0.2, 4, 2, 0.5),
        ("flat", 0.0, 2, 3, 0.3),
        ("symmetric", 0.1, 3, 1, 0.1),
        ("circular", 0.3, 4, 5, 0.5),
    ],
)
def test_the_built_in_shapes_typed_as_expressions_give_the_registry_law(shape, beta, n, k, E):
    user = well_law(UserWell(f"{shape}_user", BUILT_IN[shape], PAPER), k, E, {"beta": beta, "n": n})
    registry = equilibrium_law(Sink(Well(0.5, beta, n, shape=shape), particles=k), E)
    assert user.n == registry.n and user.exponent == registry.exponent
    # measured: 3e-16 and 6e-16 at most (the registry's closed forms and quadratures)
    assert user.mean_fraction == pytest.approx(registry.mean_fraction, rel=1e-12)
    f = [0.1, 0.5, 0.8]
    assert user.tail(f) == pytest.approx(registry.tail(f), rel=1e-12)


@pytest.mark.parametrize(
    "potential,n", [("Abs(x)**3 + 2*Abs(y)**3", 1.5), ("sqrt(x**2 + 4*y**2)", 0.5)]
)
def test_a_leading_degree_that_is_not_even_gives_a_half_integer_n(potential, n):
    # homogeneous of degree 3 and 1: A(e) ~ e^(2/3), e^2, and the law is Beta(1, k (1 + 1/n))
    law = well_law(UserWell("w", potential, {}), 2, 0.5)
    b = 2 * (1 + 1 / n)
    assert law.n == n and law.mean_fraction == pytest.approx(1 / (1 + b), rel=1e-12)


def test_energies_are_measured_from_the_centre():
    # V = exp(x^2 + y^2), V(0, 0) = 1: the basin of e is r^2 < log(1 + e), A = pi log(1 + e)
    E = 0.3
    law = well_law(UserWell("w", "exp(x**2 + y**2)", {}), 1, E)
    area = WellArea.of(UserWell("w", "exp(x**2 + y**2)", {}))
    assert area.area(0.2) == pytest.approx(math.pi * math.log1p(0.2), rel=1e-12)
    num = integrate.quad(lambda v: v * math.log1p(E * (1 - v)), 0, 1, epsrel=1e-13)[0]
    den = integrate.quad(lambda v: math.log1p(E * (1 - v)), 0, 1, epsrel=1e-13)[0]
    assert law.mean_fraction == pytest.approx(num / den, rel=1e-12)
