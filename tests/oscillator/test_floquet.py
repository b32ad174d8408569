"""Floquet stability of the normal mode y = 0: every number against an independent reference.

References used: mpmath's Taylor ODE solver at 30 digits (other method, other
arithmetic), scipy's solve_ivp DOP853 over whole half periods (no quarter-period
symmetry), scipy's Mathieu characteristic values (n = 1), the rigid-wall limit
phi_half -> 1 - 2 Lam A0^2 derived in sinktheory.floquet, and direct integration in the
un-normalised variables for the amplitude invariance.
"""

import json

import mpmath
import numpy as np
import pytest
from _cli import run_cli as run
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import optimize, special
from scipy.integrate import solve_ivp

from sinktheory._generated import oscillator as osc
from sinktheory._generated.shapes import bundle
from sinktheory.errors import ParameterError
from sinktheory.floquet import (
    model_hill,
    model_problem,
    pure_hill,
    pure_problem,
    rigid_limit_phi_half,
    rotation_number,
    scan,
)
from sinktheory.hill import (
    HillIntegrationError,
    integrate_quarter_period,
    monodromy_solve_ivp,
    quarter_period_mpmath,
)
from sinktheory.plot.floquet import plot_fig7, plot_tongues

FLAT, SYMMETRIC = bundle("flat"), bundle("symmetric")


def mp_phi_half(n, lam):
    """phi_half from the 30-digit mpmath reference (as an mpf)."""
    y1, dy1, y2, dy2, _ = quarter_period_mpmath(n, lam, dps=30)
    return y1 * dy2 + y2 * dy1


# --- the quarter-period formulas --------------------------------------------------------


@pytest.mark.parametrize(("n", "lam"), [(2, 0.7), (10, 2.3), (3, -0.4), (1, 9.0)])
def test_quarter_period_formulas_match_half_period_monodromy(n, lam):
    """M(T/2) = [[y1 y2' + y2 y1', 2 y2 y2'], [2 y1 y1', y1 y2' + y2 y1']] at Q, M(T) = M(T/2)^2.

    The half- and full-period matrices come from solve_ivp over whole half periods
    (no symmetry used); its rtol 1e-13 gives about 1e-11, so 1e-9 has margin.
    """
    qp = integrate_quarter_period(n, np.array([lam]))
    y1, dy1, y2, dy2 = qp.y1[0], qp.dy1[0], qp.y2[0], qp.dy2[0]
    assert y1 * dy2 - y2 * dy1 == pytest.approx(1.0, abs=1e-12)  # Wronskian
    predicted = np.array([[y1 * dy2 + y2 * dy1, 2 * y2 * dy2], [2 * y1 * dy1, y1 * dy2 + y2 * dy1]])
    half = monodromy_solve_ivp(n, lam)
    scale = max(1.0, np.abs(half).max())
    np.testing.assert_allclose(half, predicted, atol=1e-9 * scale, rtol=0)
    full = monodromy_solve_ivp(n, lam, half_periods=2)
    np.testing.assert_allclose(full, half @ half, atol=1e-9 * scale**2, rtol=0)
    chart = pure_hill([lam], n)
    assert chart.phi[0] == pytest.approx(np.trace(full) / 2, abs=1e-9 * scale**2)


# --- certification by the mpmath reference ------------------------------------------------


@pytest.mark.parametrize(
    ("n", "lam"), [(2, 0.5), (2, 1.7), (10, 2.0), (10, 25.0), (1, 12.0), (20, 0.9)]
)
def test_phi_half_certified_by_mpmath(n, lam):
    """phi_half to 1e-10 relative to max(1, |phi|): the accuracy the chart promises."""
    ref = mp_phi_half(n, lam)
    got = pure_hill([lam], n).phi_half[0]
    assert abs(got - float(ref)) <= 1e-10 * max(1.0, abs(float(ref)))


