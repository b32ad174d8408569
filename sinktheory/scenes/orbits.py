"""Figs. 3 and 11: bifurcation diagrams over beta with the Floquet-unstable intervals, and
beside each the chaos map lambda_1(beta) that decides regular or irregular.

Each panel needs single-particle sections (:mod:`sinktheory.bifurcation`), the maximal
Lyapunov exponent and the transverse exponent of y = 0 on the same betas
(:mod:`sinktheory.sweep.chaosmap`), both computed through the sweep layer, and the stability
scan of the fixed-container normal mode (:mod:`sinktheory.floquet`).  A beta is chaotic
when the ensemble's lambda_1 minus two standard errors exceeds 3 ln t / t (a regular
orbit's finite-time exponent decays like ln t / t).  The generic-start chaos map is
judged run by run (:func:`sinktheory.chaos.verdicts.map_calls`, the same envelope for
each run's lambda_1): a beta whose runs split into regular and chaotic ones is reported
as mixed, with its regular fraction, never by the mean of its runs.
"""

from __future__ import annotations

import numpy as np

from ..chaos.verdicts import THRESHOLD_FACTOR, agreement, map_calls
from ..floquet import model_problem, scan
from ..model import confining_betas
from ..plot.paper import orbit_figure, orbit_panel
from ..sweep import run_sweep
from ..sweep.chaosmap import beta_grid, chaos_map
from ..sweep.views import bifurcation_diagram
from .base import BEYOND, FAILS, HOLDS, SIGN_CALL, UNDECIDED, Claim, Scene, SceneResult

__all__ = ["FIG11", "FIG3", "MARGIN"]


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
    return diagram, floq, cmap, _coupled_mode(alpha, n, shape, ranges, quick)


#: Betas at which the coupled normal mode's Floquet multipliers are computed, and the beta
#: its branch starts from (inside every panel's range).
MODE_POINTS, MODE_START = 24, -0.2


def _coupled_mode(alpha, n, shape, ranges, quick):
    """The transverse Floquet multipliers of the coupled normal mode at the chaos map's
    energy (:func:`sinktheory.nnm.agreement.transverse_chart`) on MODE_POINTS betas of the
    range holding MODE_START, started from the particle's mode shot at E = 0.5 (which the
    container's mode continued up in energy becomes, :mod:`sinktheory.nnm.agreement`):
    (chart, start orbit), or a sentence saying why there is none."""
    if quick:
        return "the coupled normal mode's Floquet multipliers are not computed in a --quick preview"
    lo, hi = next((a, b) for a, b in ranges if a < MODE_START < b)
    return _mode_chart(alpha, n, shape, MODE_START, np.linspace(lo, hi, MODE_POINTS))


def _mode_chart(alpha, n, shape, beta, betas):
    """The coupled normal mode's transverse chart on ``betas`` (total energy 0.5, m = 0.2),
    its branch started from the particle's mode shot at ``beta``: (chart, the start
    orbit), or a sentence saying why there is none."""
    from ..errors import NumericalError
    from ..model import Sink, Well
    from ..nnm.agreement import transverse_chart
    from ..nnm.modes import mode_guess, sink_flow
    from ..nnm.shooting import shoot

    sink = Sink(Well(alpha, beta, n, shape=shape), particles=1, mass=0.2)
    try:
        z0, T = mode_guess(sink, "particle", 0.5)
        start = shoot(sink_flow(sink), z0, T, steps=400, total_energy=0.5, subspace="plane")
        return transverse_chart(sink, 0.5, betas, start=start), start
    except NumericalError as e:  # ShootingError: the branch cannot be followed
        return f"the coupled normal mode could not be followed at E = 0.5 ({e})"


#: Margin (standard errors) of a per-beta stability call on either side of the threshold.
MARGIN = 2.0


def false_call(runs: int) -> float:
    """Chance that a call at MARGIN standard errors from ``runs`` runs is wrong when the
    truth lies on the threshold: Student's tail with runs - 1 degrees of freedom.

    Examples
    --------
    >>> round(false_call(6), 3), round(false_call(10**6), 4)
    (0.051, 0.0228)
    """
    from scipy import stats

    return float(stats.t.sf(MARGIN, runs - 1))


