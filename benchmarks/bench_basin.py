"""Accuracy and cost of the basin of a user's well (sinktheory.basin, issue 36 item 2).

The three built-in shapes entered as user expressions, an elliptic well and the
Henon-Heiles well, against closed forms and the registry::

    python benchmarks/bench_basin.py

prints the machine, then the largest relative error of each quantity over the cases
(escape energies: the symmetric corner saddle from ``symbolic.symmetric_corner_saddle``,
the poles of beta < 0 in closed form, Henon-Heiles' 1/6; reach: ``Well.reach`` where it is
exact; areas: ``equilibrium.area.basin_area``'s closed forms and pi a b (2 n e /
gamma)^(1/n)), the cases the area quadrature refuses, and the time of one
``check_well`` (symbolic checks and the escape search), best of 3.
"""

from __future__ import annotations

import math

from machine import best_of, describe  # benchmarks/ is on sys.path when run as a script

from sinktheory import symbolic as S
from sinktheory.equilibrium.area import basin_area
from sinktheory.errors import NumericalError
from sinktheory.model import Well
from sinktheory.userwell import UserWell, check_well

BUILT_IN = {
    "flat": "gamma/(2*n) * ((x/(alpha + beta*(y**2 - 1)))**(2*n) + y**(2*n))",
    "symmetric": "gamma/(2*n) * ((x/(alpha + beta*(y**2 - 1)))**(2*n)"
    " + (y/(alpha + beta*(x**2 - 1)))**(2*n))",
    "circular": "gamma/(2*n) * ((x**2 + y**2)/(alpha - beta)**2)**n",
}
PAPER = {"alpha": 0.5, "beta": (0.3, (-5.0, 0.45)), "gamma": 1.0, "n": (4, (1, 1000))}
ALPHA = 0.5


def main() -> None:
    print(describe())
    worst: dict[str, float] = {}
    refused = []

    def record(key: str, error: float) -> None:
        worst[key] = max(worst.get(key, 0.0), error)

    def basin(shape, **given):
        return check_well(UserWell(f"{shape}_user", BUILT_IN[shape], PAPER), **given).basin

    for n in (1, 2, 4, 10):
        saddle = S.symmetric_corner_saddle()[1]
        exact = float(saddle.subs({S.alpha: ALPHA, S.beta: 0.3, S.n: n, S.gamma: 1}))
        got = basin("symmetric", n=n).escape.escape_potential
        record("escape: symmetric saddle", abs(got / exact - 1))
        for shape in ("flat", "symmetric"):
            pole = math.sqrt(1 - ALPHA / -0.7)
            axis = pole / (ALPHA + 0.7) if shape == "symmetric" else pole
            got = basin(shape, n=n, beta=-0.7).escape.escape_potential
            record("escape: poles (beta < 0)", abs(got / (axis ** (2 * n) / (2 * n)) - 1))
        cases = (("flat", 0.3), ("flat", -0.7), ("circular", 0.3), ("symmetric", -0.7))
        for shape, beta in cases:
            b = basin(shape, n=n, beta=beta)
            well = Well(ALPHA, beta, n, shape=shape)
            for e in (0.01, 0.05):
                r, registry = b.reach(e), well.reach(e)
                record("reach", max(abs(r.x_max / registry[0] - 1), abs(r.y_max / registry[1] - 1)))
                if shape == "symmetric":
                    continue
                try:
                    record("area: built-in closed forms", abs(b.area(e) / basin_area(well, e) - 1))
                except NumericalError as exc:
                    refused.append(f"{shape} beta={beta} n={n} e={e}: {exc}")
    for n in (1, 2, 5, 20):
        params = {"a": 0.3, "b": 0.2, "gamma": 2.0, "n": n}
        b = check_well(UserWell("ellipse", "gamma/(2*n) * ((x/a)**2 + (y/b)**2)**n", params)).basin
        for e in (0.01, 0.5):
            exact = math.pi * 0.3 * 0.2 * (2 * n * e / 2.0) ** (1 / n)
            record("area: elliptic", abs(b.area(e) / exact - 1))
    hh = UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})
    record("escape: Henon-Heiles 1/6", abs(check_well(hh).basin.escape.escape_potential * 6 - 1))
    print(f"{'largest relative error':32s}")
    for key, value in worst.items():
        print(f"  {key:30s} {value:.2e}")
    for line in refused:
        print(f"  refused (numerical error): {line}")
    symmetric = UserWell("symmetric_user", BUILT_IN["symmetric"], PAPER)
    for name, well in (("symmetric (saddle)", symmetric), ("Henon-Heiles", hh)):
        seconds, _ = best_of(lambda well=well: check_well(well))
        print(f"check_well {name}: {seconds * 1e3:.0f} ms (best of 3)")


if __name__ == "__main__":
    main()
