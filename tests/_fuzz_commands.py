"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules commands.

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
        "sinktheory.commands.derive.cached_renderings",  # fresh=True: Hang
    ),
    "CLI plumbing: takes a parsed namespace (argv is checked by the CLI tests)": (
        "sinktheory.commands.billiard.add_arguments",
        "sinktheory.commands.billiard.run",
        "sinktheory.commands.chaos.add_arguments",
        "sinktheory.commands.chaos.run",
        "sinktheory.commands.compare.add_arguments",
        "sinktheory.commands.compare.run",
        "sinktheory.commands.derive.add_arguments",
        "sinktheory.commands.derive.run",
        "sinktheory.commands.derive.well_renderings",
        "sinktheory.commands.design.add_arguments",
        "sinktheory.commands.design.params_of",
        "sinktheory.commands.design.run",
        "sinktheory.commands.design.summary_line",
        "sinktheory.commands.equilibrium.add_arguments",
        "sinktheory.commands.equilibrium.run",
        "sinktheory.commands.floquet.add_arguments",
        "sinktheory.commands.floquet.run",
        "sinktheory.commands.lifetime.add_arguments",
        "sinktheory.commands.lifetime.run",
        "sinktheory.commands.load",
        "sinktheory.commands.nnm.add_arguments",
        "sinktheory.commands.nnm.run",
        "sinktheory.commands.period.add_arguments",
        "sinktheory.commands.period.decimal_text",
        "sinktheory.commands.period.run",
        "sinktheory.commands.relaxation.add_arguments",
        "sinktheory.commands.relaxation.run",
        "sinktheory.commands.reproduce.add_arguments",
        "sinktheory.commands.reproduce.run",
        "sinktheory.commands.series.add_arguments",
        "sinktheory.commands.series.run",
        "sinktheory.commands.simulate.add_arguments",
        "sinktheory.commands.simulate.run",
        "sinktheory.commands.sink.add_arguments",
        "sinktheory.commands.sink.run",
        "sinktheory.commands.sweep.add_arguments",
        "sinktheory.commands.sweep.estimate_line",
        "sinktheory.commands.sweep.params_of",
        "sinktheory.commands.sweep.params_with_well",
        "sinktheory.commands.sweep.run",
        "sinktheory.commands.sweep.split_summary",
        "sinktheory.commands.well.add_arguments",
        "sinktheory.commands.well.run",
    ),
}
