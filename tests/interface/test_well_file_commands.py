"""``--well FILE`` on the commands that need no compiled engine (well, floquet,
equilibrium, billiard, derive): the built-in shapes typed as well files give the
registry's numbers, an elliptic and a Henon-Heiles well file give closed forms or
independent quadratures, and a bad well or a well a command cannot use is refused with
one line, exit 2, nothing written."""

import math

import numpy as np
import pytest
from _cli import BUILT_IN, ELLIPTIC, HH, PAPER, cli_json, refused_well, write_well_file
from scipy import integrate, optimize, special

ELLIPSE = {"a": 0.3, "b": 0.25, "gamma": 1.0, "n": (4, (1, 20))}
#: the built-in shapes' rigid walls, as wall ratios (level 1 on the wall)
WALLS = {
    "flat": ["x/(alpha + beta*(y**2 - 1))", "y"],
    "circular": ["sqrt(x**2 + y**2)/(alpha - beta)"],
}


@pytest.fixture
def files(tmp_path):
    """Well files: the built-in shapes (the paper's parameters), an ellipse, Henon-Heiles."""
    out = {s: write_well_file(tmp_path, f"{s}_user", BUILT_IN[s], PAPER, WALLS.get(s, ()))
           for s in BUILT_IN}  # fmt: skip
    out["ellipse"] = write_well_file(tmp_path, "ellipse", ELLIPTIC, ELLIPSE,
                                     ["sqrt((x/a)**2 + (y/b)**2)"])  # fmt: skip
    out["hh"] = write_well_file(tmp_path, "hh", HH)
    return {k: str(v) for k, v in out.items()}


# --- well -----------------------------------------------------------------------------------
def test_well_reports_the_henon_heiles_saddle_and_reach(files, capsys):
    data = cli_json(["well", "--well", files["hh"], "--particle-energy", "0.1"], capsys)
    assert abs(data["escape_energy"] - 1 / 6) <= 1e-15 and not data["y_invariant"]
    # the basin at e: |x| <= max over y of sqrt((e - y^2/2 + y^3/3) / (1/2 + y)); y from
    # the roots of e = y^2/2 - y^3/3 on the axis x = 0
    best = optimize.minimize_scalar(lambda y: -(0.1 - y * y / 2 + y**3 / 3) / (0.5 + y),
                                    bounds=(-0.4, 0.5), method="bounded",
                                    options={"xatol": 1e-12})  # fmt: skip
    y_roots = [optimize.brentq(lambda y: y * y / 2 - y**3 / 3 - 0.1, a, b, xtol=1e-15)
               for a, b in ((-1, 0), (0, 1))]  # fmt: skip
    assert data["reach"]["x"] == pytest.approx(math.sqrt(-best.fun), rel=1e-11)
    assert data["reach"]["y"] == pytest.approx(max(abs(r) for r in y_roots), rel=1e-12)


def test_well_draws_the_level_lines_of_a_well_file(files, capsys, tmp_path):
    path = tmp_path / "hh.png"
    data = cli_json(["well", "--well", files["hh"], "--particle-energy", "0.15", "--plot",
                     str(path)], capsys)  # fmt: skip
    assert data["plot"] == str(path) and path.read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize("shape,beta", [("flat", -0.2), ("circular", 0.3)])
def test_well_gives_the_registry_reach(shape, beta, files, capsys):
    user = cli_json(["well", "--well", files[shape], "--well-param", f"beta={beta}"], capsys)
    registry = cli_json(["well", "--shape", shape, "--alpha", "0.5", "--beta", str(beta),
                         "--n", "4"], capsys)  # fmt: skip
    for axis in ("x", "y"):
        assert user["reach"][axis] == pytest.approx(registry["reach"][axis], rel=1e-12)


# --- equilibrium ----------------------------------------------------------------------------
def test_equilibrium_of_the_elliptic_file_is_the_beta_law(files, capsys):
    data = cli_json(["equilibrium", "--well", files["ellipse"], "--particles", "2",
                     "--well-param", "n=3"], capsys)  # fmt: skip
    b = 2 * (1 + 1 / 3)
    assert data["law"]["mean_fraction"] == pytest.approx(1 / (1 + b), rel=1e-12)
    assert data["tails"][3] == pytest.approx(0.5**b, rel=1e-12)  # f = 0.5
    assert data["law"]["alpha"] is None and data["law"]["parameters"]["n"] == 3.0


