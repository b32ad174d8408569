"""Chaos maps: lambda_1(beta) as a sweep, to set beside the Floquet theory of y = 0.

A chaos map is a ``chaos`` sweep (:mod:`sinktheory.sweep.kinds`) over beta: at each beta
an ensemble of R runs started as in ``simulate`` (container at X = sqrt(2 E0), particles
at rest in the box around the centre), lambda_1 per run from the tangent map and the
transverse exponent of y = 0, with mean and standard error.  The verdict per beta and the
agreement with Floquet stability are :mod:`sinktheory.chaos.verdicts`.

Examples
--------
>>> from sinktheory.chaos.verdicts import verdicts
>>> ds = chaos_map(0.5, 4, [0.1, 0.3], runs=2, periods=10, dt=0.01, workers=1)
>>> v = verdicts(ds)
>>> v["chaotic"].shape, float(v["threshold"]) > 0
((2,), True)
"""

from __future__ import annotations

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..glossary import renamed
from .grid import MAX_POINTS

__all__ = ["beta_grid", "chaos_map"]


@renamed(energy="container_energy")
def chaos_map(
    alpha: float,
    n: int,
    betas,
    *,
    shape: str = "flat",
    particles: int = 1,
    mass: float = 0.2,
    container_energy: float = 0.5,
    runs: int = 8,
    periods: int = 300,
    transverse: bool = True,
    dt: float | None = None,
    seed: int = 0,
    workers: int | None = None,
    store=None,
    progress: bool = False,
    stop_early: bool = False,
    transient: int = 0,
):
    """lambda_1 (and the transverse exponent) over ``betas``: an xarray Dataset with
    dimension beta (see :data:`sinktheory.sweep.kinds.KINDS` ``["chaos"]``); with
    ``stop_early`` a beta's runs stop as soon as they are settled chaotic, and the growth
    over the first ``transient`` periods is left out of the exponents
    (:mod:`sinktheory.chaos.staged`)."""
    from .runner import run_sweep

    grid = v.real_array("betas", betas, "a sequence of betas")
    if grid.ndim != 1 or grid.size == 0:
        raise ParameterError("betas", f"an array of shape {grid.shape}", "a sequence of betas")
    params = {
        "alpha": alpha,
        "beta": grid.tolist(),
        "n": n,
        "shape": shape,
        "particles": particles,
        "mass": mass,
        "container_energy": container_energy,
        "runs": runs,
        "periods": periods,
        "transverse": int(v.flag("transverse", transverse)),
        "dt": dt,
        "stop_early": int(bool(stop_early)),
        "transient": transient,
    }
    return run_sweep("chaos", params, seed=seed, workers=workers, store=store, progress=progress)


def beta_grid(ranges, points: int) -> np.ndarray:
    """About ``points`` betas over the intervals ``ranges`` [(lo, hi), ...], shared in
    proportion to their lengths (at least two per interval).

    Examples
    --------
    >>> beta_grid([(0.0, 0.2), (0.4, 0.5)], 6).round(3).tolist()  # 6 x 2/3 and 6 x 1/3
    [0.0, 0.067, 0.133, 0.2, 0.4, 0.5]
    >>> beta_grid([(0.2, 0.0)], 6)
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: ranges = [(0.2, 0.0)] is not allowed: must be \
intervals (lo, hi) of finite numbers with lo < hi
    """
    points = v.positive_int("points", points, minimum=2, maximum=MAX_POINTS)
    bounds = v.real_array("ranges", ranges, "intervals (lo, hi) of finite numbers")
    if bounds.ndim != 2 or bounds.shape[1] != 2 or not bounds.size:
        raise ParameterError("ranges", ranges, "intervals (lo, hi) of finite numbers")
    if not (np.isfinite(bounds).all() and (bounds[:, 0] < bounds[:, 1]).all()):
        raise ParameterError("ranges", ranges, "intervals (lo, hi) of finite numbers with lo < hi")
    ranges = bounds.tolist()
    total = sum(b - a for a, b in ranges)
    return np.concatenate(
        [np.linspace(a, b, max(2, round(points * (b - a) / total))) for a, b in ranges]
    )
