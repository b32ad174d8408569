"""``sinktheory period``: exact period of x'' + x^(2n-1) = 0 at any precision (paper eq. T)."""

from __future__ import annotations

import argparse

from . import HELP as HELPS
from ._common import Output, add_json, number

__all__ = ["NO_WELL", "HELP", "NAME"]

NAME = "period"
HELP = HELPS[NAME]
#: Why ``--well FILE`` is refused (see :func:`sinktheory.cli.main`).
NO_WELL = "it has no well: the oscillator x'' + x^(2n-1) = 0 of one degree of freedom"


def decimal_text(text: str) -> str:
    """argparse type: a number kept as its text, so "0.1" means exactly 1/10 at any precision."""
    number(text)  # the same parse errors as every other numeric option
    return text.strip()


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--n", type=number, required=True, help="exponent, integer >= 1")
    g = parser.add_mutually_exclusive_group(required=True)
    g.add_argument("--amplitude", type=decimal_text, help="amplitude A0 > 0")
    g.add_argument("--energy", type=decimal_text, help="energy E_n = A0^(2n)/(2n) > 0")
    parser.add_argument(
        "--digits",
        type=number,
        default=30,
        help="significant digits printed for A0, E_n and T_n (default 30)",
    )
    add_json(parser)


def run(args: argparse.Namespace) -> Output:
    from ..oscillator import _check_dps as check_dps
    from ..oscillator import oscillator

    digits = check_dps(args.digits, "digits")
    o = oscillator(args.n, amplitude=args.amplitude, energy=args.energy, dps=digits)
    data = o.as_dict()
    lines = [
        f"x'' + x^{2 * o.n - 1} = 0   ({digits} significant digit{'s' * (digits != 1)})",
        f"  amplitude A0   {data['amplitude']}",
        f"  energy    E_n  {data['energy']}",
        f"  period    T_n  {data['period']}",
    ]
    return Output(data, "\n".join(lines))
