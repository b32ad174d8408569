"""The design report: ranked designs, charts and ``report.md`` in one directory.

:func:`write_report` writes into a directory:

* ``report.md`` -- what was swept, the rules behind every number, the recommended designs
  with their numbers and standard errors, the equipartition verdicts, the cost;
* ``designs.csv`` -- every computed design, ranked, with all its measures;
* ``pareto.png`` -- speed against depth against reliability
  (:func:`sinktheory.plot.design.pareto_chart`);
* ``heatmap_<y>_<x>.png`` -- one per pair of swept parameters
  (:func:`sinktheory.plot.design.heatmap`);
* ``energy.png`` -- <E>(jT) of the recommended designs.

Beside each recommended design's measures the report gives its predicted settling time
(:mod:`.settling`: when the mean container energy comes within 5 % of the exact law,
predicted from short runs on the energy shell, with the model's interval), unless
``settling=False``.

Examples
--------
>>> rows = [{"rank": 1, "layer": 1, "n": 4, "depth": 0.6, "depth_se": 0.01}]
>>> fmt(rows[0]["depth"], rows[0]["depth_se"])
'0.600 ± 0.010'
"""

from __future__ import annotations

import csv
import math
import os
import time
from pathlib import Path

import numpy as np

from .. import validation as v
from ..chaos.verdicts import box_starts
from ..equilibrium.prediction import MODEL_FACTOR, Settling
from ..errors import ParameterError
from ..plot.design import label, swept
from .measures import VERDICTS
from .ranking import design_dataset, rank
from .settling import SETTLING_FIELDS, settling_column, settling_fields, settling_text


def _ranked(ranked) -> list:
    """``ranked`` if it is a ranking as :func:`~.ranking.rank` returns it."""
    rows = ("rank", "layer", "depth")
    if not isinstance(ranked, list | tuple) or not all(
        isinstance(r, dict) and all(k in r for k in rows) for r in ranked
    ):
        shown = type(ranked).__name__
        raise ParameterError("ranked", shown, "None or the list of rows of rank(ds)")
    return list(ranked)


def _predicted(predicted, shown: list) -> tuple:
    """``predicted`` if it holds (rank -> settling, seconds) for the ``shown`` rows."""
    allowed = "None or (rank -> predicted settling of the top rows, seconds), as made by "
    allowed += "settling_column"
    ok = isinstance(predicted, tuple | list) and len(predicted) == 2
    if ok:
        column, seconds = predicted
        ok = (
            isinstance(column, dict)
            and all(isinstance(column.get(r["rank"]), Settling | str) for r in shown)
            and not isinstance(seconds, bool)
            and isinstance(seconds, int | float)
            and math.isfinite(seconds)
            and seconds >= 0
        )
    if not ok:
        raise ParameterError("predicted", type(predicted).__name__, allowed)
    return tuple(predicted)


def _directory(directory) -> Path:
    """The report's directory, created if needed (ParameterError naming ``directory`` if
    it is no path or cannot be written in)."""
    if not isinstance(directory, str | os.PathLike) or not str(directory).strip():
        raise ParameterError("directory", directory, "the path of a directory (a str or Path)")
    out = Path(directory)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise ParameterError("directory", directory, "a directory that can be created",
                             why=e.strerror or str(e)) from None  # fmt: skip
    v.writable_directory("directory", directory, out)
    return out


__all__ = ["write_report"]


def fmt(x: float, se: float | None = None, digits: int = 3) -> str:
    """``x ± se`` with ``digits`` decimals ('never' for NaN values)."""
    if x is None or not math.isfinite(x):
        return "never" if x is not None and math.isnan(x) else str(x)
    text = f"{x:.{digits}f}"
    if se is not None and math.isfinite(se):
        text += f" ± {se:.{digits}f}"
    return text


def is_damped(ranked: list) -> bool:
    """Whether any design has inelastic wall contact (damping > 0)."""
    return any(float(r["damping"]) > 0 for r in ranked)


def damper(r: dict) -> str:
    """Which damper acted at a ranked design: ``"dashpot"`` (the result's dashpot is 1)
    or ``"contact"`` (inelastic wall contact, also when the result has no dashpot).

    Examples
    --------
    >>> damper({"dashpot": 1.0}), damper({"dashpot": 0.0}), damper({})
    ('dashpot', 'contact', 'contact')
    """
    return "dashpot" if r.get("dashpot") == 1.0 else "contact"


