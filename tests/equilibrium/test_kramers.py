"""The shell sampler and the Kramers-Moyal coefficients of E_c, each against something
independent: closed-form basin integrals, the law of k - 1 particles, a Jacobi diffusion
with known coefficients and stationary Beta law, and the exact law for the simulator's
runs (the fluctuation-dissipation check, which must also reject a wrong law)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, stats
from scipy.linalg import expm

from sinktheory.canonical import FIG8_WELL, SYMMETRIC_SINK
from sinktheory.ensemble import total_energy
from sinktheory.equilibrium import (
    area_ratio,
    basin_area,
    check_fluctuation_dissipation,
    equilibrium_law,
    measure_kramers_moyal,
    scaled_energy,
    shell_states,
)
from sinktheory.equilibrium.kramers import (
    gauss_grid,
    jacobi_increments,
    kramers_moyal,
    solve_fokker_planck,
)
from sinktheory.equilibrium.microcanonical import basin_points, particle_energies
from sinktheory.errors import ParameterError
from sinktheory.layout import StateLayout
from sinktheory.model import Sink, Well


@pytest.mark.parametrize(
    "sink, ec",
    [(Sink(FIG8_WELL, 1, 0.2), 0.3), (Sink(FIG8_WELL, 5, 0.2), 0.05), (SYMMETRIC_SINK, 0.2)],
)
def test_shell_states_lie_on_the_shell(sink, ec):
    """Total energy E and container energy E_c exactly (rounding), from the engine's own
    energy kernel."""
    rows = shell_states(sink, 0.5, ec, 50, np.random.default_rng(3))
    L = StateLayout(sink.particles)
    assert np.allclose(total_energy(sink, rows), 0.5, rtol=1e-13, atol=0)
    assert np.allclose((rows[:, L.X] ** 2 + rows[:, L.XDOT] ** 2) / 2, ec, rtol=1e-13)


def test_energy_split_is_the_law_of_the_others():
    """Particle 1's energy e given E_p has density A(e) G_{k-1}(E_p - e), i.e. A(e) times
    the law of k - 1 particles at total E_p evaluated at E_c = e (law.py's convolution, an
    independent computation; its CDF by the trapezoid rule on 20001 points, error ~1e-6).
    KS at 200000 draws; the Dirichlet proposal alone (the homogeneous split) must fail the
    same test (p ~ 1e-5 already at 100000 draws in four seeds), so the test has the power
    to see the curved wall's A(e)."""
    well, k, ep = FIG8_WELL, 3, 0.4
    rng = np.random.default_rng(11)
    e1 = particle_energies(well, k, ep, 200_000, rng)[:, 0]
    law = equilibrium_law(Sink(well, k - 1, 0.2), ep)
    grid = np.linspace(0, ep, 20001)
    t = scaled_energy(well, ep) * (grid / ep) ** (1 / well.n)
    density = t * area_ratio(well, np.maximum(t, 1e-300)) * law.pdf(grid / ep)
    cdf_grid = integrate.cumulative_trapezoid(density, grid, initial=0)
    cdf_grid /= cdf_grid[-1]

    def cdf(x):
        return np.interp(x, grid, cdf_grid)

    assert stats.kstest(e1, cdf).pvalue > 1e-3
    proposal = ep * rng.dirichlet(np.full(k, 1 + 1 / well.n), size=200_000)[:, 0]
    assert stats.kstest(proposal, cdf).pvalue < 1e-6


def test_basin_points_are_uniform_in_the_basin():
    """Flat well (beta = 0.3, n = 4) at e = 0.3: <V> over the basin is
    e - \\int_0^e A / A(e) in closed form (A = 2 t (L J_0 + beta t J_2), t ~ e^(1/n)), and
    the fraction of points with V < e/2 is A(e/2) / A(e).  Tolerances: 4 standard errors."""
    well, e = FIG8_WELL, 0.3
    n, L, beta = well.n, well.wall_distance, well.beta
    j0 = math.exp(math.lgamma(1 / 8) + math.lgamma(9 / 8) - math.lgamma(5 / 4)) / n
    j2 = math.exp(math.lgamma(3 / 8) + math.lgamma(9 / 8) - math.lgamma(3 / 2)) / n
    t = (2 * n * e / well.gamma) ** (1 / n)
    area = 2 * t * (L * j0 + beta * t * j2)
    assert area == pytest.approx(basin_area(well, e), rel=1e-12)
    integral = 2 * (L * j0 * e * t / (1 + 1 / n) + beta * j2 * e * t**2 / (1 + 2 / n))
    xy = basin_points(well, np.full(20000, e), np.random.default_rng(5))
    from sinktheory.equilibrium.microcanonical import _potential

    vs = _potential(well)(xy[:, 0], xy[:, 1])
    assert np.all(vs < e)
    assert abs(vs.mean() - (e - integral / area)) < 4 * vs.std() / math.sqrt(vs.size)
    p = basin_area(well, e / 2) / area
    assert abs(np.mean(vs < e / 2) - p) < 4 * math.sqrt(p * (1 - p) / vs.size)


