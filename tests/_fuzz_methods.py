"""The API fuzz's tables for the public methods of the public classes (issue 34, item 5;
see tests/_fuzz.py and tests/interface/test_api_fuzz_methods.py).

A method with user input (``law.pdf(s)``, ``chart.factor(beta)``) is an entry point as
much as a function is: it is fuzzed on an instance, one argument at a time replaced by a
hostile value.

* :func:`instances`: a small valid instance of each class, by the class's key (a value
  costly to build wrapped in ``_fuzz.Lazy``);
* :func:`arguments`: valid keyword arguments by method key (``module.Class.method``),
  where the parameters' names do not give them (``_fuzz._valid``);
* :func:`fixed_leaks`: each leak found and fixed, as a call and the parameter its
  ParameterError must name; :data:`HEAVY`: methods whose call takes seconds;
* :data:`PENDING_BY_REASON`: the methods not fuzzed yet, by why.
"""


def instances() -> dict:
    """A small valid instance of each public class whose methods are fuzzed, by key."""
    return {}


def arguments() -> dict:
    """Valid keyword arguments of the methods, by method key."""
    return {}


def fixed_leaks() -> list:
    """(call, parameter its ParameterError must name) of each leak fixed in a method."""
    return []


#: Methods whose calls take seconds: fewer examples.
HEAVY: set[str] = set()

