"""``sinktheory sweep``: a parameter sweep into a Zarr store, locally or on a Dask cluster.

``--param NAME=LO:HI:COUNT`` sweeps COUNT evenly spaced values (both ends included),
``--param NAME=V1,V2,...`` sweeps the listed values and ``--param NAME=V`` fixes one;
every model or run setting of the kind can be given (see :mod:`sinktheory.sweep.kinds`).
Everything is checked before the store is created, so bad input writes nothing.  A
killed sweep is continued by the same command with ``--resume``: only the points not yet
flagged done are computed.  The store opens with ``xarray.open_zarr(STORE)``.
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
from ._common import Output, add_json, damage_note, interruptible, number, resume_hint

__all__ = ["add_arguments", "estimate_line", "HELP", "NAME", "params_of", "run"]

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
    parser.add_argument("--quiet", action="store_true", help="no estimate line, no progress bar")
    add_json(parser)
    parser.epilog = "parameters of each KIND: " + "; ".join(
        f"{name}: {', '.join(kind.params)}" for name, kind in KINDS.items()
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


def estimate_line(sweep) -> str:
    """What the sweep prints before it starts: its points and their estimated work."""
    from ..limits import MAX_SECONDS, SECONDS_PER_PARTICLE_STEP
    from ..worklimit import duration

    return (
        f"{sweep.grid.size} point(s), estimated work {duration(sweep.estimate)} in all "
        f"(optimistic: {SECONDS_PER_PARTICLE_STEP:g} s per particle step; each point may "
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

    sweep = Sweep.make(args.kind, params_of(args.param), args.seed)
    if not args.quiet:  # before any work: the estimate
        print(f"sinktheory sweep: {estimate_line(sweep)}", file=sys.stderr, flush=True)
    done = execute(
        sweep,
        store=args.out,
        scheduler=args.scheduler,
        workers=args.workers,
        resume=args.resume,
        repair=args.repair,
        progress=not args.quiet,
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
    return Output(data, text)
