"""The Zarr store of a sweep: created whole, written point by point, resumable.

Layout.  One Zarr v3 group, readable with ``xarray.open_zarr``: each result is an array
over (swept parameters..., result dimensions...), the swept parameters and result
dimensions are coordinates, and the attributes hold the fixed parameters, the seed, the
package version and the sweep's fingerprint (SHA-256 of its canonical description: kind,
swept values, fixed values, seed).  ``done`` flags the points stored; ``point_seed``
holds every point's seed.

Why a killed sweep never corrupts the store or loses a finished point:

* creation writes the complete empty store into a hidden sibling directory and renames
  it into place (``os.rename`` of a directory is atomic), so a store either exists whole
  or not at all;
* only the driver process writes, one point batch at a time, in order: first the result
  values, then the ``done`` flags.  zarr 3's ``LocalStore`` writes every chunk to a
  temporary file and renames it over the old one, so a chunk holds either its old or its
  new contents, never a mix; a neighbouring point that shares a chunk is rewritten with
  its old values intact;
* the ``done`` flag is the commit point: a point killed between its data and its flag is
  computed again on resume (it gives the same numbers), and leftover temporary files are
  removed;
* resuming reads every array once: a store whose chunks do not decode, whose arrays are
  missing or misshapen, or whose fingerprint does not match its description is refused
  as damaged rather than silently extended;
* while a driver writes, it holds an exclusive lock (``flock``) on a file in the store, so
  a second driver is refused; the system drops the lock when the process dies.

This holds for a killed process (kill -9) on a local file system; it does not promise
durability across a power cut (no fsync) or on object stores.

Examples
--------
>>> import tempfile, pathlib
>>> from sinktheory.sweep.plan import Sweep
>>> sweep = Sweep.make("floquet", {"alpha": 0.5, "beta": [-0.2, 0.1], "n": 10})
>>> path = pathlib.Path(tempfile.mkdtemp()) / "chart.zarr"
>>> store = SweepStore.create(path, sweep)
>>> store.done().tolist()
[False, False]
>>> SweepStore.create(path, sweep)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: store = '...chart.zarr' is not allowed: must be a path \
that does not exist yet (resume to continue the sweep stored there)
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import math
import os
import shutil
import uuid
import warnings
from pathlib import Path
from typing import Any

import dask.array as da
import numpy as np
import xarray as xr
import zarr

from .. import validation as v
from ..errors import ParameterError
from .plan import MARK, Sweep

#: File in the store locked by the process writing to it.
LOCK = ".sweep.lock"
#: Target number of values in one chunk of a result array.
CHUNK_VALUES = 4096


class SweepStore:
    """An open sweep store (use :meth:`create` or :meth:`open`)."""

    def __init__(self, path: Path, sweep: Sweep, group: zarr.Group) -> None:
        self.path = path
        self.sweep = sweep
        self.group = group
        self._lock = _lock(path)
        self._arrays = {name: group[name] for name in (*sweep.kind.results, "done")}

    # --- creating and opening -----------------------------------------------------------
    @classmethod
    def create(cls, path: str | Path, sweep: Sweep) -> SweepStore:
        """Create the empty store of ``sweep`` at ``path`` (which must not exist)."""
        path = _checked_path(path)
        if path.exists():
            raise ParameterError(
                "store",
                str(path),
                "a path that does not exist yet (resume to continue the sweep stored there)",
            )
        tmp = path.parent / f".{path.name}.creating-{uuid.uuid4().hex}"
        try:
            template = sweep.dataset(_empty_results(sweep), np.zeros(sweep.grid.shape, bool))
            encoding = {name: {"chunks": _chunks(sweep, name)} for name in sweep.kind.results}
            encoding["done"] = {"chunks": _flag_chunks(sweep)}
            with warnings.catch_warnings():  # consolidated metadata: not (yet) in the v3 spec
                warnings.filterwarnings("ignore", message="Consolidated metadata")
                template.to_zarr(tmp, mode="w-", compute=False, encoding=encoding)
            try:
                os.rename(tmp, path)
            except OSError as e:  # another process created the store meanwhile
                if not path.exists():
                    raise
                raise ParameterError(
                    "store",
                    str(path),
                    "a path that does not exist yet",
                    why=f"another process created it while this one did ({e.strerror})",
                ) from None
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
        return cls(path, sweep, zarr.open_group(path, mode="r+"))

    @classmethod
    def open(cls, path: str | Path, sweep: Sweep) -> SweepStore:
        """Open the store at ``path`` to resume ``sweep``; refuse anything else.

        Raises ParameterError naming ``store`` when the path is not a Zarr group, is not a
        sinktheory sweep, was made by a different sweep, or is damaged.
        """
        path = _checked_path(path)
        try:
            group = zarr.open_group(path, mode="r+", use_consolidated=False)
            attrs = dict(group.attrs)
        except Exception as e:  # noqa: BLE001 - any failure to read means "not a store"
            raise ParameterError(
                "store", str(path), "a sinktheory sweep store", why=f"not a Zarr group: {e}"
            ) from None
        spec = attrs.get("sweep_spec")
        if MARK not in attrs or not isinstance(spec, str):
            raise ParameterError(
                "store", str(path), "a sinktheory sweep store", why="it has no sweep fingerprint"
            )
        if hashlib.sha256(spec.encode()).hexdigest() != attrs[MARK]:
            raise ParameterError(
                "store", str(path), "an intact sweep store", why="its fingerprint does not match"
            )
        if attrs[MARK] != sweep.fingerprint:
            raise ParameterError(
                "store",
                str(path),
                "a store made by this same sweep (kind, grid, fixed parameters, seed)",
                why=_difference(json.loads(spec), json.loads(sweep.spec)),
            )
        try:
            store = cls(path, sweep, group)
            for name, array in store._arrays.items():
                expected = sweep.grid.shape if name == "done" else sweep.shape(name)
                if array.shape != expected:
                    raise ValueError(f"{name} has shape {array.shape}, expected {expected}")
                _read_all(array)  # every chunk decodes: no finished point is unreadable
        except ParameterError:  # locked by another process
            raise
        except Exception as e:  # noqa: BLE001 - a missing or unreadable array is damage
            raise ParameterError(
                "store", str(path), "an intact sweep store", why=f"damaged: {e}"
            ) from None
        for leftover in path.rglob("*.partial"):  # temporary chunk files of a killed write
            leftover.unlink(missing_ok=True)
        return store

    # --- reading and writing ------------------------------------------------------------
    def done(self) -> np.ndarray:
        """The ``done`` flags over the grid (bool array)."""
        return np.asarray(self._arrays["done"][...], dtype=bool)

    def write(self, indices: np.ndarray, results: dict[str, Any]) -> None:
        """Store the results of the points ``indices`` (flat, C order), then flag them done.

        ``results[name]`` has shape (len(indices), *result dimensions).
        """
        for name, value in results.items():
            _vset(self._arrays[name], *selection(self.sweep, indices, value))
        _vset(self._arrays["done"], *selection(self.sweep, indices, np.ones(len(indices), bool)))

    def dataset(self) -> xr.Dataset:
        """The stored results, opened lazily with ``xarray.open_zarr``."""
        return xr.open_zarr(self.path)

    def close(self) -> None:
        """Release the store's lock (the results stay readable with xarray)."""
        self._lock.close()


