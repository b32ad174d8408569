"""Adversarial input (issue 13): every bad input is refused cleanly, nothing is written.

Each CLI case must exit with status 2, print exactly one line on stderr naming the
parameter, no traceback, and leave the working directory as it was.
"""

import os
from pathlib import Path

import pytest
from _cli import run_cli

from sinktheory.commands import _common
from sinktheory.errors import ParameterError

WELL = ["--alpha", "0.5", "--beta", "0.3", "--n", "4"]
SIM = ["simulate", *WELL, "--runs", "2", "--periods", "2", "--quiet"]


def snapshot(root: Path) -> set[str]:
    """Every path under ``root`` (hidden files included)."""
    return {str(p.relative_to(root)) for p in root.rglob("*")}


def refused(argv, capsys, tmp_path, monkeypatch, name: str) -> str:
    """Run ARGV in ``tmp_path``; assert a clean refusal naming ``name``; return stderr."""
    monkeypatch.chdir(tmp_path)
    before = snapshot(tmp_path)
    code, out, err = run_cli(argv, capsys)
    assert code == 2, (code, err)
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert "Traceback" not in err
    assert f"error: {name} = " in lines[0] or f"argument {name}" in lines[0], lines[0]
    assert snapshot(tmp_path) == before, "a file was written"
    return lines[0]


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
    ([*SIM, "--out", "/proc/x.npz"], "--out"),
    ([*SIM, "--out", "d.png"], "--out"),
    ([*SIM, "--out", "ok.npz", "--plot", "/proc/x.png"], "--plot"),
    ([*SIM, "--out", "ok.npz", "--plot", "/sys/x.png"], "--plot"),
    ([*SIM, "--out", "ok.npz", "--plot", "d.png"], "--plot"),
    (
        [
            "sweep",
            "floquet",
            "--param",
            "alpha=0.5",
            "--param",
            "beta=0.1,0.2",
            "--param",
            "n=4",
            "--out",
            "/proc/s.zarr",
        ],
        "out",
    ),
    (
        [
            "sweep",
            "floquet",
            "--param",
            "alpha=0.5",
            "--param",
            "beta=0.1,0.2",
            "--param",
            "n=4",
            "--out",
            "",
        ],
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

    def broken_plot(path, *args):
        Path(path).write_bytes(b"half a png")
        raise OSError(28, "No space left on device", str(path))

    from sinktheory.commands import simulate as command

    monkeypatch.setattr(command, "_plot", broken_plot)
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
        "lo",
    )
    assert "-inf" in line


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
