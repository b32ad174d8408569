"""A sweep store written under the old parameter names (``energy``, ``method``, before
they became ``container_energy`` and ``scheme``) still resumes and reads.

The old store is built here as the code before the rename wrote it: the same kind with
its parameters under the old names, its grid, description and fingerprint made from
those names, and the store created from them (attributes, coordinates and dimensions
named ``energy`` and ``method``)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import xarray as xr

from sinktheory.errors import ParameterError
from sinktheory.sweep.grid import Grid, fingerprint
from sinktheory.sweep.kinds import get_kind
from sinktheory.sweep.plan import Sweep
from sinktheory.sweep.runner import execute, run_sweep
from sinktheory.sweep.store import SweepStore

#: The names before the rename, written out here rather than taken from the package.
OLD = {"container_energy": "energy", "scheme": "method"}
PARAMS = {"alpha": 0.5, "beta": 0.3, "n": 4, "container_energy": [0.4, 0.5],
          "scheme": "yoshida4", "runs": 2, "periods": 3}  # fmt: skip
SEED = 4


def _old_store(path, done: dict[str, np.ndarray] | None = None) -> None:
    """The store of the ``PARAMS`` sweep as it was written before the rename; the first
    point stored from ``done`` (the results of the whole sweep), if given."""
    kind = get_kind("ensemble")
    old_kind = dataclasses.replace(kind, params={OLD.get(k, k): p for k, p in kind.params.items()})
    completed = kind.complete(PARAMS)
    grid = Grid.from_params({OLD.get(k, k): v for k, v in completed.items()})
    spec, digest = fingerprint("ensemble", grid, SEED)
    sweep = Sweep(old_kind, grid, SEED, spec, digest)
    store = SweepStore.create(path, sweep)
    if done is not None:
        store.write(np.array([0]), {name: done[name][:1] for name in kind.results})
    store.close()


def test_an_old_store_resumes_under_the_new_names_to_the_same_numbers(tmp_path):
    fresh = run_sweep("ensemble", PARAMS, seed=SEED, workers=1, progress=False)
    path = tmp_path / "old.zarr"
    _old_store(path, {name: fresh[name].values for name in fresh.data_vars})
    raw = xr.open_zarr(path)
    assert "energy" in raw.dims and raw.attrs["method"] == "yoshida4"  # spelt the old way
    assert "container_energy" not in raw.dims and "scheme" not in raw.attrs

    done = execute(Sweep.make("ensemble", PARAMS, SEED), store=path, resume=True, workers=1,
                   progress=False)  # fmt: skip
    assert (done.computed, done.skipped, done.repaired) == (1, 1, 0)
    ds = done.dataset
    assert ds.mean_energy.dims == ("container_energy", "period")
    assert ds.container_energy.values.tolist() == [0.4, 0.5]
    assert ds.attrs["scheme"] == "yoshida4" and "method" not in ds.attrs
    for name in fresh.data_vars:
        np.testing.assert_array_equal(ds[name].values, fresh[name].values, err_msg=name)
    again = execute(Sweep.make("ensemble", PARAMS, SEED), store=path, resume=True, workers=1,
                    progress=False)  # fmt: skip
    assert (again.computed, again.skipped) == (0, 2)
    assert "energy" in xr.open_zarr(path).dims  # read under the new names, not rewritten


def test_an_old_store_of_another_sweep_is_still_refused_naming_the_difference(tmp_path):
    path = tmp_path / "old.zarr"
    _old_store(path)
    with pytest.raises(ParameterError, match=r"made by another sweep: runs = 2 there, 3 here\)$"):
        run_sweep("ensemble", {**PARAMS, "runs": 3}, seed=SEED, store=path, resume=True,
                  workers=1, progress=False)  # fmt: skip
    changed = r"another sweep: scheme = 'yoshida4' there, 'verlet' here\)$"
    with pytest.raises(ParameterError, match=changed):
        run_sweep("ensemble", {**PARAMS, "scheme": "verlet"}, seed=SEED, store=path,
                  resume=True, workers=1, progress=False)  # fmt: skip


def test_an_old_parameter_on_the_command_line_runs_with_a_note(tmp_path, capsys):
    """``--param energy=...`` runs the sweep under its new name, with the one-line note of
    an old option (:func:`sinktheory.glossary.modern_argv`)."""
    from _cli import run_cli

    store = tmp_path / "b.zarr"
    args = ["sweep", "bifurcation", "--param", "alpha=0.5", "--param", "beta=0.1,0.3",
            "--param", "n=4", "--param", "transient=1", "--param", "count=2",
            "--out", str(store), "--quiet", "--json"]  # fmt: skip
    code, out, err = run_cli([*args, "--param", "energy=0.4"], capsys)
    assert code == 0, err
    assert err.strip() == ("sinktheory sweep: note: --param energy is now --param "
                           "container_energy (the old name goes in the next release)")  # fmt: skip
    assert xr.open_zarr(store).attrs["container_energy"] == 0.4
    params = {"alpha": 0.5, "beta": [0.1, 0.3], "n": 4, "transient": 1, "count": 2,
              "container_energy": 0.4}  # fmt: skip
    new = run_sweep("bifurcation", params, workers=1, progress=False)
    np.testing.assert_array_equal(xr.open_zarr(store).section.values, new.section.values)