class MemoryStore:
    """The results of a sweep kept in memory; same interface as :class:`SweepStore`."""

    path = None

    def __init__(self, sweep: Sweep) -> None:
        self.sweep = sweep
        self.results = {
            name: np.full(sweep.shape(name), False if spec.dtype == "bool" else np.nan)
            for name, spec in sweep.kind.results.items()
        }
        self.flags = np.zeros(sweep.grid.shape, dtype=bool)

    def done(self) -> np.ndarray:
        return self.flags

    def write(self, indices: np.ndarray, results: dict[str, Any]) -> None:
        for name, value in results.items():
            where, value = selection(self.sweep, indices, value)
            self.results[name][where] = value
        where, value = selection(self.sweep, indices, np.ones(len(indices), bool))
        self.flags[where] = value

    def dataset(self) -> xr.Dataset:
        return self.sweep.dataset(self.results, self.flags)

    def close(self) -> None:
        """Nothing to release."""


def selection(sweep: Sweep, indices: np.ndarray, value: np.ndarray) -> tuple[tuple, np.ndarray]:
    """(where, value) to assign ``value`` (len(indices), *result dims) at points ``indices``:
    a coordinate selection, or () and the one value for a grid with no swept dimension."""
    if not sweep.grid.shape:
        return (), value[0]
    return coordinates(sweep, indices, value.shape[1:]), value


def _vset(array: zarr.Array, where: tuple, value: np.ndarray) -> None:
    if where:
        array.vindex[where] = value
    else:
        array[...] = value


