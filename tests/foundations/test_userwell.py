"""A user's well: parsed as written, equal to the built-in shapes, checked (minimum,
confinement, realness, y = 0 invariance) with every refusal shown."""

from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from _cli import BUILT_IN, HH, PAPER

from sinktheory import symbolic as S
from sinktheory.errors import WellDefinitionError
from sinktheory.userwell import (
    FUNCTIONS,
    Parameter,
    UserWell,
    check_well,
    load_well,
    parse_potential,
    y_invariant,
)

ROOT = Path(__file__).resolve().parents[2]
x, y = S.x, S.y
a, b, c = sp.symbols("a b c", real=True)


# --- parsing ------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text,expected",
    [
        ("x**2 + y**2", x**2 + y**2),
        ("-x + +y - 3", -x + y - 3),
        ("0.3*x", sp.Rational(3, 10) * x),  # a decimal is exact
        ("1e-3*y**2", y**2 / 1000),
        ("x/2", x / 2),
        ("a*x**2 + (y/b)**2", a * x**2 + y**2 / b**2),
        ("2**10 * x", 1024 * x),
        ("pi*x**2", sp.pi * x**2),
        ("sqrt(x**2 + y**2)", sp.sqrt(x**2 + y**2)),
        ("Abs(x) + exp(-y**2)", sp.Abs(x) + sp.exp(-(y**2))),
    ],
)
def test_accepted_text_builds_the_expression_sympy_would(text, expected):
    assert sp.simplify(parse_potential(text, ("a", "b")) - expected) == 0


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_every_whitelisted_function_is_the_sympy_one(name):
    built = parse_potential(f"{name}(x/2 + 1/3)", ())
    assert built == FUNCTIONS[name](x / 2 + sp.Rational(1, 3))


def test_powers_stay_as_written_so_they_do_not_overflow_in_parts():
    V = parse_potential("(x/(1 + y**2))**100", ())
    assert isinstance(V, sp.Pow) and V.exp == 100  # not x**100 / (1 + y**2)**100


def test_a_sympy_expression_is_matched_to_the_declared_symbols_by_name():
    a_pos = sp.Symbol("a", positive=True)  # other assumptions than the parser's
    well = UserWell("u", a_pos * sp.Symbol("x") ** 2 + sp.Symbol("y") ** 2, {"a": 1.0})
    assert well.potential.free_symbols == {a, x, y}
    assert well.potential == UserWell("v", "a*x**2 + y**2", {"a": 1.0}).potential


# --- the definition -----------------------------------------------------------------------
def test_parameters_may_be_given_as_in_a_well_file():
    well = UserWell("u", "c*(x**2 + y**2)", {"c": {"default": 0.5, "range": [0, 1]}})
    assert well.parameters == (Parameter("c", 0.5, (0.0, 1.0)),)


def test_a_wall_ratio_must_be_below_one_at_the_centre():
    good = UserWell("u", "x**2 + y**2", {"L": 0.2}, wall_ratios=["sqrt(x**2 + y**2)/L"])
    assert check_well(good).y_invariant
    bad = UserWell("u", "x**2 + y**2", {"L": 0.2}, wall_ratios=["1 + (x/L)**2"])
    with pytest.raises(WellDefinitionError, match=r"well u: wall_ratios\[0\]: '1 at \(0, 0\)'"):
        check_well(bad)


def test_values_are_exact_and_checked_against_their_ranges():
    well = UserWell("u", "c*(x**2 + y**2)", {"c": (0.1, (0.0, 1.0))})
    assert well.values() == {c: sp.Rational(1, 10)}
    assert well.values(c=1) == {c: 1}
    assert well.potential_at(c=0.5) == (x**2 + y**2) / 2
    with pytest.raises(WellDefinitionError, match=r"c: 2.0 is refused: outside the range"):
        well.values(c=2)
    with pytest.raises(WellDefinitionError, match="'d' is refused: not a parameter of u"):
        well.values(d=1)


