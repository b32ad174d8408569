"""The sweep layer: grids, bitwise reproducibility across engines, kill -9 and resume,
refusal of foreign or damaged stores, labelled results.

Every numeric comparison here is bitwise (``np.array_equal``): a sweep point must give the
very numbers of a direct call of its point function with the same inputs, wherever it ran.
Those direct calls (``section``, ``model_hill``, ``simulate``) are the independent reference.
"""

from __future__ import annotations

import io
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import zarr
from _cli import refused

from sinktheory.bifurcation import bifurcation, section
from sinktheory.canonical import FIG8_WELL
from sinktheory.cli import main
from sinktheory.errors import ParameterError
from sinktheory.floquet import model_hill
from sinktheory.model import RunSettings, Sink, Well
from sinktheory.progress import ProgressBar
from sinktheory.simulate import simulate
from sinktheory.sweep import (
    Grid,
    Sweep,
    SweepPointError,
    bifurcation_diagram,
    parse_param,
    point_seed,
    run_sweep,
)

# small, fast bifurcation points (~0.05 s each)
BIF = {"alpha": 0.5, "beta": [-0.3, -0.1, 0.1, 0.3], "n": 4, "transient": 2, "count": 3}


def direct_section(beta: float, n: int = 4, transient: int = 2, count: int = 3) -> np.ndarray:
    return section(Sink(Well(0.5, beta, n), 1, 0.2), transient=transient, count=count)


# --------------------------------------------------------------------------- grid parsing
@pytest.mark.parametrize(
    ("text", "name", "values"),
    [
        ("beta=-0.5:0.5:5", "beta", [-0.5 + 0.25 * i for i in range(5)]),
        ("n=2:10:5", "n", [2, 4, 6, 8, 10]),
        ("n=2:3:3", "n", [2.0, 2.5, 3.0]),  # not whole numbers: floats (Well refuses them)
        ("beta=0.2:0.2:1", "beta", [0.2]),
        ("shape=flat,symmetric", "shape", ["flat", "symmetric"]),
        ("runs=5", "runs", [5]),
        (" mass = 1e-1 ", "mass", [0.1]),
    ],
)
def test_parse_param(text, name, values):
    got_name, got = parse_param(text)
    assert got_name == name
    # exact: the grid points k/4 and small integers are representable
    assert got == values
    assert [type(x) for x in got] == [type(x) for x in values]


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("beta=0:1:0", "COUNT >= 1"),
        ("beta=0:1:-3", "COUNT >= 1"),
        ("beta=0:1:2.5", "COUNT >= 1"),
        ("beta=1:0:3", "LO <= HI"),
        ("beta=0:1:1", "COUNT >= 2 when LO < HI"),
        ("beta=a:1:3", "finite numbers"),
        ("beta=0:inf:3", "finite numbers"),
        ("beta=nan:1:3", "finite numbers"),
        ("beta=0:1", "LO:HI:COUNT"),
        ("beta=0:1:2:3", "LO:HI:COUNT"),
        ("beta", "NAME=LO:HI:COUNT"),
        ("=1", "NAME=LO:HI:COUNT"),
        ("beta=", "NAME=LO:HI:COUNT"),
        ("beta=0.1,,0.2", "none empty"),
    ],
)
def test_parse_param_refuses(text, fragment):
    with pytest.raises(ParameterError, match=fragment.replace("(", r"\(")):
        parse_param(text)


def test_grid_points_in_c_order_and_refusals():
    g = Grid.from_params({"beta": [0.1, 0.2], "n": [2, 4, 6], "alpha": 0.5})
    assert g.names == ("beta", "n") and g.shape == (2, 3)
    # C order: the last swept parameter varies fastest
    assert [(p["beta"], p["n"]) for p in map(g.point, range(6))] == [
        (b, n) for b in (0.1, 0.2) for n in (2, 4, 6)
    ]
    with pytest.raises(ParameterError, match="distinct"):
        Grid.from_params({"beta": [0.1, 0.1]})
    with pytest.raises(ParameterError, match="non-empty"):
        Grid.from_params({"beta": []})


