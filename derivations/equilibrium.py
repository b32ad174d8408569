"""The equilibrium law of the container energy: separation, density of states, Beta law.

    python derivations/equilibrium.py

1. In the separable coordinates (X, u_j, y_j) of :func:`sinktheory.symbolic.
   separable_hamiltonian`, the shift u_j -> x_j = u_j - X at fixed X has Jacobian 1 and
   splits H into the container oscillator P^2/2 + X^2/2 plus k one-particle Hamiltonians
   p^2/(2 mu) + V(x_j, y_j); the momenta are untouched.  So the microcanonical density of
   E_c = P^2/2 + X^2/2 on H = E is the container's density of states (2 pi) times G_k(E - E_c),
   G_k the k-fold convolution of one particle's density of states g.
2. One particle: the momenta with p^2/(2 mu) < e - V fill a disc of area 2 pi mu (e - V),
   so the phase volume is Phi(e) = 2 pi mu int (e - V)_+ dx dy and g = Phi' = 2 pi mu A(e).
3. Homogeneous wells: A(e) = A_1 e^(1/n) (scaling x, y by e^(1/(2n))); powers convolve as
   e^(a-1) * e^(b-1) = B(a, b) e^(a+b-1), so G_k ~ e^(k(1+1/n) - 1) and s = E_c / E has the
   density b (1 - s)^(b-1), b = k (1 + 1/n): Beta(1, b), with mean 1/(1 + b), which is the
   equipartition estimate of sinktheory.sinkstats.
4. The closed-form areas of sinktheory.equilibrium.area: flat well
   A = 2 t (L J_0 + beta t J_2), J_m = B((m+1)/(2n), 1 + 1/(2n)) / n, t = (2 n e/gamma)^(1/n),
   checked exactly for n = 1 and by 40-digit quadrature for n = 2, 3; circular pi L^2 t.
"""

import mpmath
import sympy as sp
from _report import check, finish, show

from sinktheory import symbolic as S
from sinktheory.symbolic import X, beta, gamma, mu, n

k = 2
sh = S.separable_hamiltonian(k, "flat")
H = sh.kinetic + sh.potential
us, ys = sh.coordinates[1 : 1 + k], sh.coordinates[1 + k :]
Pi, pus, pys = sh.momenta[0], sh.momenta[1 : 1 + k], sh.momenta[1 + k :]
xs = sp.symbols(f"x_1:{k + 1}", real=True)
shift = {u: xj + X for u, xj in zip(us, xs, strict=True)}
H_shifted = sp.expand(H.subs(shift, simultaneous=True))
container = Pi**2 / 2 + X**2 / 2
particles = sum(
    (a**2 + b**2) / (2 * mu) + S.potential("flat", xj, yj)
    for a, b, xj, yj in zip(pus, pys, xs, ys, strict=True)
)
check(
    f"H after u_j = x_j + X (k = {k}): container + independent particles",
    H_shifted,
    container + particles,
)
jac = sp.Matrix([X, *[u.subs(shift) for u in us], *ys]).jacobian([X, *xs, *ys])
check("Jacobian of (X, x_j, y_j) -> (X, u_j, y_j)", jac.det(), 1)

# one particle: area of the momentum disc p^2/(2 mu) < w (w = e - V > 0)
wv, p, phi = sp.symbols("w p phi", positive=True)
disc = sp.integrate(sp.integrate(p, (p, 0, sp.sqrt(2 * mu * wv))), (phi, 0, 2 * sp.pi))
check("momentum area {p^2/(2 mu) < e - V}", disc, 2 * sp.pi * mu * wv)
show(
    "so g(e) = d/de [2 pi mu int (e - V)_+ dx dy] = 2 pi mu A(e)",
    2 * sp.pi * mu * sp.Symbol("A(e)"),
)
# the container: {P^2/2 + X^2/2 < E_c} is a disc of radius sqrt(2 E_c): area 2 pi E_c
Ec = sp.Symbol("E_c", positive=True)
check(
    "container phase area below E_c (density of states 2 pi)",
    sp.pi * (sp.sqrt(2 * Ec)) ** 2,
    2 * sp.pi * Ec,
)

# convolution of powers, at exact exponents of the form 1 + j/n (and 1, the container)
e, s = sp.symbols("e s", positive=True)
for a_, b_ in ((sp.Rational(5, 4), sp.Integer(1)), (sp.Rational(3, 2), sp.Integer(2))):
    conv = sp.integrate((e * s) ** (a_ - 1) * (e * (1 - s)) ** (b_ - 1) * e, (s, 0, 1))
    check(
        f"e^(a-1) * e^(b-1) = B(a, b) e^(a+b-1) at a = {a_}, b = {b_}",
        sp.gammasimp(conv),
        sp.gammasimp(sp.beta(a_, b_) * e ** (a_ + b_ - 1)),
    )
