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
* every point gets a checksum (BLAKE2b-64 of its stored results, in the ``checksum``
  variable, written after the data and before the flag); resuming recomputes the
  checksum of every done point and flags the points that no longer match (a flipped
  bit, a deleted chunk read back as fill values) not done, so they are computed again;
  coordinates (swept values, result coordinates, ``point_seed``) are compared with the
  sweep's own and a difference refuses the store; a chunk that no longer decodes
  refuses it too, unless resumed with ``repair``, which removes that chunk and
  recomputes its points;
* two drivers creating one new store at once: the second rename fails and that driver
  is refused with a ParameterError (the store of the first stays whole);
* while a driver writes, it holds an exclusive lock (``flock``) on a file in the store, so
  a second driver is refused; the system drops the lock when the process dies.

This holds for a killed process (kill -9) on a local file system; it does not promise
durability across a power cut (no fsync) or on object stores.

Renamed parameters.  A store written before a sweep parameter was renamed
(:data:`sinktheory.glossary.RENAMED_PARAMETERS`: ``energy`` is now ``container_energy``,
``method`` is now ``scheme``) holds the old names in its description, attributes,
coordinates and dimensions, and so another fingerprint.  Opening it for the same sweep
under the new names tries the old spelling (:func:`old_spelling`) when the fingerprint
does not match, and resumes it as it is; its results read under the new names
(:func:`read`).  The store itself is not rewritten.

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

import contextlib
import dataclasses
import fcntl
import hashlib
import itertools
import json
import math
import os
import shutil
import uuid
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import dask.array as da
import numpy as np
import xarray as xr
import zarr

from .. import validation as v
from ..errors import ParameterError
from ..glossary import RENAMED_PARAMETERS
from .grid import Grid, fingerprint
from .plan import MARK, Sweep

__all__ = [
    "CHECKSUM",
    "CHECKSUM_ATTR",
    "CHUNK_VALUES",
    "LOCK",
    "read",
]

#: File in the store locked by the process writing to it.
LOCK = ".sweep.lock"
#: Variable holding each point's checksum: BLAKE2b (64 bits) of its stored results.
CHECKSUM = "checksum"
#: Root attribute recording that the store keeps checksums (a store with it that lost its
#: ``checksum`` array is damaged, not of the format before checksums).
CHECKSUM_ATTR = "sweep_checksums"
#: Target number of values in one chunk of a result array.
CHUNK_VALUES = 4096