def test_point_seed_is_the_spawned_child():
    # independent derivation: the i-th child of SeedSequence(seed).spawn
    for seed, index in [(0, 0), (0, 7), (12345, 3)]:
        child = np.random.SeedSequence(seed).spawn(index + 1)[index]
        assert point_seed(seed, index) == int(child.generate_state(1, np.uint64)[0])


@pytest.mark.parametrize(
    ("params", "kind", "fragment"),
    [
        ({**BIF, "mas": 0.2}, "bifurcation", "mas = 0.2 .* a parameter of a bifurcation"),
        ({"alpha": 0.5, "n": 4}, "bifurcation", "beta = None .* given"),
        ({**BIF, "count": [3, 4]}, "bifurcation", "count .* a single value"),
        ({**BIF, "particles": 2}, "bifurcation", "particles = 2"),
        ({**BIF, "n": 2.5}, "bifurcation", "n = 2.5 .* an integer"),
        ({**BIF, "beta": [0.1, 0.5]}, "bifurcation", "beta = 0.5 .* < alpha"),
        ({**BIF, "shape": "round"}, "bifurcation", "shape = 'round'"),
        (BIF, "orbit", "kind = 'orbit'"),
        ({"alpha": 0.5, "beta": 0.1, "n": 4, "scheme": "euler"}, "ensemble", "scheme = 'euler'"),
        ({"alpha": 0.5, "beta": 0.1, "n": 4, "periods": [2, 3]}, "ensemble", "periods"),
    ],
)
def test_bad_sweeps_refused_before_any_work(params, kind, fragment, tmp_path):
    store = tmp_path / "s.zarr"
    with pytest.raises(ParameterError, match=fragment):
        run_sweep(kind, params, store=store, workers=1, progress=False)
    assert not store.exists() and list(tmp_path.iterdir()) == []


# --------------------------------------------------------------------------- kinds
def test_bifurcation_points_equal_direct_sections():
    ds = run_sweep("bifurcation", BIF, workers=1, progress=False)
    assert ds.section.dims == ("beta", "sample")
    for beta in BIF["beta"]:
        assert np.array_equal(ds.section.sel(beta=beta).values, direct_section(beta))
    assert ds.sample.values.tolist() == [1, 2, 3]
    assert bool(ds.done.all())


def test_bifurcation_diagram_view_equals_the_serial_diagram():
    params = {k: v for k, v in BIF.items() if k != "beta"}
    serial = bifurcation(BIF["beta"], **params)
    view = bifurcation_diagram(run_sweep("bifurcation", BIF, workers=2, progress=False))
    assert np.array_equal(view.section, serial.section)
    assert np.array_equal(view.beta, serial.beta)
    fields = ("quantity", "alpha", "n", "gamma", "shape", "mass", "container_energy", "transient",
              "count")  # fmt: skip
    assert [getattr(view, f) for f in fields] == [getattr(serial, f) for f in fields]
    with pytest.raises(ParameterError, match="a bifurcation sweep over beta alone"):
        bifurcation_diagram(run_sweep("floquet", {"alpha": 0.5, "beta": [0.1, 0.2], "n": 4}))


def test_progress_counts_points_on_a_terminal_and_in_a_log():
    """The sweep's progress (ProgressBar counting points): a bar with rate on a terminal,
    plain lines with the count when stderr is a file."""

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    def bar(stream, **kw):
        return ProgressBar(4, enabled=True, stream=stream, delay=0.0, label="sweep ",
                           unit="point", **kw)  # fmt: skip

    shown = bar(Terminal())
    shown.update(1)
    shown.close()
    assert "sweep" in shown.stream.getvalue() and "1/4" in shown.stream.getvalue()
    assert "point/s" in shown.stream.getvalue()
    log = bar(io.StringIO(), interval=0.0)
    log.update(2)
    log.update(2)
    log.close()
    lines = log.stream.getvalue().splitlines()
    assert lines and "\r" not in log.stream.getvalue() and "4/4" in lines[-1]
    quiet = ProgressBar(4, enabled=False, stream=Terminal(), delay=0.0)
    quiet.update(4)
    quiet.close()
    assert quiet.stream.getvalue() == ""


