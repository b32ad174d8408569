"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules billiard,
vibroimpact, attachments, damped, compare.

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
        "sinktheory.attachments.start_rows",  # att=None: AttributeError
        "sinktheory.billiard.convergence.wall_ratios",  # well=None: AttributeError
        "sinktheory.billiard.convergence.wall_terms",  # well=None: AttributeError
        "sinktheory.billiard.impact.kinetic_energy",  # vc=None: TypeError
        "sinktheory.billiard.run.start_directions",  # particles=True: TypeError
        "sinktheory.compare.efficiency.work",  # attachments=None: TypeError
    ),
    "valid arguments not written yet": (
        "sinktheory.billiard.convergence.convergence",
        "sinktheory.billiard.convergence.count_hits",
        "sinktheory.billiard.convergence.lambda_after",
        "sinktheory.billiard.convergence.lyapunov_chart",
        "sinktheory.billiard.convergence.measure",
        "sinktheory.billiard.convergence.power_rate",
        "sinktheory.billiard.impact.velocities_after",
        "sinktheory.billiard.kinetic.kinetic_coefficients",
        "sinktheory.billiard.relaxation.measure_rigid_settling",
        "sinktheory.billiard.relaxation.predict_rigid_relaxation",
        "sinktheory.billiard.relaxation.rigid_shell_increments",
        "sinktheory.billiard.run.check_flights",
        "sinktheory.billiard.run.expected_collisions",
        "sinktheory.billiard.run.flight_seconds",
        "sinktheory.billiard.table.poly_eval",
        "sinktheory.billiard.table.polynomial_table",
        "sinktheory.compare.transfer.transfer_maps",
        "sinktheory.compare.wavelet.ridge_of",
        "sinktheory.vibroimpact.advancement_bound",
        "sinktheory.vibroimpact.check_flights",
        "sinktheory.vibroimpact.flight",
        "sinktheory.vibroimpact.next_hit",
    ),
    "a result record the package builds": (
        "sinktheory.attachments.ImpulseResponse",
        "sinktheory.billiard.convergence.Convergence",
        "sinktheory.billiard.convergence.LyapunovChart",
        "sinktheory.billiard.convergence.Measurement",
        "sinktheory.billiard.run.BilliardResult",
        "sinktheory.billiard.run.RigidLimit",
        "sinktheory.billiard.table.Piece",
        "sinktheory.billiard.table.Table",
        "sinktheory.compare.efficiency.Comparison",
        "sinktheory.compare.transfer.TransferMap",
        "sinktheory.compare.wavelet.WaveletMap",
        "sinktheory.damped.InelasticResult",
        "sinktheory.vibroimpact.VibroImpactResult",
    ),
    "a compiled kernel or engine part, called by checked wrappers": (
        "sinktheory.billiard.kernels.advance_fixed",
        "sinktheory.billiard.kernels.advance_moving",
        "sinktheory.billiard.kernels.energies",
        "sinktheory.billiard.kernels.impact",
        "sinktheory.billiard.kernels.impulse",
        "sinktheory.billiard.kernels.next_hit",
        "sinktheory.billiard.kernels.outward_normal",
        "sinktheory.billiard.kernels.reflect_tangent",
        "sinktheory.billiard.kernels.run_fixed",
        "sinktheory.billiard.kernels.run_moving",
        "sinktheory.billiard.kernels.wall_hessian",
        "sinktheory.billiard.kernels.wall_value",
    ),
}
