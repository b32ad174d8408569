"""Charts of Floquet stability: phi_half against a parameter (Fig. 7) and stability tongues.

All functions return :class:`matplotlib.figure.Figure` objects (no pyplot state).
phi_half is drawn on a symmetric-log axis (linear for |phi_half| <= 1), so both kinds of
instability, phi_half > 1 and phi_half < -1, stay visible however large phi grows.

Examples
--------
>>> from sinktheory.floquet import pure_problem, scan
>>> fig = plot_scan(scan(pure_problem(2), -0.5, 3.0, 50))
>>> fig.axes[0].get_xlabel()
'$\\\\Lambda$'
"""

from __future__ import annotations

import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.figure import Figure
from matplotlib.ticker import SymmetricalLogLocator

from .. import validation as v
from ..errors import ParameterError
from ..floquet import StabilityScan, model_problem, pure_problem, scan
from ..model import SHAPES
from . import checked_result, checked_title

__all__ = ["plot_fig7", "plot_scan", "plot_tongues"]

#: Most panels (wall stiffnesses) of :func:`plot_fig7`.
MAX_PANELS = 10
#: Most rows (wall stiffnesses) and grid points per row of :func:`plot_tongues`.
MAX_ROWS, MAX_COUNT = 100, 100_000

_LABEL = {"lam": r"$\Lambda$", "beta": r"$\beta$"}
_CAP = 1e300


def _stiffnesses(ns, maximum: int) -> tuple[int, ...]:
    """``ns`` as a tuple of 1 to ``maximum`` wall stiffnesses, else ParameterError."""
    if isinstance(ns, str) or not hasattr(ns, "__len__") or not 1 <= len(ns) <= maximum:
        raise ParameterError("ns", ns, f"a sequence of 1 to {maximum} wall stiffnesses n")
    return tuple(v.positive_int("ns", n) for n in ns)


def _phi_axis(ax, h: np.ndarray) -> None:
    """Symmetric-log axis for phi_half: linear in [-1, 1], decades beyond, plain labels."""
    ax.set_yscale("symlog", linthresh=1.0, linscale=2.0)
    top = int(np.ceil(np.log10(max(1.0, float(np.max(np.abs(h)))))))
    step = max(1, top // 6)
    decades = [10.0**k for k in range(step, top + 1, step)]
    ticks = [-d for d in decades[::-1]] + [-1.0, -0.5, 0.0, 0.5, 1.0] + decades
    ax.set_yticks(ticks, [f"{t:g}" for t in ticks])
    ax.yaxis.set_minor_locator(SymmetricalLogLocator(base=10, linthresh=1.0, subs=range(2, 10)))


def _draw_scan(ax, result: StabilityScan, title: str) -> None:
    chart = result.chart
    h = np.clip(chart.phi_half, -_CAP, _CAP)
    _phi_axis(ax, h)
    for k, (a, b) in enumerate(result.stable_intervals):
        ax.axvspan(a, b, color="tab:green", alpha=0.15, lw=0, label="stable" if k == 0 else None)
    ax.plot(chart.values, h, color="k", lw=1.2, label=r"$\phi_{T/2}$")
    for y in (-1.0, 1.0):
        ax.axhline(y, color="tab:red", lw=0.8, ls="--")
    ax.axhline(0.0, color="0.6", lw=0.5)
    if result.boundaries:
        xb = [b.value for b in result.boundaries]
        yb = [b.phi_half for b in result.boundaries]
        ax.plot(xb, yb, "o", ms=3.5, color="tab:red", label="boundary (brentq)")
    if result.resonances:
        ax.plot(
            result.resonances,
            np.zeros(len(result.resonances)),
            "D",
            ms=4,
            mfc="none",
            color="tab:blue",
            label=r"$\phi_T=-1$ (resonance)",
        )
    ax.set_xlabel(_LABEL[chart.problem.parameter])
    ax.set_ylabel(r"$\phi_{T/2}$ (symlog)")
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)


