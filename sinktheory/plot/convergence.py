"""Figures of soft walls against the rigid billiard (matplotlib is imported when drawing).

Examples
--------
>>> from sinktheory.billiard.convergence import lyapunov_chart
>>> from sinktheory.model import RunSettings
>>> c = lyapunov_chart(0.5, [-0.3, 0.3], ns=(4,), settings=RunSettings(runs=2, periods=3))
>>> len(lyapunov_figure(c).axes)
1
"""

from __future__ import annotations

import numpy as np

from ..billiard.convergence import Convergence, LyapunovChart
from . import checked_result, checked_title

__all__ = ["convergence_figure", "lyapunov_figure"]


def lyapunov_figure(chart: LyapunovChart, *, title: str = ""):
    """lambda_1(beta) for each soft n and for n = oo on one plot, error bars of one
    standard error; the rigid row in black; a point some of whose runs are regular
    (:func:`sinktheory.chaos.verdicts.split`) says how many beneath it.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    checked_result(
        "chart",
        chart,
        LyapunovChart,
        "a LyapunovChart (sinktheory.billiard.convergence.lyapunov_chart)",
    )
    checked_title(title)
    fig = Figure(figsize=(8, 4.6), layout="constrained")
    ax = fig.subplots()
    shift = 0.12 * np.min(np.diff(chart.betas)) if chart.betas.size > 1 else 0.0
    rows = [(f"n = {n}", chart.lambda1[i], chart.lambda1_se[i], chart.regular[i])
            for i, n in enumerate(chart.ns)]  # fmt: skip
    rows.append((r"n = $\infty$ (rigid billiard)", chart.rigid_lambda1, chart.rigid_lambda1_se,
                 chart.rigid_regular))  # fmt: skip
    middle = (len(rows) - 1) / 2
    for i, (label, mean, se, regular) in enumerate(rows):
        rigid = i == len(rows) - 1
        x = chart.betas + (i - middle) * shift
        ax.errorbar(
            x, mean, yerr=se, label=label, marker="o",
            ms=3.5, lw=1.6 if rigid else 1.0, capsize=2, color="k" if rigid else None,
        )  # fmt: skip
        for j in np.nonzero(regular)[0]:  # a mixed point: how many of its runs are regular
            ax.annotate(f"{regular[j]} reg.", (x[j], mean[j]), fontsize=6, ha="center",
                        va="top", xytext=(0, -6), textcoords="offset points")  # fmt: skip
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.axvline(0.0, color="0.6", lw=0.6, ls=":")
    ax.set_xlabel(r"$\beta$ (walls bulge inward for $\beta$ > 0)")
    ax.set_ylabel(r"$\lambda_1$ per unit time")
    ax.legend(fontsize=8)
    p = chart.parameters
    ax.set_title(
        title
        or rf"{p['shape']}, $\alpha$ = {p['alpha']:g}, k = {p['particles']}, m = {p['mass']:g}, "
        rf"$E_0$ = {p['container_energy']:g}; {p['runs']} runs x {p['periods']} T per point",
        fontsize=9,
    )
    return fig


def convergence_figure(result: Convergence, *, title: str = ""):
    """Three panels against n (log axis): lambda_1, the mean free time and the time-averaged
    container energy, soft points with error bars and the rigid value as a band of one
    standard error.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    checked_result(
        "result", result, Convergence, "a Convergence (sinktheory.billiard.convergence.convergence)"
    )
    checked_title(title)
    fig = Figure(figsize=(12, 3.8), layout="constrained")
    labels = {
        "lambda1": r"$\lambda_1$ per unit time",
        "mean_free_time": "mean free time",
        "energy_average": r"time average of $E$ (container)",
    }
    for ax, (q, label) in zip(fig.subplots(1, 3), labels.items(), strict=True):
        m, se, rm, rse = result.summary(q)
        ax.errorbar(result.ns, m, yerr=se, marker="o", capsize=2, label="soft walls")
        ax.axhspan(rm - rse, rm + rse, color="0.8", label=r"rigid ($n = \infty$)")
        ax.axhline(rm, color="k", lw=1)
        ax.set_xscale("log")
        ax.set_xlabel("n")
        ax.set_ylabel(label)
    fig.axes[0].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return fig
