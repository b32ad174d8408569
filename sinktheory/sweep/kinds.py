"""What a sweep can compute: one pure point function per kind.

Each kind lists its parameters (type, default, whether it may be swept), checks a point
with the model's own validators before anything runs, and computes a point as a pure
function of (parameters, point seed), returning a dict of arrays whose shapes depend only
on the fixed parameters.  The work of each kind lives in its analysis package, loaded at
the first point: ``check_point`` and ``point`` (or ``points``, many at once) of
:mod:`sinktheory.floquet`, :mod:`sinktheory.bifurcation`, :mod:`sinktheory.simulate`,
:mod:`sinktheory.chaos.points` and :mod:`sinktheory.equilibrium.ergodicity`, and
:mod:`sinktheory.design.point`; this table holds only what a kind takes and stores.

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
                                                                each with its ``*_se``;
                                                                regular_runs and lambda_1
                                                                of each group
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

import json
import numbers
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from importlib import import_module
from typing import Any

import numpy as np

from .. import validation as v
from ..bifurcation import QUANTITIES
from ..chaos.verdicts import SPLIT_RESULTS
from ..design.measures import ATTACHMENTS
from ..ensemble import ENERGY_BOUND
from ..equilibrium import ergodicity as _ergodicity
from ..errors import ParameterError
from ..glossary import RENAMED_PARAMETERS
from ..integrators import DEFAULT_SCHEME, SCHEMES
from ..limits import DEFAULT_RTOL
from ..model import DAMPING_KINDS, SHAPES

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


def _lazy(module: str, name: str) -> Callable:
    """The function ``name`` of the analysis module ``module`` (relative to the package),
    imported at its first call: every kind's work lives in its own package, and this
    table loads none of them."""

    def call(*args, **kwargs):
        return getattr(import_module(module, "sinktheory"), name)(*args, **kwargs)

    call.__name__ = call.__qualname__ = f"{module.lstrip('.')}.{name}"
    return call


def _one(many: Callable) -> Callable:
    """A point function from a function of many points (grouping never changes a result)."""
    return lambda p, seed: many([(p, seed)])[0]


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
SINK = {
    "particles": Param(int, 1),
    "mass": Param(float, 0.2),
    "container_energy": Param(float, 0.5),
}


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
    #: Whether the kind takes a user's well (``well``, see :meth:`complete`).
    user_well: bool = False
    #: Whether ``shape`` also takes users' wells, beside the registered shapes (see
    #: :meth:`complete`).
    shape_wells: bool = False

    def complete(self, given: Mapping[str, Any]) -> dict[str, Any]:
        """Check names, add defaults, coerce types (values may be lists of values).  An old
        name (:data:`sinktheory.glossary.RENAMED_PARAMETERS`) is taken for its new one,
        with a DeprecationWarning.

        ``well`` (a :class:`~sinktheory.userwell.UserWell`, or the TOML text of its well
        file) puts a user's well in place of the shape parameters :data:`WELL`: its own
        parameters, with its defaults, take their place (each may be swept), and the
        well's text (:func:`~sinktheory.userwell.well_text`) becomes the fixed parameter
        ``well``, so that the store keeps it and every worker rebuilds the same well.

        A kind whose ``shape`` takes users' wells (``shape_wells``: design) takes a
        :class:`~sinktheory.userwell.UserWell` among the values of ``shape``: the well's
        name labels it, and the fixed parameter ``wells`` (JSON: name -> the well's text)
        keeps its definition.  Its parameters named like the kind's alpha, beta, n or
        gamma take the point's values, the others their defaults."""
        if not isinstance(given, Mapping):
            raise ParameterError("given", given, "a mapping of parameter names to values")
        given = _modern_names(given)
        table, own = self.params, None
        if "well" in given:
            given = dict(given)
            given["well"], table, own = self._with_well(given["well"])
        if self.shape_wells and "shape" in given:
            given = dict(given)
            given["shape"], wells = _shape_wells(given["shape"])
            if wells:
                names = (*table["shape"].options, *sorted(wells))
                table = {**table, "shape": Param(str, "flat", names),
                         "wells": Param(str, sweepable=False)}  # fmt: skip
                given["wells"] = json.dumps(wells, sort_keys=True)
        for name in given:
            if name not in table and own is not None and name in WELL:
                listed = ", ".join(own) or "none"
                raise ParameterError(name, given[name], "left out beside a well (it defines "
                                     f"the shape; its parameters: {listed})")  # fmt: skip
            if name not in table:
                raise ParameterError(
                    name,
                    given[name],
                    f"a parameter of a {self.name} sweep: {', '.join(sorted(table))}",
                )
        out = {}
        for name, p in table.items():
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

    def _with_well(self, well: Any) -> tuple[str, dict[str, Param], tuple[str, ...]]:
        """(the well's text, this kind's parameters with the well's in place of WELL, the
        well's parameter names)."""
        from ..userwell import UserWell, read_well, well_text

        if self.shape_wells:
            raise ParameterError("well", getattr(well, "name", well), f"on the shape axis of "
                                 f"a {self.name} sweep (shape = [..., the well]; on the "
                                 "command line, --well FILE adds it there)")  # fmt: skip
        if not self.user_well:
            takes = ", ".join(k.name for k in KINDS.values() if k.user_well)
            raise ParameterError("well", getattr(well, "name", well), f"left out of a "
                                 f"{self.name} sweep (the kinds that take a well: "
                                 f"{takes})")  # fmt: skip
        if isinstance(well, str):
            well = read_well(well)
        if not isinstance(well, UserWell):
            raise ParameterError("well", well, "a sinktheory.userwell.UserWell or its TOML text")
        own = {name: p for name, p in self.params.items() if name not in WELL}
        clash = [name for name in well.parameter_names if name in own or name == "well"]
        if clash:
            raise ParameterError(
                "well", well.name, f"a well whose parameters are not named like the "
                f"{self.name} sweep's settings ({', '.join(clash)} is one)",
            )  # fmt: skip
        table = {p.name: Param(float, p.default) for p in well.parameters}
        table = {**table, **own, "well": Param(str, sweepable=False)}
        return well_text(well), table, well.parameter_names


def _shape_wells(shape: Any) -> tuple[Any, dict[str, str]]:
    """``shape`` with each UserWell among its values replaced by its name, and the wells'
    texts by name (two different wells of one name refused)."""
    from ..userwell import UserWell, well_text

    many = isinstance(shape, list | tuple | np.ndarray)
    values = list(np.asarray(shape, dtype=object).ravel()) if many else [shape]
    wells: dict[str, str] = {}
    for i, value in enumerate(values):
        if isinstance(value, UserWell):
            text = well_text(value)
            if wells.setdefault(value.name, text) != text:
                raise ParameterError("shape", value.name, "wells of different names (two "
                                     "different wells are called so)")  # fmt: skip
            values[i] = value.name
    return (values if many else values[0]), wells


def _modern_names(given: Mapping[str, Any]) -> dict[str, Any]:
    """``given`` with its old parameter names renamed, each with a DeprecationWarning."""
    out = {}
    for name, value in given.items():
        new = RENAMED_PARAMETERS.get(name)
        if new is not None:
            warnings.warn(
                f"sweep: the parameter {name!r} is now {new!r} (the old name goes in the next "
                "release)",
                DeprecationWarning,
                stacklevel=4,
            )
            if new in given:
                raise ParameterError(name, value, f"left out: {new} is given too")
            name = new
        out[name] = value
    return out


# --------------------------------------------------------------------------- floquet
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


# --------------------------------------------------------------------------- ensemble
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
    for name, text in SPLIT_RESULTS.items():
        out[name] = Result((), "float64", text)
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
        _lazy(".floquet", "check_point"),
        _lazy(".floquet", "point"),
        batch=64,
        cost=lambda p: 1e-4 if "well" not in p else 0.5,  # measured 6e-5 to 7e-5 s for
        # n = 2 to 1000; a user's well: its check and Hill equation, 0.4 s (notebook)
        user_well=True,
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
        _lazy(".bifurcation", "check_point"),
        _one(_lazy(".bifurcation", "points")),
        lambda p: {"sample": np.arange(1, p["count"] + 1)},
        batch=256,
        cost=lambda p: SECONDS_PER_PERIOD * (p["transient"] + p["count"]),
        compute_many=_lazy(".bifurcation", "points"),
        user_well=True,
    ),
    "ensemble": Kind(
        "ensemble",
        {
            **WELL,
            **SINK,
            "runs": Param(int, 25),
            "periods": Param(int, 1500, sweepable=False),
            "box": Param(float, 0.01),
            "scheme": Param(str, DEFAULT_SCHEME, tuple(SCHEMES)),
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
        _lazy(".simulate", "check_point"),
        _lazy(".simulate", "point"),
        lambda p: {"period": np.arange(p["periods"] + 1)},
        cost=lambda p: SECONDS_PER_PERIOD * p["periods"] * p["runs"] * p["particles"],
        user_well=True,
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
        shape_wells=True,
    ),
}


# --------------------------------------------------------------------------- chaos
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
        "scheme": Param(str, DEFAULT_SCHEME, tuple(SCHEMES)),
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
    _lazy(".chaos.points", "check_point"),
    _one(_lazy(".chaos.points", "points")),
    lambda p: {"run": np.arange(p["runs"])},
    batch=256,
    cost=lambda p: (
        3 * (1 + p["transverse"]) * SECONDS_PER_PERIOD * p["periods"] * p["runs"] * p["particles"]
    ),
    compute_many=_lazy(".chaos.points", "points"),
    user_well=True,
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
    user_well=True,
)


def get_kind(name: str) -> Kind:
    """The kind called ``name`` (ParameterError naming ``kind`` otherwise)."""
    return KINDS[v.choice("kind", name, tuple(KINDS))]
