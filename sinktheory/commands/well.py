"""``sinktheory well``: describe a well (wall distance, curvature, reach) and draw it.

With ``--well FILE`` a user's well file instead (:func:`sinktheory.model.user_well_summary`:
its minimum, escape energy and normal mode y = 0 with how each was found, and the reach,
energies measured from V(0, 0))."""

from __future__ import annotations

import argparse

from ..validation import positive
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_well_arguments,
    number,
    parameters_text,
    png_path,
    user_well_from_args,
    well_from_args,
)

__all__ = ["HELP", "NAME"]

NAME = "well"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser, well_file=True)
    parser.add_argument(
        "--particle-energy",
        type=number,
        default=0.5,
        help="the particle energy E whose reach is shown (default 0.5)",
    )
    parser.add_argument("--plot", metavar="FILE.png", help="draw level lines of V")
    add_json(parser)


def _user_well(args: argparse.Namespace, user) -> Output:
    from ..model import user_well_summary

    well, given, check = user
    plot = png_path("plot", args.plot)
    s = user_well_summary(well, args.particle_energy, given, well_check=check)
    text = "\n".join(
        [
            f"{s.name} well  {parameters_text(s.parameters)}",
            f"  V(x, y)               {s.potential}",
            f"  minimum at (0, 0)     {s.minimum}",
            f"  {s.escape}",
            f"  y = 0                 {'invariant' if s.y_invariant else 'not invariant'} "
            f"({s.normal_mode})",
            f"  wall ratios           {', '.join(s.wall_ratios) or 'none'}",
            f"  reach at E = {s.particle_energy:g}     |x| <= {s.reach.x:.6g}, "
            f"|y| <= {s.reach.y:.6g} (E from V(0, 0))",
        ]
    )
    out = Output(s.as_dict(), text)
    if plot is not None:
        from ..plot.well import plot_user_well

        numeric = check.basin.well  # V - V(0, 0) on arrays
        fig = plot_user_well(s, lambda x, y: numeric.f(x, y) - numeric.v0)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        out.data["plot"] = str(plot)
    return out


def run(args: argparse.Namespace) -> Output:
    user = user_well_from_args(args)
    if user is not None:
        return _user_well(args, user)
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