@pytest.mark.parametrize(
    "kwargs,message",
    [
        (dict(name="flat"), "name: 'flat' is refused: the name of a built-in shape"),
        (dict(name="a b"), "name: 'a b' is refused"),
        (dict(name=""), "name: '' is refused"),
        (dict(parameters={"x": 1.0}), "parameters: 'x' is refused: a reserved name"),
        (dict(parameters={"exp": 1.0}), "parameters: 'exp' is refused: a reserved name"),
        (dict(parameters={"_c": 1.0}), "parameters: '_c' is refused: a parameter name"),
        (dict(parameters={"c": (5.0, (0, 1))}), "parameters.c.default: 5.0 is refused"),
        (dict(parameters={"c": float("nan")}), "parameters.c.default: nan is refused"),
        (dict(parameters={"c": (1.0, (2, 0))}), "parameters.c.range"),
        (dict(parameters=(Parameter("c", 1.0), Parameter("c", 2.0))), "declared twice"),
        (dict(potential="c*x**2 + d*y**2"), "potential: 'd' is refused: a name that is not"),
        (dict(wall_ratios="x"), "wall_ratios: 'x' is refused: must be a list"),
        (dict(wall_ratios=["x", "y.real"]), "wall_ratios[1]: 'y.real' is refused: attribute"),
        (dict(parameters={"c": {"default": 1.0, "code": "x"}}), "parameters.c: 'code' is"),
        (dict(parameters={"c": {"range": [0, 1]}}), "parameters.c: 'default' is refused"),
    ],
)
def test_a_bad_definition_is_refused_by_name(kwargs, message):
    args = dict(name="u", potential="c*(x**2 + y**2)", parameters={"c": 1.0}) | kwargs
    with pytest.raises(WellDefinitionError) as info:
        UserWell(**args)
    assert message in str(info.value) and "\n" not in str(info.value)


# --- the built-in shapes as user expressions ----------------------------------------------
@pytest.mark.parametrize("shape", sorted(BUILT_IN))
@pytest.mark.parametrize("beta,n", [(0.3, 1), (0.3, 4), (-0.7, 3)])
def test_a_built_in_shape_written_by_a_user_is_the_registry_potential(shape, beta, n):
    well = UserWell(f"{shape}_user", BUILT_IN[shape], PAPER)
    mine = well.potential_at(beta=beta, n=n)
    at = {S.alpha: sp.Rational(1, 2), S.beta: sp.Rational(str(beta)), S.gamma: 1, S.n: n}
    registry = S.potential(shape).subs(at)
    assert sp.simplify(mine - registry) == 0
    # and numerically at random points inside the walls, to 1e-14 relative
    points = np.random.default_rng(7).uniform(-0.19, 0.19, size=(2, 50))
    f, g = (sp.lambdify((x, y), e, "numpy") for e in (mine, registry))
    np.testing.assert_allclose(f(*points), g(*points), rtol=1e-14, atol=0)


@pytest.mark.parametrize("shape", ["flat", "circular"])
@pytest.mark.parametrize("beta,n", [(0.3, 1), (0.3, 4), (-0.7, 3), (0.3, 1000)])
def test_the_flat_and_circular_shapes_pass_the_checks(shape, beta, n):
    report = check_well(UserWell(f"{shape}_user", BUILT_IN[shape], PAPER), beta=beta, n=n)
    # n = 1: V_xx = gamma/(alpha - beta)^2 > 0, V_yy > 0 (closed form); n >= 2: Hessian 0
    assert report.minimum.startswith("strict" if n == 1 else "V(0, 0) <= V on the rings")
    assert report.y_invariant  # both are even in y


@pytest.mark.parametrize("beta", [0.3, -0.7])
def test_the_symmetric_shape_is_accepted_below_what_closes_its_basin(beta):
    # V -> 0 along the diagonals (independent: the limit on x = y), yet the basin around
    # the centre is bounded: by the corner saddle (beta > 0) or the poles D = 0 (beta < 0);
    # the escape energies themselves are checked in test_basin.py
    diagonal = S.potential("symmetric").subs({x: S.x, y: S.x})
    limit = sp.limit(diagonal.subs({S.n: 2, S.alpha: 1, S.beta: beta, S.gamma: 1}), S.x, sp.oo)
    assert limit == 0
    report = check_well(UserWell("symmetric_user", BUILT_IN["symmetric"], PAPER), beta=beta)
    assert report.basin.escape.kind == ("saddle" if beta > 0 else "singular")


