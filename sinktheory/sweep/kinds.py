"""What a sweep can compute: one pure point function per kind.

Each kind lists its parameters (type, default, whether it may be swept), checks a point
with the model's own validators before anything runs, and computes a point as a pure
function of (parameters, point seed), returning a dict of arrays whose shapes depend only
on the fixed parameters.

=============  ==============================================  ===============================
kind           point function                                  results per point
=============  ==============================================  ===============================
floquet        :func:`sinktheory.floquet.model_hill` at one     lam, phi_half, phi, stable,
               beta (never batched: the integrator shares its   log_abs_phi_half,
               steps over a batch, which would make a value     rotation_number,
               depend on its neighbours)                        floquet_exponent
bifurcation    :func:`sinktheory.bifurcation.section`           section (sample)
ensemble       :func:`sinktheory.simulate.simulate`, seeded     mean_energy (period),
               with the point's seed                            stderr (period),
                                                                max_relative_energy_error,
                                                                dt_used
design         :func:`sinktheory.design.point.compute`: an      absorbed (horizon), passage
               ensemble, lambda_1 and the design measures       (level), long-time share and
               (:mod:`sinktheory.design.measures`)              equipartition verdict, spread,
                                                                lambda1, excursion, rqa_*,
                                                                zeta_eq, dissipated,
                                                                each with its ``*_se``
=============  ==============================================  ===============================

The bifurcation section starts from a fixed state and does not use the seed.  An ensemble
point's runs start from positions drawn with the point's seed; sweep ``replica=0:9:10`` to
repeat an ensemble with ten independent seeds.

Examples
--------
>>> kind = get_kind("floquet")
>>> point = kind.complete({"alpha": 0.5, "beta": -0.2, "n": 10})
>>> kind.check(point)
>>> out = kind.compute(point, seed=0)
>>> round(float(out["lam"]), 12), bool(out["stable"])
(0.28, True)
>>> kind.complete({"alpha": 0.5, "beta": 0.1, "n": 10, "mas": 1})
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: mas = 1 is not allowed: must be a parameter of a floquet \
sweep: alpha, amplitude, beta, gamma, n, rtol, shape
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import validation as v
from ..bifurcation import QUANTITIES
from ..design.measures import ATTACHMENTS
from ..ensemble import ENERGY_BOUND
from ..equilibrium import ergodicity as _ergodicity
from ..errors import ParameterError
from ..integrators import DEFAULT_SCHEME, SCHEMES, get_scheme
from ..limits import DEFAULT_RTOL
from ..model import DAMPING_KINDS, MAX_PERIODS, SHAPES, RunSettings, Sink, Well
from ..simulate import simulate
from ..stepsize import step_of
from ..worklimit import check_work

__all__ = [
    "DESIGN_TOL",
    "FLOQUET_RESULTS",
    "get_kind",
    "Kind",
    "KINDS",
    "Param",
    "REQUIRED",
    "Result",
    "SECONDS_PER_PERIOD",
    "SINK",
    "WELL",
]

REQUIRED = object()
#: Rough cost of one container period of one particle (n = 10, single thread: 24 sections
#: of 80 periods took 1.6 s); only used to decide whether to start local processes.
SECONDS_PER_PERIOD = 1e-3


@dataclass(frozen=True)
class Param:
    """One parameter of a kind: ``type`` float, int or str; ``default`` REQUIRED if none.

    ``sweepable`` is False for parameters that set the length of a result (a sweep's
    results must have the same shape at every point).
    """

    type: type
    default: Any = REQUIRED
    options: tuple[str, ...] | None = None
    sweepable: bool = True

    def coerce(self, name: str, value: Any) -> Any:
        """The value in canonical type; range checks are left to the model's validators."""
        if value is None and self.default is None:
            return None
        if self.type is str:
            if self.options is not None:
                return v.choice(name, value, self.options)
            if not isinstance(value, str):
                raise ParameterError(name, value, "a name")
            return value
        if self.type is int:
            if isinstance(value, bool):
                raise ParameterError(name, value, "an integer")
            if isinstance(value, numbers.Integral):
                return int(value)
            x = v.finite(name, value)
            if x != int(x):
                raise ParameterError(name, value, "an integer")
            return int(x)
        return v.finite(name, value)


@dataclass(frozen=True)
class Result:
    """One result variable: its extra dimensions (after the swept ones), dtype and fill."""

    dims: tuple[str, ...]
    dtype: str
    description: str