def transverse_calls(cmap) -> tuple[np.ndarray, np.ndarray]:
    """Per beta of a chaos map: +1 where y = 0 is transversally unstable in the coupled
    system (its transverse exponent less MARGIN s.e. above THRESHOLD_FACTOR ln t / t, t
    the time it ran after the transient), -1 where stable (plus MARGIN s.e. below it), 0
    where the runs cannot tell; and the thresholds."""
    t = (cmap.transverse_periods.values - cmap.attrs["transient"]) * 2 * np.pi
    thr = THRESHOLD_FACTOR * np.log(t) / t
    m, se = cmap.transverse.values, cmap.transverse_se.values
    return np.where(m - MARGIN * se > thr, 1, np.where(m + MARGIN * se < thr, -1, 0)), thr


def _floquet_calls(floq, betas: np.ndarray) -> np.ndarray:
    """+1 unstable, -1 stable by the fixed-container Floquet theory; 0 within one grid
    step of a stability boundary (the grid cannot place the boundary closer)."""
    step = float(np.min(np.diff(betas))) if betas.size > 1 else 0.0
    stable = floq.chart.problem.evaluate(betas).stable
    edges = np.array([e for iv in floq.stable_intervals for e in iv])
    near = (
        np.min(np.abs(betas[:, None] - edges[None, :]), axis=1) < step
        if edges.size
        else np.zeros(betas.size, bool)
    )
    return np.where(near, 0, np.where(stable, -1, 1))


def _floquet_claim(label, floq, mode) -> Claim:
    """The paper's Floquet prediction (fixed container) against the coupled normal mode's
    transverse Floquet multipliers, beta by beta on the mode's grid: both are exact to
    numerical precision, and the grid places the mode's boundaries to one step, so a beta
    counts against the theory when the two differ there farther than one grid step from a
    fixed-container boundary."""
    statement = (
        f"{label}: Floquet stability of y = 0 (fixed container) predicts where the normal "
        "mode y = 0 is stable in the oscillating container"
    )
    fixed = ", ".join(f"({a:.4f}, {b:.4f})" for a, b in floq.stable_intervals)
    if isinstance(mode, str):
        return Claim(statement, f"fixed-container Floquet-stable beta: {fixed}; {mode}",
                     UNDECIDED)  # fmt: skip
    mode = mode[0]
    betas = mode.beta
    step = float(betas[1] - betas[0])
    theory = floq.chart.problem.evaluate(betas).stable
    edges = np.array([e for iv in floq.stable_intervals for e in iv])
    far = np.min(np.abs(betas[:, None] - edges[None, :]), axis=1) > step
    differ = betas[far & (theory != mode.stable)]
    coupled = ", ".join(f"({a:.3f}, {b:.3f})" for a, b in mode.stable_intervals())
    return Claim(
        statement,
        f"fixed-container Floquet-stable beta: {fixed}; the coupled normal mode's transverse "
        f"Floquet multipliers (shooting at E = 0.5, m = 0.2, {betas.size} betas in "
        f"[{betas[0]:.3f}, {betas[-1]:.3f}], step {step:.3f}; stable where every "
        f"|phi_half| <= 1, i.e. its transverse exponent is 0): stable for beta in "
        f"{coupled or 'none'}; the two differ at {differ.size} betas farther than a step from "
        "a fixed-container boundary (holds at 0)"
        + (f": {', '.join(f'{b:.3f}' for b in differ)}" if differ.size else ""),
        HOLDS if not differ.size else FAILS,
        f"The coupled normal mode is transversally stable for beta in {coupled or 'none'}, "
        f"the fixed container's mode in {fixed}: "
        + ("with the container moving they differ nowhere farther than one grid step "
           f"({step:.3f}) from a fixed-container boundary, so the paper's prediction holds "
           "for the normal mode itself, up to a shift of its edges; the "
           "other motions in the plane y = 0 and generic starts are another matter (next "
           "row)." if not differ.size else
           "the container's motion moves the stability boundaries by more than the grid's "
           "step."),
    )  # fmt: skip


