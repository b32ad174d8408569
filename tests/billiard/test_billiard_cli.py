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
    """Issue 34: E0 = 1e18 ran 28 s, then failed.  The flights' work is priced by the
    collisions expected at the particles' speed sqrt(2 E0 / m) over the table's mean free
    path (BILLIARD_SECONDS per collision and per particle-period); here by hand."""
    import math

    from _cli import refused

    from sinktheory.billiard.run import BILLIARD_SECONDS as cost
    from sinktheory.billiard.table import rigid_table

    mfp = rigid_table("flat", 0.5, 0.3).mean_free_path
    collisions = 2 * 10 * 2 * math.pi * math.sqrt(2e18 / 0.2) / mfp
    argv = ["billiard", "--alpha", "0.5", "--beta", "0.3", "--container-energy", "1e18",
            "--runs", "2", "--periods", "10"]  # fmt: skip
    line = refused(argv, capsys, tmp_path, monkeypatch, "periods")
    assert f"about {collisions:.3g} collisions" in line, line
    slow = 1 + 3 / (1 + math.sqrt(2e18) / mfp)  # the container's amplitude over the table
    seconds = 20 * cost["period"] + collisions * (cost["moving"] + cost["per_particle"]) * slow
    assert f"about {seconds / 86400:.3g} days" in line, line
    # fixed container: the one particle has the same speed, each collision its own price
    line = refused([*argv, "--fixed"], capsys, tmp_path, monkeypatch, "periods")
    assert f"about {collisions:.3g} collisions" in line, line
    seconds = 20 * cost["period"] + collisions * cost["collision"]
    assert f"about {seconds / 86400:.3g} days" in line, line


def test_expected_collisions_against_a_hand_count():
    """expected_collisions of a moving container: E = (3^2 + 4^2) / 2 + 0.5 x 0.2 x 1^2 =
    12.6 and 0.5 in the two runs, a particle's speed sqrt(2 E / (k mu)); two runs add up."""
    import math

    from sinktheory.billiard.run import expected_collisions
    from sinktheory.billiard.table import stadium_table

    t = stadium_table(1, 1)
    vel = np.array([[[1.0, 0.0]], [[0.0, 0.0]]])
    cont = np.array([[3.0, 4.0], [0.0, 1.0]])
    speeds = math.sqrt(2 * 12.6 / 0.2) + math.sqrt(2 * 0.5 / 0.2)
    got = expected_collisions(t, vel, 0.2, cont, 3)
    assert got == pytest.approx(3 * 2 * math.pi * speeds / t.mean_free_path, rel=1e-14)
    # area pi + 4, perimeter 2 pi + 4 (two half discs of radius 1 and a 2 x 2 square)
    assert t.mean_free_path == pytest.approx(math.pi * (math.pi + 4) / (2 * math.pi + 4))
