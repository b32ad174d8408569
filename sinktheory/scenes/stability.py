"""Fig. 7: phi(beta) of the normal mode y = 0 (Hill's equation only)."""

from __future__ import annotations

from ..floquet import model_problem, scan
from ..plot.floquet import plot_fig7
from .base import FAILS, HOLDS, Claim, Scene, SceneResult

__all__ = ["FIG7"]

ALPHA, NS, RANGE = 0.5, (2, 10), (-1.0, 0.499)


def _fig7(quick: bool) -> SceneResult:
    count = 200 if quick else 800
    fig = plot_fig7(
        alpha=ALPHA,
        ns=NS,
        beta_range=RANGE,
        count=count,
        title="Fig. 7: $\\phi_{T/2}(\\beta)$ of the normal mode $y$ = 0, $\\alpha$ = 1/2, "
        "$\\gamma$ = 1 (rescaled, $A_0$ = 1)",
    )
    claims, notes = [], []
    for n in NS:
        s = scan(model_problem(ALPHA, n), *RANGE, count)
        stable = ", ".join(f"({a:.10f}, {b:.10f})" for a, b in s.stable_intervals)
        claims.append(
            Claim(
                f"n = {n}: the normal mode is stable on a beta interval and unstable outside it "
                "(both signs of beta can be unstable)",
                f"stable intervals (boundaries by root finding to 1e-12): {stable or 'none'}",
                HOLDS if s.stable_intervals else FAILS,
                f"Exact Floquet theory of the fixed container: stable for beta in {stable}, "
                "unstable beyond on both sides (focusing walls too curved, or dispersing "
                "walls).",
            )
        )
        res = ", ".join(f"{r:.10f}" for r in s.resonances)
        claims.append(
            Claim(
                f"n = {n}: curves phi(beta) touch phi = -1 inside the stability interval",
                f"phi_T = -1 (phi_half = 0) at beta = {res or 'none'}; there phi_T touches -1 "
                "without crossing (phi_T = 2 phi_half^2 - 1 >= -1)",
                HOLDS if s.resonances else FAILS,
                f"The touchings exist (beta = {res}) but only touch: the half-period "
                "symmetry of the coefficient makes phi_T = 2 phi_half^2 - 1, so the linear "
                "equation has no instability window there; whether the full system has "
                "one is Fig. 3's last row.",
            )
        )
    notes.append(
        "phi_half = [y1 + y2']/2 over the half period T_n/2 is drawn (symlog axis), "
        "which separates phi_half > 1 from phi_half < -1; the paper's phi over T_n "
        "is 2 phi_half^2 - 1."
    )
    return SceneResult(
        fig,
        {
            "alpha": ALPHA,
            "gamma": 1.0,
            "n": list(NS),
            "beta range": RANGE,
            "grid": count,
            "amplitude A0": 1.0,
        },
        claims,
        notes,
    )


FIG7 = Scene(7, "Floquet stability of the normal mode", "Hill's equation only", _fig7)
