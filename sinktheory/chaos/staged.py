"""Chaos-map exponents decided as soon as they are settled: sequential looks.

A chaos map calls a beta chaotic when the mean finite-time exponent of its runs minus two
standard errors exceeds THRESHOLD_FACTOR ln t / t at the end of the run
(:mod:`sinktheory.chaos.verdicts`).  Most betas of the paper's maps are clearly chaotic long
before the end, so the runs are looked at on the way (:data:`LOOKS`): at a quarter of the
periods a group of runs (one beta) stops if its mean minus **four** standard errors exceeds
the threshold at that time, at half the periods if it exceeds it by **three**.  The
threshold decreases with t (for t > e), so a group stopped at a look is also chaotic by the
final rule; groups that do not settle run to the end and get exactly the numbers of an
unstopped run.  Only "chaotic" is ever decided early: a regular orbit's exponent decays
like ln t / t and is judged at the end.

A transient of ``transient`` periods can be left out: the exponent is then the growth
rate from its end, (ln|delta(t)| - ln|delta(t_0)|) / (t - t_0).  A regular orbit's
deviation grows at most linearly, so its rate from t_0 is ln(t / t_0) / (t - t_0), below
ln t / t once t > t_0 > e: the same threshold stays a safe bound.

Error rate: under a normal approximation for the mean of the runs, a group that the final
look would call regular is stopped as chaotic at a look with probability at most
Phi(-4) + Phi(-3) = 0.0014, so the sequential map's false-chaotic rate is at most
0.1 percentage point above the single look's one-sided 2.3 % (O'Brien-Fleming-like
boundaries: strict early, nominal at the end).

Examples
--------
>>> looks(200)
[(50, 4.0), (100, 3.0)]
>>> looks(6)  # too short to look at: every group runs to the end
[]
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..ensemble import ENERGY_BOUND
from ..glossary import renamed
from ..runstats import ensemble_mean
from .verdicts import threshold

__all__ = ["LOOKS", "MIN_LOOK", "StagedExponent"]

if TYPE_CHECKING:
    from ..engine.core import Ensemble

#: (fraction of the periods, z): where the groups are looked at and the margin asked for.
LOOKS = ((0.25, 4.0), (0.5, 3.0))
#: No look before this many periods (the exponents are dominated by the transient).
MIN_LOOK = 20


def looks(periods: int, transient: int = 0) -> list[tuple[int, float]]:
    """The looks (period, z) of a run of ``periods`` periods whose first ``transient``
    are discarded (none before MIN_LOOK periods after the transient)."""
    out = []
    for fraction, z in LOOKS:
        at = int(periods * fraction)
        if transient + MIN_LOOK <= at < periods:
            out.append((at, z))
    return out


@dataclass(frozen=True)
class StagedExponent:
    """Finite-time exponent of deviation vector 0 of each run, at the time its group
    stopped.

    exponent : (R,) growth rate of ln|delta| from t_0 (transient's end, or 0) to t_r
    periods : (R,) t_r in periods (the run's group stopped at a look, or ran to the end)
    worst : (R,) largest relative energy error of the run while it ran
    """

    exponent: np.ndarray
    periods: np.ndarray
    worst: np.ndarray


@renamed(method="scheme")
def staged_chaos(sinks, settings, *, dt, transverse: bool, scheme: str,
                 renorm: int = 0, energy_bound: float = ENERGY_BOUND,
                 transient: int = 0) -> list[dict]:  # fmt: skip
    """lambda_1 (and the transverse exponent) of several set-ups as in
    :func:`~sinktheory.chaos.chaos_batch`, each set-up's runs stopped at the first look
    where they are settled chaotic.

    Returns one dict per set-up: ``lambda1`` and ``transverse`` (StagedExponent of its runs,
    ``transverse`` None unless asked for).  A set-up that never settles gets bitwise the
    exponents of ``chaos_batch`` (and of ``chaos`` alone) with the same step.  ``dt``: one
    step, or one per set-up (as for ``chaos_batch``).
    """
    from ..ensemble import engine_name
    from ..integrators import get_scheme
    from .sink import _join, _params, _per_run, _Point, _vectors, point_steps, transverse_mask

    points = [_Point.of(k, s, transverse, None) for k, s in zip(sinks, settings, strict=True)]
    system = engine_name(points[0].sink)
    scheme = get_scheme(scheme)
    dts, steps = point_steps(points, dt)
    dt, steps = _per_run(points, dts), _per_run(points, steps)
    periods = points[0].settings.periods
    groups = np.concatenate([np.full(p.settings.runs, i) for i, p in enumerate(points)])
    params = _params(points)
    masks = [None] + ([transverse_mask(points[0].sink.particles)] if transverse else [])
    out = []
    for mask in masks:
        dq, dv = _vectors(points, 1, mask)
        states = [p.on_plane if mask is not None else (p.q, p.v) for p in points]
        from ..engine.core import Ensemble  # numba loads with the first run

        ens = Ensemble(
            system,
            _join(s[0] for s in states),
            _join(s[1] for s in states),
            params,
            dq=dq,
            dv=dv,
            tangent="normalise",
            reference_energy=None if mask is not None else np.concatenate([p.h0 for p in points]),
        )
        out.append(staged_exponent(ens, groups, scheme, dt=dt, steps=steps, periods=periods,
                                   bound=energy_bound, renorm=renorm,
                                   transient=transient))  # fmt: skip
    return [
        {
            "lambda1": _part(out[0], groups == i),
            "transverse": _part(out[1], groups == i) if transverse else None,
        }
        for i in range(len(points))
    ]


def _part(s: StagedExponent, runs) -> StagedExponent:
    return StagedExponent(s.exponent[runs], s.periods[runs], s.worst[runs])


def staged_exponent(ensemble: Ensemble, groups, scheme, *, dt, steps,
                    periods: int, bound: float, renorm: int = 0,
                    transient: int = 0) -> StagedExponent:  # fmt: skip
    """Advance ``ensemble`` (deviation vector 0 normalised each period) for up to
    ``periods`` periods, stopping the runs of each group (``groups``: (R,) labels) at the
    first look where the group is settled chaotic (module docstring); the growth over the
    first ``transient`` periods is left out of the exponents.  ``dt``, ``steps``: one step,
    or one per run."""
    groups = np.asarray(groups)
    R = ensemble.runs
    exponent, used, worst = np.empty(R), np.full(R, periods), np.zeros(R)
    start = np.zeros(R)  # ln|delta| at the end of the transient
    dt, steps = np.broadcast_to(dt, (R,)), np.broadcast_to(steps, (R,))  # one per run
    segment = dt * steps  # each run's times are segment x k, as its ChaosResult.times
    active = np.arange(R)
    done = 0
    stages = [(transient, None)] if transient else []
    for at, z in [*stages, *looks(periods, transient), (periods, None)]:
        rec = ensemble.run(scheme, dt=dt[active], steps=steps[active], segments=at - done,
                           record=(), renorm=renorm, bound=bound, unit="period")  # fmt: skip
        done = at
        worst[active] = np.maximum(worst[active], rec.worst)
        if at == transient:
            start[active] = ensemble.logs[0]
            continue
        span = segment[active] * at - segment[active] * transient
        exponent[active] = (ensemble.logs[0] - start[active]) / span
        if z is None:
            break
        stop = np.zeros(active.size, bool)
        for g in np.unique(groups[active]):
            mine = groups[active] == g
            if mine.sum() < 2:  # no standard error from one run: it runs to the end
                continue
            mean, se = ensemble_mean(exponent[active][mine][:, None])
            if mean[0] - z * se[0] > threshold(at):
                stop |= mine
        used[active[stop]] = at
        if stop.all():
            break
        if stop.any():
            ensemble = ensemble._take(~stop)
            active = active[~stop]
    return StagedExponent(exponent, used, worst)
