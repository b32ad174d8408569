"""Exact period and exact periodic solution of x'' + x^(2n-1) = 0.

References used here are independent of the code under test: a direct quadrature of
the energy integral (mpmath), the closed form for n = 1 (sin), and a numerical ODE
solution (scipy DOP853).
"""

import json
import math

import mpmath
import numpy as np
import pytest
from _cli import run_cli
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from sinktheory.errors import ParameterError
from sinktheory.oscillator import (
    PeriodOutOfRangeError,
    exact_shape,
    exact_shape_mp,
    exact_solution,
    exact_solution_mp,
    oscillator,
    period,
    triangle_wave,
    triangle_wave_derivative,
)


def quadrature_period(n, amplitude=None, energy=None, dps=60):
    """T = 4 int_0^A0 dx / sqrt(2 (E - x^(2n)/(2n))) by mpmath.quad, written afresh.

    With x = A0 sin(theta): E - x^(2n)/(2n) = E (1 - sin^(2n)) and
    1 - s^(2n) = (1 - s^2) sum_{k<n} s^(2k), so the cos(theta) of dx cancels the
    endpoint singularity exactly and no digits are lost near theta = pi/2:
    T = 4 A0 / sqrt(2E) int_0^(pi/2) dtheta / sqrt(sum_{k<n} sin^(2k) theta).
    """
    with mpmath.workdps(dps):
        if amplitude is not None:
            a0 = mpmath.mpf(amplitude)
            e = a0 ** (2 * n) / (2 * n)
        else:
            e = mpmath.mpf(energy)
            a0 = mpmath.root(2 * n * e, 2 * n)

        def integrand(theta):
            s2 = mpmath.sin(theta) ** 2
            total, term = mpmath.mpf(0), mpmath.mpf(1)
            for _ in range(n):
                total += term
                term *= s2
            return 1 / mpmath.sqrt(total)

        # The integrand changes fastest within ~1/sqrt(n) of pi/2: split there.
        cut = mpmath.pi / 2 - 2 / mpmath.sqrt(n)
        nodes = [0, cut, mpmath.pi / 2] if cut > 0 else [0, mpmath.pi / 2]
        value, err = mpmath.quad(integrand, nodes, error=True)
        assert err < mpmath.mpf(10) ** (-dps + 8)
        return 4 * a0 / mpmath.sqrt(2 * e) * value


@pytest.mark.parametrize("n", range(1, 51))
def test_period_matches_quadrature_50_digits(n):
    # 50 digits asked; the quadrature runs at 60 digits with its error estimate < 1e-52,
    # so agreement to 1e-48 relative tests every requested digit but the last two.
    amplitude = "0.7" if n % 2 else "1.3"
    t = period(n, amplitude=amplitude, dps=50)
    ref = quadrature_period(n, amplitude=amplitude)
    with mpmath.workdps(60):
        assert abs(t / ref - 1) < mpmath.mpf(10) ** -48


def test_period_from_energy_matches_quadrature():
    # Same tolerance reasoning as above; energy path goes through amplitude_of_energy_mp.
    t = period(5, energy="0.37", dps=50)
    ref = quadrature_period(5, energy="0.37")
    with mpmath.workdps(60):
        assert abs(t / ref - 1) < mpmath.mpf(10) ** -48


def test_period_n1_is_two_pi_for_any_amplitude():
    for a in ("1e-200", "0.3", "1", "7e150"):
        with mpmath.workdps(60):
            assert abs(period(1, amplitude=a, dps=50) - 2 * mpmath.pi) < mpmath.mpf(10) ** -49


def test_period_scales_as_amplitude_power():
    # T_n(A0) = T_n(1) A0^(1-n): the scaling law of x'' + x^(2n-1) = 0 (exact).
    with mpmath.workdps(40):
        ratio = period(4, amplitude="0.5", dps=40) / period(4, amplitude=1, dps=40)
        assert abs(ratio - 8) < mpmath.mpf(10) ** -38


def test_precision_is_rounded_to_request():
    # The dps = 20 result is the 50-digit value rounded to 20 digits (guard digits inside).
    t20 = period(3, amplitude="0.9", dps=20)
    t50 = period(3, amplitude="0.9", dps=50)
    with mpmath.workdps(20):
        assert t20 == +t50
    with mpmath.workdps(50):
        assert t20 != t50


