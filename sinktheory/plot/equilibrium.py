"""Figures of the equilibrium law: the density of E_c / E, and Kac lifetimes against k and f."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure


def plot_law(summary, ax=None):
    """Density of s = E_c / E (an :class:`~sinktheory.equilibrium.EquilibriumSummary`),
    with the mean, the homogeneous-well estimate and the tail fractions marked.

    Examples
    --------
    >>> from sinktheory.model import Sink, Well
    >>> from sinktheory.equilibrium import equilibrium_law
    >>> fig = plot_law(equilibrium_law(Sink(Well(0.5, 0.3, 4)), 0.5).summary(points=21))
    >>> fig.axes[0].get_xlabel()
    '$s = E_c / E$'
    """
    law = summary.law
    if ax is None:
        fig = Figure(figsize=(6.0, 4.2), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    ax.plot(summary.s, summary.pdf, color="C0", lw=1.8, label="exact law")
    ax.axvline(law.mean_fraction, color="C0", ls="--", lw=1.0, label=r"$\langle E_c\rangle/E$")
    homogeneous = law.homogeneous_mean / law.energy
    ax.axvline(homogeneous, color="C3", ls=":", lw=1.0, label=r"$1/(1 + k(1 + 1/n))$")
    for f, p in zip(summary.fractions, summary.tails, strict=True):
        ax.axvline(f, color="0.6", lw=0.6)
        ax.annotate(
            f"P={p:.2g}",
            (f, 0.95),
            xycoords=("data", "axes fraction"),
            fontsize=7,
            rotation=90,
            va="top",
            ha="right",
            color="0.35",
        )
    ax.set_yscale("log")
    positive = summary.pdf[summary.pdf > 0]
    if positive.size:
        ax.set_ylim(max(positive.min(), positive.max() * 1e-8), positive.max() * 2)
    ax.set_xlim(0, 1)
    ax.set_xlabel("$s = E_c / E$")
    ax.set_ylabel("density of $s$")
    ax.set_title(
        f"{law.shape} well $\\alpha$={law.alpha:g}, $\\beta$={law.beta:g}, $n$={law.n}, "
        f"$k$={law.particles}, $E$={law.energy:g}",
        fontsize=9,
    )
    ax.legend(fontsize=8)
    return fig


def plot_lifetimes(fractions, particles, predicted, measured=None, ax=None):
    """Kac's mean return time (periods) to {E_c >= f E} against f, one line per k, with
    measured points and their errors.

    Parameters
    ----------
    fractions : array (F,)
    particles : array (K,) of k
    predicted : array (K, F)
        1 / P(E_c >= f E) from the law.
    measured : sequence of (k, f, mean, stderr), optional

    Examples
    --------
    >>> fig = plot_lifetimes([0.2, 0.5], [1, 2], [[2.0, 5.0], [4.0, 30.0]], [(1, 0.5, 5.2, 0.3)])
    >>> fig.axes[0].get_yscale()
    'log'
    """
    if ax is None:
        fig = Figure(figsize=(6.0, 4.2), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    fractions = np.asarray(fractions, dtype=float)
    predicted = np.asarray(predicted, dtype=float)
    colours = {}
    for i, k in enumerate(particles):
        (line,) = ax.plot(fractions, predicted[i], lw=1.5, label=f"$k$={k} (Kac, law)")
        colours[int(k)] = line.get_color()
    for k, f, mean, se in measured or ():
        ax.errorbar(f, mean, yerr=se, fmt="o", ms=4, capsize=3, color=colours.get(int(k), "k"))
    if measured:
        ax.plot([], [], "o", color="k", ms=4, label="measured (runs)")
    ax.axhline(1e4, color="0.5", ls=":", lw=1.0)
    ax.set_yscale("log")
    ax.set_xlabel("fraction $f$ of the total energy")
    ax.set_ylabel(r"mean return time to $\{E_c \geq fE\}$ (periods $T$)")
    ax.legend(fontsize=8)
    return fig
