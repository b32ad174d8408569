"""Curvature of the rigid-wall contour as n -> oo, paper eq. (kappa).

    python derivations/curvature.py

On the level line V = E of the flat well, x = D(y) (2nE/gamma)^(1/(2n)); the factor
tends to 1, so the rigid wall is x = D(y) = alpha + beta (y^2 - 1), whose curvature is
x''/(1 + x'^2)^(3/2).
"""

from _report import check, finish, show

from sinktheory import symbolic as S
from sinktheory.symbolic import beta, y

show("rigid-wall contour x(y) as n -> oo", S.rigid_wall_contour())
kappa = S.rigid_wall_curvature()
check("curvature (kappa)", kappa, 2 * beta / (1 + 4 * beta**2 * y**2) ** S.sp.Rational(3, 2))
check("beta is half the curvature at y = 0", kappa.subs(y, 0) / 2, beta)
finish()
