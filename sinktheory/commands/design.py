"""``sinktheory design``: explore absorber designs over a grid; rank, chart and report them.

Each design option takes one value, a list ``V1,V2,...`` or a range ``LO:HI:COUNT``
(``--shape flat,symmetric --beta -0.3:0.3:5 --n 4,6,10 --particles 1,3,5``), the contact
damping too (``--damping 0,0.1,0.5``: inelastic wall contact, with the container's
equivalent damping ratio per design), and the attachment (``--attachment well,nes,impact``:
the 1-D cubic NES and vibro-impact NES of :mod:`sinktheory.attachments` beside the 2-D
well, ranked on the same measures).  Every point of the grid runs an ensemble
(``--runs`` x ``--periods``) on the sweep layer (local processes or a Dask cluster) into
the Zarr store ``--out``, point by point; a killed run is continued by the same command
with ``--resume``.  Before starting, the per-point cost is calibrated and the estimated
time printed on stderr; a progress bar follows.  With ``--report DIR`` the heat maps, the
Pareto chart, ``designs.csv`` (the ranked designs) and ``report.md`` are written there.
Bad input: one line on stderr, exit status 2, no store and no report.
"""

from __future__ import annotations

import argparse
import math
import re
import sys
from pathlib import Path

from .._generated.shapes import NAMES as SHAPE_NAMES
from ..errors import ParameterError
from ..sweep.grid import parse_param
from ..validation import writable_directory
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    as_directory,
    damage_note,
    interruptible,
    number,
    output_directory,
    resume_hint,
)

__all__ = ["GRID", "HELP", "NAME", "NEGATIVE_VALUE", "SETTINGS"]

NAME = "design"
HELP = HELPS[NAME]

#: the design parameters given as options of the same name (each takes a value, a list
#: or a range)
GRID = (
    "shape",
    "alpha",
    "beta",
    "n",
    "gamma",
    "particles",
    "mass",
    "container_energy",
    "damping",
    "attachment",
    "damping_kind",
)
#: option -> setting of the design kind (one value each)
SETTINGS = (
    "runs",
    "periods",
    "tol",
    "transient",
    "sigmas",
    "risk_level",
    "rqa_eps",
    "bootstrap",
    "lyapunov_runs",
    "lyapunov_periods",
    "box",
)


