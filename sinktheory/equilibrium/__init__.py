"""Statistical mechanics of the sink: the exact equilibrium law of the container energy.

* :mod:`~sinktheory.equilibrium.area` -- A(e), the area of the basin {V < e} of each well
  shape (closed forms and a quadrature over the basin's edge);
* :mod:`~sinktheory.equilibrium.law` -- the law of E_c on the energy shell from the k-fold
  convolution of the particles' density of states: density, distribution, mean,
  quantiles, tails and Kac's mean return times (a user's well: :func:`well_law`);
* :mod:`~sinktheory.equilibrium.lifetime` -- measured return times, sojourns, entry
  intervals, autocorrelation times and a run-bootstrap KS comparison of simulated runs
  with the law;
* :mod:`~sinktheory.equilibrium.relaxation` -- when the ensemble mean of E_c settles
  within a fraction of the law's mean (crossing of a fitted stretched exponential, with a
  bootstrap interval over runs that does not move with their number);
* :mod:`~sinktheory.equilibrium.prediction` -- the predicted relaxation (a one-variable
  Fokker-Planck model with the law as its stationary state and a measured drift) and
  :func:`settling_periods`, how long an ensemble must run (predicted or measured);
* :mod:`~sinktheory.equilibrium.microcanonical` -- states drawn from the shell's measure
  at a prescribed E_c (the particles on their own microcanonical shell);
* :mod:`~sinktheory.equilibrium.kramers` -- Kramers-Moyal drift and diffusion of E_c from
  short runs started there, and the fluctuation-dissipation check against the law;
* :mod:`~sinktheory.equilibrium.ergodicity` -- the ergodicity map: the runs' distance
  from the law beside lambda_1, point by point (also the sweep kind ``ergodicity``).
"""

from .area import area_quadrature, area_ratio, basin_area, scaled_energy
from .kramers import (
    FluctuationDissipation,
    KramersMoyal,
    check_fluctuation_dissipation,
    measure_kramers_moyal,
)
from .law import EquilibriumLaw, EquilibriumSummary, equilibrium_law, well_law
from .lifetime import LawComparison, compare_with_law, measure_lifetimes
from .microcanonical import shell_states
from .prediction import RelaxationPrediction, Settling, predict_relaxation, settling_periods
from .relaxation import Relaxation, measure_relaxation

__all__ = [
    "EquilibriumLaw",
    "EquilibriumSummary",
    "FluctuationDissipation",
    "KramersMoyal",
    "LawComparison",
    "Relaxation",
    "RelaxationPrediction",
    "Settling",
    "basin_area",
    "area_quadrature",
    "check_fluctuation_dissipation",
    "area_ratio",
    "compare_with_law",
    "equilibrium_law",
    "measure_kramers_moyal",
    "measure_lifetimes",
    "measure_relaxation",
    "predict_relaxation",
    "scaled_energy",
    "settling_periods",
    "shell_states",
    "well_law",
]
