"""Design explorer for energy absorbers: which shape, stiffness and particle count drain
the most energy, fastest, most reliably.

A design is a point (shape, alpha, beta, n, k, m, E0); the explorer runs an ensemble at
every point of a grid on the sweep layer (:mod:`sinktheory.sweep`, kind ``design``:
local processes or Dask, resumable, Zarr) and measures it (:mod:`.measures`); the
designs are then ranked (:mod:`.ranking`), charted (:mod:`sinktheory.plot.design`,
matplotlib imported there only) and reported (:mod:`.report`).

* :func:`~sinktheory.design.explorer.explore` -- run (or resume) a design sweep;
* :func:`~sinktheory.design.measures.design_measures` -- the measures of one ensemble;
* :func:`~sinktheory.design.ranking.rank` -- Pareto layers and the ranked table;
* :func:`~sinktheory.design.report.write_report` -- charts, table and ``report.md``;
* :func:`~sinktheory.design.cost.estimate` -- the time a grid will take (calibrated);
* :func:`~sinktheory.damped.simulate_inelastic` -- inelastic wall contact
  (the engine with its damping on, audited dissipation, equivalent damping ratio).

Modules are loaded on first use, so importing the command line stays light.
"""

from importlib import import_module

_LAZY = {
    "DesignMeasures": "measures",
    "design_measures": "measures",
    "explore": "explorer",
    "DesignRun": "explorer",
    "rank": "ranking",
    "pareto_front": "ranking",
    "write_report": "report",
    "estimate": "cost",
    "Estimate": "cost",
    "simulate_inelastic": "..damped",
}


def __getattr__(name: str):
    if name in _LAZY:
        module = _LAZY[name]
        return getattr(import_module(module if module[0] == "." else f".{module}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = sorted(_LAZY)