def _plane_claim(label, diagram, floq, cmap) -> Claim:
    """Beyond the paper: the fixed-container Floquet prediction against the transverse
    exponent of runs started anywhere on the plane y = 0 of the coupled system, per beta
    with an error on each side; the generic-start chaos map beside it."""
    from scipy import stats

    betas = np.asarray(diagram.beta, float)
    theory = _floquet_calls(floq, betas)
    measured, thr = transverse_calls(cmap)
    both = (theory != 0) & (measured != 0)
    N, D = int(both.sum()), int((both & (theory != measured)).sum())
    p = false_call(int(cmap.attrs["runs"]))
    # each side of the theory apart (Floquet-stable betas, Floquet-unstable betas), at
    # 99.5 % each, so that a one-sided failure is not diluted by the other side's matches
    sides = []
    for call in (-1, 1):
        on = both & (theory == call)
        n_side, d_side = int(on.sum()), int((on & (measured != call)).sum())
        sides.append((n_side, d_side, int(stats.binom.ppf(0.995, n_side, p)) if n_side else 0))
    stable_txt = ", ".join(f"({a:.4f}, {b:.4f})" for a, b in floq.stable_intervals)
    wrong = betas[both & (theory == -1) & (measured == 1)]
    generic = agreement(cmap, theory == -1)
    statement = (
        f"{BEYOND} {label}: Floquet stability of y = 0 (fixed container) predicts the "
        "transverse stability of every motion in the plane y = 0 of the oscillating "
        "container (runs started on it at rest at random x)"
    )
    measured_text = (
        f"fixed-container Floquet-stable beta: {stable_txt or 'none'}; the coupled "
        f"system's transverse exponent of y = 0 per beta ({cmap.attrs['runs']} runs started "
        f"on y = 0, mean +- {MARGIN:g} s.e. against {THRESHOLD_FACTOR:g} ln t / t = "
        f"{thr.min():.3g}-{thr.max():.3g}): unstable at {int((measured == 1).sum())}, stable "
        f"at {int((measured == -1).sum())}, unresolved at {int((measured == 0).sum())} of "
        f"{betas.size} betas; Floquet calls {int((theory == 0).sum())} betas within a grid "
        f"step of a boundary; of the {N} betas both sides call, {D} disagree: "
        f"{sides[0][1]} of {sides[0][0]} Floquet-stable and {sides[1][1]} of {sides[1][0]} "
        f"Floquet-unstable betas (holds if at most {sides[0][2]} and {sides[1][2]}, the "
        f"99.5 % quantiles of wrong calls at {100 * p:.1f} % each)"
        + (f"; Floquet-stable but unstable in the coupled system at beta "
           f"{wrong.min():.3f} to {wrong.max():.3f} ({wrong.size} betas)" if wrong.size else "")
        + ". Beside it, a different question: generic starts (the chaos map, each run "
        f"regular when its lambda_1 <= {THRESHOLD_FACTOR:g} ln t / t) " + generic_runs(cmap)
        + (f"; of the {generic['scored']} betas whose runs agree, every run regular exactly "
           f"where Floquet-stable at {100 * generic['floquet']:.0f} %" if generic["scored"]
           else "")
    )  # fmt: skip
    # power: the chance each side would flag a theory wrong at half its betas
    power = min(float(stats.binom.sf(a, n_, 0.5)) for n_, _, a in sides)
    fails = any(d > allowed for _, d, allowed in sides)
    holds = not fails and power >= 0.8
    physics = (
        f"The fixed-container theory places the stable interval at {stable_txt or 'none'}; "
        f"in the oscillating container (m = 0.2) the transverse exponent of y = 0 "
        + ("agrees beta by beta within its errors." if holds else
           f"disagrees at {D} of {N} betas ({wrong.size} of them Floquet-stable but unstable "
           "in the coupled system): the runs on y = 0 follow the coupled in-plane motion of "
           "particle and recoiling container, not the fixed-container orbit the theory "
           "linearises about, and their transverse growth follows that motion.")
    )  # fmt: skip
    measured_text += (
        f". Power: a theory wrong at half the betas of a side is flagged with chance "
        f"{power:.2f} (holds needs 0.8). {SIGN_CALL}"
    )
    verdict = FAILS if fails else (HOLDS if holds else UNDECIDED)
    return Claim(statement, measured_text, verdict, physics if verdict != UNDECIDED else "")