def lambda1_text(r: dict) -> str:
    """The lambda_1 cell of a ranked design: mean +- s.e. over its Lyapunov runs, or, where
    they split into regular and chaotic runs, the regular count and each group's lambda_1
    (the mean of a mixed ensemble is set by how many runs start in an island).

    Examples
    --------
    >>> from sinktheory.chaos.verdicts import split
    >>> lam = [0.004, 0.005, 0.41, 0.43]
    >>> lambda1_text({"lambda1": 0.21, "lambda1_se": 0.12, "lambda1_split": split(lam, 100)})
    'mixed: 2 of 4 regular (0.0045 ± 0.0005), chaotic (0.420 ± 0.010)'
    >>> lambda1_text({"lambda1": 0.42, "lambda1_se": 0.01, "lambda1_split": None})
    '0.420 ± 0.010'
    """
    if not math.isfinite(r["lambda1"]):
        return "n/a"
    s = r.get("lambda1_split")
    if s is not None and s.mixed:
        return (f"mixed: {s.regular} of {s.runs} regular ({fmt(s.regular_mean, s.regular_se, 4)}"
                f"), chaotic ({fmt(s.chaotic_mean, s.chaotic_se)})")  # fmt: skip
    every = "" if s is None else " (every run regular)" if s.regular == s.runs else ""
    return fmt(r["lambda1"], r["lambda1_se"]) + every


