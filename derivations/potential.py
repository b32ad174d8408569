"""The soft-wall well, paper eqs. (V definition) and (V definition2).

    python derivations/potential.py

Builds V from the wall ratios s1 = x/D(y), s2 = y (flat) or y/D(x) (symmetric) with
D(s) = alpha + beta (s^2 - 1), compares with the printed forms, and checks the symmetries
the analyses rely on (y -> -y and x -> -x for every shape, x <-> y for the symmetric one,
rotations for the circular one, whose V is written out independently here).
"""

import sympy as sp
from _report import check, finish, show

from sinktheory import symbolic as S
from sinktheory.symbolic import alpha, beta, gamma, n, x, y

paper_flat = gamma / (2 * n) * ((x / (alpha + beta * (y**2 - 1))) ** (2 * n) + y ** (2 * n))
paper_symmetric = (
    gamma
    / (2 * n)
    * ((x / (alpha + beta * (y**2 - 1))) ** (2 * n) + (y / (alpha + beta * (x**2 - 1))) ** (2 * n))
)
check("V, flat well (V definition)", S.potential("flat"), paper_flat)
check("V, symmetric well (V definition2)", S.potential("symmetric"), paper_symmetric)
r2 = x**2 + y**2
check(
    "V, circular well", S.potential("circular"), gamma / (2 * n) * (r2 / (alpha - beta) ** 2) ** n
)


def probes(a):
    """Rational test points at alpha = a: beta = +-0.3, n = 1, 2, 5."""
    return [
        {
            x: sp.Rational(3, 10),
            y: sp.Rational(-2, 7),
            alpha: a,
            beta: sp.Rational(b, 10),
            gamma: sp.Rational(13, 10),
            n: k,
        }
        for b in (-3, 3)
        for k in (1, 2, 5)
    ]


check(
    "circular: V depends on r only, V(x, y) = V(r, 0)",
    S.potential("circular"),
    S.potential("circular", sp.sqrt(r2), 0),
    probes=probes(1),
)

for shape in S.SHAPES:
    V = S.potential(shape)
    check(f"{shape}: V(x, -y) = V(x, y)", V.subs(y, -y), V)
    check(f"{shape}: V(-x, y) = V(x, y)", V.subs(x, -x), V)
Vs = S.potential("symmetric")
check("symmetric: V(y, x) = V(x, y)", Vs.subs({x: y, y: x}, simultaneous=True), Vs)

for shape in S.SHAPES:
    Vx, Vy = S.gradient_in_ratios(shape)
    show(f"{shape}: dV/dx in the kernel atoms {', '.join(map(str, S.atom_values(shape)))}", Vx)
    show(f"{shape}: dV/dy in the kernel atoms", Vy)
    V = S.potential(shape)
    check(
        f"{shape}: atom form of dV/dx = dV/dx",
        S.substitute_ratios(Vx, shape),
        sp.diff(V, x),
        probes=probes(sp.Rational(1, 2)),
    )
    check(
        f"{shape}: atom form of dV/dy = dV/dy",
        S.substitute_ratios(Vy, shape),
        sp.diff(V, y),
        probes=probes(sp.Rational(1, 2)),
    )
finish()
