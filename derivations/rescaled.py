"""The rescaled single-particle system, paper eqs. (rescale), (x-oscill), (y-oscill).

    python derivations/rescaled.py

For k = 1 the equations of motion are rescaled by {x, y, X, t sqrt(gamma/mu)}/(alpha - beta),
the y-equation is linearised about the normal mode y = 0, and the results are compared
with the printed equations (paper's wells) or the radial-force form (circular well).
For n = 1 the term y^(2n) of the well is quadratic, so its
force is linear in y and adds to Hill's coefficient; the paper's (y-oscill) omits it.
"""

import sympy as sp
from _report import check, finish

from sinktheory import symbolic as S
from sinktheory.symbolic import X, alpha, beta, gamma, mu, n, x, xdd

L = alpha - beta
lam = -2 * beta * (alpha - beta)
PAPER_SHAPES = ("flat", "symmetric")

for shape in S.SHAPES:  # every shape whose normal mode y = 0 exists
    if S.normal_mode_refusal(shape):
        continue
    r = S.rescaled_equations(shape)
    derived_xdd = sp.solve(r.x_equation, xdd)[0]
    paper = sp.Eq(xdd + x ** (2 * n - 1), mu / (1 + mu) * (xdd + L**2 / gamma * X))
    paper_xdd = sp.solve(paper, xdd)[0]
    check(f"{shape}: (x-oscill) on the normal mode y = 0", derived_xdd, paper_xdd)
for shape in PAPER_SHAPES:
    r = S.rescaled_equations(shape)
    check(
        f"{shape}: (y-oscill) coefficient q(x) for n >= 2: lambda x^(2n)",
        r.hill_coefficient,
        lam * x ** (2 * n),
    )

check("lambda = -2 beta (alpha - beta)", S.lambda_coefficient(), lam)
check(
    "unloaded oscillator (mu -> 0, right-hand side of x-oscill dropped): x'' = -x^(2n-1)",
    S.oscillator_acceleration(),
    -(x ** (2 * n - 1)),
)
check("Hill's coefficient over lambda: x^(2n)", S.hill_shape(), x ** (2 * n))

# n = 1: the well's y-term gamma y^2/2 (flat) or gamma (y/D(x))^2/2 (symmetric) is
# quadratic; rescaled by (alpha - beta) it contributes L^2 (flat) and
# 1/(1 + beta L x^2)^2 (symmetric, since D(L x) = L (1 + beta L x^2)) to Hill's coefficient.
corrected = {
    "flat": lam * x**2 + L**2,
    "symmetric": lam * x**2 + 1 / (1 + beta * L * x**2) ** 2,
}
for shape in PAPER_SHAPES:
    check(
        f"{shape}: Hill coefficient for n = 1 (corrected form)",
        S.rescaled_equations(shape, 1).hill_coefficient,
        corrected[shape],
        note="the paper's (y-oscill) omits this extra linear term for n = 1",
    )

# The circular well V(r): on y = 0 the transverse force is V'(r) y / r, so Hill's
# coefficient is (1/x) dV/dx on the axis; rescaled, V = x^(2n)/(2n) gives x^(2n-2)
# (1 for n = 1), whatever beta.  Turning the orbit by a small angle, y = eps x(t) solves it.
check(
    "circular: Hill coefficient x^(2n-2)",
    S.rescaled_equations("circular").hill_coefficient,
    x ** (2 * n - 2),
)
check(
    "circular: Hill coefficient for n = 1",
    S.rescaled_equations("circular", 1).hill_coefficient,
    sp.Integer(1),
)
finish()
