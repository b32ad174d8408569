"""``sinktheory sweep``: a parameter sweep into a Zarr store, locally or on a Dask cluster.

``--param NAME=LO:HI:COUNT`` sweeps COUNT evenly spaced values (both ends included),
``--param NAME=V1,V2,...`` sweeps the listed values and ``--param NAME=V`` fixes one;
every model or run setting of the kind can be given (see :mod:`sinktheory.sweep.kinds`).
Everything is checked before the store is created, so bad input writes nothing.  A
killed sweep is continued by the same command with ``--resume``: only the points not yet
flagged done are computed.  The store opens with ``xarray.open_zarr(STORE)``.

A ``chaos`` or ``ergodicity`` sweep's report says where a point's lambda_1 runs split into
regular and chaotic ones (:func:`split_summary`), since there the stored mean lambda_1
depends on the start distribution.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import ParameterError
from ..sweep.grid import Value, parse_param
from ..sweep.kinds import KINDS
from ..validation import writable_directory
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_well_file,
    damage_note,
    interruptible,
    number,
    resume_hint,
)

__all__ = ["HELP", "NAME"]

NAME = "sweep"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("kind", metavar="KIND", help=f"one of {', '.join(KINDS)}")
    parser.add_argument(
        "--param",
        action="append",
        default=[],
        metavar="NAME=SPEC",
        help="NAME=LO:HI:COUNT, NAME=V1,V2,... or NAME=VALUE (repeat for each parameter)",
    )
    parser.add_argument("--seed", type=number, default=0, help="sweep seed >= 0 (default 0)")
    parser.add_argument("--out", required=True, metavar="STORE", help="Zarr store to write")
    parser.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="Dask scheduler address (default: DASK_SCHEDULER_ADDRESS, else local processes)",
    )
    parser.add_argument(
        "--workers", type=number, default=None, help="local processes (default: all cores)"
    )
    parser.add_argument(
        "--resume", action="store_true", help="continue the sweep in STORE (missing points only)"
    )
    parser.add_argument(
        "--repair",
        action="store_true",
        help="with --resume: remove chunks that no longer decode and recompute their points",
    )
    parser.add_argument(
        "--quiet", action="store_true", help="no estimate line, no progress of the check or run"
    )
    add_json(parser)
    add_well_file(parser)
    parser.epilog = (
        "parameters of each KIND: "
        + "; ".join(f"{name}: {', '.join(kind.params)}" for name, kind in KINDS.items())
        + ". With --well FILE ("
        + ", ".join(name for name, kind in KINDS.items() if kind.user_well)
        + ") the well's own parameters replace alpha, beta, n, gamma and shape: sweep them "
        "with --param, fix them with --param or --well-param; the store keeps the well's "
        "definition, and --resume refuses a changed file"
    )


def params_of(specs: list[str]) -> dict[str, list[Value]]:
    """The ``--param`` options as name -> values; a name given twice is refused."""
    params: dict[str, list[Value]] = {}
    for spec in specs:
        name, values = parse_param(spec)
        if name in params:
            raise ParameterError(name, spec, "given once (it was given twice)")
        params[name] = values
    return params


def params_with_well(args: argparse.Namespace) -> dict:
    """The ``--param`` options, with ``--well FILE`` as the parameter ``well`` (its
    :class:`~sinktheory.userwell.UserWell`) and each ``--well-param NAME=VALUE`` as a
    ``--param`` (a name given by both is refused as given twice).  A design sweep puts the
    well on its shape axis instead, beside the shapes of ``--param shape=...``."""
    if args.well is None:
        if args.well_param:
            raise ParameterError("well_param", args.well_param[0], "given with --well FILE")
        return params_of(args.param)
    params = params_of(args.param + args.well_param)
    if "well" in params:
        raise ParameterError("well", params["well"], "given as --well FILE, not as --param")
    from ..sweep.kinds import get_kind
    from ..userwell import load_well

    well = load_well(args.well)
    if get_kind(args.kind).shape_wells:  # design: the well is one more shape
        return {**params, "shape": [*params.get("shape", []), well]}
    return {**params, "well": well}


def estimate_line(sweep) -> str:
    """What the sweep prints before it starts: its points and their estimated work."""
    from ..limits import MAX_SECONDS, SECONDS_PER_PARTICLE_STEP
    from ..worklimit import duration

    return (
        f"{sweep.grid.size} point(s), estimated work {duration(sweep.estimate)} in all "
        f"({SECONDS_PER_PARTICLE_STEP:g} s per particle step; each point may "
        f"take up to {duration(MAX_SECONDS)})"
    )


def run(args: argparse.Namespace) -> Output:
    """Ctrl-C or SIGTERM at any point: one line, status 130 or 143
    (:func:`~sinktheory.commands._common.interruptible`); the store keeps every point
    finished and ``--resume`` continues it (the line says so once the store exists)."""
    with interruptible("sinktheory sweep", resume_hint(str(args.out))):
        return _run(args)


def _run(args: argparse.Namespace) -> Output:
    if not args.out.strip():
        raise ParameterError("out", args.out, "the path of a Zarr store (not empty)")
    writable_directory("out", args.out, Path(args.out).parent)  # before any work
    from ..sweep.plan import Sweep  # imports xarray, zarr and dask: only when sweeping
    from ..sweep.runner import execute

    sweep = Sweep.make(args.kind, params_with_well(args), args.seed, progress=not args.quiet)

    def announce() -> None:  # before any work, after every refusal: the estimate
        if not args.quiet:
            print(f"sinktheory sweep: {estimate_line(sweep)}", file=sys.stderr, flush=True)

    done = execute(
        sweep,
        store=args.out,
        scheduler=args.scheduler,
        workers=args.workers,
        resume=args.resume,
        repair=args.repair,
        progress=not args.quiet,
        announce=announce,
    )
    data = {
        "store": str(done.store),
        "kind": sweep.kind.name,
        "dims": sweep.dims,
        "points": sweep.grid.size,
        "computed": done.computed,
        "repaired": done.repaired,
        "skipped": done.skipped,
        "seconds": done.seconds,
        "estimated_seconds": sweep.estimate,
        "where": done.where,
        "seed": sweep.seed,
        "fingerprint": sweep.fingerprint,
    }
    text = "\n".join(
        [
            sweep.describe(),
            f"{done.computed} point(s) computed{damage_note(done.repaired)}, {done.skipped} "
            f"already done, in {done.seconds:.1f} s on {done.where}",
            f"results: {done.store} (xarray.open_zarr)",
        ]
    )
    from ..sweep.views import split_points

    points = split_points(done.dataset)
    if points:
        lines, data["split_lambda1"] = split_summary(points)
        text += "\n" + "\n".join(lines)
    return Output(data, text)


#: Mixed points listed one by one in the text (all of them are in --json).
LISTED = 12


def split_summary(points: list) -> tuple[list[str], dict]:
    """The text lines and the JSON of :func:`sinktheory.sweep.views.split_points`: how many
    points have every run regular, every run chaotic or both kinds (mixed), and for each
    mixed point its regular fraction and each group's lambda_1 (the first LISTED in the
    text).

    Examples
    --------
    >>> from sinktheory.chaos.verdicts import split
    >>> points = [({"beta": -0.3}, split([0.001, 0.002, 0.4, 0.5], 200)),
    ...           ({"beta": 0.3}, split([0.4, 0.5, 0.6, 0.5], 200))]
    >>> lines, data = split_summary(points)
    >>> print("\\n".join(lines))  # doctest: +NORMALIZE_WHITESPACE
    lambda_1 run by run: 1 of 2 point(s) mixed (regular and chaotic runs: their mean
    lambda_1 depends on the starts), 1 with every run chaotic, 0 with every run regular
      beta=-0.3: runs: 2 of 4 regular (lambda_1 <= 3 ln t/t = 0.017), regular 0.0015 +-
      0.0005, chaotic 0.45 +- 0.05
    >>> data["mixed_points"], data["mixed"][0]["beta"], data["mixed"][0]["regular_fraction"]
    (1, -0.3, 0.5)
    """
    from dataclasses import replace

    mixed = [(where, s) for where, s in points if s.mixed]
    regular = sum(s.regular == s.runs for _, s in points)
    starts = {s.starts for _, s in points}
    once = len(starts) == 1 and "" not in starts  # the same starts everywhere: say it once
    lines = [
        f"lambda_1 run by run: {len(mixed)} of {len(points)} point(s) mixed (regular and "
        "chaotic runs: their mean lambda_1 depends on the starts), "
        f"{len(points) - len(mixed) - regular} with every run chaotic, {regular} with every "
        "run regular" + (f"; starts: {next(iter(starts))}" if once else "")
    ]
    for where, s in mixed[:LISTED]:
        at = " ".join(f"{name}={value:g}" if isinstance(value, float) else f"{name}={value}"
                      for name, value in where.items())  # fmt: skip
        lines.append(f"  {at or 'the point'}: {(replace(s, starts='') if once else s).text()}")
    if len(mixed) > LISTED:
        lines.append(f"  ... {len(mixed) - LISTED} more mixed point(s): --json lists them all")
    data = {
        "points": len(points),
        "mixed_points": len(mixed),
        "regular_points": regular,
        "chaotic_points": len(points) - len(mixed) - regular,
        "mixed": [{**where, **s.as_dict()} for where, s in mixed],
    }
    return lines, data
