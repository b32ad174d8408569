"""``sinktheory well``: describe a well (wall distance, curvature, reach) and draw it."""

from __future__ import annotations

import argparse

from ..validation import positive
from . import HELP as HELPS
from ._common import Output, add_json, add_well_arguments, number, png_path, well_from_args

__all__ = ["add_arguments", "HELP", "NAME", "run"]

NAME = "well"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser)
    parser.add_argument(
        "--particle-energy",
        type=number,
        default=0.5,
        help="the particle energy E whose reach is shown (default 0.5)",
    )
    parser.add_argument("--plot", metavar="FILE.png", help="draw level lines of V")
    add_json(parser)


def run(args: argparse.Namespace) -> Output:
    well = well_from_args(args)
    energy = positive("particle_energy", args.particle_energy)
    plot = png_path("plot", args.plot)
    s = well.summary(energy)
    data = s.as_dict()
    text = "\n".join(
        [
            f"{s.shape} well  alpha={s.alpha:g} beta={s.beta:g} n={s.n} gamma={s.gamma:g}",
            f"  walls                 {s.walls}",
            f"  wall distance         alpha - beta = {s.wall_distance:.12g}",
            f"  curvature at y = 0    {s.curvature_at_centre:.12g}",
            f"  reach at E = {energy:g}     |x| <= {s.reach.x:.6g}, |y| <= {s.reach.y:.6g}",
        ]
    )
    out = Output(data, text)
    if plot is not None:
        from ..plot.well import plot_well

        fig = plot_well(well, particle_energy=energy)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        data["plot"] = str(plot)
    return out
