"""Figs. 3 and 11: bifurcation diagrams over beta with the Floquet-unstable intervals, and
beside each the chaos map lambda_1(beta) that decides regular or irregular.

Each panel needs single-particle sections (:mod:`sinktheory.bifurcation`), the maximal
Lyapunov exponent and the transverse exponent of y = 0 on the same betas
(:mod:`sinktheory.sweep.chaosmap`), both computed through the sweep layer, and the stability
scan of the fixed-container normal mode (:mod:`sinktheory.floquet`).  A beta is chaotic
when the ensemble's lambda_1 minus two standard errors exceeds 3 ln t / t (a regular
orbit's finite-time exponent decays like ln t / t); the report gives how often (a) the
Floquet theory and (b) the transverse exponent agree with that verdict.
"""

from __future__ import annotations

import numpy as np

from ..chaos.verdicts import THRESHOLD_FACTOR, agreement, verdicts
from ..floquet import model_problem, scan
from ..model import confining_betas
from ..plot.paper import orbit_figure, orbit_panel
from ..sweep import run_sweep
from ..sweep.chaosmap import beta_grid, chaos_map
from ..sweep.views import bifurcation_diagram
from .base import FAILS, HOLDS, UNDECIDED, Claim, Scene, SceneResult

__all__ = ["FIG11", "FIG3"]

#: Agreement between Floquet stability and the chaos map needed for "holds";
#: below LOW the claim "does not hold".
AGREE, LOW = 0.8, 0.6


def _fidelity(quick: bool) -> dict:
    """Sections (count, transient periods) and chaos map (runs x periods) per beta."""
    return (
        dict(count=40, transient=40, points=24, runs=4, periods=60)
        if quick
        else dict(count=150, transient=150, points=161, runs=6, periods=200)
    )


def _unstable(stable: list[tuple[float, float]], lo: float, hi: float):
    cuts, out, a = sorted(stable), [], lo
    for s, e in cuts:
        if s > a:
            out.append((a, s))
        a = max(a, e)
    if a < hi:
        out.append((a, hi))
    return out


