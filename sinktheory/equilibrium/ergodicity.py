"""Ergodicity map: where the runs sample the equilibrium law, beside the chaos map lambda_1.

For one parameter point, :func:`ergodicity_point` simulates ``runs`` runs of ``periods``
periods, compares E_c after ``transient`` periods with the law
(:func:`~sinktheory.equilibrium.lifetime.compare_with_law`: KS distance and its
run-bootstrap p-value, the mean's z, the tail ratios occupation / P with errors) and,
with ``lyapunov_runs`` > 0, computes the maximal Lyapunov exponent lambda_1 of a small
ensemble (:func:`sinktheory.chaos.chaos`).  The verdict, a stated rule:

* **chaotic** when lambda_1 - 2 se(lambda_1) > 3 ln t / t (se over the Lyapunov runs, t
  their time: :func:`sinktheory.chaos.verdicts.chaotic`, the chaos map's rule; a regular
  orbit's finite-time exponent decays like ln t / t, so "> 0" called regular runs
  chaotic), else **regular**; where the Lyapunov runs split into regular and chaotic ones
  (:func:`sinktheory.chaos.verdicts.split`: a run is regular when its lambda_1 <=
  3 ln t / t), the point also reports how many are regular and lambda_1 of each group,
  since their mean depends on the starts (the box, :data:`DEFAULTS`);
* **sampling the law** when the KS p-value > :data:`P_LEVEL` and |mean z| < 3;
* verdict 2 = chaotic and sampling the law (ergodic as far as the runs tell),
  1 = chaotic but not sampling it (islands, slow mixing, or a transient too short),
  0 = regular; -1 = undecided (no Lyapunov runs).

The law is that of one total energy, the runs' mean, so the runs must share it: a start
box in which particles at rest could add more than ``ENERGY_SLACK`` of E0 to a run's
total energy is refused before anything runs, naming ``box`` and the largest box that
keeps the runs on one shell (:func:`~sinktheory.equilibrium.lifetime.check_one_shell`;
near the symmetric well's corner saddle the default box reaches high up the well).

The sweep kind ``ergodicity`` (:mod:`sinktheory.sweep.kinds`) computes the same point
function over any grid of parameters; :func:`ergodicity_map` runs it over a list of beta
for the chart (:func:`sinktheory.plot.equilibrium.plot_ergodicity`).

Examples
--------
>>> out = ergodicity_point(
...     {"alpha": 0.5, "beta": 0.3, "n": 4, "runs": 2, "periods": 40, "transient": 10,
...      "lyapunov_runs": 0}, seed=1)
>>> sorted(out)[:4], int(out["verdict"])
(['autocorrelation_time', 'kac_periods', 'ks_distance', 'ks_pvalue'], -1)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..chaos.verdicts import SPLIT_RESULTS
from ..results import Result
from ..runstats import check_runs
from .law import check_fractions
from .lifetime import check_one_shell

__all__ = [
    "DEFAULTS",
    "ergodicity_map",
    "ergodicity_point",
    "ErgodicityMap",
    "fractions_of",
    "P_LEVEL",
    "RESULTS",
]

#: KS p-value below which the runs are said not to sample the law.
P_LEVEL = 0.01
#: The point's parameters beyond the well and the sink, with defaults.
DEFAULTS = {
    "runs": 8,
    "periods": 3000,
    "transient": 1000,
    "box": 0.01,
    "tol": 1e-8,
    "fractions": "0.2,0.5,0.8",
    "lyapunov_runs": 4,
    "lyapunov_periods": 200,
}
#: Results: name -> (extra dimensions, description).
RESULTS = {
    "law_mean": ((), "the law's <E_c>"),
    "mean": ((), "measured <E_c> after the transient"),
    "mean_z": ((), "(measured - law) / standard error across runs"),
    "ks_distance": ((), "sup |F_hat - F| of E_c / E"),
    "ks_pvalue": ((), "run-bootstrap p-value of the KS distance"),
    "autocorrelation_time": ((), "integrated autocorrelation time of E_c (periods)"),
    "tail_ratio": (("fraction",), "occupation of {E_c >= f E} over the law's P"),
    "tail_ratio_se": (("fraction",), "standard error of tail_ratio (jackknife over runs)"),
    "kac_periods": (("fraction",), "Kac's mean return time 1/P (periods)"),
    "return_time": (("fraction",), "measured mean return time (periods)"),
    "lambda1": ((), "maximal Lyapunov exponent (per unit time; NaN without Lyapunov runs)"),
    "lambda1_se": ((), "standard error of lambda1 over the Lyapunov runs"),
    **{name: ((), text) for name, text in SPLIT_RESULTS.items()},
    "verdict": (
        (),
        "2 chaotic and sampling the law, 1 chaotic not sampling it, 0 regular, -1 undecided",
    ),
}


def fractions_of(text: str) -> np.ndarray:
    """The fractions of a comma-separated string ("0.2,0.5,0.8")."""
    try:
        values = [float(x) for x in str(text).split(",")]
    except ValueError:
        raise v.ParameterError("fractions", text, "comma-separated numbers in (0, 1)") from None
    return check_fractions(values)


def _sink_settings(p: dict, seed: int):
    """The point's sink and run settings, the model's defaults (:data:`MODEL`) and the
    start box filled in."""
    from ..ensemble import settings_of, sink_of

    given = {name: value for name, value in MODEL.items() if value is not None}
    point = {**given, "box": DEFAULTS["box"], **p}
    return sink_of(point), settings_of(point, seed)


#: The well's and the sink's parameters a point takes (alpha, beta and n required).
MODEL = {"alpha": None, "beta": None, "n": None, "gamma": 1.0, "shape": "flat",
         "particles": 1, "mass": 0.2, "container_energy": 0.5}  # fmt: skip
#: Set by a sweep to tell replicas of one point apart (their seeds differ).
REPLICA = "replica"


def check_point(p: dict) -> None:
    """Refuse a point before anything runs: unknown or missing parameters, and every
    value the simulation and the Lyapunov ensemble would refuse (the model's validators,
    the memory and work limits), each named by the point's parameter (a Lyapunov
    ensemble's refusal names ``lyapunov_runs`` or ``lyapunov_periods``)."""
    from dataclasses import replace

    from ..chaos.sink import check_tangent_work
    from ..stepsize import check_tol, step_of
    from ..worklimit import check_work

    if not isinstance(p, dict):
        raise v.ParameterError("p", p, "a dict of the point's parameters")
    allowed = (*MODEL, *DEFAULTS, REPLICA)
    if "well" in p:  # a user's well (its text): its own parameters replace the shape's
        from ..userwell import read_well

        own = read_well(p["well"]).parameter_names
        allowed = ("well", *own, "particles", "mass", "container_energy", *DEFAULTS, REPLICA)
    for name in p:
        if name not in allowed:
            raise v.ParameterError(name, p[name], f"a parameter of a point: {', '.join(allowed)}")
    for name, default in MODEL.items():
        if default is None and name not in p and "well" not in p:
            raise v.ParameterError(name, "missing", "given (alpha, beta and n are required)")
    p = {**DEFAULTS, **p}
    sink, settings = _sink_settings(p, 0)
    settings.check(sink)
    check_one_shell(sink, settings)
    check_runs("runs", p["runs"])
    v.positive_int("transient", p["transient"], minimum=0, maximum=p["periods"] - 4)
    fractions_of(p["fractions"])
    v.positive_int(REPLICA, p.get(REPLICA, 0), minimum=0)
    tol = check_tol(p["tol"])
    scheme, _, steps, _ = step_of(sink, settings.total_energy_bound(sink), tol=tol,
                                  settings=settings)  # fmt: skip
    check_work(settings, sink, steps, scheme)
    lyapunov_runs = check_runs("lyapunov_runs", p["lyapunov_runs"], none=True)
    periods = v.positive_int("lyapunov_periods", p["lyapunov_periods"])
    if lyapunov_runs:
        try:
            lyapunov = replace(settings, runs=lyapunov_runs, periods=periods)
            lyapunov.check(sink)
            check_tangent_work(sink, lyapunov, steps, None, 0, False, scheme)
        except v.ParameterError as e:
            if e.name not in ("runs", "periods"):
                raise
            named = v.ParameterError(f"lyapunov_{e.name}", e.value, e.allowed)
            named.args = (str(e).replace(e.name, named.name, 1),)  # the same reason
            raise named from None


