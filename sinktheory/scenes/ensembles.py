"""Figs. 5, 8, 9 and 12: ensemble energy histories of the container (records E(jT) only)."""

from __future__ import annotations

import functools

import numpy as np

from ..canonical import FIG8_WELL
from ..model import RunSettings, Sink, Well
from ..plot.paper import energy_curves, energy_panels, recurrence_columns, running_and_recurrence
from ..recurrence import rqa
from ..runstats import ensemble_mean
from ..simulate import simulate
from ..sinkstats import SinkMeasures, running_mean, sink_measures
from .base import FAILS, HOLDS, Claim, Scene, SceneResult

__all__ = [
    "ensemble",
    "FIG12",
    "FIG45_BETAS",
    "FIG5",
    "FIG8",
    "FIG8_KS",
    "FIG8_N",
    "FIG8_WELL",
    "FIG9",
    "FIG9_BETAS",
    "FIG9_EPS",
]

E0, MASS, SEED = 0.5, 0.2, 2016


@functools.lru_cache(maxsize=32)
def ensemble(
    shape: str, alpha: float, beta: float, n: int, k: int, runs: int, periods: int
) -> tuple[np.ndarray, float, float]:
    """E(jT) for every run (R, P + 1), the worst energy error, and the total energy.

    Cached, so a scene reusing another scene's ensemble (Fig. 12 compares with Fig. 8)
    does not integrate it twice.
    """
    sink = Sink(Well(alpha, beta, n, shape=shape), particles=k, mass=MASS)
    settings = RunSettings(container_energy=E0, runs=runs, periods=periods, seed=SEED)
    res = simulate(sink, settings, progress=False)
    return res.container_energy, res.max_relative_energy_error, float(res.initial_energy.mean())


def _measures(e_runs: np.ndarray, total: float, k: int, n: int) -> SinkMeasures:
    """Sink measures with the second half of the run as the long-time window."""
    return sink_measures(
        e_runs, e0=E0, total_energy=total, particles=k, n=n, transient=(e_runs.shape[1] - 1) // 2
    )


def _law_claim(label: str, m: SinkMeasures, well: Well, k: int, total: float) -> Claim:
    """Beyond the paper: is the long-time <E> the mean of the exact equilibrium law of E_c
    (:mod:`sinktheory.equilibrium`), within 3 standard errors?  The error is the spread of
    the runs' time averages over sqrt(R): independent runs as batches, so the
    autocorrelation inside a run is accounted for."""
    from ..equilibrium import equilibrium_law

    law = equilibrium_law(Sink(well, particles=k, mass=MASS), total)
    z = (m.long_time_mean - law.mean) / max(m.long_time_stderr, 1e-12)
    return Claim(
        f"(beyond the paper) {label}: the long-time <E> is the mean of the exact "
        "equilibrium law of E_c on the energy shell (reached if the motion is ergodic)",
        f"measured {m.long_time_mean:.4f} +- {m.long_time_stderr:.4f} (s.e. over the runs' "
        f"time averages), law {law.mean:.4f}, z = {z:+.1f}; homogeneous estimate "
        f"E/(1 + k(1 + 1/n)) = {m.equipartition:.4f}; particles hold "
        f"{100 * m.particle_fraction:.1f} % of the energy",
        HOLDS if abs(z) <= 3 else FAILS,
    )


def _recurrence_claim(well: Well, total: float) -> Claim:
    """Beyond the paper: the recurrence claim in numbers, Kac's mean return time 1/P from
    the exact law (``sinktheory lifetime`` measures it where runs can observe it)."""
    from ..equilibrium import equilibrium_law

    rows, held = [], []
    for k in FIG8_KS:
        kac = equilibrium_law(Sink(well, particles=k, mass=MASS), total).kac_periods([0.5, 0.8])
        rows.append(f"k = {k}: {kac[0]:.3g} (f = 0.5), {kac[1]:.3g} (f = 0.8)")
        held += [(k, f) for f, x in zip((0.5, 0.8), kac, strict=True) if x > 1e4]
    return Claim(
        "(beyond the paper) Poincare recurrence takes far longer than the system's natural "
        "times: Kac's mean return time (periods) to {E_c >= f E}, 1/P from the exact law, "
        "exceeds 10^4 periods for some k, f",
        "; ".join(rows)
        + "; over 10^4 for "
        + (", ".join(f"k = {k}, f = {f:g}" for k, f in held) or "none"),
        HOLDS if held else FAILS,
    )


def _passage_note(label: str, m: SinkMeasures) -> str:
    """First periods at which <E> fell below fractions of E0, and the spread across runs."""
    times = ", ".join(
        f"{int(100 * f)} %: {'never' if j is None else f't = {j} T'}"
        for f, j in m.first_below.items()
    )
    return (
        f"{label}: <E> first below fractions of E0 at {times}; run-to-run spread "
        f"(std) of the long-time means {m.run_spread:.4f}"
    )


