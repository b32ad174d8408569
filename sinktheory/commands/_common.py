"""Pieces shared by the subcommands: argument types, the well options, output files."""

from __future__ import annotations

import argparse
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import ParameterError
from ..model import SHAPES, Well


@dataclass
class Output:
    """What a command produced: a JSON-ready dict, its text rendering, files to write.

    ``writers`` maps a path to a callable that writes it; they run only after the
    command has finished computing, so an error never leaves a partial file.
    """

    data: dict[str, Any]
    text: str
    writers: dict[Path, Any] = field(default_factory=dict)
    #: 1 when the command finished but part of it failed numerically (reported in data)
    exit_status: int = 0


def number(text: str) -> int | float:
    """argparse type: an int or float literal (nan and inf pass, so the model can name them)."""
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None


def add_json(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object on stdout")


def add_well_arguments(parser: argparse.ArgumentParser, *, beta: bool = True) -> None:
    g = parser.add_argument_group("well")
    g.add_argument("--alpha", type=number, required=True, help="alpha > 0")
    if beta:
        g.add_argument("--beta", type=number, required=True, help="beta < alpha (curvature/2)")
    g.add_argument("--n", type=number, required=True, help="wall stiffness, integer >= 1")
    g.add_argument("--gamma", type=number, default=1.0, help="well strength > 0 (default 1)")
    g.add_argument("--shape", default="flat", help=f"one of {', '.join(SHAPES)} (default flat)")


def add_sink_arguments(
    parser: argparse.ArgumentParser,
    *,
    runs_default: int | None = 25,
    runs_help: str = "ensemble size, integer >= 1 (default 25)",
):
    """Options of the particles and the run: particles, mass, energy, runs, periods, seed.

    Returns the argument group, so a command can add options of its own to it.
    """
    g = parser.add_argument_group("sink and run")
    g.add_argument("--particles", type=number, default=1, help="k, integer >= 1 (default 1)")
    g.add_argument(
        "--mass", type=number, default=0.2, help="total particle mass m > 0 (default 0.2)"
    )
    g.add_argument(
        "--energy", type=number, default=0.5, help="container energy E0 > 0 (default 0.5)"
    )
    g.add_argument("--runs", type=number, default=runs_default, help=runs_help)
    g.add_argument(
        "--periods", type=number, default=1500, help="periods T = 2 pi, integer >= 1 (default 1500)"
    )
    g.add_argument("--seed", type=number, default=0, help="random seed, integer >= 0 (default 0)")
    return g


def well_from_args(args: argparse.Namespace) -> Well:
    return Well(args.alpha, args.beta, args.n, gamma=args.gamma, shape=args.shape)


def png_path(name: str, value: str | None) -> Path | None:
    """Validate an output PNG path: suffix .png and an existing directory."""
    if value is None:
        return None
    path = Path(value)
    if path.suffix.lower() != ".png":
        raise ParameterError(name, value, "a file name ending in .png")
    if not path.parent.resolve().is_dir():
        raise ParameterError(name, value, "a path in an existing directory")
    return path


def finite_or_none(x: float) -> float | None:
    """JSON has no inf/nan: map them to null."""
    return x if math.isfinite(x) else None
