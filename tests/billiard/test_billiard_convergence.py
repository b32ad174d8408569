"""Soft walls against the rigid limit (sinktheory.billiard.convergence) and ``--n inf``."""

import json
import math

import numpy as np
import pytest
from _cli import run_cli
from scipy.integrate import solve_ivp

from sinktheory._generated import oscillator as osc
from sinktheory.billiard import billiard
from sinktheory.billiard.convergence import (
    convergence,
    count_hits,
    lambda_after,
    measure,
    power_rate,
    wall_terms,
)
from sinktheory.canonical import SYMMETRIC_WELL
from sinktheory.errors import ParameterError
from sinktheory.model import RunSettings, Sink, Well
from sinktheory.validation import stiffness


def _oscillator_samples(n, alpha, mu, energy, periods, per_period):
    """States (1, S, 6) of one particle on y = 0 in a container at rest (beta = 0), started
    at x = 0 moving right, integrated by DOP853 at rtol 1e-12; and its exact period.  With
    u = x / alpha and s = t / (alpha sqrt(mu)) (gamma 1) the motion is the generated
    oscillator u'' = -u^(2n-1) of amplitude (2 n E)^(1/(2n)) (paper eq. T)."""
    scale = alpha * math.sqrt(mu)
    period = scale * osc.period(n, osc.amplitude_of_energy(n, energy))

    def rhs(t, z):
        return [z[1], osc.oscillator_acceleration(z[0] / alpha, n) * alpha / scale**2]

    t = np.linspace(0, periods * period, int(periods * per_period) + 1)
    sol = solve_ivp(rhs, (0, t[-1]), [0.0, math.sqrt(2 * energy / mu)], method="DOP853",
                    t_eval=t, rtol=1e-12, atol=1e-14)  # fmt: skip
    states = np.zeros((1, t.size, 6))
    states[0, :, 2], states[0, :, 4] = sol.y
    return states, period


def test_hits_of_the_power_law_oscillator_are_its_turning_points():
    # a particle on y = 0 of a resting container is the oscillator mu x'' = -V'(x): its
    # wall hits are its turning points, at T/4 + j T/2 (exact period from Gamma functions)
    n, alpha, mu, energy, periods = 6, 0.5, 0.2, 0.3, 10.3
    states, period = _oscillator_samples(n, alpha, mu, energy, periods, 400)
    sink = Sink(Well(alpha, 0.0, n), particles=1, mass=mu)
    expected = math.floor((periods * period - period / 4) / (period / 2)) + 1
    assert count_hits(sink, states).tolist() == [[expected, 0]]
    # split at a turning point (the worst place): the chunks share their boundary sample
    cut = int(round(2.75 * 400))
    first = count_hits(sink, states[:, : cut + 1])
    second = count_hits(sink, states[:, cut:], before=states[:, cut - 1])
    assert (first + second).tolist() == [[expected, 0]]


def test_wall_terms_sum_to_the_generated_potential():
    rng = np.random.default_rng(1)
    x, y = rng.uniform(-0.4, 0.4, 50), rng.uniform(-0.6, 0.6, 50)
    for well in (SYMMETRIC_WELL, Well(0.5, -0.3, 5), Well(0.5, 0.1, 3,
                 shape="circular")):  # fmt: skip
        v = np.array([well.potential(a, b) for a, b in zip(x, y, strict=True)])
        np.testing.assert_allclose(wall_terms(well, x, y).sum(axis=-1), v, rtol=1e-12)


def test_power_rate_recovers_an_exact_power_and_skips_noise():
    ns = np.array([4, 10, 20, 50, 100])
    q = 1.0 + 2.0 * ns**-1.5
    r = power_rate(ns, q, np.full(5, 1e-6), 1.0, 1e-6)
    assert r["p"] == pytest.approx(1.5, abs=1e-9) and r["C"] == pytest.approx(2.0, rel=1e-8)
    # differences within two standard errors of the limit are left out of the fit
    r = power_rate(ns, q, np.full(5, 0.01), 1.0, 0.0)
    assert r["fit_ns"] == [4, 10, 20]  # 2 n^-1.5 = 0.25, 0.063, 0.022 > 0.02; 0.0057, 0.002
    assert r["p"] == pytest.approx(1.5, abs=1e-9)
    assert power_rate(ns, q, np.full(5, 1e-6), 1.0, 1e-6, n_min=20)["fit_ns"] == [20, 50, 100]