def _jacobi_moments(s0, tau, a, b, c):
    """Exact <Delta s> and <Delta s^2> of the Jacobi diffusion after time tau: the first
    two moments obey a closed linear system (its generator maps polynomials of degree 2
    to themselves), solved by a matrix exponential."""
    gen = np.array(
        [[0, 0, 0], [c * a, -c * (a + b), 0], [0, 2 * c * (a + 1), -2 * c * (a + b + 1)]]
    )
    _, m1, m2 = expm(gen * tau) @ np.array([np.ones_like(s0), s0, s0**2])
    return m1 - s0, m2 - 2 * s0 * m1 + s0**2


def test_jacobi_coefficients_and_their_law():
    """A Jacobi diffusion with D1 = c (a (1 - s) - b s), D2 = c s (1 - s) and stationary
    Beta(a, b): the estimator recovers the exact finite-lag moments (|z| < 4 at every
    point, mean z^2 < 2.5; 20 seeds gave mean z^2 of 0.9), the check accepts Beta(1, 1.25)
    (the homogeneous n = 4, k = 1 law) and rejects Beta(1, 2.5) (k = 2), with and without
    a base lag."""
    s, _ = gauss_grid(10, 4)
    a, b, c = 1.0, 1.25, 0.01
    inc = jacobi_increments(s, (1, 2, 4), 3000, np.random.default_rng(7), a=a, b=b, c=c)
    right = equilibrium_law(Sink(Well(0.5, 0.0, 4), 1), 1.0)
    wrong = equilibrium_law(Sink(Well(0.5, 0.0, 4), 2), 1.0)
    for base in (0, 1):
        km = kramers_moyal(s, 1.0, 4, (1, 2, 4), inc, base_lag=base)
        j = km.lag_index(2)
        first, second = _jacobi_moments(s, 2, a, b, c)
        if base:
            first0, second0 = _jacobi_moments(s, base, a, b, c)
            first, second = first - first0, second - second0
        z1 = (km.drift[:, j] - first / km.spans[j]) / km.drift_stderr[:, j]
        z2 = (km.diffusion[:, j] - second / (2 * km.spans[j])) / km.diffusion_stderr[:, j]
        for z in (z1, z2):
            assert np.all(np.abs(z) < 4) and np.mean(z**2) < 2.5
        assert check_fluctuation_dissipation(km, right, lag=2, tests=3).p_value > 1e-3
        assert check_fluctuation_dissipation(km, wrong, lag=2, tests=3).p_value < 1e-6


@pytest.mark.parametrize("seed", [0, 3])
def test_fig8_single_particle_satisfies_the_law_and_rejects_the_wrong_k(seed):
    """k = 1 in Fig. 8's well (m = 0.2, E = 0.5), 12 points x 200 runs, lag 1 period.  With
    the two lowest test functions (f linear and quadratic: the expansion is then exact at
    any lag) the law must hold (p > 1e-3; five seeds gave 0.36-0.84) and the law of k = 2
    must fail (p < 1e-8; five seeds gave < 2e-11)."""
    sink = Sink(FIG8_WELL, 1, 0.2)
    km = measure_kramers_moyal(sink, 0.5, points=12, lags=(1,), runs=200, seed=seed)
    assert check_fluctuation_dissipation(km, equilibrium_law(sink, 0.5), tests=2).p_value > 1e-3
    wrong = equilibrium_law(Sink(FIG8_WELL, 2, 0.2), 0.5)
    assert check_fluctuation_dissipation(km, wrong, tests=2).p_value < 1e-8


