"""Lagrangian (Lagr), Legendre transform (Hamiltonian), equations of motion, and the
canonical change u_j = X + x_j that separates H.

    python derivations/hamiltonian.py
"""

import sympy as sp
from _report import check, finish, show

from sinktheory import symbolic as S
from sinktheory.symbolic import P, X, mu, p_x, p_y, x, y

L, m = S.lagrangian(1, "flat")
show("Lagrangian (Lagr), k = 1", L)

H = S.hamiltonian(1, "flat")
V = S.potential("flat")
expected = (P - p_x) ** 2 / 2 + X**2 / 2 + (p_x**2 + p_y**2) / (2 * mu) + V
check(
    "Hamiltonian (Hamiltonian), k = 1",
    H,
    expected,
    note="the paper's Legendre sum lists only p_j x_j'; the y-momenta p_y enter as well "
    "(with p_y = mu y').",
)

k = 3
Hk = S.hamiltonian(k, "symmetric")
mk = S.mechanics(k)
pxs, pys = mk.momenta[1 : 1 + k], mk.momenta[1 + k :]
expected_k = (P - sum(pxs)) ** 2 / 2 + X**2 / 2
expected_k += sum((a**2 + b**2) / (2 * mu) for a, b in zip(pxs, pys, strict=True))
expected_k += sum(S.potential("symmetric", a, b) for a, b in zip(mk.xs, mk.ys, strict=True))
check(f"Hamiltonian, k = {k}, symmetric well", Hk, expected_k)

acc = S.equations_of_motion(1, "flat")
show("accelerations (Euler-Lagrange), k = 1, in kernel atoms", acc)
# Independent: from L directly, mu (X'' + x'') = -V_x and (1 + mu) X'' + mu x'' = -X.
Xdd, xdd_ = sp.symbols("Xdd xdd_")
Vx = sp.diff(V, x)
sol = sp.solve([mu * (Xdd + xdd_) + Vx, (1 + mu) * Xdd + mu * xdd_ + X], [Xdd, xdd_])
for q, a in ((X, sol[Xdd]), (x, sol[xdd_])):
    check(
        f"acceleration of {q} from the two Euler-Lagrange equations",
        S.substitute_ratios(acc[q], "flat"),
        a,
    )
check("acceleration of y: mu y'' = -V_y", S.substitute_ratios(acc[y], "flat"), -sp.diff(V, y) / mu)

sh = S.separable_hamiltonian(k, "flat")
show("separable Hamiltonian after u_j = X + x_j (k = 3): kinetic part", sh.kinetic)
show("potential part", sh.potential)
masses = sp.diag(*[1 / sp.diff(sh.kinetic, p, 2) for p in sh.momenta])
mixed = [sp.diff(sh.kinetic, a, b) for i, a in enumerate(sh.momenta) for b in sh.momenta[i + 1 :]]
check("kinetic energy has no cross terms (diagonal mass matrix)", sp.Add(*map(abs, mixed)), 0)
check("mass matrix = diag(1, mu, ..., mu)", masses, sp.diag(1, *[mu] * (2 * k)))
check(
    "kinetic part is free of coordinates",
    sp.Integer(sum(1 for q in sh.coordinates if sh.kinetic.has(q))),
    0,
)
check(
    "potential part is free of momenta",
    sp.Integer(sum(1 for p in sh.momenta if sh.potential.has(p))),
    0,
)
finish()
