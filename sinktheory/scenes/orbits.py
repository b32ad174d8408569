"""Figs. 3 and 11: bifurcation diagrams over beta with the Floquet-unstable intervals.

Each panel needs single-particle sections (:mod:`sinktheory.bifurcation`, computed in
parallel through the sweep layer :mod:`sinktheory.sweep`) and the stability scan of the
normal mode (:mod:`sinktheory.floquet`); nothing else.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ..bifurcation import BifurcationDiagram, plot_bifurcation
from ..floquet import model_problem, scan
from ..model import confining_betas
from ..sweep import run_sweep
from ..sweep.views import bifurcation_diagram
from .base import FAILS, HOLDS, UNDECIDED, Claim, Scene, SceneResult

#: A section whose y spans more than this (10x the initial offset 0.01) is "irregular".
SPREAD = 0.1
#: Agreement between Floquet stability and regular sections needed for "holds";
#: below LOW the claim "does not hold".
AGREE, LOW = 0.8, 0.6


def _fidelity(quick: bool) -> dict:
    return (
        dict(count=40, transient=40, points=24)
        if quick
        else dict(count=150, transient=150, points=161)
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


def _panel(alpha, n, shape, ranges, quick, ax):
    """Sections over the valid beta ``ranges`` [(lo, hi), ...] (points shared in
    proportion to length) and the Floquet scan over their whole span."""
    f = _fidelity(quick)
    total = sum(b - a for a, b in ranges)
    betas = np.concatenate(
        [np.linspace(a, b, max(2, round(f["points"] * (b - a) / total))) for a, b in ranges]
    )
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
    unstable = _unstable(floq.stable_intervals, lo, hi)
    plot_bifurcation(diagram, unstable, ax=ax)
    for (_, a), (b, _) in zip(ranges[:-1], ranges[1:], strict=True):
        ax.axvspan(a, b, color="0.85", hatch="//", lw=0)
        ax.text(
            (a + b) / 2,
            0.5,
            "well does not\nhold E = 0.5",
            transform=ax.get_xaxis_transform(),
            ha="center",
            va="center",
            fontsize=8,
        )
    for r in floq.resonances:
        ax.axvline(r, color="tab:blue", lw=0.8, ls=":")
    return diagram, floq


def _agreement(diagram: BifurcationDiagram, floq) -> tuple[float, np.ndarray]:
    regular = np.ptp(diagram.section, axis=1) <= SPREAD
    stable = floq.chart.problem.evaluate(diagram.beta).stable
    return float(np.mean(regular == stable)), regular


def _claims(panels, label_of) -> list[Claim]:
    claims = []
    for (diagram, floq), label in zip(panels, label_of, strict=True):
        agree, regular = _agreement(diagram, floq)
        irregular_neg = bool(np.any(~regular[diagram.beta < 0]))
        irregular_pos = bool(np.any(~regular[diagram.beta > 0]))
        claims.append(
            Claim(
                f"{label}: irregular motion in both negative and positive beta intervals",
                f"irregular sections (y spread > {SPREAD}) at beta < 0: {irregular_neg}, "
                f"beta > 0: {irregular_pos}",
                HOLDS if irregular_neg and irregular_pos else FAILS,
            )
        )
        stable_txt = ", ".join(f"({a:.4f}, {b:.4f})" for a, b in floq.stable_intervals)
        verdict = HOLDS if agree >= AGREE else (FAILS if agree < LOW else UNDECIDED)
        claims.append(
            Claim(
                f"{label}: Floquet stability of y = 0 matches the regular beta intervals",
                f"Floquet-stable beta: {stable_txt or 'none'}; sections regular where stable "
                f"and irregular where unstable at {100 * agree:.0f}% of {diagram.beta.size} "
                f"beta values (holds >= {100 * AGREE:.0f}%, fails < {100 * LOW:.0f}%)",
                verdict,
            )
        )
    return claims


def _fig3(quick: bool) -> SceneResult:
    fig = Figure(figsize=(7.5, 7.5), layout="constrained")
    axes = fig.subplots(2, 1)
    panels = [
        _panel(0.5, n, "flat", [(-0.7, 0.45)], quick, ax)
        for n, ax in zip((2, 10), axes, strict=True)
    ]
    fig.suptitle(
        "Fig. 3: flat well, $\\alpha$ = 1/2, $\\gamma$ = 1, $k$ = 1, $m$ = 0.2; "
        "dotted: $\\phi_T = -1$"
    )
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
    fig = Figure(figsize=(7.5, 4.2), layout="constrained")
    ax = fig.subplots()
    valid = confining_betas(1.0, 6, 0.5, shape="symmetric")
    ranges = [(a + 0.01, b - 0.01) for a, b in valid]  # a margin from the edges of validity
    panel = _panel(1.0, 6, "symmetric", ranges, quick, ax)
    fig.suptitle("Fig. 11: symmetric well, $\\alpha$ = 1, $\\gamma$ = 1, $n$ = 6, $k$ = 1")
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
    3, "bifurcation diagrams, flat well", "single-particle sweeps over beta + Floquet scan", _fig3
)
FIG11 = Scene(
    11,
    "bifurcation diagram, symmetric well",
    "single-particle sweep over beta + Floquet scan",
    _fig11,
)