def _fidelity(quick: bool, runs: int, periods: int) -> tuple[int, int]:
    return (max(4, runs // 5), max(30, periods // 10)) if quick else (runs, periods)


# -------------------------------------------------------------------------- Fig. 5
FIG45_BETAS = (-0.5, -0.3, -0.2, -0.14, 0.009, 0.3)


def _fig5(quick: bool) -> SceneResult:
    runs, periods = _fidelity(quick, 50, 100)
    panels, finals, laws, worst = [], [], [], 0.0
    for beta, label in zip(FIG45_BETAS, "abcdef", strict=True):
        e, err, total = ensemble("flat", 0.5, beta, 10, 1, runs, periods)
        laws.append(
            _law_claim(
                f"beta = {beta:g}", _measures(e, total, 1, 10), Well(0.5, beta, 10), 1, total
            )
        )
        worst = max(worst, err)
        m, se = ensemble_mean(e)
        finals.append(float(m[-periods // 4 :].mean()))
        panels.append((f"{label}) $\\beta$ = {beta:g}", m, se))
    fig = energy_panels(
        panels,
        f"Fig. 5: $\\langle E\\rangle$ over {runs} runs (band: $\\pm$ standard "
        f"error), $n$ = 10, $k$ = 1, $\\alpha$ = 1/2, $m$ = {MASS}",
        top=0.55,
    )
    drained = [b for b, f in zip(FIG45_BETAS, finals, strict=True) if f < 0.8 * E0]
    return SceneResult(
        fig,
        {
            "alpha": 0.5,
            "n": 10,
            "k": 1,
            "mass": MASS,
            "runs": runs,
            "periods": periods,
            "beta": list(FIG45_BETAS),
            "seed": SEED,
            "max energy error": f"{worst:.2g}",
        },
        [
            Claim(
                "energy flows out of the container for both negative and positive unstable beta",
                "mean <E> over the last quarter: "
                + ", ".join(
                    f"beta {b:g}: {f:.3f}" for b, f in zip(FIG45_BETAS, finals, strict=True)
                ),
                HOLDS if any(b < 0 for b in drained) and any(b > 0 for b in drained) else FAILS,
            ),
            *laws,
        ],
        ["The caption does not give the horizon; 100 periods, as in Fig. 4."],
    )


# -------------------------------------------------------------------------- Fig. 8
FIG8_KS = (1, 3, 5)
FIG8_N = FIG8_WELL.n


def _fig8(quick: bool) -> SceneResult:
    runs, periods = _fidelity(quick, 25, 1500)
    curves, measures, totals, worst = [], [], [], 0.0
    for k in FIG8_KS:
        e, err, total = ensemble("flat", 0.5, 0.3, FIG8_N, k, runs, periods)
        totals.append(total)
        worst = max(worst, err)
        curves.append((f"$k$ = {k}", *ensemble_mean(e)))
        measures.append(_measures(e, total, k, FIG8_N))
    fig = energy_curves(
        curves,
        f"Fig. 8: flat well, $\\beta$ = 0.3, $\\alpha$ = 1/2, $n$ = {FIG8_N}, "
        f"$m$ = {MASS}, {runs} runs",
    )
    decreasing = all(
        a.long_time_mean > b.long_time_mean + 2 * np.hypot(a.long_time_stderr, b.long_time_stderr)
        for a, b in zip(measures, measures[1:], strict=False)
    )
    return SceneResult(
        fig,
        {
            "shape": "flat",
            "alpha": 0.5,
            "beta": 0.3,
            "n": FIG8_N,
            "mass": MASS,
            "k": list(FIG8_KS),
            "runs": runs,
            "periods": periods,
            "seed": SEED,
            "max energy error": f"{worst:.2g}",
        },
        [
            Claim(
                "the energy decay becomes more explicit as the number of particles grows",
                "long-time <E> (second half, +- s.e.): "
                + ", ".join(
                    f"k = {k}: {m.long_time_mean:.4f} +- {m.long_time_stderr:.4f}"
                    for k, m in zip(FIG8_KS, measures, strict=True)
                )
                + " (holds if each k is lower than the previous by 2 s.e.)",
                HOLDS if decreasing else FAILS,
            ),
            *[
                _law_claim(f"k = {k}", m, FIG8_WELL, k, t)
                for k, m, t in zip(FIG8_KS, measures, totals, strict=True)
            ],
            _recurrence_claim(FIG8_WELL, totals[-1]),
        ],
        [
            "The paper does not state n for Fig. 8; n = 4 as in Fig. 9.",
            *[_passage_note(f"k = {k}", m) for k, m in zip(FIG8_KS, measures, strict=True)],
        ],
    )


# -------------------------------------------------------------------------- Fig. 9
FIG9_BETAS = (-0.5, -0.2, 0.3)
#: Recurrence neighbourhood for Fig. 9: 1 % of E0, the same for the three shapes so
#: their recurrence rates compare.
FIG9_EPS = 0.01 * E0


def _fig9(quick: bool) -> SceneResult:
    runs, periods = _fidelity(quick, 25, 1500)
    window = 50
    columns, stats = [], []
    for beta in FIG9_BETAS:
        e, _, _ = ensemble("flat", 0.5, beta, 4, 3, runs, periods)
        m, _ = ensemble_mean(e)
        columns.append((f"$\\beta$ = {beta:g}, $\\varepsilon$ = {FIG9_EPS:g}", m))
        stats.append(rqa(m, FIG9_EPS))
    fig = recurrence_columns(
        columns,
        FIG9_EPS,
        window,
        f"Fig. 9: $k$ = 3, $n$ = 4, {runs} runs; recurrence of $\\langle E\\rangle$ "
        "(top) and its running mean (bottom)",
    )
    rr = [s.recurrence_rate for s in stats]
    return SceneResult(
        fig,
        {
            "shape": "flat",
            "alpha": 0.5,
            "n": 4,
            "k": 3,
            "mass": MASS,
            "beta": list(FIG9_BETAS),
            "runs": runs,
            "periods": periods,
            "running window": f"{window}T",
            "eps": FIG9_EPS,
            "seed": SEED,
        },
        [
            Claim(
                "recurrence effects are strongest for the stadium-like beta = -0.5",
                "; ".join(
                    f"beta {b:g}: RR {s.recurrence_rate:.3f}, DET {s.determinism:.3f}, "
                    f"LAM {s.laminarity:.3f}"
                    for b, s in zip(FIG9_BETAS, stats, strict=True)
                ),
                HOLDS if rr[0] == max(rr) else FAILS,
            )
        ],
        [
            "Runs per ensemble not given for Fig. 9; 25 as in Fig. 8.",
            "eps = 1 % of E0 for all three panels (Theiler window 1: main diagonal excluded).",
        ],
    )


# -------------------------------------------------------------------------- Fig. 12
def _fig12(quick: bool) -> SceneResult:
    runs, periods = _fidelity(quick, 25, 1500)
    window = 5
    e, err, total = ensemble("symmetric", 1.0, 0.1, 6, 5, runs, periods)
    m, _ = ensemble_mean(e)
    r = running_mean(m, window)
    fig = running_and_recurrence(
        m,
        E0,
        0.01 * E0,
        window,
        f"Fig. 12: symmetric well, $\\alpha$ = 1, $\\beta$ = 0.1, $n$ = 6, $k$ = 5, {runs} runs",
    )
    sym = _measures(e, total, 5, 6)
    late = sym.long_time_mean
    settle = next(
        (int(i) + window - 1 for i in np.flatnonzero(np.abs(r - late) <= 0.2 * late)), None
    )
    flat_e, _, flat_total = ensemble("flat", 0.5, 0.3, FIG8_N, 5, runs, periods)
    flat = _measures(flat_e, flat_total, 5, FIG8_N)
    return SceneResult(
        fig,
        {
            "shape": "symmetric",
            "alpha": 1.0,
            "beta": 0.1,
            "gamma": 1.0,
            "n": 6,
            "k": 5,
            "mass": MASS,
            "runs": runs,
            "periods": periods,
            "running window": f"{window}T",
            "seed": SEED,
            "max energy error": f"{err:.2g}",
        },
        [
            Claim(
                "a statistical equilibrium is reached after about 100 cycles",
                f"the {window}T running mean first comes within 20 % of the long-time <E> at "
                f"t/T = {settle} (holds for 50 to 200)",
                HOLDS if settle is not None and 50 <= settle <= 200 else FAILS,
            ),
            Claim(
                "the equilibrium lies near <E> = 0.1",
                f"long-time <E> = {late:.4f} +- {sym.long_time_stderr:.4f} (holds within 20 % "
                "of 0.1)",
                HOLDS if 0.08 <= late <= 0.12 else FAILS,
            ),
            Claim(
                "particles absorb energy more effectively in the symmetric container than "
                "in the flat one",
                f"long-time <E>: symmetric {late:.4f} +- {sym.long_time_stderr:.4f} vs flat "
                f"(Fig. 8, k = 5) {flat.long_time_mean:.4f} +- {flat.long_time_stderr:.4f}",
                HOLDS
                if late + 2 * sym.long_time_stderr < flat.long_time_mean - 2 * flat.long_time_stderr
                else FAILS,
            ),
            _law_claim("symmetric, k = 5", sym, Well(1.0, 0.1, 6, shape="symmetric"), 5, total),
        ],
        [
            "The caption gives beta = 1.0, which with alpha = 1 makes the well singular at its "
            "centre (validation refuses it); the text says beta = 0.1, used here."
        ],
    )


FIG5 = Scene(
    5,
    "container energy, one particle, six shapes",
    "ensembles of the coupled system, E(jT) only",
    _fig5,
)
FIG8 = Scene(
    8,
    "container energy for k = 1, 3, 5 particles",
    "ensembles of the coupled system, E(jT) only",
    _fig8,
)
FIG9 = Scene(9, "running averages and recurrence plots", "ensembles, E(jT) only", _fig9)
FIG12 = Scene(12, "symmetric well, five particles", "ensembles, E(jT) only", _fig12)
