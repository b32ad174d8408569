"""The circular well, added as one definition in ``sinktheory.symbolic``, end to end.

V = gamma/(2n) ((x^2 + y^2)/(alpha - beta)^2)^n.  Every check compares with something
independent of the generated kernels:

* the potential and its derivatives against the formula written out here with numpy;
* the engine's accelerations in 2-D against the coupled equations with that formula; the
  simulator's energy audit (bound 1e-8); and on the line y = 0, where the circular and flat
  wells coincide for every n, against the flat engine;
* Floquet: turning the orbit on y = 0 by a small angle gives the solution y = eps x(t) of
  Hill's equation, so phi_half = -1 exactly (for every beta, n and amplitude), and against
  a second integrator (solve_ivp);
* the sweeps and the CLI against the same exact value.
"""

import json

import numpy as np
import pytest
from _cli import run_cli as run

from sinktheory import symbolic as S
from sinktheory._generated.shapes import bundle
from sinktheory.ensemble import random_positions
from sinktheory.errors import ParameterError
from sinktheory.floquet import model_hill, model_problem
from sinktheory.hill import monodromy_solve_ivp
from sinktheory.model import SHAPES, RunSettings, Sink, Well
from sinktheory.simulate import simulate
from sinktheory.sweep import run_sweep

CIRCULAR = bundle("circular")


def _radial(x, y, alpha, beta, gamma, n):
    """V and its derivatives from the formula, independent of the kernels."""
    L2 = (alpha - beta) ** 2
    w = (x * x + y * y) / L2
    V = gamma / (2 * n) * w**n
    f = gamma * w ** (n - 1) / L2  # V_x = f x, V_y = f y
    g = 2 * (n - 1) * gamma * w ** (n - 2) / L2**2 if n > 1 else 0.0  # df/d(x or y) = g x
    return V, (f * x, f * y), (f + g * x * x, g * x * y, f + g * y * y)


def test_registered_everywhere():
    assert "circular" in S.SHAPES and "circular" in SHAPES
    assert CIRCULAR.NAME == "circular" and CIRCULAR.NORMAL_MODE_REFUSAL == ""


@pytest.mark.parametrize("n", [1, 2, 3, 8, 40])
def test_kernels_against_the_radial_formula(n):
    """Relative 1e-13 (a few roundings of O(1) numbers and one integer power)."""
    rng = np.random.default_rng(n)
    for _ in range(20):
        alpha, beta, gamma = rng.uniform(0.4, 1.2), rng.uniform(-0.5, 0.3), rng.uniform(0.5, 2)
        r, t = rng.uniform(0.0, 1.3) * (alpha - beta), rng.uniform(0, 2 * np.pi)
        x, y = r * np.cos(t), r * np.sin(t)
        V, grad, hess = _radial(x, y, alpha, beta, gamma, n)
        args = (x, y, alpha, beta, gamma, n)
        np.testing.assert_allclose(CIRCULAR.potential(*args), V, rtol=1e-13)
        scale = max(abs(grad[0]), abs(grad[1]))
        np.testing.assert_allclose(CIRCULAR.gradient(*args), grad, rtol=1e-13, atol=1e-13 * scale)
        hscale = max(abs(h) for h in hess)
        np.testing.assert_allclose(CIRCULAR.hessian(*args), hess, rtol=1e-12, atol=1e-13 * hscale)


def test_centre_is_regular():
    """At r = 0 no 0/0: force 0, Hessian gamma/L^2 for n = 1 (harmonic) and 0 for n >= 2."""
    for n, expected in ((1, 1.0 / 0.25), (2, 0.0), (5, 0.0)):
        assert CIRCULAR.gradient(0.0, 0.0, 0.8, 0.3, 1.0, n) == (0.0, 0.0)
        hxx, hxy, hyy = CIRCULAR.hessian(0.0, 0.0, 0.8, 0.3, 1.0, n)
        assert (hxx, hxy, hyy) == (expected, 0.0, expected)