def table_rows(ranked: list, dims: list[str], top: int, settling=None) -> list[str]:
    """The markdown table of the ``top`` ranked designs (with zeta_eq and the dissipated
    share of H0 when any design has inelastic contact, and the predicted settling time
    when ``settling`` maps ranks to :func:`~.settling.predicted_settling`)."""
    damped = is_damped(ranked)
    head = (
        ["rank", "layer"]
        + dims
        + [
            "depth",
            "t50 / T",
            "t80 / T",
            "spread / E0",
            "<E> long",
            "equipartition",
            "verdict",
            "excursion / T",
            "lambda_1",
            "DET",
        ]
        + (["damper", "zeta_eq", "dissipated / H0"] if damped else [])
        + (["settles / T (predicted)"] if settling else [])
    )
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in ranked[:top]:
        cells = [str(r["rank"]), str(r["layer"])] + [label(r[d]) for d in dims]
        cells += [
            fmt(r["depth"], r["depth_se"]),
            fmt(r[("passage", 0.5)], r[("passage_se", 0.5)], 0),
            fmt(r[("passage", 0.8)], r[("passage_se", 0.8)], 0),
            fmt(r["rel_spread"], r["rel_spread_se"]),
            fmt(r["long_time_mean"], r["long_time_se"], 4),
            fmt(r["equipartition"], None, 4),
            VERDICTS[int(r["verdict"])] + f" (z = {r['equipartition_z']:.1f})",
            fmt(r["excursion"], r["excursion_se"], 0),
            lambda1_text(r),
            fmt(r["rqa_determinism"], r["rqa_determinism_se"]),
        ]
        if damped:
            cells += [
                damper(r),
                fmt(r["zeta_eq"], r["zeta_eq_se"], 4),
                fmt(r["dissipated"], r["dissipated_se"]),
            ]
        if settling:
            cells.append(settling_text(settling[r["rank"]]))
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def report_text(ds, ranked: list | None = None, *, top: int = 10, run=None, figures=(),
                settling=None, settling_seconds: float = 0.0) -> str:  # fmt: skip
    """The markdown report of a design sweep (see the module docstring); ``settling``:
    rank -> predicted settling (:func:`~.settling.settling_column`), made in
    ``settling_seconds``."""
    ranked = rank(ds) if ranked is None else ranked
    dims = swept(ds)
    a = ds.attrs
    done = int(np.asarray(ds.done).sum())
    total = int(np.asarray(ds.done).size)
    lines = ["# Design explorer: energy absorbers", ""]
    values = ", ".join(f"{d} = {', '.join(label(v) for v in ds[d].values)}" for d in dims)
    names = ("shape", "alpha", "beta", "n", "gamma", "particles", "mass", "container_energy",
             "damping")  # fmt: skip
    fixed = ", ".join(f"{k} = {a[k]}" for k in names if k in a)
    lines += [
        f"- swept: {values or 'nothing (one design)'}",
        f"- fixed: {fixed}",
        f"- ensemble per design: {a.get('runs')} runs x {a.get('periods')} periods "
        f"(T = 2 pi), tol {a.get('tol')}, sweep seed {a.get('sweep_seed')}; "
        f"{done} of {total} designs computed",
        "- horizons of the absorbed fraction: "
        + ", ".join(f"{int(h)} T" for h in ds.horizon.values),
        f"- lambda_1: {a.get('lyapunov_runs')} runs x {a.get('lyapunov_periods')} periods "
        "(sinktheory.chaos; finite-time estimate per unit time)",
    ]
    if run is not None:
        lines.append(
            f"- this call: {run.computed} computed, {run.skipped} already stored, "
            f"{run.seconds:.1f} s on {run.where}"
            + (f"; {est.describe()}" if (est := getattr(run, "estimate", None)) else "")
        )
    worst = float(np.nanmax(np.asarray(ds.max_relative_energy_error))) if done else math.nan
    lines += [f"- largest relative energy error of any run: {worst:.2g}", ""]

    lines += ["## Recommended designs", ""]
    if not ranked:
        lines += ["No design has been computed yet.", ""]
    else:
        lines += table_rows(ranked, dims, top, settling) + [""]
        lines += [
            "Ranking: Pareto layers of (speed = t50, depth, reliability = spread / E0), "
            "then depth (deepest first), then speed.  Layer 1 is the Pareto front: no other "
            "design is at least as fast, as deep and as reliable and better in one.  A "
            "design that never reaches 50 % absorbed has no t50 and counts as slower than "
            "every design that does: it comes after all of them, however reliable.",
            "",
        ]
        h = [int(x) for x in ds.horizon.values]
        lines += ["### Absorbed fraction 1 - <E>(hT)/E0 of the recommended designs", ""]
        lines += ["| rank | " + " | ".join(f"h = {x}" for x in h) + " |", "|---|" + "---|" * len(h)]
        for r in ranked[:top]:
            cells = [fmt(r[("absorbed", x)], r[("absorbed_se", x)]) for x in h]
            lines.append(f"| {r['rank']} | " + " | ".join(cells) + " |")
        lines.append("")

    lines += ["## Equipartition verdicts", ""]
    if ranked:
        counts = {name: 0 for name in VERDICTS.values()}
        for r in ranked:
            counts[VERDICTS[int(r["verdict"])]] += 1
        lines.append(
            "Long-time <E> against E_total / (1 + k(1 + 1/n)): "
            + ", ".join(f"{v}: {c}" for v, c in counts.items())
            + f" (within {a.get('sigmas')} standard errors: equipartition; above: the drain "
            "is incomplete over the run; below: the container keeps less than the share)."
        )
        if any(float(r.get("beta", a.get("beta", 1.0))) == 0.0 for r in ranked):
            lines += [
                "",
                "At beta = 0 both wells are separable, V = (x^2n + y^2n)/(2n alpha^2n) (the "
                "flat well with gamma = 1), so each particle's y-motion decouples from the "
                "container and keeps its (tiny) initial energy: the microcanonical share of "
                "the x-subsystem is E_x / (1 + k(1 + 1/n)/2), and E/(1 + k(1 + 1/n)) cannot "
                "be reached.  Expect 'above' there.",
            ]
        lines.append("")

    lines += [
        "## How each number is made",
        "",
        "- depth: 1 - <E>_long / E0, <E>_long the mean over runs of each run's time average "
        f"from period {a.get('transient') if a.get('transient') is not None else 'P/2'} on, "
        "± its standard error across runs;",
        "- t50, t80: first period with <E> below 50 % / 20 % of E0 (50 % / 80 % absorbed); "
        "standard error by a bootstrap over runs; 'never' if not reached in the run;",
        "- spread: standard deviation of the runs' long-time averages (s.e. s/sqrt(2(R-1)));",
        "- excursion: the longest stretch (periods) of <E> back above "
        f"{1 - float(a.get('risk_level', 0.5)):g} E0 after first falling below it "
        "(recurrence risk; bootstrap s.e.);",
        f"- DET: determinism of the recurrence plot of <E> with eps = {a.get('rqa_eps')} E0 "
        "(bootstrap s.e.); the store also holds RR, LAM, TT and the mean recurrence time;",
        "- lambda_1: mean ± s.e. over runs of the largest Lyapunov exponent from the tangent "
        "map (sinktheory.chaos), same start positions as the first runs of the ensemble "
        f"({box_starts(a['box']) if 'box' in a else 'each design its own start box'}); "
        "a run is regular when its lambda_1 <= 3 ln t / t of its length "
        "(sinktheory.chaos.verdicts.split).  Where a design's runs split into regular and "
        "chaotic ones, the cell gives the regular count and each group's lambda_1 instead of "
        "their mean, which the start box sets (how many runs start in an island).",
    ]
    if settling:
        lines += [
            "- settles / T (predicted): periods until the ensemble mean of the container "
            "energy, started as the ensemble is, comes within 5 % of the mean of the exact "
            "equilibrium law (sinktheory.equilibrium.settling_periods): a slow-mode model "
            "fitted to short runs on the energy shell, not measured on this design's runs; "
            "the interval is the bootstrap interval widened by the model's known error, a "
            f"factor {MODEL_FACTOR:g} either way; '+': a slow relaxation, which the model "
            "predicts short (measure it: sinktheory relaxation --measure); n/a for 1-D "
            "attachments and damped contact (no law to settle to); "
            f"{len(settling)} prediction(s) in {settling_seconds:.0f} s; designs.csv (and the "
            "JSON of `sinktheory design`) has them as settles, settles_low, settles_high and "
            "settles_note, empty below the top rows;",
        ]
    if ranked and is_damped(ranked):
        lines += [
            "- damping > 0 (inelastic wall contact, sinktheory.damped): a viscous "
            "force -c0 s v_rel on each particle's velocity relative to the container, s = "
            "2n V/gamma (about 1 at the wall), integrated by a Strang splitting with exactly "
            "solved dissipative pair flows; the energy error shown is that of the audit "
            "H + W = H0 (W the dissipated work); damper 'dashpot': the same force with "
            "s = 1 everywhere in the well, c shared by the particles (the 1-D attachments "
            "always, the well with --damping-kind viscous);",
            "- zeta_eq: equivalent damping ratio of the container, W / (2 omega integral of "
            "E_c dt) over the run (the linear dashpot on the container that would dissipate "
            "the same work), mean ± s.e. over runs; dissipated / H0: the share of the total "
            "energy dissipated by the end of the run;",
            "- with damping > 0, lambda_1 is not computed (the chaos indicators are of the "
            "conservative model) and the equipartition share still uses the initial total "
            "energy, so the verdict is expected to be 'below'.",
        ]
    lines.append("")
    if figures:
        lines += ["## Charts", ""] + [f"![{f}]({f})" for f in figures] + [""]
    return "\n".join(lines)


