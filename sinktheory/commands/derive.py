"""``sinktheory derive``: print the equations derived from the Lagrangian.

With ``--json`` every value is a string that :func:`sympy.sympify` reads back.
"""

from __future__ import annotations

import argparse

import sympy as sp
from sympy.printing.str import StrPrinter

from .. import symbolic as S
from . import HELP as HELPS
from ._common import Output, add_json

NAME = "derive"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--latex", action="store_true", help="print LaTeX instead of text")
    add_json(parser)


def equations() -> dict[str, sp.Expr]:
    """The derived equations, keyed as in the JSON output.

    ``x_equation`` and ``y_equation`` are expressions equal to zero in the plain symbols
    x, y, X, xdd, ydd (second time derivatives), n, mu, alpha, beta, gamma of the rescaled
    single-particle system; ``y_equation`` is linear in y (general n >= 2) and the
    ``y_equation_n1_*`` keys give the n = 1 forms with their extra term.
    """
    flat = S.rescaled_equations("flat")
    return {
        "potential_flat": S.potential("flat"),
        "potential_symmetric": S.potential("symmetric"),
        "hamiltonian": S.hamiltonian(1, "flat"),
        "hamiltonian_symmetric": S.hamiltonian(1, "symmetric"),
        "x_equation": flat.x_equation,
        "y_equation": flat.y_equation,
        "y_equation_n1_flat": S.rescaled_equations("flat", 1).y_equation,
        "y_equation_n1_symmetric": S.rescaled_equations("symmetric", 1).y_equation,
        "lambda": S.lambda_coefficient(),
        "period": S.period_closed_form(),
        "curvature": S.rigid_wall_curvature(),
    }


class _SympifiableStr(StrPrinter):
    """str() that sympify reads back: symbols whose names sympify would take for a
    function or constant (beta, gamma, E, ...) are written as Symbol('name')."""

    def _print_Symbol(self, expr):  # noqa: D102 - printer protocol
        name = expr.name
        if isinstance(sp.sympify(name), sp.Symbol):
            return name
        return f"Symbol({name!r})"


def sympifiable(expr: sp.Expr) -> str:
    """A string of ``expr`` that :func:`sympy.sympify` turns back into the same expression
    (up to symbol assumptions).

    Examples
    --------
    >>> from sinktheory.symbolic import beta, gamma, x
    >>> sympifiable(gamma * x**2 - beta)
    "-Symbol('beta') + Symbol('gamma')*x**2"
    """
    return _SympifiableStr().doprint(expr)


def run(args: argparse.Namespace) -> Output:
    eqs = equations()
    data = {key: sympifiable(expr) for key, expr in eqs.items()}
    if args.latex:
        text = "\n".join(f"% {key}\n{sp.latex(expr)}" for key, expr in eqs.items())
    else:
        text = "\n\n".join(
            f"{key}:\n{sp.pretty(expr, use_unicode=True, wrap_line=False)}"
            for key, expr in eqs.items()
        )
    return Output(data, text)
