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


def checked_axes(ax):
    """``ax`` if it is None or a matplotlib Axes, else ParameterError naming ``ax``."""
    from matplotlib.axes import Axes

    from ..errors import ParameterError

    if ax is not None and not isinstance(ax, Axes):
        raise ParameterError("ax", ax, "a matplotlib Axes or None")
    return ax