def _panel(alpha, n, shape, ranges, quick, ax, ax_map):
    """Sections and the chaos map over the valid beta ``ranges`` [(lo, hi), ...] (points
    shared in proportion to length) and the Floquet scan over their whole span, drawn on
    ``ax`` and ``ax_map``."""
    f = _fidelity(quick)
    betas = beta_grid(ranges, f["points"])
    params = {
        "alpha": alpha,
        "beta": [float(b) for b in betas],
        "n": n,
        "shape": shape,
        "transient": f["transient"],
        "count": f["count"],
    }
    diagram = bifurcation_diagram(run_sweep("bifurcation", params, progress=False))
    lo, hi = ranges[0][0], ranges[-1][1]
    floq = scan(model_problem(alpha, n, shape=shape), lo, hi, 400)
    cmap = chaos_map(alpha, n, betas, shape=shape, runs=f["runs"], periods=f["periods"],
                     stop_early=True, transient=f["periods"] // 10)  # fmt: skip
    gaps = [(a, b) for (_, a), (b, _) in zip(ranges[:-1], ranges[1:], strict=True)]
    title = f"{shape}, n = {n}: {f['runs']} runs x {f['periods']} periods per beta"
    unstable = _unstable(floq.stable_intervals, lo, hi)
    orbit_panel(
        ax, ax_map, diagram, unstable, gaps, floq.resonances, cmap, floq.stable_intervals, title
    )
    return diagram, floq, cmap


def _claims(panels, label_of) -> list[Claim]:
    claims = []
    for (diagram, floq, cmap), label in zip(panels, label_of, strict=True):
        v = verdicts(cmap)
        chaotic = v["chaotic"]
        stable = floq.chart.problem.evaluate(diagram.beta).stable
        agree = agreement(cmap, stable)
        early = int((cmap.lambda1_periods.values < cmap.attrs["periods"]).sum())
        basis = (
            f"chaotic where the mean lambda_1 of {cmap.attrs['runs']} runs minus 2 standard "
            f"errors exceeds {THRESHOLD_FACTOR:g} ln t / t = {v['threshold']:.3g} "
            f"(t = {cmap.attrs['periods']} T; lambda_1 is the growth rate after a transient "
            f"of {cmap.attrs['transient']} T; {early} betas settled chaotic at an earlier "
            "look by 4 or 3 standard errors, sinktheory.chaos.staged)"
        )
        neg = bool(np.any(chaotic[diagram.beta < 0]))
        pos = bool(np.any(chaotic[diagram.beta > 0]))
        claims.append(
            Claim(
                f"{label}: irregular motion in both negative and positive beta intervals",
                f"{basis}: {int(chaotic.sum())} of {chaotic.size} betas chaotic; at beta < 0: "
                f"{neg}, beta > 0: {pos}",
                HOLDS if neg and pos else FAILS,
            )
        )
        stable_txt = ", ".join(f"({a:.4f}, {b:.4f})" for a, b in floq.stable_intervals)
        share = agree["floquet"]
        verdict = HOLDS if share >= AGREE else (FAILS if share < LOW else UNDECIDED)
        transverse = (
            f"; the transverse exponent of y = 0 (coupled container) agrees with the chaos "
            f"map at {100 * agree['transverse']:.0f}%"
            if "transverse" in agree
            else ""
        )
        claims.append(
            Claim(
                f"{label}: Floquet stability of y = 0 matches the regular beta intervals",
                f"Floquet-stable beta: {stable_txt or 'none'}; stable where the chaos map is "
                f"regular and unstable where chaotic at {100 * share:.0f}% of "
                f"{chaotic.size} betas (holds >= {100 * AGREE:.0f}%, fails < {100 * LOW:.0f}%)"
                + transverse,
                verdict,
            )
        )
    return claims


def _fig3(quick: bool) -> SceneResult:
    fig, axes = orbit_figure(
        2,
        (13, 7.5),
        "Fig. 3: flat well, $\\alpha$ = 1/2, $\\gamma$ = 1, $k$ = 1, $m$ = 0.2; "
        "dotted: $\\phi_T = -1$",
    )
    panels = [
        _panel(0.5, n, "flat", [(-0.7, 0.45)], quick, ax, ax_map)
        for n, (ax, ax_map) in zip((2, 10), axes, strict=True)
    ]
    f = _fidelity(quick)
    res = panels[1][1].resonances
    return SceneResult(
        fig,
        {
            "shape": "flat",
            "alpha": 0.5,
            "gamma": 1.0,
            "n": [2, 10],
            "mass": 0.2,
            "beta": f"{f['points']} values in [-0.7, 0.45]",
            "transient": f["transient"],
            "section periods": f["count"],
            "chaos map": f"{f['runs']} runs x {f['periods']} periods per beta",
            "start": "(x, y) = (0, 0.01) at rest, X(0) = 1",
        },
        _claims(panels, ("n = 2", "n = 10"))
        + [
            Claim(
                "narrow instability windows inside stability intervals come from phi = -1 "
                "touchings",
                "phi_T = -1 (rotation number 1/2) inside stable intervals at beta = "
                + (", ".join(f"{r:.4f}" for r in res) or "none"),
                UNDECIDED,
            )
        ],
        [
            "The caption gives n = 10 for panel (b); the text calls it n = 5. We use n = 10, "
            "as in Figs. 4-5, which the text calls the stiffer walls.",
            "The paper does not give the particle mass for Figs. 3-5; we use m = 0.2 (Fig. 8).",
        ],
    )


def _fig11(quick: bool) -> SceneResult:
    fig, ((ax, ax_map),) = orbit_figure(
        1,
        (13, 4.2),
        "Fig. 11: symmetric well, $\\alpha$ = 1, $\\gamma$ = 1, $n$ = 6, $k$ = 1",
    )
    valid = confining_betas(1.0, 6, 0.5, shape="symmetric")
    ranges = [(a + 0.01, b - 0.01) for a, b in valid]  # a margin from the edges of validity
    panel = _panel(1.0, 6, "symmetric", ranges, quick, ax, ax_map)
    f = _fidelity(quick)
    return SceneResult(
        fig,
        {
            "shape": "symmetric",
            "alpha": 1.0,
            "gamma": 1.0,
            "n": 6,
            "mass": 0.2,
            "beta": f"{f['points']} values in "
            + ", ".join(f"[{a:.4f}, {b:.4f}]" for a, b in ranges),
            "transient": f["transient"],
            "section periods": f["count"],
            "chaos map": f"{f['runs']} runs x {f['periods']} periods per beta",
        },
        _claims([panel], ("symmetric, n = 6",))
        + [
            Claim(
                "beta = 1.0 belongs to the unstable domain",
                "with alpha = 1, beta = 1 makes D(0) = alpha - beta = 0: the well is singular at "
                "its centre; a particle with E = 0.5 is held only for beta in "
                + ", ".join(f"({a:.4f}, {b:.4f})" for a, b in valid)
                + " (outside, it escapes over the corner saddle or D vanishes within reach)",
                UNDECIDED,
            )
        ],
        [
            "Sections only where the well holds E = 0.5 (less a 0.01 margin at each edge); "
            "the Floquet scan covers the whole span."
        ],
    )


FIG3 = Scene(
    3,
    "bifurcation diagrams, flat well",
    "single-particle sweeps and chaos maps over beta + Floquet scan",
    _fig3,
)
FIG11 = Scene(
    11,
    "bifurcation diagram, symmetric well",
    "single-particle sweep and chaos map over beta + Floquet scan",
    _fig11,
)
