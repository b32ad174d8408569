"""Plotting lives in one package: no module outside ``sinktheory.plot`` imports matplotlib,
and the analyses and sweep workers run without loading it."""

import ast
import subprocess
import sys
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[2] / "sinktheory"


def matplotlib_imports(source: str) -> list[int]:
    """Lines of ``source`` that import matplotlib (any form, at any depth)."""
    lines = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names = [node.module]
        else:
            continue
        if any(n == "matplotlib" or n.startswith("matplotlib.") for n in names):
            lines.append(node.lineno)
    return sorted(lines)


def test_the_checker_finds_every_form_of_import():
    source = (
        "import matplotlib\n"
        "def f():\n    from matplotlib.figure import Figure\n"
        "import numpy, matplotlib.pyplot as plt\n"
        "from matplotlibx import y\n"  # another package: not matplotlib
        "'''import matplotlib in a docstring'''\n"
    )
    assert matplotlib_imports(source) == [1, 3, 4]


def test_only_the_plot_package_imports_matplotlib():
    offenders = {
        str(path.relative_to(PACKAGE.parent)): lines
        for path in PACKAGE.rglob("*.py")
        if "plot" not in path.relative_to(PACKAGE).parts[:1]
        and (lines := matplotlib_imports(path.read_text()))
    }
    assert offenders == {}
    assert matplotlib_imports((PACKAGE / "plot" / "floquet.py").read_text())  # it does look


@pytest.mark.parametrize(
    "code",
    [
        "import sinktheory.bifurcation, sinktheory.recurrence, sinktheory.series",
        "import sinktheory.sweep.runner, sinktheory.sweep.kinds, sinktheory.sweep.chaosmap",
        # a sweep worker's work: one bifurcation point computed
        "from sinktheory.sweep.kinds import KINDS\n"
        "k = KINDS['bifurcation']\n"
        "p = k.complete({'alpha': 0.5, 'beta': 0.3, 'n': 4, 'transient': 1, 'count': 2})\n"
        "k.check(p)\n"
        "assert k.compute(p, 0)['section'].shape == (2,)",
    ],
)
def test_analyses_and_sweep_workers_do_not_load_matplotlib(code):
    probe = code + "\nimport sys\nprint('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_the_probe_sees_matplotlib_when_a_plot_module_is_imported():
    code = "import sinktheory.plot.floquet\nimport sys\nprint('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "True"


def test_no_package_shadows_its_submodules():
    """``from .x import x`` in a package's __init__ would make ``package.x`` the function,
    not the module (ambiguous for users and for the API reference)."""
    import importlib
    import pkgutil
    import types

    import sinktheory

    shadowed = []
    for info in pkgutil.walk_packages(sinktheory.__path__, "sinktheory."):
        parent, _, name = info.name.rpartition(".")
        if name.startswith("_") or parent.startswith("sinktheory._generated"):
            continue
        package = importlib.import_module(parent)
        value = package.__dict__.get(name)
        if value is not None and not isinstance(value, types.ModuleType):
            shadowed.append(info.name)
    assert shadowed == []
    from sinktheory.chaos import chaos, general, indicators

    assert indicators is general.indicators and callable(chaos)
