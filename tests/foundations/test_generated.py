"""Generated kernels: identical to a fresh generation, and exact to 1e-12 against SymPy.

The reference values here come from SymPy/mpmath evaluation of the *explicit* model
(S.potential and its derivatives taken by sympy.diff, or mpmath numerical
differentiation), not from the atom-form expressions the kernels were printed from, so
a slip in the chain rule or the printer shows up as a mismatch.
"""

from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from sinktheory import codegen
from sinktheory import symbolic as S
from sinktheory._generated import oscillator
from sinktheory._generated.shapes import bundle

KERNELS = {
    name: (bundle(name).potential, bundle(name).gradient, bundle(name).hessian) for name in S.SHAPES
}
DPS = 30
# Relative tolerance of a float64 kernel against a 30-digit reference: a few dozen
# roundings of O(1) numbers plus one ipow of depth log2(2n) stay far below 1e-12.
RTOL = 1e-12


def test_checked_in_kernels_match_a_fresh_generation(tmp_path):
    written = codegen.write(tmp_path)
    for path in written:
        name = path.relative_to(tmp_path)
        checked_in = Path(codegen.GENERATED_DIR, name).read_text()
        assert path.read_text() == checked_in, f"{name} differs: regenerate the kernels"
    generated = {p.relative_to(codegen.GENERATED_DIR) for p in codegen.GENERATED_DIR.rglob("*.py")}
    assert generated == {p.relative_to(tmp_path) for p in written}, "stale generated files"


def _explicit_derivatives(shape):
    V = S.potential(shape)
    return [
        V,
        sp.diff(V, S.x),
        sp.diff(V, S.y),
        sp.diff(V, S.x, 2),
        sp.diff(V, S.x, S.y),
        sp.diff(V, S.y, 2),
    ]


@pytest.fixture(scope="module", params=S.SHAPES)
def shape_and_exact(request):
    return request.param, _explicit_derivatives(request.param)


def _points(seed, count, n):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        alpha = rng.uniform(0.3, 1.5)
        beta = rng.uniform(-0.5, 0.9 * alpha)
        x, y = rng.uniform(-1.2, 1.2, 2)
        D = lambda s: alpha + beta * (s * s - 1)  # noqa: E731 - test-local helper
        # keep |x/D(y)|, |y/D(x)|, |y|, r/(alpha - beta) <= 1.5 so that n up to 100 stays
        # finite
        ratios = (abs(x / D(y)), abs(y / D(x)), abs(y), np.hypot(x, y) / (alpha - beta))
        if min(D(x), D(y)) < 0.2 or max(ratios) > 1.5:
            continue
        out.append((x, y, alpha, beta, rng.uniform(0.5, 2.0)))
    return out


@pytest.mark.parametrize("n", [1, 2, 3, 10, 37, 100])
def test_kernels_agree_with_exact_evaluation(shape_and_exact, n):
    shape, exact = shape_and_exact
    pot, grad, hess = KERNELS[shape]
    exact_n = [
        sp.lambdify((S.x, S.y, S.alpha, S.beta, S.gamma), e.subs(S.n, n), "mpmath") for e in exact
    ]
    with mpmath.workdps(DPS):
        for x, y, a, b, g in _points(n, 12, n):
            got = [pot(x, y, a, b, g, n), *grad(x, y, a, b, g, n), *hess(x, y, a, b, g, n)]
            args = [mpmath.mpf(v) for v in (x, y, a, b, g)]
            ref = [f(*args) for f in exact_n]
            assert all(np.isfinite(got))
            scale = max(abs(float(r)) for r in ref[1:3])  # gradient terms can cancel
            for name, value, r in zip(
                ["V", "Vx", "Vy", "Vxx", "Vxy", "Vyy"], got, ref, strict=True
            ):
                tol = RTOL * max(abs(float(r)), scale if name in ("Vx", "Vy") else 0.0)
                assert abs(value - float(r)) <= tol + 1e-300, (shape, n, name, x, y, a, b)


@pytest.mark.parametrize("shape", S.SHAPES)
def test_gradient_is_the_derivative_of_the_potential_kernel(shape):
    """mpmath numerical differentiation (at 30 digits) of the exact V gives the force."""
    pot, grad, _ = KERNELS[shape]
    n = 4
    V = sp.lambdify(
        (S.x, S.y),
        S.potential(shape).subs(
            {S.n: n, S.alpha: sp.Rational(1, 2), S.beta: sp.Rational(3, 10), S.gamma: 1}
        ),
        "mpmath",
    )
    with mpmath.workdps(DPS):
        for x, y in [(0.1, 0.2), (-0.25, 0.7), (0.3, -1.0)]:
            dx = mpmath.diff(lambda t: V(t, mpmath.mpf(y)), mpmath.mpf(x))
            dy = mpmath.diff(lambda t: V(mpmath.mpf(x), t), mpmath.mpf(y))
            gx, gy = grad(x, y, 0.5, 0.3, 1.0, n)
            assert gx == pytest.approx(float(dx), rel=RTOL)
            assert gy == pytest.approx(float(dy), rel=RTOL)


