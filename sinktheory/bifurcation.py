"""Bifurcation (orbit) diagrams over beta for one particle (paper Figs. 3 and 11).

The section
-----------
For each beta the full coupled system (container + one particle, k = 1) is integrated
from the paper's start: container displaced to X = sqrt(2 E0) and released, particle at
rest at (x, y) = (0, 0.01) relative to the container (as in Fig. 4).  After a transient
of ``transient`` periods the stroboscopic section is sampled at t = jT (T = 2 pi, the
container's period) for ``count`` periods.  Two section quantities are offered:

* ``"y"`` (default): the particle's y relative to the container.  While the normal mode
  y = 0 is stable the particle stays near it and the section is a thin band around
  |y| <= 0.01; when the mode is unstable the particle wanders over the whole well and the
  section fills an interval of width ~ the well's reach.
* ``"energy"``: the container energy E(jT); regular motion returns few values, chaotic
  motion a cloud.

A diagram is a pure function of its parameters: the same input gives the same points.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.figure import Figure

from . import validation as v
from .errors import ParameterError
from .model import RunSettings, Sink, Well
from .simulate import default_step, simulate

QUANTITIES = ("y", "energy")
#: Start of the particle relative to the container (Fig. 4 of the paper).
START = (0.0, 0.01)


@dataclass(frozen=True)
class BifurcationDiagram:
    """Section values (B, count) at each beta, with everything needed to redraw them."""

    beta: np.ndarray
    section: np.ndarray
    quantity: str
    alpha: float
    n: int
    gamma: float
    shape: str
    mass: float
    energy: float
    transient: int
    count: int


def sampled_run(sink: Sink, settings: RunSettings, start, *, per_period: int) -> np.ndarray:
    """One run from ``start`` = (x, y) (each particle at rest), its state sampled exactly
    ``per_period`` times per container period: rows (P * per_period + 1, 2 + 4k) with
    columns X, Xdot, u_1..u_k, y_1..y_k, udot..., ydot... (u = X + x).

    The step is the default one shortened so a period holds a multiple of
    ``per_period`` steps, so the samples fall on t = jT / per_period.
    """
    per_period = v.positive_int("per_period", per_period)
    dt, steps = default_step(sink, settings.total_energy_bound(sink))
    steps = per_period * -(-steps // per_period)  # round up to a multiple
    res = simulate(
        sink,
        settings,
        initial=[start] * sink.particles,
        record=("trajectory",),
        dt=2 * np.pi / steps,
        stride=steps // per_period,
        progress=False,
    )
    if res.steps_per_period != steps:  # samples must fall exactly on t = jT / per_period
        raise AssertionError("trajectory stride does not match the period")
    return res.trajectory[0]


def section(
    sink: Sink,
    *,
    transient: int = 200,
    count: int = 200,
    quantity: str = "y",
    energy: float = 0.5,
) -> np.ndarray:
    """The stroboscopic section of one single-particle run (see the module docstring).

    Examples
    --------
    >>> s = section(Sink(Well(0.5, 0.3, 4), 1, 0.2), transient=2, count=3)
    >>> s.shape
    (3,)
    """
    if sink.particles != 1:
        raise ParameterError("particles", sink.particles, "1 for a bifurcation diagram")
    transient = v.positive_int("transient", transient, minimum=0)
    count = v.positive_int("count", count)
    quantity = v.choice("quantity", quantity, QUANTITIES)
    settings = RunSettings(energy=energy, runs=1, periods=transient + count)
    if quantity == "energy":
        res = simulate(sink, settings, initial=[START], record=("container",), progress=False)
        return res.container_energy[0, transient + 1 :]
    rows = sampled_run(sink, settings, START, per_period=1)
    return rows[transient + 1 :, 3]  # columns X, Xdot, u, y, udot, ydot


def bifurcation(
    betas,
    *,
    alpha: float,
    n: int,
    gamma: float = 1.0,
    shape: str = "flat",
    mass: float = 0.2,
    energy: float = 0.5,
    transient: int = 200,
    count: int = 200,
    quantity: str = "y",
) -> BifurcationDiagram:
    """Sections for each beta in ``betas`` (run one after another; see :mod:`sinktheory.sweep`
    for parallel and resumable sweeps).

    Raises ParameterError naming ``beta`` if a value gives an invalid well.
    """
    betas = np.asarray(betas, dtype=float)
    if betas.ndim != 1 or betas.size == 0:
        raise ParameterError("betas", f"array of shape {betas.shape}", "a non-empty 1-D array")
    sinks = [Sink(Well(alpha, b, n, gamma=gamma, shape=shape), 1, mass) for b in betas]
    for s in sinks:  # refuse bad input before any long computation
        RunSettings(energy=energy, runs=1, periods=1).check(s)
    rows = [
        section(s, transient=transient, count=count, quantity=quantity, energy=energy)
        for s in sinks
    ]
    w = sinks[0].well
    return BifurcationDiagram(
        betas,
        np.array(rows),
        quantity,
        w.alpha,
        w.n,
        w.gamma,
        w.shape,
        mass,
        energy,
        transient,
        count,
    )


def plot_bifurcation(diagram: BifurcationDiagram, unstable=(), ax=None, title=None):
    """Draw the section points against beta; shade the Floquet-unstable ``unstable``
    intervals [(lo, hi), ...] of the normal mode y = 0.  Returns the Figure."""
    if ax is None:
        fig = Figure(figsize=(7.0, 4.0), layout="constrained")
        ax = fig.subplots()
    else:
        fig = ax.figure
    for i, (lo, hi) in enumerate(unstable):
        ax.axvspan(
            lo,
            hi,
            color="tab:red",
            alpha=0.15,
            lw=0,
            label="normal mode unstable (Floquet)" if i == 0 else None,
        )
    b = np.repeat(diagram.beta, diagram.section.shape[1])
    ax.plot(b, diagram.section.ravel(), ".", ms=1.0, color="black", alpha=0.6)
    ax.set_xlabel("$\\beta$")
    ax.set_ylabel("$y(jT)$" if diagram.quantity == "y" else "$E(jT)$")
    ax.set_title(
        title or (f"{diagram.shape} well, $\\alpha$={diagram.alpha:g}, $n$={diagram.n}, $k$=1"),
        fontsize=9,
    )
    if unstable:
        ax.legend(loc="upper left", fontsize=8)
    return fig