def coordinates(sweep: Sweep, indices: np.ndarray, extra: tuple[int, ...]) -> tuple:
    """Coordinate selection of points ``indices`` (flat) over all their result values:
    one integer array per dimension, each of shape (len(indices), *extra).  Works for
    numpy fancy indexing and zarr's ``vindex`` alike.

    Examples
    --------
    >>> from sinktheory.sweep.plan import Sweep
    >>> s = Sweep.make("floquet", {"alpha": 0.5, "beta": [0.1, 0.2], "n": [2, 4, 6]})
    >>> [c.tolist() for c in coordinates(s, np.array([2, 3]), ())]
    [[0, 1], [2, 0]]
    """
    m = len(indices)
    lead = np.unravel_index(np.asarray(indices), sweep.grid.shape)
    trailing = (1,) * len(extra)
    out = [np.broadcast_to(i.reshape((m, *trailing)), (m, *extra)) for i in lead]
    out += [np.broadcast_to(j, (m, *extra)) for j in np.indices(extra)]
    return tuple(out)


def _read_all(array: zarr.Array) -> None:
    """Read ``array`` band by band along its first axis (a codec error if a chunk is bad)."""
    if not array.shape:
        array[...]
        return
    step = array.chunks[0]
    for start in range(0, array.shape[0], step):
        array[start : start + step]


def _lock(path: Path):
    """Hold an exclusive lock on ``path/LOCK`` while the store is open for writing.

    Two drivers writing one store could overwrite each other's chunks; the second is
    refused.  The operating system drops the lock when its process ends, kill -9 included.
    """
    try:
        handle = open(path / LOCK, "a")  # noqa: SIM115 - held open as long as the store
    except OSError as e:
        raise ParameterError(
            "store", str(path), "a store this process can write to", why=e.strerror or str(e)
        ) from None
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        handle.close()
        raise ParameterError(
            "store", str(path), "a store no other sweep is writing to", why="it is locked"
        ) from None
    return handle


def _checked_path(path: str | Path) -> Path:
    """The store's path, refused unless its directory exists and takes new files."""
    if isinstance(path, bool) or not isinstance(path, str | os.PathLike) or not str(path).strip():
        raise ParameterError("store", path, "a path (str or os.PathLike) of a Zarr store")
    path = Path(path)
    v.writable_directory("store", str(path), path.parent)
    if path.exists() and not path.is_dir():
        raise ParameterError("store", str(path), "a Zarr store (a directory)", why="it is a file")
    return path


def _chunks(sweep: Sweep, name: str) -> tuple[int, ...]:
    """Whole along the result dimensions; about :data:`CHUNK_VALUES` values per chunk,
    filled from the last swept dimension backwards (neighbouring points share a chunk,
    so writing a point rewrites at most some tens of kilobytes)."""
    shape = sweep.shape(name)
    ndim = len(sweep.grid.shape)
    return _fill(shape[:ndim], math.prod(shape[ndim:])) + shape[ndim:]


def _flag_chunks(sweep: Sweep) -> tuple[int, ...]:
    """Chunks of ``done``: about :data:`CHUNK_VALUES` flags each."""
    return _fill(sweep.grid.shape, 1)


def _fill(shape: tuple[int, ...], per_point: int) -> tuple[int, ...]:
    """Chunk sizes over ``shape`` holding about CHUNK_VALUES / per_point points."""
    budget = max(1, CHUNK_VALUES // max(1, per_point))
    chunks = []
    for size in reversed(shape):
        chunks.append(max(1, min(size, budget)))
        budget = max(1, budget // chunks[-1])
    return tuple(reversed(chunks))


def _empty_results(sweep: Sweep) -> dict[str, da.Array]:
    """Lazy fill values (NaN, or False for flags): creating the store writes no chunk."""
    out = {}
    for name, spec in sweep.kind.results.items():
        fill = False if spec.dtype == "bool" else np.nan
        out[name] = da.full(sweep.shape(name), fill, dtype=spec.dtype, chunks=_chunks(sweep, name))
    return out


def _swept(dims: list) -> str:
    """A short description of swept values: ``beta: 161 values in [-0.7, 0.45]``."""
    if not dims:
        return "nothing"
    parts = []
    for name, values in dims:
        if len(values) <= 4:
            parts.append(f"{name}: {values}")
        else:
            parts.append(f"{name}: {len(values)} values from {values[0]} to {values[-1]}")
    return "; ".join(parts)


def _difference(stored: dict, given: dict) -> str:
    """Say how the stored sweep differs from the one asked for."""
    parts = []
    for key in ("kind", "seed"):
        if stored.get(key) != given.get(key):
            parts.append(f"{key} {stored.get(key)!r} there, {given.get(key)!r} here")
    if stored.get("dims") != given.get("dims"):
        there, here = _swept(stored.get("dims", [])), _swept(given.get("dims", []))
        parts.append(f"swept {there} there, {here} here")
    a, b = stored.get("fixed", {}), given.get("fixed", {})
    for key in sorted(set(a) | set(b)):
        if a.get(key) != b.get(key):
            parts.append(f"{key} = {a.get(key)!r} there, {b.get(key)!r} here")
    return "the store was made by another sweep: " + "; ".join(parts)
