"""Frequency-energy plots and transverse-stability charts of the normal modes.

matplotlib is imported inside the functions only (the package itself does not need it).
Every function returns a :class:`matplotlib.figure.Figure` (no pyplot state).

* :func:`plot_frequency_energy`: frequency omega = 2 pi / T against the total energy
  (log axis), solid where the orbit is stable, dotted where it is not (in-plane or
  transverse), events marked (Kerschen et al., MSSP 2009 style).
* :func:`plot_transverse`: the transverse phi_half of the coupled normal mode against
  beta beside the paper's fixed-container phi_half(beta) (Fig. 7,
  :func:`sinktheory.floquet.scan`); a ``chaos`` hook draws a chaos map below it
  (the chaos package will provide one).

Examples
--------
>>> import numpy as np
>>> from sinktheory.nnm.system import FlowSystem
>>> from sinktheory.nnm.continuation import continue_orbits
>>> b = continue_orbits(FlowSystem("duffing2", []), np.array([0.1, 0.1, 0, 0]),
...                     2 * np.pi, steps=64, total_energy=0.01, interval=(1e-3, 1.0), ds=0.5)
>>> fig = plot_frequency_energy([b.result(label="NNM1")])
>>> fig.axes[0].get_xlabel()
'total energy $H$'
"""

from __future__ import annotations

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..floquet import StabilityScan
from ..nnm.result import BranchResult
from . import _shown, checked_result, checked_results, checked_title

__all__ = ["plot_frequency_energy", "plot_nnm", "plot_transverse"]

_MARK = {
    "fold": ("s", "tab:purple"),
    "period-doubling": ("o", "tab:red"),
    "transverse-period-doubling": ("v", "tab:orange"),
    "symmetry-breaking": ("^", "tab:green"),
    "branch-point": ("D", "tab:brown"),
}


#: The stability flags a frequency-energy plot can draw lines by.
STABILITY = ("stable", "stable_inplane", "stable_transverse")
_BRANCHES = "BranchResult (sinktheory.nnm)"


def _beta_branch(name: str, result) -> BranchResult:
    """``result`` if it is a branch continued in a well parameter, else ParameterError."""
    allowed = "a BranchResult continued in a well parameter (beta), not in the energy"
    checked_result(name, result, BranchResult, allowed)
    if result.meta.get("continue_in") == "energy":
        raise ParameterError(name, "a branch continued in the energy", allowed)
    return result


def _chaos_hook(chaos, arrays: bool):
    """``chaos`` if None, a function of an Axes or (when ``arrays``) (beta, values, label)
    of equal-length 1-d arrays and a text, else ParameterError naming ``chaos``."""
    allowed = "None, a function chaos(ax)" + (" or (beta, values, label)" if arrays else "")
    if chaos is None or callable(chaos):
        return chaos
    if not arrays or not isinstance(chaos, tuple | list) or len(chaos) != 3:
        raise ParameterError("chaos", _shown(chaos), allowed)
    beta = v.finite_array("chaos", chaos[0], allowed, ndim=1)
    values = v.real_array("chaos", chaos[1], allowed)
    if values.shape != beta.shape or not isinstance(chaos[2], str):
        raise ParameterError("chaos", _shown(chaos), allowed)
    return beta, values, chaos[2]


def _runs(flags: np.ndarray):
    """(start, stop) index ranges of equal flags, overlapping by one point."""
    start = 0
    for i in range(1, flags.size + 1):
        if i == flags.size or flags[i] != flags[start]:
            yield start, min(i + 1, flags.size), bool(flags[start])
            start = i


def draw_frequency_energy(ax, results, *, stability: str = "stable_inplane") -> None:
    """Draw branches (BranchResult) on ``ax``: line style from the flag ``stability``
    (solid: stable), small crosses where the orbit is transversally unstable."""
    seen = set()
    for k, r in enumerate(results):
        color = f"C{k}"
        label = r.meta.get("label", f"branch {k}")
        flags = np.asarray(getattr(r, stability), bool)
        for a, b, ok in _runs(flags):
            ax.plot(
                r.total_energy[a:b],
                r.frequency[a:b],
                ls="-" if ok else ":",
                lw=1.8 if ok else 1.3,
                color=color,
                label=label if a == 0 else None,
            )
        tu = ~np.asarray(r.stable_transverse, bool)
        if tu.any() and r.transverse.size and stability != "stable":
            ax.plot(
                r.total_energy[tu],
                r.frequency[tu],
                "x",
                color=color,
                ms=3,
                alpha=0.6,
                label="transversally unstable" if "tu" not in seen else None,
            )
            seen.add("tu")
        for e in r.events:
            marker, c = _MARK.get(e["kind"], ("x", "k"))
            ax.plot(
                e["total_energy"],
                e["frequency"],
                marker,
                color=c,
                ms=6,
                mfc="none",
                label=e["kind"] if e["kind"] not in seen else None,
            )
            seen.add(e["kind"])
    ax.set_xscale("log")
    ax.set_xlabel("total energy $H$")
    ax.set_ylabel(r"frequency $\omega = 2\pi/T$")
    ax.grid(alpha=0.3, which="both")


