"""The derivation ladder of a user's well (symbolic.ladder, one interface with the built-in
shapes) and `sinktheory derive --well FILE`."""

import json
import math
import re

import numpy as np
import pytest
import sympy as sp
from _cli import run_cli, snapshot

from sinktheory import symbolic as S
from sinktheory.userwell import UserWell, load_well

FLAT = "gamma/(2*n) * ((x/(alpha + beta*(y**2 - 1)))**(2*n) + y**(2*n))"
PAPER = {"alpha": 0.5, "beta": (0.3, (-5.0, 0.45)), "gamma": 1.0, "n": (4, (1, 1000))}
ELLIPTIC = "gamma/(2*n) * ((x/a)**2 + (y/b)**2)**n"
HH = "(x**2 + y**2)/2 + x**2*y - y**3/3"
x, y, X, mu = S.x, S.y, S.X, S.mu


def test_a_shape_and_a_user_well_are_both_well_definitions():
    assert isinstance(S.SHAPES["flat"], S.WellDefinition)
    assert isinstance(UserWell("hh", HH, {}), S.WellDefinition)
    assert not isinstance("flat", S.WellDefinition)


def test_the_flat_shape_written_by_a_user_has_the_registry_ladder():
    user = UserWell("flat_user", FLAT, PAPER)
    mine, registry = S.ladder(user), S.ladder("flat")
    for n in (1, 3):
        check_equal(user, mine, registry, user.values(beta=0.3, n=n), n)


def check_equal(user, mine, registry, at_user, n):
    at_registry = {S.alpha: sp.Rational(1, 2), S.beta: sp.Rational(3, 10), S.gamma: 1, S.n: n}
    point = {
        x: sp.Rational(1, 7),
        y: sp.Rational(-1, 5),
        X: sp.Rational(1, 3),
        mu: sp.Rational(1, 5),
    }
    pairs = [
        (mine.hamiltonian, registry.hamiltonian),
        *zip(mine.force, registry.force, strict=True),
        *zip(mine.hessian, registry.hessian, strict=True),
        *((mine.equations_of_motion[q], registry.equations_of_motion[q]) for q in (X, x, y)),
        (S.normal_mode(user, at_user).hill_coefficient, registry.normal_mode.hill_coefficient),
    ]
    for a, b in pairs:
        p = {
            s: sp.Rational(1, 11) for s in a.free_symbols | b.free_symbols if s.name.startswith("p")
        }
        va = a.subs(at_user).subs(point | p)
        vb = b.subs(at_registry).subs(point | p)
        assert abs(sp.N(va - vb, 50)) <= 1e-40 * (1 + abs(sp.N(vb, 50))), (a, b)
    assert mine.separable.masses == registry.separable.masses == (1, mu, mu)


@pytest.mark.parametrize("n", [1, 3])
def test_the_hill_coefficient_is_the_rescaled_one_unscaled(n):
    # independent path: rescaled_equations rescales q = L xbar, t = L sqrt(mu/gamma) tbar, so
    # q_bar(xbar) = (mu L^2 / gamma) q(L xbar), with q = V_yy(x, 0) / mu from the ladder
    q = S.normal_mode("flat").hill_coefficient
    q_bar = S.rescaled_equations("flat", n).hill_coefficient
    at = {
        S.alpha: sp.Rational(1, 2),
        S.beta: sp.Rational(-3, 10),
        S.gamma: sp.Rational(7, 5),
        S.n: n,
    }
    L = at[S.alpha] - at[S.beta]
    for xv in (sp.Rational(1, 3), sp.Rational(-4, 5)):
        mine = mu * L**2 / at[S.gamma] * q.subs(at).subs(x, L * xv)
        assert sp.simplify(mine - q_bar.subs(at).subs(x, xv)) == 0


