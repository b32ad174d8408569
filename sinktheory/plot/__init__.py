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


def checked_results(name: str, value, kind, allowed: str, *, maximum: int = 20) -> list:
    """``value`` as a list of 1 to ``maximum`` results of ``kind`` (a class, or the fields
    of a result class the plots may not import: :func:`checked_fields`), else
    ParameterError naming ``name``."""
    from ..errors import ParameterError

    text = f"a sequence of 1 to {maximum} {allowed}"
    if isinstance(value, str | bytes | dict) or not hasattr(value, "__iter__"):
        raise ParameterError(name, _shown(value), text)
    items = list(value)
    if not 1 <= len(items) <= maximum:
        raise ParameterError(name, f"{len(items)} items", text)
    for item in items:
        if isinstance(kind, tuple):
            checked_fields(name, item, kind, text)
        else:
            checked_result(name, item, kind, text)
    return items


def checked_title(title, name: str = "title"):
    """``title`` if it is a text or None, else ParameterError naming ``name``."""
    from ..errors import ParameterError

    if title is not None and not isinstance(title, str):
        raise ParameterError(name, _shown(title), "a text or None")
    return title


def checked_path(name: str, value):
    """``value`` if a figure can be saved there (a non-empty path in a writable directory,
    with a file type matplotlib writes, or none: PNG), else ParameterError naming ``name``."""
    import os
    from pathlib import Path

    from matplotlib.figure import Figure

    from ..errors import ParameterError
    from ..validation import writable_directory

    if not isinstance(value, str | os.PathLike) or not str(value):
        raise ParameterError(name, _shown(value), "a path to write the figure to")
    kinds = Figure().canvas.get_supported_filetypes()
    suffix = Path(value).suffix.lower().lstrip(".")
    if suffix and suffix not in kinds:
        raise ParameterError(name, _shown(value), f"a file of type {', '.join(sorted(kinds))}")
    writable_directory(name, value, Path(value).parent)
    return value


def checked_fields(name: str, value, fields: tuple[str, ...], allowed: str):
    """``value`` if it is a :class:`~sinktheory.results.Result` with ``fields``, else
    ParameterError naming ``name``: the check of a result whose class lives in a layer
    above the plots (which may not import it)."""
    from ..errors import ParameterError
    from ..results import Result

    if not isinstance(value, Result) or not all(hasattr(value, f) for f in fields):
        raise ParameterError(name, _shown(value), allowed)
    return value
