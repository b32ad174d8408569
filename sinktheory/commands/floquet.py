"""``sinktheory floquet``: Floquet stability of the normal mode y = 0 (paper Fig. 7).

Modes (exactly one of):

* ``--beta B`` (with ``--alpha``): the model's Hill equation at one beta;
* ``--lam L``: the pure Hill equation y'' + L x^(2n) y = 0;
* ``--beta-range LO HI COUNT`` / ``--lam-range LO HI COUNT``: a chart on a grid with
  stability intervals whose ends are located by root finding (not read off the grid);
* ``--well FILE`` (``--well-param NAME=VALUE``): a user's well file, on the orbit along
  y = 0 with turning point x = ``--amplitude`` (:func:`sinktheory.floquet.well_floquet`),
  or a chart over ``--amplitude-range LO HI COUNT`` with located boundaries
  (:func:`sinktheory.floquet.well_scan`); refused with the reason when y = 0 is not
  invariant.

Huge numbers.  In deeply unstable zones phi and the multipliers can exceed float range.
A value whose magnitude is below 1e300 (and, for the small multiplier, above 1e-300) is
a JSON number; otherwise it is a decimal string such as ``"-3.14159265e+512"`` with 8
decimals, the precision the logarithm it is built from supports.  ``log_abs_phi_half``
and ``log_abs_phi`` (natural logarithms) are always plain numbers.
"""

from __future__ import annotations

import argparse

from .._generated.shapes import NAMES as SHAPE_NAMES
from ..errors import ParameterError
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_well_file,
    number,
    parameters_text,
    png_path,
    user_well_from_args,
)

__all__ = ["HELP", "NAME"]

NAME = "floquet"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--beta", type=number, help="one beta of the model (needs --alpha)")
    mode.add_argument("--lam", type=number, help="one Lam of the pure Hill equation")
    mode.add_argument(
        "--beta-range", nargs=3, type=number, metavar=("LO", "HI", "COUNT"), help="beta grid"
    )
    mode.add_argument(
        "--lam-range", nargs=3, type=number, metavar=("LO", "HI", "COUNT"), help="Lam grid"
    )
    add_well_file(parser, exclusive=mode)
    parser.add_argument("--alpha", type=number, help="alpha > 0 of the well (beta modes)")
    parser.add_argument(
        "--n", type=number, help="wall stiffness, integer >= 1 (required unless --well)"
    )
    parser.add_argument("--gamma", type=number, help="well strength (default 1)")
    parser.add_argument("--shape", help=f"one of {', '.join(SHAPE_NAMES)} (default flat)")
    parser.add_argument(
        "--amplitude", type=number, default=1.0, help="amplitude A0 of x(t) (default 1; with "
        "--well the turning point x = A0 of the orbit on y = 0)",
    )  # fmt: skip
    parser.add_argument(
        "--amplitude-range", nargs=3, type=number, metavar=("LO", "HI", "COUNT"),
        help="with --well: a chart over the amplitude, boundaries located",
    )  # fmt: skip
    parser.add_argument("--plot", metavar="FILE.png", help="chart phi_{T/2} (range modes)")
    add_json(parser)


def _check_alpha(args: argparse.Namespace, beta_mode: bool) -> None:
    """Refuse alpha where the mode has none (and a missing one or a missing n)."""
    if beta_mode and args.alpha is None:
        raise ParameterError("alpha", None, "given with --beta or --beta-range")
    if not beta_mode and args.alpha is not None:
        raise ParameterError("alpha", args.alpha, "omitted for the pure equation (--lam)")
    if args.n is None:
        raise ParameterError("n", None, "given (or --well FILE)")


