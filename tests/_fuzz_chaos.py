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
RECORDS: dict[str, str] = {}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {
    "leaks raw exceptions on hostile input (the first found is noted); its validation is not "
    "written yet": (
        "sinktheory.chaos.general.check_bound",  # bound=inf: nonfinite
        "sinktheory.chaos.general.check_gali",  # dim=None: TypeError
        "sinktheory.chaos.general.check_params",  # runs=[]: TypeError
        "sinktheory.chaos.general.vector_count",  # dim=None: TypeError
        "sinktheory.chaos.sink.check_tangent_work",  # gali=None: TypeError
        "sinktheory.chaos.sink.tangent_runs",  # gali=None: TypeError
        "sinktheory.chaos.sink.transverse_mask",  # particles=None: TypeError
        "sinktheory.chaos.staged.looks",  # periods=None: TypeError
        "sinktheory.chaos.vectors.vector_seed",  # run=None: TypeError
        "sinktheory.nnm.modes.fixed_container_amplitude",  # sink=None: AttributeError
        "sinktheory.nnm.system.parameter_names",  # system=None: AttributeError
    ),
    "valid arguments not written yet": (
        "sinktheory.chaos.general.check_transverse",
        "sinktheory.chaos.points.check_point",
        "sinktheory.chaos.points.points",
        "sinktheory.chaos.result.time_average",
        "sinktheory.chaos.sink.chaos_batch",
        "sinktheory.chaos.sink.point_steps",
        "sinktheory.chaos.staged.staged_chaos",
        "sinktheory.chaos.staged.staged_exponent",
        "sinktheory.chaos.vectors.orthonormalise",
        "sinktheory.chaos.verdicts.agreement",
        "sinktheory.chaos.verdicts.box_starts",
        "sinktheory.chaos.verdicts.map_calls",
        "sinktheory.chaos.verdicts.map_split",
        "sinktheory.chaos.verdicts.point_values",
        "sinktheory.chaos.verdicts.stored_split",
        "sinktheory.chaos.verdicts.stored_splits",
        "sinktheory.chaos.verdicts.verdicts",
        "sinktheory.nnm.agreement.agreement_report",
        "sinktheory.nnm.agreement.statement",
        "sinktheory.nnm.agreement.transverse_chart",
        "sinktheory.nnm.backbone.container_share",
        "sinktheory.nnm.backbone.localisation_energy",
        "sinktheory.nnm.continuation.check_stop",
        "sinktheory.nnm.continuation.merge",
        "sinktheory.nnm.continuation.switch_branch",
        "sinktheory.nnm.continuation.tangent",
        "sinktheory.nnm.modes.check_user_well",
        "sinktheory.nnm.modes.linear_modes",
        "sinktheory.nnm.shooting.checked_start",
        "sinktheory.nnm.shooting.checked_steps",
        "sinktheory.nnm.shooting.subspace_indices",
        "sinktheory.nnm.stability.angles",
        "sinktheory.nnm.stability.classify",
        "sinktheory.nnm.stability.reduced_monodromy",
    ),
    "a result record the package builds": (
        "sinktheory.chaos.result.ChaosResult",
        "sinktheory.chaos.staged.StagedExponent",
        "sinktheory.chaos.verdicts.Split",
        "sinktheory.nnm.agreement.TransverseChart",
        "sinktheory.nnm.continuation.Branch",
        "sinktheory.nnm.continuation.Event",
        "sinktheory.nnm.result.BranchResult",
        "sinktheory.nnm.shooting.Orbit",
        "sinktheory.nnm.shooting.ShootingProblem",
        "sinktheory.nnm.stability.Floquet",
    ),
}
