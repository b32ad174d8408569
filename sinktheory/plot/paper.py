"""The drawing of the paper's figures for :mod:`sinktheory.scenes` (the scenes compute,
these functions draw what they computed).

Every function returns a :class:`matplotlib.figure.Figure` (no pyplot state).

Examples
--------
>>> import numpy as np
>>> from sinktheory.model import Well
>>> fig = trajectory_panels([("a)", Well(0.5, 0.3, 4), np.zeros((3, 2)))], "paths")
>>> fig.axes[0].get_xlabel()
'$x$'
"""

from __future__ import annotations

import numpy as np

from ..glossary import renamed
from ..sinkstats import running_mean
from .bifurcation import plot_bifurcation
from .chaos import draw_map
from .recurrence import plot_recurrence
from .well import plot_well

__all__: list[str] = []


def _figure(figsize):
    from matplotlib.figure import Figure

    return Figure(figsize=figsize, layout="constrained")


@renamed(energy="particle_energy")
def well_panels(wells, ncols: int, particle_energy: float, title: str):
    """Level lines of each (label, Well) of ``wells`` up to ``particle_energy`` (Figs. 2
    and 10)."""
    nrows = int(np.ceil(len(wells) / ncols))
    fig = _figure((4.2 * ncols, 4.0 * nrows))
    axes = fig.subplots(nrows, ncols, squeeze=False).ravel()
    for ax, (label, well) in zip(axes, wells, strict=False):
        plot_well(well, particle_energy=particle_energy, ax=ax, points=201)
        ax.set_title(f"{label}  $n$={well.n}, $\\beta$={well.beta:g}", fontsize=10)
    fig.suptitle(title)
    return fig


def trajectory_panels(panels, title: str, level: float = 0.5):
    """Particle paths (label, Well, xy (S, 2)) over the level line V = ``level`` (Fig. 4)."""
    fig = _figure((8, 11))
    axes = fig.subplots(3, 2).ravel()
    g = np.linspace(-1.2, 1.2, 241)
    X, Y = np.meshgrid(g, g)
    for ax, (label, well, xy) in zip(axes, panels, strict=False):
        ax.contour(X, Y, well.potential(X, Y), levels=[level], colors="0.6", linewidths=1)
        ax.plot(xy[:, 0], xy[:, 1], lw=0.3, color="tab:blue")
        ax.set_aspect("equal")
        ax.set_title(label, fontsize=10)
        ax.set_xlabel("$x$")
        ax.set_ylabel("$y$")
    fig.suptitle(title)
    return fig


def energy_band(ax, mean: np.ndarray, stderr: np.ndarray, label=None, color=None) -> None:
    """<E>(t/T) with its +- standard-error band on ``ax``."""
    t = np.arange(mean.size)
    line = ax.plot(t, mean, lw=0.8, label=label, color=color)[0]
    ax.fill_between(t, mean - stderr, mean + stderr, color=line.get_color(), alpha=0.25, lw=0)


def _energy_axes(ax) -> None:
    ax.set_xlabel("$t/T$")
    ax.set_ylabel("$\\langle E \\rangle$")


def energy_panels(panels, title: str, top: float):
    """One <E>(t/T) band per panel (label, mean, stderr), 3 x 2 (Fig. 5)."""
    fig = _figure((8, 8))
    for ax, (label, mean, se) in zip(fig.subplots(3, 2).ravel(), panels, strict=False):
        energy_band(ax, mean, se)
        ax.set_title(label, fontsize=10)
        _energy_axes(ax)
        ax.set_ylim(0, top)
    fig.suptitle(title)
    return fig


def energy_curves(curves, title: str):
    """Several <E>(t/T) bands (label, mean, stderr) on one axes (Fig. 8)."""
    fig = _figure((8, 4.5))
    ax = fig.subplots()
    for label, mean, se in curves:
        energy_band(ax, mean, se, label)
    _energy_axes(ax)
    ax.legend()
    fig.suptitle(title)
    return fig


def _running(ax, mean: np.ndarray, window: int) -> None:
    r = running_mean(mean, window)
    ax.plot(np.arange(r.size) + window - 1, r, lw=0.9)
    ax.set_xlabel("$t/T$")
    ax.set_ylabel(f"{window}T running mean of $\\langle E\\rangle$")


def recurrence_columns(columns, eps: float, window: int, title: str):
    """Per column (label, <E>): its recurrence plot over its ``window`` T running mean
    (Fig. 9)."""
    fig = _figure((11, 7))
    axes = fig.subplots(2, len(columns))
    for col, (label, mean) in enumerate(columns):
        plot_recurrence(mean, eps, ax=axes[0, col], title=label)
        _running(axes[1, col], mean, min(window, mean.size))
    fig.suptitle(title)
    return fig


def running_and_recurrence(mean: np.ndarray, start: float, eps: float, window: int, title):
    """The ``window`` T running mean of <E> from ``start`` beside its recurrence plot
    (Fig. 12)."""
    fig = _figure((11, 4.5))
    ax, ax_r = fig.subplots(1, 2, width_ratios=(1.6, 1))
    _running(ax, mean, window)
    ax.plot([0], [start], "ko")
    plot_recurrence(mean, eps, ax=ax_r)
    fig.suptitle(title)
    return fig


def orbit_figure(rows: int, figsize, title: str):
    """A figure of ``rows`` x 2 axes (bifurcation diagram, chaos map) for Figs. 3 and 11;
    returns (figure, axes (rows, 2))."""
    fig = _figure(figsize)
    fig.suptitle(title)
    return fig, np.atleast_2d(fig.subplots(rows, 2))


def orbit_panel(ax, ax_map, diagram, unstable, gaps, resonances, chaos_map, stable, title):
    """Bifurcation diagram with the Floquet-unstable intervals shaded, ``gaps`` (beta
    intervals where the well does not hold E = 0.5) hatched and phi_T = -1 at
    ``resonances`` dotted; beside it the chaos map with the ``stable`` intervals."""
    plot_bifurcation(diagram, unstable, ax=ax)
    for a, b in gaps:
        ax.axvspan(a, b, color="0.85", hatch="//", lw=0)
        ax.text(
            (a + b) / 2,
            0.5,
            "well does not\nhold E = 0.5",
            transform=ax.get_xaxis_transform(),
            ha="center",
            va="center",
            fontsize=8,
        )
    for r in resonances:
        ax.axvline(r, color="tab:blue", lw=0.8, ls=":")
    draw_map(chaos_map, stable, ax_map, title=title)
