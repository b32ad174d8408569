"""``sinktheory well``: describe a well (wall distance, curvature, reach) and draw it."""

from __future__ import annotations

import argparse

from ..validation import positive
from . import HELP as HELPS
from ._common import Output, add_json, add_well_arguments, number, png_path, well_from_args

NAME = "well"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser)
    parser.add_argument(
        "--energy", type=number, default=0.5, help="particle energy for the reach (default 0.5)"
    )
    parser.add_argument("--plot", metavar="FILE.png", help="draw level lines of V")
    add_json(parser)


def run(args: argparse.Namespace) -> Output:
    well = well_from_args(args)
    energy = positive("energy", args.energy)
    plot = png_path("plot", args.plot)
    x_max, y_max = well.reach(energy)
    data = {
        "shape": well.shape,
        "alpha": well.alpha,
        "beta": well.beta,
        "n": well.n,
        "gamma": well.gamma,
        "wall_distance": well.wall_distance,
        "curvature_at_centre": well.curvature_at_centre,
        "energy": energy,
        "reach": {"x": x_max, "y": y_max},
    }
    kind = (
        "scattering (Sinai-like)"
        if well.beta > 0
        else ("focusing (stadium-like)" if well.beta < 0 else "straight")
    )
    text = "\n".join(
        [
            f"{well.shape} well  alpha={well.alpha:g} beta={well.beta:g} n={well.n} "
            f"gamma={well.gamma:g}",
            f"  walls                 {kind}",
            f"  wall distance         alpha - beta = {well.wall_distance:.12g}",
            f"  curvature at y = 0    2 beta = {well.curvature_at_centre:.12g}",
            f"  reach at E = {energy:g}     |x| <= {x_max:.6g}, |y| <= {y_max:.6g}",
        ]
    )
    out = Output(data, text)
    if plot is not None:
        from ..plot.well import plot_well

        fig = plot_well(well, energy=energy)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        data["plot"] = str(plot)
    return out