def test_geometry_reach_and_walls():
    """Basin V <= E is the disc r <= c (alpha - beta), c = (2 n E/gamma)^(1/2n); the wall
    ratio is r/(alpha - beta); the rigid wall has curvature -1/(alpha - beta)."""
    well = Well(0.7, 0.2, 6, gamma=1.5, shape="circular")
    E = 0.3
    c = (2 * 6 * E / 1.5) ** (1 / 12)
    assert well.reach(E) == pytest.approx((0.5 * c, 0.5 * c), rel=1e-15)
    g = np.linspace(-0.7, 0.7, 701)
    X, Y = np.meshgrid(g, g)
    inside = well.potential(X, Y) <= E
    assert np.abs(X[inside]).max() == pytest.approx(0.5 * c, abs=0.003)
    assert well.wall_ratio(0.3, 0.4) == pytest.approx(1.0, rel=1e-15)
    with pytest.raises(ParameterError, match="^initial = "):
        well.check_position("initial", 0.3, 0.4)
    well.check_position("initial", 0.29, 0.4)
    assert well.curvature_at_centre == pytest.approx(-2.0, rel=1e-15)
    # alpha and beta enter only through alpha - beta
    other = Well(1.0, 0.5, 6, gamma=1.5, shape="circular")
    assert other.potential(0.21, -0.33) == pytest.approx(well.potential(0.21, -0.33), rel=1e-14)


def test_simulate_conserves_energy():
    """Engine run (k = 2, n = 4, beta = 0.1): the audited relative energy error <= 1e-8."""
    sink = Sink(Well(0.5, 0.1, 4, shape="circular"), particles=2, mass=0.2)
    res = simulate(
        sink, RunSettings(runs=3, periods=150, seed=2), tol=1e-9, record=("container", "particles")
    )
    assert res.max_relative_energy_error <= 1e-8
    total = res.container_energy + res.particle_energy.sum(axis=2)
    assert np.abs(total / res.initial_energy[:, None] - 1).max() <= 1e-8
    assert res.container_energy.min() < 0.49  # energy did flow into the particles


def test_engine_forces_against_the_radial_formula():
    """The compiled engine's accelerations at random 2-D states (k = 2, n = 4) against
    the coupled equations written out here with the radial formula: X'' = -X + sum V_x,
    u_j'' = -V_x / mu, y_j'' = -V_y / mu with mu = m / k (relative 1e-12)."""
    from sinktheory.engine.cache import load
    from sinktheory.ensemble import engine_name, engine_params

    alpha, beta, k, m = 0.5, 0.1, 2, 0.2
    sink = Sink(Well(alpha, beta, 4, shape="circular"), particles=k, mass=m)
    module = load(engine_name(sink))
    rng = np.random.default_rng(7)
    R = 16
    X = rng.uniform(-1, 1, R)
    r = rng.uniform(0.0, 1.1, (k, R)) * (alpha - beta)
    t = rng.uniform(0, 2 * np.pi, (k, R))
    x, y = r * np.cos(t), r * np.sin(t)
    q = np.vstack([X, X + x, y])  # [X, u_1..u_k, y_1..y_k], u_j = X + x_j
    got = module.block_accelerations(q, module.table_of(engine_params(sink), R))
    _, (fx, fy), _ = _radial(x, y, alpha, beta, 1.0, 4)
    mu = m / k
    want = np.vstack([-X + fx.sum(axis=0), -fx / mu, -fy / mu])
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * np.abs(want).max())


