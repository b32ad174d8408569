"""Canonical reference systems: the paper's set-ups that the scenes, the tests and the docs
come back to, defined once.

Examples
--------
>>> FIG8_SINK.particles, FIG8_SINK.mass, FIG8_WELL.n
(5, 0.2, 4)
>>> SYMMETRIC_WELL.shape, SYMMETRIC_WELL.n
('symmetric', 6)
"""

from __future__ import annotations

from .model import Sink, Well

__all__ = ["FIG8_SINK", "FIG8_WELL", "HENON_HEILES", "SYMMETRIC_SINK", "SYMMETRIC_WELL"]

#: Fig. 8's flat well: alpha = 1/2, beta = 0.3 (inward-bulging walls), n = 4.
FIG8_WELL = Well(0.5, 0.3, 4)
#: Fig. 8's five particles of total mass 0.2 in it (the paper's main energy sink).
FIG8_SINK = Sink(FIG8_WELL, particles=5, mass=0.2)
#: Figs. 11 and 12's symmetric well: alpha = 1, beta = 0.1, n = 6.
SYMMETRIC_WELL = Well(1.0, 0.1, 6, shape="symmetric")
#: Fig. 12's five particles of total mass 0.2 in the symmetric well.
SYMMETRIC_SINK = Sink(SYMMETRIC_WELL, particles=5, mass=0.2)
#: The engine's reference system with a closed-form Hamiltonian, H = (px^2 + py^2)/2 +
#: (x^2 + y^2)/2 + x^2 y - y^3/3 (:func:`sinktheory.engine.systems.henon_heiles`).
HENON_HEILES = "henon_heiles"
