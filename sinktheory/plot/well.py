"""Level lines of the well V(x, y), as in the paper's Figs. 2 and 10."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ..errors import ParameterError
from ..glossary import renamed
from ..model import UserWellSummary, Well
from ..validation import positive_int, real_array
from . import _shown, checked_axes, checked_result

__all__ = ["LEVEL_FRACTIONS", "plot_user_well", "plot_well"]

#: Most grid points per axis of a level-line plot (16 M points, 128 MB an array).
MAX_GRID = 4001
#: Level lines drawn, as fractions of the energy E (the outermost one, E itself, is bold).
LEVEL_FRACTIONS = (1e-3, 1e-2, 0.05, 0.15, 0.35, 0.65, 1.0)


@renamed(energy="particle_energy")
def plot_well(well: Well, particle_energy: float = 0.5, ax=None, points: int = 301):
    """Draw level lines V = f E of ``well`` over the basin a particle of energy E reaches.

    Parameters
    ----------
    well : Well
    particle_energy : float > 0
        E, the energy of one particle.
        The outermost level line; the plot covers the region it encloses.
    ax : matplotlib Axes, optional
        Draw into it; a new Figure is made otherwise.
    points : int
        Grid points per axis.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = plot_well(Well(alpha=0.5, beta=0.3, n=10), points=41)
    >>> fig.axes[0].get_xlabel()
    '$x$'
    """
    if not isinstance(well, Well):
        raise ParameterError("well", well, "a sinktheory.Well (a user's well: plot_user_well)")
    points = positive_int("points", points, minimum=2, maximum=MAX_GRID)
    checked_axes(ax)
    energy = particle_energy
    x_max, y_max = well.reach(energy)
    title = (
        f"{well.shape} well: $\\alpha$={well.alpha:g}, $\\beta$={well.beta:g}, "
        f"$n$={well.n}, $\\gamma$={well.gamma:g}"
    )
    return _levels(well.potential, max(x_max, y_max), energy, title, ax, points)


def plot_user_well(summary, potential, ax=None, points: int = 301):
    """Draw level lines V - V(0, 0) = f E of a user's well over the basin of energy E,
    from its :class:`~sinktheory.model.UserWellSummary` (the reach at E =
    ``summary.particle_energy``) and ``potential(x, y)`` on arrays, measured from V(0, 0).

    Examples
    --------
    >>> from sinktheory.model import user_well_summary
    >>> from sinktheory.userwell import UserWell, check_well
    >>> hh = UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})
    >>> basin = check_well(hh).basin
    >>> fig = plot_user_well(user_well_summary(hh, 0.1), basin.well.f, points=41)
    >>> fig.axes[0].get_title().splitlines()[0]
    'hh well (no parameters)'
    """
    checked_result(
        "summary",
        summary,
        UserWellSummary,
        "a UserWellSummary (sinktheory.model.user_well_summary)",
    )
    if not callable(potential):
        raise ParameterError("potential", _shown(potential), "a function V(x, y) on arrays")
    points = positive_int("points", points, minimum=2, maximum=MAX_GRID)
    checked_axes(ax)
    values = ", ".join(f"{k}={v:g}" for k, v in summary.parameters.items()) or "no parameters"
    title = f"{summary.name} well ({values})"
    half = max(summary.reach.x, summary.reach.y)
    return _levels(potential, half, summary.particle_energy, title, ax, points)


def _levels(potential, half, energy, title, ax, points):
    """Level lines f E of ``potential`` on the square |x|, |y| <= 1.15 ``half``."""
    half = 1.15 * half
    xs = np.linspace(-half, half, points)
    X, Y = np.meshgrid(xs, xs)
    V = real_array("potential", potential(X, Y), "a function V(x, y) giving real arrays")
    if V.shape != X.shape:
        raise ParameterError(
            "potential",
            f"a function giving shape {V.shape} for {X.shape}",
            "a function V(x, y) on arrays, of their shape",
        )
    if ax is None:
        fig = Figure(figsize=(5.5, 5.0), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    inner = [energy * f for f in LEVEL_FRACTIONS if f < 1]
    cs = ax.contour(X, Y, V, levels=inner, cmap="viridis", linewidths=1.0)
    ax.clabel(cs, fmt=lambda v: f"{v:.3g}", fontsize=7)
    ax.contour(X, Y, V, levels=[energy], colors="black", linewidths=2.0)
    ax.set_aspect("equal")
    ax.set_xlabel("$x$")
    ax.set_ylabel("$y$")
    ax.set_title(f"{title}\nlevel lines of $V$ up to $E$={energy:g} (bold)", fontsize=9)
    return fig
