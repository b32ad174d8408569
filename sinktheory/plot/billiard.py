"""Figures of the rigid billiard (matplotlib is imported when drawing).

Examples
--------
>>> from sinktheory.billiard import billiard
>>> from sinktheory.model import RunSettings
>>> r = billiard("flat", 0.5, 0.3, settings=RunSettings(runs=2, periods=4), lyapunov=True)
>>> len(billiard_figure(r).axes)
3
"""

from __future__ import annotations

import numpy as np

from ..billiard.run import BilliardResult
from ..runstats import ensemble_mean
from . import checked_result, checked_title

__all__ = ["billiard_figure"]


def billiard_figure(result: BilliardResult, *, title: str = ""):
    """Three panels: the table (walls coloured by curvature sign: blue dispersing, red
    focusing, black flat), the container energy <E>(t/T) with its standard-error band
    (moving container), and the finite-time lambda_1(t) of each run (when computed),
    coloured by its group (:meth:`~sinktheory.billiard.run.BilliardResult.split`: blue
    regular, red chaotic) with the mean of each group and the regular fraction in the
    title, never one mean over a mixed ensemble.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    checked_result("result", result, BilliardResult, "a BilliardResult (sinktheory.billiard)")
    checked_title(title)
    fig = Figure(figsize=(13, 4.2), layout="constrained")
    ax_t, ax_e, ax_l = fig.subplots(1, 3)
    for piece in result.table.pieces:
        pts = piece.points(300)
        k = np.nanmean(piece.curvature(np.linspace(piece.lo, piece.hi, 9)[1:-1]))
        color = "tab:blue" if k > 1e-12 else "tab:red" if k < -1e-12 else "k"
        ax_t.plot(pts[:, 0], pts[:, 1], color=color)
    ax_t.set_aspect("equal")
    ax_t.set_xlabel("x")
    ax_t.set_ylabel("y")
    t = result.table
    ax_t.set_title(
        f"{t.name}: A = {t.area:.4g}, P = {t.perimeter:.4g}, pi A/P = {t.mean_free_path:.4g}"
    )
    periods = result.times / (2 * np.pi)
    if result.fixed:
        ax_e.text(0.5, 0.5, "fixed container", ha="center", va="center", transform=ax_e.transAxes)
    else:
        mean, se = ensemble_mean(result.container_energy)  # no band for one run
        ax_e.plot(periods, mean, color="k")
        ax_e.fill_between(periods, mean - se, mean + se, color="0.7")
    ax_e.set_xlabel("t / T")
    ax_e.set_ylabel(r"$\langle E \rangle$ of the container")
    if result.logs is not None:
        with np.errstate(divide="ignore", invalid="ignore"):
            finite = result.logs[:, 1:] / result.times[1:]
        split = result.split()
        regular = result.lambda1 <= split.threshold
        for group, light, dark, name in ((regular, "#9ecae1", "tab:blue", "regular"),
                                         (~regular, "#fcae91", "tab:red", "chaotic")):  # fmt: skip
            for row in finite[group]:
                ax_l.plot(periods[1:], row, color=light, lw=0.6)
            if group.any():
                ax_l.plot(periods[1:], finite[group].mean(axis=0), color=dark,
                          label=f"{name} runs: {int(group.sum())}")  # fmt: skip
        ax_l.set_yscale("log")
        ax_l.legend(fontsize=8)
        ax_l.set_title(
            f"{split.regular} of {split.runs} runs regular "
            rf"($\lambda_1 \leq$ 3 ln t / t = {split.threshold:.2g})",
            fontsize=9,
        )
        ax_l.set_ylabel(rf"$\lambda_1(t)$ ({result.lyapunov_method})")
    else:
        ax_l.text(0.5, 0.5, "no --lyapunov", ha="center", va="center", transform=ax_l.transAxes)
    ax_l.set_xlabel("t / T")
    if title:
        fig.suptitle(title)
    return fig