def test_floquet_points_equal_single_beta_charts_over_two_dims():
    ds = run_sweep(
        "floquet",
        {"alpha": 0.5, "beta": [-0.2, 0.1, 0.3], "n": [2, 10], "shape": "symmetric"},
        workers=1,
        progress=False,
    )
    assert ds.phi_half.dims == ("beta", "n")
    for beta in (-0.2, 0.1, 0.3):
        for n in (2, 10):
            chart = model_hill(0.5, [beta], n, shape="symmetric")
            point = ds.sel(beta=beta, n=n)
            assert point.phi_half.item() == chart.phi_half[0]
            assert point.stable.item() == chart.stable[0]
            assert point.rotation_number.item() == chart.rotation_number[0]


def test_ensemble_points_use_their_own_seeds():
    params = {"alpha": 0.5, "beta": 0.3, "n": 4, "particles": 2, "runs": 3, "periods": 4}
    ds = run_sweep("ensemble", {**params, "replica": [0, 1]}, seed=9, workers=1, progress=False)
    for r in (0, 1):
        seed = point_seed(9, r)
        assert ds.point_seed.sel(replica=r).item() == seed
        sink = Sink(FIG8_WELL, particles=2, mass=0.2)
        res = simulate(sink, RunSettings(runs=3, periods=4, seed=seed), progress=False)
        mean, stderr = res.ensemble_energy()
        assert np.array_equal(ds.mean_energy.sel(replica=r).values, mean)
        assert np.array_equal(ds.stderr.sel(replica=r).values, stderr)
    # different seeds, different starts: the replicas differ
    assert not np.array_equal(ds.mean_energy.values[0], ds.mean_energy.values[1])


def test_single_point_sweep_has_no_dimension(tmp_path):
    params = {"alpha": 0.5, "beta": 0.1, "n": 4, "transient": 2, "count": 3}
    ds = run_sweep("bifurcation", params, store=tmp_path / "one.zarr", progress=False)
    assert ds.section.dims == ("sample",)
    assert np.array_equal(ds.section.values, direct_section(0.1))


def test_numerical_failure_names_the_point_and_keeps_finished_ones(tmp_path):
    store = tmp_path / "fail.zarr"
    # a step of 1 (about T/6) cannot resolve the wall collisions: the energy audit stops it
    params = {"alpha": 0.5, "beta": 0.3, "n": 10, "runs": 1, "periods": 3, "dt": [None, 1.0]}
    with pytest.raises(SweepPointError, match=r"point 1 \(.*'dt': 1.0"):
        run_sweep("ensemble", params, store=store, workers=1, progress=False)
    assert zarr.open_group(store)["done"][...].tolist() == [True, False]


# --------------------------------------------------------------------------- engines
def test_local_processes_and_dask_cluster_match_bitwise(tmp_path, capsys):
    import dask
    import distributed

    serial = run_sweep("bifurcation", BIF, workers=1, progress=False)
    pool = run_sweep("bifurcation", BIF, workers=2, progress=False)
    ens = {"alpha": 0.5, "beta": 0.3, "n": 4, "runs": 2, "periods": 3, "replica": [0, 1, 2]}
    ens_local = run_sweep("ensemble", ens, seed=4, workers=1, progress=False)
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None
    ) as cluster:
        address = cluster.scheduler_address
        on_cluster = run_sweep("bifurcation", BIF, scheduler=address, progress=False)
        ens_cluster = run_sweep("ensemble", ens, seed=4, scheduler=address, progress=False)
        # the address from dask's configuration (what DASK_SCHEDULER_ADDRESS sets)
        with dask.config.set({"scheduler-address": address}):
            stored = run_sweep("bifurcation", BIF, store=tmp_path / "c.zarr", progress=False)
        # the command line with --scheduler
        line = "bifurcation --param alpha=0.5 --param beta=-0.3,-0.1,0.1,0.3 --param n=4 "
        line += f"--param transient=2 --param count=3 --scheduler {address} --json --quiet"
        assert main(["sweep", *line.split(), "--out", str(tmp_path / "cli.zarr")]) == 0
        assert json.loads(capsys.readouterr().out)["where"].startswith("Dask cluster")
    by_cli = xr.open_zarr(tmp_path / "cli.zarr")
    for other in (pool, on_cluster, stored, by_cli):
        assert np.array_equal(serial.section.values, other.section.values)
    assert np.array_equal(ens_cluster.mean_energy.values, ens_local.mean_energy.values)


