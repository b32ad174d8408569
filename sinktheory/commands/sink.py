"""``sinktheory sink``: check and describe a whole set-up before a long run."""

from __future__ import annotations

import argparse

from ..model import RunSettings, Sink
from . import HELP as HELPS
from ._common import Output, add_json, add_sink_arguments, add_well_arguments, well_from_args

NAME = "sink"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser)
    add_sink_arguments(parser)
    add_json(parser)


def run(args: argparse.Namespace) -> Output:
    sink = Sink(well_from_args(args), particles=args.particles, mass=args.mass)
    settings = RunSettings(energy=args.energy, runs=args.runs, periods=args.periods, seed=args.seed)
    settings.check(sink)
    e_total = settings.total_energy_bound(sink)
    x_max, y_max = sink.well.reach(e_total)
    data = {
        "particles": sink.particles,
        "mass": sink.mass,
        "mu": sink.mu,
        "energy": settings.energy,
        "total_energy_bound": e_total,
        "runs": settings.runs,
        "periods": settings.periods,
        "seed": settings.seed,
        "reach": {"x": x_max, "y": y_max},
    }
    text = "\n".join(
        [
            f"{sink.particles} particle(s) of mass mu = {sink.mu:.6g} (total m = {sink.mass:g})",
            f"  {sink.well.shape} well alpha={sink.well.alpha:g} beta={sink.well.beta:g} "
            f"n={sink.well.n} gamma={sink.well.gamma:g}",
            f"  container energy E0 = {settings.energy:g}; total energy <= {e_total:.10g}",
            f"  particles stay within |x| <= {x_max:.6g}, |y| <= {y_max:.6g}",
            f"  {settings.runs} run(s) x {settings.periods} period(s), seed {settings.seed}",
        ]
    )
    return Output(data, text)
