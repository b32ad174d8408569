"""Recurrence plots of an energy series (paper Figs. 9 and 12); the image comes from
:func:`sinktheory.recurrence.recurrence_image`.

Examples
--------
>>> import numpy as np
>>> fig = plot_recurrence(np.sin(np.arange(50) * 0.3), eps=0.1)
>>> fig.axes[0].get_xlabel()
'$i$ (periods $T$)'
"""

from __future__ import annotations

from ..glossary import renamed
from ..recurrence import epsilon_for_rate, recurrence_image
from . import checked_axes

__all__ = ["plot_recurrence"]


@renamed(energy="series")
def plot_recurrence(series, eps: float | None = None, ax=None, title: str | None = None):
    """Draw the recurrence plot of ``series`` (ones dark, zeros white); return the Figure."""
    eps = epsilon_for_rate(series) if eps is None else eps
    img = recurrence_image(series, eps)  # checks the series and eps
    checked_axes(ax)
    last = len(series) - 1
    if ax is None:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(4.5, 4.5), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    ax.imshow(
        img,
        origin="lower",
        cmap="Greys",
        vmin=0,
        vmax=1,
        interpolation="nearest",
        extent=(0, last, 0, last),
    )
    ax.set_xlabel("$i$ (periods $T$)")
    ax.set_ylabel("$j$ (periods $T$)")
    ax.set_title(title or f"recurrence plot, $\\varepsilon$ = {eps:.3g}", fontsize=9)
    return fig
