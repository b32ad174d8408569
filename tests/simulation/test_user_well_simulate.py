"""``simulate`` on a user's well (:class:`sinktheory.wellat.WellAt`), with the fixed and
the adaptive stepper: the paper's flat well typed as a user's expression runs as the
registry's well, and a Hénon–Heiles well is integrated below its escape energy and refused
above it.

References: the registry's flat well (a second derivation of the same model: its
hand-declared wall ratios against SymPy's derivatives of the user's text), the
Hénon–Heiles escape energy 1/6 (the saddles' height, exact), the fixed stepper at a tight
tolerance (a second method) and the wall layer 1/(2n) of a power-law wall (closed form).
"""

import numpy as np
import pytest
from _cli import BUILT_IN, LIFTED_HH, PAPER

from sinktheory import RunSettings, Sink, Well
from sinktheory import symbolic as S
from sinktheory.adaptive import simulate_adaptive
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
    """Lifted by 1: its energies count from V(0, 0), so the escape energy is still 1/6; the
    energy error is checked in absolute terms (the engine's H0 holds k V(0, 0) = 2)."""
    hh = Sink(WellAt(UserWell("hh", LIFTED_HH, {})), particles=2, mass=0.2)
    res = simulate(hh, RunSettings(container_energy=0.02, runs=3, periods=5, seed=1))
    assert (res.run_errors * np.abs(res.initial_energy)).max() < 1e-10
    with pytest.raises(ParameterError, match=r"container_energy = 0.5 .*0\.166666667"):
        simulate(hh, RunSettings(container_energy=0.5, runs=3, periods=5, seed=1))
    with pytest.raises(ParameterError, match="^box = "):
        simulate(hh, RunSettings(container_energy=0.02, runs=1, periods=1, box=2.0))


def test_a_start_outside_the_basin_is_refused():
    hh = Sink(WellAt(UserWell("hh", LIFTED_HH, {})), particles=1, mass=0.2)
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
    code, out, err = run_cli([*argv[:-1], "--alpha", "0.5"], capsys)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1, err


#: The registry's flat well as a user types it, with the registry's wall ratios.
FLAT_RATIOS = [str(r) for r in S.wall_ratios("flat")]


def test_the_adaptive_step_runs_the_typed_flat_well_as_the_registry(tmp_path, capsys):
    """With the registry's wall ratios declared, the measured wall layer is 1/(2n) and the
    adaptive step takes the registry's steps: the same container energies (held to 1e-12,
    measured identical), in Python and through ``simulate --well --stepper adaptive``."""
    import json

    from _cli import run_cli, write_well_file

    well = WellAt(UserWell("paperflat", BUILT_IN["flat"], PAPER, FLAT_RATIOS), n=4)
    assert abs(well.wall_layer() - 1 / 8) < 1e-12
    settings = RunSettings(runs=3, periods=3, seed=2)
    registry = simulate_adaptive(Sink(Well(0.5, 0.3, 4), 2, 0.2), settings, eps=0.2)
    user = simulate_adaptive(Sink(well, 2, 0.2), settings, eps=0.2)
    np.testing.assert_allclose(user.container_energy, registry.container_energy, rtol=1e-12)
    assert user.message == registry.message
    path = write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], PAPER, FLAT_RATIOS)
    code, out, err = run_cli(["simulate", "--well", str(path), "--particles", "2", "--runs", "3",
                              "--periods", "3", "--seed", "2", "--stepper", "adaptive", "--eps",
                              "0.2", "--json"], capsys)  # fmt: skip
    assert code == 0, err
    np.testing.assert_allclose(json.loads(out)["container_energy"], registry.container_energy,
                               rtol=1e-12)  # fmt: skip


def test_the_adaptive_step_on_a_well_without_wall_ratios_agrees_with_the_fixed_step():
    """Hénon–Heiles (lifted by 1) declares no wall ratios: the controller follows the local
    frequency alone.  Its container energies agree with the fixed step at tol 1e-10 to
    1e-9 (measured 2.4e-12 unlifted), its absolute energy error below 1e-10."""
    hh = Sink(WellAt(UserWell("hh", LIFTED_HH, {})), particles=2, mass=0.2)
    settings = RunSettings(container_energy=0.02, runs=3, periods=5, seed=1)
    adaptive = simulate_adaptive(hh, settings, eps=0.2)
    fixed = simulate(hh, settings, tol=1e-10)
    assert (adaptive.run_errors * np.abs(adaptive.initial_energy)).max() < 1e-10
    np.testing.assert_allclose(adaptive.container_energy, fixed.container_energy, atol=1e-9)


@pytest.mark.parametrize("n", [1, 4, 25])
def test_the_wall_layer_of_a_power_law_wall_is_one_over_2n(n):
    """V = ((x/a)^2 + (y/b)^2)^n with its ratio w = sqrt((x/a)^2 + (y/b)^2): q . grad V =
    2n V at every point, so the layer is 1/(2n) exactly (held to 1e-12)."""
    well = UserWell("ell", "((x/a)**2 + (y/b)**2)**n", {"a": 0.3, "b": 0.2, "n": (4, (1, 100))},
                    ["sqrt((x/a)**2 + (y/b)**2)"])  # fmt: skip
    assert abs(WellAt(well, n=n).wall_layer() * 2 * n - 1) < 1e-12


def test_wall_ratios_that_never_reach_the_wall_are_refused():
    well = WellAt(UserWell("bowl", "x**2 + y**2", {}, ["1/2"]))
    with pytest.raises(ParameterError, match="^wall_ratios = "):
        well.wall_layer()
