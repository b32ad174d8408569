"""``sinktheory billiard``: the rigid limit n -> oo of the sink, an exact billiard.

The table is the well's rigid wall (``--shape``, ``--alpha``, ``--beta``; or ``--well FILE``,
a user's well file with wall ratios, :func:`sinktheory.billiard.well_billiard`); the runs start
as ``sinktheory simulate`` starts them (same seed, same positions): the container at
X = sqrt(2 E0) at rest, the particles at rest.  With ``--fixed`` the container stays
still and the particles share E0 in seeded random directions.  Exponents are per unit
time (T = 2 pi), ensemble mean +- standard error std(ddof=1)/sqrt(R), and split into
regular and chaotic runs (:func:`sinktheory.chaos.verdicts.split`): a table with islands
has both, in a proportion the start distribution sets.
"""

from __future__ import annotations

import argparse

from ..errors import ParameterError
from ..runstats import plus_minus
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_sink_arguments,
    add_well_file,
    add_work_limit,
    number,
    parameters_text,
    png_path,
    user_well_from_args,
)

__all__ = ["HELP", "NAME"]

NAME = "billiard"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from ..model import SHAPES

    g = parser.add_argument_group("table (the rigid wall of the well)")
    g.add_argument("--alpha", type=number, help="alpha > 0 (required unless --well)")
    g.add_argument(
        "--beta", type=number, help="beta < alpha (curvature/2) (required unless --well)"
    )
    g.add_argument("--shape", help=f"one of {', '.join(SHAPES)} (default flat)")
    add_well_file(g)
    s = add_sink_arguments(parser)
    s.add_argument("--fixed", action="store_true", help="keep the container fixed")
    s.add_argument(
        "--lyapunov",
        action="store_true",
        help="lambda_1 (tangent map if fixed, two nearby trajectories if moving)",
    )
    o = parser.add_argument_group("output")
    o.add_argument("--plot", help="draw the table, <E>(t) and lambda_1(t) to FILE.png")
    add_json(parser)
    add_work_limit(parser)


def _fmt(stats: dict) -> str:
    """``mean +- se`` of an ensemble statistic, or why there is none.

    Examples
    --------
    >>> _fmt({"mean": 0.5, "stderr": 0.01}), _fmt({"mean": None, "stderr": None})
    ('0.5 +- 0.01', 'undefined (a run had no impact)')
    >>> _fmt({"mean": 0.5, "stderr": None})
    '0.5 (no standard error from one run)'
    """
    if stats["mean"] is None:
        return "undefined (a run had no impact)"
    return plus_minus(stats["mean"], stats["stderr"])


def run(args: argparse.Namespace) -> Output:
    from ..billiard import billiard, well_billiard
    from ..model import RunSettings

    user = user_well_from_args(args)
    if user is None:
        for name in ("alpha", "beta"):
            if getattr(args, name) is None:
                raise ParameterError(name, None, "given (or --well FILE instead of the shape)")
    plot = png_path("plot", args.plot)
    settings = RunSettings(
        container_energy=args.container_energy, runs=args.runs, periods=args.periods,
        seed=args.seed,
    )  # fmt: skip
    runs = dict(particles=args.particles, mass=args.mass, settings=settings, fixed=args.fixed,
                lyapunov=args.lyapunov)  # fmt: skip
    if user is None:
        shape = "flat" if args.shape is None else args.shape
        result = billiard(shape, args.alpha, args.beta, **runs)
        well = f"alpha={args.alpha:g} beta={args.beta:g}"
    else:
        well_file, given, _ = user
        result = well_billiard(well_file, given, **runs)
        well = parameters_text(result.table.parameters)
    data = result.as_dict()
    t = result.table
    kmin, kmax = t.curvature_range()
    lines = [
        f"rigid {t.name} table {well}: area {t.area:.6g}, "
        f"perimeter {t.perimeter:.6g}, curvature {kmin:.3g} .. {kmax:.3g} "
        "(> 0 dispersing), Santalo mean free path pi A/P = " + f"{t.mean_free_path:.6g}",
        f"{'fixed' if result.fixed else 'moving'} container; k={result.particles}, "
        f"m={args.mass:g}; {settings.runs} run(s) x {settings.periods} period(s); "
        f"{int(result.collisions.sum())} impacts; max relative energy error "
        f"{result.max_relative_energy_error:.3g}",
        f"mean free time {_fmt(data['mean_mean_free_time'])}",
    ]
    if not result.fixed:
        e = result.container_energy
        lines.append(
            f"<E>(0) = {e[:, 0].mean():.6f}   <E>({settings.periods} T) = {e[:, -1].mean():.6f}"
        )
    if result.logs is not None:
        lines.append(
            f"lambda_1 = {_fmt(data['mean_lambda1'])} per unit time, "
            f"{_fmt(data['mean_lambda1_per_collision'])} per impact ({result.lyapunov_method})"
        )
        lines.append("lambda_1 " + result.split().text())
    writers = {}
    if plot is not None:

        def draw(path):
            from ..plot.billiard import billiard_figure

            billiard_figure(result).savefig(path, dpi=120)

        writers[plot] = draw
    return Output(data, "\n".join(lines), writers)
