"""Triangle-wave series: the paper's R_2, the iteration, its convergence and bounds; CLI.

Independent references: the printed R_2 (symbolic identity), the closed-form solution of
the n = 1 family (arccos / sin), SymPy differentiation of the built polynomials, and the
exact solution of :mod:`sinktheory.oscillator` (itself checked against quadrature and
DOP853 in test_oscillator.py).
"""

import json

import mpmath
import numpy as np
import pytest
import sympy as sp
from _cli import run_cli as run

from sinktheory.errors import ParameterError
from sinktheory.oscillator import exact_shape, period
from sinktheory.series import (
    MAX_ORDER,
    accuracy,
    bound,
    check_bounds,
    error_table,
    tau_symbol,
    triangle_series,
)

tau = tau_symbol
n_sym = sp.Symbol("n", positive=True, integer=True)


def paper_r2(n):
    return (
        sp.Rational(1, 2)
        * (2 * n - 1)
        / (2 * n + 1)
        * (tau ** (2 * n + 1) / (2 * n + 1) - tau ** (4 * n + 1) / (4 * n + 1))
    )


def test_order_two_is_the_printed_r2_for_symbolic_n():
    s = triangle_series(n_sym, 2)
    assert sp.simplify(s.remainder(1) - tau ** (2 * n_sym + 1) / (2 * n_sym + 1)) == 0
    assert sp.simplify(s.remainder(2) - paper_r2(n_sym)) == 0


@pytest.mark.parametrize("n", [1, 2, 3, 10, 57])
def test_order_two_is_the_printed_r2_for_integer_n(n):
    assert sp.expand(triangle_series(n, 2).remainder(2) - paper_r2(n)) == 0


def test_symbolic_and_rational_paths_agree_at_order_three():
    # Two arithmetic back-ends of the same recurrence (rational functions of n vs
    # Fractions for fixed n): exact agreement.
    s = triangle_series(n_sym, 3)
    for n in (1, 2, 5):
        r = triangle_series(n, 3)
        assert sp.expand(s.remainder(3).subs(n_sym, n) - r.remainder(3)) == 0
        assert sp.simplify(s.kappa[2].subs(n_sym, n) - r.kappa[2]) == 0


def test_n1_matches_closed_form_family():
    # n = 1: v'' = -eps kappa v, v'(1) = 1 - eps is solved by omega = arccos(1 - eps),
    # kappa = omega^2 / eps, v = sin(omega tau) / omega.  Expanding in eps must give the
    # built kappa_j and v_j exactly.
    order = 5
    e = sp.Symbol("e", positive=True)
    omega = sp.acos(1 - e)
    s = triangle_series(1, order)
    kappa_series = sp.series(omega**2 / e, e, 0, order).removeO()
    for j in range(order):
        assert sp.nsimplify(kappa_series.coeff(e, j)) == sp.Rational(s.kappa[j])
    # sin(w tau)/w = sum_k (-1)^k w^(2k) tau^(2k+1)/(2k+1)!, with w^2 = omega^2 a series
    w2 = sp.series(omega**2, e, 0, order + 1).removeO()
    v_series = sp.expand(
        sum(
            (-1) ** k * w2**k * tau ** (2 * k + 1) / sp.factorial(2 * k + 1)
            for k in range(order + 1)
        )
    )
    for j in range(1, order + 1):
        assert sp.expand(v_series.coeff(e, j) + s.remainder(j)) == 0


@pytest.mark.parametrize("n", [1, 2, 4, 9])
def test_boundary_conditions_hold_at_every_order(n):
    # U(0) = 0, U'(0) = A (slope fixed: each R_i has R_i'(0) = 0), U'(1) = 0 for every
    # truncation order i >= 1 -- checked by SymPy differentiation, exactly.
    s = triangle_series(n, 5)
    for i in range(1, 6):
        u = s.shape_expr(i)
        du = sp.diff(u, tau)
        assert u.subs(tau, 0) == 0
        assert du.subs(tau, 0) == 1
        assert du.subs(tau, 1) == 0
        assert sp.diff(s.remainder(i), tau).subs(tau, 0) == 0
    # the ODE at order i: v_i'' = -sum_j kappa_j [v^(2n-1)]_{i-1-j}; at i = 1 this is
    # R_1'' = kappa_0 tau^(2n-1) with kappa_0 = 2n
    assert sp.expand(sp.diff(s.remainder(1), tau, 2) - 2 * n * tau ** (2 * n - 1)) == 0


@pytest.mark.parametrize("n", [1, 2, 5, 20, 50])
def test_errors_fall_with_order_and_period_converges(n):
    rows = error_table(n, 6, samples=2001)
    shape = [r.shape_error for r in rows]
    rel = [abs(r.period_relative_error) for r in rows]
    # geometric convergence (paper: ~2^(1-i)): each order at least 1.8x better
    assert all(b < a / 1.8 for a, b in zip(shape, shape[1:], strict=False))
    assert all(b < a / 1.8 for a, b in zip(rel, rel[1:], strict=False))
    # the period estimate is recomputed here from kappa and U_i(1), not from the table
    s = triangle_series(n, 6)
    with mpmath.workdps(30):
        a = 1 / mpmath.mpf(float(s.amplitude_ratio(6)))
        t6 = 4 * mpmath.sqrt(float(s.frequency_factor(6))) / a ** (n - 1)
        assert abs(t6 / rows[-1].period_estimate - 1) < 1e-14  # float inputs: 1e-14
        assert abs(float(rows[-1].period_estimate / period(n, amplitude=1)) - 1) < 6e-3


