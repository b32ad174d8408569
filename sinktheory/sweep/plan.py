"""A checked sweep: kind, grid, seed, fingerprint, and the layout of its labelled results.

:meth:`Sweep.make` validates everything before any work starts: parameter names and
types, and every point of the grid with the model's own validators, so a bad value fails
at once with a :class:`~sinktheory.errors.ParameterError` naming the parameter.  A point's
work is checked against the resumable limit (:func:`sinktheory.worklimit.resumable`), and
the estimates of these checks add up to the sweep's (:attr:`Sweep.estimate`).

Examples
--------
>>> s = Sweep.make("floquet", {"alpha": 0.5, "beta": [-0.2, 0.1], "n": 10})
>>> s.grid.names, s.grid.size, s.dims
(('beta',), 2, {'beta': 2})
>>> Sweep.make("floquet", {"alpha": 0.5, "beta": [0.1, 0.5], "n": 10})  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: beta = 0.5 is not allowed: must be < alpha = 0.5 (...)
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr

from .. import __version__
from .. import validation as v
from ..errors import ParameterError
from ..progress import ProgressBar
from ..worklimit import resumable, tally
from .grid import Grid, fingerprint, point_seed
from .kinds import Kind, get_kind

__all__ = ["CHECK_DELAY", "MARK", "Sweep"]

#: Attribute that marks a store as a sinktheory sweep (its value: the fingerprint).
MARK = "sweep_fingerprint"
#: Seconds of checking the grid before :meth:`Sweep.make` shows its progress.
CHECK_DELAY = 1.0


@dataclass(frozen=True)
class Sweep:
    """A validated sweep.  ``spec`` is its canonical JSON, ``fingerprint`` its SHA-256."""

    kind: Kind
    grid: Grid
    seed: int
    spec: str
    fingerprint: str
    #: Estimated seconds of all points together: the sum of the estimates their work
    #: checks made (:func:`sinktheory.worklimit.tally`; optimistic, as the limit's), or of
    #: the kind's rough cost for a point that checks none (a floquet point).
    estimate: float = 0.0

    @classmethod
    def make(
        cls, kind: str, params: Mapping[str, Any], seed: int = 0, *, progress: bool = False
    ) -> Sweep:
        """Check ``params`` (name -> value or list of values) for ``kind`` at every point.

        With ``progress``, a check lasting over :data:`CHECK_DELAY` seconds shows the
        points checked on stderr (:class:`~sinktheory.progress.ProgressBar`): a user's
        well is checked at each point's parameter values, about 0.4 s a point."""
        k = get_kind(kind)
        if not isinstance(params, Mapping):
            raise ParameterError(
                "params", params, "a mapping of parameter names to values or lists of values"
            )
        seed = v.positive_int("seed", seed, minimum=0)
        grid = Grid.from_params(k.complete(params))
        estimates = []
        bar = ProgressBar(grid.size, enabled=progress, delay=CHECK_DELAY,
                          label="checking the grid ", unit="point")  # fmt: skip
        try:
            with resumable():  # points are stored and resumed one by one: the 30-day limit
                for index in range(grid.size):
                    point = grid.point(index)
                    with tally() as checked:
                        k.check(point)
                    estimates.append(math.fsum(checked) if checked else k.cost(point))
                    bar.update(1)
        finally:
            bar.close()
        _check_memory(k, grid)
        spec, digest = fingerprint(k.name, grid, seed)
        return cls(k, grid, seed, spec, digest, math.fsum(estimates))

    # --- points -------------------------------------------------------------------------
    def _task(self, index: int) -> tuple[int, dict, int]:
        """(index, parameters, point seed) of point ``index``: what a worker needs."""
        return index, self.grid.point(index), point_seed(self.seed, index)

    @property
    def fixed(self) -> dict[str, Any]:
        return dict(self.grid.fixed)

    # --- layout of the results ------------------------------------------------------------
    @property
    def extra_coords(self) -> dict[str, np.ndarray]:
        """Coordinates of the result dimensions after the swept ones (e.g. ``sample``)."""
        return self.kind.extra_coords(self.grid.point(0))

    @property
    def dims(self) -> dict[str, int]:
        """Sizes of the swept dimensions, in order."""
        return dict(zip(self.grid.names, self.grid.shape, strict=True))

    def shape(self, name: str) -> tuple[int, ...]:
        """Shape of result ``name`` over the whole grid."""
        extra = self.extra_coords
        results = self.kind.results
        if not isinstance(name, str) or name not in results:
            raise ParameterError(
                "name", name, f"a result of the {self.kind.name} sweep: {sorted(results)}"
            )
        return self.grid.shape + tuple(extra[d].size for d in results[name].dims)

    def coords(self) -> dict[str, np.ndarray]:
        swept = {name: _coordinate(values) for name, values in self.grid.dims}
        return {**swept, **self.extra_coords}

    def attrs(self) -> dict[str, Any]:
        """Fixed parameters (those not None), kind, seed, package version, fingerprint."""
        fixed = {name: value for name, value in self.grid.fixed if value is not None}
        return {
            **fixed,
            "sweep_kind": self.kind.name,
            "sweep_seed": self.seed,
            "sweep_spec": self.spec,
            MARK: self.fingerprint,
            "sinktheory_version": __version__,
        }

    def point_seeds(self) -> np.ndarray:
        """The seed of every point, shaped like the grid."""
        seeds = [point_seed(self.seed, i) for i in range(self.grid.size)]
        return np.array(seeds, dtype=np.uint64).reshape(self.grid.shape)

    def _dataset(self, results: Mapping[str, Any], done: np.ndarray) -> xr.Dataset:
        """The labelled results: ``results`` (name -> array over the grid) plus bookkeeping.

        ``done`` flags the points computed; ``point_seed`` holds each point's seed.
        """
        names = self.grid.names
        data = {
            name: (names + spec.dims, results[name], {"description": spec.description})
            for name, spec in self.kind.results.items()
        }
        data["done"] = (names, done, {"description": "point computed and stored"})
        data["point_seed"] = (names, self.point_seeds(), {"description": "seed of the point"})
        return xr.Dataset(data, coords=self.coords(), attrs=self.attrs())

    def describe(self) -> str:
        """One line: kind, swept dimensions and fixed parameters."""
        swept = ", ".join(f"{n} ({s})" for n, s in self.dims.items()) or "no swept parameter"
        fixed = self.fixed
        well = ""
        if "well" in fixed:  # a user's well: its name here, its text in the store
            from ..userwell import read_well

            well = f" in the well {read_well(fixed.pop('well')).name}"
        if "wells" in fixed:  # users' wells on the shape axis: their texts are in the store
            fixed["wells"] = f"{len(json.loads(fixed['wells']))} user's well(s), in the store"
        return f"{self.kind.name} sweep{well} over {swept}; fixed {json.dumps(fixed)}"