WELL = {
    "alpha": Param(float),
    "beta": Param(float),
    "n": Param(int),
    "gamma": Param(float, 1.0),
    "shape": Param(str, "flat", SHAPES),
}
SINK = {"particles": Param(int, 1), "mass": Param(float, 0.2), "energy": Param(float, 0.5)}


@dataclass(frozen=True)
class Kind:
    """A kind of sweep: parameters, results, checks and the point function.

    ``extra_coords(point)`` gives the coordinates of the result dimensions beyond the
    swept ones (they depend on fixed parameters only).  Grouping points into tasks
    (``batch``) never changes a result: each point is computed on its own, or together
    with others by ``compute_many`` to the same bits.
    """

    name: str
    params: dict[str, Param]
    results: dict[str, Result]
    check: Callable[[dict], None]
    compute: Callable[[dict, int], dict[str, Any]]
    extra_coords: Callable[[dict], dict[str, np.ndarray]] = field(default=lambda p: {})
    #: Optional: the points of a task [(params, seed), ...] computed together (for
    #: example as one vectorised ensemble); each output must equal ``compute`` of its
    #: point bitwise, so grouping still never changes a result.
    compute_many: Callable[[list], list[dict[str, Any]]] | None = None
    #: Points per task at most (cheap points are grouped to save scheduling overhead).
    batch: int = 1
    #: Rough seconds a point takes, to decide whether local processes are worth starting.
    cost: Callable[[dict], float] = lambda p: 1.0

    def complete(self, given: Mapping[str, Any]) -> dict[str, Any]:
        """Check names, add defaults, coerce types (values may be lists of values)."""
        for name in given:
            if name not in self.params:
                raise ParameterError(
                    name,
                    given[name],
                    f"a parameter of a {self.name} sweep: {', '.join(sorted(self.params))}",
                )
        out = {}
        for name, p in self.params.items():
            if name not in given:
                if p.default is REQUIRED:
                    raise ParameterError(name, None, "given (it has no default)")
                out[name] = p.default
                continue
            value = given[name]
            if isinstance(value, list | tuple | np.ndarray):
                values = [p.coerce(name, x) for x in np.asarray(value, dtype=object).ravel()]
                if len(values) > 1 and not p.sweepable:
                    raise ParameterError(
                        name, value, "a single value (it sets the length of the results)"
                    )
                if len(values) > 1 and name in self.results:
                    raise ParameterError(
                        name,
                        value,
                        f"a single value (a result of the {self.name} kind has this name, "
                        "so it cannot also label a swept dimension)",
                    )
                out[name] = values
            else:
                out[name] = p.coerce(name, value)
        return out


# --------------------------------------------------------------------------- floquet
def _floquet_check(p: dict) -> None:
    from ..floquet import model_problem  # the Floquet layer loads with its first point

    model_problem(
        p["alpha"],
        p["n"],
        gamma=p["gamma"],
        shape=p["shape"],
        amplitude=p["amplitude"],
        rtol=p["rtol"],
    ).check([p["beta"]])


def _floquet(p: dict, seed: int) -> dict[str, Any]:
    from ..floquet import model_hill

    c = model_hill(
        p["alpha"],
        [p["beta"]],
        p["n"],
        gamma=p["gamma"],
        shape=p["shape"],
        amplitude=p["amplitude"],
        rtol=p["rtol"],
    )
    items = c.items()  # the chart's quantities (sinktheory.results protocol)
    return {name: items["lambda" if name == "lam" else name][0] for name in FLOQUET_RESULTS}


FLOQUET_RESULTS = {
    "lam": Result((), "float64", "lambda = -2 beta (alpha - beta) of Hill's equation"),
    "phi_half": Result((), "float64", "half trace of the half-period map (+-inf beyond range)"),
    "phi": Result((), "float64", "phi_T = 2 phi_half^2 - 1 (+inf beyond float range)"),
    "stable": Result((), "bool", "normal mode y = 0 stable: |phi_half| < 1"),
    "log_abs_phi_half": Result((), "float64", "ln|phi_half|"),
    "rotation_number": Result((), "float64", "theta/pi, theta = arccos(phi_half)"),
    "floquet_exponent": Result((), "float64", "largest Floquet exponent (0 where stable)"),
}

# --------------------------------------------------------------------------- bifurcation


