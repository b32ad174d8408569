"""The basin of a user's well, found numerically (sinktheory.basin), against closed forms
and the registry: escape energies, reach and areas of the built-in shapes entered as
expressions, an elliptic well and the Henon-Heiles well."""

import math

import numpy as np
import pytest
import sympy as sp
from _cli import BUILT_IN, ELLIPTIC, HH, PAPER
from scipy import integrate, optimize

from sinktheory import symbolic as S
from sinktheory.basin import Basin
from sinktheory.equilibrium.area import basin_area
from sinktheory.errors import ParameterError, WellDefinitionError
from sinktheory.model import Well
from sinktheory.userwell import UserWell, check_well, parse_potential


def basin_of(shape, beta, n, gamma=1.0):
    well = UserWell(f"{shape}_user", BUILT_IN[shape], PAPER)
    return check_well(well, beta=beta, n=n, gamma=gamma).basin


def pole_limit(shape, alpha, beta, n, gamma):
    """The registry's limit for beta < 0 (a wall denominator vanishing within reach), in
    closed form: V on the axis at the pole, D(s) = 0 at s^2 = 1 - alpha/beta."""
    pole = math.sqrt(1 - alpha / beta)
    axis = pole / (alpha - beta) if shape == "symmetric" else pole  # V(pole, 0) or V(0, pole)
    return gamma / (2 * n) * axis ** (2 * n)


# --- escape energies ----------------------------------------------------------------------
@pytest.mark.parametrize("n,gamma", [(1, 1.0), (4, 2.0), (10, 1.0)])
def test_the_symmetric_corner_saddle_is_the_registry_escape_energy(n, gamma):
    _, v_star = S.symmetric_corner_saddle()  # closed form, derived symbolically
    exact = float(v_star.subs({S.alpha: 0.5, S.beta: sp.Rational(3, 10), S.n: n, S.gamma: gamma}))
    escape = basin_of("symmetric", 0.3, n, gamma).escape
    assert escape.kind == "saddle"
    assert abs(escape.escape_potential / exact - 1) <= 1e-12
    assert abs(abs(escape.point[0]) - abs(escape.point[1])) <= 1e-12  # on a diagonal
    assert escape.bracket[0] <= exact  # the grid's basin is closed below the saddle


@pytest.mark.parametrize("shape", ["flat", "symmetric"])
@pytest.mark.parametrize("n", [1, 4])
def test_beta_below_zero_the_poles_close_the_basin_where_the_registry_refuses(shape, n):
    escape = basin_of(shape, -0.7, n).escape
    exact = pole_limit(shape, 0.5, -0.7, n, 1.0)
    assert escape.kind == "singular"
    assert abs(escape.escape_potential / exact - 1) <= 1e-12
    well = Well(0.5, -0.7, n, shape=shape)  # the registry accepts below, refuses above
    well.reach(exact * (1 - 1e-9))
    with pytest.raises(ParameterError, match="beta"):
        well.reach(exact * (1 + 1e-9))


@pytest.mark.parametrize("shape,beta", [("flat", 0.3), ("circular", 0.3), ("circular", -0.7)])
def test_wells_that_confine_every_energy_are_bounded_up_to_the_search_box(shape, beta):
    escape = basin_of(shape, beta, 4).escape
    assert escape.kind == "box" and escape.escape_potential > 1e30  # the registry: never escapes


# --- reach ----------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "shape,beta,n,e",
    [("flat", 0.3, 4, 0.05), ("flat", -0.7, 3, 0.05), ("circular", 0.3, 2, 0.05),
     ("symmetric", -0.7, 4, 0.05), ("flat", 0.3, 1, 0.05),
     ("flat", 0.3, 10, 0.01)],  # its widest point: a spike thinner than a grid cell
)  # fmt: skip
def test_the_reach_is_the_registry_reach_where_that_is_exact(shape, beta, n, e):
    reach = basin_of(shape, beta, n).reach(e)
    registry = Well(0.5, beta, n, shape=shape).reach(e)  # c L, c, or a golden-section max
    assert reach.refined == (True, True)
    np.testing.assert_allclose((reach.x_max, reach.y_max), registry, rtol=1e-10, atol=0)


def test_the_symmetric_reach_lies_inside_the_registry_bound():
    e = 0.5 * float(S.symmetric_corner_saddle()[1].subs({S.alpha: 0.5, S.beta: 0.3, S.n: 4,
                                                          S.gamma: 1}))  # fmt: skip
    reach = basin_of("symmetric", 0.3, 4).reach(e)
    bound = Well(0.5, 0.3, 4, shape="symmetric").reach(e)
    assert reach.x_max <= bound[0] + 1e-12 and abs(reach.x_max - reach.y_max) <= 1e-12