@pytest.mark.parametrize("shape,beta,n", [("symmetric", 0.1, 3)])  # the others: test_well_law
def test_equilibrium_of_the_built_in_files_is_the_registry_law(shape, beta, n, files, capsys):
    common = ["--particles", "3", "--total-energy", "0.2"]
    user = cli_json(["equilibrium", "--well", files[shape], "--well-param", f"beta={beta}",
                     "--well-param", f"n={n}", *common], capsys)  # fmt: skip
    registry = cli_json(["equilibrium", "--shape", shape, "--alpha", "0.5", "--beta",
                         str(beta), "--n", str(n), *common], capsys)  # fmt: skip
    assert user["law"]["mean"] == pytest.approx(registry["law"]["mean"], rel=1e-12)
    assert user["tails"] == pytest.approx(registry["tails"], rel=1e-12)


# --- floquet --------------------------------------------------------------------------------
@pytest.mark.parametrize("shape,beta,n,a0", [("flat", 0.3, 4, 1.0), ("flat", -0.4, 1, 0.7),
                                             ("symmetric", 0.2, 2, 1.0),
                                             ("symmetric", -0.3, 1, 0.5)])  # fmt: skip
def test_floquet_of_the_built_in_files_is_the_registry_chart(shape, beta, n, a0, files, capsys):
    registry = cli_json(["floquet", "--shape", shape, "--alpha", "0.5", "--beta", str(beta),
                         "--n", str(n), "--amplitude", str(a0)], capsys)  # fmt: skip
    # the registry's x is in units of the wall distance alpha - beta
    user = cli_json(
        [
            "floquet",
            "--well",
            files[shape],
            "--well-param",
            f"beta={beta}",
            "--well-param",
            f"n={n}",
            "--amplitude",
            str(a0 * (0.5 - beta)),
        ],
        capsys,
    )
    assert user["symmetric"] and user["stable"] == registry["stable"]
    # measured: 1.1e-14 and 5.5e-14 at most
    assert user["phi_half"] == pytest.approx(registry["phi_half"], abs=1e-12)
    assert user["phi"] == pytest.approx(registry["phi"], abs=1e-12)


def test_floquet_of_the_circular_file_is_neutral(files, capsys):
    data = cli_json(["floquet", "--well", files["circular"], "--amplitude", "0.15"], capsys)
    assert data["phi_half"] == pytest.approx(-1.0, abs=1e-12)  # y = eps x(t) solves it


def test_floquet_of_a_harmonic_ellipse_is_cos_pi_a_over_b(files, capsys):
    # n = 1: x = A cos(t / a), y'' + y / b^2 = 0: phi_half = cos(pi a / b)
    data = cli_json(["floquet", "--well", files["ellipse"], "--well-param", "n=1",
                     "--amplitude", "0.1"], capsys)  # fmt: skip
    assert data["phi_half"] == pytest.approx(math.cos(math.pi * 0.3 / 0.25), abs=1e-12)


@pytest.mark.parametrize("c", [0.3, 1.1])
def test_floquet_without_symmetry_is_the_full_period_monodromy(c, tmp_path, capsys):
    # V = r^2/2 + c x y^2: x = A cos t exactly, and y'' + (1 + 2 c A cos t) y = 0 is
    # integrated here over the whole period from that closed form (no reversibility)
    path = write_well_file(tmp_path, "tilted", "(x**2 + y**2)/2 + c*x*y**2", {"c": c})
    A = 0.4
    data = cli_json(["floquet", "--well", str(path), "--amplitude", str(A)], capsys)

    def rhs(t, s):
        q = 1 + 2 * c * A * math.cos(t)
        return [s[1], -q * s[0], s[3], -q * s[2]]

    end = integrate.solve_ivp(rhs, (0, 2 * math.pi), [1, 0, 0, 1], method="DOP853",
                              rtol=1e-13, atol=1e-15).y[:, -1]  # fmt: skip
    assert not data["symmetric"] and data["phi_half"] is None
    assert data["period"] == pytest.approx(2 * math.pi, rel=1e-11)
    assert data["phi"] == pytest.approx((end[0] + end[3]) / 2, abs=1e-12)


