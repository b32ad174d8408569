"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules design,
scenes, report.

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
        "sinktheory.design.inelastic_reference.contact_weight",  # q=None: TypeError
        "sinktheory.design.inelastic_reference.solve_damped_ivp",  # damping=None: TypeError
        "sinktheory.design.measures.default_window",  # periods=None: TypeError
        "sinktheory.design.measures.longest_excursion",  # mean=None: nonfinite
        "sinktheory.design.measures.sustained_crossing",  # mean='x': ValueError
        "sinktheory.design.point.equipartition_n",  # p={...}['x']: TypeError
        "sinktheory.design.point.user_shape",  # p=None: TypeError
        "sinktheory.design.report.fmt",  # digits=None: ValueError
        "sinktheory.scenes.estimate",  # number=None: KeyError
        "sinktheory.scenes.orbits.false_call",  # runs=None: TypeError
        "sinktheory.scenes.trajectories.indicators",  # periods=None: TypeError
        "sinktheory.scenes.wells.level_line_curvature",  # h=None: TypeError
    ),
    "valid arguments not written yet": (
        "sinktheory.design.cost.work",
        "sinktheory.design.explorer.todo_of",
        "sinktheory.design.inelastic_reference.dissipate",
        "sinktheory.design.inelastic_reference.simulate_inelastic_reference",
        "sinktheory.design.measures.design_measures",
        "sinktheory.design.point.attachment_of",
        "sinktheory.design.point.check",
        "sinktheory.design.point.compute",
        "sinktheory.design.point.ensemble",
        "sinktheory.design.point.lyapunov",
        "sinktheory.design.ranking.design_table",
        "sinktheory.design.ranking.rank",
        "sinktheory.design.report.damper",
        "sinktheory.design.report.is_damped",
        "sinktheory.design.report.lambda1_text",
        "sinktheory.design.report.report_text",
        "sinktheory.design.report.table_rows",
        "sinktheory.design.report.write_csv",
        "sinktheory.design.report.write_report",
        "sinktheory.design.settling.predicted_settling",
        "sinktheory.design.settling.settling_column",
        "sinktheory.design.settling.settling_fields",
        "sinktheory.design.settling.settling_text",
        "sinktheory.report.closing",
        "sinktheory.report.render",
        "sinktheory.scenes.ensembles.ensemble",
        "sinktheory.scenes.ensembles.long_time",
        "sinktheory.scenes.horizons.describe",
        "sinktheory.scenes.horizons.horizon",
        "sinktheory.scenes.horizons.settling_time",
        "sinktheory.scenes.orbits.generic_runs",
        "sinktheory.scenes.orbits.mode_touching",
        "sinktheory.scenes.orbits.transverse_calls",
        "sinktheory.scenes.scene",
    ),
    "a result record the package builds": (
        "sinktheory.design.cost.Estimate",
        "sinktheory.design.explorer.DesignRun",
        "sinktheory.design.measures.DesignMeasures",
        "sinktheory.report.SceneOutcome",
        "sinktheory.scenes.base.Claim",
        "sinktheory.scenes.base.Scene",
        "sinktheory.scenes.base.SceneResult",
        "sinktheory.scenes.ensembles.LongTime",
    ),
}
