"""``sinktheory sink``: check and describe a whole set-up before a long run."""

from __future__ import annotations

import argparse

from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_sink_arguments,
    add_well_arguments,
    sink_well_from_args,
    well_text,
)

__all__ = ["HELP", "NAME"]

NAME = "sink"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser, well_file=True)
    add_sink_arguments(parser)
    add_json(parser)


def run(args: argparse.Namespace) -> Output:
    from ..model import RunSettings, Sink

    sink = Sink(sink_well_from_args(args), particles=args.particles, mass=args.mass)
    settings = RunSettings(
        container_energy=args.container_energy, runs=args.runs, periods=args.periods,
        seed=args.seed,
    )  # fmt: skip
    s = sink.summary(settings)
    text = "\n".join(
        [
            f"{s.particles} particle(s) of mass mu = {s.mu:.6g} (total m = {s.mass:g})",
            f"  {sink.well.shape} well {well_text(sink.well)}",
            f"  container energy E0 = {s.container_energy:g}; "
            f"total energy <= {s.total_energy_bound:.10g}",
            f"  particles stay within |x| <= {s.reach.x:.6g}, |y| <= {s.reach.y:.6g}",
            f"  {s.runs} run(s) x {s.periods} period(s), seed {s.seed}",
        ]
    )
    data = s.as_dict()
    if hasattr(sink.well, "definition"):  # a user's well: its name and values
        data["well"] = {"name": sink.well.shape, "parameters": sink.well.parameters}
    return Output(data, text)