class SweepStore:
    """An open sweep store (use :meth:`create` or :meth:`open`).  ``written`` is the sweep
    as the store spells it (:func:`old_spelling` for a store written under old parameter
    names; the sweep itself otherwise)."""

    def __init__(
        self, path: Path, sweep: Sweep, group: zarr.Group, written: Sweep | None = None
    ) -> None:
        self.path = path
        self.sweep = sweep
        #: current name -> the name the store holds it under (empty: the same names)
        self.stored_names = {} if written is None or written is sweep else _OLD_NAMES
        self.group = group
        self._lock = _lock(path)
        self._arrays = {name: group[name] for name in (*sweep.kind.results, "done")}
        #: per-point checksums (None: a store made before they were kept)
        self._checksum = group[CHECKSUM] if CHECKSUM in group else None
        #: points found damaged on opening and flagged not done (recomputed on resume)
        self.repaired = 0

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
            template = sweep._dataset(_empty_results(sweep), np.zeros(sweep.grid.shape, bool))
            template[CHECKSUM] = (
                sweep.grid.names,
                np.zeros(sweep.grid.shape, np.uint64),
                {"description": "BLAKE2b-64 of the point's stored results (0: none yet)"},
            )
            template.attrs[CHECKSUM_ATTR] = f"BLAKE2b-64 of each point's results in {CHECKSUM}"
            encoding = {name: {"chunks": _chunks(sweep, name)} for name in sweep.kind.results}
            encoding["done"] = {"chunks": _flag_chunks(sweep)}
            encoding[CHECKSUM] = {"chunks": _flag_chunks(sweep)}
            # consolidated metadata: not (yet) in the v3 spec
            with warnings.catch_warnings(), _naming(path):
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
    def open(cls, path: str | Path, sweep: Sweep, *, repair: bool = False) -> SweepStore:
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
        written = next(
            (s for s in (sweep, old_spelling(sweep)) if s.fingerprint == attrs[MARK]), None
        )
        if written is None:
            raise ParameterError(
                "store",
                str(path),
                "a store made by this same sweep (kind, grid, fixed parameters, seed)",
                why=_difference(json.loads(spec), json.loads(sweep.spec)),
            )
        _check_attributes(path, attrs, written)
        missing = [name for name in sweep.kind.results if name not in group]
        if missing:
            raise ParameterError(
                "store", str(path), "a store holding every result of its kind",
                why=f"it has no {', '.join(missing)}: written by a sinktheory "
                f"{attrs.get('sinktheory_version', '(unknown)')} that did not compute "
                f"{'it' if len(missing) == 1 else 'them'}, or damaged (start the sweep "
                "again in a new store; xarray.open_zarr still reads this one)",
            )  # fmt: skip
        if CHECKSUM_ATTR in attrs and CHECKSUM not in group:
            raise ParameterError(
                "store",
                str(path),
                "an intact sweep store",
                why=f"damaged: its {CHECKSUM} array is missing, so the stored points cannot "
                "be verified (start the sweep again in a new store)",
            )
        store = None
        try:
            store = cls(path, sweep, group, written)
            for name, array in store._arrays.items():
                expected = sweep.grid.shape if name == "done" else sweep.shape(name)
                if array.shape != expected:
                    raise ValueError(f"{name} has shape {array.shape}, expected {expected}")
            store._verify(repair)
            for array in store._arrays.values():
                _read_all(array)  # every chunk decodes: no finished point is unreadable
        except ParameterError:  # locked by another process, or damaged coordinates
            if store is not None:
                store.close()
            raise
        except Exception as e:  # noqa: BLE001 - a missing or unreadable array is damage
            if store is not None:
                store.close()
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

        ``results[name]`` has shape (len(indices), *result dimensions).  An I/O error
        (disk full, file too large) names the store.
        """
        with _naming(self.path):
            for name, value in results.items():
                _vset(self._arrays[name], *selection(self.sweep, indices, value))
            if self._checksum is not None:
                sums = _point_checksums(self.sweep, results)
                _vset(self._checksum, *selection(self.sweep, indices, sums))
            flags = np.ones(len(indices), bool)
            _vset(self._arrays["done"], *selection(self.sweep, indices, flags))

    # --- checks on resuming ---------------------------------------------------------------
    def _verify(self, repair: bool) -> None:
        """Check the coordinates against the sweep and every done point against its checksum.

        A coordinate that differs from the sweep's own (swept values, result coordinates,
        ``point_seed``) refuses the store: it cannot be recomputed point by point.  A done
        point whose stored results no longer match its checksum (a flipped bit, a deleted
        chunk read back as fill values) is flagged not done, so it is computed again.  A
        chunk that does not decode refuses the store, or with ``repair`` is removed and
        its points are flagged not done.
        """
        self._check_coordinates()
        reset = self._drop_undecodable() if repair else np.zeros(self.sweep.grid.shape, bool)
        if self._checksum is None:
            self.repaired += int(reset.sum())
            return
        names = list(self.sweep.kind.results)
        stored = {name: np.asarray(self._arrays[name][...]) for name in names}
        size = self.sweep.grid.size
        flat = {name: value.reshape(size, -1) for name, value in stored.items()}
        expected = _point_checksums(self.sweep, flat).reshape(self.sweep.grid.shape)
        done = self.done()
        sums = np.asarray(self._checksum[...])
        damaged = done & (sums != expected)
        if damaged.any():
            self._arrays["done"][...] = done & ~damaged
        # a point with a checksum but no flag lost its flag (a deleted or reset chunk of
        # ``done``), or its write was cut short between the two: computed again either way
        unflagged = ~done & (sums != 0)
        self.repaired += int(damaged.sum()) + int((unflagged | reset).sum())

    def _check_coordinates(self) -> None:
        expected = {**self.sweep.coords(), "point_seed": self.sweep.point_seeds()}
        for name, values in expected.items():
            try:
                stored = np.asarray(self.group[self.stored_names.get(name, name)][...])
                same = stored.shape == np.shape(values) and bool(
                    # via object: numpy refuses StringDType (zarr 3's strings) -> str
                    np.all(stored.astype(object).astype(str) == np.asarray(values).astype(str))
                    if stored.dtype.kind in "OUST"
                    else np.array_equal(stored, np.asarray(values))
                )
            except Exception as e:  # noqa: BLE001 - unreadable is damaged
                same, why = False, f": {e}"
            else:
                why = ""
            if not same:
                raise ParameterError(
                    "store",
                    str(self.path),
                    "an intact sweep store",
                    why=f"damaged: the coordinate {name} differs from the sweep's{why}",
                )

    def _drop_undecodable(self) -> np.ndarray:
        """Remove result or flag chunks that do not decode; flag their points not done
        (returned: the points of the removed chunks)."""
        ndim = len(self.sweep.grid.shape)
        reset = np.zeros(self.sweep.grid.shape, dtype=bool)
        arrays = {**self._arrays}
        if self._checksum is not None:
            arrays[CHECKSUM] = self._checksum
        for name, array in arrays.items():
            lead = zip(array.shape[:ndim], array.chunks[:ndim], strict=True)
            grid = [range(0, n, c) for n, c in lead]
            for start in itertools.product(*grid):
                region = tuple(
                    slice(i, i + c) for i, c in zip(start, array.chunks[:ndim], strict=True)
                )
                try:
                    array[region]
                except Exception:  # noqa: BLE001 - a codec error: this chunk is damaged
                    index = [i // c for i, c in zip(start, array.chunks[:ndim], strict=True)]
                    index += [0] * (len(array.shape) - ndim)
                    key = "/".join(["c", *map(str, index)]) if array.shape else "c"
                    (self.path / name / key).unlink(missing_ok=True)
                    reset[region] = True
        if reset.any():
            flags = self._arrays["done"]
            flags[...] = np.asarray(flags[...], dtype=bool) & ~reset
        return reset

    def dataset(self) -> xr.Dataset:
        """The stored results, opened lazily (:func:`read`)."""
        return read(self.path)

    def close(self) -> None:
        """Release the store's lock (the results stay readable with xarray)."""
        self._lock.close()


