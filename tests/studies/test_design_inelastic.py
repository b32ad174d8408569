"""Inelastic wall contact: the compiled integrator against the simulator (zero damping,
bitwise), the NumPy version of the same splitting (round-off), solve_ivp of the damped
equations (second order), the exact work of the dissipative stage, the audit, the seed.

Workloads are tiny (flat well, n = 4, a few runs x a few periods).
"""

from __future__ import annotations

import numpy as np
import pytest

from sinktheory import RunSettings, Sink, Well
from sinktheory.canonical import FIG8_WELL
from sinktheory.damped import simulate_inelastic
from sinktheory.design.inelastic_reference import simulate_inelastic_reference, solve_damped_ivp
from sinktheory.errors import EnergyDriftError, NonFiniteStateError, ParameterError
from sinktheory.simulate import simulate

SINK2 = Sink(FIG8_WELL, particles=2, mass=0.2)


def test_zero_damping_is_bitwise_the_simulator():
    """c0 = 0: the dissipative stage adds exact zeros, and the conservative stage is the
    simulator's scheme and step with the same arithmetic: the numbers are simulate's."""
    settings = RunSettings(runs=3, periods=3, seed=4)
    on = simulate_inelastic(SINK2, settings, damping=0.0, tol=1e-6)
    off = simulate_inelastic(SINK2, settings, dissipative_stage=False, tol=1e-6)
    ref = simulate(SINK2, settings, tol=1e-6, progress=False)
    assert (on.scheme, on.dt) == (ref.scheme, ref.dt)
    assert on.container_energy.tobytes() == off.container_energy.tobytes()
    assert on.total_energy.tobytes() == off.total_energy.tobytes()
    assert on.container_energy.tobytes() == ref.container_energy.tobytes()
    assert not on.dissipated.any() and not on.damping_ratio.any()
    # the audit is then the simulator's energy error
    assert on.max_audit_error == pytest.approx(ref.max_relative_energy_error, rel=1e-12)


def test_zero_viscous_damping_is_bitwise_the_simulator():
    """The viscous kind at c0 = 0 (constant factors, exactly 0): simulate's numbers."""
    settings = RunSettings(runs=3, periods=3, seed=4)
    on = simulate_inelastic(SINK2, settings, damping=0.0, damping_kind="viscous", tol=1e-6)
    ref = simulate(SINK2, settings, tol=1e-6, progress=False)
    assert (on.scheme, on.dt, on.damping_kind) == (ref.scheme, ref.dt, "viscous")
    assert on.container_energy.tobytes() == ref.container_energy.tobytes()
    assert not on.dissipated.any() and on.sample_times is None


def test_samples_are_the_simulators_trajectory():
    """samples_per_period = 8 with a step count divisible by 8: X and Xdot at the samples
    are simulate's trajectory at the same step and stride, bitwise (c0 = 0)."""
    settings = RunSettings(runs=2, periods=2, seed=3)
    res = simulate_inelastic(SINK2, settings, damping=0.0, damping_kind="viscous",
                             dt=2 * np.pi / 96, samples_per_period=8)  # fmt: skip
    ref = simulate(SINK2, settings, dt=2 * np.pi / 96, record=("trajectory",), stride=12,
                   progress=False)  # fmt: skip
    assert res.steps_per_period == 96 and res.container_x.shape == (2, 17)
    assert res.container_x.tobytes() == np.ascontiguousarray(ref.trajectory[:, :, 0]).tobytes()
    assert res.container_v.tobytes() == np.ascontiguousarray(ref.trajectory[:, :, 1]).tobytes()
    np.testing.assert_array_equal(res.sample_times, ref.trajectory_times)
    y = np.abs(ref.trajectory[:, :, 4:6]).max(axis=2)
    np.testing.assert_array_equal(res.transverse, y)
    # a step count that 7 does not divide is rounded up to a multiple of 7
    odd = simulate_inelastic(SINK2, RunSettings(runs=1, periods=1), dt=2 * np.pi / 96,
                             samples_per_period=7)  # fmt: skip
    assert odd.steps_per_period == 98 and odd.dt == 2 * np.pi / 98