def test_floquet_of_henon_heiles_turned_is_the_monodromy_over_the_quadrature_period(
    tmp_path, capsys
):
    # Henon-Heiles with x and y swapped: y = 0 is one of its invariant lines; on it
    # x'' = -(x - x^2) (V = x^2/2 - x^3/3, no symmetry) and y'' + (1 + 2 x) y = 0.  The
    # period from the energy integral (an independent quadrature), then the monodromy over
    # that whole period, without the reversibility the command uses
    path = write_well_file(tmp_path, "hh_turned", "(x**2 + y**2)/2 + y**2*x - x**3/3")
    A = 0.3
    data = cli_json(["floquet", "--well", str(path), "--amplitude", str(A)], capsys)
    e = A * A / 2 - A**3 / 3
    B = optimize.brentq(lambda x: x * x / 2 - x**3 / 3 - e, -1.0, 0.0, xtol=1e-16)
    mid, half = (A + B) / 2, (A - B) / 2

    def dt(phi):  # x = mid - half cos(phi): the square roots at the turning points cancel
        x = mid - half * math.cos(phi)
        return half * math.sin(phi) / math.sqrt(2 * max(e - x * x / 2 + x**3 / 3, 1e-300))

    period = 2 * integrate.quad(dt, 0.0, math.pi, epsabs=0, epsrel=1e-13)[0]  # open ends

    def rhs(t, s):
        x = s[0]
        return [s[1], -(x - x * x), s[3], -(1 + 2 * x) * s[2], s[5], -(1 + 2 * x) * s[4]]

    end = integrate.solve_ivp(rhs, (0, period), [A, 0, 1, 0, 0, 1], method="DOP853",
                              rtol=1e-13, atol=1e-16).y[:, -1]  # fmt: skip
    assert not data["symmetric"]
    assert data["period"] == pytest.approx(period, rel=1e-12)  # measured 8e-15
    assert data["phi"] == pytest.approx((end[2] + end[5]) / 2, abs=1e-12)  # measured 9e-15


def test_floquet_amplitude_chart_finds_the_mathieu_tongue(tmp_path, capsys):
    # V = (x^2 + k y^2)/2 + c x y^2: x = A cos t and y'' + (k + 2 c A cos t) y = 0, in
    # t = 2 tau Mathieu's y'' + (a - 2 q cos 2 tau) y = 0 with a = 4 k, q = -4 c A; at
    # k = 1.2 the motion is stable until a_2(q) = a (SciPy's characteristic value)
    path = write_well_file(tmp_path, "tilted", "(x**2 + k*y**2)/2 + c*x*y**2",
                           {"k": 1.2, "c": 0.3})  # fmt: skip
    data = cli_json(["floquet", "--well", str(path), "--amplitude-range", "0.5", "1.5", "5"],
                    capsys)  # fmt: skip
    q = optimize.brentq(lambda q: special.mathieu_a(2, q) - 4.8, 0.1, 3.0, xtol=1e-15)
    # the edge is a zero of one factor at the half period (no symmetry): 2 y2 y1' = phi - 1
    assert [(b["phi_half"], b["factor"] in ("y2", "dy1")) for b in data["boundaries"]] == [
        (1.0, True)
    ]
    assert data["boundaries"][0]["value"] == pytest.approx(q / 1.2, rel=1e-11)  # measured 6e-14
    assert data["stable_intervals"] == [[0.5, data["boundaries"][0]["value"]]]
    assert data["stable"] == [True, True, True, True, False]  # A = 0.5, 0.75, ..., 1.5


def test_floquet_refuses_henon_heiles_with_the_reason(files, capsys, tmp_path, monkeypatch):
    refused_well(["floquet", "--well", files["hh"], "--amplitude", "0.1"], capsys, tmp_path,
                 monkeypatch, "dV/dy(x, 0) = x**2, not identically 0")  # fmt: skip


# --- billiard -------------------------------------------------------------------------------
def test_billiard_of_the_elliptic_file_has_the_ellipse_table(files, capsys):
    data = cli_json(["billiard", "--well", files["ellipse"], "--fixed", "--runs", "2",
                     "--periods", "3"], capsys)  # fmt: skip
    assert data["table"]["area"] == pytest.approx(math.pi * 0.3 * 0.25, rel=1e-12)