def plot_scan(result: StabilityScan, *, title: str | None = None) -> Figure:
    """phi_half over the scan's grid, stable intervals shaded, boundaries and resonances marked.

    Parameters
    ----------
    result : StabilityScan
        From :func:`sinktheory.floquet.scan`.
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    checked_result("result", result, StabilityScan, "a StabilityScan (sinktheory.floquet.scan)")
    checked_title(title)
    p = result.chart.problem
    fig = Figure(figsize=(8, 4.5), layout="constrained")
    ax = fig.add_subplot()
    if title is None:
        title = (
            f"pure Hill equation, n = {p.n}, $A_0$ = {p.amplitude:g}"
            if p.kind == "pure"
            else rf"{p.kind} well, $\alpha$ = {p.alpha:g}, n = {p.n}, $A_0$ = {p.amplitude:g}"
        )
    _draw_scan(ax, result, title)
    ax.legend(fontsize=8, loc="best")
    return fig


def plot_fig7(
    *,
    alpha: float = 0.5,
    gamma: float = 1.0,
    ns: tuple[int, ...] = (2, 10),
    beta_range: tuple[float, float] = (-1.0, 0.499),
    count: int = 600,
    shape: str = "flat",
    title: str | None = None,
) -> Figure:
    """Fig. 7 of the paper: phi_half(beta) for alpha = 1/2, gamma = 1, one panel per n.

    Parameters
    ----------
    alpha, gamma : float
        Well parameters (gamma does not change phi; it is validated).
    ns : tuple of int
        Wall stiffnesses, one panel each (the paper: 2 and 10, as in Fig. 3).
    beta_range : (float, float)
        beta from ... to (must stay below alpha).
    count : int
        Grid points per panel; boundaries are located by root finding regardless.
    shape : "flat" or "symmetric"
    title : str, optional
        Title over the panels.

    Returns
    -------
    matplotlib.figure.Figure
    """
    ns = _stiffnesses(ns, MAX_PANELS)
    pair = "two finite numbers (from, to)"
    lo_hi = v.finite_array("beta_range", beta_range, pair, ndim=1)
    if lo_hi.size != 2:
        raise ParameterError("beta_range", f"{lo_hi.size} numbers", pair)
    lo, hi = lo_hi
    checked_title(title)
    fig = Figure(figsize=(8, 3.2 * len(ns) + 0.5), layout="constrained")
    for k, n in enumerate(ns):
        ax = fig.add_subplot(len(ns), 1, k + 1)
        problem = model_problem(alpha, n, gamma=gamma, shape=shape)
        result = scan(problem, lo, hi, count)
        _draw_scan(
            ax, result, rf"{shape} well, $\alpha$ = {alpha:g}, $\gamma$ = {gamma:g}, n = {n}"
        )
        if k == 0:
            ax.legend(fontsize=8, loc="best")
    if title:
        fig.suptitle(title)
    return fig


def plot_tongues(
    ns,
    lo: float,
    hi: float,
    *,
    count: int = 400,
    alpha: float | None = None,
    shape: str = "flat",
    amplitude: float = 1.0,
) -> Figure:
    """Stability tongues over (parameter, n): Lam for the pure equation, beta if alpha given.

    Stable points are coloured by their rotation number theta/pi (so the strong
    resonances phi_T = -1 are where the colour passes 1/2); phi_half > 1 and
    phi_half < -1 get two flat colours.  The pure chart also shows the rigid-wall limit
    stability interval 0 < Lam A0^2 < 1.

    Parameters
    ----------
    ns : sequence of int
        Wall stiffnesses (rows).
    lo, hi : float
        Parameter range.
    count : int
        Grid points per row.
    alpha : float, optional
        If given, the model family in beta for this alpha; otherwise the pure family.
    shape : "flat" or "symmetric"
    amplitude : float
        A0.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = plot_tongues([1, 2, 4], -0.5, 3.0, count=40)
    >>> fig.axes[0].get_ylabel()
    '$n$'
    """
    ns = sorted(set(_stiffnesses(ns, MAX_ROWS)))
    lo, hi = v.finite("lo", lo), v.finite("hi", hi)
    if not lo < hi:
        raise ParameterError("hi", hi, f"a number above lo = {lo:g}")
    count = v.positive_int("count", count, minimum=2, maximum=MAX_COUNT)
    v.choice("shape", shape, SHAPES)
    grid = np.linspace(lo, hi, count)
    rows = []
    param = "lam"
    for n in ns:
        if alpha is None:
            problem = pure_problem(n, amplitude)
        else:
            problem = model_problem(alpha, n, shape=shape, amplitude=amplitude)
        param = problem.parameter
        chart = problem.evaluate(grid)
        h = chart.phi_half
        row = np.where(chart.stable, chart.rotation_number, np.where(h > 0, 1.5, -0.5))
        rows.append(row)
    z = np.array(rows)
    fig = Figure(figsize=(8, 5), layout="constrained")
    ax = fig.add_subplot()
    ypos = np.arange(len(ns))
    stable = np.ma.masked_where((z < 0) | (z > 1), z)
    up = np.ma.masked_where(z != 1.5, z)
    down = np.ma.masked_where(z != -0.5, z)
    ax.pcolormesh(grid, ypos, up, cmap=ListedColormap(["0.35"]), shading="nearest")
    ax.pcolormesh(grid, ypos, down, cmap=ListedColormap(["tab:red"]), shading="nearest")
    mesh = ax.pcolormesh(grid, ypos, stable, cmap="viridis", vmin=0, vmax=1, shading="nearest")
    fig.colorbar(mesh, ax=ax, label=r"rotation number $\theta/\pi$ (stable)")
    ax.set_yticks(ypos, [str(n) for n in ns])
    ax.set_xlabel(_LABEL[param])
    ax.set_ylabel("$n$")
    if alpha is None:
        for x in (0.0, 1.0 / amplitude**2):
            ax.axvline(x, color="w", ls="--", lw=1.0)
        ax.set_title(
            r"stability tongues of $\ddot y + \Lambda x^{2n} y = 0$ "
            r"(grey: $\phi_{T/2}>1$, red: $\phi_{T/2}<-1$; dashed: rigid limit)",
            fontsize=9,
        )
    else:
        ax.set_title(
            rf"stability tongues, {shape} well, $\alpha$ = {alpha:g} "
            r"(grey: $\phi_{T/2}>1$, red: $\phi_{T/2}<-1$)",
            fontsize=9,
        )
    return fig
