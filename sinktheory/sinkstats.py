"""Statistics of the energy sink: ensemble means, running averages, sink measures.

All functions take the container energy sampled once per period, E[r, j] = E(jT) for
runs r = 0..R-1 and j = 0..P, and return plain numbers or arrays.

The equipartition estimate
--------------------------
In the microcanonical ensemble, <q dH/dq> = <p dH/dp> = Theta for every canonical pair,
whatever the number of degrees of freedom (Theta = Omega / Omega', the phase volume over
its energy derivative).  In relative coordinates the potential is X^2/2 + sum_j V(x_j, y_j),
so <X^2> = Theta; in the separable coordinates every momentum gives <p^2/m> = Theta.
Hence the container holds <E_c> = <P_X^2/2 + X^2/2> = Theta exactly, the k particles hold
k Theta of kinetic energy, and, when V is homogeneous of degree 2n (beta = 0), Euler's
theorem x V_x + y V_y = 2n V gives <V> = Theta/n per particle.  With E the total energy,

    <E_c> = E / (1 + k (1 + 1/n)),

exact for beta = 0 if the motion is ergodic on the energy shell, and an estimate for
beta != 0 (V is then not homogeneous).  A particle that moves on a line (d = 1
coordinate, the 1-D absorbers) holds half of that: Theta/2 of kinetic and Theta/(2n) of
potential energy, so in general

    <E_c> = E / (1 + k (d/2) (1 + 1/n)),

and rigid walls (n = inf) hold no potential energy.
:func:`equipartition_container_energy` returns it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import validation as v
from .errors import ParameterError
from .runstats import as_runs, ensemble_mean, spread

__all__ = [
    "equipartition_container_energy",
    "first_fall_below",
    "running_mean",
    "sink_measures",
    "SinkMeasures",
]


def running_mean(series, window: int) -> np.ndarray:
    """Trailing running mean: out[j] = mean(series[j : j + window]), length N - window + 1.

    The value out[j] is the average over periods j .. j + window - 1 (plot it against
    j + window - 1 for a causal average, or j + (window - 1)/2 for a centred one).

    Examples
    --------
    >>> running_mean([1.0, 2.0, 3.0, 4.0], 2).tolist()
    [1.5, 2.5, 3.5]
    """
    s = v.real_array("series", series, "a finite 1-D series")
    if s.ndim != 1 or not np.isfinite(s).all():
        raise ParameterError("series", f"array of shape {s.shape}", "a 1-D series")
    window = v.positive_int("window", window, maximum=max(s.size, 1))
    kernel = np.full(window, 1.0 / window)
    return np.convolve(s, kernel, mode="valid")


def first_fall_below(mean_energy, fractions, e0: float) -> dict[float, int | None]:
    """First period j at which <E>_j < f E0, for each fraction f (None if never).

    Examples
    --------
    >>> first_fall_below([0.5, 0.4, 0.2, 0.3, 0.1], [0.9, 0.5, 0.1], 0.5)
    {0.9: 1, 0.5: 2, 0.1: None}
    """
    m = v.real_array("mean_energy", mean_energy, "a finite 1-D series")
    if m.ndim != 1 or not np.isfinite(m).all():
        raise ParameterError("mean_energy", f"array of shape {m.shape}", "a finite 1-D series")
    e0 = v.positive("e0", e0)
    fs = v.real_array("fractions", fractions, "numbers > 0")
    if fs.ndim != 1:
        raise ParameterError("fractions", fractions if isinstance(fractions, str) else fs.shape,
                             "a list of numbers > 0")  # fmt: skip
    out: dict[float, int | None] = {}
    for f in fs.tolist():
        f = v.positive("fractions", f)
        below = np.flatnonzero(m < f * e0)
        out[f] = int(below[0]) if below.size else None
    return out


def equipartition_container_energy(
    total_energy: float, particles: int, n: float, dimension: int = 2
) -> float:
    """E / (1 + k (d/2) (1 + 1/n)): the container's long-time share (see the module
    docstring) for k particles of d = ``dimension`` coordinates (2: the well; 1: a particle
    on a line) in walls of exponent 2n: n > 0 (half the degree of a homogeneous well, such
    as 3/2 for r^3), or math.inf for rigid walls.

    Examples
    --------
    >>> round(equipartition_container_energy(0.5, 5, 6), 6)
    0.073171
    >>> equipartition_container_energy(1.0, 1, 2, 1), equipartition_container_energy(
    ...     1.0, 1, math.inf, 1)
    (0.5714285714285714, 0.6666666666666666)
    >>> equipartition_container_energy(1.0, 1, 1.5)  # r^3: 1 + 1 + 2/3 shares
    0.375
    """
    e = v.positive("total_energy", total_energy)
    k = v.positive_int("particles", particles)
    if dimension not in (1, 2) or isinstance(dimension, bool):
        raise ParameterError("dimension", dimension, "1 (a particle on a line) or 2 (the well)")
    d = int(dimension)
    if n != math.inf:
        n = v.positive("n", n)
    return e / (1 + k * d / 2 * (1 + 1 / n))


@dataclass(frozen=True)
class SinkMeasures:
    """Energy-sink measures of an ensemble (energies in the model's units, times in periods).

    Attributes
    ----------
    first_below : {fraction: first period with <E> < fraction * E0, or None}
    long_time_mean : mean over runs of each run's time average after ``transient``
    long_time_stderr : standard error of that mean across runs (NaN for one run)
    run_spread : standard deviation (ddof = 1) of the runs' time averages (NaN for one run)
    equipartition : E_total / (1 + k (1 + 1/n))
    particle_fraction : 1 - long_time_mean / E_total, the share of energy the particles hold
    transient : first period included in the long-time averages
    """

    first_below: dict[float, int | None]
    long_time_mean: float
    long_time_stderr: float
    run_spread: float
    equipartition: float
    particle_fraction: float
    transient: int


def sink_measures(
    energy_runs,
    *,
    e0: float,
    total_energy: float,
    particles: int,
    n: float,
    transient: int | None = None,
    fractions=(0.8, 0.5, 0.3, 0.2),
) -> SinkMeasures:
    """Summarise how much of the container's energy the particles absorb, and how fast.

    Parameters
    ----------
    energy_runs : array (R, P + 1)
        Container energy E(jT) per run.
    e0, total_energy : float > 0
        Initial container energy and the conserved total energy.
    particles : int
        k.
    n : float > 0
        The wall stiffness, half the well's degree (for the equipartition estimate).
    transient : int, optional
        Periods skipped before time averaging (default: the first half of the run).
    fractions : fractions f of E0 for the first-passage times.
    """
    e = as_runs(energy_runs)
    P = e.shape[1] - 1
    transient = (
        P // 2
        if transient is None
        else v.positive_int("transient", transient, minimum=0, maximum=P)
    )
    mean, _ = ensemble_mean(e)
    per_run = e[:, transient:].mean(axis=1)
    R = per_run.size
    run_spread = spread(per_run)
    total = v.positive("total_energy", total_energy)
    ltm = float(per_run.mean())
    return SinkMeasures(
        first_below=first_fall_below(mean, fractions, e0),
        long_time_mean=ltm,
        long_time_stderr=run_spread / np.sqrt(R),
        run_spread=run_spread,
        equipartition=equipartition_container_energy(total, particles, n),
        particle_fraction=1.0 - ltm / total,
        transient=transient,
    )