def test_on_the_line_y_0_equals_the_flat_well():
    """On y = 0 both wells are gamma/(2n) (x/(alpha - beta))^(2n) and neither pushes off
    the line, so a particle started on it with the container moves along x alone and two
    different generated engines (flat and circular, n = 4, which the suite compiles
    anyway) must give the same container energies, to round-off: 1e-12.  The motion is
    chaotic (round-off grows about 3x per period), so 3 periods: measured 1.7e-13 here,
    8 seeds 7e-14..5e-13; a wrong force differs at once by far more."""
    settings = RunSettings(runs=2, periods=3, seed=4)
    start = random_positions(settings, 1)
    start[:, :, 1] = 0.0
    out = {}
    for shape in ("flat", "circular"):
        sink = Sink(Well(0.5, 0.1, 4, shape=shape), particles=1, mass=0.2)
        out[shape] = simulate(
            sink, settings, scheme="blanes-moan6", dt=0.01, initial=start, progress=False
        )
    assert out["flat"].container_energy.min() < 0.45  # the particle did take energy
    np.testing.assert_allclose(
        out["circular"].container_energy, out["flat"].container_energy, rtol=0, atol=1e-12
    )


@pytest.mark.parametrize("n", [1, 2, 6])
def test_floquet_normal_mode_is_neutral(n):
    """phi_half = -1 exactly (rotation of the orbit), at every beta and amplitude: 1e-10."""
    for amplitude in (1.0, 1.7):
        chart = model_hill(0.5, [-0.4, 0.0, 0.3], n, shape="circular", amplitude=amplitude)
        np.testing.assert_allclose(chart.phi_half, -1.0, atol=1e-10)
        np.testing.assert_allclose(chart.lam, 1.0)


def test_floquet_against_solve_ivp():
    """A second integrator over the half period agrees (1e-8, its own accuracy)."""
    ref = monodromy_solve_ivp(4, 0.2, coefficient=CIRCULAR.hill_coefficient, alpha=0.5)
    got = model_hill(0.5, [0.2], 4, shape="circular").phi_half[0]
    assert got == pytest.approx(np.trace(ref) / 2, abs=1e-8)


def test_floquet_refuses_a_shape_without_normal_mode(monkeypatch):
    monkeypatch.setattr(CIRCULAR, "NORMAL_MODE_REFUSAL", "y = 0 is not invariant (test)")
    with pytest.raises(ParameterError, match="^shape = 'circular'.*y = 0 is not invariant"):
        model_problem(0.5, 4, shape="circular")


def test_sweeps_over_the_circular_well():
    """A floquet sweep (exact -1) and an ensemble sweep (energy audit) over a small grid."""
    ds = run_sweep(
        "floquet",
        {"alpha": 0.5, "beta": [-0.3, 0.2], "n": [2, 5], "shape": "circular"},
        workers=1,
        progress=False,
    )
    np.testing.assert_allclose(ds.phi_half.values, -1.0, atol=1e-10)
    ens = run_sweep(
        "ensemble",
        {"alpha": 0.5, "beta": [-0.2, 0.1], "n": 4, "shape": "circular", "runs": 2, "periods": 40},
        workers=1,
        progress=False,
    )
    assert ens.mean_energy.shape[:1] == (2,)
    assert np.all(np.abs(ens.mean_energy.values[:, 0] - 0.5) < 1e-3)  # E0 plus the box


def test_cli(capsys):
    code, out, err = run(
        [
            "simulate",
            "--shape",
            "circular",
            "--alpha",
            "0.5",
            "--beta",
            "0.1",
            "--n",
            "4",
            "--runs",
            "2",
            "--periods",
            "30",
            "--quiet",
            "--json",
        ],
        capsys,
    )
    assert code == 0, err
    assert "circular" in out
    code, out, err = run(
        ["floquet", "--shape", "circular", "--alpha", "0.5", "--beta", "0.1", "--n", "4", "--json"],
        capsys,
    )
    assert code == 0, err
    assert json.loads(out)["phi_half"] == pytest.approx(-1.0, abs=1e-10)
    code, out, err = run(
        ["simulate", "--shape", "oval", "--alpha", "0.5", "--beta", "0.1", "--n", "4"], capsys
    )
    assert code == 2 and "shape" in err and "circular" in err