# --- other wells --------------------------------------------------------------------------
def test_the_elliptic_well_file_in_the_guide_loads_and_passes():
    well = load_well(ROOT / "docs" / "guide" / "elliptic.toml")
    values = well.values()
    assert {s.name: v for s, v in values.items()} == {"a": sp.Rational(3, 10), "b": 1 / sp.S(5),
                                                      "gamma": 1, "n": 4}  # fmt: skip
    V = well.potential.subs(values)
    expected = ((x / sp.Rational(3, 10)) ** 2 + (y * 5) ** 2) ** 4 / 8  # the closed form
    assert sp.expand(V - expected) == 0
    (ratio,) = well.wall_ratios
    assert ratio.subs(values).subs({x: sp.Rational(3, 10), y: 0}) == 1  # the wall at x = a
    report = check_well(well)
    assert report.y_invariant and report.minimum.startswith("V(0, 0) <= V on the rings")
    n1 = check_well(well, n=1)  # V = gamma/2 ((x/a)^2 + (y/b)^2): Hessian diag(1/a^2, 1/b^2)
    assert n1.minimum.startswith("strict")


def test_the_henon_heiles_well_with_a_quartic_term_passes_and_y0_is_not_invariant():
    well = UserWell("hhq", HH + " + c*(x**2 + y**2)**2", {"c": (0.1, (0.0, 10.0))})
    report = check_well(well)
    assert report.minimum.startswith("strict")  # Hessian at 0: the identity
    assert not report.y_invariant
    assert report.y_invariant_reason == "dV/dy(x, 0) = x**2, not identically 0"
    assert report.basin.escape.kind == "box"  # c = 0.1: no critical point but the centre
    # a small c leaves a saddle a little above Henon-Heiles' 1/6 before r^4 wins far out
    weak = check_well(well, c=1e-3).basin.escape
    assert weak.kind == "saddle" and 1 / 6 < weak.escape_potential < 0.17


def test_the_plain_henon_heiles_well_is_accepted_below_its_saddles():
    # independent: V - 1/6 = (y + 1/2)(sqrt(3) x - y + 1)(-sqrt(3) x - y + 1)/... vanishes on
    # the triangle through the three saddles (0, 1), (+-sqrt(3)/2, -1/2), each at V = 1/6
    report = check_well(UserWell("hh", HH, {}))
    escape = report.basin.escape
    assert escape.kind == "saddle" and abs(escape.escape_potential - 1 / 6) <= 1e-15
    saddles = [(0.0, 1.0), (3**0.5 / 2, -0.5), (-(3**0.5) / 2, -0.5)]
    assert min(np.hypot(escape.point[0] - a, escape.point[1] - b) for a, b in saddles) < 1e-14
    assert report.confinement.startswith("escape energy 0.1666666666666")


# --- each check refuses -------------------------------------------------------------------
@pytest.mark.parametrize(
    "text,reason",
    [
        ("(x - 0.1)**2 + y**2", "'grad V(0, 0) = (-1/5, 0)' is refused: no minimum"),
        ("(x**2 + y**2)**2/4 - (x**2 + y**2)/2", "the Hessian has a negative eigenvalue"),
        ("x**2 - y**2", "'Hessian at (0, 0) = [[2, 0], [0, -2]]' is refused"),
        ("x**3 + y**2", "no minimum at the centre: lower at"),  # Hessian singular: rings
        ("x**4 - y**6 + y**8", "no minimum at the centre: lower at"),
        ("sqrt(0.5 - x**2) + y**2", "'V = nan' is refused: not real and finite"),
        ("x**2 + y**2 + log(1 - x**2 - y**2)", "'V = -inf' is refused: not real and finite"),
        ("x**2 + y**2 + 1/(x - 0.3)", "a denominator, non-zero and of one sign, fails"),
        ("x**2 + y**2 + log(x**2 + 0.5 - y)", "is refused: not real and finite"),
        ("x**2 + y**2 + (x + 0.7)**0.5", "'V = nan' is refused: not real and finite"),
        ("x**2 + y**2 + 1/(x**2 - 0.09)**2", "a denominator, non-zero and of one sign"),
        ("x**2", "not confining: at every energy above V(0, 0) the basin reaches (0, "),
    ],
)
def test_a_bad_well_is_refused_with_one_line_saying_what_is_wrong(text, reason):
    with pytest.raises(WellDefinitionError) as info:
        check_well(UserWell("u", text, {}))
    message = str(info.value)
    assert reason in message and message.startswith("well u: ") and "\n" not in message


