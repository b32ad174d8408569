"""One design point of the ``design`` sweep kind: the ensemble, lambda_1 and the measures.

:func:`compute` is a pure function of (parameters, point seed): the ensemble is
:func:`sinktheory.simulate.simulate` with ``RunSettings(seed=point seed)`` recording the
container energy, the measures are :func:`~sinktheory.design.measures.design_measures`
(bootstrap seeded from the same seed), and lambda_1 is the mean over the first
``lyapunov_runs`` runs (same start positions) of :func:`sinktheory.chaos.chaos` over
``lyapunov_periods`` periods -- a finite-time estimate per unit time (times T = 2 pi:
the growth exponent per period) -- with those runs split into regular and chaotic ones
(:func:`sinktheory.chaos.verdicts.split`: a run is regular when its lambda_1 <=
3 ln t / t), since a mean over both groups is set by how many runs start in an island.
``lyapunov_runs = 0`` leaves them out (NaN); one run is refused, as in every sweep
(:func:`sinktheory.runstats.check_runs`: it has no standard error to judge lambda_1 by).
A user's well on the shape axis (:func:`user_shape`) has the equipartition share of its
own homogeneity (:func:`equipartition_n`): n is half the degree of V's leading term at the
centre, not a parameter the well may call n.

With a contact damping c0 = ``damping`` > 0 the ensemble is
:func:`sinktheory.damped.simulate_inelastic` instead (same start states, same
tolerance; the audit of H + W = H0 is the energy error reported), and the point also gets
the equivalent damping ratio zeta_eq of the container (mean over runs +- standard error)
and the share of H0 dissipated by the end.  lambda_1 is then left out (NaN: the chaos
indicators are of the conservative model); the equipartition share still compares with
the initial total energy, so its verdict is expected to be "below".  With c0 = 0,
zeta_eq and the dissipated share are exactly 0.

What ``damping`` means is set by ``damping_kind`` and reported in the result
``dashpot`` (1 or 0): for the 2-D well ``"contact"`` (the default, above: c0 per
particle, at the wall only) or ``"viscous"``, the 1-D attachments' dashpot on the
particles' velocity relative to the container everywhere in the well, c = ``damping``
shared by the k particles (c/k each, as :func:`sinktheory.attachments.impulse_response`
does for the well), so that a well and an NES at the same ``damping`` have equal
dashpots.  The 1-D attachments always use the dashpot (``damping_kind`` does not change
them).

The ``attachment`` dimension (default ``"well"``: everything above, unchanged) also runs
the 1-D absorbers of :mod:`sinktheory.attachments` at the point's mass: ``"nes"`` (one
particle on the line y = 0 of the point's well, force ~ x^(2n-1); n = 2 is the cubic
NES) and ``"impact"`` (the vibro-impact NES, clearance alpha - beta).  Their ensemble is
:func:`sinktheory.attachments.impulse_response` seeded with the point seed: an impulsive
start (container at X = 0 with energy E0, the particle at rest) instead of simulate's
start states, with ``damping`` the dashpot coefficient c on the particle's velocity
relative to the container (the viscous damper of the 1-D absorbers; 0: conservative).
zeta_eq is the same equivalent ratio W(t) / (2 integral E_c dt) (trapezoid rule over
``SAMPLES`` samples per period), lambda_1 is left out (NaN), and the equipartition
share is that of a particle on a line, E/(1 + k(1 + 1/n)/2), with n = oo for the
vibro-impact NES (:func:`sinktheory.sinkstats.equipartition_container_energy` with
d = 1).  They need particles = 1 and gamma = 1, and their start box is ``box`` times sqrt(2 E0)
(:func:`~sinktheory.attachments.impulse_response`); dt_used is the response's ``dt``
(NaN for the vibro-impact NES, whose flow is exact).

Examples
--------
>>> p = {"shape": "flat", "alpha": 0.5, "beta": 0.3, "n": 4, "gamma": 1.0,
...      "particles": 1, "mass": 0.2, "container_energy": 0.5, "runs": 2, "periods": 12,
...      "box": 0.01, "tol": 1e-6, "energy_bound": None, "horizons": "6+12",
...      "transient": None, "sigmas": 3.0, "risk_level": 0.5, "rqa_eps": 0.01,
...      "bootstrap": 10, "lyapunov_runs": 0, "lyapunov_periods": 10, "damping": 0.0,
...      "replica": 0}
>>> check(p)
>>> out = compute(p, seed=5)
>>> out["absorbed"].shape, out["mean_energy"].shape, bool(np.isnan(out["lambda1"]))
((2,), (13,), True)
>>> float(out["zeta_eq"]), float(compute({**p, "damping": 0.5}, seed=5)["zeta_eq"]) > 0
(0.0, True)
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .. import validation as v
from ..chaos.verdicts import SPLIT_RESULTS
from ..ensemble import settings_of, sink_of
from ..errors import ParameterError
from ..model import DAMPING_KINDS, MAX_PERIODS, RunSettings
from ..runstats import check_runs, ensemble_mean, mean_stderr
from ..stepsize import check_tol, step_of
from ..worklimit import DISSIPATIVE, check_particle_steps, ensemble_steps
from .measures import MAX_BOOTSTRAP, RQA_MEASURES, design_measures, horizons_of

__all__ = ["ENSEMBLE_RESULTS", "equipartition_n", "MAX_BOOTSTRAP", "SAMPLES"]

#: Results of a point that come from its ensemble (besides the container energy).
ENSEMBLE_RESULTS = (
    "dashpot",
    "max_relative_energy_error",
    "dt_used",
    "zeta_eq",
    "zeta_eq_se",
    "dissipated",
    "dissipated_se",
)


#: Samples per period of the 1-D attachments' records (for zeta_eq's integral).
SAMPLES = 16


def attachment_of(p: dict):
    """The :class:`~sinktheory.attachments.Attachment` of a 1-D design point (ParameterError
    naming the parameter a 1-D attachment cannot take)."""
    from ..attachments import Attachment

    if p["gamma"] != 1.0:
        raise ParameterError("gamma", p["gamma"], f"1 for the {p['attachment']} attachment")
    return Attachment(
        p["attachment"], p["shape"], p["alpha"], p["beta"], p["n"], p["particles"], p["mass"]
    )


def check(p: dict) -> None:
    """Raise ParameterError for anything the point cannot run with, naming the parameter;
    the step is chosen here, so a well too stiff for any step is named before anything
    runs, and the work (ensemble and lambda_1 runs with their tangent vector) is checked
    against the work limit (:mod:`sinktheory.worklimit`)."""
    sink = sink_of(p)
    settings = settings_of(p, 0)
    if hasattr(sink.well, "definition"):  # a user's well on the shape axis
        _check_user_well(p, sink.well)
    if p.get("attachment", "well") != "well":
        attachment_of(p)
    settings.check(sink)
    check_tol(p["tol"])
    scheme, _, steps, _ = step_of(
        sink, settings.total_energy_bound(sink), tol=p["tol"], settings=settings
    )
    v.positive_int("replica", p["replica"], minimum=0)
    v.positive_int("lyapunov_periods", p["lyapunov_periods"], maximum=MAX_PERIODS)
    if p["energy_bound"] is not None:
        v.positive("energy_bound", p["energy_bound"])
    horizons_of(p["horizons"], p["periods"])
    if p["transient"] is not None:
        v.positive_int("transient", p["transient"], minimum=0, maximum=p["periods"] - 1)
    v.positive("sigmas", p["sigmas"])
    if not 0 < v.positive("risk_level", p["risk_level"]) < 1:
        raise ParameterError("risk_level", p["risk_level"], "a fraction in (0, 1)")
    v.positive("rqa_eps", p["rqa_eps"])
    v.positive_int("bootstrap", p["bootstrap"], minimum=2, maximum=MAX_BOOTSTRAP)
    v.fits_memory(
        "bootstrap",
        p["bootstrap"],
        8.0 * p["bootstrap"] * (p["runs"] + p["periods"] + 1),
        f"{p['bootstrap']} resample(s) of {p['runs']} run(s) x {p['periods'] + 1} values",
        "smaller",
    )
    check_runs("runs", p["runs"])
    check_runs("lyapunov_runs", p["lyapunov_runs"], maximum=p["runs"], none=True)
    if p["lyapunov_runs"]:
        RunSettings(
            container_energy=p["container_energy"],
            runs=p["lyapunov_runs"],
            periods=p["lyapunov_periods"],
        ).check(sink)
    v.nonnegative("damping", p["damping"])
    v.choice("damping_kind", p.get("damping_kind", "contact"), DAMPING_KINDS)
    lyapunov = 0.0
    if p["lyapunov_runs"]:
        lyapunov = ensemble_steps(
            p["lyapunov_runs"], steps * p["lyapunov_periods"], p["particles"], 1, scheme
        )
    ensemble = ensemble_steps(p["runs"], steps * p["periods"], p["particles"], scheme=scheme)
    if p["damping"] > 0 or p.get("attachment", "well") == "nes":  # the damped engine
        ensemble *= DISSIPATIVE
    name = "periods" if ensemble >= lyapunov else "lyapunov_periods"
    check_particle_steps(
        name,
        p[name],
        ensemble + lyapunov,
        f"{p['runs']} run(s) x {p['periods']} period(s) and {p['lyapunov_runs']} lambda_1 "
        f"run(s) x {p['lyapunov_periods']} period(s) at {steps} steps per period",
    )


def user_shape(p: dict) -> bool:
    """Whether the point's shape is a user's well (named in its ``wells``)."""
    return "wells" in p and p["shape"] in json.loads(p["wells"])


def equipartition_n(p: dict) -> int | float:
    """The n of a point's equipartition share E/(1 + k (1 + 1/n)) (the virial theorem: a
    well homogeneous of degree 2n holds Theta/n of potential energy per particle against
    Theta of kinetic): a registered shape's n, and for a user's well half the degree of
    V's leading term at the centre (:attr:`sinktheory.wellat.WellAt.leading_order`, what
    the law of E_c reads too), whatever its parameters are called.  Exact for a
    homogeneous well; for another, the estimate of its leading order, as for a
    registered shape with beta != 0.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell, well_text
    >>> quartic = well_text(UserWell("quartic", "(x**2 + y**2)**2", {}))
    >>> equipartition_n({"shape": "quartic", "wells": json.dumps({"quartic": quartic}),
    ...                  "n": 4, "particles": 1, "mass": 0.2})
    2
    """
    if not isinstance(p, Mapping) or not {"shape", "n"} <= set(p):
        raise ParameterError("p", p, "a design point: a dict with its shape and n at least")
    if not user_shape(p):
        return v.stiffness("n", p["n"])
    return sink_of(p).well.leading_order.n


def _check_user_well(p: dict, well) -> None:
    """A user's well as a design: its leading term at the centre gives the equipartition
    share's n (:func:`equipartition_n`), and it is the 2-D well itself (the 1-D
    attachments are built from a registered shape)."""
    from ..errors import WellDefinitionError

    try:
        _ = well.leading_order  # decided (and cached) on first access
    except WellDefinitionError as exc:
        why = (
            "the design's equipartition share E/(1 + k (1 + 1/n)) reads n, half its degree: "
            f"{exc.value} is refused: {exc.allowed}"
        )
        allowed = "a well whose leading term at the centre is a form positive in every direction"
        raise ParameterError("shape", p["shape"], allowed, why=why) from None
    if p.get("attachment", "well") != "well":
        raise ParameterError("attachment", p["attachment"], f"well with the user's well "
                             f"{p['shape']} (the 1-D attachments take a registered "
                             "shape)")  # fmt: skip


def lyapunov(p: dict, seed: int) -> dict[str, float]:
    """lambda_1 (per unit time) of the first ``lyapunov_runs`` runs: their mean and its
    s.e. (``lambda1``, ``lambda1_se``), and the runs split into regular and chaotic ones
    (:data:`~sinktheory.chaos.verdicts.SPLIT_RESULTS`: where some runs start in an
    island, the mean mixes two groups and depends on the start box).  A user's well on
    the shape axis runs on its own engine, as the ensemble does.

    All NaN when ``lyapunov_runs`` is 0, the contact is damped (the chaos indicators are
    of the conservative model) or the attachment is 1-D.
    """
    none = dict.fromkeys(("lambda1", "lambda1_se", *SPLIT_RESULTS), math.nan)
    if not p["lyapunov_runs"] or p["damping"] > 0 or p.get("attachment", "well") != "well":
        return none
    from ..chaos import chaos

    settings = RunSettings(
        container_energy=p["container_energy"],
        runs=p["lyapunov_runs"],
        periods=p["lyapunov_periods"],
        seed=seed,
        box=p["box"],
    )
    res = chaos(sink_of(p), settings, progress=False)
    lam, lam_se = mean_stderr(res.lambda1)
    return {"lambda1": lam, "lambda1_se": lam_se, **res.split().stored()}


def ensemble(p: dict, seed: int) -> dict[str, Any]:
    """The point's ensemble: container energy (R, P + 1), H0 (R,), the largest energy
    (or audit) error, the step, and zeta_eq and the dissipated share of H0 with their
    standard errors (zeros without damping)."""
    from ..simulate import simulate

    if p.get("attachment", "well") != "well":
        return _impulse_ensemble(p, seed)
    sink, settings = sink_of(p), settings_of(p, seed)
    kind = p.get("damping_kind", "contact")
    dashpot = float(kind == "viscous")
    if p["damping"] > 0:
        from ..damped import simulate_inelastic

        c = p["damping"] / p["particles"] if dashpot else p["damping"]
        res = simulate_inelastic(sink, settings, damping=c, damping_kind=kind, tol=p["tol"],
                                 energy_bound=p["energy_bound"])  # fmt: skip
        zeta, zeta_se = res.equivalent_damping()
        share = res.dissipated[:, -1] / res.initial_energy
        return {
            "energy": res.container_energy,
            "h0": res.initial_energy,
            "dashpot": dashpot,
            "max_relative_energy_error": res.max_audit_error,
            "dt_used": res.dt,
            "zeta_eq": zeta,
            "zeta_eq_se": zeta_se,
            **dict(zip(("dissipated", "dissipated_se"), mean_stderr(share), strict=True)),
        }
    res = simulate(
        sink,
        settings,
        tol=p["tol"],
        energy_bound=p["energy_bound"],
        record=("container",),
        progress=False,
    )
    return {
        "energy": res.container_energy,
        "h0": res.initial_energy,
        "dashpot": dashpot,
        "max_relative_energy_error": res.max_relative_energy_error,
        "dt_used": res.dt,
        "zeta_eq": 0.0,
        "zeta_eq_se": 0.0,
        "dissipated": 0.0,
        "dissipated_se": 0.0,
    }


def _impulse_ensemble(p: dict, seed: int) -> dict[str, Any]:
    """:func:`ensemble` of a 1-D attachment: impulse responses (module docstring)."""
    from scipy.integrate import trapezoid

    from ..attachments import impulse_response

    res = impulse_response(
        attachment_of(p),
        p["container_energy"],
        damping=p["damping"],
        periods=p["periods"],
        runs=p["runs"],
        seed=seed,
        samples_per_period=SAMPLES,
        tol=p["tol"],
        box=p["box"],
        energy_bound=p["energy_bound"],
    )
    work = res.dissipated[:, -1]
    integral = trapezoid(res.container_energy, res.t, axis=1)
    zeta = work / (2.0 * integral)
    share = work / res.initial_energy
    return {
        "energy": res.container_energy[:, ::SAMPLES],
        "h0": res.initial_energy,
        "dashpot": 1.0,
        "max_relative_energy_error": res.max_audit_error,
        "dt_used": res.dt,
        **dict(zip(("zeta_eq", "zeta_eq_se"), mean_stderr(zeta), strict=True)),
        **dict(zip(("dissipated", "dissipated_se"), mean_stderr(share), strict=True)),
    }


def compute(p: dict, seed: int) -> dict[str, Any]:
    """Everything the ``design`` kind stores for one point (its results in
    :mod:`sinktheory.sweep.kinds`)."""
    ens = ensemble(p, seed)
    e = ens["energy"]
    total = float(ens["h0"].mean())
    m = design_measures(
        e,
        e0=p["container_energy"],
        total_energy=total,
        particles=p["particles"],
        n=equipartition_n(p),
        horizons=horizons_of(p["horizons"], p["periods"]),
        transient=p["transient"],
        sigmas=p["sigmas"],
        risk_level=p["risk_level"],
        rqa_eps=p["rqa_eps"],
        bootstrap=p["bootstrap"],
        seed=seed,
        attachment=p.get("attachment", "well"),
    )
    mean, stderr = ensemble_mean(e)
    out: dict[str, Any] = {
        "absorbed": m.absorbed,
        "absorbed_se": m.absorbed_se,
        "passage": m.passage,
        "passage_se": m.passage_se,
        "passage_reach": m.passage_reach,
        "long_time_mean": m.long_time_mean,
        "long_time_se": m.long_time_se,
        "equipartition": m.equipartition,
        "equipartition_z": m.equipartition_z,
        "verdict": float(m.verdict),
        "depth": m.depth,
        "depth_se": m.depth_se,
        "spread": m.spread,
        "spread_se": m.spread_se,
        "excursion": m.excursion,
        "excursion_se": m.excursion_se,
        **lyapunov(p, seed),
        "total_energy": total,
        "mean_energy": mean,
        "stderr": stderr,
        **{name: ens[name] for name in ENSEMBLE_RESULTS},
    }
    for name in RQA_MEASURES:
        out[f"rqa_{name}"] = m.rqa[name]
        out[f"rqa_{name}_se"] = m.rqa_se[name]
    return {k: np.asarray(x, dtype=float) for k, x in out.items()}
