"""A user's well near the edges of stability: the multipliers and the located boundaries
come from the quarter-period factors (phi_half - 1 = 2 y2 y1', phi_half + 1 = 2 y1 y2'),
as the registered charts take them, not from phi_half itself.

Independent references:

* the elliptic well gamma/(2n) ((x/a)^2 + (y/b)^2)^n at n = 1 is harmonic: x = A cos(t/a)
  (gamma = 1), period T = 2 pi a, and y'' + y/b^2 = 0, so M(T/2) is the rotation by
  pi a/b: phi_half = cos(pi a/b), rotation number a/b folded into [0, 1], multipliers over T
  exp(+-2 pi i a/b) (mpmath at 50 digits).  abs(phi_half) = 1 exactly where a/b is an integer
  (+1 even, -1 odd), and there the gap is closed: phi_half touches +-1 without crossing,
  the factors y2 and y1' (even a/b) or y1 and y2' (odd a/b) both cross zero.  The
  amplitude does not enter, so its boundaries are not on an amplitude chart;
* with the x-motion made anharmonic, x'' = -x - x^3 (V = x^2/2 + x^4/4 + w^2 y^2/2), the
  Hill coefficient stays w^2 and phi_half = cos(w T(A)/2) with
  T(A) = 4 K(m) / sqrt(1 + A^2), m = A^2 / (2 (1 + A^2)) (cn orbit): closed gaps where
  w T(A) / 2 = k pi, located by mpmath at 50 digits;
* an open gap (V = (x^2 + (k + c x^2) y^2)/2, Mathieu's equation on x = A cos t) on its
  unstable side: mpmath's Taylor integration of the quarter period at 20 digits.
"""

import math

import mpmath as mp
import numpy as np
import pytest
from _cli import ELLIPTIC, cli_json, run_cli, write_well_file
from scipy import integrate

from sinktheory.floquet import well_floquet, well_hill, well_scan
from sinktheory.userwell import UserWell


def _old_multipliers(f):
    """What WellFloquet gave before: phi +- sqrt(phi^2 - 1) from phi = 2 phi_half^2 - 1."""
    root = np.sqrt(complex(f.phi * f.phi - 1.0))
    return np.array([f.phi + root, f.phi - root])


def _error(got, exact) -> float:
    """The larger distance between two multiplier pairs (each matched by its imaginary part)."""
    got = sorted((complex(z) for z in got), key=lambda z: (z.imag, z.real))
    exact = sorted(exact, key=lambda z: (float(mp.im(z)), float(mp.re(z))))
    return max(float(abs(mp.mpc(g) - e)) for g, e in zip(got, exact, strict=True))


@pytest.mark.parametrize("ratio,rel", [(1e-6, 1e-11), (1 - 1e-6, 1e-7), (1 + 1e-6, 1e-7),
                                       (2 - 1e-7, 1e-5)])  # fmt: skip
def test_multipliers_of_the_elliptic_well_near_the_edges_against_mpmath(ratio, rel):
    """rho = exp(+-2 pi i a/b) within |rho - 1| = 6e-6 (6e-7 at a/b = 2 - 1e-7) of the
    double multiplier 1: held to 5e-13 absolute and ``rel`` of |rho - 1| (measured 1.5e-18,
    3e-14, 1e-14, 1.1e-13 absolute: 2e-13, 5e-9, 1.7e-9, 1.7e-7 relative, the integration's
    phase error).  The trace formula phi +- sqrt(phi^2 - 1) was off by 1.9e-10 to 2.3e-8
    (3e-5 to 0.037 of |rho - 1|): it fails the same bound."""
    well = UserWell("elliptic", ELLIPTIC, {"a": 0.5, "b": 1.0, "gamma": 1.0, "n": 1})
    b = 0.5 / ratio
    f = well_floquet(well, 0.2, {"b": b})
    with mp.workdps(50):
        nu = mp.mpf(0.5) / mp.mpf(b)  # the float parameters, exactly
        exact = [mp.exp(2j * mp.pi * nu), mp.exp(-2j * mp.pi * nu)]
        scale = float(abs(exact[0] - 1))
        bound = min(5e-13, rel * scale)
        assert f.stable and f.growth_per_period == 0.0
        assert _error(f.multipliers, exact) <= bound
        assert _error(_old_multipliers(f), exact) > 100 * bound
        assert abs(f.rotation_number - float(mp.acos(mp.cos(mp.pi * nu)) / mp.pi)) <= 1e-11


