"""Tolerance-driven steps: the calibrated error model keeps its promise on workloads it was
not calibrated on, picks the cheapest scheme, and refuses what it cannot promise.

The reference is the conserved Hamiltonian itself (the energy audit of each run), on wells
outside the calibration set of benchmarks/calibrate_steps.py (flat beta = -0.2, at n = 10, the
stiffer of the calibrated flat walls and an engine the suite compiles anyway; the symmetric
well at beta = -0.1; k = 2 and 3; and k = 10, twice the most particles calibrated).
"""

import math

import pytest

from sinktheory import ParameterError, RunSettings, Sink, Well
from sinktheory.integrators import SCHEMES, get_scheme
from sinktheory.simulate import simulate
from sinktheory.stepsize import CALIBRATION, TOL_RANGE, choose, cost_table

UNSEEN = [
    Sink(Well(0.5, -0.2, 10), particles=3, mass=0.2),
    Sink(Well(1.0, -0.1, 6, shape="symmetric"), particles=2, mass=0.2),
]
MANY = Sink(Well(0.5, 0.1, 4), particles=10, mass=0.2)


def test_every_scheme_is_calibrated():
    assert set(CALIBRATION) == set(SCHEMES)
    assert all(c > 0 and 0 < cliff < 1 for c, cliff in CALIBRATION.values())


@pytest.mark.parametrize("sink", UNSEEN, ids=["flat-b-0.2-n10-k3", "symmetric-b-0.1-n6-k2"])
@pytest.mark.parametrize("tol", [1e-6, 1e-9])
def test_tolerance_is_met_on_unseen_wells(sink, tol):
    res = simulate(sink, RunSettings(runs=2, periods=150, seed=8), tol=tol, progress=False)
    assert res.tol == tol
    assert res.max_relative_energy_error <= tol
    assert res.container_energy.min() < 0.45  # the particles really took up energy


@pytest.mark.parametrize("tol", [1e-6, 1e-9])
def test_tolerance_is_met_with_ten_particles(tol):
    """Twice the particles of any calibrated workload (lighter particles, a stiffer
    frequency bound): the audit must still show tol met."""
    res = simulate(MANY, RunSettings(runs=4, periods=150, seed=5), tol=tol, progress=False)
    assert res.max_relative_energy_error <= tol
    assert res.container_energy.min() < 0.45


def test_choice_is_the_cheapest_and_cost_falls_with_tolerance():
    sink = UNSEEN[0]
    costs = []
    for tol in (1e-11, 1e-9, 1e-7, 1e-5):
        table = cost_table(sink, 0.5, tol)
        best = choose(sink, 0.5, tol)
        assert best == table[0]
        assert all(
            best.force_evaluations_per_period <= c.force_evaluations_per_period for c in table
        )
        assert all(c.predicted_error <= tol * (1 + 1e-12) for c in table)
        costs.append(best.force_evaluations_per_period)
        # the step really is the scheme's: stages x steps per period
        s = get_scheme(best.scheme)
        assert best.force_evaluations_per_period == s.stages * best.steps_per_period
        assert best.dt * best.steps_per_period == pytest.approx(2 * math.pi, rel=1e-14)
    assert costs == sorted(costs, reverse=True)


@pytest.mark.parametrize("tol", [0.0, -1e-8, TOL_RANGE[0] / 10, TOL_RANGE[1] * 10, math.nan])
def test_bad_tolerance_is_refused_naming_tol(tol):
    with pytest.raises(ParameterError, match=r"^tol = "):
        simulate(UNSEEN[0], RunSettings(runs=1, periods=1), tol=tol, progress=False)


def test_tol_and_dt_together_are_refused():
    with pytest.raises(ParameterError, match="tol"):
        simulate(UNSEEN[0], RunSettings(runs=1, periods=1), tol=1e-8, dt=1e-3, progress=False)


def test_forced_method_gets_its_own_step_for_the_tolerance():
    res = simulate(UNSEEN[0], RunSettings(runs=1, periods=20, seed=1), scheme="yoshida4", tol=1e-7)
    assert (res.stepper, res.scheme) == ("fixed", "yoshida4")
    assert res.max_relative_energy_error <= 1e-7


def test_cli_tol_picks_scheme_and_step_and_reports_them(capsys):
    import json

    from _cli import run_cli

    argv = ["simulate", "--alpha", "0.5", "--beta", "-0.2", "--n", "10", "--particles", "3"]
    argv += ["--mass", "0.2", "--runs", "2", "--periods", "3", "--quiet", "--json"]
    code, out, err = run_cli([*argv, "--tol", "1e-6"], capsys)
    assert code == 0, err
    data = json.loads(out)
    expected = choose(UNSEEN[0], 0.5, 1e-6)
    assert (data["scheme"], data["tol"]) == (expected.scheme, 1e-6)
    assert data["steps_per_period"] == expected.steps_per_period
    assert data["max_relative_energy_error"] <= 1e-6
    code, out, err = run_cli([*argv, "--tol", "1e-2"], capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and "tol = " in err