def test_bad_input_names_the_parameter():
    sink = Sink(FIG8_WELL, 1, 0.2)
    with pytest.raises(ParameterError, match="container_energy"):
        shell_states(sink, 0.5, 0.5, 3, np.random.default_rng(0))
    with pytest.raises(ParameterError, match="rng"):
        shell_states(sink, 0.5, 0.1, 3, 0)
    with pytest.raises(ParameterError, match="increments"):
        kramers_moyal([0.1, 0.2], 1.0, 1, (1,), np.zeros((2, 1)))
    km = kramers_moyal(*gauss_grid(3, 1)[:1], 1.0, 1, (1,), np.ones((3, 1, 4)) * [1, 2, 3, 4])
    with pytest.raises(ParameterError, match="lag"):
        check_fluctuation_dissipation(km, equilibrium_law(Sink(Well(0.5, 0, 1)), 1.0), lag=3)
    with pytest.raises(ParameterError, match="law"):
        check_fluctuation_dissipation(km, equilibrium_law(Sink(Well(0.5, 0, 1)), 0.5))


def test_exact_form_is_the_expansion_for_quadratic_tests():
    """For f linear and quadratic, f(E + dE) - f(E) = f' dE + f'' dE^2 / 2 exactly, so the
    two forms of the check give the same integrals (to rounding), with and without a
    base lag; for a cubic f they differ."""
    s, _ = gauss_grid(6, 4)
    inc = jacobi_increments(s, (1, 2), 500, np.random.default_rng(1), a=1.0, b=1.25, c=0.05)
    law = equilibrium_law(Sink(Well(0.5, 0.0, 4), 1), 1.0)
    for base in (0, 1):
        km = kramers_moyal(s, 1.0, 4, (1, 2), inc, base_lag=base)
        a = check_fluctuation_dissipation(km, law, lag=2, tests=3)
        b = check_fluctuation_dissipation(km, law, lag=2, tests=3, exact=True)
        assert np.allclose(a.integrals[:2], b.integrals[:2], rtol=1e-9, atol=1e-15)
        assert np.allclose(a.stderr[:2], b.stderr[:2], rtol=1e-9)
        assert not np.isclose(a.integrals[2], b.integrals[2], rtol=1e-3)


@pytest.mark.parametrize("seed", [0, 3])
def test_fig8_single_particle_is_stationary_but_not_a_diffusion_at_one_period(seed):
    """The same runs: the law is stationary under their exact increments with six test
    functions (p > 1e-3), but the diffusion's second-order expansion fails from the
    quartic test on (p < 1e-8; three seeds gave 1e-23 to 1e-31): one period's exchange
    (|dE| ~ 0.1 of E = 0.5) is no small jump."""
    sink = Sink(FIG8_WELL, 1, 0.2)
    km = measure_kramers_moyal(sink, 0.5, points=12, lags=(1,), runs=200, seed=seed)
    law = equilibrium_law(sink, 0.5)
    assert check_fluctuation_dissipation(km, law, tests=6, exact=True).p_value > 1e-3
    assert check_fluctuation_dissipation(km, law, tests=4).p_value < 1e-8


def test_fokker_planck_relaxes_the_jacobi_mean_exactly():
    """The Jacobi diffusion's mean relaxes exactly as s_inf + (s0 - s_inf) exp(-c (a + b) t)
    and its stationary law is Beta(a, b): the solver (1000 cells, 4 steps per period,
    first order) agrees to 2e-3 in the mean at every period and 1e-3 in the final standard
    deviation; with c off by 10 % the mean misses by more than 5e-3."""
    s = np.linspace(0, 1, 201)
    a, b, c = 1.0, 1.25, 0.01
    t = np.arange(601)
    exact = a / (a + b) + (1 - a / (a + b)) * np.exp(-c * (a + b) * t)
    sd_beta = math.sqrt(a * b / ((a + b) ** 2 * (a + b + 1)))

    def solve(cc):
        return solve_fokker_planck(1.0, s, cc * (a * (1 - s) - b * s), cc * s * (1 - s), 1.0, 600)

    mean, sd = solve(c)
    assert np.max(np.abs(mean - exact)) < 2e-3
    assert abs(sd[-1] - sd_beta) < 1e-3
    assert np.max(np.abs(solve(1.1 * c)[0] - exact)) > 5e-3