def test_the_elliptic_well_ladder_in_closed_form():
    well = UserWell("ellipse", ELLIPTIC, {"a": 0.3, "b": 0.2, "gamma": 1, "n": 3})
    steps = S.ladder(well)
    a, b, gamma, n = well.parameter_symbols
    mode = steps.normal_mode
    assert mode.invariant
    # typed independently: V_yy(x, 0) / mu = gamma / (mu b^2) (x / a)^(2n - 2)
    expected = gamma / (mu * b**2) * (x / a) ** (2 * n - 2)
    probe = {a: sp.Rational(3, 10), b: sp.Rational(1, 5), gamma: 2, x: sp.Rational(1, 7), mu: 3}
    for k in (1, 2, 5):
        assert sp.simplify((mode.hill_coefficient - expected).subs(n, k).subs(probe)) == 0
    # the force is -grad V, the y equation mu ydd = -dV/dy
    V = gamma / (2 * n) * ((x / a) ** 2 + (y / b) ** 2) ** n
    assert sp.simplify(steps.force[1] + sp.diff(V, y)) == 0
    assert sp.simplify(mu * steps.equations_of_motion[y] + sp.diff(V, y)) == 0


def _at_point(form, expr, values, point):
    """expr (in the atoms of ``form``) at a point: the atoms computed in order."""
    at = dict(values) | point
    for atom, definition in form.atoms:
        at[atom] = definition.subs(at)
    return expr.subs(at)


@pytest.mark.parametrize("text", [ELLIPTIC, FLAT, HH + " + (x**2 + y**2)**2"])
def test_the_kernel_form_differentiates_through_atoms_to_the_plain_derivatives(text):
    well = UserWell("w", text, PAPER if "alpha" in text else {"a": 0.3, "b": 0.2,
                    "gamma": 1, "n": 3} if "a)" in text else {})  # fmt: skip
    form = S.kernel_form(well)
    V = well.potential
    plain = (sp.diff(V, x), sp.diff(V, y), sp.diff(V, x, 2), sp.diff(V, x, y), sp.diff(V, y, 2))
    mine = (*S.gradient_in_ratios(form), *S.hessian_in_ratios(form))
    values = well.values()
    for point in ({x: sp.Rational(1, 7), y: sp.Rational(-1, 9)}, {x: sp.Rational(-1, 5), y: 0}):
        for a, b in zip(mine, plain, strict=True):
            va, vb = _at_point(form, a, values, point), b.subs(values | point)
            assert abs(sp.N(va - vb, 40)) <= 1e-30 * (1 + abs(sp.N(vb, 40))), (a, b)


def test_the_kernel_form_is_finite_at_the_centre_where_sympy_gives_nan():
    well = UserWell("ellipse", ELLIPTIC, {"a": 0.3, "b": 0.2, "gamma": 1, "n": 3})
    values = {s.name: float(v) for s, v in well.values().items()}

    def in_floats(expr, atoms=()):
        """expr at (0.0, 0.0) in float64, the atoms computed in order, as a kernel would."""
        at = {"x": 0.0, "y": 0.0, **values}
        for atom, definition in atoms:
            at[atom.name] = float(sp.lambdify(list(definition.free_symbols), definition)(
                *(at[s.name] for s in definition.free_symbols)))  # fmt: skip
        names = sorted(expr.free_symbols, key=str)
        with np.errstate(all="ignore"):
            return float(
                sp.lambdify(names, expr, "numpy")(*(np.float64(at[s.name]) for s in names))
            )

    assert math.isnan(in_floats(sp.diff(well.potential, y)))  # 0/0 as SymPy writes it
    form = S.kernel_form(well)
    assert [in_floats(g, form.atoms) for g in S.gradient_in_ratios(form)] == [0.0, 0.0]
    # the registry's flat shape written by a user gets the registry's atoms: D(y), x / D(y)
    flat = S.kernel_form(UserWell("flat_user", FLAT, PAPER))
    alpha, beta = flat.parameter_symbols[:2]
    assert [d for _, d in flat.atoms] == [alpha + beta * (y**2 - 1), x / flat.atoms[0][0]]


