"""Fig. 4: single-particle trajectories in the container's frame (k = 1, n = 10)."""

from __future__ import annotations

import numpy as np

from ..bifurcation import sampled_run
from ..layout import StateLayout
from ..model import RunSettings, Sink, Well
from ..plot.paper import trajectory_panels
from .base import HOLDS, UNDECIDED, Claim, Scene, SceneResult

__all__ = ["BETAS", "FIG4", "SAMPLES", "trajectory"]

BETAS = (-0.5, -0.3, -0.2, -0.14, 0.009, 0.3)
ALPHA, N, MASS, START = 0.5, 10, 0.2, (0.0, 0.01)
#: Trajectory samples per container period (about 40 per wall-to-wall flight).
SAMPLES = 200


def trajectory(beta: float, periods: int) -> np.ndarray:
    """Relative positions (x, y) of the particle over ``periods`` container periods."""
    sink = Sink(Well(ALPHA, beta, N), particles=1, mass=MASS)
    tr = sampled_run(sink, RunSettings(runs=1, periods=periods), START, per_period=SAMPLES)
    return StateLayout(1).relative_positions(tr)[:, 0]  # the one particle's (x, y)


def _fig4(quick: bool) -> SceneResult:
    periods = 20 if quick else 100
    panels, spreads = [], []
    for beta, label in zip(BETAS, "abcdef", strict=True):
        xy = trajectory(beta, periods)
        spreads.append(float(np.abs(xy[:, 1]).max()))
        panels.append((f"{label}) $\\beta$ = {beta:g}", Well(ALPHA, beta, N), xy))
    fig = trajectory_panels(
        panels,
        f"Fig. 4: particle paths, $0 \\leq t/T \\leq {periods}$, $\\alpha$ = 1/2, "
        f"$n$ = {N}, $k$ = 1, $m$ = {MASS}; grey: V = 0.5",
    )
    measured = "; ".join(
        f"beta = {b:g}: max|y| = {s:.3f}" for b, s in zip(BETAS, spreads, strict=True)
    )
    return SceneResult(
        fig,
        {
            "alpha": ALPHA,
            "gamma": 1.0,
            "n": N,
            "k": 1,
            "mass": MASS,
            "beta": list(BETAS),
            "start": "(x, y) = (0, 0.01) at rest; container X(0) = 1 at rest",
            "periods": periods,
        },
        [
            Claim(
                "the particle path is regular or chaotic depending on beta",
                measured + " (regular: max|y| < 0.05; wandering: max|y| > 0.3)",
                HOLDS if min(spreads) < 0.05 and max(spreads) > 0.3 else UNDECIDED,
            )
        ],
        ["The paper does not give m for Figs. 3-5; m = 0.2 as in Fig. 8."],
    )


FIG4 = Scene(4, "particle trajectories for six wall shapes", "single-particle trajectories", _fig4)
