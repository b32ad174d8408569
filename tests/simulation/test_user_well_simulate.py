"""``simulate`` on a user's well (:class:`sinktheory.wellat.WellAt`): the paper's flat well
typed as a user's expression runs as the registry's well, and a Hénon–Heiles well is
integrated below its escape energy and refused above it.

References: the registry's flat well (a second derivation of the same model: its
hand-declared wall ratios against SymPy's derivatives of the user's text), and the
Hénon–Heiles escape energy 1/6 (the saddles' height, exact).
"""

import numpy as np
import pytest
from _cli import BUILT_IN, HH, PAPER

from sinktheory import RunSettings, Sink, Well
from sinktheory.errors import ParameterError
from sinktheory.simulate import simulate
from sinktheory.userwell import UserWell
from sinktheory.wellat import WellAt


def test_the_flat_well_typed_by_a_user_simulates_as_the_registry():
    """Same step, same start, the container's energy to 1e-12 over 3 periods (measured:
    identical), and the run's parameters are the well's own."""
    settings = RunSettings(runs=4, periods=3, seed=2)
    user = simulate(Sink(WellAt(UserWell("paperflat", BUILT_IN["flat"], PAPER)), 3, 0.2), settings)
    registry = simulate(Sink(Well(0.5, 0.3, 4), 3, 0.2), settings)
    assert user.dt == registry.dt
    np.testing.assert_allclose(user.container_energy, registry.container_energy, rtol=1e-12)
    assert user.parameters["shape"] == "paperflat" and user.parameters["n"] == 4.0


def test_henon_heiles_runs_below_its_escape_energy_and_is_refused_above():
    hh = Sink(WellAt(UserWell("hh", HH, {})), particles=2, mass=0.2)
    res = simulate(hh, RunSettings(container_energy=0.02, runs=3, periods=5, seed=1))
    assert res.run_errors.max() < 1e-8
    with pytest.raises(ParameterError, match=r"container_energy = 0.5 .*0\.166666667"):
        simulate(hh, RunSettings(container_energy=0.5, runs=3, periods=5, seed=1))
    with pytest.raises(ParameterError, match="^stepper = "):
        simulate(hh, RunSettings(container_energy=0.02, runs=1, periods=1), stepper="adaptive")
    with pytest.raises(ParameterError, match="^box = "):
        simulate(hh, RunSettings(container_energy=0.02, runs=1, periods=1, box=2.0))


def test_a_start_outside_the_basin_is_refused():
    hh = Sink(WellAt(UserWell("hh", HH, {})), particles=1, mass=0.2)
    with pytest.raises(ParameterError, match="^initial = "):
        simulate(hh, RunSettings(container_energy=0.02, runs=1, periods=1), initial=[(0.0, 2.0)])


def test_the_command_line_runs_a_well_file_as_python_does(capsys):
    """``simulate --well FILE --well-param`` equals ``simulate`` of a WellAt; a shape option
    beside the file and the adaptive stepper are refused (exit 2)."""
    import json
    from pathlib import Path

    from _cli import run_cli

    from sinktheory.userwell import load_well

    path = str(Path(__file__).parents[2] / "docs" / "guide" / "elliptic.toml")
    argv = ["simulate", "--well", path, "--well-param", "n=3", "--particles", "2", "--runs",
            "2", "--periods", "2", "--json"]  # fmt: skip
    code, out, err = run_cli(argv, capsys)
    assert code == 0, err
    data = json.loads(out)
    sink = Sink(WellAt(load_well(path), n=3), particles=2, mass=0.2)
    direct = simulate(sink, RunSettings(runs=2, periods=2), progress=False)
    assert data["container_energy"] == direct.container_energy.tolist()
    assert data["parameters"]["n"] == 3.0 and data["parameters"]["shape"] == "elliptic"
    for extra in (["--alpha", "0.5"], ["--stepper", "adaptive"]):
        code, out, err = run_cli([*argv[:-1], *extra], capsys)
        assert code == 2 and out == "" and len(err.strip().splitlines()) == 1, (extra, err)