@pytest.mark.parametrize("n", [1, 2, 5])
def test_the_elliptic_reach_and_area_are_the_closed_forms(n):
    a, b, gamma, e = 0.3, 0.2, 2.0, 0.05
    well = UserWell("ellipse", ELLIPTIC, {"a": a, "b": b, "gamma": gamma, "n": n})
    basin = check_well(well).basin
    scale = (2 * n * e / gamma) ** (1 / (2 * n))
    reach = basin.reach(e)
    assert abs(reach.x_max / (a * scale) - 1) <= 1e-12
    assert abs(reach.y_max / (b * scale) - 1) <= 1e-12
    area = math.pi * a * b * (2 * n * e / gamma) ** (1 / n)
    assert abs(basin.area(e) / area - 1) <= 1e-12


# --- areas --------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "shape,beta,n", [("flat", 0.3, 4), ("flat", -0.7, 2), ("circular", 0.3, 3), ("flat", 0.3, 1)]
)
def test_the_area_is_the_registry_closed_form(shape, beta, n):
    e = 0.05
    mine = basin_of(shape, beta, n).area(e)
    assert abs(mine / basin_area(Well(0.5, beta, n, shape=shape), e) - 1) <= 1e-12


def test_the_symmetric_area_at_beta_zero_is_the_superellipse():
    n, e, side = 3, 0.1, 0.5  # L = alpha = 0.5
    t = (2 * n * e) ** (1 / n)
    exact = 4 * side**2 * t * math.gamma(1 + 1 / (2 * n)) ** 2 / math.gamma(1 + 1 / n)
    assert abs(basin_of("symmetric", 0.0, n).area(e) / exact - 1) <= 1e-12


def test_the_henon_heiles_reach_and_area_by_independent_methods():
    e = 0.1
    basin = check_well(UserWell("hh", HH, {})).basin
    reach = basin.reach(e)
    # y_max: on the axis x = 0 (V_x = x (1 + 2y) = 0), the root of y^2/2 - y^3/3 = e
    roots = np.roots([-1 / 3, 1 / 2, 0, -e])
    y_top = min(r.real for r in roots if abs(r.imag) < 1e-12 and r.real > 0)
    assert abs(reach.y_max - y_top) <= 1e-12
    # x_max: {V = e, V_y = y + x^2 - y^2 = 0} by SymPy's own Newton solver
    x, y = S.x, S.y
    V = (x**2 + y**2) / 2 + x**2 * y - y**3 / 3
    sol = sp.nsolve([V - e, y + x**2 - y**2], [x, y], [0.45, -0.2], prec=30)
    assert abs(reach.x_max - float(sol[0])) <= 1e-12
    # the area by adaptive quadrature of r*(theta)^2 / 2, each r* by Brent's method
    f = sp.lambdify((x, y), V)

    def edge(theta):
        return optimize.brentq(lambda r: f(r * math.cos(theta), r * math.sin(theta)) - e,
                               0.0, 1.0, xtol=1e-15)  # fmt: skip

    area, _ = integrate.quad(lambda t: edge(t) ** 2 / 2, 0, 2 * math.pi, epsabs=0,
                             epsrel=1e-12, limit=200)  # fmt: skip
    assert abs(basin.area(e) / area - 1) <= 1e-10


# --- refusals -----------------------------------------------------------------------------
def test_energies_outside_the_basin_are_refused_by_name():
    basin = check_well(UserWell("hh", HH, {})).basin
    for e in (1 / 6, 0.2, 0.0, -1.0):
        refused = r"well hh: particle_energy: .* must be above V\(0"
        with pytest.raises(WellDefinitionError, match=refused):
            basin.reach(e)
        with pytest.raises(WellDefinitionError, match="below the escape energy 0.16666"):
            basin.area(e)


def test_a_basin_of_a_well_built_directly():
    # Basin.of without a well file: V = x^2 + y^2 - x^4 has its saddles at (+-1/sqrt 2, 0)
    basin = Basin.of(parse_potential("x**2 + y**2 - x**4", ()))
    assert basin.escape.kind == "saddle" and abs(basin.escape.escape_potential - 0.25) <= 1e-15


def test_a_registered_shape_has_the_same_basin_interface():
    # Basin.of takes any V: the registry's own expression at its own symbols' values
    values = {S.alpha: sp.Rational(1, 2), S.beta: sp.Rational(3, 10), S.gamma: 1, S.n: 4}
    basin = Basin.of(S.potential("symmetric"), values, "symmetric")
    exact = float(S.symmetric_corner_saddle()[1].subs(values))
    assert basin.escape.kind == "saddle" and abs(basin.escape.escape_potential / exact - 1) <= 1e-12
