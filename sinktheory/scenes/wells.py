"""Figs. 2 and 10: shapes of the potential well (level lines only)."""

from __future__ import annotations

from .._generated import oscillator as _osc
from ..glossary import renamed
from ..model import Well
from ..plot.paper import well_panels
from .base import FAILS, HOLDS, Claim, Scene, SceneResult

__all__ = ["ENERGY", "FIG10", "FIG2"]

#: The container's initial energy in the paper's runs; the outer level line drawn.
ENERGY = 0.5


@renamed(energy="particle_energy")
def level_line_curvature(well: Well, particle_energy: float, h: float = 1e-3) -> float:
    """Curvature of the level line V = ``particle_energy`` at y = 0 (x > 0), by central
    differences.

    The level line x(y) is found by bisection on V(x, y) = particle_energy at y = 0, +-h; an
    independent, purely numerical view of the wall's bending at finite n.
    """

    def x_of(y: float) -> float:
        lo, hi = 0.0, 10.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if float(well.potential(mid, y)) < particle_energy:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)

    x0, xp, xm = x_of(0.0), x_of(h), x_of(-h)
    d1 = (xp - xm) / (2 * h)
    d2 = (xp - 2 * x0 + xm) / (h * h)
    return d2 / (1 + d1 * d1) ** 1.5


def _curvature_claim(wells: list[tuple[str, Well]]) -> Claim:
    """beta is half the wall curvature at y = 0 in the rigid limit, eq. (kappa)."""
    parts, ok = [], True
    for label, well in wells:
        c = _osc.axis_reach_factor(ENERGY, well.gamma, well.n)
        # the level line V = E is x = c D(y) (1 - (y/c)^2n)^(1/2n): near y = 0 its
        # curvature is c (2 beta) up to O(y^2n-2) terms, so divide by c
        k = level_line_curvature(well, ENERGY) / c
        parts.append(f"{label}: {k:.4f} vs 2beta = {2 * well.beta:.4f}")
        ok &= abs(k - 2 * well.beta) <= 1e-3 + 1e-3 * abs(well.beta)
    return Claim(
        "beta is half the curvature of the wall at y = 0 (eq. kappa, rigid limit)",
        "level-line curvature at y = 0 / c: " + "; ".join(parts),
        HOLDS if ok else FAILS,
        "beta is the wall's curvature parameter exactly as the paper defines it: the "
        "measured level lines bend by 2 beta at y = 0 to 1e-3.",
    )


def _fig2(quick: bool) -> SceneResult:
    wells = [
        ("a)", Well(0.5, 0.3, 2)),
        ("b)", Well(0.5, 0.3, 10)),
        ("c)", Well(0.5, 0.0, 2)),
        ("d)", Well(0.5, -0.3, 2)),
    ]
    title = "Fig. 2: flat wells, $\\alpha$ = 1/2, $\\gamma$ = 1; level lines up to E = 0.5"
    fig = well_panels(wells, 2, ENERGY, title)
    return SceneResult(
        fig,
        {
            "shape": "flat",
            "alpha": 0.5,
            "gamma": 1.0,
            "(n, beta)": [(2, 0.3), (10, 0.3), (2, 0.0), (2, -0.3)],
        },
        [_curvature_claim(wells)],
    )


def _fig10(quick: bool) -> SceneResult:
    wells = [
        ("a)", Well(1.0, -0.1, 6, shape="symmetric")),
        ("b)", Well(1.0, 0.1, 6, shape="symmetric")),
    ]
    title = "Fig. 10: symmetric wells, $\\alpha$ = 1, $\\gamma$ = 1, $n$ = 6"
    fig = well_panels(wells, 2, ENERGY, title)
    sym = all(float(w.potential(0.3, -0.7)) == float(w.potential(-0.7, 0.3)) for _, w in wells)
    return SceneResult(
        fig,
        {"shape": "symmetric", "alpha": 1.0, "gamma": 1.0, "n": 6, "beta": [-0.1, 0.1]},
        [
            Claim(
                "the symmetric well is invariant under x <-> y",
                "V(0.3, -0.7) == V(-0.7, 0.3) exactly for both wells: " + str(sym),
                HOLDS if sym else FAILS,
                "The symmetric well is built symmetric in x and y, and the computed potential "
                "is, exactly.",
            ),
            Claim(
                "beta = -0.1 gives a stadium-like well, beta = 0.1 convex scatterers",
                "rigid-wall curvature at y = 0: "
                + ", ".join(f"{w.curvature_at_centre:+.2f}" for _, w in wells),
                HOLDS
                if wells[0][1].curvature_at_centre < 0 < wells[1][1].curvature_at_centre
                else FAILS,
                "The sign of beta sets the sign of the wall's curvature: negative beta "
                "focuses (stadium-like), positive beta disperses.",
            ),
        ],
    )


FIG2 = Scene(2, "shapes of the flat well", "potential contours", _fig2)
FIG10 = Scene(10, "shapes of the symmetric well", "potential contours", _fig10)
