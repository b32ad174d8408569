"""``sinktheory chaos``: JSON output, the plot, and bad input (one line, exit 2, no file)."""

import json

import numpy as np
import pytest
from _cli import run_cli

from sinktheory import RunSettings, Sink
from sinktheory.canonical import FIG8_WELL
from sinktheory.chaos import chaos

BASE = ["chaos", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--particles", "1",
        "--mass", "0.2", "--dt", "0.01", "--quiet"]  # fmt: skip


def test_spectrum_json_pairs_sum_to_zero(capsys):
    code, out, err = run_cli(
        BASE + ["--runs", "2", "--periods", "100", "--spectrum", "--json"], capsys
    )
    assert code == 0, err
    d = json.loads(out)
    mean = np.array(d["spectrum"]["mean"])
    assert mean.shape == (6,)
    assert np.abs(np.array(d["pair_sums"]["runs"])).max() < 10 / d["time"]
    assert mean[0] > 0.1
    # the same numbers as the Python API for the same options
    res = chaos(Sink(FIG8_WELL, 1, 0.2), RunSettings(runs=2, periods=100), spectrum=True,
                dt=0.01)  # fmt: skip
    np.testing.assert_array_equal(np.array(d["spectrum"]["runs"]), res.spectrum)
    # lambda_1 split into regular and chaotic runs, from the per-run values shown
    groups = d["split_lambda1"]
    lam = np.array(d["lambda1"]["runs"])
    assert groups["runs"] == 2 and groups["regular"] == int(np.sum(lam <= groups["threshold"]))
    assert "(-0.01, 0.01)^2" in groups["starts"]


def test_half_spectrum_from_the_cli(capsys):
    code, out, err = run_cli(
        BASE + ["--runs", "2", "--periods", "20", "--spectrum", "half"], capsys
    )
    assert code == 0, err
    assert "symplectic pairing" in out and "pairs lambda_i" not in out
    code, out, err = run_cli(BASE + ["--runs", "2", "--periods", "2", "--spectrum", "all"], capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and "--spectrum" in err


def test_all_indicators_text_and_plot(capsys, tmp_path):
    png = tmp_path / "conv.png"
    args = ["--runs", "2", "--periods", "20", "--gali", "2", "--megno", "--transverse"]
    code, out, err = run_cli(BASE + args + ["--plot", str(png)], capsys)
    assert code == 0, err
    assert "lambda_1 =" in out and "GALI_2" in out and "SALI" in out and "transverse" in out
    assert "lambda_1 runs: " in out and " of 2 regular (lambda_1 <= 3 ln t/t = " in out
    assert png.stat().st_size > 10_000


@pytest.mark.parametrize(
    "extra, name",
    [
        (["--gali", "1"], "gali"),
        (["--gali", "99"], "gali"),
        (["--renorm", "-3"], "renorm"),
        (["--runs", "0"], "runs"),
        (["--scheme", "euler"], "scheme"),
        (["--plot", "out.txt"], "plot"),
    ],
)
def test_bad_input_one_line_exit_2_nothing_written(capsys, tmp_path, monkeypatch, extra, name):
    monkeypatch.chdir(tmp_path)
    code, out, err = run_cli(BASE + ["--periods", "2", "--plot", "x.png"] + extra, capsys)
    assert code == 2
    assert out == ""
    assert len(err.strip().splitlines()) == 1 and name in err
    assert list(tmp_path.iterdir()) == []
