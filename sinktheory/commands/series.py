"""``sinktheory series``: the triangle-wave series, its errors and the paper's bounds."""

from __future__ import annotations

import argparse

from . import HELP as HELPS
from ._common import Output, add_json, number, png_path

__all__ = ["NO_WELL", "HELP", "NAME"]

NAME = "series"
HELP = HELPS[NAME]
#: Why ``--well FILE`` is refused (see :func:`sinktheory.cli.main`).
NO_WELL = "it has no well: the triangle-wave series of the oscillator x'' + x^(2n-1) = 0"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--n", type=number, required=True, help="exponent, integer >= 1")
    parser.add_argument("--order", type=number, required=True, help="highest order i >= 1")
    parser.add_argument("--plot", metavar="FILE.png", help="draw x(t), U_i(t) and the errors")
    add_json(parser)


def run(args: argparse.Namespace) -> Output:
    plot = png_path("plot", args.plot)
    from ..series import accuracy  # SymPy and mpmath: after the cheap checks

    result = accuracy(args.n, args.order)
    n, order, rows, checks = result.n, result.order, result.errors, result.bounds
    data = result.as_dict()
    lines = [
        f"x'' + x^{2 * n - 1} = 0, U_i = A (tau - R_1 - ... - R_i), A0 = U_i(1) = 1",
        "  i   max|U_i - x|/A0   T_i (A0 = 1)       T_i/T_n - 1",
    ]
    lines += [
        f"  {r.order:<3d} {r.shape_error:<17.3e} {float(r.period_estimate):<18.12g} "
        f"{r.period_relative_error:+.3e}"
        for r in rows
    ]
    if checks:
        lines.append("  bounds 0 < R_i < (2n-1)|tau|^(2n+1) / (2^(i-1) (2n+1)^2), 0 < tau <= 1:")
        lines += [
            f"  i = {c.i}: sup R_i/bound = {c.max_ratio:.4f}, min R_i/tau^(2n+1) = "
            f"{c.min_scaled:.3e}  {'holds' if c.holds else 'FAILS'}"
            for c in checks
        ]
    out = Output(data, "\n".join(lines))
    if plot is not None:
        from ..plot.series import plot_series

        fig = plot_series(n, order)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        data["plot"] = str(plot)
    return out