def _sink(p: dict) -> Sink:
    well = Well(p["alpha"], p["beta"], p["n"], gamma=p["gamma"], shape=p["shape"])
    return Sink(well, particles=p["particles"], mass=p["mass"])


def _bifurcation_check(p: dict) -> None:
    sink = _sink(p)
    if sink.particles != 1:
        raise ParameterError("particles", sink.particles, "1 for a bifurcation sweep")
    v.positive_int("transient", p["transient"], minimum=0, maximum=MAX_PERIODS)
    v.positive_int("count", p["count"], maximum=MAX_PERIODS)
    v.choice("quantity", p["quantity"], QUANTITIES)
    settings = RunSettings(energy=p["energy"], runs=1, periods=p["transient"] + p["count"])
    settings.check(sink)
    # a well too stiff to integrate names the parameter responsible, and the section's
    # periods are checked against the work limit
    _, _, steps, _ = step_of(sink, p["energy"], settings=settings)
    check_work(settings, sink, steps)


def _bifurcation(p: dict, seed: int) -> dict[str, Any]:
    return _bifurcation_many([(p, seed)])[0]


def _bifurcation_many(points: list) -> list[dict[str, Any]]:
    """Sections of a task's points, those sharing an engine and the section's settings as
    one ensemble whose runs carry their own parameters and steps
    (:func:`sinktheory.bifurcation.sections`)."""
    from ..bifurcation import sections

    groups: dict[tuple, list[int]] = {}
    for i, (p, _) in enumerate(points):
        key = (p["shape"], p["n"], p["transient"], p["count"], p["quantity"], p["energy"])
        groups.setdefault(key, []).append(i)
    out: list = [None] * len(points)
    for members in groups.values():
        first = points[members[0]][0]
        rows = sections(
            [_sink(points[i][0]) for i in members],
            transient=first["transient"],
            count=first["count"],
            quantity=first["quantity"],
            energy=first["energy"],
        )
        for i, row in zip(members, rows, strict=True):
            out[i] = {"section": row}
    return out


# --------------------------------------------------------------------------- ensemble
def _settings(p: dict, seed: int) -> RunSettings:
    return RunSettings(
        energy=p["energy"], runs=p["runs"], periods=p["periods"], seed=seed, box=p["box"]
    )


def _ensemble_check(p: dict) -> int:
    """Check an ensemble point; its steps per period (a well too stiff for any step
    names the parameter responsible, and the work is checked against the limit)."""
    sink, settings = _sink(p), _settings(p, 0)
    settings.check(sink)
    get_scheme(p["method"])
    if p["dt"] is not None:
        v.time_step("dt", p["dt"])
    v.positive("energy_bound", p["energy_bound"])
    v.positive_int("replica", p.get("replica", 0), minimum=0)
    energy = settings.total_energy_bound(sink)
    _, _, steps, _ = step_of(sink, energy, method=p["method"], dt=p["dt"], settings=settings)
    check_work(settings, sink, steps)
    return steps


def _ensemble(p: dict, seed: int) -> dict[str, Any]:
    res = simulate(
        _sink(p),
        _settings(p, seed),
        method=p["method"],
        dt=p["dt"],
        record=("container",),
        energy_bound=p["energy_bound"],
        progress=False,
    )
    r = res.items()  # the result's own fields and ensemble mean (sinktheory.results)
    return {
        "mean_energy": r["mean_energy"],
        "stderr": r["stderr"],
        "max_relative_energy_error": r["max_relative_energy_error"],
        "dt_used": r["dt"],
    }


# --------------------------------------------------------------------------- design
def _design_check(p: dict) -> None:
    from ..design.point import check  # the design package is loaded when a design runs

    check(p)


def _design(p: dict, seed: int) -> dict[str, Any]:
    from ..design.point import compute

    return compute(p, seed)


def _design_coords(p: dict) -> dict[str, np.ndarray]:
    from ..design.measures import ABSORBED_LEVELS, horizons_of

    return {
        "horizon": np.array(horizons_of(p["horizons"], p["periods"])),
        "level": np.array(ABSORBED_LEVELS),
        "period": np.arange(p["periods"] + 1),
    }


