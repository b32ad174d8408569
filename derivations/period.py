"""Period of the power-law oscillator x'' + x^(2n-1) = 0, paper eq. (T).

    python derivations/period.py

From the energy E_n = x'^2/2 + x^(2n)/(2n) = A0^(2n)/(2n) the quarter period is
int_0^A0 dx / sqrt(2 (E_n - x^(2n)/(2n))); x = A0 z gives the paper's first line, and the
Beta-function integral gives its Gamma-function form.
"""

import sympy as sp
from _report import check, finish, show

from sinktheory import symbolic as S
from sinktheory.symbolic import A0, E, n

z = sp.Symbol("z", positive=True)
T_int = S.period_integral()
show("period integral", T_int)
(integral,) = T_int.atoms(sp.Integral)
check(
    "period integral (T), first line: 4 x integrand = 4 sqrt(n) / A0^(n-1) / sqrt(1 - z^2n)",
    4 * integral.function,
    4 * sp.sqrt(n) / A0 ** (n - 1) / sp.sqrt(1 - z ** (2 * n)),
)
T = S.period_closed_form()
paper_T = (
    2 / A0 ** (n - 1) * sp.sqrt(sp.pi / n) * sp.gamma(1 / (2 * n)) / sp.gamma((1 + n) / (2 * n))
)
check(
    "period (T), Gamma-function form",
    sp.gammasimp(T / paper_T),
    1,
    probes=[{A0: sp.Rational(3, 2), n: k} for k in (1, 2, 3, 7, 20)],
)
check("T_1 = 2 pi for every amplitude", sp.simplify(T.subs(n, 1)), 2 * sp.pi)
xd = sp.Symbol("xd", real=True)
check(
    "first integral E_n = x'^2/2 + x^(2n)/(2n) (text after eq. T)",
    S.oscillator_energy(),
    xd**2 / 2 + S.x ** (2 * n) / (2 * n),
)
show("amplitude of energy A0(E_n)", S.amplitude_of_energy())
check(
    "A0 = (2 n E_n)^(1/(2n))",
    S.amplitude_of_energy(),
    (2 * n * E) ** (1 / (2 * n)),
    probes=[{E: sp.Rational(1, 3), n: k} for k in (1, 2, 5)],
)
finish()