def test_deep_instability_growth_certified_by_mpmath():
    """|phi_half| > 1e30 (phi > 1e60): ln|phi_half| to 1e-10 relative (the growth exponent)."""
    n, lam = 2, -4500.0
    ref = mp_phi_half(n, lam)
    assert abs(ref) > 1e30
    chart = pure_hill([lam], n)
    log_ref = float(mpmath.log(abs(ref)))
    assert chart.log_abs_phi_half[0] == pytest.approx(log_ref, rel=1e-10)
    # growth per period = 2 arccosh|phi_half|, evaluated in mpmath from the reference
    growth_ref = float(2 * mpmath.acosh(abs(ref)))
    assert chart.growth_per_period[0] == pytest.approx(growth_ref, rel=1e-10)


def test_renormalised_growth_beyond_float_range_matches_solve_ivp():
    """Lam = -1e5, n = 1: each solution passes 2^400 and is renormalised; phi ~ 1e549.

    solve_ivp's entries stay below 1e308 over the half period (phi_half ~ 1e274), so its
    trace is an independent value; both integrators keep ln|phi_half| to ~1e-12 here.
    """
    chart = pure_hill([-1e5], 1)
    assert chart.quarter.scale1[0] > 0 and chart.quarter.scale2[0] > 0
    half = monodromy_solve_ivp(1, -1e5)
    log_ref = np.log(np.trace(half) / 2)
    assert chart.log_abs_phi_half[0] == pytest.approx(log_ref, rel=1e-10)
    assert not np.isfinite(chart.phi[0])  # beyond float range: documented inf ...
    assert np.isfinite(chart.log_abs_phi[0])  # ... with the logarithm finite
    assert chart.log_abs_phi[0] == pytest.approx(np.log(2.0) + 2 * log_ref, rel=1e-10)


def test_tolerance_controls_the_error():
    """Looser steps give larger but bounded errors (where the method stops being exact)."""
    ref = float(mp_phi_half(10, 3.0))
    errors = [
        abs(pure_problem(10, rtol=rtol).evaluate([3.0]).phi_half[0] - ref)
        for rtol in (1e-5, 1e-9, 1e-13)
    ]
    assert errors[0] > errors[2]
    assert errors[0] < 1e-3  # the per-step tolerance bounds the global error loosely
    assert errors[1] < 1e-7
    assert errors[2] < 1e-11


# --- second method across the chart -----------------------------------------------------


@pytest.mark.parametrize("n", [2, 10, 200])
def test_chart_agrees_with_solve_ivp(n):
    """Fig. 7 grid (alpha = 1/2): phi_half from the trace of M(T/2) by solve_ivp, to 1e-8.

    n = 200 is where the stiff walls make the float path work hardest.
    """
    betas = np.linspace(-1.0, 0.45, 9)
    chart = model_hill(0.5, betas, n)
    for b, phi in zip(betas, chart.phi_half, strict=True):
        m = monodromy_solve_ivp(n, b, coefficient=FLAT.hill_coefficient, alpha=0.5)
        ref = np.trace(m) / 2
        assert abs(phi - ref) <= 1e-8 * max(1.0, abs(ref))


def test_symmetric_shape_n1_agrees_with_solve_ivp():
    """The symmetric well's n = 1 coefficient is a rational function of x; check it too."""
    betas = np.array([-0.6, -0.3, 0.2])
    chart = model_hill(0.5, betas, 1, shape="symmetric")
    for b, phi in zip(betas, chart.phi_half, strict=True):
        ref = np.trace(monodromy_solve_ivp(1, b, coefficient=SYMMETRIC.hill_coefficient, alpha=0.5))
        ref /= 2
        assert abs(phi - ref) <= 1e-8 * max(1.0, abs(ref))


# --- Mathieu equation (n = 1) ------------------------------------------------------------


def mathieu_boundaries(a_of, q_of, lo, hi, count=400):
    """Zeros of a(p) - c(|q(p)|) for the Mathieu characteristic values c = a_r, b_r (r <= 4)."""
    grid = np.linspace(lo, hi, count)
    roots = []
    for r in range(5):
        for fn in (special.mathieu_a, special.mathieu_b):
            if fn is special.mathieu_b and r == 0:
                continue

            def g(p, fn=fn, r=r):
                return a_of(p) - fn(r, abs(q_of(p)))

            vals = [g(p) for p in grid]
            for i in range(count - 1):
                if vals[i] * vals[i + 1] < 0:
                    roots.append(optimize.brentq(g, grid[i], grid[i + 1], xtol=1e-14))
    return np.sort(roots)


