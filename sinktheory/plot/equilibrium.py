"""Figures of the equilibrium law: the density of E_c / E, and Kac lifetimes against k and f."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from .. import validation as v
from ..equilibrium.ergodicity import ErgodicityMap
from ..equilibrium.law import EquilibriumSummary
from ..equilibrium.prediction import RelaxationPrediction
from ..equilibrium.relaxation import Relaxation
from ..errors import ParameterError
from . import _shown, checked_axes, checked_result

__all__ = ["plot_ergodicity", "plot_law", "plot_lifetimes", "plot_relaxation", "VERDICTS"]


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
    checked_result(
        "summary", summary, EquilibriumSummary, "an EquilibriumSummary (EquilibriumLaw.summary)"
    )
    checked_axes(ax)
    law = summary.law
    if ax is None:
        fig = Figure(figsize=(6.0, 4.2), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    ax.plot(summary.s, summary.pdf, color="C0", lw=1.8, label="exact law")
    ax.axvline(law.mean_fraction, color="C0", ls="--", lw=1.0, label=r"$\langle E_c\rangle/E$")
    homogeneous = law.homogeneous_mean / law.total_energy
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
    if np.isnan(law.alpha):  # a user's well: its own parameters
        well = ", ".join(f"{k}={v:g}" for k, v in law.parameters.items()) or "(no parameters)"
    else:
        well = f"$\\alpha$={law.alpha:g}, $\\beta$={law.beta:g}"
    ax.set_title(
        f"{law.shape} well {well}, $n$={law.n}, $k$={law.particles}, $E$={law.total_energy:g}",
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
    fractions = v.finite_array("fractions", fractions, "a non-empty 1-d array of fractions", ndim=1)
    particles = v.finite_array("particles", particles, "a non-empty 1-d array of k", ndim=1)
    if not fractions.size or not particles.size:
        raise ParameterError(
            "fractions" if not fractions.size else "particles", [], "a non-empty 1-d array"
        )
    particles = [v.positive_int("particles", k) for k in particles]
    shape = (len(particles), fractions.size)
    allowed = f"an array of shape {shape} (particles x fractions) of positive times"
    predicted = v.real_array("predicted", predicted, allowed)
    if predicted.shape != shape or not np.all(predicted > 0):  # inf: never returns
        raise ParameterError("predicted", f"an array of shape {predicted.shape}", allowed)
    measured = _measured(measured)
    checked_axes(ax)
    if ax is None:
        fig = Figure(figsize=(6.0, 4.2), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
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


def _measured(measured) -> list:
    """The measured points of :func:`plot_lifetimes`: (k, f, mean, stderr) rows, finite."""
    if measured is None:
        return []
    rows = v.finite_array("measured", measured, "a sequence of (k, f, mean, stderr) rows")
    if rows.size == 0:
        return []
    if rows.ndim != 2 or rows.shape[1] != 4:
        raise ParameterError(
            "measured", _shown(measured), "a sequence of (k, f, mean, stderr) rows"
        )
    return [tuple(row) for row in rows]


def plot_relaxation(prediction, measured=None, ax=None):
    """Predicted <E_c>(t) (a :class:`~sinktheory.equilibrium.prediction.RelaxationPrediction`)
    with its band and run-to-run spread, the law's mean and the settled band, the
    predicted settling time and, when given, the measured window means (a
    :class:`~sinktheory.equilibrium.relaxation.Relaxation`) with their band and settling.

    Examples
    --------
    >>> from sinktheory.canonical import FIG8_WELL
    >>> from sinktheory.equilibrium.prediction import predict_relaxation
    >>> from sinktheory.model import Sink
    >>> p = predict_relaxation(Sink(FIG8_WELL, particles=1, mass=0.2), 0.5, shell_energies=4,
    ...                        shell_runs=16, lag=64, resamples=20, seed=1)
    >>> plot_relaxation(p).axes[0].get_xlabel()
    'time (periods $T$)'
    """
    checked_result(
        "prediction",
        prediction,
        RelaxationPrediction,
        "a RelaxationPrediction (sinktheory.equilibrium.predict_relaxation)",
    )
    if measured is not None:
        checked_result(
            "measured",
            measured,
            Relaxation,
            "a Relaxation (sinktheory.equilibrium.measure_relaxation) or None",
        )
    checked_axes(ax)
    if ax is None:
        fig = Figure(figsize=(6.4, 4.2), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    p = prediction
    mu, f = p.target, p.fraction
    ax.fill_between(p.times, p.means - p.spread, p.means + p.spread, color="C0", alpha=0.12,
                    lw=0, label="predicted run-to-run spread")  # fmt: skip
    ax.fill_between(p.times, p.low, p.high, color="C0", alpha=0.35, lw=0)
    ax.plot(p.times, p.means, color="C0", lw=1.6, label=r"predicted $\langle E_c\rangle$")
    ax.axvline(p.settle_time, color="C0", ls="--", lw=1.0, label="predicted settling")
    if measured is not None:
        m = measured
        ax.fill_between(m.times, m.low, m.high, color="C3", alpha=0.25, lw=0)
        ax.plot(m.times, m.means, color="C3", lw=1.0, label=f"measured ({m.runs} runs)")
        ax.axvline(m.settle_time, color="C3", ls="--", lw=1.0, label="measured settling")
    ax.axhspan(mu * (1 - f), mu * (1 + f), color="0.6", alpha=0.3, lw=0)
    ax.axhline(mu, color="k", lw=0.8, label="law's mean")
    ax.set_xlim(0, p.times[-1])
    ax.set_ylim(0, None)
    ax.set_xlabel("time (periods $T$)")
    ax.set_ylabel(r"$E_c$")
    ax.set_title(f"$k$={p.particles}, $m$={p.mass:g}, $E_0$={p.container_energy:g}: settling "
                 f"within {100 * f:g} % of the law's mean", fontsize=9)  # fmt: skip
    ax.legend(fontsize=8)
    return fig


#: Colours of the ergodicity verdicts (:func:`sinktheory.equilibrium.ergodicity.verdict`).
VERDICTS = {
    2: ("chaotic, samples the law", "C2"),
    1: ("chaotic, not sampling the law", "C1"),
    0: ("regular", "C0"),
    -1: ("undecided (no lambda_1)", "0.5"),
}


def plot_ergodicity(result, ax=None):
    """An :class:`~sinktheory.equilibrium.ergodicity.ErgodicityMap`: the KS distance of the
    runs from the law (top) and lambda_1 with its errors (bottom) against beta, each point
    coloured by its verdict; where the Lyapunov runs split into regular and chaotic ones,
    the lambda_1 of each group (crosses) and the regular count beside them; where every
    run is regular, a ring (the verdict's rule, lambda_1 - 3 s.e. > 0, can still call such
    a point chaotic: a regular run's finite-time lambda_1 is ~ ln t / t, not 0).  ``ax``: a
    pair of Axes (top, bottom) to draw into; a new Figure otherwise.

    Examples
    --------
    >>> from sinktheory.equilibrium.ergodicity import ergodicity_map
    >>> m = ergodicity_map([0.2, 0.3], alpha=0.5, n=4, runs=2, periods=40, transient=10,
    ...                    lyapunov_runs=0, progress=False)
    >>> [a.get_ylabel() for a in plot_ergodicity(m).axes]
    ['KS distance to the law', '$\\\\lambda_1$']
    """
    checked_result(
        "result",
        result,
        ErgodicityMap,
        "an ErgodicityMap (sinktheory.equilibrium.ergodicity.ergodicity_map)",
    )
    if ax is not None:
        pair = "a pair of matplotlib Axes (top, bottom) or None"
        if isinstance(ax, str) or not hasattr(ax, "__len__") or len(ax) != 2:
            raise ParameterError("ax", _shown(ax), pair)
        for a in ax:
            if checked_axes(a) is None:
                raise ParameterError("ax", _shown(ax), pair)
    if ax is None:
        fig = Figure(figsize=(7.0, 5.5), layout="constrained")
        top, bottom = fig.subplots(2, 1, sharex=True)
    else:
        top, bottom = ax
        fig = top.figure
    beta = np.asarray(result.beta)
    for code, (label, colour) in VERDICTS.items():
        pick = result.verdict == code
        if not pick.any():
            continue
        top.plot(beta[pick], result.ks_distance[pick], "o", color=colour, ms=4, label=label)
        bottom.errorbar(
            beta[pick],
            result.lambda1[pick],
            yerr=3 * result.lambda1_se[pick],
            fmt="o",
            color=colour,
            ms=4,
            capsize=2,
        )
    runs = result.parameters.get("lyapunov_runs", 0)
    mixed = (result.regular_runs > 0) & (result.regular_runs < runs)
    for j in np.nonzero(mixed)[0]:  # regular and chaotic runs: each group's lambda_1
        bottom.plot([beta[j]] * 2, [result.lambda1_regular[j], result.lambda1_chaotic[j]], "x",
                    color="k", ms=5)  # fmt: skip
        bottom.annotate(f"{int(result.regular_runs[j])}/{runs} reg.",
                        (beta[j], result.lambda1_chaotic[j]), fontsize=6, ha="center",
                        va="bottom")  # fmt: skip
    if mixed.any():
        bottom.plot([], [], "x", color="k", label="mixed: each group's $\\lambda_1$")
    regular = result.regular_runs == runs  # every run within the envelope 3 ln t / t
    if runs and regular.any():
        bottom.plot(beta[regular], result.lambda1[regular], "o", mfc="none", mec="k", ms=9,
                    label=r"every run regular ($\lambda_1 \leq 3 \ln t / t$)")  # fmt: skip
    if mixed.any() or (runs and regular.any()):
        bottom.legend(fontsize=7)
    top.plot(beta, result.ks_distance, color="0.7", lw=0.8, zorder=0)
    top.set_ylabel("KS distance to the law")
    top.legend(fontsize=7)
    bottom.axhline(0.0, color="0.6", lw=0.8)
    bottom.set_ylabel("$\\lambda_1$")
    bottom.set_xlabel("$\\beta$")
    p = result.parameters
    top.set_title(
        f"{p.get('shape', 'flat')} well $\\alpha$={p.get('alpha')}, $n$={p.get('n')}, "
        f"$k$={p.get('particles', 1)}: {p['runs']} runs x {p['periods'] - p['transient']} "
        "periods after the transient; bars: 3 se",
        fontsize=8,
    )
    return fig
