"""Every command against two well files: the elliptic well of ``docs/guide/elliptic.toml``
(at n = 3, wall ratios declared) and Hénon–Heiles lifted by 1 (``LIFTED_HH``: no wall
ratios, y = 0 not invariant).  Each (command, well) either runs at the smallest sizes
(exit 0, output naming the well, one number checked where cheap) or is refused with the
reason (exit 2, one line, nothing written).  The table "Every command" in
docs/guide/user_wells.rst is this file's table in words.

References: closed forms of the ellipse (reach a (2 n e / gamma)^(1/2n), Hill coefficient
(x/a)^(2n-2) / b^2, area pi a b, the law's mean fraction 1/(1 + k (1 + 1/n))),
Hénon–Heiles' escape energy 1/6, the law of the unlifted Hénon–Heiles well (the lift by 1
must change nothing), and the fixed stepper beside the adaptive one (a second method).
The engines are those other tests compile (the elliptic well's, Hénon–Heiles lifted)."""

import json
import math
import warnings
from pathlib import Path

import pytest
import sympy as sp
from _cli import HH, LIFTED_HH, refused_well, run_cli, write_well_file
from scipy import special

ELLIPSE = str(Path(__file__).parents[2] / "docs" / "guide" / "elliptic.toml")
A, B, N = 0.3, 0.2, 3  # the file's semi-axes, n given below
#: the options that pick each well, and the energies each holds (Hénon–Heiles escapes at 1/6)
WELLS = {
    "elliptic": (["--well", ELLIPSE, "--well-param", f"n={N}"], "0.5"),
    "hh": (["--well", "hh.toml"], "0.02"),
}
NOT_INVARIANT = "dV/dy(x, 0) = x**2, not identically 0"


def ellipse_reach_x(e):
    return A * (2 * N * e) ** (1 / (2 * N))


def law_fraction(k):
    return 1 / (1 + k * (1 + 1 / N))


def hh_law_mean(k, total):
    from sinktheory.equilibrium import well_law
    from sinktheory.userwell import UserWell

    return well_law(UserWell("plain", HH, {}), k, total).mean


def simulate_fixed(argv, capsys):
    """The container energies of the same run with the fixed stepper."""
    fixed = [a for a in argv if a not in ("--stepper", "adaptive")]
    code, out, err = run_cli([*fixed, "--json"], capsys)
    assert code == 0, err
    return json.loads(out)["mean_energy"]


def check_simulate_adaptive(d, argv, capsys, _well):
    assert d["mean_energy"] == pytest.approx(simulate_fixed(argv, capsys), abs=1e-9)


def check_sweep(d, argv, capsys, well):
    import xarray as xr

    ds = xr.open_zarr(d["store"])
    assert f'name = "{well}"' in ds.attrs["well"] and bool(ds.done.all())


def check_design_hh(d, *_):
    """Hénon–Heiles is harmonic at its centre: n = 1, the share E/(1 + 2k) of the total."""
    import xarray as xr

    ds = xr.open_zarr(d["store"])
    assert bool(ds.done.all()) and ds.attrs["particles"] == 2
    share = ds.total_energy.values / (1 + 2 * 2)
    assert abs(ds.equipartition.values - share).max() <= 1e-12 * share.max()


def check_well_hh(d, *_):
    assert abs(d["escape_energy"] - 1 / 6) < 1e-14 and not d["y_invariant"]


def check_derive(d, argv, capsys, well):
    x, y, a, b, gamma, n = sp.symbols("x y a b gamma n")
    want = gamma / (2 * n) * ((x / a) ** 2 + (y / b) ** 2) ** n if well == "elliptic" else (
        1 + (x**2 + y**2) / 2 + x**2 * y - y**3 / 3)  # fmt: skip
    names = {"x": x, "y": y, "a": a, "b": b, "n": n, "gamma": gamma}
    difference = sp.sympify(d["potential"], locals=names) - want
    point = {x: 0.11, y: -0.07, a: 0.3, b: 0.2, gamma: 1.3, n: 3}
    assert abs(float(difference.subs(point))) < 1e-15


def check_floquet_ellipse(d, *_):
    x = sp.Symbol("x")
    hill = sp.sympify(d["hill_coefficient"])
    assert sp.simplify(hill - (x / sp.Rational(3, 10)) ** 4 / sp.Rational(1, 5) ** 2) == 0
    assert d["particle_energy"] == pytest.approx((0.1 / A) ** (2 * N) / (2 * N), rel=1e-12)