def test_viscous_compiled_equals_the_numpy_splitting_and_is_audited():
    """The viscous weight in both versions of the splitting, from given start rows
    (particles at absolute rest, the container kicked): equal to round-off; W sampled
    agrees with W at the period ends; W is the energy lost (audit)."""
    rows = np.zeros((3, 10))
    rows[:, 1] = 1.0  # Xdot
    rows[:, 2:4] = [[0.01, -0.02], [0.0, 0.03], [-0.02, 0.0]]  # u_1, u_2
    rows[:, 4:6] = [[0.02, 0.0], [-0.01, 0.01], [0.0, -0.03]]  # y_1, y_2
    settings = RunSettings(runs=3, periods=3)
    kw = {"damping": 0.3, "damping_kind": "viscous", "tol": 1e-6, "start": rows}
    fast = simulate_inelastic(SINK2, settings, **kw)
    slow = simulate_inelastic_reference(SINK2, settings, **kw)
    assert fast.dissipated[:, -1].min() > 0.05  # a dashpot everywhere takes a lot
    np.testing.assert_allclose(fast.container_energy, slow.container_energy, rtol=0, atol=1e-12)
    np.testing.assert_allclose(fast.dissipated, slow.dissipated, rtol=1e-10, atol=1e-15)
    assert fast.max_audit_error < 1e-6
    sampled = simulate_inelastic(SINK2, settings, samples_per_period=4, **kw)
    np.testing.assert_array_equal(sampled.sample_dissipated[:, ::4], sampled.dissipated)
    np.testing.assert_allclose(sampled.dissipated, fast.dissipated, rtol=1e-5)


def test_compiled_equals_the_numpy_splitting():
    """Same splitting written twice (numba with the generated energy kernel for the
    contact weight; NumPy with the well's own potential): equal to round-off over three
    periods (chaos amplifies round-off by well under 1e3 by then), for two particles."""
    settings = RunSettings(runs=3, periods=3, seed=8)
    fast = simulate_inelastic(SINK2, settings, damping=1.0, tol=1e-6)
    slow = simulate_inelastic_reference(SINK2, settings, damping=1.0, tol=1e-6)
    assert fast.dissipated[:, -1].min() > 1e-4  # something is dissipated
    np.testing.assert_allclose(fast.container_energy, slow.container_energy, rtol=0, atol=1e-12)
    np.testing.assert_allclose(fast.dissipated, slow.dissipated, rtol=1e-10, atol=1e-15)
    np.testing.assert_allclose(fast.damping_ratio, slow.damping_ratio, rtol=1e-10)
    assert fast.max_audit_error == pytest.approx(slow.max_audit_error, rel=1e-3)


def test_against_solve_ivp_second_order_and_audited():
    sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    settings = RunSettings(runs=1, periods=1, seed=2)
    ec_ref, w_ref, int_ref = solve_damped_ivp(sink, settings, 2.0, 1)
    assert w_ref > 1e-3  # the contact dissipates noticeably over one period
    errors = []
    for steps in (200, 400):
        res = simulate_inelastic(sink, settings, damping=2.0, dt=2 * np.pi / steps,
                                 scheme="blanes-moan6")  # fmt: skip
        assert res.steps_per_period == steps
        assert res.max_audit_error < 1e-8  # H + W = H0 up to the conservative stage
        assert np.all(np.diff(res.dissipated, axis=1) >= 0)
        dw, dec = res.dissipated[0, -1] - w_ref, res.container_energy[0, -1] - ec_ref
        errors.append(abs(dw) + abs(dec))
    assert errors[1] < 1e-4
    assert 3.0 < errors[0] / errors[1] < 5.5  # second order: 4x per halving
    zeta_ref = w_ref / (2 * int_ref)
    assert res.damping_ratio[0] == pytest.approx(zeta_ref, rel=1e-3)


def test_dissipative_stage_removes_exactly_the_work_it_counts():
    """One D stage of the engine's printed kernels, two particles sharing the container:
    the energy falls by exactly the work W counted (positions frozen), momentum in x is
    kept, and with the viscous weight the relative velocity decays as exp(-c (1+mu)/mu t)
    (the exact solution, computed here independently)."""
    from sinktheory.engine.cache import load
    from sinktheory.ensemble import engine_name, engine_params

    engine = load(engine_name(SINK2))
    params = engine.table_of(engine_params(SINK2), 6)
    rng = np.random.default_rng(0)
    q, vel = rng.uniform(-0.3, 0.3, (5, 6)), rng.uniform(-1, 1, (5, 6))
    mu = SINK2.mu
    for weighted in (True, False):
        f, after, work = np.empty((4, 6)), vel.copy(), np.empty(6)
        engine.damping_factors(q, params, 2.5, weighted, 0.025, f)
        engine.dissipate(after, f, params, work)
        h0 = engine.block_energies(q, vel, params)[0]
        h1 = engine.block_energies(q, after, params)[0]
        np.testing.assert_allclose(h0 - h1, work, rtol=1e-12, atol=1e-15)
        assert np.all(work > 0)
        np.testing.assert_allclose(
            vel[0] + mu * vel[1:3].sum(0), after[0] + mu * after[1:3].sum(0), rtol=1e-14
        )
    # one particle (a state of 3 coordinates), constant c
    one, w1, f1 = vel[[0, 1, 3]].copy(), np.empty(6), np.empty((2, 6))
    q1 = q[[0, 1, 3]].copy()
    engine.damping_factors(q1, params, 2.5, False, 0.025, f1)
    engine.dissipate(one, f1, params, w1)
    np.testing.assert_allclose(
        one[1] - one[0], (vel[1] - vel[0]) * np.exp(-2.5 * (1 + mu) / mu * 0.05), rtol=1e-13
    )
    np.testing.assert_allclose(one[2], vel[3] * np.exp(-2.5 / mu * 0.05), rtol=1e-13)


