"""``sinktheory billiard``: JSON equal to the Python API, the plot, one-line refusals."""

import json

import numpy as np
import pytest
from _cli import run_cli

from sinktheory.billiard import billiard
from sinktheory.model import RunSettings

BASE = ["billiard", "--alpha", "0.5", "--beta", "0.3", "--particles", "2", "--runs", "2",
        "--periods", "20"]  # fmt: skip


def test_json_matches_the_api(capsys):
    code, out, err = run_cli(BASE + ["--lyapunov", "--json"], capsys)
    assert code == 0, err
    d = json.loads(out)
    r = billiard("flat", 0.5, 0.3, particles=2, settings=RunSettings(runs=2, periods=20),
                 lyapunov=True)  # fmt: skip
    np.testing.assert_array_equal(np.array(d["container_energy"]), r.container_energy)
    np.testing.assert_array_equal(np.array(d["lambda1"]), r.lambda1)
    assert d["table"]["area"] == pytest.approx(1.2, rel=1e-12)
    assert d["max_relative_energy_error"] < 1e-12


def test_mixed_table_split_in_json_and_text(capsys):
    """The focusing table has regular and chaotic runs: both say how many and which."""
    args = ["billiard", "--alpha", "0.5", "--beta", "-0.3", "--runs", "12", "--periods", "150",
            "--fixed", "--lyapunov"]  # fmt: skip
    code, out, err = run_cli(args + ["--json"], capsys)
    assert code == 0, err
    d = json.loads(out)
    groups, lam = d["split_lambda1"], np.array(d["lambda1"])
    regular = lam <= groups["threshold"]
    assert groups["mixed"] and groups["regular"] == regular.sum()
    assert groups["chaotic_lambda1"]["mean"] == pytest.approx(lam[~regular].mean(), rel=1e-12)
    assert groups["regular_fraction"] == pytest.approx(regular.mean(), rel=1e-12)
    code, out, err = run_cli(args, capsys)
    assert f"lambda_1 runs: {regular.sum()} of 12 regular" in out and "starts: particles" in out
    code, out, err = run_cli(args[:5] + ["--runs", "1", "--fixed", "--lyapunov"], capsys)
    assert code == 0 and "of 1 regular" in out and "(no standard error from one run)" in out


def test_text_and_plot(capsys, tmp_path):
    png = tmp_path / "b.png"
    code, out, err = run_cli(BASE + ["--fixed", "--lyapunov", "--plot", str(png)], capsys)
    assert code == 0, err
    assert "fixed container" in out and "lambda_1 =" in out and "pi A/P = 0.605271" in out
    assert png.stat().st_size > 10_000


@pytest.mark.parametrize(
    "extra,name",
    [
        (["--beta", "0.6"], "beta"),
        (["--shape", "symmetric", "--alpha", "2", "--beta", "1"], "beta"),
        (["--shape", "oval"], "shape"),
        (["--runs", "0"], "runs"),
        (["--mass", "-1"], "mass"),
    ],
)
def test_bad_input_one_line_exit_2_nothing_written(capsys, tmp_path, extra, name):
    png = tmp_path / "b.png"
    code, out, err = run_cli(BASE + extra + ["--plot", str(png)], capsys)
    assert code == 2
    assert err.count("\n") == 1 and f"{name} = " in err
    assert not png.exists() and list(tmp_path.iterdir()) == []


def test_huge_energy_is_refused_with_its_estimate_before_any_flight(capsys, tmp_path, monkeypatch):
    """Issue 34: E0 = 1e18 ran 28 s, then failed.  The flights' work is bounded below by
    speed x time / reach steps (moving container: speed sqrt(2 E0 / (1 + m))), counted
    at ADVANCEMENT_STEP particle steps each (4e-7 s); here by hand: 29.4 days, over the
    hour."""
    import math

    from _cli import refused

    from sinktheory.billiard.run import ADVANCEMENT_STEP
    from sinktheory.billiard.table import rigid_table

    reach = rigid_table("flat", 0.5, 0.3).reach
    steps = 2 * 10 * 2 * math.pi * math.sqrt(2e18 / 1.2) / reach
    argv = ["billiard", "--alpha", "0.5", "--beta", "0.3", "--container-energy", "1e18",
            "--runs", "2", "--periods", "10"]  # fmt: skip
    line = refused(argv, capsys, tmp_path, monkeypatch, "periods")
    assert f"at least {steps:.3g} conservative-advancement steps" in line, line
    assert f"about {ADVANCEMENT_STEP * steps * 4e-7 / 86400:.3g} days" in line, line
    # fixed container: every particle keeps its speed sqrt(2 E0 / m)
    line = refused([*argv, "--fixed"], capsys, tmp_path, monkeypatch, "periods")
    fixed = 2 * 10 * 2 * math.pi * math.sqrt(2e18 / 0.2) / reach
    assert f"at least {fixed:.3g} conservative-advancement steps" in line, line


def test_flight_work_bound_against_a_hand_count():
    """advancement_steps of a moving container: E = (3^2 + 4^2) / 2 + 0.5 x 0.2 x 1^2 =
    12.6, bound speed sqrt(2 E / 1.2); two runs add up."""
    import math

    from sinktheory.billiard.run import advancement_steps
    from sinktheory.billiard.table import stadium_table

    t = stadium_table(1, 1)
    vel = np.array([[[1.0, 0.0]], [[0.0, 0.0]]])
    cont = np.array([[3.0, 4.0], [0.0, 1.0]])
    speeds = math.sqrt(2 * 12.6 / 1.2) + math.sqrt(2 * 0.5 / 1.2)
    got = advancement_steps(t, vel, 0.2, cont, 3)
    assert got == pytest.approx(3 * 2 * math.pi * speeds / t.reach, rel=1e-14)
