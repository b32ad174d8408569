"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules engine,
codegen, symbolic, twins, integrators, adaptive, stepsize, hill, series, oscillator.

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
        "sinktheory.codegen.GeometryPrinter",  # settings=True: TypeError
        "sinktheory.codegen.KernelPrinter",  # settings=True: TypeError
        "sinktheory.codegen.write",  # directory=None: TypeError
        "sinktheory.engine.blocks.groups_of",  # steps=None: TypeError
        "sinktheory.engine.cache.user_well",  # name=[]: TypeError
        "sinktheory.symbolic.denominator",  # s=None: TypeError
        "sinktheory.symbolic.y_invariance",  # V=None: TypeError
    ),
    "valid arguments not written yet": (
        "sinktheory.adaptive.kernels",
        "sinktheory.codegen.chain",
        "sinktheory.codegen.integer_powers",
        "sinktheory.codegen.kernel_lines",
        "sinktheory.codegen.lowest_powers",
        "sinktheory.symbolic.ladder",
        "sinktheory.symbolic.lift_powers",
        "sinktheory.symbolic.mechanics",
        "sinktheory.symbolic.ratio_derivative",
        "sinktheory.symbolic.substitute_ratios",
        "sinktheory.twins.python_kernel",
    ),
    "a result record the package builds": (
        "sinktheory.engine.blocks.BlockPlan",
        "sinktheory.engine.core.Records",
        "sinktheory.engine.systems.Damping",
        "sinktheory.engine.systems.SeparableSystem",
        "sinktheory.engine.systems.Term",
        "sinktheory.hill.QuarterPeriod",
        "sinktheory.integrators.SplittingScheme",
        "sinktheory.oscillator.Oscillator",
        "sinktheory.series.BoundCheck",
        "sinktheory.series.SeriesAccuracy",
        "sinktheory.series.SeriesError",
        "sinktheory.series.TriangleSeries",
        "sinktheory.stepsize.StepChoice",
        "sinktheory.symbolic.AtomForm",
        "sinktheory.symbolic.Mechanics",
        "sinktheory.symbolic.NormalMode",
        "sinktheory.symbolic.RescaledSystem",
        "sinktheory.symbolic.SeparableHamiltonian",
        "sinktheory.symbolic.Shape",
        "sinktheory.symbolic.WellLadder",
    ),
    "a compiled kernel or engine part, called by checked wrappers": (
        "sinktheory.engine.blocks.block_costs",
        "sinktheory.engine.blocks.candidates",
        "sinktheory.engine.blocks.efficient_width",
        "sinktheory.engine.blocks.fixed",
        "sinktheory.engine.blocks.layout",
        "sinktheory.engine.blocks.measure",
        "sinktheory.engine.blocks.plan",
        "sinktheory.engine.cache.cost_table_path",
        "sinktheory.engine.cache.engine_system",
        "sinktheory.engine.cache.import_generated",
        "sinktheory.engine.cache.load",
        "sinktheory.engine.cache.well_definition",
        "sinktheory.engine.cache.well_name",
        "sinktheory.engine.core.audit_error",
        "sinktheory.engine.core.earliest_failure",
        "sinktheory.engine.printer.cse_lines",
        "sinktheory.engine.printer.render",
        "sinktheory.engine.systems.run_time_symbols",
        "sinktheory.engine.systems.sink_system",
    ),
}