@pytest.mark.parametrize("shape,beta", [("flat", 0.3), ("flat", -0.2), ("circular", 0.1)])
def test_billiard_of_the_built_in_files_is_the_registry_billiard(shape, beta, files, capsys):
    runs = ["--runs", "2", "--periods", "4", "--seed", "3"]
    user = cli_json(["billiard", "--well", files[shape], "--well-param", f"beta={beta}",
                     *runs], capsys)  # fmt: skip
    registry = cli_json(["billiard", "--shape", shape, "--alpha", "0.5", "--beta", str(beta),
                         *runs], capsys)  # fmt: skip
    assert user["table"]["area"] == pytest.approx(registry["table"]["area"], rel=1e-12)
    assert user["table"]["perimeter"] == pytest.approx(registry["table"]["perimeter"], rel=1e-12)
    user_e, registry_e = (np.ravel(d["container_energy"]) for d in (user, registry))
    assert user_e == pytest.approx(registry_e, abs=1e-9)


def test_billiard_refuses_a_well_without_wall_ratios(files, capsys, tmp_path, monkeypatch):
    refused_well(["billiard", "--well", files["hh"]], capsys, tmp_path, monkeypatch,
                 "a rigid table needs the wall ratios")  # fmt: skip


# --- bad wells and bad combinations, on every command that takes --well -------------------
COMMANDS = {
    "well": [],
    "derive": [],
    "equilibrium": [],
    "floquet": ["--amplitude", "0.1"],
    "billiard": ["--fixed"],
}


@pytest.mark.parametrize("command", sorted(COMMANDS))
@pytest.mark.parametrize(
    "potential,reason",
    [("__import__('os').system('touch pwned')", "attribute access"),
     ("x**2", "not confining"), ("x**2 + y**2 - k", "a name that is not declared")],
)  # fmt: skip
def test_a_bad_well_file_is_refused(command, potential, reason, capsys, tmp_path, monkeypatch):
    path = write_well_file(tmp_path, "bad", potential)
    refused_well([command, "--well", str(path), *COMMANDS[command]], capsys, tmp_path,
                 monkeypatch, reason)  # fmt: skip
    assert not (tmp_path / "pwned").exists()


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_a_parameter_outside_its_range_is_refused(command, files, capsys, tmp_path,
                                                  monkeypatch):  # fmt: skip
    refused_well([command, "--well", files["ellipse"], "--well-param", "n=40",
                  *COMMANDS[command]], capsys, tmp_path, monkeypatch, "outside")  # fmt: skip


@pytest.mark.parametrize("command", ["well", "equilibrium", "floquet", "billiard"])
def test_a_shape_option_beside_a_well_file_is_refused(command, files, capsys, tmp_path,
                                                     monkeypatch):  # fmt: skip
    refused_well([command, "--well", files["ellipse"], "--alpha", "0.5", *COMMANDS[command]],
                 capsys, tmp_path, monkeypatch, "well = ")  # fmt: skip


def test_the_equilibrium_law_refuses_a_well_without_a_power_law_area(capsys, tmp_path,
                                                                     monkeypatch):  # fmt: skip
    path = write_well_file(tmp_path, "valley", "x**2 + y**4")
    refused_well(["equilibrium", "--well", str(path), "--total-energy", "0.1"], capsys,
                 tmp_path, monkeypatch, "not positive along the direction")  # fmt: skip


def test_a_well_param_needs_a_well_file_and_a_number(files, capsys, tmp_path, monkeypatch):
    refused_well(["well", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--well-param",
                  "a=1"], capsys, tmp_path, monkeypatch, "well_param = 'a=1'")  # fmt: skip
    refused_well(["well", "--well", files["ellipse"], "--well-param", "a=big"], capsys,
                 tmp_path, monkeypatch, "NAME=VALUE, VALUE a number")  # fmt: skip
    refused_well(["well", "--well", files["ellipse"], "--well-param", "c=1"], capsys,
                 tmp_path, monkeypatch, "not a parameter of ellipse")  # fmt: skip