def test_series_error_is_measured_against_exact_shape():
    # Spot check of error_table's number against an independent dense evaluation.
    n, i = 3, 4
    s = triangle_series(n, i)
    taus = np.linspace(0, 1, 20001)
    ref = np.max(np.abs(s.shape(taus, i) - exact_shape(taus, n)))
    table = error_table(n, i, samples=20001)[-1].shape_error
    assert table == pytest.approx(ref, rel=1e-12)


def test_n1_series_tends_to_sine():
    # n = 1: exact U = A0 sin(pi tau / 2); order 12 should be within 2^-12-ish * 0.02.
    s = triangle_series(1, 12)
    taus = np.linspace(-1, 1, 401)
    assert np.max(np.abs(s.shape(taus) - np.sin(np.pi * taus / 2))) < 2e-6
    assert float(s.period_estimate(5.0)) == pytest.approx(2 * np.pi, rel=1e-5)


def test_large_n_series_is_finite_and_accurate():
    # n = 200 and 1000: powers tau^(2n m) only underflow; the error keeps falling.
    for n in (200, 1000):
        rows = error_table(n, 3, samples=1001)
        assert all(np.isfinite(r.shape_error) for r in rows)
        assert rows[-1].shape_error < rows[0].shape_error < 1e-3
        t = rows[-1].period_estimate
        assert mpmath.isfinite(t) and t > 0


def test_paper_bounds_hold_for_n_2_to_20_orders_2_to_6():
    checks = check_bounds(range(2, 21), range(2, 7))
    assert len(checks) == 19 * 5
    assert all(c.holds for c in checks)
    # tight only for i = 2 (sup ratio -> 1 as tau -> 0); looser for higher orders
    assert all(c.max_ratio == pytest.approx(1.0, rel=1e-12) for c in checks if c.i == 2)
    assert all(c.max_ratio < 0.97 for c in checks if c.i > 2)


@pytest.mark.parametrize("n", [2, 7, 20])
def test_bounds_on_a_dense_grid_independently(n):
    # Brute force with the SymPy expressions of R_i (lambdified): 0 < R_i < bound on
    # 0 < tau <= 1 and odd in tau.  Evaluated in mpmath at 300 digits: for i = 2 the
    # ratio is 1 - O(tau^(2n)), which must be resolved down to tau = 1/400 (1e-104 at n = 20).
    s = triangle_series(n, 6)
    with mpmath.workdps(300):
        grid = [mpmath.mpf(k) / 400 for k in range(1, 401)]
        for i in range(2, 7):
            f = sp.lambdify(tau, s.remainder(i), "mpmath")
            b = sp.lambdify(tau, bound_expr(n, i), "mpmath")
            ratios = [f(t) / b(t) for t in grid]
            assert all(0 < r < 1 for r in ratios)
            assert f(-grid[5]) == -f(grid[5])


def bound_expr(n, i):
    return sp.Integer(2 * n - 1) * tau ** (2 * n + 1) / (2 ** (i - 1) * (2 * n + 1) ** 2)


def test_bound_check_can_fail():
    # i = 1: R_1 = tau^(2n+1)/(2n+1) exceeds the formula's value (2n-1)/(2n+1)^2 tau^(2n+1)
    # by (2n+1)/(2n-1); the checker must report that (the paper states the bound for i >= 2).
    (c,) = check_bounds([3], [1])
    assert not c.holds
    assert c.max_ratio == pytest.approx(7 / 5)
    assert float(bound(1.0, 3, 1)) == pytest.approx(5 / 49)


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: triangle_series(2, 0), "order"),
        (lambda: triangle_series(2, MAX_ORDER + 1), "order"),
        (lambda: triangle_series(0, 2), "n"),
        (lambda: triangle_series(2.5, 2), "n"),
        (lambda: triangle_series(n_sym, 2).shape(0.5), "n"),
        (lambda: triangle_series(2, 3).shape(0.5, 4), "order"),
        (lambda: triangle_series(2, 3).period_estimate(0.0), "amplitude"),
        (lambda: error_table(2, 3, samples=1), "samples"),
    ],
)
def test_bad_input(call, name):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name


# --- CLI --------------------------------------------------------------------------------


def test_cli_series_json_and_plot(tmp_path, capsys):
    png = tmp_path / "s.png"
    code, out, err = run(
        ["series", "--n", "4", "--order", "4", "--json", "--plot", str(png)], capsys
    )
    assert code == 0, err
    data = json.loads(out)
    assert [r["order"] for r in data["errors"]] == [1, 2, 3, 4]
    errs = [r["shape_error"] for r in data["errors"]]
    assert errs == sorted(errs, reverse=True)
    assert [b["i"] for b in data["bounds"]] == [2, 3, 4] and all(b["holds"] for b in data["bounds"])
    assert data == {**accuracy(4, 4).as_dict(), "plot": str(png)}  # the API result's dict
    t1 = error_table(4, 1)[0].period_estimate  # computed with 30 digits
    with mpmath.workdps(40):
        assert abs(mpmath.mpf(data["errors"][0]["period_estimate"]) / t1 - 1) < 1e-28
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_cli_series_text(capsys):
    code, out, _ = run(["series", "--n", "1", "--order", "2"], capsys)
    assert code == 0
    assert "holds" in out and "max|U_i - x|/A0" in out


@pytest.mark.parametrize(
    "argv, name",
    [
        (["series", "--n", "0", "--order", "2"], "n"),
        (["series", "--n", "3", "--order", "0"], "order"),
        (["series", "--n", "3", "--order", "2.5"], "order"),
        (["series", "--n", "3", "--order", "99"], "order"),
        (["series", "--n", "nan", "--order", "2"], "n"),
        (["series", "--n", "3", "--order", "2", "--plot", "x.pdf"], "plot"),
    ],
)
def test_cli_series_bad_input(argv, name, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(argv, capsys)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and f"{name} = " in err
    assert list(tmp_path.iterdir()) == []
