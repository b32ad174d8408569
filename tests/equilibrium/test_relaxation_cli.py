"""``sinktheory relaxation``: the CLI prints the API's prediction and measurement; bad input
is one line, exit 2, no file."""

import json
import math

import numpy as np
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


RIGID = ["relaxation", "--alpha", "0.5", "--beta", "0.3", "--n", "inf"]


def test_rigid_walls_against_the_rigid_law_and_direct_billiards(capsys):
    # --n inf: exact billiards.  Independent references: the rigid law Beta(1, k) (its
    # mean and standard deviation, which the predicted curve must end at), the settling
    # formula t_f = t_r ln(c |s0 - mu| / (f mu)) by hand, and the measured window means
    # against billiard runs made and averaged here
    from scipy import stats

    from sinktheory.billiard import billiard
    from sinktheory.model import RunSettings

    k, e0 = 2, 0.4
    argv = [*RIGID, *SMALL, "--particles", str(k), "--container-energy", str(e0),
            "--periods", "40000", "--measure", "6", "600", "--json"]  # fmt: skip
    code, out, err = run(argv, capsys)
    assert code == 0, err
    data = json.loads(out)
    p, r = data["prediction"], data["measured"]
    assert "n=inf" in data["well"]
    law = stats.beta(1, k)
    assert p["total_energy"] == e0 and math.isclose(p["target"], e0 * law.mean(), rel_tol=1e-14)
    assert p["means"][0] == e0
    assert p["times"][-1] > 20 * p["rate_time"]  # long after the slow mode has gone
    assert math.isclose(p["means"][-1], e0 * law.mean(), rel_tol=1e-6)
    assert math.isclose(p["spread"][-1], e0 * law.std(), rel_tol=1e-3)  # the chain's cells
    mu = law.mean()
    by_hand = p["rate_time"] * math.log(p["visible"] * (1 - mu) / (0.05 * mu))
    assert math.isclose(p["settle_time"], by_hand, rel_tol=1e-12)
    runs = billiard(
        "flat",
        0.5,
        0.3,
        particles=k,
        mass=0.2,
        settings=RunSettings(container_energy=e0, runs=6, periods=600, seed=3),
    )
    windows = runs.container_energy[:, :600].reshape(6, 12, 50).mean(axis=2).mean(axis=0)
    assert r["target"] == pytest.approx(e0 / (k + 1), rel=1e-14)
    assert np.allclose(r["means"], windows, rtol=1e-12)


def test_rigid_text_names_the_billiard(capsys):
    code, out, err = run([*RIGID, *SMALL], capsys)
    assert code == 0, err
    assert "n=inf (rigid walls, exact billiards)" in out and "rigid billiards from the shell" in out


@pytest.mark.parametrize(
    "argv,name",
    [
        ([*RIGID, "--tol", "1e-8"], "--tol"),
        ([*RIGID, "--gamma", "0"], "gamma"),
        ([*RIGID, "--particles", "0"], "particles"),
        ([*RIGID, "--measure", "2", "100"], "measure"),
        ([*RIGID, "--plot", "out.txt"], "plot"),
        (["relaxation", "--alpha", "0.5", "--beta", "0.6", "--n", "inf"], "beta"),
        ([*RIGID, "--shape", "round"], "shape"),
    ],
)
def test_rigid_bad_input_one_line_exit_2_nothing_written(argv, name, tmp_path, capsys,
                                                         monkeypatch):  # fmt: skip
    refused(argv, capsys, tmp_path, monkeypatch, name)