def test_tiny_amplitude_gives_huge_finite_period_not_overflow():
    # n = 200, A0 = 1e-300: T ~ A0^(-199) = 1e59700, far beyond float64 but exact in mpmath.
    t = period(200, amplitude="1e-300", dps=20)
    ref = period(200, amplitude=1, dps=30)
    with mpmath.workdps(30):
        assert mpmath.isfinite(t)
        assert abs(t / (ref * mpmath.mpf(10) ** (300 * 199)) - 1) < mpmath.mpf(10) ** -19


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"amplitude": 0}, "amplitude"),
        ({"amplitude": -1.0}, "amplitude"),
        ({"amplitude": float("nan")}, "amplitude"),
        ({"energy": 0.0}, "energy"),
        ({"energy": float("inf")}, "energy"),
        ({"energy": "abc"}, "energy"),
        ({}, "amplitude/energy"),
        ({"amplitude": 1, "energy": 1}, "amplitude/energy"),
    ],
)
def test_bad_amplitude_or_energy_refused(kwargs, name):
    with pytest.raises(ParameterError) as info:
        oscillator(3, **kwargs)
    assert info.value.name == name


@pytest.mark.parametrize("n", [0, 2.5, 1001, True])
def test_bad_n_refused(n):
    with pytest.raises(ParameterError) as info:
        period(n, amplitude=1)
    assert info.value.name == "n"


def test_triangle_wave_matches_literal_formula():
    # The literal (2/pi) asin(sin(2 pi p)) at 40 digits is the reference; the piecewise
    # float form must agree to a few ulps (5e-16 covers the rounding of p mod 1).
    phases = np.linspace(-2.3, 3.7, 1001)
    with mpmath.workdps(40):
        ref = [float(2 / mpmath.pi * mpmath.asin(mpmath.sin(2 * mpmath.pi * p))) for p in phases]
    assert np.max(np.abs(triangle_wave(phases) - ref)) < 5e-15
    # derivative: central difference away from the corners is exact for a linear piece
    h = 1e-6
    inner = phases[np.abs(np.mod(phases, 0.5) - 0.25) > 2 * h]
    fd = (triangle_wave(inner + h) - triangle_wave(inner - h)) / (2 * h)
    assert np.allclose(triangle_wave_derivative(inner), fd, rtol=0, atol=1e-8)


def test_shape_n1_is_sine():
    # n = 1: x'' + x = 0, x = A0 sin(2 pi t / T) = A0 sin(pi tau / 2) exactly.
    tau = np.linspace(-1, 1, 2001)
    assert np.max(np.abs(exact_shape(tau, 1) - np.sin(np.pi * tau / 2))) < 3e-16


@pytest.mark.parametrize("n", [1, 2, 3, 7, 20, 50, 200, 1000])
def test_float_shape_matches_mp_shape(n):
    # Two different inversions (scipy betainc/Newton vs mpmath 2F1/findroot at 30 digits).
    # Tolerance 2e-15 absolute = a few ulps of numbers <= 1: the accuracy the module
    # docstring promises, including points hugging 0 and the turning point.
    rng = np.random.default_rng(n)
    tau = np.concatenate(
        [rng.uniform(-1, 1, 25), [0, 1e-300, 1e-12, 1e-3, 0.5, 1 - 1e-9, 1 - 1e-15, 1, -1]]
    )
    ref = np.array([float(exact_shape_mp(float(t), n, dps=30)) for t in tau])
    assert np.max(np.abs(exact_shape(tau, n) - ref)) < 2e-15


@pytest.mark.parametrize("n, amplitude", [(1, 1.0), (2, 1.5), (3, 0.8), (6, 1.0), (10, 1.2)])
def test_solution_matches_ode(n, amplitude):
    # DOP853 at rtol = atol = 1e-13 over one period is accurate to ~1e-12; the exact
    # solution must agree within 1e-10 (leaves room for the integrator's global error).
    t_end = float(period(n, amplitude=amplitude))

    def rhs(_, y):
        return [y[1], -(y[0] ** (2 * n - 1))]

    ts = np.linspace(0, t_end, 301)
    sol = solve_ivp(rhs, (0, t_end), [amplitude, 0.0], "DOP853", t_eval=ts, rtol=1e-13, atol=1e-13)
    assert sol.success
    assert np.max(np.abs(exact_solution(ts, n, amplitude) - sol.y[0])) < 1e-10
    zero = solve_ivp(
        rhs,
        (0, t_end),
        [0.0, amplitude**n / math.sqrt(n)],
        "DOP853",
        t_eval=ts,
        rtol=1e-13,
        atol=1e-13,
    )  # x(0) = 0, x'(0) = sqrt(2E)
    assert np.max(np.abs(exact_solution(ts, n, amplitude, start="zero") - zero.y[0])) < 1e-10