def write_csv(ranked: list, dims: list[str], path: Path, settling=None) -> None:
    """Every ranked design with all its measures, one row each; with ``settling`` (rank ->
    predicted settling, :func:`~.settling.settling_column`) also the columns
    :data:`~.settling.SETTLING_FIELDS` (:func:`~.settling.settling_fields`; empty numbers
    for designs without a prediction)."""
    if not ranked:
        Path(path).write_text("")
        return
    skip = ("rank", "layer", "lambda1_split", *dims)  # the split's numbers have columns
    keys = ["rank", "layer"] + dims + [k for k in ranked[0] if k not in skip]
    extra = list(SETTLING_FIELDS) if settling is not None else []
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([k if isinstance(k, str) else f"{k[0]}@{k[1]:g}" for k in keys] + extra)
        for r in ranked:
            row = [r.get(k) for k in keys]
            if settling is not None:
                row += list(settling_fields(settling.get(r["rank"])).values())
            w.writerow(row)


def write_report(ds, directory, *, ranked: list | None = None, top: int = 10, run=None,
                 settling: bool = True, predicted=None) -> Path:  # fmt: skip
    """Write the charts, ``designs.csv`` and ``report.md`` of a design sweep into
    ``directory`` (created if needed), with the predicted settling time of the ``top``
    designs (in the report's table and designs.csv) unless ``settling`` is False;
    ``predicted``: those predictions made already (``(rank -> settling, seconds)`` from
    :func:`~.settling.settling_column`), else they are made here; ``run``: the
    :class:`~sinktheory.design.explorer.DesignRun` whose call the report describes.
    Returns the path of ``report.md``."""
    from ..plot import design as plots

    ds = design_dataset(ds).load()
    top = v.positive_int("top", top)
    settling = v.flag("settling", settling)
    if run is not None and not all(hasattr(run, a) for a in ("computed", "skipped", "seconds",
                                                             "where")):  # fmt: skip
        raise ParameterError("run", type(run).__name__, "None or the DesignRun of explore")
    ranked = rank(ds) if ranked is None else _ranked(ranked)
    if predicted is not None and settling and ranked:
        predicted = _predicted(predicted, ranked[:top])
    out = _directory(directory)
    dims = swept(ds)
    figures = []
    if ranked:
        plots.pareto_chart(ranked).savefig(out / "pareto.png", dpi=110)
        figures.append("pareto.png")
        plots.energy_curves(ds, ranked).savefig(out / "energy.png", dpi=110)
        figures.append("energy.png")
        if dims:
            for name, fig in plots.heatmaps(ds).items():
                fig.savefig(out / name, dpi=110)
                figures.append(name)
    column, seconds = None, 0.0
    if settling and ranked:
        if predicted is None:
            start = time.perf_counter()
            predicted = settling_column(ranked, ds.attrs, top), time.perf_counter() - start
        column, seconds = predicted
    write_csv(ranked, dims, out / "designs.csv", column)
    path = out / "report.md"
    path.write_text(report_text(ds, ranked, top=top, run=run, figures=figures,
                                settling=column, settling_seconds=seconds))  # fmt: skip
    return path