def test_closed_gaps_over_the_amplitude_against_the_elliptic_integral():
    """V = x^2/2 + x^4/4 + w^2 y^2/2 at w = 3.5 on A in [0.5, 2]: w T(A)/2 = 3 pi at
    A = 0.69779663796779184 (phi_half = -1: y1 and y2' vanish) and 2 pi at
    A = 1.6826547898730388 (phi_half = +1: y2 and y1'); each of the four zeros is held to
    1e-12 relative (measured 3.3e-14 at most).  phi_half only touches -1 and +1 there, so
    the trace never crosses them: the trace -+ 1 search found no boundary at all."""

    def period(a):
        a = mp.mpf(a)
        return 4 * mp.ellipk(a * a / (2 * (1 + a * a))) / mp.sqrt(1 + a * a)

    with mp.workdps(50):
        # T(A) against the energy integral at one A, x = A sin(th) (no end singularity)
        a, e = mp.mpf("0.7"), mp.mpf("0.7") ** 2 / 2 + mp.mpf("0.7") ** 4 / 4
        quad = 4 * mp.quad(
            lambda th: (
                a
                * mp.cos(th)
                / mp.sqrt(2 * (e - (a * mp.sin(th)) ** 2 / 2 - (a * mp.sin(th)) ** 4 / 4))
            ),
            [0, mp.pi / 2],
        )
        assert abs(quad - period(a)) < mp.mpf("1e-20")
        edges = {k: float(mp.findroot(lambda a, k=k: period(a) - 2 * mp.pi * k / 3.5, 1.0))
                 for k in (3, 2)}  # fmt: skip
    hill = well_hill(UserWell("duffing", "x**2/2 + x**4/4 + w**2*y**2/2", {"w": 3.5}))
    chart = well_scan(hill, (0.5, 2.0, 4))
    found = [(b.factor, b.phi_half) for b in chart.boundaries]
    assert sorted(found[:2]) == [("dy2", -1.0), ("y1", -1.0)]
    assert sorted(found[2:]) == [("dy1", 1.0), ("y2", 1.0)]
    for b in chart.boundaries:
        exact = edges[3] if b.phi_half == -1.0 else edges[2]
        assert abs(b.value - exact) <= 1e-12 * exact
    assert np.all(np.abs(chart.trace) < 1)  # no sign change of trace -+ 1 on the grid
    assert chart.stable_intervals == [(0.5, 2.0)]  # stable on both sides of a closed gap


def test_the_unstable_side_of_an_open_gap_against_mpmath():
    """V = (x^2 + (0.6 + 0.5 x^2) y^2)/2: the gap where phi_half < -1 opens at
    A_0 = 1.03000059815 (located by well_scan); at A_0 (1 + 1e-6), phi_half = -1 - 2.8e-7,
    the multipliers exp(+-g) over T (g = 2 arccosh abs(phi_half) = 1.5e-3, real positive:
    squares of the half period's) are held to 1e-7 of g (measured 3e-9, the integration's
    own error in y1(Q)) against mpmath's Taylor integration of the quarter period at 20
    digits through the same quarter-period identities."""
    hill = well_hill(UserWell("mathieu", "(x**2 + (k + c*x**2)*y**2)/2", {"k": 0.6, "c": 0.5}))
    (first, *_) = well_scan(hill, (0.5, 1.5, 4)).boundaries
    assert first.phi_half == -1.0 and first.factor in ("y1", "dy2")
    amplitude = first.value * (1 + 1e-6)
    f = hill.at(amplitude)
    with mp.workdps(20):
        a = mp.mpf(amplitude)

        def rhs(t, s):
            q = 0.6 + 0.5 * (a * mp.cos(t)) ** 2
            return [s[1], -q * s[0], s[3], -q * s[2]]

        y1, dy1, y2, dy2 = mp.odefun(rhs, 0, [1, 0, 0, 1])(mp.pi / 2)
        h = y1 * dy2 + y2 * dy1
        rho = [(h - mp.sqrt(h * h - 1)) ** 2, (h + mp.sqrt(h * h - 1)) ** 2]
        g = float(mp.log(max(rho)))  # h < -1: h - sqrt(h^2 - 1) is the larger in size
    assert not f.stable and f.phi_half < -1
    assert abs(f.growth_per_period - g) <= 1e-7 * g
    assert _error(f.multipliers, rho) <= 1e-7 * g
    assert all(z.imag == 0 and z.real > 0 for z in f.multipliers)


def test_without_symmetry_the_multipliers_are_the_full_period_monodromy_s():
    """V = (x^2 + y^2/4)/2 + 0.2 x y^2 is not even in x; on x = A cos t,
    y'' + (1/4 + 0.4 A cos t) y = 0 is in its first tongue at A = 0.5, phi < -1: the
    multipliers are negative, the eigenvalues of the monodromy over 2 pi integrated here
    from the closed form (held to 1e-10, measured 2e-14)."""
    hill = well_hill(UserWell("tilted", "(x**2 + y**2/4)/2 + 0.2*x*y**2", {}))
    f = hill.at(0.5)

    def rhs(t, s):
        q = 0.25 + 0.4 * 0.5 * math.cos(t)
        return [s[1], -q * s[0], s[3], -q * s[2]]

    end = integrate.solve_ivp(rhs, (0, 2 * math.pi), [1, 0, 0, 1], method="DOP853",
                              rtol=1e-13, atol=1e-15).y[:, -1]  # fmt: skip
    eig = np.sort(np.linalg.eigvals(end.reshape(2, 2).T).real)
    assert not f.symmetric and not f.stable and f.phi < -1
    np.testing.assert_allclose(np.sort(f.multipliers.real), eig, rtol=1e-10)
    assert f.growth_per_period == pytest.approx(math.log(-eig[0]), rel=1e-10)


def test_the_floquet_well_text_prints_the_rotation_number(tmp_path, capsys):
    """As the registered floquet text does: 'rotation number NU, growth per period G'."""
    path = write_well_file(tmp_path, "ellipse", ELLIPTIC,
                           {"a": 0.3, "b": 0.25, "gamma": 1.0, "n": (1, (1, 20))})  # fmt: skip
    code, out, _ = run_cli(["floquet", "--well", str(path), "--amplitude", "0.1"], capsys)
    data = cli_json(["floquet", "--well", str(path), "--amplitude", "0.1"], capsys)
    assert code == 0
    assert f"  rotation number {data['rotation_number']:.12g}, growth per period 0" in out
    assert data["rotation_number"] == pytest.approx(2 - 0.3 / 0.25, abs=1e-12)  # 1.2 folded