#: Parameters that set the length of a result dimension (their value + offset).
_DIM_LENGTH = {"sample": ("count", 0), "period": ("periods", 1)}


def _check_memory(kind: Kind, grid: Grid) -> None:
    """Refuse a sweep whose results would not fit in memory, before anything is allocated
    (the result dimensions' lengths are read off their parameters, not built)."""
    point = grid.point(0)
    per_point = 0
    longest = None
    for spec in kind.results.values():
        size = 1
        for dim in spec.dims:
            if dim in _DIM_LENGTH:
                name, offset = _DIM_LENGTH[dim]
                size *= point[name] + offset
                longest = name
            else:
                size *= len(kind.extra_coords(point)[dim])
        per_point += size
    name = longest or (grid.names[0] if grid.names else "params")
    value = point.get(name, f"{grid.size} points")
    v.fits_memory(
        name,
        value,
        8.0 * per_point * grid.size,
        f"{grid.size} point(s) x {per_point} value(s) per point",
        "smaller: the sweep's results must fit in memory",
    )


def _coordinate(values: tuple) -> np.ndarray:
    """Labels of a swept parameter; names become variable-length strings (Zarr v3 spec)."""
    if all(isinstance(x, str) for x in values):
        return np.array(values, dtype=object)
    return np.array(values)
