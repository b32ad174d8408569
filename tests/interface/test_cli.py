"""The command line: help, version, JSON, plots, and one-line errors with status 2."""

import json
import subprocess
import sys

import pytest
from _cli import run_cli as run

from sinktheory import __version__
from sinktheory.cli import main
from sinktheory.commands import COMMANDS


def test_version(capsys):
    with pytest.raises(SystemExit) as info:
        main(["--version"])
    assert info.value.code == 0
    assert __version__ in capsys.readouterr().out


@pytest.mark.parametrize("module", COMMANDS, ids=lambda m: m.NAME)
def test_every_subcommand_has_help_and_json(module, capsys):
    with pytest.raises(SystemExit) as info:
        main([module.NAME, "--help"])
    assert info.value.code == 0
    assert "--json" in capsys.readouterr().out


def test_well_json_and_plot(tmp_path, capsys):
    png = tmp_path / "w.png"
    code, out, err = run(
        ["well", "--alpha", "0.5", "--beta", "0.3", "--n", "10", "--plot", str(png), "--json"],
        capsys,
    )
    assert code == 0, err
    data = json.loads(out)
    assert data["wall_distance"] == pytest.approx(0.2)
    assert data["curvature_at_centre"] == pytest.approx(0.6)
    assert isinstance(data["n"], int)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_sink_describes_setup(capsys):
    code, out, _ = run(
        ["sink", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--particles", "5", "--json"],
        capsys,
    )
    assert code == 0
    assert json.loads(out)["mu"] == pytest.approx(0.04)


WELL = ["--alpha", "0.5", "--beta", "0.3", "--n", "4"]
BAD = [
    (["well", "--alpha", "0.5", "--beta", "0.3", "--n", "0"], "n"),
    (["well", "--alpha", "0.5", "--beta", "0.3", "--n", "2.5"], "n"),
    (["well", "--alpha", "0.5", "--beta", "0.3", "--n", "nan"], "n"),
    (["well", *WELL, "--gamma", "0"], "gamma"),
    (["well", *WELL, "--gamma", "inf"], "gamma"),
    (["well", "--alpha", "-1", "--beta", "-2", "--n", "4"], "alpha"),
    (["well", "--alpha", "0.5", "--beta", "0.5", "--n", "4"], "beta"),
    (["well", "--alpha", "1", "--beta", "1", "--n", "6", "--shape", "symmetric"], "beta"),
    (["well", "--alpha", "0.5", "--beta", "-2", "--n", "2"], "beta"),
    (["well", *WELL, "--shape", "round"], "shape"),
    (["sink", *WELL, "--particles", "0"], "particles"),
    (["sink", *WELL, "--particles", "1.5"], "particles"),
    (["sink", *WELL, "--mass", "0"], "mass"),
    (["sink", *WELL, "--mass", "nan"], "mass"),
    (["sink", *WELL, "--runs", "0"], "runs"),
    (["sink", *WELL, "--periods", "0"], "periods"),
    (["sink", *WELL, "--periods", "-5"], "periods"),
    (["sink", *WELL, "--container-energy", "inf"], "container_energy"),
]


@pytest.mark.parametrize("argv,name", BAD, ids=[" ".join(a) for a, _ in BAD])
def test_bad_input_one_line_status_2_no_file(argv, name, tmp_path, capsys):
    png = tmp_path / "out.png"
    extra = ["--plot", str(png)] if argv[0] == "well" else []
    code, out, err = run(argv + extra, capsys)
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert f"{name} = " in lines[0]
    assert "Traceback" not in err
    assert not png.exists()


def test_unparseable_number_is_one_line(capsys):
    code, _, err = run(["well", "--alpha", "0.5", "--beta", "0.3", "--n", "ten"], capsys)
    assert code == 2
    assert len(err.strip().splitlines()) == 1 and "--n" in err


def test_plot_into_missing_directory_is_refused(tmp_path, capsys):
    code, _, err = run(["well", *WELL, "--plot", str(tmp_path / "no" / "w.png")], capsys)
    assert code == 2 and "plot = " in err


def test_console_entry_point_in_a_subprocess(tmp_path):
    """The real process: exit status 2 and a single stderr line."""
    r = subprocess.run(
        [sys.executable, "-m", "sinktheory", "well", "--alpha", "0.5", "--beta", "0.9", "--n", "2"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1 and r.stderr.startswith("sinktheory well: error: beta = ")