def generic_runs(cmap) -> str:
    """A chaos map's betas by their runs (:func:`~sinktheory.chaos.verdicts.map_calls`):
    how many have every run chaotic, how many split (with the regular fractions) and how
    many have every run regular."""
    c = map_calls(cmap)
    calls, frac = c["calls"], c["regular_fraction"]
    beta = np.asarray(cmap.beta.values, float)
    mixed = np.flatnonzero(calls == 0)
    text = (f"have every run chaotic at {int((calls == 1).sum())}, their runs split into "
            f"regular and chaotic at {mixed.size} and every run regular at "
            f"{int((calls == -1).sum())} of {calls.size} betas")  # fmt: skip
    if mixed.size and mixed.size <= 6:
        text += (
            " (regular fraction "
            + ", ".join(f"{100 * frac[j]:.0f} % at {beta[j]:.3f}" for j in mixed)
            + ")"
        )
    elif mixed.size:
        text += (f" (regular fraction {100 * frac[mixed].min():.0f}-"
                 f"{100 * frac[mixed].max():.0f} %, at beta {beta[mixed].min():.3f} to "
                 f"{beta[mixed].max():.3f})")  # fmt: skip
    return text


def _claims(panels, label_of) -> list[Claim]:
    claims = []
    for (diagram, floq, cmap, mode), label in zip(panels, label_of, strict=True):
        calls = map_calls(cmap)["calls"]
        early = int((cmap.lambda1_periods.values < cmap.attrs["periods"]).sum())
        t = (cmap.attrs["periods"] - cmap.attrs["transient"]) * 2 * np.pi
        basis = (
            f"each of the {cmap.attrs['runs']} runs per beta is chaotic when its lambda_1 "
            f"exceeds {THRESHOLD_FACTOR:g} ln t / t (= {THRESHOLD_FACTOR * np.log(t) / t:.3g} "
            f"over the full span; lambda_1 is the growth rate after a transient of "
            f"{cmap.attrs['transient']} T, over {cmap.attrs['periods']} T less it; {early} "
            "betas settled chaotic at an earlier look, their mean by 4 or 3 standard "
            "errors, sinktheory.chaos.staged, and their runs are judged over the span they ran)"
        )
        irregular = calls != -1  # at least one chaotic run
        neg = bool(np.any(irregular[diagram.beta < 0]))
        pos = bool(np.any(irregular[diagram.beta > 0]))
        claims.append(
            Claim(
                f"{label}: irregular motion in both negative and positive beta intervals",
                f"{basis}: generic starts {generic_runs(cmap)}; chaotic runs at beta < 0: "
                f"{neg}, beta > 0: {pos}",
                HOLDS if neg and pos else FAILS,
                f"Generic starts give chaotic runs at {int(irregular.sum())} of "
                f"{irregular.size} betas, "
                + (
                    "on both sides of beta = 0, as the paper says."
                    if neg and pos
                    else f"only at beta {'< 0' if neg else '> 0' if pos else 'nowhere'}: on the "
                    "other side every run stays regular over the span."
                ),  # fmt: skip
            )
        )
        claims.append(_floquet_claim(label, floq, mode))
        claims.append(_plane_claim(label, diagram, floq, cmap))
    return claims


#: Half-width of the fine beta grid around each phi = -1 touching, and its points
#: (paper fidelity, --quick): a step of 0.002 sees any window of two steps, 0.004 wide,
#: well below the width a window needs to show on the paper's Fig. 3 (its beta axis spans
#: 1.15, so a visible window is ~0.01 wide).
TOUCH_WIDTH, TOUCH_POINTS = 0.02, (11, 21)
#: Half-width and points of the fine beta grid on which the coupled normal mode's transverse
#: multipliers are computed around each touching (paper fidelity only, like the Floquet
#: rows): the same step, 0.002, on a wider grid, since the container's motion moves the
#: touching (phi_half = 0 of the coupled mode at E = 0.5, m = 0.2: +0.008 from the
#: fixed-container touching at n = 10, +0.029 at n = 2).
MODE_TOUCH_WIDTH, MODE_TOUCH_POINTS = 0.04, 41