def test_pure_n1_boundaries_are_mathieu():
    """x = cos t, x^2 = (1 + cos 2t)/2: y'' + (a - 2q cos 2s) y = 0 with a = Lam/2, q = Lam/4.

    (shift s = t + pi/2).  Kept to q <= 5 where scipy's characteristic values agree with
    each other to ~1e-13; tolerance 1e-9 in Lam.
    """
    ref = mathieu_boundaries(lambda L: L / 2, lambda L: L / 4, 0.05, 20.0)
    found = np.array([b.value for b in scan(pure_problem(1), 0.05, 20.0, 200).boundaries])
    assert len(ref) == 5
    np.testing.assert_allclose(found, ref, atol=1e-9, rtol=0)


def test_model_n1_boundaries_are_mathieu_with_the_extra_term():
    """Flat well, n = 1: q(x) = (alpha - beta)^2 + lambda x^2 (not the paper's lambda x^2).

    Mathieu form: a = (alpha - beta)^2 + lambda/2, q = lambda/4, lambda = -2 beta (alpha - beta).
    The characteristic values at -q are those at q (as a set), so |q| is used.
    """
    alpha, lo, hi = 2.0, -2.0, 1.9
    lam = lambda b: -2 * b * (alpha - b)  # noqa: E731 - the reference's own formula
    ref = mathieu_boundaries(lambda b: (alpha - b) ** 2 + lam(b) / 2, lambda b: lam(b) / 4, lo, hi)
    assert max(abs(lam(b)) / 4 for b in np.linspace(lo, hi, 50)) <= 5  # trustworthy q
    result = scan(model_problem(alpha, 1), lo, hi, 300)
    found = np.array([b.value for b in result.boundaries])
    assert len(ref) >= 2
    np.testing.assert_allclose(found, ref, atol=1e-9, rtol=0)
    # the paper's equation (pure, Lam = lambda) has other boundaries (except at lambda = 0,
    # where both are y'' + c y = 0 with c = 0 or c = alpha^2 = 4, i.e. phi_half = +-1)
    pure = pure_hill([lam(b) for b in found if abs(lam(b)) > 1e-6], 1)
    assert np.all(np.abs(np.abs(pure.phi_half) - 1) > 1e-3)


# --- invariance under the amplitude -------------------------------------------------------


def direct_phi_half(n, amplitude, coefficient):
    """phi_half by solve_ivp in the un-normalised time t, x(0) = A0, over T_n(A0)/2."""
    t_half = osc.period(n, amplitude) / 2

    def rhs(_t, u):
        c = coefficient(u[0])
        return [u[1], -(u[0] ** (2 * n - 1)), u[3], -c * u[2], u[5], -c * u[4]]

    sol = solve_ivp(rhs, (0, t_half), [amplitude, 0, 1, 0, 0, 1], "DOP853", rtol=1e-13, atol=1e-15)
    y = sol.y[:, -1]
    return (y[2] + y[5]) / 2


def test_pure_equation_depends_on_lam_times_amplitude_squared():
    n, lam, a0 = 3, 0.4, 1.7
    ref = direct_phi_half(n, a0, lambda x: lam * x ** (2 * n))
    assert pure_hill([lam], n, amplitude=a0).phi_half[0] == pytest.approx(ref, abs=1e-9)
    # the same phi for amplitude 1 and Lam A0^2
    assert pure_hill([lam * a0**2], n).phi_half[0] == pytest.approx(ref, abs=1e-9)


def test_model_amplitude_n1_uses_the_kernel_at_the_true_x():
    """n = 1 is not a pure power, so the amplitude enters beyond lambda A0^2."""
    a0, alpha, beta = 1.3, 0.5, -0.4
    ref = direct_phi_half(1, a0, lambda x: FLAT.hill_coefficient(x, alpha, beta, 1))
    got = model_hill(alpha, [beta], 1, amplitude=a0).phi_half[0]
    assert got == pytest.approx(ref, abs=1e-9)


# --- rigid-wall limit --------------------------------------------------------------------


