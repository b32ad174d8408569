"""``sinktheory reproduce``: every figure of the paper as a PNG, and report.md.

Before each figure one line on stderr names it with its expected run time (as measured on
a 2-core machine, :data:`sinktheory.scenes.SECONDS`, plus about
:data:`~sinktheory.engine.cache.COMPILE_SECONDS` for each engine it compiles on first
use, :data:`sinktheory.scenes.ENGINES`), and after it one line gives the
time it took, so a log file shows where a long run is; long computations inside a figure
add their own progress lines (:mod:`sinktheory.progress`).  The scene modules (numpy,
numba, matplotlib) are imported only after the arguments are checked.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from ..errors import ParameterError
from ..scenes import FIGURES, estimate
from . import HELP as HELPS
from ._common import Output, add_json, as_directory, output_directory

__all__ = ["NO_WELL", "HELP", "NAME"]

NAME = "reproduce"
HELP = HELPS[NAME]
#: Why ``--well FILE`` is refused (see :func:`sinktheory.cli.main`).
NO_WELL = "the paper's figures are drawn for the registered shapes"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--figure",
        type=int,
        nargs="+",
        metavar="N",
        help=f"figures to draw (default all: {', '.join(map(str, FIGURES))})",
    )
    parser.add_argument("--quick", action="store_true", help="low-fidelity preview")
    parser.add_argument("--out", required=True, metavar="DIR", help="output directory")
    add_json(parser)


def _say(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


def _first_compilations(figures) -> dict[int, list[str]]:
    """The engines each figure will compile on its first use here: those it runs
    (:data:`sinktheory.scenes.ENGINES`) that are not in the cache and that no earlier
    figure of this run compiles."""
    from ..engine.cache import compiled
    from ..scenes import ENGINES

    seen: set[str] = set()
    out = {}
    for number in figures:
        out[number] = [e for e in ENGINES[number] if e not in seen and not compiled(e)]
        seen.update(ENGINES[number])
    return out


def _cpu_seconds() -> float:
    """CPU seconds of this process (all threads) and of its finished child processes (the
    sweeps' worker pools), so that a figure's CPU time counts its workers too."""
    try:
        import resource
    except ImportError:  # not on Windows: this process only
        return time.process_time()
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + children.ru_utime + children.ru_stime


def run(args: argparse.Namespace) -> Output:
    figures = sorted(set(args.figure or FIGURES))
    unknown = [f for f in figures if f not in FIGURES]
    if unknown:
        allowed = ", ".join(map(str, FIGURES))
        raise ParameterError("figure", unknown[0], f"one of {allowed}")
    out_dir = output_directory("out", args.out)

    from .. import __version__
    from ..engine.cache import COMPILE_SECONDS
    from ..errors import NumericalError
    from ..report import SceneOutcome, render
    from ..scenes import scene as scene_of

    first_use = _first_compilations(figures)
    compiling = COMPILE_SECONDS * sum(len(e) for e in first_use.values())
    expected = sum(estimate(f, args.quick) for f in figures) + compiling
    _say(
        f"reproduce: {len(figures)} figure(s) at {'quick' if args.quick else 'paper'} "
        f"fidelity, expected about {expected:.0f} s (measured on 2 cores"
        + (
            f"; includes about {compiling:.0f} s compiling engines on first use)"
            if compiling
            else ")"
        )
    )
    outcomes = []
    for i, number in enumerate(figures, 1):
        scene = scene_of(number)
        new = first_use[number]
        seconds = estimate(number, args.quick) + COMPILE_SECONDS * len(new)
        _say(
            f"Fig. {number} ({i}/{len(figures)}): {scene.title}; about {seconds:.0f} s"
            + (f" (compiles {', '.join(new)} first)" if new else "")
        )
        start, cpu = time.perf_counter(), _cpu_seconds()
        try:
            result = scene.build(args.quick)
            error = None
        except NumericalError as e:  # reported, not hidden: the run exits with status 1
            result, error = None, f"{type(e).__name__}: {e}"
        seconds, cpu = time.perf_counter() - start, _cpu_seconds() - cpu
        _say(f"Fig. {number}: {'failed' if error else 'done'} in {seconds:.1f} s")
        image = f"fig{number:02d}.png" if result is not None else None
        outcomes.append(SceneOutcome(scene, result, image, seconds, error, cpu))
    report = render(outcomes, quick=args.quick, version=__version__)
    data = {
        "out": str(out_dir),
        "figures": [o.as_dict() for o in outcomes],
        "report": str(out_dir / "report.md"),
    }
    text = (
        "\n".join(
            f"Fig. {o.scene.number}: {'FAILED ' + o.error if o.error else o.image} "
            f"({o.seconds:.1f} s)"
            for o in outcomes
        )
        + f"\nreport: {out_dir / 'report.md'}"
    )

    @as_directory
    def write_all(path: Path) -> None:
        path.mkdir(parents=True, exist_ok=True)
        for o in outcomes:
            if o.result is not None:
                o.result.figure.savefig(path / o.image, dpi=130)
        (path / "report.md").write_text(report)

    failed = any(o.error for o in outcomes)
    return Output(data, text, {out_dir: write_all}, exit_status=1 if failed else 0)