def test_mp_solution_matches_float_solution_and_symmetries():
    # mp path at 30 digits vs float path: 1e-14 absolute (float path accuracy ~1e-15 A0
    # plus the phase rounding of t / T).
    n, a0 = 4, 1.3
    t = float(period(n, amplitude=a0))
    for frac in (0.0, 0.1, 0.25, 0.4, 0.6, 0.9):
        x_mp = exact_solution_mp(frac * t, n, a0, dps=30)
        assert abs(float(x_mp) - exact_solution(frac * t, n, a0)) < 1e-14
    # x(t + T/2) = -x(t) and x(T - t) = x(t) (turning-point convention)
    ts = np.linspace(0, t, 97)
    x = exact_solution(ts, n, a0)
    assert np.allclose(exact_solution(ts + t / 2, n, a0), -x, atol=1e-14)
    assert np.allclose(exact_solution(t - ts, n, a0), x, atol=1e-14)


def test_mp_solution_at_high_precision_satisfies_energy():
    # Energy E = x'^2/2 + x^(2n)/(2n) from a 40-digit central difference of the mp
    # solution must equal A0^(2n)/(2n) to ~1e-25 (difference step 1e-12, error O(h^2)).
    n, a0, t = 3, mpmath.mpf("1.1"), mpmath.mpf("0.37")
    with mpmath.workdps(40):
        h = mpmath.mpf(10) ** -13
        xp = exact_solution_mp(t + h, n, a0, dps=40)
        xm = exact_solution_mp(t - h, n, a0, dps=40)
        x0 = exact_solution_mp(t, n, a0, dps=40)
        e = ((xp - xm) / (2 * h)) ** 2 / 2 + x0 ** (2 * n) / (2 * n)
        assert abs(e - a0 ** (2 * n) / (2 * n)) < mpmath.mpf(10) ** -22


def test_float_path_refuses_out_of_range_period():
    # n = 200, A0 = 0.01: T ~ 1e398 > float64 max -> a NumericalError, never inf/nan.
    with pytest.raises(PeriodOutOfRangeError):
        exact_solution([0.0, 1.0], 200, 0.01)
    # ... while the mp path still works there: x(0) = A0 exactly.
    x0 = exact_solution_mp(0, 200, "0.01", dps=20)
    with mpmath.workdps(20):
        assert x0 == mpmath.mpf("0.01")


def test_float_path_large_n_in_range():
    # n = 200 at A0 = 1 (T finite): compare with the mp path, 2e-15 as above.
    t = float(period(200, amplitude=1))
    ts = np.linspace(0, t, 41)
    ref = [float(exact_solution_mp(float(s), 200, 1.0, dps=30)) for s in ts]
    assert np.max(np.abs(exact_solution(ts, 200, 1.0) - ref)) < 2e-15


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: exact_solution([0.0], 2, 0.0), "amplitude"),
        (lambda: exact_solution([np.nan], 2, 1.0), "t"),
        (lambda: exact_solution([0.0], 2, 1.0, start="middle"), "start"),
        (lambda: exact_shape([1.5], 2), "tau"),
        (lambda: exact_shape_mp(2, 2), "tau"),
        (lambda: exact_solution_mp(float("inf"), 2, 1.0), "t"),
        (lambda: exact_solution_mp(0.0, 2, 1.0, dps=0), "dps"),
    ],
)
def test_solution_bad_input(call, name):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name


# --- CLI: sinktheory period --------------------------------------------------------------


