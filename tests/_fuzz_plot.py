"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules plot.

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
        "sinktheory.plot.simulate.well_title",  # well=None: AttributeError
    ),
    "draws a result object": (
        "sinktheory.plot.bifurcation.plot_bifurcation",
        "sinktheory.plot.billiard.billiard_figure",
        "sinktheory.plot.chaos.convergence_figure",
        "sinktheory.plot.chaos.draw_map",
        "sinktheory.plot.chaos.plot_convergence",
        "sinktheory.plot.compare.draw_efficiency",
        "sinktheory.plot.compare.draw_t90",
        "sinktheory.plot.compare.plot_comparison",
        "sinktheory.plot.compare.plot_efficiency",
        "sinktheory.plot.compare.plot_t90",
        "sinktheory.plot.compare.plot_transfer",
        "sinktheory.plot.convergence.convergence_figure",
        "sinktheory.plot.convergence.lyapunov_figure",
        "sinktheory.plot.design.energy_curves",
        "sinktheory.plot.design.heatmap",
        "sinktheory.plot.design.heatmaps",
        "sinktheory.plot.design.panels",
        "sinktheory.plot.design.pareto_chart",
        "sinktheory.plot.design.swept",
        "sinktheory.plot.equilibrium.plot_ergodicity",
        "sinktheory.plot.equilibrium.plot_law",
        "sinktheory.plot.equilibrium.plot_lifetimes",
        "sinktheory.plot.equilibrium.plot_relaxation",
        "sinktheory.plot.floquet.plot_scan",
        "sinktheory.plot.floquet.plot_tongues",
        "sinktheory.plot.nnm.draw_frequency_energy",
        "sinktheory.plot.nnm.draw_transverse",
        "sinktheory.plot.nnm.plot_frequency_energy",
        "sinktheory.plot.nnm.plot_nnm",
        "sinktheory.plot.nnm.plot_transverse",
        "sinktheory.plot.paper.energy_band",
        "sinktheory.plot.paper.energy_curves",
        "sinktheory.plot.paper.energy_panels",
        "sinktheory.plot.paper.orbit_figure",
        "sinktheory.plot.paper.orbit_panel",
        "sinktheory.plot.paper.recurrence_columns",
        "sinktheory.plot.paper.running_and_recurrence",
        "sinktheory.plot.paper.trajectory_panels",
        "sinktheory.plot.paper.well_panels",
        "sinktheory.plot.simulate.plot_ensemble_energy",
        "sinktheory.plot.well.plot_user_well",
    ),
}
