"""``sinktheory equilibrium``: the CLI prints the API's law; bad input is one line, exit 2,
no file."""

import json

import pytest
from _cli import run_cli as run

from sinktheory.canonical import FIG8_WELL
from sinktheory.equilibrium import equilibrium_law
from sinktheory.model import Sink

FIG8 = ["equilibrium", "--alpha", "0.5", "--beta", "0.3", "--n", "4"]


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5])
def test_cli_equals_api_for_the_fig8_wells(k, capsys):
    code, out, err = run([*FIG8, "--particles", str(k), "--json"], capsys)
    assert code == 0, err
    data = json.loads(out)
    law = equilibrium_law(Sink(FIG8_WELL, particles=k), 0.5)
    assert data["law"]["mean"] == law.mean
    assert data["fractions"] == [0.1, 0.2, 0.3, 0.5, 0.8]
    assert data["tails"] == law.tail([0.1, 0.2, 0.3, 0.5, 0.8]).tolist()
    assert data["kac_periods"] == [1 / p for p in data["tails"]]


def test_text_and_plot(tmp_path, capsys):
    png = tmp_path / "law.png"
    code, out, err = run(
        [*FIG8, "--particles", "2", "--fractions", "0.5", "--plot", str(png)], capsys
    )
    assert code == 0, err
    assert "<E_c>" in out and "Kac" in out
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


SYM = ["equilibrium", "--alpha", "0.5", "--beta", "0.3", "--n", "2", "--shape", "symmetric"]


@pytest.mark.parametrize(
    "argv,name",
    [
        ([*FIG8, "--particles", "0"], "particles"),
        ([*FIG8, "--fractions", "0"], "fractions"),
        ([*FIG8, "--fractions", "0.5", "1"], "fractions"),
        ([*FIG8, "--fractions", "-0.1"], "fractions"),
        ([*FIG8, "--total-energy", "0"], "total_energy"),
        ([*FIG8, "--total-energy", "nan"], "total_energy"),
        ([*FIG8, "--mass", "-1"], "mass"),
        ([*SYM, "--total-energy", "10"], "total_energy"),  # above the corner saddle 8.68
        (
            ["equilibrium", "--alpha", "0.5", "--beta", "-0.3", "--n", "4", "--total-energy", "50"],
            "beta",
        ),
        (["equilibrium", "--alpha", "0.5", "--beta", "0.5", "--n", "4"], "beta"),
    ],
)
def test_bad_input_one_line_exit_2_nothing_written(argv, name, tmp_path, capsys):
    png = tmp_path / "law.png"
    code, out, err = run([*argv, "--plot", str(png)], capsys)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and f"error: {name} = " in err
    assert not png.exists() and list(tmp_path.iterdir()) == []


LIFE = ["lifetime", "--alpha", "0.5", "--beta", "0.3", "--n", "4"]


def test_lifetime_cli_equals_api(tmp_path, capsys):
    from sinktheory import RunSettings
    from sinktheory.equilibrium.lifetime import measure_lifetimes

    png = tmp_path / "life.png"
    argv = [*LIFE, "--runs", "2", "--periods", "60", "--transient", "20", "--fractions", "0.5"]
    code, out, err = run([*argv, "--json", "--plot", str(png)], capsys)
    assert code == 0, err
    data = json.loads(out)
    c, _ = measure_lifetimes(
        Sink(FIG8_WELL), RunSettings(runs=2, periods=60), transient=20, fractions=[0.5]
    )
    assert data["mean"] == c.mean and data["ks_distance"] == c.ks_distance
    assert data["kac_periods"] == c.kac_periods.tolist() and data["samples"] == 41
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(
    "argv,name",
    [
        ([*LIFE, "--runs", "1"], "runs"),
        ([*LIFE, "--periods", "50", "--transient", "50"], "transient"),
        ([*LIFE, "--fractions", "1.0"], "fractions"),
        ([*LIFE, "--particles", "0"], "particles"),
    ],
)
def test_lifetime_bad_input(argv, name, tmp_path, capsys):
    png = tmp_path / "life.png"
    code, out, err = run([*argv, "--plot", str(png)], capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and f"error: {name} = " in err
    assert list(tmp_path.iterdir()) == []