#: Methods not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {
    "instance and valid arguments not written yet": (
        "sinktheory.attachments.ImpulseResponse.time_leaving_line",
        "sinktheory.attachments.ImpulseResponse.time_to_fraction",
        "sinktheory.basin.Basin.area",
        "sinktheory.basin.Basin.check_energy",
        "sinktheory.basin.Basin.of",
        "sinktheory.basin.Basin.reach",
        "sinktheory.basin.Escape.describe",
        "sinktheory.basin.NumericWell.gradient",
        "sinktheory.basin.NumericWell.hessian",
        "sinktheory.basin.NumericWell.valid",
        "sinktheory.billiard.convergence.Convergence.rate",
        "sinktheory.billiard.convergence.Convergence.summary",
        "sinktheory.billiard.convergence.LyapunovChart.pooled_rate",
        "sinktheory.billiard.table.Piece.curvature",
        "sinktheory.billiard.table.Piece.points",
        "sinktheory.billiard.table.Piece.values",
        "sinktheory.billiard.table.Table.check_positions",
        "sinktheory.billiard.table.Table.contains",
        "sinktheory.billiard.table.Table.wall_values",
        "sinktheory.chaos.result.ChaosResult.as_dict",
        "sinktheory.chaos.result.ChaosResult.mean",
        "sinktheory.chaos.result.ChaosResult.runs_of",
        "sinktheory.chaos.result.ChaosResult.window_exponents",
        "sinktheory.compare.efficiency.Comparison.span",
        "sinktheory.design.explorer.DesignRun.of",
        "sinktheory.engine.core.Ensemble.plan",
        "sinktheory.engine.core.Ensemble.run",
        "sinktheory.engine.core.Ensemble.take",
        "sinktheory.engine.systems.Term.plain",
        "sinktheory.equilibrium.area.WellArea.area",
        "sinktheory.equilibrium.area.WellArea.check_energy",
        "sinktheory.equilibrium.area.WellArea.of",
        "sinktheory.equilibrium.area.WellArea.ratio",
        "sinktheory.equilibrium.area.WellArea.rays",
        "sinktheory.equilibrium.kramers.KramersMoyal.lag_index",
        "sinktheory.equilibrium.law.EquilibriumLaw.cdf",
        "sinktheory.equilibrium.law.EquilibriumLaw.log10_kac_periods",
        "sinktheory.equilibrium.law.EquilibriumLaw.log_tail",
        "sinktheory.equilibrium.law.EquilibriumLaw.quantile",
        "sinktheory.equilibrium.prediction.LawChain.moments",
        "sinktheory.floquet.FloquetChart.as_dict",
        "sinktheory.floquet.FloquetChart.factor",
        "sinktheory.floquet.HillProblem.check",
        "sinktheory.floquet.HillProblem.evaluate",
        "sinktheory.floquet.HillProblem.lam",
        "sinktheory.floquet.HillProblem.quarter",
        "sinktheory.floquet.WellHill.at",
        "sinktheory.floquet.WellHill.factor",
        "sinktheory.layout.StateLayout.join",
        "sinktheory.layout.StateLayout.of",
        "sinktheory.layout.StateLayout.relative_positions",
        "sinktheory.layout.StateLayout.split",
        "sinktheory.layout.StateLayout.start",
        "sinktheory.model.RunSettings.check",
        "sinktheory.model.RunSettings.check_box",
        "sinktheory.model.RunSettings.check_memory",
        "sinktheory.model.RunSettings.memory_bytes",
        "sinktheory.model.RunSettings.total_energy_bound",
        "sinktheory.model.Sink.check_particles",
        "sinktheory.model.Sink.summary",
        "sinktheory.model.Well.check_energy",
        "sinktheory.model.Well.check_position",
        "sinktheory.model.Well.curvature",
        "sinktheory.model.Well.denominator",
        "sinktheory.model.Well.potential",
        "sinktheory.model.Well.reach",
        "sinktheory.model.Well.summary",
        "sinktheory.model.Well.wall_ratio",
        "sinktheory.nnm.continuation.Branch.result",
        "sinktheory.nnm.result.BranchResult.from_branch",
        "sinktheory.nnm.shooting.Orbit.trajectory",
        "sinktheory.nnm.shooting.ShootingProblem.evaluate",
        "sinktheory.nnm.shooting.ShootingProblem.lam",
        "sinktheory.nnm.shooting.ShootingProblem.newton",
        "sinktheory.nnm.shooting.ShootingProblem.orbit",
        "sinktheory.nnm.shooting.ShootingProblem.pack",
        "sinktheory.nnm.shooting.ShootingProblem.phase_vector",
        "sinktheory.nnm.shooting.ShootingProblem.scales",
        "sinktheory.nnm.shooting.ShootingProblem.system_at",
        "sinktheory.nnm.shooting.ShootingProblem.unpack",
        "sinktheory.nnm.system.FlowSystem.accelerations",
        "sinktheory.nnm.system.FlowSystem.gradient",
        "sinktheory.nnm.system.FlowSystem.hamiltonian",
        "sinktheory.nnm.system.FlowSystem.index",
        "sinktheory.nnm.system.FlowSystem.param_derivative",
        "sinktheory.nnm.system.FlowSystem.propagate",
        "sinktheory.nnm.system.FlowSystem.stiffness",
        "sinktheory.nnm.system.FlowSystem.vector_field",
        "sinktheory.nnm.system.FlowSystem.with_param",
        "sinktheory.progress.ProgressBar.update",
        "sinktheory.series.TriangleSeries.amplitude_ratio",
        "sinktheory.series.TriangleSeries.frequency_factor",
        "sinktheory.series.TriangleSeries.period_estimate",
        "sinktheory.series.TriangleSeries.remainder",
        "sinktheory.series.TriangleSeries.shape",
        "sinktheory.series.TriangleSeries.shape_expr",
        "sinktheory.sweep.grid.Grid.from_params",
        "sinktheory.sweep.grid.Grid.point",
        "sinktheory.sweep.kinds.Kind.complete",
        "sinktheory.sweep.kinds.Param.coerce",
        "sinktheory.sweep.plan.Sweep.dataset",
        "sinktheory.sweep.plan.Sweep.make",
        "sinktheory.sweep.plan.Sweep.shape",
        "sinktheory.sweep.plan.Sweep.task",
        "sinktheory.sweep.store.MemoryStore.write",
        "sinktheory.sweep.store.SweepStore.create",
        "sinktheory.sweep.store.SweepStore.open",
        "sinktheory.sweep.store.SweepStore.write",
        "sinktheory.userwell.Parameter.check",
        "sinktheory.userwell.UserWell.potential_at",
        "sinktheory.userwell.UserWell.values",
        "sinktheory.userwell.UserWell.with_defaults",
        "sinktheory.wellat.WellAt.box_potential",
        "sinktheory.wellat.WellAt.check_box",
        "sinktheory.wellat.WellAt.check_energy",
        "sinktheory.wellat.WellAt.check_position",
        "sinktheory.wellat.WellAt.hessian_at",
        "sinktheory.wellat.WellAt.potential",
        "sinktheory.wellat.WellAt.reach",
        "sinktheory.wellat.WellAt.wall_distance",
    ),
}