def _design_results() -> dict[str, Result]:
    scalar = {
        "long_time_mean": "long-time container energy (mean of the runs' time averages)",
        "equipartition": "equipartition share E_total / (1 + k (1 + 1/n)) (1-D: k/2)",
        "equipartition_z": "(long_time_mean - equipartition) / long_time_se",
        "verdict": "0 equipartition, +1 above it (drain incomplete), -1 below (within sigmas)",
        "depth": "long-time fraction of E0 absorbed, 1 - long_time_mean / E0",
        "spread": "run-to-run std of the runs' long-time means",
        "excursion": "longest excursion (periods) of <E> back above the risk level",
        "lambda1": "largest Lyapunov exponent (per unit time), mean of lyapunov_runs runs",
        "rqa_recurrence_rate": "RQA of <E>: recurrence rate",
        "rqa_determinism": "RQA of <E>: determinism",
        "rqa_laminarity": "RQA of <E>: laminarity",
        "rqa_trapping_time": "RQA of <E>: trapping time (periods)",
        "rqa_mean_recurrence_time": "RQA of <E>: mean recurrence time (periods)",
    }
    out = {
        "absorbed": Result(("horizon",), "float64", "1 - <E>(hT)/E0"),
        "absorbed_se": Result(("horizon",), "float64", "standard error of absorbed"),
        "passage": Result(("level",), "float64", "first period with <E> < (1 - level) E0"),
        "passage_se": Result(("level",), "float64", "bootstrap standard error of passage"),
        "passage_reach": Result(("level",), "float64", "share of bootstrap resamples reaching it"),
    }
    for name, text in scalar.items():
        out[name] = Result((), "float64", text)
        if name not in ("equipartition", "equipartition_z", "verdict"):
            out[f"{name}_se"] = Result((), "float64", f"standard error of {name}")
    out["long_time_se"] = out.pop("long_time_mean_se")
    out["total_energy"] = Result((), "float64", "total energy H0 (mean over runs)")
    out["max_relative_energy_error"] = Result((), "float64", "largest |H - H0|/H0 of all runs")
    out["dt_used"] = Result((), "float64", "integration step used")
    out["mean_energy"] = Result(("period",), "float64", "ensemble mean <E>(jT)")
    out["stderr"] = Result(("period",), "float64", "standard error of <E>(jT)")
    out["zeta_eq"] = Result((), "float64", "equivalent damping ratio of the container")
    out["zeta_eq_se"] = Result((), "float64", "standard error of zeta_eq")
    out["dissipated"] = Result((), "float64", "share of H0 dissipated (contact or dashpot)")
    out["dashpot"] = Result((), "float64", "1: damping by a dashpot, 0: inelastic wall contact")
    out["dissipated_se"] = Result((), "float64", "standard error of dissipated")
    return out


#: Default tolerance of the design kind: ensemble statistics carry standard errors of
#: ~1e-2, so an energy error of 1e-6 is ample, and the step is about half as costly.
DESIGN_TOL = 1e-6

