"""Level lines of the well V(x, y), as in the paper's Figs. 2 and 10."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ..glossary import renamed
from ..model import Well

__all__ = ["LEVEL_FRACTIONS", "plot_well"]

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
    energy = particle_energy
    x_max, y_max = well.reach(energy)
    half = 1.15 * max(x_max, y_max)
    xs = np.linspace(-half, half, points)
    X, Y = np.meshgrid(xs, xs)
    V = well.potential(X, Y)
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
    ax.set_title(
        f"{well.shape} well: $\\alpha$={well.alpha:g}, $\\beta$={well.beta:g}, "
        f"$n$={well.n}, $\\gamma$={well.gamma:g}\nlevel lines of $V$ up to $E$={energy:g} (bold)",
        fontsize=9,
    )
    return fig
