"""Nonlinear normal modes of the container-particle system (issue 15).

Periodic orbits of the full Hamiltonian system by shooting on the compiled engine's exact
tangent map (:mod:`.shooting`), pseudo-arclength continuation in energy or a well
parameter with Floquet multipliers and bifurcation detection (:mod:`.continuation`,
:mod:`.stability`), and frequency-energy plots (:mod:`sinktheory.plot.nnm`, matplotlib
imported there only).
"""

from .shooting import Orbit, ShootingError, shoot
from .stability import Floquet, floquet
from .system import FlowSystem

__all__ = ["FlowSystem", "Floquet", "Orbit", "ShootingError", "floquet", "shoot"]
