"""The result protocol: as_dict() is JSON-ready and survives a JSON round trip unchanged;
to_dataset() has the named dimensions and coordinates; the CLI prints as_dict()."""

import json

import numpy as np
import pytest

from sinktheory import RunSettings, Sink, Well
from sinktheory.bifurcation import bifurcation
from sinktheory.canonical import FIG8_WELL
from sinktheory.chaos import chaos
from sinktheory.cli import main
from sinktheory.layout import StateLayout
from sinktheory.recurrence import rqa
from sinktheory.results import Result, attribute, plain
from sinktheory.series import accuracy
from sinktheory.simulate import simulate

SINK = Sink(FIG8_WELL, particles=2, mass=0.2)


def roundtrip(d: dict) -> dict:
    return json.loads(json.dumps(d, allow_nan=False))


@pytest.fixture(scope="module")
def sim():
    record = ("container", "particles", "trajectory", "final")
    return simulate(SINK, RunSettings(runs=3, periods=2, seed=4), record=record, progress=False)


def test_plain_types():
    x = plain({"a": np.array([[1.5, np.nan]]), "z": np.complex128(2 - 1j), 3: np.int64(7)})
    assert x == {"a": [[1.5, None]], "z": [2.0, -1.0], "3": 7}
    assert type(x["3"]) is int
    with pytest.raises(TypeError):
        plain(object())
    assert attribute(True) == 1 and attribute({"k": [1, np.inf]}) == '{"k": [1, null]}'


def test_simulation_result_round_trip_and_dataset(sim):
    d = sim.as_dict()
    assert roundtrip(d) == d
    assert d["container_energy"] == sim.container_energy.tolist()
    assert d["mean_energy"] == sim.ensemble_energy()[0].tolist()
    assert d["final_state"]["values"] == sim.final_state.values.tolist()
    assert d["parameters"]["runs"] == 3 and d["parameters"]["shape"] == "flat"
    ds = sim.to_dataset()
    assert ds.container_energy.dims == ("run", "time")
    assert ds.particle_energy.dims == ("run", "time", "particle")
    assert ds.trajectory.dims == ("run", "sample", "state")
    assert ds.final_state_values.dims == ("run", "state")
    np.testing.assert_array_equal(ds.time.values, sim.times)
    np.testing.assert_array_equal(ds.sample.values, sim.trajectory_times)
    assert list(ds.state.values) == list(StateLayout(2).names())
    # the dataset's total energy per period is the conserved total (independent check)
    total = ds.container_energy + ds.particle_energy.sum("particle")
    np.testing.assert_allclose(total, ds.initial_energy.broadcast_like(total), rtol=1e-8)
    assert json.loads(ds.attrs["parameters"]) == d["parameters"]


def test_bifurcation_and_rqa():
    d = bifurcation([0.1, 0.3], alpha=0.5, n=4, transient=2, count=3)
    assert roundtrip(d.as_dict()) == d.as_dict()
    ds = d.to_dataset()
    assert ds.section.dims == ("beta", "sample") and ds.beta.values.tolist() == [0.1, 0.3]
    assert ds.sample.values.tolist() == [1, 2, 3] and ds.attrs["quantity"] == "y"
    r = rqa([0.0, 1.0, 0.0, 1.0, 0.0, 1.0], eps=0.1)
    rd = r.as_dict()
    assert roundtrip(rd) == rd and rd["determinism"] == 1.0 and rd["laminarity"] == 0.0
    assert rd["trapping_time"] is None  # nan: no vertical line
    assert r.to_dataset().diagonal_lines.dims == ("length",)


def test_chaos_result_follows_the_protocol():
    res = chaos(SINK, RunSettings(runs=2, periods=3, seed=1), dt=0.02, progress=False)
    assert isinstance(res, Result)
    d = res.as_dict()
    assert roundtrip(d) == d and d["lambda1"]["runs"] == res.lambda1.tolist()


def test_nested_lists_of_results():
    a = accuracy(3, 2, samples=101)
    d = a.as_dict()
    assert roundtrip(d) == d
    assert [e["order"] for e in d["errors"]] == [1, 2] and d["bounds"][0]["i"] == 2