finite = st.floats(-1.0, 1.0, allow_nan=False)


@settings(max_examples=200, deadline=None)
@given(x=finite, y=finite, n=st.integers(1, 60))
def test_symmetric_well_is_invariant_under_x_y_exchange(x, y, n):
    a, b, g = 1.0, 0.1, 1.0
    pot, grad, _ = KERNELS["symmetric"]
    assert pot(x, y, a, b, g, n) == pot(y, x, a, b, g, n)
    gx, gy = grad(x, y, a, b, g, n)
    hx, hy = grad(y, x, a, b, g, n)
    # the two evaluations round differently: a wall ratio s carries one rounding of its
    # division, which s^(2n-1) amplifies to (2n - 1) eps in each of the two terms
    rel = 8 * n * np.finfo(float).eps
    assert gx == pytest.approx(hy, rel=rel, abs=1e-300)
    assert gy == pytest.approx(hx, rel=rel, abs=1e-300)


@settings(max_examples=200, deadline=None)
@given(
    x=finite,
    y=finite,
    n=st.integers(1, 60),
    shape=st.sampled_from(tuple(S.SHAPES)),
    beta=st.floats(-0.4, 0.4),
)
def test_every_shape_is_invariant_under_y_reflection(x, y, n, shape, beta):
    pot, grad, hess = KERNELS[shape]
    args = (1.0, beta, 1.0, n)
    assert pot(x, -y, *args) == pot(x, y, *args)
    gx, gy = grad(x, y, *args)
    mx, my = grad(x, -y, *args)
    assert mx == gx and my == -gy
    hxx, hxy, hyy = hess(x, y, *args)
    kxx, kxy, kyy = hess(x, -y, *args)
    assert (kxx, kxy, kyy) == (hxx, -hxy, hyy)


def test_large_n_stays_finite_at_the_allowed_edge():
    """n = 100 with |x/D| = 1.5: 1.5^200 ~ 1.6e35, far from overflow; check exactly."""
    n, a, b = 100, 0.5, 0.3
    x = 1.5 * 0.2  # D(0) = 0.2
    pot, _, hess = KERNELS["flat"]
    v = pot(x, 0.0, a, b, 1.0, n)
    assert v == pytest.approx(1.5**200 / 200, rel=1e-13)
    assert np.isfinite(hess(x, 0.0, a, b, 1.0, n)).all()


def test_hill_coefficient_kernels_against_the_papers_lambda():
    """n >= 2: q(x) = lambda x^2n with lambda = -2 beta (alpha - beta), the paper's (y-oscill)."""
    for n in (2, 5, 10):
        for x in (0.0, 0.3, -0.9, 1.0):
            lam = -2 * 0.3 * (0.5 - 0.3)
            for f in (bundle("flat").hill_coefficient, bundle("symmetric").hill_coefficient):
                assert f(x, 0.5, 0.3, n) == pytest.approx(lam * x ** (2 * n), rel=1e-14, abs=0)


def test_period_kernel_against_quadrature():
    """Closed form vs an independent tanh-sinh quadrature of the energy integral."""
    for n in (1, 2, 5, 13):
        with mpmath.workdps(25):
            # T = 4 sqrt(n) int_0^1 dz / sqrt(1 - z^2n) for A0 = 1
            quad = (
                4
                * mpmath.sqrt(n)
                * mpmath.quad(lambda z: 1 / mpmath.sqrt(1 - z ** (2 * n)), [0, 1])
            )
            assert oscillator.period_mp(n, mpmath.mpf(1)) == pytest.approx(quad, rel=1e-20)
        assert oscillator.period(n, 1.0) == pytest.approx(float(quad), rel=1e-14)
    assert oscillator.period(1, 0.37) == pytest.approx(2 * np.pi, rel=1e-15)


def test_the_python_twin_of_ipow_leaves_an_array_argument_alone():
    """The plain-Python twin of a kernel may be given arrays: squaring must not happen in
    place, or the caller's array would come back as its own power (it did: y -> y^(2n))."""
    from sinktheory._generated._support import ipow
    from sinktheory.twins import python_kernel

    y = np.array([0.5, -1.5, 2.0])
    out = python_kernel(ipow)(y, 8)
    np.testing.assert_array_equal(y, [0.5, -1.5, 2.0])
    np.testing.assert_allclose(out, y**8, rtol=1e-15)  # against numpy's own power