#: A renamed parameter's current name -> its old name.
_OLD_NAMES = {new: old for old, new in RENAMED_PARAMETERS.items()}


def old_spelling(sweep: Sweep) -> Sweep:
    """``sweep`` as a store written before its parameters were renamed spells it: the old
    names (:data:`sinktheory.glossary.RENAMED_PARAMETERS`) in its grid, description and
    fingerprint; the same points, seeds and results.

    Examples
    --------
    >>> s = Sweep.make("ensemble", {"alpha": 0.5, "beta": 0.3, "n": 4,
    ...                             "container_energy": [0.4, 0.5], "periods": 2, "runs": 2})
    >>> old = old_spelling(s)
    >>> old.grid.names, old.fixed["method"] == s.fixed["scheme"], old.fingerprint != s.fingerprint
    (('energy',), True, True)
    """
    grid = Grid(
        tuple((_OLD_NAMES.get(name, name), values) for name, values in sweep.grid.dims),
        tuple(sorted((_OLD_NAMES.get(name, name), value) for name, value in sweep.grid.fixed)),
    )
    spec, digest = fingerprint(sweep.kind.name, grid, sweep.seed)
    return dataclasses.replace(sweep, grid=grid, spec=spec, fingerprint=digest)


def read(path: str | Path) -> xr.Dataset:
    """The results of the sweep store at ``path``, opened lazily with ``xarray.open_zarr``,
    under the current parameter names: in a store written under old names
    (:data:`sinktheory.glossary.RENAMED_PARAMETERS`) the swept coordinates, dimensions
    and fixed-parameter attributes of an old name read under its new one.  A ``path`` that
    is no Zarr directory is refused naming ``path``."""
    allowed = "the path (str or os.PathLike) of a sweep store, a Zarr directory"
    if isinstance(path, bool) or not isinstance(path, str | os.PathLike) or not str(path).strip():
        raise ParameterError("path", path, allowed)
    if not Path(path).is_dir():
        why = "it is a file" if Path(path).exists() else "it does not exist"
        raise ParameterError("path", str(path), allowed, why=why)
    try:
        ds = xr.open_zarr(path)
    except (zarr.errors.BaseZarrError, ValueError, KeyError, OSError) as e:
        raise ParameterError(
            "path", str(path), allowed, why=" ".join(f"{type(e).__name__}: {e}".split())
        ) from None
    names = {old: new for old, new in RENAMED_PARAMETERS.items() if old in ds.variables or
             old in ds.dims}  # fmt: skip
    if names:
        ds = ds.rename(names)
    old = [name for name in RENAMED_PARAMETERS if name in ds.attrs]
    for name in old:
        ds.attrs[RENAMED_PARAMETERS[name]] = ds.attrs.pop(name)
    return ds


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
        return self.sweep._dataset(self.results, self.flags)

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