def test_rigid_measurement_is_the_billiard_api():
    st = RunSettings(runs=3, periods=12, seed=5)
    m = measure("flat", 0.5, -0.3, math.inf, settings=st, transient=2)
    r = billiard("flat", 0.5, -0.3, settings=st, lyapunov=True)
    np.testing.assert_array_equal(m.container_energy, r.container_energy)
    np.testing.assert_array_equal(m.mean_free_time, r.mean_free_time)
    logs = r.logs
    np.testing.assert_allclose(
        m.lambda1, (logs[:, -1] - logs[:, 2]) / (10 * 2 * math.pi), rtol=1e-14
    )
    with pytest.raises(ParameterError, match="transient"):
        lambda_after(r, 12)


def test_soft_mean_free_time_approaches_the_rigid_one():
    # n = 10 (an engine the suite compiles anyway; n = 50 cost 30 s of CI) against n = oo,
    # the same 12 seeded starts, beta = 0.3 (chaotic).  Tolerance: 3 standard errors of
    # the difference plus 8 % of the rigid value, the largest soft-rigid difference at
    # n = 10 in the guide's table (docs/guide/convergence_n.inc, 256 runs: 7.9 %, the energy
    # average at beta = 0.3; 5 % from n = 20 on); with 12 runs x 25 periods that allows
    # about 30 %: a loose check that catches a hit count off by a large factor; the exact
    # check of the count is the oscillator's above
    st = RunSettings(runs=12, periods=25, seed=3)
    c = convergence("flat", 0.5, 0.3, ns=(4, 10), settings=st)
    m, se, rm, rse = c.summary("mean_free_time")
    assert abs(m[1] - rm) <= 3 * math.hypot(se[1], rse) + 0.08 * rm
    assert 0.3 < rm < 1.5  # about pi A / P / speed: a hit count off by 2x would fail
    # the container energy ends on the same level within the same allowance
    m, se, rm, rse = c.summary("energy_average")
    assert abs(m[1] - rm) <= 3 * math.hypot(se[1], rse) + 0.08 * rm


def test_stiffness_values():
    assert stiffness("n", "inf") == math.inf and stiffness("n", 7.0) == 7
    for bad in (0, 2.5, -math.inf, math.nan, "oo", True):
        with pytest.raises(ParameterError, match="rigid limit"):
            stiffness("n", bad)


BASE = ["--alpha", "0.5", "--beta", "0.3", "--n", "inf", "--runs", "2", "--periods", "6"]


def test_chaos_n_inf_is_the_rigid_billiard(capsys, tmp_path):
    png = tmp_path / "c.png"
    code, out, err = run_cli(["chaos", *BASE, "--transient", "1", "--json"], capsys)
    assert code == 0, err
    d = json.loads(out)
    r = billiard("flat", 0.5, 0.3, settings=RunSettings(runs=2, periods=6), lyapunov=True)
    np.testing.assert_array_equal(d["lambda1"], lambda_after(r, 1))
    assert d["n"] == "inf" and d["max_relative_energy_error"] < 1e-12
    code, out, err = run_cli(["chaos", *BASE, "--plot", str(png)], capsys)
    assert code == 0 and "rigid billiard" in out and png.stat().st_size > 10_000


def test_simulate_n_inf_is_the_rigid_billiard(capsys):
    code, out, err = run_cli(["simulate", *BASE, "--json"], capsys)
    assert code == 0, err
    d = json.loads(out)
    r = billiard("flat", 0.5, 0.3, settings=RunSettings(runs=2, periods=6))
    np.testing.assert_array_equal(d["mean_energy"], r.container_energy.mean(axis=0))


@pytest.mark.parametrize(
    "argv,name",
    [
        (["chaos", *BASE, "--dt", "0.01"], "--dt"),
        (["chaos", *BASE, "--spectrum"], "--spectrum"),
        (["chaos", *BASE, "--scheme", "verlet"], "--scheme"),
        (["simulate", *BASE, "--tol", "1e-6"], "--tol"),
        (["simulate", *BASE, "--initial", "0", "0"], "--initial"),
        (["chaos", *BASE[:5], "-inf", *BASE[6:]], "n"),
        (["simulate", *BASE[:5], "0", *BASE[6:]], "n"),
        (["well", "--alpha", "0.5", "--beta", "0.3", "--n", "inf"], "n"),
    ],
)
def test_refusals_are_one_line_and_write_nothing(argv, name, capsys, tmp_path):
    png = tmp_path / "x.png"
    extra = ["--plot", str(png)] if argv[0] != "well" else []
    code, out, err = run_cli(argv + extra, capsys)
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and f"{name} = " in err, err
    assert not png.exists()
