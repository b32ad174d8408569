"""``sinktheory relaxation``: the CLI prints the API's prediction and measurement; bad input
is one line, exit 2, no file."""

import json

import pytest
from _cli import refused
from _cli import run_cli as run

from sinktheory.canonical import FIG8_WELL
from sinktheory.equilibrium.prediction import measure_settling, predict_relaxation
from sinktheory.model import Sink

FIG8 = ["relaxation", "--alpha", "0.5", "--beta", "0.3", "--n", "4"]
SMALL = [
    "--shell-energies",
    "4",
    "--shell-runs",
    "64",
    "--lag",
    "32",
    "--seed",
    "3",
    "--resamples",
    "20",
]


def test_cli_equals_api_and_draws(tmp_path, capsys):
    png = tmp_path / "relax.png"
    argv = [*FIG8, *SMALL, "--measure", "4", "240", "--json", "--plot", str(png)]
    code, out, err = run(argv, capsys)
    assert code == 0, err
    data = json.loads(out)
    sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    p = predict_relaxation(sink, 0.5, shell_energies=4, shell_runs=64, lag=32, seed=3, resamples=20)
    r, _ = measure_settling(sink, 0.5, (4, 240), seed=3, resamples=20)
    assert data["prediction"]["settle_time"] == p.settle_time
    assert data["prediction"]["means"] == p.means.tolist()
    assert data["measured"]["settle_time"] == r.settle_time
    assert data["measured"]["means"] == r.means.tolist()
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_text_says_what_the_prediction_is(capsys):
    code, out, err = run([*FIG8, *SMALL], capsys)
    assert code == 0, err
    assert "predicted: settles at" in out and "fast noise" in out and "  measured:" not in out


@pytest.mark.parametrize(
    "argv,name",
    [
        ([*FIG8, "--particles", "0"], "particles"),
        ([*FIG8, "--fraction", "1"], "fraction"),
        ([*FIG8, "--fraction", "-0.1"], "fraction"),
        ([*FIG8, "--container-energy", "0"], "container_energy"),
        ([*FIG8, "--mass", "nan"], "mass"),
        ([*FIG8, "--lag", "4"], "lag"),
        ([*FIG8, "--shell-energies", "2"], "shell_energies"),
        ([*FIG8, "--shell-runs", "3"], "shell_runs"),
        ([*FIG8, "--measure", "2", "100"], "measure"),
        ([*FIG8, "--measure", "8", "10"], "measure"),
        ([*FIG8, "--plot", "out.txt"], "plot"),
        ([*FIG8, "--resamples", "5"], "resamples"),
        (["relaxation", "--alpha", "0.5", "--beta", "0.5", "--n", "4"], "beta"),
    ],
)
def test_bad_input_one_line_exit_2_nothing_written(argv, name, tmp_path, capsys, monkeypatch):
    refused(argv, capsys, tmp_path, monkeypatch, name)
