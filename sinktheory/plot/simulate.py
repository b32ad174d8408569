"""The ensemble-mean container energy <E>(t/T) of a simulation (paper Figs. 5 and 8).

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> from sinktheory.simulate import simulate
>>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
>>> fig = plot_ensemble_energy(simulate(sink, RunSettings(runs=2, periods=3)), sink)
>>> fig.axes[0].get_xlabel()
'$t/T$'
"""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError
from ..model import Sink
from ..simulate import SimulationResult
from . import checked_result

__all__ = ["plot_ensemble_energy"]


def well_title(well) -> str:
    """The parameters of a sink's well for a plot's title: a registered shape's alpha,
    beta and n, a user's well's own.

    Examples
    --------
    >>> from sinktheory import Well
    >>> print(well_title(Well(0.5, 0.3, 4)))
    $\\alpha$=0.5, $\\beta$=0.3, n=4
    """
    if hasattr(well, "definition"):  # a user's well (sinktheory.wellat.WellAt)
        return ", ".join(f"{k}={x:g}" for k, x in well.parameters.items()) or "no parameters"
    return rf"$\alpha$={well.alpha:g}, $\beta$={well.beta:g}, n={well.n}"


def plot_ensemble_energy(result: SimulationResult, sink: Sink):
    """<E>(t/T) with its standard-error band, from a result that recorded "container".

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    checked_result("result", result, SimulationResult, "a SimulationResult (sinktheory.simulate)")
    if result.container_energy is None:
        raise ParameterError(
            "result",
            "a SimulationResult without the container's energy",
            'one that recorded "container"',
        )
    checked_result("sink", sink, Sink, "a sinktheory.Sink (the one simulated)")
    mean, stderr = result.ensemble_energy()
    fig = Figure(figsize=(8, 4.5), layout="constrained")
    ax = fig.add_subplot()
    t = result.times / (2 * np.pi)
    ax.fill_between(t, mean - stderr, mean + stderr, color="C0", alpha=0.3, label="± std. error")
    ax.plot(t, mean, color="C0", lw=1.0, label=r"$\langle E\rangle$")
    ax.set_xlabel(r"$t/T$")
    ax.set_ylabel(r"$\langle E\rangle$ (container energy)")
    w = sink.well
    ax.set_title(
        rf"{w.shape} well, {well_title(w)}, "
        rf"k={sink.particles}, m={sink.mass:g}; {result.container_energy.shape[0]} run(s)"
    )
    ax.set_xlim(t[0], t[-1])
    ax.legend(loc="upper right")
    ax.grid(alpha=0.3)
    return fig