KINDS = {
    "floquet": Kind(
        "floquet",
        {**WELL, "amplitude": Param(float, 1.0), "rtol": Param(float, DEFAULT_RTOL)},
        FLOQUET_RESULTS,
        _floquet_check,
        _floquet,
        batch=64,
        cost=lambda p: 1e-4,  # measured 6e-5 to 7e-5 s for n = 2 to 1000
    ),
    "bifurcation": Kind(
        "bifurcation",
        {
            **WELL,
            **SINK,
            "transient": Param(int, 200),
            "count": Param(int, 200, sweepable=False),
            "quantity": Param(str, "y", QUANTITIES),
        },
        {"section": Result(("sample",), "float64", "y(jT) or E(jT), j = transient + sample")},
        _bifurcation_check,
        _bifurcation,
        lambda p: {"sample": np.arange(1, p["count"] + 1)},
        batch=256,
        cost=lambda p: SECONDS_PER_PERIOD * (p["transient"] + p["count"]),
        compute_many=_bifurcation_many,
    ),
    "ensemble": Kind(
        "ensemble",
        {
            **WELL,
            **SINK,
            "runs": Param(int, 25),
            "periods": Param(int, 1500, sweepable=False),
            "box": Param(float, 0.01),
            "method": Param(str, DEFAULT_SCHEME, tuple(SCHEMES)),
            "dt": Param(float, None),
            "energy_bound": Param(float, ENERGY_BOUND),
            "replica": Param(int, 0),
        },
        {
            "mean_energy": Result(("period",), "float64", "ensemble mean <E>(jT)"),
            "stderr": Result(("period",), "float64", "standard error of <E>(jT)"),
            "max_relative_energy_error": Result((), "float64", "largest |H - H0|/H0 of all runs"),
            "dt_used": Result((), "float64", "integration step used"),
        },
        _ensemble_check,
        _ensemble,
        lambda p: {"period": np.arange(p["periods"] + 1)},
        cost=lambda p: SECONDS_PER_PERIOD * p["periods"] * p["runs"] * p["particles"],
    ),
    "design": Kind(
        "design",
        {
            **WELL,
            "alpha": Param(float, 0.5),
            **SINK,
            "runs": Param(int, 25),
            "periods": Param(int, 1500, sweepable=False),
            "box": Param(float, 0.01),
            "tol": Param(float, DESIGN_TOL),
            "energy_bound": Param(float, None),
            "horizons": Param(str, "auto", sweepable=False),
            "transient": Param(int, None),
            "sigmas": Param(float, 3.0),
            "risk_level": Param(float, 0.5),
            "rqa_eps": Param(float, 0.01),
            "bootstrap": Param(int, 50),
            "lyapunov_runs": Param(int, 10),
            "lyapunov_periods": Param(int, 100),
            "damping": Param(float, 0.0),
            "attachment": Param(str, "well", ATTACHMENTS),
            "damping_kind": Param(str, "contact", DAMPING_KINDS),
            "replica": Param(int, 0),
        },
        _design_results(),
        _design_check,
        _design,
        _design_coords,
        cost=lambda p: (
            SECONDS_PER_PERIOD
            * p["particles"]
            * (p["periods"] * p["runs"] + 2 * p["lyapunov_periods"] * p["lyapunov_runs"])
        ),
    ),
}


# --------------------------------------------------------------------------- chaos
def _chaos_check(p: dict) -> None:
    from ..chaos.general import check_gali, check_renorm
    from ..chaos.sink import check_tangent_work

    steps = _ensemble_check(p)
    check_renorm(p["renorm"])
    v.positive_int("megno", p["megno"], minimum=0, maximum=1)
    v.positive_int("transverse", p["transverse"], minimum=0, maximum=1)
    v.positive_int("stop_early", p["stop_early"], minimum=0, maximum=1)
    v.positive_int("transient", p["transient"], minimum=0, maximum=max(0, p["periods"] - 1))
    gali = check_gali(p["gali"], 1 + 2 * p["particles"])
    if p["stop_early"] and (gali or p["megno"]):
        raise ParameterError("stop_early", 1, "0 when gali or megno is asked for (they need "
                             "every run to the end)")  # fmt: skip
    check_tangent_work(_sink(p), _settings(p, 0), steps, None, gali, bool(p["transverse"]))


def _chaos(p: dict, seed: int) -> dict[str, Any]:
    """lambda_1 (and the transverse exponent, GALI_k, <Y>) of an ensemble seeded with the
    point's seed (:func:`sinktheory.chaos.chaos`): mean and standard error over the runs."""
    return _chaos_many([(p, seed)])[0]


def _chaos_step(p: dict, seed: int) -> float:
    """The point's step: ``dt`` if given, else the step for the default tolerance taken
    down to the ladder of :func:`sinktheory.stepsize.ladder_step`, so that neighbouring
    betas share a step count and fill the engine's blocks together."""
    from ..chaos.sink import start_energy
    from ..stepsize import ladder_step, resolve_step

    if p["dt"] is not None:
        return p["dt"]
    sink = _sink(p)
    top = start_energy(sink, _settings(p, seed), bool(p["transverse"]))
    return ladder_step(resolve_step(sink, top, method=p["method"])[1])[0]