def test_a_well_without_the_normal_mode_says_why():
    mode = S.ladder(UserWell("hh", HH, {})).normal_mode
    assert not mode.invariant and mode.hill_coefficient is None
    assert mode.reason == "dV/dy(x, 0) = x**2, not identically 0"
    with pytest.raises(ValueError, match="registered shapes only"):
        S.rescaled_equations(UserWell("hh", HH, {}))


def test_a_parameter_may_not_take_a_name_of_the_mechanics():
    with pytest.raises(ValueError, match="parameters: 'mu' is refused: a reserved name"):
        UserWell("w", "mu*(x**2 + y**2)", {"mu": 1.0})


# --- the command --------------------------------------------------------------------------
WELL_FILE = """name = "{name}"
potential = "{potential}"
[parameters]
{parameters}
"""


def write_well(tmp_path, name, potential, parameters=""):
    path = tmp_path / f"{name}.toml"
    path.write_text(WELL_FILE.format(name=name, potential=potential, parameters=parameters))
    return path


def test_derive_well_prints_the_ladder(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = write_well(tmp_path, "hh", HH)
    code, out, err = run_cli(["derive", "--well", str(path)], capsys)
    assert code == 0 and err == ""
    assert "the saddle at" in out and "y = 0 is not invariant" in out
    code, out, _ = run_cli(["derive", "--well", str(path), "--json"], capsys)
    data = json.loads(out)
    assert abs(data["escape_energy"] - 1 / 6) <= 1e-15
    assert {"hamiltonian", "xdd", "ydd", "Xdd", "force_x", "hessian_yy"} <= set(data)
    assert "hill_coefficient" not in data
    V = sp.sympify(data["potential"])  # the test's own constant: sympify is safe here
    assert sp.expand(V - sp.sympify(HH)) == 0
    code, out, _ = run_cli(["derive", "--well", str(path), "--latex"], capsys)
    assert code == 0 and out.startswith("% well hh") and r"\frac{x^{2}}{2}" in out
    # measured from V(0, 0), as `well` reports it: the saddles stay 1/6 above the centre
    lifted = write_well(tmp_path, "hh1", "1 + " + HH)
    code, out, _ = run_cli(["derive", "--well", str(lifted), "--json"], capsys)
    data = json.loads(out)
    assert code == 0 and abs(data["escape_energy"] - 1 / 6) <= 1e-15
    assert data["escape"].startswith("escape energy 0.166666666666667 above V(0, 0) = 1: ")


@pytest.mark.parametrize(
    "potential,parameters,reason",
    [
        ("__import__('os').system('touch pwned')", "", "attribute access"),
        ("x**2", "", "not confining"),
        ("x**2 + y**2 - k", "", "a name that is not declared"),
        ("(x/a)**2 + y**2", "a = { default = 0.0, range = [-1, 1] }", "not real and finite"),
    ],
)
def test_derive_refuses_a_bad_well_with_one_line_and_writes_nothing(
    potential, parameters, reason, tmp_path, capsys, monkeypatch
):
    path = write_well(tmp_path, "bad", potential, parameters)
    monkeypatch.chdir(tmp_path)
    before = snapshot(tmp_path)
    code, out, err = run_cli(["derive", "--well", str(path)], capsys)
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("sinktheory derive: error: "), err
    assert reason in lines[0], lines[0]
    assert snapshot(tmp_path) == before


def test_derive_refuses_a_missing_file(tmp_path, capsys):
    code, out, err = run_cli(["derive", "--well", str(tmp_path / "none.toml")], capsys)
    assert code == 2 and out == "" and "cannot be read" in err and len(err.splitlines()) == 1


def test_the_guide_well_file_derives(capsys):
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "docs" / "guide" / "elliptic.toml"
    code, out, _ = run_cli(["derive", "--well", str(path), "--json"], capsys)
    data = json.loads(out)
    assert code == 0 and data["well"] == load_well(path).name
    assert "hill_coefficient" in data and data["normal_mode"].startswith("y = 0 is a normal mode")


# --- parameters named like SymPy's functions and constants ---------------------------------
#: gamma and beta are SymPy functions, E is Euler's number: as parameters they are symbols
GBE = "gamma*x**2/2 + beta*y**2/2 + E*(x**2 + y**2)**2"
GBE_PARAMETERS = {"gamma": 1.5, "beta": 2.0, "E": 0.5}


def test_parameters_named_like_sympy_functions_are_plain_symbols(tmp_path, capsys):
    """Parsed as real symbols (potential and wall ratios), printed by their plain names in
    every JSON string of `derive --well` (which printed Symbol('gamma') before), read back
    with those names to the ladder typed here by hand, and passed to the engine as its own
    run-time parameters."""
    from _cli import write_well_file

    from sinktheory.engine.printer import render
    from sinktheory.engine.systems import sink_system

    path = write_well_file(tmp_path, "gbe", GBE, GBE_PARAMETERS, ["sqrt(x**2 + y**2)/(E + beta)"])
    well = load_well(path)
    for expr in (well.potential, *well.wall_ratios):
        assert not expr.atoms(sp.Function) and sp.E not in expr.atoms(sp.NumberSymbol)
        assert {s.name for s in expr.free_symbols} <= {"x", "y", *GBE_PARAMETERS}
        assert all(type(s) is sp.Symbol and s.is_real for s in expr.free_symbols)
    code, out, err = run_cli(["derive", "--well", str(path), "--json"], capsys)
    assert code == 0, err
    data = json.loads(out)
    texts = [v for k, v in data.items() if k not in ("well", "escape", "normal_mode")
             and isinstance(v, str)]  # fmt: skip
    assert len(texts) >= 14 and not [t for t in texts if "Symbol" in t]
    assert data["parameters"] == GBE_PARAMETERS
    assert data["potential"] == "E*(x**2 + y**2)**2 + beta*y**2/2 + gamma*x**2/2"
    # read back with the parameters' names as symbols: the forces and Hill's coefficient
    # of the potential typed here
    g, b, e, x_, y_, mu_ = sp.symbols("gamma beta E x y mu")
    names = {"gamma": g, "beta": b, "E": e}
    V = g * x_**2 / 2 + b * y_**2 / 2 + e * (x_**2 + y_**2) ** 2
    for key, want in (("potential", V), ("force_x", -sp.diff(V, x_)),
                      ("force_y", -sp.diff(V, y_)),
                      ("hill_coefficient", sp.diff(V, y_, 2).subs(y_, 0) / mu_)):  # fmt: skip
        assert sp.simplify(sp.sympify(data[key], locals=names) - want) == 0, key
    for flag, shown in (([], "γ"), (["--latex"], r"\gamma")):
        code, out, _ = run_cli(["derive", "--well", str(path), *flag], capsys)
        assert code == 0 and shown in out and "Symbol" not in out
    engine = render(sink_system(well), "# gbe")
    assert {"par_gamma", "par_beta", "par_E"} <= set(re.findall(r"\bpar_\w+", engine))


def test_a_parameter_named_like_a_name_of_the_printed_code():
    """abs is a name the numerical functions' code calls (|terms| of the basin's scale):
    as a parameter it no longer shadows it.  The bowl k (x^2 + y^2)/2 reaches
    sqrt(2 e / k) along each axis."""
    from sinktheory.wellat import WellAt

    bowl = WellAt(UserWell("bowl", "abs*(x**2 + y**2)/2 + numpy*x**4", {"abs": 1.5, "numpy": 0.0}))
    for reach in bowl.reach(0.1):
        assert reach == pytest.approx(math.sqrt(2 * 0.1 / 1.5), rel=1e-12)


@pytest.mark.parametrize("name", ["lambda", "None", "if"])
def test_a_python_keyword_is_not_a_parameter_name(name):
    with pytest.raises(ValueError, match=f"'{name}' is refused: a Python keyword"):
        UserWell("w", "x**2 + y**2", {name: 1.0})
