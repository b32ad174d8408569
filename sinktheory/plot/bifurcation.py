"""Bifurcation (orbit) diagrams: the section points of
:class:`~sinktheory.bifurcation.BifurcationDiagram` against beta (paper Figs. 3 and 11).

Examples
--------
>>> import numpy as np
>>> from sinktheory.bifurcation import BifurcationDiagram
>>> d = BifurcationDiagram(np.array([0.1, 0.2]), np.zeros((2, 3)), "y", 0.5, 4, 1.0,
...                        "flat", 0.2, 0.5, 10, 3)
>>> plot_bifurcation(d, unstable=[(0.15, 0.2)]).axes[0].get_ylabel()
'$y(jT)$'
"""

from __future__ import annotations

import numpy as np

from ..bifurcation import BifurcationDiagram
from ..errors import ParameterError
from ..validation import finite_array
from . import checked_axes, checked_result, checked_title

__all__ = ["plot_bifurcation"]


def plot_bifurcation(diagram: BifurcationDiagram, unstable=(), ax=None, title=None):
    """Draw the section points against beta; shade the Floquet-unstable ``unstable``
    intervals [(lo, hi), ...] of the normal mode y = 0.  Returns the Figure."""
    checked_result(
        "diagram", diagram, BifurcationDiagram, "a BifurcationDiagram (sinktheory.bifurcation)"
    )
    pairs = "a sequence of (lo, hi) pairs of finite betas"
    unstable = finite_array("unstable", unstable, pairs)
    unstable = unstable.reshape(0, 2) if unstable.size == 0 else unstable
    if unstable.ndim != 2 or unstable.shape[1] != 2:
        raise ParameterError("unstable", f"an array of shape {unstable.shape}", pairs)
    checked_axes(ax)
    checked_title(title)
    if ax is None:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(7.0, 4.0), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    for i, (lo, hi) in enumerate(unstable):
        ax.axvspan(
            lo,
            hi,
            color="tab:red",
            alpha=0.15,
            lw=0,
            label="normal mode unstable (Floquet)" if i == 0 else None,
        )
    b = np.repeat(diagram.beta, diagram.section.shape[1])
    ax.plot(b, diagram.section.ravel(), ".", ms=1.0, color="black", alpha=0.6)
    ax.set_xlabel("$\\beta$")
    ax.set_ylabel("$y(jT)$" if diagram.quantity == "y" else "$E(jT)$")
    ax.set_title(
        title or (f"{diagram.shape} well, $\\alpha$={diagram.alpha:g}, $n$={diagram.n}, $k$=1"),
        fontsize=9,
    )
    if len(unstable):
        ax.legend(loc="upper left", fontsize=8)
    return fig
