"""The ``chaos`` sweep kind's points: indicators of many set-ups as few ensembles.

:func:`points` groups a task's points by engine, periods and analysis options and runs
each group as one ensemble whose runs carry their own parameters and steps
(:func:`sinktheory.chaos.chaos_batch`, or with ``stop_early``
:func:`sinktheory.chaos.staged.staged_chaos`), so a chaos map over beta is one ensemble;
:func:`check_point` checks a point before any work.  The kind itself (its parameters and
stored results) is :data:`sinktheory.sweep.kinds.KINDS` ``["chaos"]``.
"""

from __future__ import annotations

import numpy as np

from .. import validation as v
from ..ensemble import settings_of, sink_of
from ..errors import ParameterError
from ..runstats import check_runs, ensemble_mean
from ..simulate import check_point as ensemble_check

__all__ = []


def check_point(p: dict) -> None:
    """Check a ``chaos`` sweep point: the ensemble's, then the indicators' options and the
    tangent work."""
    from ..chaos.general import check_gali, check_renorm
    from ..chaos.sink import check_tangent_work

    steps = ensemble_check(p)
    check_runs("runs", p["runs"])  # the verdict needs lambda_1's standard error
    check_renorm(p["renorm"])
    v.positive_int("megno", p["megno"], minimum=0, maximum=1)
    v.positive_int("transverse", p["transverse"], minimum=0, maximum=1)
    v.positive_int("stop_early", p["stop_early"], minimum=0, maximum=1)
    v.positive_int("transient", p["transient"], minimum=0, maximum=max(0, p["periods"] - 1))
    gali = check_gali(p["gali"], 1 + 2 * p["particles"])
    if p["stop_early"] and (gali or p["megno"]):
        raise ParameterError("stop_early", 1, "0 when gali or megno is asked for (they need "
                             "every run to the end)")  # fmt: skip
    check_tangent_work(sink_of(p), settings_of(p, 0), steps, None, gali, bool(p["transverse"]))


def _chaos_step(p: dict, seed: int) -> float:
    """The point's step: ``dt`` if given, else the step for the default tolerance taken
    down to the ladder of :func:`sinktheory.stepsize.ladder_step`, so that neighbouring
    betas share a step count and fill the engine's blocks together."""
    from ..chaos.sink import start_energy
    from ..stepsize import ladder_step, resolve_step

    if p["dt"] is not None:
        return p["dt"]
    sink = sink_of(p)
    top = start_energy(sink, settings_of(p, seed), bool(p["transverse"]))
    return ladder_step(resolve_step(sink, top, scheme=p["scheme"])[1])[0]


def points(points: list) -> list[dict]:
    """The points of a task grouped by engine, periods and analysis options, each group
    one ensemble whose runs carry their own parameters and steps
    (:func:`sinktheory.chaos.chaos_batch`, or with ``stop_early``
    :func:`sinktheory.chaos.staged.staged_chaos`): a chaos map over beta is one ensemble.
    Steps per run need ``renorm`` = 0 (it counts steps), so with renorm the step is part
    of the group."""
    groups: dict[tuple, list[int]] = {}
    steps = [_chaos_step(p, seed) for p, seed in points]
    for i, (p, _) in enumerate(points):
        same = ("particles", "periods", "scheme", "gali", "megno", "transverse", "renorm",
                "energy_bound", "stop_early", "transient")  # fmt: skip
        # the engine: a registered shape, or a user's well by its text (its own parameters
        # in place of shape and n, which it may lack)
        engine = (p.get("well"), p.get("shape"), p.get("n"))
        key = (*engine, *(p[k] for k in same), steps[i] if p["renorm"] else None)
        groups.setdefault(key, []).append(i)
    out: list = [None] * len(points)
    for members in groups.values():
        first = points[members[0]][0]
        sinks = [sink_of(points[i][0]) for i in members]
        settings = [settings_of(points[i][0], points[i][1]) for i in members]
        options = {
            "dt": [steps[i] for i in members],
            "transverse": bool(first["transverse"]),
            "scheme": first["scheme"],
            "renorm": first["renorm"],
            "energy_bound": first["energy_bound"],
        }
        if first["stop_early"]:
            from ..chaos.staged import staged_chaos

            runs = staged_chaos(sinks, settings, transient=first["transient"], **options)
            summaries = [_staged_summary(r, dt) for r, dt in zip(runs, options["dt"], strict=True)]
        else:
            from ..chaos import chaos_batch

            extra = {"gali": first["gali"], "megno": bool(first["megno"]), "progress": False}
            results = chaos_batch(sinks, settings, **extra, **options)
            summaries = [
                _chaos_summary(res, first["periods"], first["transient"]) for res in results
            ]
        for i, summary in zip(members, summaries, strict=True):
            out[i] = summary
    return out


def _staged_summary(res: dict, dt: float) -> dict:
    """The chaos kind's results from :func:`~sinktheory.chaos.staged.staged_chaos`: the
    same means and standard errors over the runs, each exponent at its stopping time."""
    lam, trans = res["lambda1"], res["transverse"]
    out = {"lambda1_runs": lam.exponent, "dt_used": np.array(dt)}
    worst = lam.worst if trans is None else np.maximum(lam.worst, trans.worst)
    out["max_relative_energy_error"] = np.array(float(worst.max()))
    for name, s in (("lambda1", lam), ("transverse", trans)):
        if s is None:
            mean = se = periods = np.nan
        else:
            m, e = ensemble_mean(s.exponent[:, None])
            mean, se, periods = m[0], e[0], float(s.periods.max())
        out[name], out[f"{name}_se"] = np.array(mean), np.array(se)
        out[f"{name}_periods"] = np.array(periods)
    for name in ("gali", "mean_megno"):
        out[name] = out[f"{name}_se"] = np.array(np.nan)
    return out


def _chaos_summary(res, periods: int, transient: int) -> dict:
    """What the chaos kind stores of a ChaosResult: per-run lambda_1 (the growth after
    ``transient`` periods), ensemble means and standard errors, the audit, the step, and
    the periods each exponent ran; GALI and MEGNO as ``as_dict`` gives them."""
    from dataclasses import replace

    from ..chaos.staged import StagedExponent

    res = replace(res, transient=transient)
    exponents = {
        name: StagedExponent(rate, np.full(rate.size, periods), res.run_errors)
        for name, rate in (("lambda1", res.lambda1), ("transverse", res.transverse))
        if rate is not None
    }
    out = _staged_summary(
        {"lambda1": exponents["lambda1"], "transverse": exponents.get("transverse")},
        res.parameters["dt"],
    )
    d = res.as_dict()
    keys = {"gali": f"gali{res.gali_order}"}  # as_dict's name where it differs
    for name in ("gali", "mean_megno"):
        summary = d.get(keys[name] if name in keys else name, {})  # absent when not computed
        # None (absent, or a NaN in JSON) is stored as NaN
        out[name] = np.array(summary.get("mean"), dtype=float)
        out[f"{name}_se"] = np.array(summary.get("stderr"), dtype=float)
    return out