def check_billiard_ellipse(d, *_):
    assert d["table"]["area"] == pytest.approx(math.pi * A * B, rel=1e-12)
    perimeter = 4 * A * special.ellipe(1 - (B / A) ** 2)  # measured 7e-13
    assert d["table"]["perimeter"] == pytest.approx(perimeter, rel=1e-11)


#: (command, well, arguments after the well's, what to expect): a check of the JSON (a
#: function of (data, argv, capsys, well)), None (exit 0 and the well named), or the
#: refusal's reason.  "E0" stands for the well's container energy.
ROWS = [
    ("well", "elliptic", [],
     lambda d, *_: pytest.approx(ellipse_reach_x(0.5), rel=1e-10) == d["reach"]["x"]),
    ("well", "hh", ["--particle-energy", "0.1"], check_well_hh),
    ("sink", "elliptic", ["--particles", "2"],
     lambda d, *_: pytest.approx(ellipse_reach_x(0.5), rel=1e-6) == d["reach"]["x"]),
    ("sink", "hh", ["--particles", "2", "--container-energy", "E0"], None),
    ("derive", "elliptic", [], check_derive),
    ("derive", "hh", [], check_derive),
    *[("simulate", w, ["--particles", "2", "--runs", "2", "--periods", "2",
                       "--container-energy", "E0", *step], check)
      for w in WELLS
      for step, check in (([], None), (["--stepper", "adaptive"], check_simulate_adaptive))],
    ("chaos", "elliptic", ["--particles", "2", "--runs", "2", "--periods", "3", "--transverse"],
     None),
    ("chaos", "hh", ["--particles", "2", "--runs", "2", "--periods", "3",
                     "--container-energy", "E0"], None),
    ("chaos", "hh", ["--container-energy", "E0", "--transverse"], NOT_INVARIANT),
    ("floquet", "elliptic", ["--amplitude", "0.1"], check_floquet_ellipse),
    ("floquet", "hh", ["--amplitude", "0.1"], NOT_INVARIANT),
    ("nnm", "elliptic", ["--continue-in", "energy", "--total-energy", "1e-3", "--interval",
                         "5e-4", "2e-3", "--points", "3", "--steps", "200"], None),
    ("nnm", "hh", ["--continue-in", "energy"], NOT_INVARIANT),
    ("equilibrium", "elliptic", ["--particles", "2"],
     lambda d, *_: pytest.approx(law_fraction(2), rel=1e-12) == d["law"]["mean_fraction"]),
    ("equilibrium", "hh", ["--particles", "2", "--total-energy", "0.05"],
     lambda d, *_: pytest.approx(hh_law_mean(2, 0.05), rel=1e-12) == d["law"]["mean"]),
    ("lifetime", "elliptic", ["--particles", "2", "--runs", "2", "--periods", "6"],
     lambda d, *_: pytest.approx(law_fraction(2), rel=1e-12) == d["law"]["mean_fraction"]),
    ("lifetime", "hh", ["--particles", "2", "--runs", "2", "--periods", "6",
                        "--container-energy", "E0"],
     lambda d, *_: pytest.approx(hh_law_mean(2, d["law"]["total_energy"]), rel=1e-12)
     == d["law"]["mean"]),
    ("billiard", "elliptic", ["--runs", "2", "--periods", "3"], check_billiard_ellipse),
    ("billiard", "hh", [], "a rigid table needs the wall ratios"),
    ("compare", "elliptic", ["--attachments", "well", "--particles", "2", "--damping", "0.05",
                             "--energies", "E0", "E0", "1", "--runs", "2", "--periods", "4",
                             "--quiet"],
     lambda d, *_: d["max_audit_error"][0][0] < 1e-6),
    ("compare", "hh", ["--attachments", "well", "--particles", "2", "--damping", "0.05",
                       "--energies", "E0", "E0", "1", "--runs", "2", "--periods", "4", "--quiet"],
     lambda d, *_: d["max_audit_error"][0][0] < 1e-6),
    *[("sweep", w, [kind, "--param", "container_energy=E0", *extra, "--out", "s.zarr",
                    "--workers", "1", "--quiet"], check_sweep)
      for w in WELLS
      for kind, extra in (("bifurcation", ["--param", "transient=2", "--param", "count=3"]),
                          ("ensemble", ["--param", "particles=2", "--param", "runs=2",
                                        "--param", "periods=2"]),
                          ("chaos", ["--param", "runs=2", "--param", "periods=3"]),
                          ("ergodicity", ["--param", "runs=2", "--param", "periods=8",
                                          "--param", "transient=2", "--param",
                                          "lyapunov_runs=0"]))],
    ("sweep", "hh", ["chaos", "--param", "container_energy=E0", "--param", "transverse=1",
                     "--out", "s.zarr", "--quiet"], NOT_INVARIANT),
    ("sweep", "elliptic", ["floquet", "--param", "amplitude=0.2", "--out", "s.zarr",
                           "--workers", "1", "--quiet"], check_sweep),
    ("sweep", "hh", ["floquet", "--param", "amplitude=0.2", "--out", "s.zarr"], NOT_INVARIANT),
    # design: --well puts the well on the shape axis; Hénon–Heiles' equipartition share
    # is that of its leading term at the centre, harmonic (n = 1)
    ("sweep", "hh", ["design", "--param", "beta=0.3", "--param", "n=4",
                     "--param", "container_energy=E0", "--param", "particles=2",
                     "--param", "runs=2", "--param", "periods=4", "--param", "horizons=2+4",
                     "--param", "bootstrap=10", "--param", "lyapunov_runs=0", "--out",
                     "s.zarr", "--workers", "1", "--quiet"], check_design_hh),
    ("relaxation", "elliptic", ["--particles", "2"], "the relaxation model reads a registered"),
    ("period", "hh", ["--n", "2"], "it has no well"),
    ("series", "hh", [], "it has no well"),
    ("reproduce", "hh", [], "the paper's figures are drawn for the registered shapes"),
]  # fmt: skip
#: design takes a well file on its shape axis (its --shape), not as --well
DESIGN = ["--beta", "0.3", "--n", "3", "--runs", "2", "--periods", "12", "--horizons", "6,12",
          "--bootstrap", "10", "--lyapunov-runs", "2", "--lyapunov-periods", "5", "--out",
          "d.zarr", "--workers", "1", "--no-estimate", "--quiet"]  # fmt: skip


