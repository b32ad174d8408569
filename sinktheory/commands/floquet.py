"""``sinktheory floquet``: Floquet stability of the normal mode y = 0 (paper Fig. 7).

Modes (exactly one of):

* ``--beta B`` (with ``--alpha``): the model's Hill equation at one beta;
* ``--lam L``: the pure Hill equation y'' + L x^(2n) y = 0;
* ``--beta-range LO HI COUNT`` / ``--lam-range LO HI COUNT``: a chart on a grid with
  stability intervals whose ends are located by root finding (not read off the grid).

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
from ._common import Output, add_json, number, png_path

__all__ = ["add_arguments", "HELP", "NAME", "run"]

NAME = "floquet"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--beta", type=number, help="one beta of the model (needs --alpha)")
    mode.add_argument("--lam", type=number, help="one Lam of the pure Hill equation")
    mode.add_argument(
        "--beta-range", nargs=3, type=number, metavar=("LO", "HI", "COUNT"), help="beta grid"
    )
    mode.add_argument(
        "--lam-range", nargs=3, type=number, metavar=("LO", "HI", "COUNT"), help="Lam grid"
    )
    parser.add_argument("--alpha", type=number, help="alpha > 0 of the well (beta modes)")
    parser.add_argument("--n", type=number, required=True, help="wall stiffness, integer >= 1")
    parser.add_argument("--gamma", type=number, default=1.0, help="well strength (default 1)")
    parser.add_argument(
        "--shape", default="flat", help=f"one of {', '.join(SHAPE_NAMES)} (default flat)"
    )
    parser.add_argument(
        "--amplitude", type=number, default=1.0, help="amplitude A0 of x(t) (default 1)"
    )
    parser.add_argument("--plot", metavar="FILE.png", help="chart phi_{T/2} (range modes)")
    add_json(parser)


def _check_alpha(args: argparse.Namespace, beta_mode: bool) -> None:
    if beta_mode and args.alpha is None:
        raise ParameterError("alpha", None, "given with --beta or --beta-range")
    if not beta_mode and args.alpha is not None:
        raise ParameterError("alpha", args.alpha, "omitted for the pure equation (--lam)")


def run(args: argparse.Namespace) -> Output:
    ranged = args.beta_range or args.lam_range
    beta_mode = args.beta is not None or args.beta_range is not None
    _check_alpha(args, beta_mode)
    plot = png_path("plot", args.plot)
    if plot is not None and not ranged:
        raise ParameterError("plot", args.plot, "used with --beta-range or --lam-range")
    from .. import floquet  # numpy and numba: after those checks

    well = {"gamma": args.gamma, "shape": args.shape, "amplitude": args.amplitude}
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
    if not isinstance(count, int):
        raise ParameterError("COUNT", count, "an integer >= 2")
    if beta_mode:
        result = floquet.model_scan(args.alpha, args.beta_range, args.n, **well)
    else:
        result = floquet.pure_scan(args.lam_range, args.n, args.amplitude)
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
