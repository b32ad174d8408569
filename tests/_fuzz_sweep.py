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
RECORDS: dict[str, str] = {}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {
    "leaks raw exceptions on hostile input (the first found is noted); its validation is not "
    "written yet": (
        "sinktheory.cli.main",  # argv=True: TypeError
        "sinktheory.glossary.modern_argv",  # argv=None: TypeError
        "sinktheory.glossary.option_of",  # name=None: AttributeError
        "sinktheory.progress.ProgressBar",  # delay=None: TypeError
        "sinktheory.sweep.grid.parse_value",  # text=None: AttributeError
        "sinktheory.validation.choice",  # options=None: TypeError
        "sinktheory.validation.fits_memory",  # nbytes=None: TypeError
        "sinktheory.validation.nbytes_text",  # n=None: TypeError
        "sinktheory.validation.positive_int",  # maximum='x': TypeError
        "sinktheory.validation.real_array",  # value=None: nonfinite
        "sinktheory.validation.stiffness",  # value=inf: nonfinite
        "sinktheory.validation.time_step",  # period=None: TypeError
        "sinktheory.validation.writable_directory",  # directory=None: TypeError
        "sinktheory.worklimit.check_particle_steps",  # steps=None: TypeError
        "sinktheory.worklimit.duration",  # seconds=None: TypeError
        "sinktheory.worklimit.ensemble_steps",  # runs='x': ValueError
        "sinktheory.worklimit.tangent_steps",  # particles=None: TypeError
    ),
    "a decorator of the package's own functions": (
        "sinktheory.glossary.refusals_named",
        "sinktheory.glossary.renamed",
    ),
    "valid arguments not written yet": (
        "sinktheory.bifurcation.check_point",
        "sinktheory.bifurcation.points",
        "sinktheory.bifurcation.well_bifurcation",
        "sinktheory.floquet.check_point",
        "sinktheory.floquet.json_value",
        "sinktheory.floquet.point",
        "sinktheory.floquet.rotation_number",
        "sinktheory.floquet.well_scan",
        "sinktheory.sweep.grid.fingerprint",
        "sinktheory.sweep.store.MemoryStore",
        "sinktheory.sweep.store.SweepStore",
        "sinktheory.sweep.store.coordinates",
        "sinktheory.sweep.store.old_spelling",
        "sinktheory.sweep.store.read",
        "sinktheory.sweep.store.selection",
        "sinktheory.sweep.views.bifurcation_diagram",
        "sinktheory.sweep.views.split_points",
        "sinktheory.userwell.read_well",
        "sinktheory.userwell.well_text",
    ),
    "a result record the package builds": (
        "sinktheory.bifurcation.BifurcationDiagram",
        "sinktheory.bifurcation.WellBifurcation",
        "sinktheory.floquet.Boundary",
        "sinktheory.floquet.FloquetChart",
        "sinktheory.floquet.HillProblem",
        "sinktheory.floquet.StabilityScan",
        "sinktheory.floquet.WellFloquet",
        "sinktheory.floquet.WellHill",
        "sinktheory.floquet.WellScan",
        "sinktheory.sweep.grid.Grid",
        "sinktheory.sweep.kinds.Kind",
        "sinktheory.sweep.kinds.Param",
        "sinktheory.sweep.kinds.Result",
        "sinktheory.sweep.runner.SweepRun",
        "sinktheory.userwell.WellCheck",
    ),
}
