"""Sweep stores: a refusal leaves no store behind and names the right parameter; an I/O
error names the store."""

from __future__ import annotations

import dataclasses
import resource
import subprocess
import sys

import pytest

from sinktheory.equilibrium.ergodicity import ergodicity_point
from sinktheory.errors import ParameterError
from sinktheory.sweep import run_sweep
from sinktheory.sweep import runner as runner_module
from sinktheory.sweep.plan import Sweep
from sinktheory.sweep.store import SweepStore

POINT = {"alpha": 0.5, "beta": 0.3, "n": 4}


@pytest.mark.parametrize(
    ("extra", "name"),
    [
        ({"tol": 1}, "tol"),  # the simulator's range 1e-12..1e-4: refused after the store
        ({"tol": 1e-20}, "tol"),
        ({"lyapunov_periods": 10**18}, "lyapunov_periods"),  # blamed periods
        ({"lyapunov_runs": 10**11}, "lyapunov_runs"),
        ({"lyapunov_runs": 1}, "lyapunov_runs"),  # a standard error of 0 from one run
        ({"replica": -1}, "replica"),  # was accepted
    ],
)
def test_ergodicity_refusal_names_the_parameter_and_leaves_no_store(extra, name, tmp_path):
    store = tmp_path / "e.zarr"
    with pytest.raises(ParameterError) as info:
        run_sweep("ergodicity", {**POINT, **extra}, store=store, workers=1, progress=False)
    assert info.value.name == name
    assert str(info.value).startswith(f"{name} = ")
    assert list(tmp_path.iterdir()) == []


#: Small points of the two kinds that compute lambda_1 over lyapunov_runs runs.
SMALL = {
    "ergodicity": {**POINT, "runs": 3, "periods": 40, "transient": 10, "lyapunov_periods": 5},
    "design": {"beta": 0.3, "n": 4, "runs": 3, "periods": 40, "lyapunov_periods": 5},
}


@pytest.mark.parametrize("kind", sorted(SMALL))
@pytest.mark.parametrize("runs", [1, 10**11])
def test_lyapunov_runs_follow_one_rule_quoting_the_set_allowed(kind, runs, tmp_path):
    """Issue 34 audit, note 2: ergodicity refused lyapunov_runs = 1 while design stored a
    NaN standard error and no verdict from it, and 10**11 was refused with the range
    [1, 10000000], which holds the refused 1.  Both kinds now refuse one run, and say
    what is allowed: 0 or [2, the most] (design: the point's runs, whose first ones they
    are)."""
    with pytest.raises(ParameterError) as info:
        run_sweep(kind, {**SMALL[kind], "lyapunov_runs": runs}, store=tmp_path / "s.zarr",
                  workers=1, progress=False)  # fmt: skip
    top = 10**7 if kind == "ergodicity" else SMALL[kind]["runs"]
    assert info.value.name == "lyapunov_runs"
    assert info.value.allowed == f"0 (none) or an integer in [2, {top}]"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    ("point", "name"),
    [
        ({"beta": 0.3, "n": 4}, "alpha"),  # KeyError before
        ({**POINT, "periods_": 10}, "periods_"),  # unknown keys were ignored
        ("x", "p"),  # TypeError before
    ],
)
def test_ergodicity_point_refuses_bad_points(point, name):
    with pytest.raises(ParameterError) as info:
        ergodicity_point(point, 0)
    assert info.value.name == name