def ids(row):
    command, well, args, expect = row
    word = args[0] if command == "sweep" else ""
    word += "-refused" if isinstance(expect, str) else "-runs"
    extra = "-adaptive" if "adaptive" in args else "-transverse" if "--transverse" in args else ""
    return f"{command}-{word}{extra}-{well}"


@pytest.fixture
def here(tmp_path, monkeypatch):
    """A directory holding hh.toml (Hénon–Heiles lifted by 1), the working directory."""
    write_well_file(tmp_path, "hh", LIFTED_HH)
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.mark.parametrize("row", ROWS, ids=[ids(r) for r in ROWS])
def test_every_command_runs_a_well_file_or_says_why_not(row, here, capsys, monkeypatch):
    command, well, args, expect = row
    options, energy = WELLS[well]
    args = [a.replace("E0", energy) for a in args]
    argv = [command, *([args[0]] if command == "sweep" else []), *options,
            *(args[1:] if command == "sweep" else args)]  # fmt: skip
    if isinstance(expect, str):
        refused_well(argv, capsys, here, monkeypatch, expect)
        return
    with warnings.catch_warnings(record=True) as caught:  # none reaches the terminal
        warnings.simplefilter("always")
        code, out, err = run_cli([*argv, "--json"], capsys)
    assert code == 0, err
    assert not caught, caught[0].message
    if command != "sweep":  # (a sweep's store holds the well: check_sweep)
        assert f'"{well}"' in out, out[:300]  # the well is named
    if expect is not None:
        assert expect(json.loads(out), argv, capsys, well) in (None, True)


@pytest.mark.parametrize("well,reason", [
    ("elliptic", None),
    ("valley", "must be a well whose leading term at the centre is a form positive in every "
               "direction"),
])  # fmt: skip
def test_design_takes_a_well_file_on_its_shape_axis(well, reason, here, capsys, monkeypatch):
    """A well whose leading term x^2 vanishes along y (x^2 + y^4) has no equipartition
    share of its leading order: refused."""
    write_well_file(here, "valley", "x**2 + y**4")
    path = ELLIPSE if well == "elliptic" else "valley.toml"
    argv = ["design", "--shape", path, *DESIGN]
    if reason:
        refused_well(argv, capsys, here, monkeypatch, reason)
        return
    code, out, err = run_cli([*argv, "--json"], capsys)
    assert code == 0, err
    import xarray as xr

    ds = xr.open_zarr("d.zarr")
    assert ds.attrs["shape"] == "elliptic"
    assert 'name = "elliptic"' in json.loads(ds.attrs["wells"])["elliptic"]
    designs = json.loads(out)["designs"]
    assert all(d["settles_note"].startswith("n/a: a user's well") for d in designs)