def test_cli_json_is_the_api_as_dict(capsys):
    argv = ["simulate", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--particles", "2"]
    assert main(argv + ["--runs", "2", "--periods", "2", "--seed", "5", "--json", "--quiet"]) == 0
    data = json.loads(capsys.readouterr().out)
    api = simulate(
        SINK, RunSettings(runs=2, periods=2, seed=5), record=("container", "final"), progress=False
    )
    assert data == api.as_dict()


def test_design_measures_follow_the_protocol():
    from sinktheory.design.measures import design_measures

    # a never-draining ensemble: E stays at E0, so no level is ever passed (NaN -> None)
    e = 0.5 + 1e-3 * np.random.default_rng(2).standard_normal((4, 41))
    m = design_measures(e, e0=0.5, total_energy=0.5, particles=1, n=4, horizons=[10, 40])
    d = m.as_dict()
    assert roundtrip(d) == d and d["horizons"] == [10, 40] and d["passage"] == [None, None]
    assert d["verdict_name"] == m.verdict_name
    ds = m.to_dataset()
    assert ds.absorbed.dims == ("horizon",) and ds.horizon.values.tolist() == [10, 40]
    assert ds.passage.dims == ("level",)


def cli_json(argv, capsys) -> dict:
    assert main([*argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_period_well_sink_cli_json_is_the_api_as_dict(capsys):
    from sinktheory.oscillator import oscillator

    o = oscillator(2, energy="0.25", dps=20)
    d = o.as_dict()
    assert roundtrip(d) == d and o.to_dataset().attrs["period"] == d["period"]
    assert cli_json(["period", "--n", "2", "--energy", "0.25", "--digits", "20"], capsys) == d

    well = Well(0.5, -0.3, 4)
    s = well.summary(0.5)
    d = s.as_dict()
    assert roundtrip(d) == d and d["walls"] == "focusing (stadium-like)"
    # independent: on the y axis V = y^(2n)/(2n), so E = 1/2 is reached at y = 4^(1/8)
    assert d["reach"]["y"] == pytest.approx(4 ** (1 / 8), rel=1e-12)
    assert s.to_dataset().attrs["reach_x"] == s.reach.x
    argv = ["--alpha", "0.5", "--beta", "-0.3", "--n", "4"]
    assert cli_json(["well", *argv], capsys) == d

    sink = Sink(well, particles=4, mass=0.2)
    settings = RunSettings(runs=3, periods=7, seed=2)
    d = sink.summary(settings).as_dict()
    assert roundtrip(d) == d and d["mu"] == pytest.approx(0.05) and d["runs"] == 3
    argv += ["--particles", "4", "--runs", "3", "--periods", "7", "--seed", "2"]
    assert cli_json(["sink", *argv], capsys) == d


def test_nnm_branch_follows_the_protocol(capsys):
    from sinktheory.nnm.continuation import continue_both

    # what `sinktheory nnm --continue-in beta` runs: particle mode, E = k gamma / (2n)
    res = continue_both(Sink(Well(0.5, -0.2, 4), 1, 0.2), "particle", continue_in="beta",
                        total_energy=0.125, interval=(-0.3, -0.1), steps=100, points=4, ds=0.1,
                        half_traces=True)  # fmt: skip
    assert isinstance(res, Result)
    d = res.as_dict()
    assert roundtrip(d) == d and d["continue_in"] == "beta" and d["steps"] == 100
    # the fixed energy of a continuation in beta, held at every point (the shooting's
    # energy row; H(z0) evaluated apart from it)
    assert np.allclose(d["total_energy"], 0.125, rtol=1e-12, atol=0) and res.points > 1
    assert d["max_trivial_error"] == max(d["trivial_error"])
    ds = res.to_dataset()
    assert ds.transverse.dims == ("point", "transverse_multiplier")
    assert ds.phi_half.dims == ("point", "particle") and ds.point.size == res.points
    assert ds.attrs["system"] == d["system"] and json.loads(ds.attrs["params"]) == d["params"]
    # independent: the full period's transverse multipliers have the trace 2 phi_T,
    # phi_T = 2 phi_half^2 - 1 from the half-period map (two separate integrations; the
    # orbit's symmetry makes it exact for the discrete maps too: 1e-14 measured)
    trace = ds.transverse.sum("transverse_multiplier").real
    np.testing.assert_allclose(trace, 2 * (2 * ds.phi_half[:, 0] ** 2 - 1), atol=1e-10)
    argv = ["nnm", "--alpha", "0.5", "--beta", "-0.2", "--n", "4", "--continue-in", "beta"]
    argv += ["--interval", "-0.3", "-0.1", "--points", "4", "--steps", "100"]
    assert cli_json(argv, capsys) == d


def test_chaos_sweep_kind_stores_the_results_summary():
    from sinktheory.sweep import run_sweep

    params = {"alpha": 0.5, "beta": 0.3, "n": 4, "runs": 3, "periods": 6, "dt": 0.05}
    ds = run_sweep("chaos", {**params, "gali": 2, "megno": 1, "replica": [0, 1]},
                   workers=1, progress=False)  # fmt: skip
    for r in (0, 1):
        seed = int(ds.point_seed.values[r])
        res = chaos(Sink(FIG8_WELL), RunSettings(runs=3, periods=6, seed=seed),
                    gali=2, megno=True, dt=0.05, progress=False)  # fmt: skip
        d = res.as_dict()
        assert ds.gali.values[r] == d["gali2"]["mean"]
        assert ds.mean_megno_se.values[r] == d["mean_megno"]["stderr"]
        # independent of as_dict: the plain mean and s.e. of the runs' last values
        g = res.gali[:, -1]
        assert ds.gali.values[r] == pytest.approx(g.mean(), rel=1e-14)
        assert ds.gali_se.values[r] == pytest.approx(g.std(ddof=1) / np.sqrt(3), rel=1e-12)
    assert np.isnan(ds.transverse.values).all() and np.isnan(ds.transverse_se.values).all()