def _user_well(args: argparse.Namespace, user) -> Output:
    from ..floquet import well_hill, well_scan

    if args.plot is not None:
        raise ParameterError("plot", args.plot, "used with --beta-range or --lam-range")
    well, given, check = user
    hill = well_hill(well, given, well_check=check)
    if args.amplitude_range is not None:
        lo, hi, count = args.amplitude_range
        if not isinstance(count, int):
            raise ParameterError("count", count, "an integer >= 2")
        chart = well_scan(hill, args.amplitude_range)
        which = "phi_T/2" if chart.symmetric else "phi"
        lines = [f"{chart.name} well {parameters_text(chart.parameters)}: {which} over the "
                 f"amplitude in [{lo:g}, {hi:g}]"]  # fmt: skip
        lines += [f"  stable  [{a:.12g}, {b:.12g}]" for a, b in chart.stable_intervals]
        lines += [f"  {which} = {b.phi_half:g} at A = {b.value:.12g} ({b.factor} = 0)"
                  for b in chart.boundaries]  # fmt: skip
        return Output(chart.as_dict(), "\n".join(lines))
    f = hill.at(args.amplitude)
    data = f.as_dict()
    state = "stable" if f.stable else "unstable"
    rho = ", ".join(f"{complex(r):.12g}" for r in f.multipliers)
    lines = [
        f"{f.name} well {parameters_text(f.parameters)}: orbit on y = 0 from x = "
        f"{f.amplitude:g} (energy {f.particle_energy:.12g} above V(0, 0)), period "
        f"{f.period:.12g} (mass 1)",
        f"  Hill's coefficient V_yy(x, 0) = {f.hill_coefficient}",
        (f"  phi_T/2 = {f.phi_half:.12g}  " if f.symmetric else "  ")
        + f"phi = {f.phi:.12g}  ({state})",
        f"  multipliers {rho}",
        # as the registered charts print it; without symmetry there is no half-period map
        (f"  rotation number {f.rotation_number:.12g}, " if f.symmetric else "  ")
        + f"growth per period {f.growth_per_period:.12g}",
    ]
    return Output(data, "\n".join(lines))


def run(args: argparse.Namespace) -> Output:
    user = user_well_from_args(args)
    if user is not None:
        return _user_well(args, user)
    if args.amplitude_range is not None:
        raise ParameterError("amplitude_range", args.amplitude_range, "used with --well FILE")
    if not (args.beta is not None or args.lam is not None or args.beta_range or args.lam_range):
        raise ParameterError(
            "beta", None, "one of --beta, --lam, --beta-range, --lam-range or --well given"
        )
    ranged = args.beta_range or args.lam_range
    beta_mode = args.beta is not None or args.beta_range is not None
    _check_alpha(args, beta_mode)
    plot = png_path("plot", args.plot)
    if plot is not None and not ranged:
        raise ParameterError("plot", args.plot, "used with --beta-range or --lam-range")
    from .. import floquet  # numpy and numba: after those checks

    gamma = 1.0 if args.gamma is None else args.gamma  # None: refused beside --well
    shape = "flat" if args.shape is None else args.shape
    well = {"gamma": gamma, "shape": shape, "amplitude": args.amplitude}
    key = "beta" if beta_mode else "lam"
    if not ranged:
        if beta_mode:
            chart = floquet.model_hill(args.alpha, [args.beta], args.n, **well)
        else:
            chart = floquet.pure_hill([args.lam], args.n, args.amplitude)
        value = args.beta if beta_mode else args.lam
        data = chart.as_dict(point=0)
        state = "stable" if data["stable"] else "unstable"
        text = (
            f"{key} = {value:g}, n = {chart.problem.n}: lambda = {data['lambda']:.12g}\n"
            f"  phi_T/2 = {data['phi_half']}  phi = {data['phi']}  ({state})\n"
            f"  rotation number {data['rotation_number']:.12g}, "
            f"growth per period {data['growth_per_period']:.12g}"
        )
        return Output(data, text)
    lo, hi, count = ranged
    option = "beta_range" if beta_mode else "lam_range"
    try:  # the scan names the parts (lo, hi, count); the command names its option
        if not isinstance(count, int):
            raise ParameterError("count", count, "an integer >= 2")
        if beta_mode:
            result = floquet.model_scan(args.alpha, args.beta_range, args.n, **well)
        else:
            result = floquet.pure_scan(args.lam_range, args.n, args.amplitude)
    except ParameterError as exc:
        if exc.name not in ("lo", "hi", "count"):
            raise
        allowed = "LO HI COUNT: finite LO < HI and a whole COUNT >= 2"
        raise ParameterError(option, (lo, hi, count), allowed, why=str(exc)) from None
    problem = result.chart.problem
    data = result.as_dict()
    lines = [f"{problem.kind} Hill equation, n = {problem.n}, {key} in [{lo:g}, {hi:g}]"]
    lines += [f"  stable  [{a:.12g}, {b:.12g}]" for a, b in result.stable_intervals]
    lines += [f"  phi_T = -1 at {key} = {r:.12g}" for r in result.resonances]
    out = Output(data, "\n".join(lines))
    if plot is not None:
        from ..plot.floquet import plot_scan

        fig = plot_scan(result)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        data["plot"] = str(plot)
    return out
