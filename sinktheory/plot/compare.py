r"""Charts of the attachment comparison (:mod:`sinktheory.compare`).

matplotlib is imported inside the functions only.  Every function returns a
:class:`matplotlib.figure.Figure` (no pyplot state), saved by the caller.

* :func:`plot_efficiency` -- the fraction of the impulse's energy dissipated in the
  window against the initial container energy E0 (log axis), one curve per attachment
  with a band of +- 2 standard errors;
* :func:`plot_t90` -- the time to dissipate 90 % against E0 (where runs reached it; the
  marker's label gives how many did);
* :func:`plot_comparison` -- the two side by side (what ``sinktheory compare --plot``
  writes);
* :func:`plot_transfer` -- the wavelet map of the container displacement, and its ridge
  drawn against the energy left over the normal modes' frequency-energy curves.

Examples
--------
>>> import numpy as np
>>> from sinktheory.compare.efficiency import Comparison
>>> e = np.array([0.01, 0.1, 1.0])
>>> c = Comparison(("NES n = 2", "well flat k = 1"), e, np.array([[0.1, 0.5, 0.6],
...                [0.4, 0.5, 0.5]]), np.full((2, 3), 0.02), np.array([[np.nan, 30, 20],
...                [40, 35, np.nan]]), np.full((2, 3), 1.0), np.array([[0, 4, 4], [4, 4, 0]]),
...                np.zeros((2, 3)), [], 0.01, 4, 50, 0, 16, 1.0)
>>> fig = plot_comparison(c)
>>> [ax.get_xlabel() for ax in fig.axes]
['initial container energy $E_0$', 'initial container energy $E_0$']
"""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError
from ..nnm.result import BranchResult
from . import _shown, checked_fields, checked_results, checked_title

__all__ = ["BAND", "plot_comparison", "plot_efficiency", "plot_t90", "plot_transfer"]

#: Half-width of the error bands, in standard errors.
BAND = 2.0


def _style(i: int, label: str) -> dict:
    """One colour per attachment; dashed for the 1-D attachments."""
    dashed = label.startswith(("NES", "vibro"))
    return {"color": f"C{i}", "ls": "--" if dashed else "-", "marker": "o", "ms": 3}


def draw_efficiency(ax, comparison) -> None:
    """Efficiency against E0 with bands of +- :data:`BAND` standard errors on ``ax``."""
    c = comparison
    for i, name in enumerate(c.attachment):
        style = _style(i, name)
        mean = c.efficiency[i]
        se = np.nan_to_num(c.efficiency_se[i])
        ax.plot(c.container_energy, mean, label=name, **style)
        ax.fill_between(c.container_energy, mean - BAND * se, mean + BAND * se,
                        color=style["color"], alpha=0.2, lw=0)  # fmt: skip
    ax.set_xscale("log")
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlabel("initial container energy $E_0$")
    ax.set_ylabel(f"fraction dissipated in {c.periods} T")
    ax.grid(alpha=0.3, which="both")


def draw_t90(ax, comparison) -> None:
    """Mean time to dissipate 90 % (+- :data:`BAND` s.e.) where any run reached it."""
    c = comparison
    for i, name in enumerate(c.attachment):
        style = _style(i, name)
        ok = c.reached[i] > 0
        if not ok.any():
            ax.plot([], [], label=f"{name}: never", **style)
            continue
        err = BAND * np.nan_to_num(c.t90_se[i][ok])
        ax.errorbar(c.container_energy[ok], c.t90[i][ok], yerr=err, label=name, capsize=2, **style)
    ax.set_xscale("log")
    ax.set_xlabel("initial container energy $E_0$")
    ax.set_ylabel("time to dissipate 90 % (periods T)")
    ax.grid(alpha=0.3, which="both")


def _checked(comparison, title) -> None:
    """ParameterError unless ``comparison`` is a Comparison and ``title`` a text or None."""
    fields = ("attachment", "container_energy", "efficiency", "t90", "reached", "damping")
    checked_fields("comparison", comparison, fields,
                   "a Comparison (sinktheory.compare.efficiency.compare)")  # fmt: skip
    checked_title(title)


def _alone(draw, comparison, title):
    """One chart of ``draw`` on its own figure."""
    from matplotlib.figure import Figure

    _checked(comparison, title)
    fig = Figure(figsize=(7, 4.6), layout="constrained")
    ax = fig.add_subplot()
    draw(ax, comparison)
    ax.legend(fontsize=8)
    ax.set_title(title or _title(comparison), fontsize=10)
    return fig


def plot_efficiency(comparison, *, title: str | None = None):
    """The efficiency chart alone."""
    return _alone(draw_efficiency, comparison, title)


def plot_t90(comparison, *, title: str | None = None):
    """The 90 % time chart alone."""
    return _alone(draw_t90, comparison, title)