def _chaos_many(points: list) -> list[dict[str, Any]]:
    """The points of a task grouped by engine, periods and analysis options, each group
    one ensemble whose runs carry their own parameters and steps
    (:func:`sinktheory.chaos.chaos_batch`, or with ``stop_early``
    :func:`sinktheory.chaos.staged.staged_chaos`): a chaos map over beta is one ensemble.
    Steps per run need ``renorm`` = 0 (it counts steps), so with renorm the step is part
    of the group."""
    groups: dict[tuple, list[int]] = {}
    steps = [_chaos_step(p, seed) for p, seed in points]
    for i, (p, _) in enumerate(points):
        same = ("shape", "n", "particles", "periods", "method", "gali", "megno", "transverse",
                "renorm", "energy_bound", "stop_early", "transient")  # fmt: skip
        key = (*(p[k] for k in same), steps[i] if p["renorm"] else None)
        groups.setdefault(key, []).append(i)
    out: list = [None] * len(points)
    for members in groups.values():
        first = points[members[0]][0]
        sinks = [_sink(points[i][0]) for i in members]
        settings = [_settings(points[i][0], points[i][1]) for i in members]
        options = {
            "dt": [steps[i] for i in members],
            "transverse": bool(first["transverse"]),
            "method": first["method"],
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


def _staged_summary(res: dict, dt: float) -> dict[str, Any]:
    """The chaos kind's results from :func:`~sinktheory.chaos.staged.staged_chaos`: the
    same means and standard errors over the runs, each exponent at its stopping time."""
    from ..sinkstats import ensemble_mean

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


def _chaos_summary(res, periods: int, transient: int) -> dict[str, Any]:
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


def _chaos_results() -> dict[str, Result]:
    text = {
        "lambda1": "maximal Lyapunov exponent per unit time (growth after the transient), "
        "mean over the runs",
        "transverse": "transverse exponent of y = 0 (NaN unless transverse = 1)",
        "gali": "GALI_k at the end, mean over the runs (NaN unless gali = k >= 2)",
        "mean_megno": "time-averaged MEGNO <Y> at the end (NaN unless megno = 1)",
    }
    out = {}
    for name, description in text.items():
        out[name] = Result((), "float64", description)
        out[f"{name}_se"] = Result((), "float64", f"standard error of {name} over the runs")
    out["lambda1_runs"] = Result(("run",), "float64", "lambda_1 of each run")
    for name in ("lambda1", "transverse"):
        out[f"{name}_periods"] = Result(
            (), "float64", f"periods {name} ran (fewer where stop_early settled it)"
        )
    out["max_relative_energy_error"] = Result((), "float64", "largest |H - H0|/H0 of all runs")
    out["dt_used"] = Result((), "float64", "integration step used")
    return out


#: The ``chaos`` kind (issue 12): chaos maps over any model parameter; lambda_1 from the
#: symplectic tangent map, costing ~3 plain runs (twice that with the transverse runs).
KINDS["chaos"] = Kind(
    "chaos",
    {
        **WELL,
        **SINK,
        "runs": Param(int, 8, sweepable=False),
        "periods": Param(int, 300),
        "box": Param(float, 0.01),
        "method": Param(str, DEFAULT_SCHEME, tuple(SCHEMES)),
        "dt": Param(float, None),
        "energy_bound": Param(float, ENERGY_BOUND),
        "renorm": Param(int, 0),
        "gali": Param(int, 0),
        "megno": Param(int, 0),
        "transverse": Param(int, 0),
        "stop_early": Param(int, 0),
        "transient": Param(int, 0),
        "replica": Param(int, 0),
    },
    _chaos_results(),
    _chaos_check,
    _chaos,
    lambda p: {"run": np.arange(p["runs"])},
    batch=256,
    cost=lambda p: (
        3 * (1 + p["transverse"]) * SECONDS_PER_PERIOD * p["periods"] * p["runs"] * p["particles"]
    ),
    compute_many=_chaos_many,
)


#: The ``ergodicity`` kind (issue 21): the runs' late E_c against the exact equilibrium
#: law (KS distance, tail ratios) beside lambda_1; the code is
#: :mod:`sinktheory.equilibrium.ergodicity`.
KINDS["ergodicity"] = Kind(
    "ergodicity",
    {
        **WELL,
        **SINK,
        **{
            name: Param(type(value), value, sweepable=name != "fractions")
            for name, value in _ergodicity.DEFAULTS.items()
        },
        "replica": Param(int, 0),
    },
    {name: Result(dims, "float64", text) for name, (dims, text) in _ergodicity.RESULTS.items()},
    _ergodicity.check_point,
    _ergodicity.ergodicity_point,
    lambda p: {"fraction": _ergodicity.fractions_of(p["fractions"])},
    cost=lambda p: (
        SECONDS_PER_PERIOD
        * p["particles"]
        * (p["periods"] * p["runs"] + 3 * p["lyapunov_periods"] * p["lyapunov_runs"])
    ),
)


def get_kind(name: str) -> Kind:
    """The kind called ``name`` (ParameterError naming ``kind`` otherwise)."""
    return KINDS[v.choice("kind", name, tuple(KINDS))]
