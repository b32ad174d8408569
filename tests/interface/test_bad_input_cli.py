"""Adversarial input (issue 13): every bad input is refused cleanly, nothing is written.

Each CLI case must exit with status 2, print exactly one line on stderr naming the
parameter, no traceback, and leave the working directory as it was.
"""

import os
from pathlib import Path

import numpy as np
import pytest
from _cli import refused, run_cli, snapshot

from sinktheory.canonical import FIG8_WELL
from sinktheory.commands import _common
from sinktheory.errors import ParameterError

WELL = ["--alpha", "0.5", "--beta", "0.3", "--n", "4"]
SIM = ["simulate", *WELL, "--runs", "2", "--periods", "2", "--quiet"]
FLOQUET_SWEEP = ["sweep", "floquet", "--param", "alpha=0.5", "--param", "beta=0.1,0.2",
                 "--param", "n=4", "--out"]  # fmt: skip


# --------------------------------------------------------------------------- output paths
UNWRITABLE = [
    (["well", *WELL, "--plot", "/proc/x.png"], "plot"),
    (["well", *WELL, "--plot", "/proc/sub/x.png"], "plot"),
    (["well", *WELL, "--plot", "/sys/x.png"], "plot"),
    (["well", *WELL, "--plot", "d.png"], "plot"),  # a directory called d.png (made below)
    (["well", *WELL, "--plot", ""], "plot"),
    (["well", *WELL, "--plot", "missing/x.png"], "plot"),
    (["series", "--n", "2", "--order", "2", "--plot", "/proc/x.png"], "plot"),
    (
        [
            "floquet",
            "--alpha",
            "0.5",
            "--n",
            "4",
            "--beta-range",
            "0",
            "0.2",
            "3",
            "--plot",
            "/proc/x.png",
        ],
        "plot",
    ),
    ([*SIM, "--out", "/proc/x.npz"], "out"),
    ([*SIM, "--out", "d.png"], "out"),
    ([*SIM, "--out", "ok.npz", "--plot", "/proc/x.png"], "plot"),
    ([*SIM, "--out", "ok.npz", "--plot", "/sys/x.png"], "plot"),
    ([*SIM, "--out", "ok.npz", "--plot", "d.png"], "plot"),
    (
        [*FLOQUET_SWEEP, "/proc/s.zarr"],
        "out",
    ),
    (
        [*FLOQUET_SWEEP, ""],
        "out",
    ),
    (["reproduce", "--figure", "2", "--quick", "--out", "/proc/x"], "out"),
    (["reproduce", "--figure", "2", "--quick", "--out", "/proc/x/y"], "out"),
    (["reproduce", "--figure", "2", "--quick", "--out", ""], "out"),
    (["reproduce", "--figure", "2", "--quick", "--out", " "], "out"),
    (["reproduce", "--figure", "2", "--quick", "--out", "f.txt"], "out"),  # a file (below)
]


@pytest.mark.parametrize(("argv", "name"), UNWRITABLE, ids=lambda a: " ".join(a)[-40:])
def test_unwritable_outputs_are_refused_before_computing(argv, name, capsys, tmp_path, monkeypatch):
    (tmp_path / "d.png").mkdir()
    (tmp_path / "f.txt").write_text("keep")
    refused(argv, capsys, tmp_path, monkeypatch, name)
    assert (tmp_path / "f.txt").read_text() == "keep"


def test_read_only_directory_is_refused(capsys, tmp_path, monkeypatch):
    locked = tmp_path / "ro"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        if os.access(locked, os.W_OK) and os.geteuid() == 0:
            # root ignores permissions; a probe file tells the truth, so check it does
            probe = locked / "probe"
            probe.touch()
            probe.unlink()
            pytest.skip("running as root: permissions do not stop writes")
        refused(["well", *WELL, "--plot", "ro/x.png"], capsys, tmp_path, monkeypatch, "plot")
    finally:
        locked.chmod(0o700)


def test_all_outputs_or_none(capsys, tmp_path, monkeypatch):
    """A plot that fails while being written leaves no .npz behind either."""
    monkeypatch.chdir(tmp_path)

    class BrokenFigure:
        def savefig(self, path, **kwargs):
            Path(path).write_bytes(b"half a png")
            raise OSError(28, "No space left on device", str(path))

    from sinktheory.plot import simulate as drawing

    monkeypatch.setattr(drawing, "plot_ensemble_energy", lambda *args: BrokenFigure())
    code, _, err = run_cli([*SIM, "--out", "ok.npz", "--plot", "ok.png"], capsys)
    assert code == 1
    assert len(err.strip().splitlines()) == 1 and "No space left" in err
    assert snapshot(tmp_path) == set()