#: Values, not options: negative numbers and lists or ranges that start with one
#: (``--beta -0.5:0.4:11``, ``--beta -0.2,0.3``), besides what the main parser accepts.
NEGATIVE_VALUE = re.compile(
    r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?([,:][-+.\deE,:]*)?$|^-(inf|infinity|nan)$",
    re.IGNORECASE,
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser._negative_number_matcher = NEGATIVE_VALUE  # argparse's hook for "-1" values
    g = parser.add_argument_group("designs (VALUE, V1,V2,... or LO:HI:COUNT)")
    g.add_argument(
        "--shape",
        default="flat",
        help=f"one or more of {', '.join(SHAPE_NAMES)} or TOML well files (FILE.toml: their "
        "parameters alpha, beta, n, gamma take the design's values), comma-separated "
        "(default flat)",
    )
    g.add_argument(
        "--well-param",
        metavar="NAME=VALUE",
        action="append",
        default=[],
        help="a value for a parameter of the well files in --shape other than alpha, beta, n, "
        "gamma, within its range (repeat for more; the files' defaults otherwise)",
    )
    g.add_argument("--alpha", default="0.5", help="alpha > 0 (default 0.5)")
    g.add_argument("--beta", required=True, help="beta < alpha")
    g.add_argument("--n", required=True, help="wall stiffness, integers >= 1")
    g.add_argument("--gamma", default="1.0", help="well strength > 0 (default 1)")
    g.add_argument("--particles", default="1", help="k, integers >= 1 (default 1)")
    g.add_argument("--mass", default="0.2", help="total particle mass m > 0 (default 0.2)")
    g.add_argument(
        "--container-energy",
        default="0.5",
        help="the container's initial energy E0 > 0 (default 0.5)",
    )
    g.add_argument(
        "--damping",
        default="0",
        help="damping >= 0 (default 0: conservative); for the well by --damping-kind, for "
        "nes and impact always their dashpot",
    )
    g.add_argument(
        "--damping-kind",
        default="contact",
        help="what --damping is for the 2-D well: contact (inelastic wall contact, c0 per "
        "particle; default) or viscous (the 1-D attachments' dashpot on the relative "
        "velocity, c shared by the k particles: equal damping with nes and impact); "
        "comma-separated; the result's dashpot column says which acted",
    )
    g.add_argument(
        "--attachment",
        default="well",
        help="well (the 2-D sink), nes (1-D, on y = 0), impact (vibro-impact), "
        "comma-separated (default well; nes and impact: impulsive start, --damping is "
        "their dashpot whatever --damping-kind)",
    )
    r = parser.add_argument_group("ensemble and measures (one value each)")
    r.add_argument("--runs", type=number, default=25, help="runs per design (default 25)")
    r.add_argument("--periods", type=number, default=1500, help="periods T (default 1500)")
    r.add_argument(
        "--horizons",
        default="auto",
        help="periods of the absorbed fraction, e.g. 100,500,1500 (default P/10, P/3, P)",
    )
    r.add_argument("--tol", type=number, default=1e-6, help="energy tolerance (default 1e-6)")
    r.add_argument("--transient", type=number, default=None, help="start of the long-time window")
    r.add_argument("--sigmas", type=number, default=3.0, help="verdict threshold in s.e.")
    r.add_argument("--risk-level", type=number, default=0.5, help="absorbed level of the risk")
    r.add_argument("--rqa-eps", type=number, default=0.01, help="RQA eps / E0 (default 0.01)")
    r.add_argument("--bootstrap", type=number, default=50, help="bootstrap resamples (50)")
    r.add_argument(
        "--lyapunov-runs", type=number, default=10, help="runs for lambda_1, 0 (none) or >= 2 (10)"
    )
    r.add_argument("--lyapunov-periods", type=number, default=100, help="periods (100)")
    r.add_argument("--box", type=number, default=0.01, help="start box half-width (0.01)")
    r.add_argument("--seed", type=number, default=0, help="sweep seed >= 0 (default 0)")
    o = parser.add_argument_group("where")
    o.add_argument("--out", required=True, metavar="STORE", help="Zarr store of the results")
    o.add_argument("--report", default=None, metavar="DIR", help="charts, table, report.md")
    o.add_argument(
        "--top", type=number, default=10,
        help="designs in the report and the JSON, each with its predicted settling time (10)",
    )  # fmt: skip
    o.add_argument("--resume", action="store_true", help="continue the sweep in STORE")
    o.add_argument(
        "--repair",
        action="store_true",
        help="with --resume: remove chunks that no longer decode and recompute their points",
    )
    o.add_argument("--scheduler", default=None, metavar="ADDRESS", help="Dask scheduler")
    o.add_argument("--workers", type=number, default=None, help="local processes (all cores)")
    o.add_argument("--no-estimate", action="store_true", help="skip the cost calibration")
    o.add_argument("--quiet", action="store_true", help="no estimate line, no progress bar")
    add_json(parser)


def params_of(args: argparse.Namespace) -> dict:
    """The design grid and settings of the options (names of the ``design`` kind)."""
    params = {}
    for name in GRID:
        text = str(getattr(args, name))
        _, values = parse_param(f"{name}={text}")
        params[name] = values
    for name in SETTINGS:
        value = getattr(args, name)
        if value is not None:
            params[name] = value
    horizons = str(args.horizons).strip()
    params["horizons"] = horizons.replace(",", "+")
    params["shape"] = _shapes(params["shape"], args.well_param)
    return params


def _shapes(values: list, items: list[str]) -> list:
    """The ``--shape`` values with each well file as its
    :class:`~sinktheory.userwell.UserWell`, its defaults replaced by ``--well-param``."""
    wells = [value for value in values if value not in SHAPE_NAMES]
    for value in wells:
        if not (isinstance(value, str) and value.endswith(".toml") and Path(value).is_file()):
            raise ParameterError("shape", value, f"one of {', '.join(SHAPE_NAMES)} or a TOML "
                                 "well file (an existing FILE.toml)")  # fmt: skip
    given = {}
    for item in items:
        try:  # its own refusals name --param, NAME or LO:HI:COUNT, not this option
            name, values_ = parse_param(item)
        except ParameterError:
            name, values_ = None, []
        if len(values_) != 1 or not isinstance(values_[0], int | float):
            raise ParameterError("well_param", item, "NAME=VALUE, VALUE a number")
        if name in GRID:
            option = "--" + name.replace("_", "-")
            raise ParameterError("well_param", item, "a parameter of a well file other than a "
                                 f"design axis (give {option})")  # fmt: skip
        given[name] = values_[0]
    if not wells:
        if given:
            raise ParameterError("well_param", items[0], "given with a well file in --shape")
        return values
    from ..userwell import load_well

    loaded = {value: load_well(value) for value in wells}
    for name in given:
        if not any(name in w.parameter_names for w in loaded.values()):
            raise ParameterError("well_param", name, "a parameter of a well file in --shape")
    out = []
    for value in values:
        well = loaded.get(value)
        if well is not None:
            well = well.with_defaults(**{k: x for k, x in given.items()
                                         if k in well.parameter_names})  # fmt: skip
        out.append(value if well is None else well)
    return out


def run(args: argparse.Namespace) -> Output:
    """Ctrl-C or SIGTERM at any point: one line, status 130 or 143
    (:func:`~sinktheory.commands._common.interruptible`); the store keeps every point
    finished and ``--resume`` continues it (the line says so once the store exists)."""
    with interruptible("sinktheory design", resume_hint(str(args.out))):
        return _run(args)


def _run(args: argparse.Namespace) -> Output:
    if not str(args.out).strip():
        raise ParameterError("out", args.out, "the path of a Zarr store (not empty)")
    writable_directory("out", args.out, Path(args.out).parent)
    report = output_directory("report", args.report)
    top = args.top
    if isinstance(top, bool) or not isinstance(top, int) or top < 1:
        raise ParameterError("top", top, "an integer >= 1")
    store = Path(args.out)
    if store.exists() and not args.resume:
        raise ParameterError("out", args.out, "a new store", why="it exists; --resume continues it")
    from ..design.explorer import DesignRun, plan, todo_of  # xarray, zarr: when exploring
    from ..sweep.runner import execute

    sweep = plan(params_of(args), args.seed)
    todo, repaired = todo_of(sweep, store, args.resume, args.repair)
    est = None
    if todo.size and not args.no_estimate:
        from ..design.cost import estimate

        est = estimate(sweep, workers=args.workers, todo=todo)
        if not args.quiet:
            print(f"sinktheory design: {est.describe()}", file=sys.stderr, flush=True)
    done = execute(
        sweep,
        store=store,
        scheduler=args.scheduler,
        workers=args.workers,
        resume=args.resume,
        repair=args.repair,
        progress=not args.quiet,
    )
    run = DesignRun._of(done, est, repaired)
    ds, ranked, repaired = run.dataset, run.ranked, run.repaired
    dims = list(ds.done.dims)
    predicted = None
    if ranked and (report is not None or args.json):  # the report's and the JSON's column
        import time

        from ..design.settling import settling_column

        start = time.perf_counter()
        predicted = settling_column(ranked, ds.attrs, top), time.perf_counter() - start
    best = [_row(r, dims, None if predicted is None else predicted[0].get(r["rank"]))
            for r in ranked[:top]]  # fmt: skip
    data = {
        "store": str(done.store),
        "report": None if report is None else str(report),
        "dims": sweep.dims,
        "points": sweep.grid.size,
        "computed": done.computed,
        "repaired": repaired,
        "skipped": done.skipped,
        "seconds": done.seconds,
        "estimated_seconds": None if est is None else est.total_seconds,
        "where": done.where,
        "seed": sweep.seed,
        "fingerprint": sweep.fingerprint,
        "designs": best,
    }
    lines = [
        sweep.describe(),
        f"{done.computed} design(s) computed{damage_note(repaired)}, {done.skipped} already "
        "done, in "
        f"{done.seconds:.1f} s on {done.where}"
        + ("" if est is None else f" (estimated {est.total_seconds:.0f} s)"),
        f"results: {done.store} (xarray.open_zarr)",
        "best designs (depth = long-time fraction of E0 absorbed, t50 in periods, lambda_1 "
        "per unit time; where its runs split, the regular count and each group's lambda_1):",
    ]
    lines += [summary_line(r, dims) for r in ranked[: min(top, 5)]]
    writers = {}
    if report is not None:
        from ..design.report import write_report

        writers[report] = as_directory(
            lambda path: write_report(
                ds, path, ranked=ranked, top=top, run=run, predicted=predicted
            )
        )
        lines.append(f"report: {report / 'report.md'}")
    return Output(data, "\n".join(lines), writers)


def summary_line(r: dict, dims: list[str]) -> str:
    """One ranked design (a row of :func:`sinktheory.design.ranking.rank`) as a line of the
    text summary: place in the grid, depth, t50, spread, verdict (the numbers ``--json``
    lists, :func:`_row`) and lambda_1 as the report's table gives it
    (:func:`sinktheory.design.report.lambda1_text`: where the runs split into regular and
    chaotic ones, the regular count and each group's lambda_1, not their mean)."""
    from ..design.report import lambda1_text
    from ..plot.design import label

    d = _row(r, dims)
    where = ", ".join(f"{k} = {label(r[k])}" for k in dims)
    return (
        f"  #{d['rank']} (Pareto layer {d['layer']}) {where}: depth {_n(d['depth'])} "
        f"+- {_n(d['depth_se'])}, t50 {_n(d['t50'], 0, 'never')}, spread/E0 "
        f"{_n(d['rel_spread'])}, {d['verdict']}, lambda_1 {lambda1_text(r)}"
    )


def _n(x: float | None, digits: int = 3, missing: str = "n/a") -> str:
    return missing if x is None else f"{x:.{digits}f}"


def _row(r: dict, dims: list[str], settling=None) -> dict:
    """A ranked design as JSON-ready plain values (NaN and inf as null), with its
    predicted settling (``settling``: :func:`~sinktheory.design.settling.settling_fields`
    of it)."""
    from ..design.measures import VERDICTS
    from ..design.report import damper
    from ..design.settling import settling_fields

    def f(x):
        return x if isinstance(x, float) and math.isfinite(x) else None

    return {
        "rank": r["rank"],
        "layer": r["layer"],
        **{d: r[d] for d in dims},
        "depth": f(r["depth"]),
        "depth_se": f(r["depth_se"]),
        "t50": f(r[("passage", 0.5)]),
        "t50_se": f(r[("passage_se", 0.5)]),
        "t80": f(r[("passage", 0.8)]),
        "t80_se": f(r[("passage_se", 0.8)]),
        "rel_spread": f(r["rel_spread"]),
        "long_time_mean": f(r["long_time_mean"]),
        "long_time_se": f(r["long_time_se"]),
        "equipartition": f(r["equipartition"]),
        "verdict": VERDICTS[int(r["verdict"])],
        "excursion": f(r["excursion"]),
        "lambda1": f(r["lambda1"]),
        "lambda1_se": f(r["lambda1_se"]),
        "split_lambda1": None if r["lambda1_split"] is None else r["lambda1_split"].as_dict(),
        "zeta_eq": f(r["zeta_eq"]),
        "zeta_eq_se": f(r["zeta_eq_se"]),
        "damper": damper(r),
        **settling_fields(settling),
    }
