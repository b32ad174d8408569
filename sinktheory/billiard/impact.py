"""The elastic impact of a particle on the moving container, derived with SymPy.

The container (mass 1) moves along x only; a particle of mass mu meets its wall with
unit outward normal n = (n_x, n_y).  The contact force is along n, so the particle's
momentum changes by -J n and the container's by +J n_x (the y part of the reaction is
taken by whatever keeps the container on its axis).  Energy conservation fixes J != 0.
``derivations/billiard.py`` prints the result and checks momentum, restitution and the
mu -> 0 limit; :func:`sinktheory.billiard.kernels.impulse` is checked against it by the
tests.

Examples
--------
>>> impulse_expression()
-2*mu*(V*n_x - n_x*v_x - n_y*v_y)/(mu*n_x**2 + 1)
"""

from __future__ import annotations

import sympy as sp

from ..errors import ParameterError

__all__ = ["impulse_expression", "J", "mu", "velocities_after"]

mu = sp.Symbol("mu", positive=True)
J = sp.Symbol("J", real=True)
v_x, v_y, V, n_x, n_y = sp.symbols("v_x v_y V n_x n_y", real=True)


def real_expression(name: str, value: object, variables=None) -> sp.Expr:
    """``value`` as a real SymPy expression (a SymPy expression or a real number; text is
    refused, as sympify would evaluate it) with no infinity, NaN or imaginary unit in it,
    and, if ``variables`` are given, no free symbol outside them; else ParameterError
    naming ``name``.  The check of the billiard package's SymPy inputs.

    Examples
    --------
    >>> real_expression("impulse", 2.5)
    2.50000000000000
    >>> real_expression("impulse", float("inf"))
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: impulse = inf is not allowed: must be a real SymPy \
expression or a finite real number
    """
    allowed = "a real SymPy expression or a finite real number"
    if variables is not None:
        allowed += " in " + ", ".join(sorted(str(v) for v in variables))
    if isinstance(value, bool | str) or type(value).__name__ in ("bool_", "bool"):
        raise ParameterError(name, value, allowed)
    try:
        expr = sp.sympify(value, strict=True)
    except (sp.SympifyError, TypeError, ValueError):
        raise ParameterError(name, type(value).__name__, allowed) from None
    if (
        not isinstance(expr, sp.Expr)
        or expr.has(sp.nan, sp.zoo, sp.oo, sp.I)
        or expr.is_real is False
        or (variables is not None and not expr.free_symbols <= set(variables))
    ):
        raise ParameterError(name, value if isinstance(value, float) else str(expr), allowed)
    return expr


def velocities_after(impulse: sp.Expr) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(v_x', v_y', V') after the impulse: particle -J n, container +J n_x."""
    impulse = real_expression("impulse", impulse)
    return v_x - impulse * n_x / mu, v_y - impulse * n_y / mu, V + impulse * n_x


def kinetic_energy(vx: sp.Expr, vy: sp.Expr, vc: sp.Expr) -> sp.Expr:
    """mu |v|^2 / 2 + V^2 / 2 (the spring's energy does not change during an impact)."""
    return mu * (vx**2 + vy**2) / 2 + vc**2 / 2


def impulse_expression() -> sp.Expr:
    """J from energy conservation (the non-zero root)."""
    unit = {n_y**2: 1 - n_x**2}
    change = sp.expand(kinetic_energy(*velocities_after(J)) - kinetic_energy(v_x, v_y, V))
    change = sp.expand(change.subs(unit))
    roots = [r for r in sp.solve(change, J) if r != 0]
    if len(roots) != 1:
        raise AssertionError(f"expected one non-zero impulse, got {roots}")
    return sp.factor(roots[0])