def test_outputs_are_written_when_all_succeed(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, _, err = run_cli([*SIM, "--out", "ok.npz", "--plot", "ok.png"], capsys)
    assert code == 0, err
    assert snapshot(tmp_path) == {"ok.npz", "ok.png"}
    assert (tmp_path / "ok.png").read_bytes()[:4] == b"\x89PNG"


def test_existing_output_is_replaced_whole(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "w.png").write_bytes(b"old")
    code, _, err = run_cli(["well", *WELL, "--plot", "w.png"], capsys)
    assert code == 0, err
    assert (tmp_path / "w.png").read_bytes()[:4] == b"\x89PNG"
    assert snapshot(tmp_path) == {"w.png"}


def test_directory_output_staged_and_moved(tmp_path):
    target = tmp_path / "a" / "b"

    def fill(path):
        path.mkdir(parents=True, exist_ok=True)
        (path / "one.txt").write_text("1")
        (path / "two.txt").write_text("2")

    _common.write_outputs({target: _common.as_directory(fill)})
    assert snapshot(tmp_path) == {"a", "a/b", "a/b/one.txt", "a/b/two.txt"}


def test_directory_output_failing_leaves_nothing(tmp_path):
    def fill(path):
        path.mkdir(parents=True, exist_ok=True)
        (path / "one.txt").write_text("1")
        raise OSError(28, "No space left on device")

    with pytest.raises(OSError):
        _common.write_outputs({tmp_path / "out": _common.as_directory(fill)})
    assert snapshot(tmp_path) == set()


def test_output_file_names_the_reason():
    with pytest.raises(ParameterError, match=r"plot = '/proc/x.png' .* writable directory"):
        _common.png_path("plot", "/proc/x.png")
    with pytest.raises(ParameterError, match="ending in .png"):
        _common.png_path("plot", "x.jpg")


# --------------------------------------------------------------------------- argparse
@pytest.mark.parametrize("text", ["-1e308", "-1E-3", "-.5e2", "-inf", "-Infinity", "-nan", "-2."])
def test_negative_scientific_numbers_are_values_not_options(text):
    from sinktheory.cli import build_parser

    same = (lambda a: a != a) if text == "-nan" else (lambda a: a == float(text))
    args = build_parser().parse_args(["floquet", "--lam", text, "--n", "4"])
    assert same(args.lam)
    args = build_parser().parse_args(
        ["floquet", "--beta-range", text, "0.2", "3", "--alpha", "0.5", "--n", "4"]
    )
    assert same(args.beta_range[0])


def test_beta_range_minus_inf_names_the_end(capsys, tmp_path, monkeypatch):
    line = refused(
        ["floquet", "--beta-range", "-inf", "0.2", "3", "--alpha", "0.5", "--n", "4"],
        capsys,
        tmp_path,
        monkeypatch,
        "beta_range",
    )
    assert "(lo = -inf is not allowed" in line


# --------------------------------------------------------------------------- start-up
HEAVY = ("matplotlib", "xarray", "zarr", "dask", "sympy", "sinktheory.scenes")
IMPORTS = """
import sys
from sinktheory.cli import main
try:
    main(sys.argv[1:])
except SystemExit:
    pass
print("LOADED", " ".join(sorted(m for m in sys.modules if m.split(".")[0] in {heavy})))
"""


def loaded_by(args):
    """Heavy top-level modules (and numba) a fresh process imports to run ARGS."""
    import subprocess
    import sys

    heavy = {m.split(".")[0] for m in (*HEAVY, "numba", "scipy", "sinktheory")}
    proc = subprocess.run(
        [sys.executable, "-c", IMPORTS.format(heavy=heavy), *args],
        capture_output=True,
        text=True,
        env={**os.environ, "MPLBACKEND": "Agg"},
        timeout=300,
    )
    line = [s for s in proc.stdout.splitlines() if s.startswith("LOADED")][-1]
    return set(line.split()[1:])


@pytest.mark.parametrize("args", [["--version"], ["--help"], ["bogus"]])
def test_version_and_help_import_no_numerics(args):
    """Timed in benchmarks/bench_startup.py; here: nothing numerical is imported."""
    loaded = loaded_by(args)
    assert not {m for m in loaded if m.split(".")[0] in {"numba", "scipy", "matplotlib"}}
    assert not {m for m in loaded if m.startswith("sinktheory.") and m not in LIGHT}, loaded


LIGHT = {
    "sinktheory.cli",
    "sinktheory.commands",
    "sinktheory.commands._common",
    "sinktheory.errors",
    "sinktheory.limits",  # plain numbers, imports nothing
    "sinktheory.glossary",  # the names of the options; functools and warnings only
    "sinktheory.progress",  # signal holding for Ctrl-C; tqdm only, no numerics
    "sinktheory.validation",
}


@pytest.mark.parametrize(
    "args",
    [
        ["well", *WELL, "--json"],
        ["period", "--n", "4", "--amplitude", "1"],
        ["floquet", "--alpha", "0.5", "--beta", "0.1", "--n", "4"],
        ["sink", *WELL],
    ],
    ids=lambda a: a[0],
)
def test_light_commands_import_no_plotting_or_arrays(args):
    loaded = loaded_by(args)
    assert not any(m.startswith(h) for m in loaded for h in HEAVY), loaded
    assert "scipy.optimize" not in loaded and "scipy.integrate" not in loaded, loaded


# --------------------------------------------------------------------------- sizes
SIZES = [
    ([*SIM, "--container-energy", "1e308"], "container_energy", "(0, 1.25e+23]"),
    ([*SIM, "--mass", "1e-320"], "mass", ">= 1e-12"),
    ([*SIM, "--mass", "5e-12", "--particles", "10"], "mass", "1e-11"),
    (["sink", *WELL, "--mass", "1e-320"], "mass", ">= 1e-12"),
    (["well", *WELL, "--particle-energy", "1e308"], "particle_energy", "reach c"),
    (["well", *WELL[:-1], "1000", "--particle-energy", "1e308"], "particle_energy", "overflow"),
    ([*SIM[:-5], "--periods", "2", "--initial", "1e308", "0", "--quiet"], "initial", "walls"),
    ([*SIM[:-5], "--periods", "2", "--initial", "0.21", "0", "--quiet"], "initial", "walls"),
    ([*SIM[:-5], "--periods", "2", "--initial", "0", "nan", "--quiet"], "initial", "walls"),
    ([*SIM, "--initial", "0", "0"], "runs", "1 with --initial"),
    ([*SIM, "--dt", "1e-320"], "dt", "steps per period"),
    ([*SIM, "--dt", "1e-300"], "dt", "steps per period"),
    ([*SIM, "--dt", "1e-9"], "dt", "steps per period"),
    ([*SIM[:-5], "--runs", "2", "--periods", "1e12", "--quiet"], "periods", "TiB"),
    ([*SIM[:-5], "--runs", "2", "--periods", "1e308", "--quiet"], "periods", "[1, 1000000000]"),
    ([*SIM[:-5], "--runs", "1e12", "--periods", "2", "--quiet"], "runs", "TiB"),
    ([*SIM[:-5], "--runs", "1e308", "--periods", "2", "--quiet"], "runs", "[1, 10000000]"),
    ([*SIM[:-5], "--runs", "100000", "--periods", "100000", "--quiet"], "runs", "memory"),
    (
        [*SIM[:-5], "--runs", "1000", "--periods", "1e6", "--dt", "1e-6", "--quiet"],
        "periods",
        "days",
    ),
    (["sink", *WELL, "--runs", "1e12"], "runs", "[1, 10000000]"),
    (["sink", *WELL, "--periods", "1e12"], "periods", "[1, 1000000000]"),
    (["sink", *WELL, "--runs", "10000000", "--periods", "1000000000"], "periods", "memory"),
]


@pytest.mark.parametrize(("argv", "name", "says"), SIZES, ids=lambda a: " ".join(a)[-44:])
def test_sizes_refused_up_front_naming_the_parameter(
    argv, name, says, capsys, tmp_path, monkeypatch
):
    line = refused(argv, capsys, tmp_path, monkeypatch, name)
    assert says in line


HOSTILE_WELLS = [
    (["sink", "--alpha", "0.5", "--beta", "0.499999999999", "--n", "4"], "beta"),
    (["well", "--alpha", "0.5", "--beta", "0.499999999999", "--n", "4"], "beta"),
    (["simulate", "--alpha", "0.5", "--beta", "0.499999999999", "--n", "4", "--quiet"], "beta"),
    (["simulate", "--alpha", "1e-12", "--beta", "0", "--n", "4", "--quiet"], "box"),
    (["sink", "--alpha", "1e-12", "--beta", "0", "--n", "4"], "box"),
    (["sink", "--alpha", "0.5", "--beta", "0.495", "--n", "4"], "box"),  # wall at 0.005
    (["sink", "--alpha", "1e-12", "--beta", "-1e-12", "--n", "4"], "box"),
]


@pytest.mark.parametrize(("argv", "name"), HOSTILE_WELLS, ids=lambda a: " ".join(a)[-40:])
def test_hostile_wells_refused(argv, name, capsys, tmp_path, monkeypatch):
    refused(argv, capsys, tmp_path, monkeypatch, name)


def test_well_with_tiny_but_exact_wall_distance_is_described(capsys):
    """alpha = 1e-12, beta = 0 is a valid (tiny) well; only a simulation in it is refused."""
    code, out, err = run_cli(["well", "--alpha", "1e-12", "--beta", "0", "--n", "4"], capsys)
    assert code == 0, err
    assert "1e-12" in out


# --------------------------------------------------------------------------- Python API
def test_bools_are_not_numbers():
    import numpy as np

    from sinktheory import RunSettings, Sink, Well

    cases = [
        (lambda: Well(alpha=True, beta=0.3, n=4), "alpha"),
        (lambda: Well(alpha=0.5, beta=False, n=4), "beta"),
        (lambda: Well(alpha=0.5, beta=0.3, n=True), "n"),
        (lambda: Well(alpha=0.5, beta=0.3, n=4, gamma=np.True_), "gamma"),
        (lambda: Well(alpha=0.5, beta=0.3, n=4, shape=1), "shape"),
        (lambda: Sink(FIG8_WELL, particles=True), "particles"),
        (lambda: Sink(FIG8_WELL, mass=True), "mass"),
        (lambda: RunSettings(runs=True), "runs"),
        (lambda: RunSettings(container_energy=np.bool_(True)), "container_energy"),
    ]
    for make, name in cases:
        with pytest.raises(ParameterError) as info:
            make()
        assert info.value.name == name


def test_model_limits_name_parameter_value_and_range():
    from sinktheory import RunSettings, Sink, Well
    from sinktheory.worklimit import check_work

    with pytest.raises(ParameterError, match=r"beta = 0.499999999999 .* <= 0.4999999"):
        Well(0.5, 0.499999999999, 4)
    Well(0.5, 0.49999, 4)  # a narrow but resolvable well is fine
    with pytest.raises(ParameterError, match="energy = 1e[+]308"):
        FIG8_WELL.reach(1e308)
    with pytest.raises(ParameterError, match="mass = 1e-320"):
        Sink(FIG8_WELL, mass=1e-320)
    with pytest.raises(ParameterError, match=r"runs = 1000000000000 .*\[1, 10000000\]"):
        RunSettings(runs=10**12)
    with pytest.raises(ParameterError, match=r"periods = 1e\+308"):
        RunSettings(periods=1e308)
    with pytest.raises(ParameterError, match="box = 0.01"):
        RunSettings().check(Sink(Well(1e-12, 0.0, 4)))
    with pytest.raises(ParameterError, match="memory"):
        RunSettings(runs=10**7, periods=10**9).check(Sink(FIG8_WELL))
    with pytest.raises(ParameterError, match="days"):
        check_work(RunSettings(runs=100, periods=10**6), Sink(FIG8_WELL), 10**6)
    RunSettings(runs=25, periods=1500).check(Sink(FIG8_WELL, particles=5))


def test_reach_of_huge_energies_is_refused_and_exact_up_to_the_limit():
    """Flat n = 1, beta > 0: the basin's x bound is max over u = y^2 of
    (a + beta u) sqrt(c^2 - u), a = alpha - beta, at u = (2 beta c^2 - a) / (3 beta).
    Up to the reach limit c = 1000 (E = 5e5) the golden-section search matches it; above,
    where it searched for minutes (E = 1e8: c = 1e4), the energy is refused at once."""
    import math

    from sinktheory import Well
    from sinktheory.model import MAX_REACH

    alpha, beta = 0.5, 0.3
    c, a = MAX_REACH, alpha - beta
    u = (2 * beta * c**2 - a) / (3 * beta)
    x_max, y_max = Well(alpha, beta, 1).reach(c**2 / 2)
    assert x_max == pytest.approx((a + beta * u) * math.sqrt(c**2 - u), rel=1e-9)
    assert y_max == pytest.approx(c, rel=1e-12)
    for energy in (5.01e5, 1e8, 1e300):
        with pytest.raises(ParameterError, match=r"energy = .*\(0, 500000\].*reach c"):
            Well(alpha, beta, 1).reach(energy)
    assert Well(alpha, beta, 1, gamma=1e300).reach(1e-300)[1] > 0  # no log of an underflow


@pytest.mark.parametrize("shape", ["flat", "symmetric", "circular"])
def test_start_box_checked_over_the_whole_box(shape):
    """check_box against a brute-force maximum of the wall ratio over a 201 x 201 grid of
    the box (edges included), for boxes on both sides of the limit and both signs of beta;
    the symmetric well's box = 10 (corner inside, (10, 0) far outside) was accepted, and
    boxes whose ratios overflow float range raised OverflowError."""
    from sinktheory import RunSettings, Well

    grid = np.linspace(-1.0, 1.0, 201)
    for beta in (0.3, -0.3):
        well = Well(0.5, beta, 4, shape=shape)
        for box in (0.05, 0.15, 0.3, 0.45, 0.6, 2.0, 10.0):
            brute = max(well.wall_ratio(box * x, box * y) for x in grid for y in grid)
            if brute < 1:
                RunSettings(box=box).check_box(well)
            else:
                with pytest.raises(ParameterError, match="box = "):
                    RunSettings(box=box).check_box(well)
        for box in (1e154, 1e200, 1e308):
            with pytest.raises(ParameterError, match="box = "):
                RunSettings(box=box).check_box(well)


# --------------------------------------------------------------------------- numerics
NUMERIC = [
    (
        ["floquet", "--alpha", "0.5", "--beta", "0.1", "--n", "4", "--amplitude", "1e-320"],
        "amplitude",
    ),
    (
        ["floquet", "--alpha", "0.5", "--beta", "0.1", "--n", "4", "--amplitude", "1e-100"],
        "amplitude",
    ),
    (
        ["floquet", "--alpha", "0.5", "--beta", "0.1", "--n", "1000", "--amplitude", "2"],
        "amplitude",
    ),
    (["floquet", "--lam", "1e3", "--n", "4", "--amplitude", "1e300"], "amplitude"),
    (["floquet", "--lam", "-1e308", "--n", "4"], "lam"),
    (["floquet", "--lam", "1e12", "--n", "4"], "lam"),
    (["floquet", "--lam-range", "-1e308", "0", "3", "--n", "4"], "lam"),
    (["floquet", "--alpha", "0.5", "--beta", "-1e300", "--n", "4"], "beta"),
    (["period", "--n", "1000", "--amplitude", "1", "--digits", "10000"], "digits"),
    (["period", "--n", "4", "--amplitude", "1", "--digits", "1001"], "digits"),
]


@pytest.mark.parametrize(("argv", "name"), NUMERIC, ids=lambda a: " ".join(a)[-40:])
def test_numerically_hostile_input_refused(argv, name, capsys, tmp_path, monkeypatch):
    refused(argv, capsys, tmp_path, monkeypatch, name)


def test_api_type_errors_are_parameter_errors():
    import numpy as np

    from sinktheory.floquet import model_problem, pure_problem, scan
    from sinktheory.hill import integrate_quarter_period
    from sinktheory.oscillator import exact_shape, exact_solution, period
    from sinktheory.recurrence import rqa

    cases = [
        (lambda: scan("x", 0.0, 1.0, 3), "problem"),
        (lambda: scan(None, 0.0, 1.0, 3), "problem"),
        (lambda: pure_problem(4).evaluate("x"), "lam"),
        (lambda: model_problem(0.5, 4).evaluate([[0.1], [0.2, 0.3]]), "beta"),
        (lambda: model_problem(0.5, 4, amplitude=1e-320).evaluate([0.1]), "amplitude"),
        (lambda: integrate_quarter_period(4, np.array([1.0]), amplitude=1e-100), "amplitude"),
        (lambda: exact_solution("x", 2, 1.0), "t"),
        (lambda: exact_solution([0.0, "a"], 2, 1.0), "t"),
        (lambda: exact_shape("x", 2), "tau"),
        (lambda: period(4, amplitude=1, dps=10_000), "dps"),
        (lambda: rqa("abc", eps=0.1), "series"),
        (lambda: rqa([1j, 2j], eps=0.1), "series"),
        (lambda: rqa([[1.0, 2.0], [3.0]], eps=0.1), "series"),
    ]
    for make, name in cases:
        with pytest.raises(ParameterError) as info:
            make()
        assert info.value.name == name, (name, info.value)


def test_amplitude_range_keeps_valid_charts():
    """The amplitude bound is not too tight: A0 = 1.2 at n = 1000 and A0 = 1e-30 at n = 1
    still give finite multipliers; and only Lam A0^2 matters for the pure equation."""
    from sinktheory.floquet import model_problem, pure_problem

    assert np.isfinite(model_problem(0.5, 1000, amplitude=1.2).evaluate([0.1]).log_abs_phi[0])
    a = pure_problem(3, amplitude=2.0).evaluate([0.3]).phi_half[0]
    b = pure_problem(3, amplitude=1.0).evaluate([1.2]).phi_half[0]
    assert a == pytest.approx(b, rel=1e-9)


# --------------------------------------------------------------------------- sweeps
SWEEP = ["sweep", "floquet", "--param", "alpha=0.5", "--param", "n=4", "--out", "s.zarr"]
ENSEMBLE = ["sweep", "ensemble", "--param", "alpha=0.5", "--param", "beta=0.1", "--param", "n=4"]
BIF = ["sweep", "bifurcation", "--param", "alpha=0.5", "--param", "beta=0.1", "--param", "n=4"]
SWEEPS = [
    ([*SWEEP, "--param", "beta=0.1:0.2:1000000000000"], "beta", "COUNT <= 1000000"),
    ([*SWEEP, "--param", "beta=0.1:0.2:1e12"], "beta", "COUNT"),
    ([*BIF, "--param", "count=1e12", "--out", "s.zarr"], "count", "[1, 1000000000]"),
    ([*BIF, "--param", "transient=1e308", "--out", "s.zarr"], "transient", "1000000000"),
    ([*ENSEMBLE, "--param", "periods=1e308", "--out", "s.zarr"], "periods", "1000000000"),
    ([*ENSEMBLE, "--param", "replica=-1", "--out", "s.zarr"], "replica", ">= 0"),
    ([*ENSEMBLE, "--param", "replica=-1,0", "--out", "s.zarr"], "replica", ">= 0"),
    ([*ENSEMBLE, "--param", "dt=1e-300", "--out", "s.zarr"], "dt", "steps per period"),
    ([*ENSEMBLE, "--param", "runs=1e12", "--out", "s.zarr"], "runs", "[1, 10000000]"),
    (
        [*SWEEP[:-2], "--param", "beta=0:0.4:1001", "--param", "gamma=1:2:1001", "--out", "s"],
        "beta",
        "at most 1000000 points",
    ),
]


@pytest.mark.parametrize(("argv", "name", "says"), SWEEPS, ids=lambda a: " ".join(a)[-40:])
def test_sweep_sizes_refused(argv, name, says, capsys, tmp_path, monkeypatch):
    assert says in refused(argv, capsys, tmp_path, monkeypatch, name)


def test_sweep_results_must_fit_in_memory(capsys, tmp_path, monkeypatch):
    from sinktheory import validation

    monkeypatch.setattr(validation, "memory_limit", lambda: 2**30)  # a 2 GiB machine
    argv = [*BIF[:4], "--param", "n=4", "--param", "beta=0.1,0.2", "--param", "count=100000000"]
    argv += ["--out", "s.zarr"]
    assert "1.49 GiB of memory" in refused(argv, capsys, tmp_path, monkeypatch, "count")


def test_run_sweep_argument_types():
    from sinktheory.sweep import run_sweep

    ok = {"alpha": 0.5, "beta": 0.1, "n": 4}
    cases = [
        (lambda: run_sweep("floquet", "x"), "params"),
        (lambda: run_sweep("floquet", None), "params"),
        (lambda: run_sweep("floquet", [("alpha", 0.5)]), "params"),
        (lambda: run_sweep(None, ok), "kind"),
        (lambda: run_sweep("floquet", ok, store=3), "store"),
        (lambda: run_sweep("floquet", ok, store=""), "store"),
        (lambda: run_sweep("floquet", ok, store="/proc/s.zarr"), "store"),
        (lambda: run_sweep("floquet", ok, seed=True), "seed"),
        (lambda: run_sweep("floquet", ok, resume="yes"), "resume"),
        (lambda: run_sweep("floquet", {**ok, "alpha": True}), "alpha"),
        (lambda: run_sweep("ensemble", {**ok, "replica": -1}), "replica"),
    ]
    for make, name in cases:
        with pytest.raises(ParameterError) as info:
            make()
        assert info.value.name == name, (name, info.value)


# --------------------------------------------------------------------------- store damage
FLOQUET = {"alpha": 0.5, "beta": [-0.3, -0.2, -0.1, 0.1, 0.2, 0.3], "n": [2, 10]}


def make_store(path):
    import xarray as xr

    from sinktheory.sweep import run_sweep

    run_sweep("floquet", FLOQUET, store=path, workers=1, progress=False)
    return xr.open_zarr(path).load()


def resume(path, repair=True):
    import xarray as xr

    from sinktheory.sweep import execute
    from sinktheory.sweep.plan import Sweep

    sweep = Sweep.make("floquet", FLOQUET)
    done = execute(sweep, store=path, resume=True, repair=repair, progress=False)
    return done.computed, xr.open_zarr(path).load()


def flip_bit(file: Path, at: int = -3) -> None:
    data = bytearray(file.read_bytes())
    data[at] ^= 0x10
    file.write_bytes(bytes(data))


def test_store_keeps_a_checksum_per_point(tmp_path):
    from sinktheory.sweep.plan import Sweep
    from sinktheory.sweep.store import _point_checksums

    path = tmp_path / "s.zarr"
    ds = make_store(path)
    sweep = Sweep.make("floquet", FLOQUET)
    rows = {name: ds[name].values.reshape(12, -1) for name in sweep.kind.results}
    expected = _point_checksums(sweep, rows).reshape(6, 2)
    assert np.array_equal(ds.checksum.values, expected) and bool((expected != 0).all())


@pytest.mark.parametrize("array", ["lam", "phi_half", "stable", "checksum"])
def test_deleted_chunk_is_detected_and_its_points_recomputed(array, tmp_path):
    path = tmp_path / "s.zarr"
    pristine = make_store(path)
    (path / array / "c" / "0" / "0").unlink()
    computed, after = resume(path, repair=False)
    # the one chunk holds every point of this small grid; a deleted chunk reads back as
    # its fill value (NaN, or False: the points whose flag really was False still match)
    lost = int(pristine.stable.sum()) if array == "stable" else 12
    assert computed == lost
    assert bool(after.done.all())
    for name in ("lam", "phi_half", "phi", "stable", "rotation_number", "checksum"):
        np.testing.assert_array_equal(after[name].values, pristine[name].values)
    assert resume(path)[0] == 0  # repaired: nothing left to do


def test_changed_value_is_detected_and_only_its_point_recomputed(tmp_path):
    """A bit flipped in a stored value (the chunk still decodes) is found by the point's
    checksum; only that point is recomputed."""
    import zarr

    path = tmp_path / "s.zarr"
    pristine = make_store(path)
    group = zarr.open_group(path, mode="r+")
    lam = group["lam"][...]
    bits = lam.view(np.uint64)
    bits[2, 1] ^= np.uint64(1)  # the last bit of one value
    group["lam"][...] = lam
    assert group["lam"][2, 1] != pristine.lam.values[2, 1]
    computed, after = resume(path, repair=False)
    assert computed == 1
    np.testing.assert_array_equal(after.lam.values, pristine.lam.values)


@pytest.mark.parametrize("damage", ["flip", "truncate"])
@pytest.mark.parametrize("array", ["lam", "done"])
def test_undecodable_chunk_refused_or_repaired(damage, array, tmp_path):
    path = tmp_path / "s.zarr"
    pristine = make_store(path)
    chunk = path / array / "c" / "0" / "0"
    if damage == "flip":
        flip_bit(chunk)
    else:
        chunk.write_bytes(chunk.read_bytes()[:5])
    try:
        computed, _ = resume(path, repair=False)
    except ParameterError as e:  # the chunk no longer decodes
        assert "damaged" in str(e)
    else:  # it decodes (a flipped bit in the payload): the checksums found it
        assert computed >= 1
    computed, after = resume(path, repair=True)
    assert bool(after.done.all())
    np.testing.assert_array_equal(after.lam.values, pristine.lam.values)
    np.testing.assert_array_equal(after.phi.values, pristine.phi.values)


@pytest.mark.parametrize("coordinate", ["beta/c/0", "n/c/0", "point_seed/c/0/0"])
def test_damaged_coordinate_chunk_refuses_the_store(coordinate, tmp_path):
    path = tmp_path / "s.zarr"
    make_store(path)
    flip_bit(path / coordinate)
    name = coordinate.split("/")[0]
    with pytest.raises(ParameterError, match=f"damaged: the coordinate {name} differs"):
        resume(path, repair=True)


def test_deleted_coordinate_chunk_refuses_the_store(tmp_path):
    path = tmp_path / "s.zarr"
    make_store(path)
    (path / "beta" / "c" / "0").unlink()
    with pytest.raises(ParameterError, match="coordinate beta differs"):
        resume(path)


def test_only_damaged_chunks_are_recomputed(tmp_path):
    """A grid spread over several chunks: delete one, only its points are recomputed."""
    import xarray as xr

    from sinktheory.sweep import execute, store
    from sinktheory.sweep.plan import Sweep

    params = {"alpha": 0.5, "beta": list(np.linspace(-0.3, 0.3, 9)), "n": 4}
    sweep = Sweep.make("floquet", params)
    path = tmp_path / "s.zarr"
    old = store.CHUNK_VALUES
    store.CHUNK_VALUES = 3  # chunks of three points
    try:
        execute(sweep, store=path, workers=1, progress=False)
        pristine = xr.open_zarr(path).load()
        (path / "lam" / "c" / "1").unlink()
        done = execute(sweep, store=path, resume=True, progress=False)
    finally:
        store.CHUNK_VALUES = old
    assert done.computed == 3
    np.testing.assert_array_equal(xr.open_zarr(path).lam.values, pristine.lam.values)


def test_store_damage_through_the_cli(capsys, tmp_path, monkeypatch):
    import json

    monkeypatch.chdir(tmp_path)
    argv = ["sweep", "floquet", "--param", "alpha=0.5", "--param", "beta=-0.2,0.1"]
    argv += ["--param", "n=4", "--out", "s.zarr", "--quiet", "--json"]
    assert run_cli(argv, capsys)[0] == 0
    (tmp_path / "s.zarr" / "phi" / "c" / "0").unlink()
    code, out, err = run_cli([*argv, "--resume"], capsys)
    assert code == 0, err
    assert json.loads(out)["computed"] == 2
    chunk = tmp_path / "s.zarr" / "phi" / "c" / "0"
    chunk.write_bytes(chunk.read_bytes()[:5])
    code, out, err = run_cli([*argv, "--resume"], capsys)
    assert code == 2 and len(err.strip().splitlines()) == 1 and "damaged" in err
    code, out, err = run_cli([*argv, "--resume", "--repair"], capsys)
    assert code == 0 and json.loads(out)["computed"] == 2, err
    flip_bit(tmp_path / "s.zarr" / "beta" / "c" / "0")
    code, out, err = run_cli([*argv, "--resume"], capsys)
    assert code == 2 and len(err.strip().splitlines()) == 1 and "coordinate beta" in err


def test_simultaneous_creation_is_a_clean_refusal(tmp_path, monkeypatch):
    """Two drivers create one new store: the one that renames second is refused."""
    from sinktheory.sweep import run_sweep, store

    path = tmp_path / "s.zarr"
    real_rename = os.rename

    raced = []

    def other_driver_first(src, dst):
        if Path(dst) == path and not raced:  # the other driver's store lands first
            raced.append(True)
            run_sweep(
                "floquet",
                {"alpha": 0.5, "beta": [0.1, 0.2], "n": 4},
                store=path,
                workers=1,
                progress=False,
            )
        return real_rename(src, dst)

    monkeypatch.setattr(store.os, "rename", other_driver_first)
    with pytest.raises(ParameterError, match="another process created it"):
        run_sweep(
            "floquet",
            {"alpha": 0.5, "beta": [0.1, 0.2], "n": 4},
            store=path,
            workers=1,
            progress=False,
        )
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".s.zarr.creating")]