def test_converges_to_rigid_wall_limit_like_one_over_n():
    """|phi_half(n) - (1 - 2 Lam)| = C/n + o(1/n): n * error settles (to 2 %) as n doubles."""
    lam = np.array([-0.5, 0.25, 0.75, 1.5])
    limit = rigid_limit_phi_half(lam)
    scaled = {n: n * np.abs(pure_hill(lam, n).phi_half - limit) for n in (100, 200, 400, 800)}
    assert np.all(scaled[800] < 4.0)  # error below 5e-3 at n = 800 for |Lam| <= 1.5
    np.testing.assert_allclose(scaled[800], scaled[400], rtol=0.02)
    # and the differences shrink (convergence of n * error, not just boundedness)
    d1 = np.abs(scaled[400] - scaled[200])
    d2 = np.abs(scaled[800] - scaled[400])
    assert np.all(d2 < d1)


def test_rigid_limit_with_amplitude():
    a0, lam = 1.5, np.array([0.1, 0.3])
    got = pure_hill(lam, 800, amplitude=a0).phi_half
    np.testing.assert_allclose(got, rigid_limit_phi_half(lam, a0), atol=2e-3)


# --- stability boundaries and resonances of Fig. 7 -----------------------------------------


def mp_factor(n, lam, name):
    y1, dy1, y2, dy2, _ = quarter_period_mpmath(n, lam, dps=30)
    return {"y1": y1, "dy1": dy1, "y2": y2, "dy2": dy2, "phi_half": y1 * dy2 + y2 * dy1}[name]


@pytest.mark.parametrize("n", [2, 10])
def test_fig7_boundaries_certified_to_1e10(n):
    """Each located boundary / resonance: the 30-digit reference changes sign within +-1e-10.

    For n >= 2 the model equation is the pure one with Lam = lambda(beta) (lambda from the
    generated kernel), which the mpmath path integrates.
    """
    alpha = 0.5
    result = scan(model_problem(alpha, n), -1.0, 0.499, 300)
    assert len(result.stable_intervals) == 1 and len(result.resonances) == 1
    lo, hi = result.stable_intervals[0]
    assert abs(hi) < 1e-12  # beta = 0: lambda = 0, y'' = 0, phi_half = 1 exactly
    (edge,) = [b for b in result.boundaries if b.value == lo]
    for value, name in [(edge.value, edge.factor), (result.resonances[0], "phi_half")]:
        below = mp_factor(n, FLAT.hill_lambda(alpha, value - 1e-10), name)
        above = mp_factor(n, FLAT.hill_lambda(alpha, value + 1e-10), name)
        assert below * above < 0, (value, name)
    chart = model_hill(alpha, [lo + 1e-6, hi - 1e-6, lo - 1e-6], n)
    assert chart.stable.tolist() == [True, True, False]


def test_stability_decision_and_phi_relations():
    """stable <=> |phi_half| < 1 away from boundaries; phi = 2 phi_half^2 - 1 >= -1."""
    lam = np.linspace(-3, 60, 400)
    chart = pure_hill(lam, 3)
    h = chart.phi_half
    clear = np.abs(np.abs(h) - 1) > 1e-9
    assert np.array_equal(chart.stable[clear], (np.abs(h) < 1)[clear])
    assert np.all(chart.phi >= -1 - 1e-12)
    np.testing.assert_allclose(chart.phi_half_minus_one, h - 1, atol=1e-12 * np.abs(h).max())


@settings(max_examples=25, deadline=None)
@given(
    n=st.integers(1, 40),
    lam=st.floats(-20.0, 60.0),
    amplitude=st.floats(0.5, 2.0),
)
def test_wronskian_and_phi_bound_hold_everywhere(n, lam, amplitude):
    """det M(Q) = 1 (Liouville) to 1e-11 of the solution size, and phi_T >= -1 always.

    The Wronskian is not imposed by the integrator, so it measures its error.
    """
    chart = pure_hill([lam], n, amplitude=amplitude)
    q = chart.quarter
    if q.scale1[0] == 0 and q.scale2[0] == 0:
        size = (abs(q.y1[0]) + abs(q.dy1[0])) * (abs(q.y2[0]) + abs(q.dy2[0]))
        assert abs(q.y1[0] * q.dy2[0] - q.y2[0] * q.dy1[0] - 1.0) <= 1e-11 * size
    assert chart.phi[0] >= -1.0 - 1e-12
    assert chart.stable[0] == (chart.rotation_number[0] not in (0.0, 1.0))


