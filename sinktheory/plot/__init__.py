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


def _shown(value):
    """``value`` for a one-line message: itself if short and simple, else its type's name."""
    simple = isinstance(value, str | int | float | complex | type(None)) and len(repr(value)) < 60
    return value if simple else type(value).__name__


def checked_result(name: str, value, cls, allowed: str):
    """``value`` if it is a ``cls`` (the result object a figure draws), else ParameterError
    naming ``name``, ``allowed`` saying what it must be and where it comes from."""
    from ..errors import ParameterError

    if not isinstance(value, cls):
        raise ParameterError(name, _shown(value), allowed)
    return value


def checked_results(name: str, value, cls, allowed: str, *, maximum: int = 20) -> list:
    """``value`` as a list of 1 to ``maximum`` ``cls`` objects, else ParameterError naming
    ``name``."""
    from ..errors import ParameterError

    text = f"a sequence of 1 to {maximum} {allowed}"
    if isinstance(value, str | bytes | dict) or not hasattr(value, "__iter__"):
        raise ParameterError(name, _shown(value), text)
    items = list(value)
    if not 1 <= len(items) <= maximum or not all(isinstance(x, cls) for x in items):
        raise ParameterError(name, _shown(value), text)
    return items


def checked_title(title, name: str = "title"):
    """``title`` if it is a text or None, else ParameterError naming ``name``."""
    from ..errors import ParameterError

    if title is not None and not isinstance(title, str):
        raise ParameterError(name, _shown(title), "a text or None")
    return title