def test_unreachable_scheduler_is_a_parameter_error_and_writes_nothing(tmp_path):
    import dask
    import distributed  # noqa: F401 (its config first: set() would drop it on exit if
    # it were loaded inside, and a later dask compute in this process would fail)

    store = tmp_path / "never.zarr"
    with dask.config.set({"distributed.comm.timeouts.connect": "0.5s"}):
        with pytest.raises(ParameterError, match="scheduler = 'tcp://127.0.0.1:1'"):
            run_sweep("bifurcation", BIF, store=store, scheduler="tcp://127.0.0.1:1")
    assert list(tmp_path.iterdir()) == []


# --------------------------------------------------------------------------- store
def test_store_opens_with_xarray_labelled(tmp_path):
    store = tmp_path / "fig.zarr"
    params = {**BIF, "shape": ["flat", "circular"]}  # n = 4 engines the suite compiles anyway
    run_sweep("bifurcation", params, seed=3, store=store, workers=1, progress=False)
    ds = xr.open_zarr(store)
    assert ds.section.dims == ("beta", "shape", "sample")
    assert ds.beta.values.tolist() == BIF["beta"]
    assert ds.shape.values.tolist() == ["flat", "circular"]
    assert (ds.attrs["alpha"], ds.attrs["n"], ds.attrs["count"]) == (0.5, 4, 3)
    assert ds.attrs["sweep_seed"] == 3 and ds.attrs["sweep_kind"] == "bifurcation"
    import sinktheory

    assert ds.attrs["sinktheory_version"] == sinktheory.__version__
    assert np.array_equal(ds.section.sel(beta=0.1, shape="flat").values, direct_section(0.1))


def test_existing_store_needs_resume_and_the_same_sweep(tmp_path):
    store = tmp_path / "s.zarr"
    run_sweep("bifurcation", BIF, store=store, workers=1, progress=False)
    with pytest.raises(ParameterError, match="does not exist yet"):
        run_sweep("bifurcation", BIF, store=store, workers=1, progress=False)
    for kind, params, seed, fragment in [
        ("bifurcation", {**BIF, "n": 6}, 0, "n = 4 there, 6 here"),
        ("bifurcation", BIF, 1, "seed 0 there, 1 here"),
        ("bifurcation", {**BIF, "beta": [-0.3, 0.3]}, 0, "swept"),
        ("floquet", {"alpha": 0.5, "beta": [0.1, 0.2], "n": 4}, 0, "kind 'bifurcation' there"),
    ]:
        with pytest.raises(ParameterError, match=f"made by another sweep.*{fragment}"):
            run_sweep(kind, params, seed=seed, store=store, resume=True, progress=False)


def test_a_store_being_written_is_refused(tmp_path):
    from sinktheory.sweep import Sweep, SweepStore

    store = tmp_path / "busy.zarr"
    writer = SweepStore.create(store, Sweep.make("bifurcation", BIF))  # holds the lock
    with pytest.raises(ParameterError, match="no other sweep is writing to .*locked"):
        run_sweep("bifurcation", BIF, store=store, resume=True, workers=1, progress=False)
    writer.close()
    ds = run_sweep("bifurcation", BIF, store=store, resume=True, workers=1, progress=False)
    assert bool(ds.done.all())


def test_foreign_and_damaged_stores_are_refused(tmp_path):
    plain = tmp_path / "plain"
    plain.mkdir()
    (plain / "notes.txt").write_text("not a store")
    foreign = tmp_path / "foreign.zarr"
    xr.Dataset({"x": ("t", np.arange(3.0))}).to_zarr(foreign, consolidated=False)
    cases = [(plain, "not a Zarr group"), (foreign, "no sweep fingerprint")]

    tampered = tmp_path / "tampered.zarr"
    run_sweep("bifurcation", BIF, store=tampered, workers=1, progress=False)
    zarr.open_group(tampered, mode="r+").attrs["sweep_spec"] = '{"kind": "x"}'
    cases.append((tampered, "fingerprint does not match"))

    damaged = tmp_path / "damaged.zarr"
    run_sweep("bifurcation", BIF, store=damaged, workers=1, progress=False)
    (damaged / "done" / "zarr.json").unlink()
    cases.append((damaged, "damaged"))

    broken_data = tmp_path / "data.zarr"
    run_sweep("bifurcation", BIF, store=broken_data, workers=1, progress=False)
    chunks = [c for c in (broken_data / "section" / "c").rglob("*") if c.is_file()]
    chunks[0].write_bytes(chunks[0].read_bytes()[:5])  # a finished point's data cut short
    cases.append((broken_data, "damaged"))

    broken_chunk = tmp_path / "chunk.zarr"
    run_sweep("bifurcation", BIF, store=broken_chunk, workers=1, progress=False)
    for chunk in (broken_chunk / "done" / "c").rglob("*"):
        if chunk.is_file():
            chunk.write_bytes(b"\x00garbage")
    cases.append((broken_chunk, "damaged"))

    for path, fragment in cases:
        with pytest.raises(ParameterError, match=f"store = .*{fragment}"):
            run_sweep("bifurcation", BIF, store=path, resume=True, progress=False)