def plot_frequency_energy(results, *, title: str | None = None, stability: str = "stable_inplane"):
    """Frequency-energy plot of one or more branches (solid: stable in the plane,
    dotted: unstable; crosses: transversally unstable).

    Parameters
    ----------
    results : sequence of BranchResult
    title : str, optional
    stability : "stable", "stable_inplane" or "stable_transverse"
    """
    from matplotlib.figure import Figure

    results = checked_results("results", results, BranchResult, _BRANCHES)
    checked_title(title)
    v.choice("stability", stability, STABILITY)
    fig = Figure(figsize=(7.5, 4.8), layout="constrained")
    ax = fig.add_subplot()
    draw_frequency_energy(ax, results, stability=stability)
    ax.legend(fontsize=8, loc="best")
    ax.set_title(
        title or "frequency-energy plot (solid: in-plane stable, dotted: unstable)", fontsize=10
    )
    return fig


def draw_transverse(ax, result, scan=None) -> None:
    """phi_half of the coupled mode (``result``, continued in beta) and of the fixed
    container (``scan``, a :class:`~sinktheory.floquet.StabilityScan`) on ``ax``."""
    from .floquet import _draw_scan

    if scan is not None:
        _draw_scan(ax, scan, "")
        for line in ax.get_lines()[:1]:
            line.set_label(r"fixed container $\phi_{T/2}$ (Fig. 7)")
    x = result.value
    h = result.phi_half[:, 0] if result.phi_half.size else np.full(x.size, np.nan)
    ax.plot(
        x, np.clip(h, -1e300, 1e300), color="tab:blue", lw=1.6, label=r"coupled NNM $\phi_{T/2}$"
    )
    unstable = ~np.asarray(result.stable_inplane, bool)
    if unstable.any():
        ax.plot(x[unstable], h[unstable], ".", color="tab:red", ms=3, label="in-plane unstable")
    if scan is None:
        ax.set_yscale("symlog", linthresh=1.0)
        for y in (-1.0, 1.0):
            ax.axhline(y, color="tab:red", lw=0.8, ls="--")
    ax.set_xlabel(r"$\beta$")
    ax.set_ylabel(r"$\phi_{T/2}$ (symlog)")
    ax.legend(fontsize=7, loc="best")


def _fixed_energy(result) -> float:
    """The total energy H of a branch in a well parameter (the same at every point)."""
    return float(result.total_energy[0]) if result.points else float("nan")


def plot_transverse(result, scan=None, *, chaos=None, title: str | None = None):
    """The coupled mode's transverse stability against beta beside the paper's phi(beta).

    Parameters
    ----------
    result : BranchResult
        A branch continued in beta with ``half_traces=True``.
    scan : StabilityScan, optional
        The fixed-container chart (:func:`sinktheory.floquet.scan`) over the same betas.
    chaos : callable or (beta, values, label), optional
        Hook for a chaos map: ``chaos(ax)`` draws on a panel below, or arrays to plot.
    """
    from matplotlib.figure import Figure

    _beta_branch("result", result)
    if scan is not None:
        checked_result("scan", scan, StabilityScan, "a StabilityScan (floquet.scan) or None")
    chaos = _chaos_hook(chaos, arrays=True)
    checked_title(title)
    rows = 2 if chaos is not None else 1
    fig = Figure(figsize=(8, 4.2 * rows), layout="constrained")
    ax = fig.add_subplot(rows, 1, 1)
    draw_transverse(ax, result, scan)
    m = result.meta
    ax.set_title(
        title
        or f"transverse stability of the coupled normal mode, {m.get('system')}, "
        f"H = {_fixed_energy(result):.4g}",
        fontsize=10,
    )
    if chaos is not None:
        cax = fig.add_subplot(rows, 1, 2, sharex=ax)
        if callable(chaos):
            chaos(cax)
        else:
            beta, values, label = chaos
            cax.plot(beta, values, color="k", lw=1, label=label)
            cax.legend(fontsize=8)
        cax.set_xlabel(r"$\beta$")
    return fig


def plot_nnm(results, beta_result=None, scan=None, *, chaos=None):
    """The frequency-energy plot and, beside it, the transverse chart against beta."""
    from matplotlib.figure import Figure

    results = checked_results("results", results, BranchResult, _BRANCHES)
    if beta_result is not None:
        _beta_branch("beta_result", beta_result)
    if scan is not None:
        checked_result("scan", scan, StabilityScan, "a StabilityScan (floquet.scan) or None")
    chaos = _chaos_hook(chaos, arrays=False)
    cols = 2 if beta_result is not None else 1
    fig = Figure(figsize=(7 * cols, 5), layout="constrained")
    ax = fig.add_subplot(1, cols, 1)
    draw_frequency_energy(ax, results)
    ax.legend(fontsize=7, loc="best")
    ax.set_title("frequency-energy plot (solid: stable, dotted: unstable)", fontsize=10)
    if beta_result is not None:
        bx = fig.add_subplot(1, cols, 2)
        draw_transverse(bx, beta_result, scan)
        bx.set_title(
            f"transverse stability against beta, H = {_fixed_energy(beta_result):.4g}",
            fontsize=10,
        )
        if chaos is not None and callable(chaos):
            chaos(bx.twinx())
    return fig