@contextlib.contextmanager
def _naming(path: Path) -> Iterator[None]:
    """Give an I/O error that names no file (zarr's writes raise them so) the store's
    path, so that "File too large" or "No space left on device" says where."""
    try:
        yield
    except OSError as e:
        if e.filename:
            raise
        raise OSError(e.errno, e.strerror or str(e), str(path)) from e


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


def _point_checksums(sweep: Sweep, results: dict[str, Any]) -> np.ndarray:
    """BLAKE2b-64 of each point's results as stored (``results[name]`` has one row per
    point); never 0, which marks a point not written."""
    names = list(sweep.kind.results)
    rows = [
        np.ascontiguousarray(
            np.asarray(results[name], dtype=sweep.kind.results[name].dtype).reshape(
                len(results[names[0]]), -1
            )
        )
        for name in names
    ]
    out = np.empty(len(rows[0]), dtype=np.uint64)
    for i in range(len(out)):
        h = hashlib.blake2b(digest_size=8)
        for row in rows:
            h.update(row[i].tobytes())
        out[i] = int.from_bytes(h.digest(), "little") or 1
    return out


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


def _check_attributes(path: Path, attrs: dict, sweep: Sweep) -> None:
    """Refuse a store whose root attributes differ from the sweep's own (an edited
    ``runs``, say: the fingerprint covers the description, not these copies of it).
    The package version may differ (a store resumed by a newer sinktheory)."""
    for key, value in sweep.attrs().items():
        if key == "sinktheory_version":
            continue
        if key not in attrs or json.dumps(attrs[key]) != json.dumps(value):
            raise ParameterError(
                "store",
                str(path),
                "an intact sweep store",
                why=f"damaged: its attribute {key} is {attrs.get(key, '(missing)')!r}, its "
                f"sweep's description says {value!r}",
            )


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
    """Say how the stored sweep differs from the one asked for (a store's old parameter
    names read as their new ones)."""
    new = RENAMED_PARAMETERS
    stored = {
        **stored,
        "dims": [[new.get(name, name), values] for name, values in stored.get("dims", [])],
        "fixed": {new.get(name, name): value for name, value in stored.get("fixed", {}).items()},
    }
    parts = []
    for key in ("kind", "seed"):
        if stored.get(key) != given.get(key):
            parts.append(f"{key} {stored.get(key)!r} there, {given.get(key)!r} here")
    if stored.get("dims") != given.get("dims"):
        there, here = _swept(stored.get("dims", [])), _swept(given.get("dims", []))
        parts.append(f"swept {there} there, {here} here")
    a, b = stored.get("fixed", {}), given.get("fixed", {})
    for key in sorted(set(a) | set(b)):
        if key == "well" and a.get(key) != b.get(key):  # well texts: the first line that differs
            parts.append(_well_difference(a.get(key), b.get(key)))
        elif a.get(key) != b.get(key):
            parts.append(f"{key} = {a.get(key)!r} there, {b.get(key)!r} here")
    return "the store was made by another sweep: " + "; ".join(parts)


def _well_difference(there: str | None, here: str | None) -> str:
    """How two wells' texts (:func:`sinktheory.userwell.well_text`) differ: the first line
    that differs, or that one side has no well.

    Examples
    --------
    >>> a, b = 'name = "a"\\npotential = "x**2 + y**2"', 'name = "a"\\npotential = "x**2"'
    >>> _well_difference(a, b)
    'the well differs: potential = "x**2 + y**2" there, potential = "x**2" here'
    """
    if there is None or here is None:
        return f"a user's well {'there' if here is None else 'here'} only"
    pairs = zip(there.splitlines() + [""], here.splitlines() + [""], strict=False)
    a, b = next((a, b) for a, b in pairs if a != b)
    return f"the well differs: {a or '(nothing)'} there, {b or '(nothing)'} here"
