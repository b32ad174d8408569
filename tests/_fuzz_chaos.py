"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules chaos, nnm.

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
    "sinktheory.chaos.result.ChaosResult": "returned by chaos.chaos, chaos_batch, indicators",
    "sinktheory.chaos.staged.StagedExponent": "returned by chaos.staged.staged_chaos",
    "sinktheory.chaos.verdicts.Split": "returned by chaos.verdicts.split",
    "sinktheory.nnm.agreement.TransverseChart": "returned by nnm.agreement.transverse_chart",
    "sinktheory.nnm.continuation.Branch": "returned by nnm.continuation.continue_orbits",
    "sinktheory.nnm.continuation.Event": "in the events of nnm.continuation.continue_orbits",
    "sinktheory.nnm.result.BranchResult": "returned by nnm.continuation.continue_both",
    "sinktheory.nnm.shooting.Orbit": "returned by nnm.shooting.shoot",
    "sinktheory.nnm.stability.Floquet": "returned by nnm.stability.floquet",
}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {
    "valid arguments not written yet": (
        "sinktheory.chaos.sink.chaos_batch",
        "sinktheory.chaos.verdicts.agreement",
        "sinktheory.chaos.verdicts.map_calls",
        "sinktheory.chaos.verdicts.verdicts",
        "sinktheory.nnm.agreement.agreement_report",
        "sinktheory.nnm.agreement.transverse_chart",
        "sinktheory.nnm.backbone.localisation_energy",
        "sinktheory.nnm.continuation.switch_branch",
        "sinktheory.nnm.modes.linear_modes",
    ),
}