def test_unflagged_points_are_recomputed_whatever_their_data(tmp_path, capsys):
    # The done flag is the commit point: a point whose data was written but whose flag
    # was not (a kill between the two) is computed again, overwriting what is there.
    store = tmp_path / "chart.zarr"
    params = {"alpha": 0.5, "beta": np.linspace(-0.5, 0.4, 150), "n": [2, 3, 4]}
    reference = run_sweep("floquet", params, workers=1, progress=False)
    run_sweep("floquet", params, store=store, workers=1, progress=False)
    group = zarr.open_group(store, mode="r+")
    lost = np.zeros((150, 3), dtype=bool)
    lost[[0, 7, 64, 65, 149], [0, 2, 1, 1, 2]] = True
    done, phi = group["done"][...], group["phi_half"][...]
    done[lost], phi[lost] = False, 12345.0
    group["done"][...], group["phi_half"][...] = done, phi
    assert main(["sweep", "floquet", *_params_args(params), "--out", str(store), "--resume",
                 "--json", "--quiet"]) == 0  # fmt: skip
    summary = json.loads(capsys.readouterr().out)
    assert (summary["computed"], summary["skipped"]) == (5, 450 - 5)
    resumed = xr.open_zarr(store)
    assert bool(resumed.done.all())
    for name in reference.data_vars:
        assert np.array_equal(resumed[name].values, reference[name].values), name


def _params_args(params: dict) -> list[str]:
    args = []
    for name, value in params.items():
        values = np.atleast_1d(value)
        args += ["--param", f"{name}=" + ",".join(repr(x.item()) for x in values)]
    return args


# --------------------------------------------------------------------------- kill -9
# an ensemble sweep writes point by point (bifurcation and chaos sweeps compute a task's
# points together, so a small one is written at once and cannot be killed half-way)
KILL_ARGS = (
    "ensemble --param alpha=0.5 --param beta=-0.3:0.4:8 --param n=4 --param particles=1 "
    "--param runs=2 --param periods=40 --seed 5"
).split()


def _done_count(store: Path) -> int:
    try:
        return int(np.sum(zarr.open_group(store, mode="r")["done"][...]))
    except Exception:  # noqa: BLE001 - the store may not exist yet
        return 0


