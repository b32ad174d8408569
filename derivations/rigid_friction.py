"""Kinetic theory of the rigid limit: the container's friction and diffusion from impacts.

    python derivations/rigid_friction.py

A particle of mass mu and speed c (energy e = mu c^2 / 2), uniform over a rigid table of
area A with an isotropic velocity (its microcanonical measure), hits the boundary element
ds with outward normal n at the rate (w)_+ ds / A per direction (dtheta / 2 pi), w the
normal velocity relative to the container moving at V along x.  Each impact gives the
container the momentum J n_x (sinktheory.billiard.impact; J = 2 mu w to first order in
mu, container mass 1).  Averaged over directions and the boundary, to first order in V and
mu:

* drift   <dP/dt>     = -gamma V,  gamma = 4 mu c W / (pi A),
* diffusion <dP^2>/dt = 2 D,       D = 4 mu^2 c^3 W / (3 pi A),   D / gamma = 2 e / 3,

with W = oint n_x^2 ds (the closed boundary's oint n_x ds vanishes).  For the container
energy E_c = (P^2 + X^2) / 2 averaged over its phase (<V^2> = E_c), D1 = -gamma E_c + D
and D2 = D E_c per unit time.  With k particles the table's density of states is flat,
so their energies are uniform on the simplex (each e_j = e_p x_j, x_j ~ Beta(1, k - 1),
e_p = E - E_c): D1 and D2 are the sums over particles averaged over the split.  Checked:
the impulse's first order in mu, the angular averages, the energy coefficients, and the
fluctuation-dissipation relation D1 p = d(D2 p)/dE_c for the exact rigid law
p ~ (E - E_c)^(k - 1) (Beta(1, k), the n -> oo limit of Beta(1, k (1 + 1/n))) for every k:
the kinetic coefficients have the law as their stationary state.
"""

import sympy as sp
from _report import check, finish, show

from sinktheory.billiard.impact import V, impulse_expression, mu, n_x, n_y, v_x, v_y

c, A, W, e, E, Ec, ep = sp.symbols("c A W e E E_c e_p", positive=True)
alpha, b = sp.symbols("alpha b", real=True)
k = sp.Symbol("k", positive=True, integer=True)

# the impulse to first order in mu, in terms of the relative normal velocity w
w = sp.Symbol("w", real=True)
J = impulse_expression()
relative = (v_x - V) * n_x + v_y * n_y
J1 = sp.series(J, mu, 0, 2).removeO()
check("impulse to first order in mu", sp.simplify(J1 - 2 * mu * relative), 0)

# angular averages over the directions that reach the wall: w = c cos(alpha) - b, b = V n_x
edge = sp.acos(b / c)


def angular(power: int) -> sp.Expr:
    """(1/2 pi) int over w > 0 of w^power, to first order in b."""
    integral = sp.integrate((c * sp.cos(alpha) - b) ** power, (alpha, -edge, edge)) / (2 * sp.pi)
    return sp.series(sp.simplify(integral), b, 0, 2).removeO()


second, third = angular(2), angular(3)
check("<w_+ w> over directions", sp.expand(second), c**2 / 4 - 2 * c * b / sp.pi)
check("<w_+ w^2> over directions at V = 0", sp.expand(third.subs(b, 0)), 2 * c**3 / (3 * sp.pi))

# the container's momentum: rate (w)_+ / A, change 2 mu w n_x; oint n_x ds = 0, oint n_x^2 ds = W
drift_per_length = 2 * mu * n_x * second.subs(b, V * n_x) / A
drift = sp.expand(drift_per_length).coeff(n_x, 2) * W  # the n_x^1 term integrates to 0
gamma = -sp.simplify(drift / V)
check("friction rate gamma", gamma, 4 * mu * c * W / (sp.pi * A))
D = sp.simplify((2 * mu) ** 2 * third.subs(b, 0) * W / A / 2)
check("momentum diffusion D", D, 4 * mu**2 * c**3 * W / (3 * sp.pi * A))
speed = sp.sqrt(2 * e / mu)
check("D / gamma = 2 e / 3", sp.simplify((D / gamma).subs(c, speed)), 2 * e / 3)
g = sp.Symbol("g", positive=True)  # 4 sqrt(2 mu) W / (pi A)
check("gamma = g sqrt(e)", sp.simplify(gamma.subs(c, speed)),
      4 * sp.sqrt(2 * mu) * W / (sp.pi * A) * sp.sqrt(e))  # fmt: skip
show("g", 4 * sp.sqrt(2 * mu) * W / (sp.pi * A))

# k particles, energies uniform on the simplex: E[x^(1/2)] and E[x^(3/2)], x ~ Beta(1, k - 1)
x = sp.Symbol("x", positive=True)


def beta_moment(power) -> sp.Expr:
    return sp.gamma(power + 1) * sp.gamma(k) / sp.gamma(k + power)


a_k, b_k = beta_moment(sp.Rational(1, 2)), beta_moment(sp.Rational(3, 2))
check("E[x^(1/2)] for k = 3", a_k.subs(k, 3),
      sp.integrate(x ** sp.Rational(1, 2) * 2 * (1 - x), (x, 0, 1)))  # fmt: skip
D1 = k * g * (-a_k * Ec * sp.sqrt(ep) + sp.Rational(2, 3) * b_k * ep ** sp.Rational(3, 2))
D2 = k * g * sp.Rational(2, 3) * b_k * ep ** sp.Rational(3, 2) * Ec
show("D1(E_c), e_p = E - E_c", D1)
show("D2(E_c)", D2)
law = (E - Ec) ** (k - 1)
on_shell = {ep: E - Ec}
residual = D1.subs(on_shell) * law - sp.diff((D2.subs(on_shell) * law), Ec)
ratio = sp.gammasimp(sp.expand(residual / (E - Ec) ** (k - sp.Rational(3, 2)) / (g * k)))
half = k + sp.Rational(1, 2)
ratio = sp.simplify(ratio.subs(sp.gamma(half + 1), half * sp.gamma(half)))  # Gamma recurrence
check("fluctuation-dissipation with the rigid law Beta(1, k), every k", ratio, 0,
      probes=[{k: j, E: 1, Ec: sp.Rational(1, 3)} for j in range(1, 7)])  # fmt: skip
finish()