def _window(calls: np.ndarray, centre: int) -> str:
    """What the calls (+1 unstable, -1 stable, 0 unresolved) show around index
    ``centre``: "window" (unstable calls at or next to it with stable calls on both
    sides), "stable", "unstable" (no stable call anywhere), or "unresolved"."""
    unstable = np.flatnonzero(calls == 1)
    if not unstable.size:
        return "stable" if (calls == -1).all() else "unresolved"
    if not (calls == -1).any():
        return "unstable" if (calls == 1).sum() > calls.size // 2 else "unresolved"
    near = unstable[np.abs(unstable - centre) <= 1]
    if near.size and (calls[: near.min()] == -1).any() and (calls[near.max() + 1 :] == -1).any():
        return "window"
    return "unresolved"


def mode_touching(n: int, touching: float) -> tuple[str, str, dict]:
    """The coupled normal mode (flat well, alpha = 1/2, E = 0.5, m = 0.2) on the fine grid
    MODE_TOUCH_POINTS around a fixed-container touching: what its transverse multipliers
    show (:func:`_window` of their calls, centred where its half-trace phi_half changes
    sign, i.e. where phi_T = -1; "unresolved" without a sign change on the grid), a
    sentence, and the numbers: the coupled touching ``beta``, ``stable`` grid points, and
    at the fixed-container touching the full-period transverse half-trace ``phi_T`` (from
    the monodromy's multipliers), ``square`` = 2 phi_half^2 - 1 (from the half-period map)
    and the half-period symmetry error ``symmetry`` of the orbit."""
    betas = touching + np.linspace(-MODE_TOUCH_WIDTH, MODE_TOUCH_WIDTH, MODE_TOUCH_POINTS)
    got = _mode_chart(0.5, n, "flat", touching, betas)
    if isinstance(got, str):
        return "unresolved", got, {}
    chart, start = got
    phi = chart.phi_half[:, 0]
    sign = np.flatnonzero(np.sign(phi[:-1]) != np.sign(phi[1:]))
    calls = np.where(chart.stable, -1, 1)
    num = {
        "stable": int(chart.stable.sum()),
        "phi_T": float(np.mean(start.floquet.transverse.real)),
        "square": float(2 * start.transverse_half_traces()[0] ** 2 - 1),
        "symmetry": start.half_period()[2],
    }
    if not sign.size:
        text = (f"its phi_half keeps one sign on [{betas[0]:.4f}, {betas[-1]:.4f}], stable at "
                f"{num['stable']} of {betas.size} betas")  # fmt: skip
        return "unresolved", text, num
    j = int(sign[0])
    num["beta"] = float(betas[j] - phi[j] * (betas[j + 1] - betas[j]) / (phi[j + 1] - phi[j]))
    kind = _window(calls, j if abs(phi[j]) <= abs(phi[j + 1]) else j + 1)
    text = (
        f"coupled normal mode: phi_half = 0 (phi_T = -1) at beta = {num['beta']:.4f}, transverse "
        f"multipliers stable at {num['stable']} of {betas.size} betas -> {kind}; at the "
        f"touching its full-period phi_T = {num['phi_T']:.6f} against 2 phi_half^2 - 1 = "
        f"{num['square']:.6f} (half-period symmetry error {num['symmetry']:.0e})"
    )
    return kind, text, num