def plot_comparison(comparison, *, title: str | None = None):
    """Efficiency (left) and 90 % time (right) against E0, attachments side by side."""
    from matplotlib.figure import Figure

    _checked(comparison, title)
    fig = Figure(figsize=(12, 4.6), layout="constrained")
    left, right = fig.subplots(1, 2)
    draw_efficiency(left, comparison)
    draw_t90(right, comparison)
    left.legend(fontsize=8)
    fig.suptitle(title or _title(comparison), fontsize=10)
    return fig


def _title(c) -> str:
    mass = c.attachments[0]["mass"] if c.attachments else None
    m = "" if mass is None else f"m = {mass:g}, "
    users = {  # a user's well named with its own parameters (once for all its k)
        f"; {a['shape']} well " + (", ".join(f"{k}={x:g}" for k, x in
                                             a["well_parameters"].items()) or "no parameters")
        for a in c.attachments if "well_parameters" in a
    }  # fmt: skip
    return (
        f"impulse responses: {m}dashpot c = {c.damping:g}, {c.runs} runs per point "
        f"(bands: +-{BAND:g} s.e.)" + "".join(sorted(users))
    )


def plot_transfer(maps, backbones=(), *, title: str | None = None):
    """Wavelet maps (top row) and their ridges over the frequency-energy plot (bottom).

    Parameters
    ----------
    maps : sequence of TransferMap
        One column each.
    backbones : sequence of list of BranchResult
        The normal-mode branches to draw under each map's ridge (same order; may be
        shorter or empty).
    """
    from matplotlib.figure import Figure

    from .nnm import draw_frequency_energy

    maps = checked_results(
        "maps",
        maps,
        ("wavelet", "energy_left", "label", "impulse_energy"),
        "TransferMap (sinktheory.compare.transfer.transfer_maps)",
    )
    branches = f"a sequence of at most {len(maps)} lists of BranchResult (one per map)"
    if isinstance(backbones, str | bytes | dict) or not hasattr(backbones, "__iter__"):
        raise ParameterError("backbones", _shown(backbones), branches)
    backbones = list(backbones)
    if len(backbones) > len(maps) or not all(
        isinstance(b, list | tuple) and all(isinstance(r, BranchResult) for r in b)
        for b in backbones
    ):
        raise ParameterError("backbones", _shown(backbones), branches)
    checked_title(title)
    backbones = [list(b) for b in backbones] + [[]] * (len(maps) - len(backbones))
    fig = Figure(figsize=(4.6 * len(maps), 7.5), layout="constrained")
    axes = np.asarray(fig.subplots(2, len(maps), squeeze=False))
    for j, m in enumerate(maps):
        w = m.wavelet
        top, bottom = axes[0, j], axes[1, j]
        periods = w.t / (2 * np.pi)
        mesh = top.pcolormesh(periods, w.omega, w.modulus, shading="auto", cmap="viridis")
        top.plot(periods, w.ridge, color="w", lw=0.8)
        top.set_yscale("log")
        top.set_xlabel("time t / T")
        top.set_ylabel(r"frequency $\omega$")
        top.set_title(f"{m.label}: $E_0$ = {m.impulse_energy:g}", fontsize=10)
        fig.colorbar(mesh, ax=top, label="|W| / sqrt(scale)")
        if backbones[j]:
            draw_frequency_energy(bottom, backbones[j])
            _mark_localisation(bottom, backbones[j])
        ok = np.isfinite(w.ridge)
        points = bottom.scatter(m.energy_left[ok], w.ridge[ok], c=periods[ok], s=2,
                                cmap="plasma", zorder=3)  # fmt: skip
        fig.colorbar(points, ax=bottom, label="time t / T")
        bottom.set_xscale("log")
        bottom.set_yscale("log")
        bottom.set_ylim(w.omega[0], w.omega[-1])  # the map's band (branches reach beyond)
        bottom.set_xlabel("total energy left $H = H_0 - W$")
        bottom.set_ylabel(r"frequency $\omega$")
        bottom.grid(alpha=0.3, which="both")
        if bottom.get_legend_handles_labels()[0]:
            bottom.legend(fontsize=7, loc="best")
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


def _mark_localisation(ax, branches) -> None:
    """A vertical line where an in-phase 1:1 backbone changes from particle- to
    container-localised (:func:`sinktheory.nnm.backbone.localisation_energy`): the
    NES's transfer threshold lies near it."""
    from ..errors import ParameterError
    from ..nnm.backbone import localisation_energy

    for b in branches:
        if b.meta.get("mode") != "in-phase":
            continue
        try:
            e = localisation_energy(b)
        except ParameterError:  # this piece does not reach the half share
            continue
        ax.axvline(e, color="0.3", ls="--", lw=1,
                   label=f"in-phase mode half in the container: E = {e:.2g}")  # fmt: skip
        return