def test_cli_period_40_digits_against_quadrature(capsys):
    code, out, err = run_cli(
        ["period", "--n", "7", "--amplitude", "1", "--digits", "40", "--json"], capsys
    )
    assert code == 0, err
    data = json.loads(out)
    assert set(data) == {"n", "amplitude", "energy", "period", "dps"} and data["n"] == 7
    assert data == oscillator(7, amplitude=1, dps=40).as_dict()  # the API's result
    mantissa = data["period"].replace(".", "").lstrip("0")
    assert len(mantissa) == 40  # exactly 40 significant digits printed
    # Reference: independent 60-digit quadrature (error estimate < 1e-52, see above).
    # A correctly rounded 40-digit value is within half a unit of the 40th digit.
    ref = quadrature_period(7, amplitude=1)
    with mpmath.workdps(60):
        assert abs(mpmath.mpf(data["period"]) - ref) <= mpmath.mpf("0.5e-38")
        # E = 1/14 = 0.0714...: 40 significant digits are correct to 0.5e-41
        assert abs(mpmath.mpf(data["energy"]) - mpmath.mpf(1) / 14) <= mpmath.mpf("0.5e-41")


def test_cli_period_decimal_input_is_exact(capsys):
    # "--energy 0.1" means 1/10: compare with the quadrature at E = 1/10 exactly, which
    # differs from E = float(0.1) in the 17th digit, so 30 digits would catch a float read.
    code, out, _ = run_cli(["period", "--n", "3", "--energy", "0.1", "--json"], capsys)
    assert code == 0
    data = json.loads(out)
    ref = quadrature_period(3, energy="0.1")
    with mpmath.workdps(60):
        assert abs(mpmath.mpf(data["period"]) / ref - 1) < mpmath.mpf(10) ** -29


def test_cli_period_text(capsys):
    code, out, _ = run_cli(["period", "--n", "1", "--amplitude", "2", "--digits", "12"], capsys)
    assert code == 0 and "6.28318530718" in out


@pytest.mark.parametrize(
    "argv, name",
    [
        (["period", "--n", "0", "--amplitude", "1"], "n"),
        (["period", "--n", "2.5", "--amplitude", "1"], "n"),
        (["period", "--n", "3", "--amplitude", "0"], "amplitude"),
        (["period", "--n", "3", "--amplitude", "-2"], "amplitude"),
        (["period", "--n", "3", "--energy", "inf"], "energy"),
        (["period", "--n", "3", "--energy", "nan"], "energy"),
        (["period", "--n", "3", "--amplitude", "1", "--digits", "0"], "digits"),
        (["period", "--n", "3", "--amplitude", "1", "--digits", "4.5"], "digits"),
    ],
)
def test_cli_period_bad_values(argv, name, capsys):
    code, out, err = run_cli(argv, capsys)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and f"{name} = " in err


@pytest.mark.parametrize(
    "argv",
    [
        ["period", "--n", "3"],  # neither amplitude nor energy
        ["period", "--n", "3", "--amplitude", "1", "--energy", "1"],  # both
        ["period", "--n", "3", "--amplitude", "abc"],
    ],
)
def test_cli_period_usage_errors(argv, capsys):
    code, out, err = run_cli(argv, capsys)
    assert code == 2 and out == "" and err.count("\n") == 1


def test_value_below_float_range_is_refused_not_misread():
    # Documented limit: inputs are validated through float64; "1e-400" must be refused
    # (ParameterError), never turned into a wrong finite period.
    with pytest.raises(ParameterError) as info:
        period(3, amplitude="1e-400")
    assert info.value.name == "amplitude"


@settings(max_examples=40, deadline=None)
@given(
    n=st.integers(1, 40),
    a0=st.floats(0.3, 3.0),
    t=st.floats(-50.0, 50.0),
)
def test_scaling_law_property(n, a0, t):
    # x'' + x^(2n-1) = 0 is invariant under x -> A0 x, t -> t / A0^(n-1):
    # x(t; A0) = A0 x(A0^(n-1) t; 1).  The two sides use different periods and phases, so
    # this checks the period kernel and the phase reduction.  Tolerance: each side's phase
    # t / T carries ~4 eps (|t| / T) rounding (quotient and kernel), and |dx/dphase| <=
    # 4 K A0 <= 2 pi A0 (K = int_0^1 dz / sqrt(1 - z^(2n)) <= pi/2), plus 2e-15 A0 of shape
    # error.
    t_period = float(period(n, amplitude=a0))
    eps = np.finfo(float).eps
    lhs = exact_solution([t], n, a0)[0]
    rhs = a0 * exact_solution([a0 ** (n - 1) * t], n, 1.0)[0]
    assert abs(lhs - rhs) <= a0 * (2e-15 + 2 * 2 * np.pi * 4 * eps * (1 + abs(t) / t_period))
