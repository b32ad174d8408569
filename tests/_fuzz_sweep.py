"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules sweep,
floquet, bifurcation, validation, glossary, worklimit, userwell, cli, progress.

* :func:`overrides`: valid keyword arguments by key, where the parameters' names do not
  give them (tests/_fuzz.py's ``_valid``); a value costly to build is wrapped in
  ``_fuzz.Lazy`` (built when first fuzzed, not when collected);
* :func:`fixed_leaks`: each leak the fuzz found and that is fixed, as a call and the
  parameter its ParameterError must name; :data:`HEAVY`: entry points taking seconds;
* :data:`RECORDS`: classes the package builds and returns (dataclasses or NamedTuples
  with no validation of their own), each with what returns it: their constructors are
  not entry points;
* :data:`PENDING_BY_REASON`: the entry points not fuzzed yet, by why.
"""


def overrides() -> dict:
    """Valid keyword arguments of the entry points of this area, by key."""
    return {}


def fixed_leaks() -> list:
    """(call, parameter its ParameterError must name) of each leak fixed in this area."""
    return []


#: Entry points of this area whose calls take seconds: fewer examples.
HEAVY: set[str] = set()

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
PENDING_BY_REASON: dict[str, tuple] = {
    "leaks raw exceptions on hostile input (the first found is noted); its validation is not "
    "written yet": (
        "sinktheory.cli.main",  # argv=True: TypeError
        "sinktheory.progress.ProgressBar",  # delay=None: TypeError
    ),
    "valid arguments not written yet": (
        "sinktheory.bifurcation.well_bifurcation",
        "sinktheory.floquet.well_scan",
        "sinktheory.sweep.store.read",
        "sinktheory.sweep.views.bifurcation_diagram",
        "sinktheory.sweep.views.split_points",
        "sinktheory.userwell.read_well",
        "sinktheory.userwell.well_text",
    ),
}