def verdict(
    lambda1: float, lambda1_se: float, periods: int, ks_pvalue: float, mean_z: float
) -> int:
    """The rule of the module docstring (``periods``: the Lyapunov runs' length).

    Examples
    --------
    >>> verdict(0.0036, 0.0003, 600, 0.5, 0.1), verdict(0.3, 0.01, 600, 0.5, 0.1)
    (0, 2)
    """
    from ..chaos.verdicts import chaotic

    if not (math.isfinite(lambda1) and math.isfinite(lambda1_se)):
        return -1  # no exponent, or one run: no standard error to judge it by
    if not chaotic(lambda1, lambda1_se, periods):
        return 0
    return 2 if ks_pvalue > P_LEVEL and abs(mean_z) < 3 else 1


def ergodicity_point(p: dict, seed: int) -> dict:
    """Results of :data:`RESULTS` at one parameter point (dict of the well, sink and
    :data:`DEFAULTS` parameters), runs seeded with ``seed``."""
    from ..equilibrium import equilibrium_law
    from ..simulate import simulate
    from .lifetime import compare_with_law

    check_point(p)
    seed = v.positive_int("seed", seed, minimum=0)
    p = {**DEFAULTS, **p}
    sink, settings = _sink_settings(p, seed)
    sim = simulate(sink, settings, tol=p["tol"], progress=False)
    law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
    c = compare_with_law(
        sim.container_energy,
        law,
        transient=p["transient"],
        fractions=fractions_of(p["fractions"]),
        seed=seed,
    )
    lam, lam_se = math.nan, math.nan
    groups = dict.fromkeys(SPLIT_RESULTS, math.nan)
    if p["lyapunov_runs"] > 0:
        from dataclasses import replace

        from ..chaos import chaos

        res = chaos(
            sink,
            replace(settings, runs=p["lyapunov_runs"], periods=p["lyapunov_periods"]),
            tol=p["tol"],
            progress=False,
        )
        summary = res.as_dict()["lambda1"]
        lam = float(summary["mean"])
        lam_se = math.nan if summary["stderr"] is None else float(summary["stderr"])
        groups = res.split().stored()
    mean_z = (c.mean - law.mean) / c.mean_stderr if c.mean_stderr > 0 else math.nan
    return {
        "law_mean": law.mean,
        "mean": c.mean,
        "mean_z": mean_z,
        "ks_distance": c.ks_distance,
        "ks_pvalue": c.ks_pvalue,
        "autocorrelation_time": c.autocorrelation_time,
        "tail_ratio": c.occupation / c.tails,
        "tail_ratio_se": c.occupation_stderr / c.tails,
        "kac_periods": c.kac_periods,
        "return_time": c.return_time,
        "lambda1": lam,
        "lambda1_se": lam_se,
        **groups,
        "verdict": verdict(lam, lam_se, p["lyapunov_periods"], c.ks_pvalue, mean_z),
    }