def test_audit_names_run_and_time():
    settings = RunSettings(runs=3, periods=2, seed=1)
    with pytest.raises(EnergyDriftError, match=r"run \d at t = 6.28319 \(period 1\): relative "
                       r"error of energy plus dissipated work .* \(H \+ W = "):  # fmt: skip
        simulate_inelastic(SINK2, settings, damping=1.0, tol=1e-6, energy_bound=1e-14)


def test_a_step_too_large_stops_with_the_run_and_time():
    """dt = T/8 cannot resolve the wall of n = 10: the audit (or the finiteness check)
    stops the run and names it, rather than returning numbers."""
    sink = Sink(Well(0.5, 0.3, 10), particles=1, mass=0.2)
    with pytest.raises((EnergyDriftError, NonFiniteStateError), match=r"run \d at t = .*period \d"):
        simulate_inelastic(sink, RunSettings(runs=2, periods=3), damping=1.0, dt=2 * np.pi / 8)


def test_seeded_and_independent_of_the_other_runs():
    a = simulate_inelastic(SINK2, RunSettings(runs=3, periods=2, seed=5), damping=0.5, tol=1e-6)
    b = simulate_inelastic(SINK2, RunSettings(runs=3, periods=2, seed=5), damping=0.5, tol=1e-6)
    one = simulate_inelastic(SINK2, RunSettings(runs=1, periods=2, seed=5), damping=0.5, tol=1e-6)
    assert a.dissipated.tobytes() == b.dissipated.tobytes()
    assert a.container_energy[:1].tobytes() == one.container_energy.tobytes()
    assert a.dissipated[:1].tobytes() == one.dissipated.tobytes()
    other = simulate_inelastic(SINK2, RunSettings(runs=3, periods=2, seed=6), damping=0.5,
                               tol=1e-6)  # fmt: skip
    assert not np.array_equal(a.container_energy, other.container_energy)


@pytest.mark.parametrize(
    "kw, name",
    [
        ({"damping": -0.1}, "damping"),
        ({"damping": float("nan")}, "damping"),
        ({"dt": 0.01, "tol": 1e-6}, "tol"),
        ({"scheme": "euler"}, "scheme"),
        ({"energy_bound": 0.0}, "energy_bound"),
        ({"damping_kind": "coulomb"}, "damping_kind"),
        ({"samples_per_period": -1}, "samples_per_period"),
        ({"start": np.zeros((2, 6))}, "start"),
        ({"start": np.tile([0, 0, 0.3, 0.3, 0, 0, 0, 0, 0, 0.0], (2, 1))}, "start"),
    ],
)
def test_bad_input_names_the_parameter(kw, name):
    with pytest.raises(ParameterError, match=name):
        simulate_inelastic(SINK2, RunSettings(runs=2, periods=1), **kw)


