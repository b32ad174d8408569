"""The impact law of the rigid-billiard limit: a particle hits the moving container.

    python derivations/billiard.py

The container (mass 1) moves along x, the particle (mass mu) meets its wall with unit
outward normal n.  The impulse is J along n on the particle (-J n) and J n_x on the
container; J follows from energy conservation (sinktheory.billiard.impact).  Checked:
the closed form, conservation of x-momentum, reversal of the relative normal velocity
(Newton's restitution law with e = 1), the unchanged tangential velocity, and the limit
mu -> 0 (a wall of prescribed velocity V: specular reflection in the wall's frame).
"""

import sympy as sp
from _report import check, finish, show

from sinktheory.billiard.impact import (
    V,
    impulse_expression,
    mu,
    n_x,
    n_y,
    v_x,
    v_y,
    velocities_after,
)

J = impulse_expression()
w = (v_x - V) * n_x + v_y * n_y  # relative normal velocity (> 0: approaching)
check("impulse J", J, 2 * mu * w / (1 + mu * n_x**2))
vx1, vy1, V1 = velocities_after(J)
show("particle velocity after", sp.Matrix([vx1, vy1]))
show("container velocity after", V1)
check("x-momentum mu v_x + V conserved", sp.simplify(mu * vx1 + V1 - (mu * v_x + V)), 0)
w1 = (vx1 - V1) * n_x + vy1 * n_y
on_unit_circle = {n_y: sp.sqrt(1 - n_x**2)}
check("relative normal velocity reversed", sp.simplify((w1 + w).subs(on_unit_circle)), 0)
tangential = (vx1 - v_x) * (-n_y) + (vy1 - v_y) * n_x
check("particle's tangential velocity unchanged", sp.simplify(tangential), 0)
limit = [sp.limit(e, mu, 0) for e in (vx1, vy1, V1)]
check(
    "mu -> 0: reflection on a wall moving at V, container unchanged",
    sp.Matrix(limit),
    sp.Matrix([v_x - 2 * w * n_x, v_y - 2 * w * n_y, V]),
)
finish()