@dataclass(frozen=True)
class ErgodicityMap(Result):
    """:func:`ergodicity_point` over a list of beta (other parameters fixed)."""

    beta: np.ndarray
    fractions: np.ndarray
    parameters: dict
    law_mean: np.ndarray
    mean: np.ndarray
    mean_z: np.ndarray
    ks_distance: np.ndarray
    ks_pvalue: np.ndarray
    autocorrelation_time: np.ndarray
    tail_ratio: np.ndarray
    tail_ratio_se: np.ndarray
    lambda1: np.ndarray
    lambda1_se: np.ndarray
    regular_runs: np.ndarray
    lambda1_regular: np.ndarray
    lambda1_regular_se: np.ndarray
    lambda1_chaotic: np.ndarray
    lambda1_chaotic_se: np.ndarray
    verdict: np.ndarray

    DIMS = {
        **{name: ("beta",) for name in RESULTS if not RESULTS[name][0]},
        "tail_ratio": ("beta", "fraction"),
        "tail_ratio_se": ("beta", "fraction"),
    }
    COORDS = {"fractions": "fraction"}


def ergodicity_map(
    betas,
    *,
    alpha: float,
    n: int,
    gamma: float = MODEL["gamma"],
    shape: str = MODEL["shape"],
    particles: int = MODEL["particles"],
    mass: float = MODEL["mass"],
    container_energy: float = MODEL["container_energy"],
    runs: int = DEFAULTS["runs"],
    periods: int = DEFAULTS["periods"],
    transient: int = DEFAULTS["transient"],
    box: float = DEFAULTS["box"],
    tol: float = DEFAULTS["tol"],
    fractions: str = DEFAULTS["fractions"],
    lyapunov_runs: int = DEFAULTS["lyapunov_runs"],
    lyapunov_periods: int = DEFAULTS["lyapunov_periods"],
    seed: int = 0,
    progress: bool = True,
) -> ErgodicityMap:
    """:func:`ergodicity_point` at each beta of ``betas``, the other parameters of a point
    (:data:`MODEL`, :data:`DEFAULTS`) as keyword arguments, every point seeded with
    ``seed``; every point is checked before the first runs.

    Examples
    --------
    >>> m = ergodicity_map([0.2, 0.3], alpha=0.5, n=4, runs=2, periods=40, transient=10,
    ...                    lyapunov_runs=0, progress=False)
    >>> m.verdict.tolist(), m.tail_ratio.shape
    ([-1, -1], (2, 3))
    """
    parameters = dict(alpha=alpha, n=n, gamma=gamma, shape=shape, particles=particles,
                      mass=mass, container_energy=container_energy, runs=runs,
                      periods=periods, transient=transient, box=box, tol=tol,
                      fractions=fractions, lyapunov_runs=lyapunov_runs,
                      lyapunov_periods=lyapunov_periods)  # fmt: skip
    seed = v.positive_int("seed", seed, minimum=0)
    progress = v.flag("progress", progress)
    from ..progress import ProgressBar

    betas = np.atleast_1d(v.finite_array("betas", betas, "finite numbers (the points' beta)"))
    if betas.ndim != 1 or not betas.size:
        raise v.ParameterError("betas", f"an array of shape {betas.shape}", "one or more beta")
    points = [{**parameters, "beta": float(b)} for b in betas]
    for p in points:
        check_point(p)
    bar = ProgressBar(len(points), enabled=progress, label="ergodicity ")
    rows = []
    for p in points:
        rows.append(ergodicity_point(p, seed))
        bar.update(1)
    bar.close()
    return ErgodicityMap(
        beta=betas,
        fractions=fractions_of(fractions),
        parameters=parameters,
        **{
            name: np.array([r[name] for r in rows])
            for name in RESULTS
            if name not in ("kac_periods", "return_time")
        },
    )