def test_a_point_refused_while_computing_leaves_no_new_store(tmp_path, monkeypatch):
    """The kind's checks cannot foresee every refusal; one that comes from a point's
    computation still removes the store this run created (not a resumed one)."""
    kind = runner_module.KINDS["floquet"]

    def refuse(params, seed):
        raise ParameterError("rtol", 1, "what the computation accepts")

    monkeypatch.setitem(runner_module.KINDS, "floquet", dataclasses.replace(kind, compute=refuse))
    params = {"alpha": 0.5, "beta": [0.1, 0.2], "n": 4}
    with pytest.raises(ParameterError, match="rtol"):
        run_sweep("floquet", params, store=tmp_path / "f.zarr", workers=1, progress=False)
    assert list(tmp_path.iterdir()) == []
    # a store that exists is the user's: resuming it into a refusal keeps it
    SweepStore.create(tmp_path / "g.zarr", Sweep.make("floquet", params)).close()
    with pytest.raises(ParameterError, match="rtol"):
        run_sweep("floquet", params, store=tmp_path / "g.zarr", workers=1, progress=False,
                  resume=True)  # fmt: skip
    assert [p.name for p in tmp_path.iterdir()] == ["g.zarr"]


def test_file_too_large_names_the_store(tmp_path):
    """A file-size limit makes zarr's chunk writes fail with EFBIG; the message named no
    file ("could not write : File too large")."""

    def small_files():
        resource.setrlimit(resource.RLIMIT_FSIZE, (8192, 8192))

    argv = ["sweep", "floquet", "--param", "alpha=0.5", "--param", "beta=-0.3:0.3:20000"]
    argv += ["--param", "n=2,10", "--out", "big.zarr", "--workers", "1", "--quiet"]
    proc = subprocess.run(
        [sys.executable, "-m", "sinktheory", *argv], cwd=tmp_path, capture_output=True,
        text=True, preexec_fn=small_files, timeout=120,
    )  # fmt: skip
    assert proc.returncode == 1, proc.stderr
    assert proc.stderr == "sinktheory sweep: could not write big.zarr: File too large\n"


def test_a_store_without_a_result_of_its_kind_is_named_not_called_damaged(tmp_path):
    """A kind that gains a result (the design kind's split of lambda_1) meets stores
    written before it: resuming one names the missing arrays, and the store is kept."""
    import shutil

    params = {"alpha": 0.5, "beta": [0.1, 0.2], "n": 4}
    SweepStore.create(tmp_path / "g.zarr", Sweep.make("floquet", params)).close()
    shutil.rmtree(tmp_path / "g.zarr" / "rotation_number")
    with pytest.raises(ParameterError, match=r"it has no rotation_number: written by a "
                       r"sinktheory \S+ that did not compute it, or damaged"):  # fmt: skip
        run_sweep("floquet", params, store=tmp_path / "g.zarr", workers=1, progress=False,
                  resume=True)  # fmt: skip
    assert [p.name for p in tmp_path.iterdir()] == ["g.zarr"]


def test_damaged_last_chunk_ends_in_one_line(tmp_path, monkeypatch):
    """Resuming a store whose last chunk no longer decodes gave the right refusal, then
    58-180 lines of asyncio/zarr output ending in "Event loop is closed" (printed as the
    interpreter exits, so only a real process shows it): now the line and nothing after."""
    import numpy as np

    from sinktheory.sweep import store as store_module

    monkeypatch.setattr(store_module, "CHUNK_VALUES", 2)  # six chunks, reads in flight
    params = {"alpha": 0.5, "beta": list(np.linspace(-0.3, 0.3, 12)), "n": 4}
    run_sweep("floquet", params, store=tmp_path / "s.zarr", workers=1, progress=False)
    last = tmp_path / "s.zarr" / "lam" / "c" / "5"
    last.write_bytes(last.read_bytes()[:5])
    argv = ["sweep", "floquet", "--param", "alpha=0.5", "--param", "beta=-0.3:0.3:12"]
    argv += ["--param", "n=4", "--out", "s.zarr", "--resume", "--quiet", "--workers", "1"]
    proc = subprocess.run([sys.executable, "-m", "sinktheory", *argv], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)  # fmt: skip
    assert proc.returncode == 2 and proc.stdout == "", proc.stderr
    assert proc.stderr.count("\n") == 1, proc.stderr
    assert proc.stderr.startswith("sinktheory sweep: error: store = 's.zarr' ")
    assert "damaged" in proc.stderr
