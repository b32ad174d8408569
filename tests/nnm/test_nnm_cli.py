"""``sinktheory nnm``: JSON output, the plot, and bad input (one line, exit 2, no file)."""

import json

import pytest
from _cli import run_cli

BASE = ["nnm", "--alpha", "0.5", "--n", "4"]


def test_energy_continuation_json_and_plot(tmp_path, capsys):
    png = tmp_path / "fep.png"
    argv = BASE + ["--beta", "-0.2", "--continue-in", "energy", "--interval", "1e-3", "0.2"]
    code, out, err = run_cli(argv + ["--points", "60", "--plot", str(png), "--json"], capsys)
    assert code == 0, err
    data = json.loads(out)
    assert data["continue_in"] == "energy" and png.stat().st_size > 10_000
    assert data["max_trivial_error"] < 1e-5 and data["max_abs_sigma"] < 1e-12
    assert min(data["frequency"]) == pytest.approx(1.0, abs=1e-3)  # container mode, low H
    assert any(e["kind"] == "fold" for e in data["events"])


@pytest.mark.parametrize(
    "extra, name",
    [
        (["--beta", "0.2", "--continue-in", "mass"], "continue_in"),
        (["--beta", "0.2", "--continue-in", "energy", "--steps", "7"], "steps"),
        (["--beta", "0.2", "--continue-in", "energy", "--interval", "1", "0.1"], "interval"),
        (["--beta", "0.6", "--continue-in", "energy"], "beta"),
        (["--beta", "0.2", "--continue-in", "beta", "--interval", "0.3", "0.4"], "beta"),
        (["--beta", "0.2", "--continue-in", "energy", "--betas", "8"], "betas"),
    ],
)
def test_bad_input_is_one_line_exit_2_no_file(tmp_path, capsys, extra, name):
    png = tmp_path / "x.png"
    code, out, err = run_cli(BASE + extra + ["--plot", str(png)], capsys)
    assert code == 2 and not png.exists()
    assert len(err.strip().splitlines()) == 1 and name in err


def test_agreement_with_a_small_chaos_map(tmp_path, capsys):
    """--betas 4 (2 runs x 20 periods: a smoke-size chaos map): the shares
    are recomputed here from the JSON's own verdict and stability arrays."""
    png = tmp_path / "agree.png"
    argv = BASE + ["--beta", "-0.2", "--continue-in", "beta", "--interval", "-0.6", "0.2",
                   "--betas", "4", "--runs", "2", "--periods", "20"]  # fmt: skip
    code, out, err = run_cli(argv + ["--plot", str(png), "--json"], capsys)
    assert code == 0, err
    a = json.loads(out)["agreement"]
    assert a["betas"] == 4 and png.stat().st_size > 10_000
    calls = a["calls"]  # +1 every run chaotic, -1 every run regular, 0 mixed (not scored)
    scored = [i for i, c in enumerate(calls) if c != 0]
    assert a["scored"] == len(scored) and a["mixed"] == len(a["mixed_beta"]) == 4 - len(scored)
    nnm = [abs(p) <= 1 for p in a["phi_half_nnm"]]
    fixed = [abs(p) < 1 for p in a["phi_half_floquet"]]
    for key, stable in (("nnm", nnm), ("floquet", fixed)):
        share = sum(stable[i] == (calls[i] == -1) for i in scored) / len(scored)
        assert a[key] == pytest.approx(share)
    assert a["statement"].startswith("NNM transverse stability predicts the chaos map")
