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
RECORDS: dict[str, str] = {
    "sinktheory.basin.Basin": "returned by Basin.of (userwell.check_well(...).basin)",
    "sinktheory.basin.Escape": "returned by basin.escape",
    "sinktheory.basin.LeadingOrder": "returned by basin.leading_order",
    "sinktheory.basin.Reach": "returned by Basin.reach",
    "sinktheory.ensemble.SimulationResult": "returned by simulate and simulate_adaptive",
    "sinktheory.ensemble.Start": "returned by ensemble.prepare",
    "sinktheory.equilibrium.area.WellArea": "returned by WellArea.of",
    "sinktheory.equilibrium.ergodicity.ErgodicityMap": "returned by ergodicity_map",
    "sinktheory.equilibrium.kramers.FluctuationDissipation": "returned by "
    "check_fluctuation_dissipation",
    "sinktheory.equilibrium.kramers.KramersMoyal": "returned by kramers_moyal and "
    "measure_kramers_moyal",
    "sinktheory.equilibrium.law.EquilibriumSummary": "returned by EquilibriumLaw.summary",
    "sinktheory.equilibrium.lifetime.LawComparison": "returned by compare_with_law",
    "sinktheory.equilibrium.lifetime.VisitStatistics": "returned by visit_statistics",
    "sinktheory.equilibrium.prediction.LawChain": "returned by law_chain",
    "sinktheory.equilibrium.prediction.RelaxationPrediction": "returned by "
    "predict_relaxation and shell_prediction",
    "sinktheory.equilibrium.prediction.Settling": "returned by settling_periods",
    "sinktheory.equilibrium.relaxation.Relaxation": "returned by measure_relaxation",
    "sinktheory.model.Reach": "returned by Well.reach",
    "sinktheory.model.SinkSummary": "returned by Sink.summary",
    "sinktheory.model.UserWellSummary": "returned by user_well_summary",
    "sinktheory.model.WellSummary": "returned by Well.summary",
    "sinktheory.recurrence.RQA": "returned by rqa and rqa_matrix",
    "sinktheory.simulate.Stepper": "the entries of simulate.STEPPERS (built by the package)",
    "sinktheory.sinkstats.SinkMeasures": "returned by sink_measures",
}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {
    "leaks raw exceptions on hostile input (the first found is noted); its validation is not "
    "written yet": (
        "sinktheory.basin.NumericWell",
        "sinktheory.basin.escape",
        "sinktheory.basin.leading_order",
        "sinktheory.ensemble.SimulationState",
        "sinktheory.ensemble.engine_name",  # sink=None: AttributeError
        "sinktheory.ensemble.join_values",  # q=None: AttributeError
        "sinktheory.ensemble.prepare",
        "sinktheory.ensemble.random_positions",  # particles=None: TypeError
        "sinktheory.ensemble.run_parameters",  # runs=nan: nonfinite
        "sinktheory.ensemble.start_state",  # container_energy=None: TypeError
        "sinktheory.ensemble.total_energy",
        "sinktheory.equilibrium.ergodicity.ergodicity_map",
        "sinktheory.equilibrium.prediction.law_chain",
        "sinktheory.equilibrium.prediction.log_lambdas",
        "sinktheory.equilibrium.prediction.measure_settling",
        "sinktheory.equilibrium.prediction.read_settling",
        "sinktheory.equilibrium.prediction.shell_lags",
        "sinktheory.equilibrium.prediction.shell_prediction",
        "sinktheory.equilibrium.prediction.slow_mode",
        "sinktheory.layout.pack_params",  # sink=None: AttributeError
    ),
}
