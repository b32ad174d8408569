"""Commands answer at once: --help and early refusals import nothing heavy.

Speed itself is measured by benchmarks/bench_startup.py, not asserted here; what a test
can check without a clock is the cause of slowness: which modules a fresh process has
imported when it answers.  numpy, numba, SymPy, mpmath, matplotlib and scipy each cost
0.05-1 s to import.
"""

import inspect
from importlib import import_module

import pytest
from _cli import probe

from sinktheory import scenes
from sinktheory.scenes.base import Scene

#: Commands whose --help is light (the others build their parsers from the sweep layer).
LIGHT_HELP = ("well", "sink", "derive", "simulate", "period", "series", "reproduce", "floquet")
#: Refusals decided before any heavy import: (argv, status).
EARLY_REFUSALS = [
    (["reproduce", "--figure", "6", "--out", "never"], 2),
    (["simulate", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--plot", "x.txt"], 2),
    (["floquet", "--beta", "0.1", "--n", "4"], 2),  # --alpha missing
    (["derive", "--digits", "3"], 2),
    (["period", "--n", "4"], 2),  # neither --amplitude nor --energy
]


@pytest.mark.parametrize("command", LIGHT_HELP)
def test_help_imports_nothing_heavy(command, tmp_path):
    status, heavy, proc = probe([command, "--help"], tmp_path)
    assert status == 0 and heavy == [], proc.stderr
    assert proc.stdout.startswith(f"usage: sinktheory {command}")


@pytest.mark.parametrize("args, status", EARLY_REFUSALS)
def test_early_refusals_import_nothing_heavy(args, status, tmp_path):
    got, heavy, proc = probe(args, tmp_path)
    assert got == status and heavy == [], proc.stderr
    assert "error" in proc.stderr and not any(tmp_path.iterdir())


def test_scene_catalogue_matches_the_scene_modules():
    """Every Scene object in the scene modules is catalogued under its own number, and
    every catalogued figure has a measured run time."""
    found = {}
    for module_name in set(scenes.MODULES.values()):
        module = import_module(f"sinktheory.scenes.{module_name}")
        for _, obj in inspect.getmembers(module, lambda o: isinstance(o, Scene)):
            found[obj.number] = module_name
    assert found == scenes.MODULES
    assert all(scenes.scene(n).number == n for n in scenes.FIGURES)
    assert set(scenes.SECONDS) == set(scenes.FIGURES)
    assert all(0 < q <= p for q, p in scenes.SECONDS.values())


def test_simulate_help_quotes_its_sources():
    """The values the simulate help writes out (to stay light) equal their sources."""
    from sinktheory.commands.simulate import QUOTED
    from sinktheory.integrators import DEFAULT_SCHEME, SCHEMES
    from sinktheory.limits import DEFAULT_EPS, MAX_EPS
    from sinktheory.simulate import ENERGY_BOUND
    from sinktheory.stepsize import DEFAULT_TOL, TOL_RANGE

    assert QUOTED == {
        "schemes": tuple(SCHEMES),
        "default_scheme": DEFAULT_SCHEME,
        "tol_range": tuple(TOL_RANGE),
        "default_tol": DEFAULT_TOL,
        "energy_bound": ENERGY_BOUND,
        "default_eps": DEFAULT_EPS,
        "max_eps": MAX_EPS,
    }