a_, b_ = sp.Rational(5, 4), sp.Rational(9, 4)
conv = sp.hyperexpand(sp.integrate(s ** (a_ - 1) * (1 - s) ** (b_ - 1), (s, 0, 1)))
check(
    "B(5/4, 9/4) from the integral, to 30 digits",
    sp.Integer(int(bool(abs(sp.N(conv - sp.beta(a_, b_), 30)) < 1e-28))),
    1,
)

# homogeneous law: density of s proportional to G_k(E (1 - s)) ~ (1 - s)^(b - 1)
bs, sv, Etot = sp.symbols("b s E", positive=True)
density = (1 - sv) ** (bs - 1)
Z = sp.integrate(density, (sv, 0, 1), conds="none")
check("normalisation of (1 - s)^(b - 1)", sp.simplify(Z), 1 / bs)
mean = sp.simplify(sp.integrate(sv * density, (sv, 0, 1), conds="none") / Z)
kk = sp.Symbol("k", positive=True, integer=True)
check(
    "E times the mean of Beta(1, b), b = k (1 + 1/n): the equipartition E / (1 + k (1 + 1/n))",
    sp.simplify((Etot * mean).subs(bs, kk * (1 + 1 / n))),
    Etot / (1 + kk * (1 + 1 / n)),
)

# the flat well's area: |y| < c, |x| < D(y) (c^(2n) - y^(2n))^(1/(2n)), D = L + beta y^2
L, c, y, tau = sp.symbols("L c y tau", positive=True)


def flat_closed(nv):
    J = [sp.beta(sp.Rational(m + 1, 2 * nv), 1 + sp.Rational(1, 2 * nv)) / nv for m in (0, 2)]
    return 2 * c**2 * (L * J[0] + beta * c**2 * J[1])


slice_n1 = sp.integrate(2 * (L + beta * y**2) * sp.sqrt(c**2 - y**2), (y, -c, c))
check(
    "flat area, n = 1: int 2 D(y) sqrt(c^2 - y^2) dy = closed form",
    slice_n1,
    sp.simplify(sp.gammasimp(flat_closed(1))),
)
VALUES = {L: sp.Rational(1, 5), beta: sp.Rational(3, 10), c: sp.Rational(11, 10)}


def flat_area_40_digits(nv):
    """int_{-c}^{c} 2 D(y) (c^(2n) - y^(2n))^(1/(2n)) dy by mpmath at 40 digits."""
    with mpmath.workdps(40):
        cv, Lv, bv = (mpmath.mpf(VALUES[s_].p) / VALUES[s_].q for s_ in (c, L, beta))

        def width(yy):
            return (
                2
                * (Lv + bv * yy**2)
                * (cv ** (2 * nv) - yy ** (2 * nv)) ** (1 / mpmath.mpf(2 * nv))
            )

        return sp.Float(str(mpmath.quad(width, [-cv, 0, cv])), 40)


for nv in (2, 3):
    ref = flat_area_40_digits(nv)
    closed = sp.N(flat_closed(nv).subs(VALUES), 40)
    print(f"\n== flat area, n = {nv}: 40-digit quadrature {ref:.20} vs closed form {closed:.20}")
    check(
        f"flat area, n = {nv}, agrees to 1e-25", sp.Integer(int(bool(abs(ref - closed) < 1e-25))), 1
    )

# circular well: V = gamma/(2n) (r/L)^(2n) < e  <=>  r < L c, area pi L^2 c^2
r = sp.Symbol("r", positive=True)
radius = sp.solve(sp.Eq(gamma / (2 * n) * (r / L) ** (2 * n), gamma / (2 * n) * c ** (2 * n)), r)
check("circular well: the level V = e is the circle r = L c", radius[0], L * c)
check("and its area pi L^2 t, t = c^2", sp.pi * radius[0] ** 2, sp.pi * L**2 * c**2)
show("t = c^2 in terms of e", sp.Eq(c**2, (2 * n * sp.Symbol("e") / gamma) ** (1 / n)))
check(
    "flat well at beta = 0 is homogeneous: A = alpha * superellipse * t",
    sp.gammasimp(sp.expand_func(flat_closed(1).subs(beta, 0))),
    sp.pi * L * c**2,
)
finish()