def _touching_claim(panels, quick: bool) -> Claim:
    """The phi = -1 claim in the full system: the coupled normal mode's transverse Floquet
    multipliers (paper fidelity) and the transverse exponent of runs on the plane y = 0
    of the oscillating container, each on a fine beta grid around each touching of each
    panel.  The mode decides (the claim is about its stability intervals); without it
    (--quick, or a mode that cannot be followed) the runs do."""
    f = _fidelity(quick)
    points = TOUCH_POINTS[0 if quick else 1]
    found, parts, modes, shifts = [], [], [], []
    for n, floq in panels:
        for r in floq.resonances:
            if not quick:
                kind, text, num = mode_touching(n, r)
                modes.append(kind)
                parts.append(f"n = {n}, touching at beta = {r:.4f}: {text}")
                if "beta" in num:
                    shifts.append(f"{num['beta'] - r:+.3f} at n = {n}")
            betas = r + np.linspace(-TOUCH_WIDTH, TOUCH_WIDTH, points)
            cmap = chaos_map(0.5, n, betas, runs=f["runs"], periods=f["periods"],
                             transient=f["periods"] // 10)  # fmt: skip
            calls, _ = transverse_calls(cmap)
            kind = _window(calls, points // 2)
            found.append(kind)
            m = cmap.transverse.values
            parts.append(
                f"n = {n}, touching at beta = {r:.4f}: runs on the plane y = 0: transverse "
                f"exponent {m.min():.3f} to {m.max():.3f} ({m[points // 2]:.3f} at the "
                f"touching); unstable at {int((calls == 1).sum())}, stable at "
                f"{int((calls == -1).sum())} of {points} betas -> {kind}"
            )
    step = 2 * TOUCH_WIDTH / (points - 1)
    statement = "narrow instability windows inside stability intervals come from phi = -1 touchings"
    measured = (
        "; ".join(parts)
        + (
            f" (coupled mode: {MODE_TOUCH_POINTS} betas, step "
            f"{2 * MODE_TOUCH_WIDTH / (MODE_TOUCH_POINTS - 1):.3g}, +-{MODE_TOUCH_WIDTH:g}, "
            "shooting at E = 0.5, m = 0.2, stable where its transverse multipliers lie on the "
            "unit circle; "
            if modes
            else " ("
        )
        + (
            f"runs: {points} betas, step {step:.3g}, +-{TOUCH_WIDTH:g} around the touching; "
            f"{f['runs']} runs x {f['periods']} periods started on y = 0, calls at "
            f"{MARGIN:g} s.e. as in the Floquet rows). In the linear equation phi_T = "
            "2 phi_half^2 - 1 only touches -1: a window of zero width. "
            + (
                "The coupled mode is exact to the shooting's precision and the runs' calls are "
                "of an exponent's sign: no run of three relaxation times is needed"
                if modes
                else SIGN_CALL
            )
        )
    )
    if modes and "unresolved" not in modes:
        if all(k == "window" for k in modes):
            return Claim(statement, measured, HOLDS, "")
        if all(k == "stable" for k in modes):
            return Claim(statement, measured, FAILS, (
                "No window at the touchings: the container's motion moves them (phi_T = -1 of "
                f"the coupled normal mode at {', '.join(shifts)} from the fixed container's), "
                "but the coupled mode is odd under the half-period shift, as the fixed one, so "
                "its phi_T is still 2 phi_half^2 - 1 >= -1 and its transverse multipliers stay "
                "on the unit circle across each fine grid: phi = -1 is touched, never crossed "
                "(a window of zero width)"
                + ("; runs on the plane y = 0 away from the mode are transversally unstable "
                   "across the grid anyway" if set(found) == {"unstable"} else "")
                + ". Narrow features in bifurcation diagrams near these betas would need "
                "another cause."))  # fmt: skip
        return Claim(statement, measured, UNDECIDED)
    if not found or "unresolved" in found:
        return Claim(statement, measured + ("" if found else "; no touching found"), UNDECIDED)
    holds = all(k == "window" for k in found)
    return Claim(
        statement,
        measured,
        HOLDS if holds else FAILS,
        "" if holds else (
            "No window at the touchings: the linear equation only touches phi = -1 (zero "
            "width); in the oscillating container, runs on the plane y = 0 are "
            + ("transversally unstable across the whole fine grid, so there is no stable "
               "background for a window, while the normal mode itself stays stable there "
               "(the Floquet rows)" if set(found) == {"unstable"} else
               "stable or unstable across each fine grid, with no window at the touching")
            + "; narrow features in bifurcation diagrams there would need another cause."
        ),
    )  # fmt: skip


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
        + [_touching_claim([(n, p[1]) for n, p in zip((2, 10), panels, strict=True)], quick)],
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
                + " (outside, it escapes over the corner saddle or D vanishes within reach); "
                "missing: which well the paper ran at beta = 1.0 (another alpha, or another "
                "beta such as the text's 0.1)",
                UNDECIDED,
                "The claim cannot be checked as printed: at alpha = 1 the well with beta = 1 "
                "is singular at its centre, so the paper must have run another set-up, "
                "which it does not name.",
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