def test_multipliers_and_rotation_number_match_monodromy_eigenvalues():
    for lam in (0.8, 7.0, -2.0, 11.0):
        chart = pure_hill([lam], 2)
        eig = np.linalg.eigvals(monodromy_solve_ivp(2, lam, half_periods=2))
        rho = chart.multipliers[0]
        np.testing.assert_allclose(np.sort_complex(rho), np.sort_complex(eig), atol=1e-8)
        if chart.stable[0]:
            nu = chart.rotation_number[0]
            assert np.min(np.abs(eig - np.exp(2j * np.pi * nu))) < 1e-8
        else:
            assert chart.growth_per_period[0] == pytest.approx(np.log(np.abs(eig).max()), 1e-9)


@pytest.mark.parametrize("d", [2e-12, 1e-8, 1e-3])
def test_rotation_number_near_the_edges_against_mpmath(d):
    """arccos(phi_half)/pi from phi_half -+ 1 given without cancellation, against mpmath
    at 50 digits of the same differences: phi_half = 1 - d to 1e-15 relative, phi_half =
    -1 + d to 4e-16 absolute (two ulps of a rotation number near 1).  Plain arccos of
    the rounded phi_half is off by 1e-5 relative at d = 2e-12."""
    with mpmath.workdps(50):
        near_plus = rotation_number(1 - d, -d, 2 - d)
        want = mpmath.acos(1 - mpmath.mpf(d)) / mpmath.pi
        assert abs(near_plus - want) <= 1e-15 * want
        near_minus = rotation_number(-1 + d, -2 + d, d)
        want = mpmath.acos(-1 + mpmath.mpf(d)) / mpmath.pi
        assert abs(near_minus - want) <= 4e-16


# --- inputs and failures --------------------------------------------------------------


@pytest.mark.parametrize("method", ["compiled", "python"])
def test_read_only_parameter_arrays_are_accepted(method):
    """Frozen results hand out read-only arrays (e.g. a diagram's beta grid); both loops
    must take them and give what the same values in a writable array give."""
    beta = np.array([0.05, 0.1, 0.2])
    frozen = beta.copy()
    frozen.setflags(write=False)
    kw = {"coefficient": FLAT.hill_coefficient, "alpha": 0.5, "implementation": method}
    a = integrate_quarter_period(4, frozen, **kw)
    b = integrate_quarter_period(4, beta, **kw)
    np.testing.assert_array_equal(a.y1, b.y1)
    np.testing.assert_array_equal(a.dy2, b.dy2)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: model_hill(0.5, [0.5], 2), "beta"),
        (lambda: model_hill(0.5, [-0.2, 0.7], 2), "beta"),
        (lambda: model_hill(-0.5, [0.1], 2), "alpha"),
        (lambda: pure_hill([1.0], 0), "n"),
        (lambda: model_hill(0.5, [-0.8], 1, shape="symmetric"), "amplitude"),  # pole of q
        (lambda: pure_hill([1.0], 1001), "n"),
        (lambda: pure_hill([np.nan], 2), "lam"),
        (lambda: pure_hill([1.0], 2, amplitude=0.0), "amplitude"),
        (lambda: pure_problem(2, rtol=1e-20).evaluate([1.0]), "rtol"),
        (lambda: scan(pure_problem(2), 1.0, 0.0, 10), "hi"),
        (lambda: scan(pure_problem(2), 0.0, 1.0, 1), "count"),
    ],
)
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name


def test_step_budget_exhausted_raises():
    with pytest.raises(HillIntegrationError, match="quarter period"):
        integrate_quarter_period(10, np.array([1e6]), max_steps=50)


# --- charts and CLI ------------------------------------------------------------------------


def test_charts_are_figures_with_labels():
    fig = plot_fig7(count=60)
    assert len(fig.axes) == 2 and fig.axes[1].get_xlabel() == r"$\beta$"
    fig = plot_tongues([1, 2, 3], -0.5, 0.4, count=20, alpha=0.5)
    assert fig.axes[0].get_xlabel() == r"$\beta$"


