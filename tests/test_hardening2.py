"""Adversarial input, second pass (issue 26): chaos, nnm, design and the newer sweep kinds.

CLI cases go through the command (``refused``: exit 2, one line naming the parameter, no
traceback, nothing written); interrupts through a real subprocess; damaged stores through
the store API and the command; the Python API through a property-based test
(test_hardening_api.py).
"""

import pytest
from test_hardening import refused

WELL = ["--alpha", "0.5", "--beta", "0.3", "--n", "4"]
CHAOS = ["chaos", *WELL, "--runs", "2", "--periods", "2", "--quiet"]
NNM = ["nnm", *WELL, "--continue", "energy"]
DESIGN = ["design", "--beta", "0.3", "--n", "4", "--out", "d.zarr", "--quiet"]
SWEEP_CHAOS = ["sweep", "chaos", "--param", "alpha=0.5", "--param", "beta=0.3", "--param", "n=4"]
SWEEP_DESIGN = ["sweep", "design", "--param", "beta=0.3", "--param", "n=4"]
SWEEP_ENSEMBLE = ["sweep", "ensemble", "--param", "alpha=0.5", "--param", "beta=0.3"]
SWEEP_ENSEMBLE += ["--param", "n=4"]
OUT = ["--out", "s.zarr", "--quiet"]

# (argv, parameter named, text the line must contain)
CASES = [
    # item 1: tracebacks before
    ([*CHAOS, "--renorm", "1e308"], "renorm", "[0, 1000000000]"),
    ([*NNM, "--ds", "1e308"], "ds", "[1e-06, 10]"),
    ([*NNM, "--ds", "1e300"], "ds", "[1e-06, 10]"),
    ([*DESIGN, "--box", "1e308"], "box", "inside the walls"),
    ([*DESIGN, "--bootstrap", "1e308"], "bootstrap", "[2, 100000]"),
    ([*SWEEP_CHAOS, "--param", "gali=2,6", *OUT], "gali", "a single value"),
    ([*SWEEP_CHAOS, "--param", "transverse=0,1", *OUT], "transverse", "a single value"),
    # item 2: the parameter responsible, before any file exists
    ([*SWEEP_ENSEMBLE, "--param", "gamma=1e308", *OUT], "gamma", "with gamma = 1 it can"),
    ([*DESIGN, "--gamma", "1e308"], "gamma", "with gamma = 1 it can"),
    ([*CHAOS, "--gamma", "1e308"], "gamma", "with gamma = 1 it can"),
    # item 3: absurd sizes refused up front, with the estimate
    (["nnm", *WELL, "--continue", "energy", "--steps", "1000000000"], "steps", "1000000]"),
    ([*NNM, "--points", "10000", "--ds", "1e-300"], "ds", "[1e-06, 10]"),
    ([*DESIGN, "--bootstrap", "1000000000"], "bootstrap", "[2, 100000]"),
    (["chaos", *WELL, "--particles", "1000", "--spectrum", "--quiet"], "spectrum", "4002"),
    # item 4: values accepted that should not be
    ([*SWEEP_CHAOS, "--param", "megno=2", *OUT], "megno", "[0, 1]"),
    ([*SWEEP_CHAOS, "--param", "megno=-1", *OUT], "megno", "[0, 1]"),
    ([*SWEEP_DESIGN, "--param", "replica=-1", *OUT], "replica", ">= 0"),
    ([*DESIGN, "--lyapunov-periods", "-1", "--lyapunov-runs", "0"], "lyapunov_periods", "[1,"),
    ([*DESIGN, "--lyapunov-periods", "0", "--lyapunov-runs", "0"], "lyapunov_periods", "[1,"),
    ([*DESIGN, "--lyapunov-periods", "0"], "lyapunov_periods", "[1,"),
]


@pytest.mark.parametrize(("argv", "name", "says"), CASES, ids=lambda a: " ".join(a)[-48:])
def test_refused_cleanly_naming_the_parameter(argv, name, says, capsys, tmp_path, monkeypatch):
    line = refused(argv, capsys, tmp_path, monkeypatch, name)
    assert says in line, line


def test_spectrum_cost_grows_with_the_square_of_the_dimension():
    """The estimate counts 2D vectors of 2D components: against a hand count."""
    from sinktheory import RunSettings, Sink, Well
    from sinktheory.chaos.sink import check_tangent_work, tangent_runs
    from sinktheory.errors import ParameterError
    from sinktheory.model import MAX_SECONDS, SECONDS_PER_PARTICLE_STEP
    from sinktheory.worklimit import VECTOR_STEP

    assert tangent_runs(201, "full", 0, False) == [402]
    assert tangent_runs(201, "half", 4, True) == [201, 4, 1]
    sink = Sink(Well(0.5, 0.3, 4), particles=100, mass=0.2)
    # 100 particles, 402 vectors: k (1 + 0.3 x 402) particle steps per step and run
    per_step = 100 * (1 + VECTOR_STEP * 402)
    limit = MAX_SECONDS / SECONDS_PER_PARTICLE_STEP
    periods = int(limit / (per_step * 1000 * 10)) + 1  # just over the limit at 1000 steps
    check_tangent_work(sink, RunSettings(runs=10, periods=periods - 2), 1000, "full", 0, False)
    with pytest.raises(ParameterError) as info:
        check_tangent_work(sink, RunSettings(runs=10, periods=periods), 1000, "full", 0, False)
    assert info.value.name == "spectrum"  # lambda_1 alone would fit
    with pytest.raises(ParameterError) as info:
        check_tangent_work(sink, RunSettings(runs=10, periods=periods * 1000), 1000, None, 0, 0)
    assert info.value.name == "periods"
