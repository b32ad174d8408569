"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules equilibrium,
ensemble, basin, model, results, layout, recurrence, sinkstats, simulate.

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
        "sinktheory.basin.numeric",  # expr=None: AttributeError
        "sinktheory.ensemble.default_energy_bound",  # tol=1e+308: nonfinite
        "sinktheory.ensemble.engine_name",  # sink=None: AttributeError
        "sinktheory.ensemble.join_values",  # q=None: AttributeError
        "sinktheory.ensemble.random_positions",  # particles=None: TypeError
        "sinktheory.ensemble.run_parameters",  # runs=nan: nonfinite
        "sinktheory.ensemble.start_positions",  # settings=None: AttributeError
        "sinktheory.ensemble.start_state",  # container_energy=None: TypeError
        "sinktheory.equilibrium.ergodicity.verdict",  # lambda1=None: TypeError
        "sinktheory.equilibrium.prediction.settling_time",  # fraction=None: TypeError
        "sinktheory.layout.pack_params",  # sink=None: AttributeError
        "sinktheory.model.Reach",  # x=nan: nonfinite
        "sinktheory.results.attribute",  # x=nan: nonfinite
        "sinktheory.results.plain",  # x=object(): TypeError
    ),
    "valid arguments not written yet": (
        "sinktheory.basin.NumericWell",
        "sinktheory.basin.escape",
        "sinktheory.basin.leading_order",
        "sinktheory.basin.reach",
        "sinktheory.basin.star_area",
        "sinktheory.ensemble.check_record",
        "sinktheory.ensemble.initial_values",
        "sinktheory.ensemble.prepare",
        "sinktheory.ensemble.settings_of",
        "sinktheory.ensemble.sink_of",
        "sinktheory.ensemble.total_energy",
        "sinktheory.ensemble.well_of_text",
        "sinktheory.equilibrium.ergodicity.check_point",
        "sinktheory.equilibrium.ergodicity.ergodicity_map",
        "sinktheory.equilibrium.prediction.check_reading",
        "sinktheory.equilibrium.prediction.fit_line",
        "sinktheory.equilibrium.prediction.law_chain",
        "sinktheory.equilibrium.prediction.log_lambdas",
        "sinktheory.equilibrium.prediction.measure_settings",
        "sinktheory.equilibrium.prediction.measure_settling",
        "sinktheory.equilibrium.prediction.read_settling",
        "sinktheory.equilibrium.prediction.shell_lags",
        "sinktheory.equilibrium.prediction.shell_prediction",
        "sinktheory.equilibrium.prediction.slow_mode",
        "sinktheory.simulate.check_point",
        "sinktheory.simulate.point",
    ),
    "a result record the package builds": (
        "sinktheory.basin.Basin",
        "sinktheory.basin.Escape",
        "sinktheory.basin.LeadingOrder",
        "sinktheory.basin.Reach",
        "sinktheory.ensemble.SimulationResult",
        "sinktheory.ensemble.SimulationState",
        "sinktheory.ensemble.Start",
        "sinktheory.equilibrium.area.WellArea",
        "sinktheory.equilibrium.ergodicity.ErgodicityMap",
        "sinktheory.equilibrium.kramers.FluctuationDissipation",
        "sinktheory.equilibrium.kramers.KramersMoyal",
        "sinktheory.equilibrium.law.EquilibriumSummary",
        "sinktheory.equilibrium.lifetime.LawComparison",
        "sinktheory.equilibrium.lifetime.VisitStatistics",
        "sinktheory.equilibrium.prediction.LawChain",
        "sinktheory.equilibrium.prediction.RelaxationPrediction",
        "sinktheory.equilibrium.prediction.Settling",
        "sinktheory.equilibrium.relaxation.Relaxation",
        "sinktheory.model.SinkSummary",
        "sinktheory.model.UserWellSummary",
        "sinktheory.model.WellSummary",
        "sinktheory.recurrence.RQA",
        "sinktheory.simulate.Stepper",
        "sinktheory.sinkstats.SinkMeasures",
    ),
}
