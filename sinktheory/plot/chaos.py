"""Convergence plots of the chaos indicators (matplotlib is imported when drawing).

Examples
--------
>>> import numpy as np
>>> from sinktheory.chaos import indicators
>>> q, v = np.array([[0.0], [-0.25]]), np.array([[0.42081], [0.0]])
>>> res = indicators("henon_heiles", q, v, [], dt=0.05, steps=20, segments=40, gali=2)
>>> fig = convergence_figure(res, window=10)
>>> len(fig.axes)
2
"""

from __future__ import annotations

import numpy as np

from ..chaos import verdicts
from ..chaos.result import ChaosResult
from ..runstats import ensemble_mean
from ..validation import positive_int
from . import checked_path, checked_result, checked_title

__all__ = ["convergence_figure", "FLOOR", "plot_convergence"]

#: GALI values below this are round-off (unit vectors parallel to machine precision).
FLOOR = 1e-16


def convergence_figure(result: ChaosResult, *, window: int | None = None, title: str = ""):
    """Finite-time exponents against time, with the ensemble mean +- standard error.

    Top: lambda_1(t) = ln|delta_1| / t of every run (thin), their mean with its standard-
    error band (for a mixed ensemble, :meth:`~sinktheory.chaos.ChaosResult.split`, one mean
    and band per group: regular and chaotic runs apart), the mean over windows of
    ``window`` segments (default: S / 20) as steps, and the other exponents of the
    spectrum (means) when computed; the transverse exponent when computed.  Bottom (when
    computed): GALI_k (log scale) and the time-averaged MEGNO <Y>.  Time in units of the
    segment (for the sink, the period T = 2 pi).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    checked_result("result", result, ChaosResult, "a ChaosResult (sinktheory.chaos)")
    segments = len(result.times) - 1
    window = None if window is None else positive_int("window", window, maximum=segments)
    checked_title(title)
    lower = result.gali is not None or result.megno is not None
    fig = Figure(figsize=(8, 7 if lower else 4.5), layout="constrained")
    axes = fig.subplots(2 if lower else 1, 1, squeeze=False)[:, 0]
    seg = result.times[1] - result.times[0]
    t = result.times[1:] / seg
    ax = axes[0]
    ft = result.finite_time_lambda1
    split = result.split()
    regular = result.lambda1 <= split.threshold
    groups = ((regular, "C9", "regular"), (~regular, "C0", "chaotic")) if split.mixed else (
        (np.ones(len(ft), bool), "C0", ""),)  # fmt: skip
    for group, color, name in groups:
        for run in ft[group][:50]:
            ax.plot(t, run, color="0.6" if not name else color, lw=0.5, alpha=0.6)
        m, se = ensemble_mean(ft[group])
        ax.fill_between(t, m - se, m + se, color=color, alpha=0.3, lw=0)
        label = (rf"$\lambda_1(t)$ of the {int(group.sum())} {name} runs of {len(ft)}" if name
                 else r"$\lambda_1(t)$, mean $\pm$ s.e.")  # fmt: skip
        ax.plot(t, m, color=color, lw=1.5, label=label)
    w = max(1, len(t) // 20) if window is None else int(window)
    ends, wl = result.window_exponents(w)
    if len(ends):
        wm = wl.mean(axis=0)
        ax.step(ends / seg, wm, where="pre", color="C3", lw=1.0, label=f"windows of {w}")
    if result.spectrum_logs is not None:
        ftl = result.spectrum_logs[:, 1:] / (result.times[1:] - result.times[0])[None, :, None]
        means = ftl.mean(axis=0)
        for i in range(1, means.shape[1]):
            ax.plot(t, means[:, i], lw=0.8, color="C2")
        ax.plot([], [], color="C2", lw=0.8, label=r"$\lambda_2 \ldots \lambda_{2D}$ (means)")
    if result.transverse_logs is not None:
        tr = result.transverse_logs[:, 1:] / (result.times[1:] - result.times[0])
        ax.plot(t, tr.mean(axis=0), color="C1", lw=1.2, ls="--", label="transverse (y = 0)")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xscale("log")
    ax.set_xlabel(r"$t$ / segment" if "period" not in result.parameters else r"$t/T$")
    ax.set_ylabel("finite-time exponent (per unit time)")
    ax.legend(loc="upper right", fontsize="small")
    ax.grid(alpha=0.3)
    if title:
        ax.set_title(title)
    if lower:
        ax2 = axes[1]
        tt = result.times / seg
        if result.gali is not None:
            g = np.clip(result.gali, FLOOR, None)  # exact zeros: parallel to round-off
            for run in g[: min(len(g), 50)]:
                ax2.plot(tt, run, color="C0", lw=0.6, alpha=0.6)
            ax2.plot([], [], color="C0", label=f"GALI$_{{{result.gali_order}}}$")
            ax2.axhline(FLOOR, color="k", lw=0.5, ls=":")
            ax2.set_yscale("log")
            ax2.set_ylabel(f"GALI$_{{{result.gali_order}}}$")
        if result.megno is not None:
            target = ax2.twinx() if result.gali is not None else ax2
            mm = result.mean_megno
            for run in mm[: min(len(mm), 50)]:
                target.plot(tt, run, color="C1", lw=0.6, alpha=0.6)
            target.axhline(2.0, color="C1", lw=0.5, ls=":")
            target.set_ylabel(r"$\langle Y\rangle$ (MEGNO)")
            target.plot([], [], color="C1", label=r"$\langle Y\rangle$")
            target.legend(loc="center right", fontsize="small")
        ax2.set_xlabel(r"$t/T$" if "period" in result.parameters else r"$t$ / segment")
        ax2.grid(alpha=0.3)
    return fig


def plot_convergence(result: ChaosResult, path, **kwargs) -> None:
    """Draw :func:`convergence_figure` to ``path`` (PNG unless its suffix says otherwise)."""
    checked_path("path", path)
    convergence_figure(result, **kwargs).savefig(path, dpi=120)


def draw_map(ds, stable_intervals, ax, *, title: str = "") -> None:
    """lambda_1(beta) with its +-2 s.e. band, the transverse exponent, the verdict
    threshold, and the Floquet-stable intervals of y = 0 shaded; betas whose runs split
    into regular and chaotic ones (:func:`sinktheory.chaos.verdicts.map_split`) get each
    run's lambda_1 as dots and the regular count written beside them."""
    beta = ds.beta.values
    lam, se = ds.lambda1.values, ds.lambda1_se.values
    v = verdicts.verdicts(ds)
    if "mixed" in v and v["mixed"].any():
        for j in np.nonzero(v["mixed"])[0]:
            runs = ds.lambda1_runs.values[j]
            ax.plot(np.full(runs.size, beta[j]), runs, ".", color="C3", ms=2)
            ax.annotate(f"{v['regular_runs'][j]}/{v['runs']} reg.", (beta[j], runs.max()),
                        fontsize=6, ha="center", va="bottom")  # fmt: skip
        ax.plot([], [], ".", color="C3", label=r"runs of a mixed $\beta$ (regular/runs)")
    for a, b in stable_intervals:
        ax.axvspan(a, b, color="tab:green", alpha=0.15, lw=0)
    ax.fill_between(beta, lam - 2 * se, lam + 2 * se, color="C0", alpha=0.3, lw=0)
    ax.plot(beta, lam, "o-", color="C0", ms=3, lw=1, label=r"$\lambda_1$ $\pm$ 2 s.e.")
    if "transverse" in ds and np.isfinite(ds.transverse.values).all():
        ax.plot(beta, ds.transverse.values, "s--", color="C1", ms=2.5, lw=0.8,
                label="transverse (y = 0)")  # fmt: skip
    ax.axhline(verdicts.threshold(int(ds.attrs["periods"])), color="k", lw=0.6, ls=":",
               label=f"{verdicts.THRESHOLD_FACTOR:g} ln t / t")  # fmt: skip
    ax.plot([], [], color="tab:green", alpha=0.4, lw=6, label="Floquet-stable y = 0")
    ax.set_xlabel(r"$\beta$")
    ax.set_ylabel(r"$\lambda_1$ (per unit time)")
    ax.set_xlim(beta.min(), beta.max())
    ax.grid(alpha=0.3)
    ax.legend(fontsize="small", loc="upper left")
    if title:
        ax.set_title(title, fontsize="medium")