def test_kill_9_then_resume_gives_the_uninterrupted_results(tmp_path, capsys):
    store = tmp_path / "killed.zarr"
    cmd = [sys.executable, "-m", "sinktheory", "sweep", *KILL_ARGS, "--out", str(store)]
    proc = subprocess.Popen([*cmd, "--workers", "1", "--quiet"], stderr=subprocess.PIPE)
    deadline = time.monotonic() + 120
    while _done_count(store) < 2 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    before = _done_count(store)
    assert proc.returncode == -signal.SIGKILL
    assert 2 <= before < 8, "the kill must land in the middle of the sweep"
    # a temporary chunk file as a killed write leaves it: removed on resume
    leftover = store / "mean_energy" / "c" / "0" / "0.deadbeef.partial"
    leftover.write_bytes(b"half a chunk")

    assert main(["sweep", *KILL_ARGS, "--out", str(store), "--resume", "--json", "--quiet"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["skipped"] == before and summary["computed"] == 8 - before
    assert summary["dims"] == {"beta": 8} and summary["points"] == 8
    assert not leftover.exists()

    resumed = xr.open_zarr(store)
    reference = run_sweep(
        "ensemble",
        {
            "alpha": 0.5,
            "beta": np.linspace(-0.3, 0.4, 8),
            "n": 4,
            "particles": 1,
            "runs": 2,
            "periods": 40,
        },  # fmt: skip
        seed=5,
        workers=1,
        progress=False,
    )
    assert bool(resumed.done.all())
    assert np.array_equal(resumed.beta.values, reference.beta.values)
    assert np.array_equal(resumed.mean_energy.values, reference.mean_energy.values)
    assert np.array_equal(resumed.point_seed.values, reference.point_seed.values)


# --------------------------------------------------------------------------- CLI
def test_cli_bad_input_exits_2_and_writes_nothing(tmp_path, capsys):
    store = tmp_path / "bad.zarr"
    for line in (
        "orbit --param beta=0.1",
        "bifurcation --param alpha=0.5 --param beta=0:1:0 --param n=4",
        "bifurcation --param alpha=0.5 --param beta=1:0:3 --param n=4",
        "bifurcation --param alpha=0.5 --param beta=x:1:3 --param n=4",
        "bifurcation --param alpha=0.5 --param beta=0.1 --param k=4",
        "bifurcation --param alpha=0.5 --param alpha=0.6 --param n=4",
        "floquet --param alpha=0.5 --param beta=0.1 --param n=4 --seed -1",
    ):
        assert main(["sweep", *line.split(), "--out", str(store), "--quiet"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "sinktheory sweep: error:" in err
    assert list(tmp_path.iterdir()) == []


def test_the_grids_check_shows_its_progress_when_asked(monkeypatch):
    """Sweep.make(progress=True) counts the points it has checked on stderr once the
    check lasts CHECK_DELAY (set to 0 here); without progress it shows nothing."""
    from sinktheory.sweep import plan

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.setattr(plan, "CHECK_DELAY", 0.0)
    grid = {"alpha": 0.5, "beta": [-0.2, 0.0, 0.2], "n": 4}
    for progress in (True, False):
        monkeypatch.setattr(sys, "stderr", Terminal())
        Sweep.make("floquet", grid, progress=progress)
        shown = sys.stderr.getvalue()
        assert ("checking the grid" in shown and "3/3" in shown) if progress else not shown


def test_one_bad_point_among_many_good_ones_is_named(tmp_path, capsys, monkeypatch):
    """The grid's check reaches every point: a single bad combination (beta = 0.45 at
    alpha = 0.4, a negative wall distance) among good ones is refused naming beta and its
    value, in Python and on the command line (one line, exit 2, no store)."""
    grid = {"alpha": [0.5, 0.6, 0.4, 0.7], "beta": [-0.3, 0.0, 0.2, 0.45], "n": 4,
            "transient": 2, "count": 3}  # fmt: skip
    with pytest.raises(ParameterError) as refusal:
        Sweep.make("bifurcation", grid)
    assert (refusal.value.name, refusal.value.value) == ("beta", 0.45)
    assert "< alpha = 0.4" in str(refusal.value)
    fine = Sweep.make("bifurcation", {**grid, "alpha": [0.5, 0.6, 0.7]})  # the others pass
    assert fine.grid.size == 12
    betas = [*np.linspace(-0.3, 0.4, 30).tolist(), 0.5, -0.2]  # floquet: the 31st point
    with pytest.raises(ParameterError, match="beta = 0.5 is not allowed: must be < alpha"):
        Sweep.make("floquet", {"alpha": 0.5, "beta": betas, "n": 4})
    line = refused(["sweep", "bifurcation", "--param", "alpha=0.5,0.6,0.4,0.7", "--param",
                    "beta=-0.3,0,0.2,0.45", "--param", "n=4", "--out", "s.zarr"], capsys,
                   tmp_path, monkeypatch, "beta")  # fmt: skip
    assert "beta = 0.45 is not allowed" in line


def test_cli_text_summary(tmp_path, capsys):
    store = tmp_path / "f.zarr"
    args = ["floquet", "--param", "alpha=0.5", "--param", "beta=-0.2,0.3", "--param", "n=10"]
    assert main(["sweep", *args, "--out", str(store), "--workers", "1"]) == 0
    out = capsys.readouterr().out
    assert "floquet sweep over beta (2)" in out and "2 point(s) computed" in out
    assert xr.open_zarr(store).stable.values.tolist() == [True, False]  # lam 0.28, -0.12


def test_cli_chaos_sweep_reports_its_mixed_points(tmp_path, capsys):
    """A chaos sweep's report says where a point's runs split into regular and chaotic
    ones: the counts and fractions are recomputed here from the stored per-run exponents
    by the rule itself (regular when lambda_1 <= 3 ln t / t, t the span), and the text
    gives each mixed point instead of its mean.  Over 40 periods the beta = 0 runs'
    exponents (0.04-0.13, seed 0, third point) straddle the envelope 0.066 (over 300
    periods all eight runs tried are chaotic, 0.10-0.17: a split of this span, not an
    island); the other betas have every run chaotic."""
    store = tmp_path / "c.zarr"
    args = ["chaos", "--param", "alpha=0.5", "--param", "beta=-0.4:0.2:4", "--param", "n=4",
            "--param", "runs=6", "--param", "periods=40", "--param", "box=0.1"]  # fmt: skip
    assert main(["sweep", *args, "--out", str(store), "--workers", "1", "--quiet"]) == 0
    text = capsys.readouterr().out
    assert main(["sweep", *args, "--out", str(store), "--resume", "--quiet", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)["split_lambda1"]
    ds = xr.open_zarr(store)
    t = ds.lambda1_periods.values * 2 * np.pi  # no transient
    regular = (ds.lambda1_runs.values <= (3 * np.log(t) / t)[:, None]).sum(axis=1)
    mixed = [b for b, r in zip(ds.beta.values, regular, strict=True) if 0 < r < 6]
    assert mixed, "the sweep was chosen to have a mixed point"
    assert data["mixed_points"] == len(mixed) and data["points"] == ds.beta.size
    assert data["regular_points"] == int((regular == 6).sum())
    assert [m["beta"] for m in data["mixed"]] == mixed
    for m in data["mixed"]:
        r = int(regular[list(ds.beta.values).index(m["beta"])])
        assert m["regular"] == r and m["regular_fraction"] == pytest.approx(r / 6)
        assert f"beta={m['beta']:g}: runs: {r} of 6 regular" in text
    assert f"lambda_1 run by run: {len(mixed)} of {ds.beta.size} point(s) mixed" in text
    assert "starts: particles at rest, uniform in (-0.1, 0.1)^2" in text


def test_ergodicity_sweep_splits_like_the_chaos_sweep():
    """An ergodicity sweep keeps only counts and group means of its Lyapunov runs; its
    split (sinktheory.sweep.views.split_points) must match the one a chaos sweep gets from
    per-run exponents of the same starts (same point seeds), integrated with another step
    (the chaos kind's ladder step, the ergodicity kind's tol 1e-8)."""
    from sinktheory.sweep.views import split_points

    common = {"alpha": 0.5, "beta": [-0.4, -0.2, 0.0, 0.2], "n": 4, "box": 0.1}
    chaos = run_sweep("chaos", {**common, "runs": 6, "periods": 40}, workers=1, progress=False)
    ergo = run_sweep("ergodicity", {**common, "runs": 2, "periods": 30, "transient": 10,
                                    "lyapunov_runs": 6, "lyapunov_periods": 40},
                     workers=1, progress=False)  # fmt: skip
    a, b = split_points(chaos), split_points(ergo)
    assert [w for w, _ in a] == [w for w, _ in b] == [{"beta": x} for x in common["beta"]]
    assert [s.regular for _, s in a] == [s.regular for _, s in b] == [0, 0, 3, 0]
    for (_, s), (_, t) in zip(a, b, strict=True):
        assert (s.runs, s.threshold, s.starts) == (t.runs, t.threshold, t.starts)
        for x, y in ((s.regular_mean, t.regular_mean), (s.chaotic_mean, t.chaotic_mean)):
            assert (np.isnan(x) and np.isnan(y)) or abs(x - y) < 0.1 * x
    assert a[2][1].gap[0] < a[2][1].threshold < a[2][1].gap[1] and np.isnan(b[2][1].gap[0])
    assert split_points(run_sweep("floquet", {"alpha": 0.5, "beta": 0.1, "n": 4},
                                  workers=1, progress=False)) == []  # fmt: skip
