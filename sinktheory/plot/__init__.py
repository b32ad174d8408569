"""Every figure of the toolkit: the one package that imports matplotlib.

Analyses compute and return result objects; the modules here draw them.  Each function
returns a :class:`matplotlib.figure.Figure` (no pyplot state), saved by the caller.
matplotlib is imported inside the drawing modules, so importing an analysis (or a sweep
worker) never loads it.

* :mod:`.nnm` -- frequency-energy plots and transverse-stability charts of normal modes;
* :mod:`.design` -- heat maps and the Pareto chart of a design sweep;
* :mod:`.chaos` -- convergence plots of the chaos indicators.
"""

#: Nothing here but the submodules (import them by name).
__all__: list[str] = []