@pytest.mark.parametrize(
    "text,minimum",
    [
        ("Abs(x) + Abs(y)", "V(0, 0) <= V on the rings"),  # linear growth confines
        ("sqrt(x**2 + y**2)", "V(0, 0) <= V on the rings (derivatives undefined"),
        ("cosh(x) + cosh(y)", "strict"),
        ("x**2 + x*y + y**2", "strict"),  # det 3/4 > 0
        ("log(1 + x**2 + y**2)", "strict"),  # bounded as far as the search box reaches
        ("x**2 + y**2 - x**4", "strict"),  # bounded below its saddles at 1/4
    ],
)
def test_wells_the_checks_accept(text, minimum):
    assert check_well(UserWell("u", text, {})).minimum.startswith(minimum)


def test_the_disc_radius_is_the_neighbourhood_checked():
    well = UserWell("u", "x**2 + y**2 + log(4 - x**2 - y**2)", {})
    with pytest.raises(WellDefinitionError, match="r <= 3"):
        check_well(well, radius=3)
    with pytest.raises(WellDefinitionError, match=r"radius: -1.0 is refused"):
        check_well(well, radius=-1)
    # r**2 underflows on the finest ring: refused at once (the basin's search took 4-23 s
    # doubling its box from 1e-300 before)
    with pytest.raises(WellDefinitionError, match=r"radius: 1e-300 is refused: must be in "):
        check_well(UserWell("u", "x**2 + y**2", {}), radius=1e-300)


@pytest.mark.parametrize("scale", [1e-300, 1.0, 1e300])
def test_a_well_scaled_by_any_factor_has_its_saddles_scaled(scale):
    """V = s (x^2 + y^2 - x^4) has its saddles at x^2 = 1/2, V = s/4 (exact), for s from
    1e-300 to 1e300: a tiny V was taken for one flat to rounding (an absolute slack of
    1e-14) and refused as not confining, and the saddle's Hessian determinant (s^2)
    underflowed; a scaled confining well is accepted."""
    escape = check_well(UserWell("u", f"{scale!r}*(x**2 + y**2 - x**4)", {})).basin.escape
    assert escape.kind == "saddle"
    assert escape.escape_potential == pytest.approx(scale / 4, rel=1e-12)
    assert abs(escape.point[0]) == pytest.approx(0.5**0.5, rel=1e-12)
    bowl = check_well(UserWell("u", f"{scale!r}*(x**2 + y**2)", {})).basin.escape
    assert bowl.kind == "box"  # bounded as far as the search reaches: no refusal


def test_y_invariance_is_decided_symbolically():
    assert y_invariant(parse_potential("x**2 + cos(y)*x**4 + y**2*exp(x)", ()))[0]
    assert y_invariant(parse_potential("(x + y)**2 + (x - y)**2", ()))[0]  # needs expand
    assert y_invariant(parse_potential("sin(y)**2 + x**2 + sin(x)**2*y", ()))[1].startswith(
        "dV/dy(x, 0) = sin(x)**2"
    )


@pytest.mark.parametrize("text", ["x**2", "y**4", "(x - y)**2 + (x + y)**6 * 0", "(x + y)**2"])
def test_a_valley_along_an_axis_or_a_diagonal_is_seen(text):
    # V = 0 exactly along that line; a rounding of cos(45 deg) != sin(45 deg) would hide it
    with pytest.raises(WellDefinitionError, match="not confining"):
        check_well(UserWell("u", text, {}))