def test_cli_model_point(capsys):
    code, out, _ = run(
        ["floquet", "--alpha", "0.5", "--n", "10", "--beta", "-0.2", "--json"], capsys
    )
    assert code == 0
    data = json.loads(out)
    assert {"lambda", "phi_half", "phi", "multipliers", "stable", "rotation_number"} <= set(data)
    assert data["lambda"] == pytest.approx(0.28, abs=1e-15)
    ref = float(mp_phi_half(10, 0.28))
    assert data["phi_half"] == pytest.approx(ref, abs=1e-10)
    assert data["phi"] == pytest.approx(2 * ref**2 - 1, abs=1e-10)
    assert data["stable"] is True


def test_floquet_results_follow_the_result_protocol(capsys):
    """CLI --json is as_dict() of the API result (range and one point); the dataset is
    labelled by beta, and its phi_T agrees with the half-period monodromy of solve_ivp."""
    argv = ["floquet", "--alpha", "0.5", "--n", "4", "--json"]
    code, out, _ = run([*argv, "--beta-range", "-0.5", "0.4", "7"], capsys)
    assert code == 0
    result = scan(model_problem(0.5, 4), -0.5, 0.4, 7)
    assert json.loads(out) == json.loads(json.dumps(result.as_dict()))
    code, out, _ = run([*argv, "--beta", "0.1"], capsys)
    assert json.loads(out) == model_problem(0.5, 4).evaluate([0.1]).as_dict(point=0)
    ds = result.to_dataset()
    assert ds.chart_phi_half.dims == ("value",)
    np.testing.assert_array_equal(ds.value, np.linspace(-0.5, 0.4, 7))
    for i in (1, 5):  # an independent integrator, phi_T = 2 (tr M(T/2) / 2)^2 - 1
        m = monodromy_solve_ivp(4, float(ds.value[i]), coefficient=FLAT.hill_coefficient, alpha=0.5)
        assert float(ds.chart_phi[i]) == pytest.approx(2 * (np.trace(m) / 2) ** 2 - 1, abs=1e-8)
    assert ds.attrs["chart_shape"] == "flat"


def test_cli_huge_values_are_strings_with_logs(capsys):
    code, out, _ = run(["floquet", "--lam", "-100000", "--n", "1", "--json"], capsys)
    data = json.loads(out)
    assert code == 0 and data["stable"] is False
    assert isinstance(data["phi"], str) and isinstance(data["log_abs_phi"], float)
    mantissa, exponent = data["phi"].split("e")
    log_phi = np.log(float(mantissa)) + int(exponent) * np.log(10.0)
    assert log_phi == pytest.approx(data["log_abs_phi"], rel=1e-9)  # 8 decimals printed


def test_cli_range_refines_interval_ends_and_plots(tmp_path, capsys):
    png = tmp_path / "chart.png"
    argv = ["floquet", "--lam-range", "0.05", "20", "41", "--n", "1", "--json", "--plot", str(png)]
    code, out, _ = run(argv, capsys)
    assert code == 0 and png.stat().st_size > 0
    data = json.loads(out)
    ends = np.array(data["stable_intervals"]).ravel()
    ref = mathieu_boundaries(lambda L: L / 2, lambda L: L / 4, 0.05, 20.0)
    inner = ends[(ends > 0.05) & (ends < 20.0)]
    np.testing.assert_allclose(inner, ref, atol=1e-9)  # ends refined, not grid points
    assert len(data["lam"]) == len(data["phi_half"]) == 41


@pytest.mark.parametrize(
    "argv",
    [
        ["floquet", "--n", "2", "--beta", "0.1"],  # no alpha
        ["floquet", "--n", "2", "--lam", "1", "--alpha", "0.5"],  # alpha with lam
        ["floquet", "--n", "2", "--lam", "1", "--plot", "x.png"],  # plot needs a range
        ["floquet", "--n", "2", "--lam-range", "0", "1", "2.5"],  # count not an integer
        ["floquet", "--n", "2", "--alpha", "0.5", "--beta", "0.5"],  # beta >= alpha
    ],
)
def test_cli_bad_input_exits_2(argv, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(argv, capsys)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert not any(tmp_path.iterdir())
