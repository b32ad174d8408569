"""Chaos maps: lambda_1(beta) through the sweep layer, against the Floquet theory of y = 0.

A chaos map is a ``chaos`` sweep (:mod:`sinktheory.sweep.kinds`) over beta: at each beta
an ensemble of R runs started as in ``simulate`` (container at X = sqrt(2 E0), particles
at rest in the box around the centre), lambda_1 per run from the tangent map and the
transverse exponent of y = 0, with mean and standard error.

Verdict and its statistical basis.  On a regular orbit deviations grow at most linearly
(shear), so the finite-time exponent decays like ln t / t (tests/test_chaos.py: the
integrable case gives lambda_1 t / ln t ~ 1).  A beta is called *chaotic* when the mean
lambda_1 exceeds that envelope with margin, by two standard errors:

    mean - 2 s.e. > THRESHOLD_FACTOR ln(t) / t,    t = P T,

and *regular* otherwise.  The Floquet theory predicts regular motion where y = 0 is stable
(with the container fixed); the agreement is the share of betas where the two verdicts
coincide.  The transverse exponent's verdict (the same test on it) measures how much of the
chaos comes from the instability of y = 0 itself.

Examples
--------
>>> import numpy as np
>>> ds = chaos_map(0.5, 4, [0.1, 0.3], runs=2, periods=10, dt=0.01, workers=1)
>>> v = verdicts(ds)
>>> v["chaotic"].shape, float(v["threshold"]) > 0
((2,), True)
"""

from __future__ import annotations

import math

import numpy as np

from .. import validation as v
from ..errors import ParameterError

#: The finite-time exponent of a regular orbit is ~ ln t / t; a chaotic verdict needs the
#: mean minus two standard errors above this factor times ln t / t.
THRESHOLD_FACTOR = 3.0


def chaos_map(
    alpha: float,
    n: int,
    betas,
    *,
    shape: str = "flat",
    particles: int = 1,
    mass: float = 0.2,
    energy: float = 0.5,
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
    from ..sweep import run_sweep

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
        "energy": energy,
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
    from ..sweep.grid import MAX_POINTS

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


def threshold(periods: int) -> float:
    """THRESHOLD_FACTOR ln(t) / t at t = periods x 2 pi (per unit time)."""
    t = periods * 2.0 * math.pi
    return THRESHOLD_FACTOR * math.log(t) / t


def chaotic(mean, se, periods: int):
    """True where an exponent is chaotic: its mean less two standard errors above
    :func:`threshold` (arrays or numbers)."""
    return np.asarray(mean) - 2 * np.asarray(se) > threshold(periods)


def verdicts(ds) -> dict:
    """Chaotic / regular per beta from lambda_1 and from the transverse exponent."""
    periods = int(ds.attrs["periods"])
    out = {"threshold": threshold(periods),
           "chaotic": chaotic(ds.lambda1.values, ds.lambda1_se.values, periods)}  # fmt: skip
    if "transverse" in ds and np.isfinite(ds.transverse.values).all():
        out["transverse_chaotic"] = chaotic(ds.transverse.values, ds.transverse_se.values, periods)
    return out


def agreement(ds, stable: np.ndarray) -> dict:
    """Shares of betas where the chaos map agrees with (a) Floquet stability of y = 0
    (stable <-> regular) and (b) the transverse exponent's verdict."""
    v = verdicts(ds)
    out = {
        "threshold": v["threshold"],
        "betas": int(ds.beta.size),
        "chaotic": int(v["chaotic"].sum()),
        "floquet": float(np.mean(np.asarray(stable) == ~v["chaotic"])),
    }
    if "transverse_chaotic" in v:
        out["transverse"] = float(np.mean(v["transverse_chaotic"] == v["chaotic"]))
    return out


#: The panels of Figs. 3 and 11: (label, alpha, n, shape).
PANELS = {
    3: [("flat, n = 2", 0.5, 2, "flat"), ("flat, n = 10", 0.5, 10, "flat")],
    11: [("symmetric, n = 6", 1.0, 6, "symmetric")],
}


def figure_panels(figure: int, *, points: int = 24, runs: int = 4, periods: int = 100,
                  workers: int | None = None, progress: bool = False) -> list[dict]:  # fmt: skip
    """Chaos maps for the panels of Fig. 3 or Fig. 11 with the Floquet-stable intervals.

    Returns one dict per panel: ``label``, ``map`` (the chaos-map Dataset),
    ``stable_intervals`` (Floquet-stable beta intervals of y = 0) and ``agreement``
    (:func:`agreement`).  beta covers the range the scene uses: [-0.7, 0.45] for Fig. 3,
    the betas where the symmetric well holds E = 0.5 (less 0.01 at each edge) for Fig. 11.
    :func:`sinktheory.plot.chaos.figure_maps` draws them.
    """
    from ..floquet import model_problem, scan
    from ..model import confining_betas

    if figure not in PANELS:
        raise ParameterError("figure", figure, "3 or 11")
    panels = []
    for label, alpha, n, shape in PANELS[figure]:
        if figure == 11:
            ranges = [(a + 0.01, b - 0.01) for a, b in confining_betas(alpha, n, 0.5, shape=shape)]
        else:
            ranges = [(-0.7, 0.45)]
        betas = beta_grid(ranges, points)
        ds = chaos_map(alpha, n, betas, shape=shape, runs=runs, periods=periods,
                       workers=workers, progress=progress)  # fmt: skip
        problem = model_problem(alpha, n, shape=shape)
        floq = scan(problem, ranges[0][0], ranges[-1][1], 400)
        panels.append(
            {
                "label": label,
                "map": ds,
                "stable_intervals": floq.stable_intervals,
                "agreement": agreement(ds, problem.evaluate(betas).stable),
            }
        )
    return panels