# --------------------------------------------------------------------------- the explorer
def test_damping_is_a_design_dimension():
    """A sweep over the contact damping: each point is simulate_inelastic (or simulate
    at c0 = 0) with the point's seed, bitwise; zeta_eq its mean +- s.e. over runs."""
    from sinktheory.design import explore
    from sinktheory.runstats import ensemble_mean
    from sinktheory.sweep.grid import point_seed

    params = {"beta": 0.3, "n": 4, "particles": 2, "damping": [0.0, 0.5], "runs": 3,
              "periods": 12, "horizons": "6+12", "lyapunov_runs": 2, "lyapunov_periods": 3,
              "bootstrap": 10}  # fmt: skip
    run = explore(params, seed=2, workers=1, progress=False, estimate_first=False)
    ds = run.dataset
    settings = [RunSettings(runs=3, periods=12, seed=point_seed(2, i)) for i in range(2)]
    plain = simulate(SINK2, settings[0], tol=1e-6, progress=False)
    damped = simulate_inelastic(SINK2, settings[1], damping=0.5, tol=1e-6)
    for c0, res in ((0.0, plain), (0.5, damped)):
        mean, se = ensemble_mean(res.container_energy)
        np.testing.assert_array_equal(ds.mean_energy.sel(damping=c0).values, mean)
        np.testing.assert_array_equal(ds.stderr.sel(damping=c0).values, se)
    zeta, zeta_se = damped.equivalent_damping()
    assert float(ds.zeta_eq.sel(damping=0.5)) == zeta > 0
    assert float(ds.zeta_eq_se.sel(damping=0.5)) == zeta_se
    share = damped.dissipated[:, -1] / damped.initial_energy
    assert float(ds.dissipated.sel(damping=0.5)) == share.mean()
    assert float(ds.max_relative_energy_error.sel(damping=0.5)) == damped.max_audit_error
    # no contact damping: nothing dissipated, exactly; lambda_1 only for the conservative
    assert float(ds.zeta_eq.sel(damping=0.0)) == 0.0 == float(ds.dissipated.sel(damping=0.0))
    assert np.isfinite(float(ds.lambda1.sel(damping=0.0)))
    assert np.isnan(float(ds.lambda1.sel(damping=0.5)))
    by_c0 = {r["damping"]: r for r in run.ranked}
    assert by_c0[0.5]["zeta_eq"] == zeta and by_c0[0.0]["zeta_eq"] == 0.0
    # the heat map over the damping gets a zeta_eq panel
    from sinktheory.plot.design import heatmaps

    (fig,) = heatmaps(ds).values()
    assert [ax.get_title() for ax in fig.axes if ax.get_title()][-1] == "$\\zeta_{eq}$ (max)"


def test_damping_on_the_command_line(tmp_path, capsys):
    import json

    from _cli import run_cli

    argv = ["design", "--beta", "0.3", "--n", "4", "--damping", "0,0.5", "--runs", "2",
            "--periods", "8", "--horizons", "8", "--lyapunov-runs", "0", "--bootstrap", "4",
            "--workers", "1", "--no-estimate", "--quiet", "--out", str(tmp_path / "d.zarr"),
            "--report", str(tmp_path / "rep"), "--json"]  # fmt: skip
    code, out, err = run_cli(argv, capsys)
    assert code == 0, err
    data = json.loads(out)
    assert "damping" in data["dims"]
    zetas = {d["damping"]: d["zeta_eq"] for d in data["designs"]}
    assert zetas[0.0] == 0.0 and zetas[0.5] > 0
    text = (tmp_path / "rep" / "report.md").read_text()
    assert "zeta_eq" in text and "inelastic wall contact" in text
    # refused: negative damping, one line, exit 2, nothing written
    bad = tmp_path / "bad"
    bad.mkdir()
    argv = ["design", "--beta", "0.3", "--n", "4", "--damping", "0,-0.1",
            "--out", str(bad / "d.zarr"), "--report", str(bad / "rep")]  # fmt: skip
    code, out, err = run_cli(argv, capsys)
    assert code == 2 and out == "" and "damping" in err and len(err.strip().splitlines()) == 1
    assert list(bad.iterdir()) == []


def test_cost_of_a_damped_design():
    """A damped design is the inelastic ensemble only (no lambda_1): its work is the
    plain ensemble's times the relative cost of a dissipative step, by hand.  In particle
    steps of the work limit: a step of 5 runs of 3 particles is 5 x 3 + 8 (their block),
    of 2 lambda_1 runs 2 x (3 (1 + 0.7) + 6.6) + 8 (one vector each, its overhead, the
    block), both x (6 + 1) / 12 for blanes-moan4's 6 stages (tol 1e-6)."""
    from sinktheory.design.cost import work
    from sinktheory.design.explorer import plan
    from sinktheory.stepsize import choose

    sweep = plan({"beta": 0.3, "n": 4, "particles": 3, "damping": [0.0, 0.5], "runs": 5,
                  "periods": 7, "lyapunov_runs": 2, "lyapunov_periods": 11})  # fmt: skip
    plain, damped = (sweep.grid.point(i) for i in range(2))
    steps = choose(Sink(FIG8_WELL, particles=3, mass=0.2), 0.5, 1e-6).steps_per_period
    stages = 7 / 12
    assert work(plain, 2.0, 3.0) == pytest.approx(
        steps * stages * (7 * (5 * 3 + 8) + 2.0 * 11 * (2 * (3 * 1.7 + 6.6) + 8)), rel=1e-12
    )
    assert work(damped, 2.0, 3.0) == pytest.approx(steps * stages * 3.0 * 7 * (5 * 3 + 8))
