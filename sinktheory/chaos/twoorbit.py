"""The two-trajectory estimate of the maximal Lyapunov exponent (Benettin et al. 1976).

A shadow orbit starts at distance d0 from each reference orbit; at every segment end the
distance d is measured (Euclidean, engine coordinates (q, v)), ln(d / d0) accumulated,
and the shadow put back at distance d0 along the current separation.  It uses only the
flow map, no tangent vectors, so it checks the tangent-map exponent independently; it is
valid while d0 times the growth over one segment stays small (linear regime) and
d0 / eps is large (round-off): d0 = 1e-9 and growth below ~1e4 per segment give ~1e-5.

Examples
--------
>>> import numpy as np
>>> q, v = np.array([[0.0], [-0.25]]), np.array([[0.42081], [0.0]])
>>> logs = two_orbit_exponent("henon_heiles", q, v, [], dt=0.05, steps=20, segments=50)
>>> logs.shape
(1, 51)
"""

from __future__ import annotations

import numpy as np

from .. import validation as val
from ..errors import NumericalError, ParameterError
from ..glossary import renamed
from ..integrators import DEFAULT_SCHEME, get_scheme
from .general import check_params, check_run
from .vectors import random_vectors

__all__ = ["D0_RANGE", "two_orbit_exponent"]

#: Allowed initial separations d0: from 1e-13 times the state's largest entry (above that
#: the shadow's difference carries at least ~1000 ulps) up to 1e-3 (still linear).
D0_RANGE = (1e-13, 1e-3)


@renamed(method="scheme")
def two_orbit_exponent(
    system: str,
    q,
    v,
    params,
    *,
    dt: float,
    steps: int,
    segments: int,
    d0: float = 1e-9,
    direction=None,
    seed: int = 0,
    scheme: str = DEFAULT_SCHEME,
) -> np.ndarray:
    """Accumulated ln(d / d0) of shadow orbits, (R, segments + 1); divide by t for lambda_1.

    Parameters
    ----------
    system, q, v, params, dt, steps, segments
        As for :func:`~sinktheory.chaos.general.indicators`.
    d0 : float
        Separation kept between the orbits (renormalised at every segment end), in
        :data:`D0_RANGE` (the lower end times the state's largest entry).
    direction : (dq, dv) arrays (D, 1, R), optional
        Initial separation directions; default: the first vector of
        :func:`~sinktheory.chaos.vectors.random_vectors` (the one ``indicators`` uses for
        lambda_1 with the same seed).
    """
    system, q, v, dt, steps, segments = check_run(system, q, v, dt, steps, segments)
    params = check_params(system, params)
    d0 = val.positive("d0", d0)
    scale = max(1.0, float(np.max(np.abs(np.concatenate([q, v]))))) if q.size else 1.0
    if not D0_RANGE[0] * scale <= d0 <= D0_RANGE[1]:
        raise ParameterError(
            "d0", d0, f"in [{D0_RANGE[0] * scale:.3g}, {D0_RANGE[1]:g}]",
            why="a smaller separation drowns in the state's round-off (or vanishes), a "
            "larger one leaves the linear regime",
        )  # fmt: skip
    D, R = q.shape
    if direction is None:
        dq, dv = random_vectors(D, 1, R, seed)
    else:
        allowed = f"(dq, dv) of shape ({D}, 1, {R})"
        try:  # a pair (dq, dv); text, numbers and other lengths are refused
            pair = None if isinstance(direction, str) else list(direction)
        except TypeError:
            pair = None
        if pair is None or len(pair) != 2:
            shown = direction if isinstance(direction, str | int | float) else type(direction)
            raise ParameterError("direction", getattr(shown, "__name__", shown), allowed)
        dq, dv = (val.real_array("direction", a, allowed) for a in pair)
        if dq.shape != (D, 1, R) or dv.shape != (D, 1, R):
            raise ParameterError("direction", f"arrays of shapes {dq.shape}, {dv.shape}",
                                 allowed)  # fmt: skip
    u = np.concatenate([dq[:, 0], dv[:, 0]])
    norms = np.sqrt((u**2).sum(0))
    if not np.all(np.isfinite(norms) & (norms > 0)):
        r = int(np.flatnonzero(~(np.isfinite(norms) & (norms > 0)))[0])
        raise ParameterError("direction", f"a vector of length {float(norms[r])!r} for run {r}",
                             "finite non-zero vectors, one per run")  # fmt: skip
    u = u / norms
    z = np.concatenate([q, v])
    Z = np.concatenate([z, z + d0 * u], axis=1)  # reference runs, then shadow runs
    from ..engine.core import Ensemble  # numba loads with the first run

    ens = Ensemble(system, Z[:D].copy(), Z[D:].copy(), params)
    ens.h0 = np.concatenate([ens.h0[:R], ens.h0[:R]])  # audit both against the reference
    scheme = get_scheme(scheme)
    logs = np.zeros((R, segments + 1))
    for s in range(segments):
        ens.run(scheme, dt=dt, steps=steps, segments=1, record=())
        diff = np.concatenate([ens.q[:, R:] - ens.q[:, :R], ens.v[:, R:] - ens.v[:, :R]])
        d = np.sqrt((diff**2).sum(0))
        if not np.all(d > 0) or not np.all(np.isfinite(d)):
            r = int(np.flatnonzero(~((d > 0) & np.isfinite(d)))[0])
            raise NumericalError(
                f"run {r}, segment {s + 1}: the shadow orbit's distance became {d[r]!r}; "
                "no exponent can be measured (try another d0 or a shorter segment)"
            )
        logs[:, s + 1] = logs[:, s] + np.log(d / d0)
        shadow = np.concatenate([ens.q[:, :R], ens.v[:, :R]]) + (d0 / d) * diff
        ens.q[:, R:] = shadow[:D]
        ens.v[:, R:] = shadow[D:]
    return logs
