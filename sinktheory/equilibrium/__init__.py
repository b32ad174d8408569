"""Statistical mechanics of the sink: the exact equilibrium law of the container energy.

* :mod:`~sinktheory.equilibrium.area` -- A(e), the area of the basin {V < e} of each well
  shape (closed forms and a quadrature over the basin's edge);
* :mod:`~sinktheory.equilibrium.law` -- the law of E_c on the energy shell from the k-fold
  convolution of the particles' density of states: density, distribution, mean,
  quantiles, tails and Kac's mean return times.
"""

from .area import area, area_quadrature, area_ratio, scaled_energy
from .law import EquilibriumLaw, EquilibriumSummary, equilibrium_law

__all__ = [
    "EquilibriumLaw",
    "EquilibriumSummary",
    "area",
    "area_quadrature",
    "area_ratio",
    "equilibrium_law",
    "scaled_energy",
]
