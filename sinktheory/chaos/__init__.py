"""Chaos indicators through the symplectic tangent map of the splitting integrator.

Deviation vectors follow the exact derivative of each splitting step (the kick's
derivative uses the generated Hessian, the drift is linear), so the tangent map is the
Jacobian of the discrete flow and is symplectic.  On top of it:

* :func:`chaos` -- the container + particles ensemble, set up like ``simulate``:
  lambda_1, the full spectrum, GALI_k / SALI, MEGNO, the transverse exponent of y = 0;
  :func:`chaos_batch` -- the same for many set-ups (a map's betas) as one ensemble whose
  runs carry their own parameters;
* :func:`indicators` -- the same for any engine system and start states (Henon-Heiles...),
  from :mod:`sinktheory.chaos.general`;
* :class:`ChaosResult` -- per-run values, ensemble mean +- standard error, finite-time
  exponents over windows, ``as_dict`` / ``to_dataset``;
* :func:`monodromy`, :func:`symplectic_defect`, :func:`finite_difference_jacobian` --
  the tangent map itself and its checks;
* :func:`two_orbit_exponent` -- the two-trajectory (Benettin) estimate of lambda_1, an
  independent check that needs no tangent map;
* :mod:`sinktheory.plot.chaos` -- convergence plots (imports matplotlib when called);
* :mod:`sinktheory.chaos.verdicts` -- chaotic or regular from the exponents' means and
  standard errors, and the agreement of a chaos map (:mod:`sinktheory.sweep.chaosmap`,
  the ``chaos`` sweep kind over beta) with the Floquet-stable intervals.

Every run is seeded (positions as in ``simulate``, deviation vectors from the same seed)
and bitwise reproducible for any thread count or engine block size.

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> from sinktheory.chaos import chaos
>>> res = chaos(Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2),
...             RunSettings(runs=2, periods=50, seed=3), spectrum=True, dt=0.01)
>>> res.spectrum.shape, bool(abs(res.pair_sums).max() < 0.05)
((2, 6), True)
"""

from .general import indicators
from .result import ChaosResult, sali_from_gali2
from .sink import chaos, chaos_batch
from .tangent import canonical, finite_difference_jacobian, monodromy, symplectic_defect
from .twoorbit import two_orbit_exponent
from .vectors import random_vectors

__all__ = [
    "ChaosResult",
    "canonical",
    "chaos",
    "chaos_batch",
    "finite_difference_jacobian",
    "indicators",
    "monodromy",
    "random_vectors",
    "sali_from_gali2",
    "symplectic_defect",
    "two_orbit_exponent",
]


from .._verbs import make_callable as _make_callable  # noqa: E402 (module complete here)

_make_callable(__name__, "chaos")
