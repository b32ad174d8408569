"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules sweep,
floquet, bifurcation, validation, glossary, worklimit, userwell, cli, progress.

Its tables (``overrides``, ``fixed_leaks``, ``HEAVY``, ``RECORDS``,
``PENDING_BY_REASON``) are laid out as tests/_fuzz.py describes.
"""

import io

#: The bifurcation sweep whose dataset the views are given.
_SECTIONS = {"alpha": 0.5, "beta": [0.1, 0.3], "n": 4, "transient": 2, "count": 3}


def _dataset():
    from sinktheory.sweep import run_sweep

    return run_sweep("bifurcation", _SECTIONS, workers=1, progress=False)


def _store():
    """A small sweep store in the fuzz's scratch directory (its path made absolute)."""
    from pathlib import Path

    from sinktheory.sweep import run_sweep

    path = Path("fuzz-sweep-store.zarr").resolve()
    if not path.exists():
        params = {"alpha": 0.5, "beta": [-0.2, 0.1], "n": 4}
        run_sweep("floquet", params, store=path, workers=1, progress=False)
    return path


def _paper_flat():
    """The paper's flat well typed as a user's well at n = 4 (the engine
    tests/studies/test_user_well_sweep.py compiles too)."""
    from _cli import BUILT_IN, PAPER

    from sinktheory.userwell import UserWell
    from sinktheory.wellat import WellAt

    return WellAt(UserWell("paperflat", BUILT_IN["flat"], PAPER), n=4)


def _tilted_hill():
    from sinktheory.floquet import well_hill
    from sinktheory.userwell import UserWell

    return well_hill(UserWell("tilted", "(x**2 + 1.2*y**2)/2 + 0.3*x*y**2", {}))


def _bowl():
    from sinktheory.userwell import UserWell

    return UserWell("bowl", "k*(x**2 + y**2)/2 + x**4", {"k": (1.0, (0.5, 2.0))})


def overrides() -> dict:
    """Valid keyword arguments of the entry points of this area, by key."""
    from _fuzz import Lazy  # _fuzz imports this module: not at its top

    s = "sinktheory."
    dataset = Lazy(_dataset)
    return {
        s + "cli.main": dict(argv=["period", "--n", "2", "--amplitude", "1"]),
        s + "progress.ProgressBar": dict(total=3, stream=io.StringIO()),
        s + "sweep.store.read": dict(path=Lazy(_store)),
        s + "sweep.views.bifurcation_diagram": dict(dataset=dataset),
        s + "sweep.views.split_points": dict(dataset=dataset),
        s + "floquet.well_scan": dict(hill=Lazy(_tilted_hill), amplitude_range=(0.5, 1.5, 3)),
        s + "bifurcation.well_bifurcation": dict(well=Lazy(_paper_flat), parameter="beta",
                                                  values=[0.1, 0.3], transient=2, count=3),
        s + "userwell.read_well": dict(
            text='name = "bowl"\npotential = "k*(x**2 + y**2)/2"\n[parameters]\n'
            "k = { default = 1.0 }\n"),
        s + "userwell.well_text": dict(well=Lazy(_bowl)),
    }  # fmt: skip


def fixed_leaks() -> list:
    """(call, parameter its ParameterError must name) of each leak fixed in this area."""
    from sinktheory.cli import main
    from sinktheory.progress import ProgressBar
    from sinktheory.sweep.store import read
    from sinktheory.sweep.views import bifurcation_diagram, split_points

    return [
        (lambda: main(True), "argv"),  # TypeError
        (lambda: main([1.0, 2.0]), "argv"),  # AttributeError
        (lambda: main("period"), "argv"),  # read letter by letter
        (lambda: ProgressBar(3, delay=None), "delay"),  # TypeError
        (lambda: ProgressBar(3, label=None), "label"),  # AttributeError
        (lambda: ProgressBar("x"), "total"),  # ValueError
        (lambda: read(None), "path"),  # zarr's GroupNotFoundError
        (lambda: read("no-such.zarr"), "path"),  # FileNotFoundError
        (lambda: bifurcation_diagram(None), "dataset"),  # AttributeError
        (lambda: split_points("x"), "dataset"),  # AttributeError
    ]


#: Entry points of this area whose calls take seconds: fewer examples.
HEAVY: set[str] = {"sinktheory.bifurcation.well_bifurcation"}

#: Records the package returns, by key: what returns each.
RECORDS: dict[str, str] = {
    "sinktheory.bifurcation.BifurcationDiagram": "returned by bifurcation.bifurcation",
    "sinktheory.bifurcation.WellBifurcation": "returned by bifurcation.well_bifurcation",
    "sinktheory.floquet.Boundary": "returned by floquet.scan and well_scan (boundaries)",
    "sinktheory.floquet.FloquetChart": "returned by floquet.model_hill and pure_hill",
    "sinktheory.floquet.HillProblem": "returned by floquet.model_problem and pure_problem",
    "sinktheory.floquet.StabilityScan": "returned by floquet.scan, model_scan and pure_scan",
    "sinktheory.floquet.WellFloquet": "returned by floquet.well_floquet",
    "sinktheory.floquet.WellHill": "returned by floquet.well_hill",
    "sinktheory.floquet.WellScan": "returned by floquet.well_scan",
    "sinktheory.sweep.grid.Grid": "returned by sweep.grid.Grid.from_params (Sweep.make's grid)",
    "sinktheory.sweep.kinds.Kind": "returned by sweep.kinds.get_kind",
    "sinktheory.sweep.kinds.Param": "returned by sweep.kinds.get_kind (a Kind's params)",
    "sinktheory.sweep.kinds.Result": "returned by sweep.kinds.get_kind (a Kind's results)",
    "sinktheory.sweep.runner.SweepRun": "returned by sweep.runner.execute",
    "sinktheory.userwell.WellCheck": "returned by userwell.check_well",
}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {}
