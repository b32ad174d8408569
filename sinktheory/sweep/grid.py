"""Parameter grids: parsing ``NAME=LO:HI:COUNT`` / ``NAME=V1,V2,...``, points and seeds.

A sweep is the Cartesian product of its swept parameters (each a list of two or more
distinct values) with every other parameter held fixed.  Points are numbered in C order
over the swept parameters, in the order they were given; point ``i`` of a sweep with seed
``s`` gets its own seed from ``numpy.random.SeedSequence(s, spawn_key=(i,))`` (the same as
``SeedSequence(s).spawn(i + 1)[i]``), so a point's numbers never depend on which worker
computed it, or when.

Examples
--------
>>> parse_param("beta=-0.5:0.5:3")
('beta', [-0.5, 0.0, 0.5])
>>> parse_param("n=2,10")
('n', [2, 10])
>>> parse_param("shape=symmetric")
('shape', ['symmetric'])
>>> parse_param("beta=1:0:3")
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: beta = '1:0:3' is not allowed: must be LO:HI:COUNT with LO <= HI
>>> point_seed(0, 3) == point_seed(0, 3) != point_seed(0, 4)
True
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..limits import MAX_SWEEP_POINTS as MAX_POINTS

__all__ = [
    "Grid",
    "MAX_POINTS",
    "parse_param",
    "parse_range",
    "point_seed",
    "Value",
]

Value = int | float | str


def parse_value(text: str) -> Value:
    """An int literal, else a float literal, else the text itself (a name such as ``flat``)."""
    text = text.strip()
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    return text


def parse_range(name: str, text: str) -> list[int | float]:
    """``LO:HI:COUNT`` -> COUNT evenly spaced values from LO to HI (both included).

    The values are ints when LO and HI are int literals and every value is a whole number
    (``n=2:10:5`` gives 2, 4, 6, 8, 10).  COUNT = 1 needs LO = HI.  A value within 1e-12
    of the range's size from zero is zero.

    Examples
    --------
    >>> parse_range("beta", "-0.4:0.2:4")[2]  # not 5.55e-17
    0.0
    """
    allowed = "LO:HI:COUNT with finite numbers LO <= HI and an integer COUNT >= 1"
    if not isinstance(text, str):
        raise ParameterError(name, text, allowed)
    parts = text.split(":")
    if len(parts) != 3:
        raise ParameterError(name, text, allowed)
    lo, hi, count = (parse_value(p) for p in parts)
    if isinstance(lo, str) or isinstance(hi, str) or not (math.isfinite(lo) and math.isfinite(hi)):
        raise ParameterError(name, text, allowed)
    if not isinstance(count, int) or count < 1:
        raise ParameterError(name, text, "LO:HI:COUNT with an integer COUNT >= 1")
    if count > MAX_POINTS:
        raise ParameterError(
            name,
            text,
            f"LO:HI:COUNT with COUNT <= {MAX_POINTS}",
            why=f"{count:.3g} values alone would take {v.nbytes_text(8.0 * count)}, and each "
            "point is checked before the sweep starts",
        )
    if lo > hi:
        raise ParameterError(name, text, "LO:HI:COUNT with LO <= HI")
    if count == 1 and lo != hi:
        raise ParameterError(name, text, "LO:HI:COUNT with COUNT >= 2 when LO < HI")
    values = np.linspace(lo, hi, count)
    # lo + i step misses zero by a rounding (-0.4:0.2:4 gave 5.55e-17): zero it is
    values[np.abs(values) < 1e-12 * max(abs(lo), abs(hi))] = 0.0
    if isinstance(lo, int) and isinstance(hi, int) and np.all(values == np.round(values)):
        return [int(x) for x in np.round(values)]
    return [float(x) for x in values]


def parse_param(text: str) -> tuple[str, list[Value]]:
    """Parse one ``--param``: ``NAME=LO:HI:COUNT``, ``NAME=V1,V2,...`` or ``NAME=V``.

    Returns the name and the list of its values (one value: the parameter is fixed).
    Whether the name and values suit the sweep's kind is checked later
    (:func:`sinktheory.sweep.kinds.get_kind`).
    """
    if not isinstance(text, str):
        raise ParameterError("param", text, "NAME=LO:HI:COUNT, NAME=V1,V2,... or NAME=VALUE")
    name, sep, rhs = text.partition("=")
    name = name.strip()
    if not sep or not name or not rhs.strip():
        raise ParameterError("param", text, "NAME=LO:HI:COUNT, NAME=V1,V2,... or NAME=VALUE")
    if ":" in rhs:
        return name, parse_range(name, rhs.strip())
    items = rhs.split(",")
    if any(not item.strip() for item in items):
        raise ParameterError(name, rhs, "a comma-separated list of values with none empty")
    return name, [parse_value(item) for item in items]


def point_seed(seed: int, index: int) -> int:
    """The seed of point ``index`` of a sweep seeded with ``seed`` (a 64-bit integer)."""
    seed = v.positive_int("seed", seed, minimum=0)
    index = v.positive_int("index", index, minimum=0)
    sequence = np.random.SeedSequence(seed, spawn_key=(index,))
    return int(sequence.generate_state(1, np.uint64)[0])


@dataclass(frozen=True)
class Grid:
    """The points of a sweep: swept parameters (``dims``) x fixed ones, in C order.

    Build it with :meth:`from_params`.  ``dims`` is a tuple of (name, values) in the
    order given; ``fixed`` maps every other parameter to its value.
    """

    dims: tuple[tuple[str, tuple[Value, ...]], ...]
    fixed: tuple[tuple[str, Any], ...]

    @classmethod
    def from_params(cls, params: Mapping[str, Any]) -> Grid:
        """Split ``params`` (name -> value or list of values) into swept and fixed ones.

        A list with one element is a fixed value; a list of two or more is swept and must
        hold distinct values (they become the labels of a coordinate).

        Examples
        --------
        >>> g = Grid.from_params({"beta": [0.1, 0.2, 0.3], "n": [2, 10], "alpha": 0.5})
        >>> g.shape, g.size, g.point(4)
        ((3, 2), 6, {'alpha': 0.5, 'beta': 0.3, 'n': 2})
        """
        if not isinstance(params, Mapping):
            raise ParameterError("params", params, "a mapping of parameter names to values")
        dims, fixed = [], {}
        for name, value in params.items():
            if isinstance(value, list | tuple | np.ndarray):
                values = [_plain(x) for x in np.asarray(value, dtype=object).ravel()]
                if not values:
                    raise ParameterError(name, value, "a value or a non-empty list of values")
                if len(values) == 1:
                    fixed[name] = values[0]
                    continue
                if len(set(values)) != len(values):
                    raise ParameterError(name, value, "a list of distinct values")
                dims.append((name, tuple(values)))
            else:
                fixed[name] = _plain(value)
        size = math.prod(len(values) for _, values in dims)
        if size > MAX_POINTS:
            name, values = max(dims, key=lambda d: len(d[1]))
            raise ParameterError(
                name,
                f"{len(values)} values",
                f"fewer values: the grid may have at most {MAX_POINTS} points",
                why=f"the swept parameters give {size} points",
            )
        return cls(tuple(dims), tuple(sorted(fixed.items())))

    @property
    def names(self) -> tuple[str, ...]:
        """Names of the swept parameters (the dimensions of the results)."""
        return tuple(name for name, _ in self.dims)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(values) for _, values in self.dims)

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    def point(self, index: int) -> dict[str, Any]:
        """All parameters of point ``index`` (C order over the swept parameters)."""
        index = v.positive_int("index", index, minimum=0, maximum=self.size - 1)
        where = np.unravel_index(index, self.shape) if self.dims else ()
        values = {name: vals[i] for (name, vals), i in zip(self.dims, where, strict=True)}
        return dict(sorted({**dict(self.fixed), **values}.items()))


def fingerprint(kind: str, grid: Grid, seed: int) -> tuple[str, str]:
    """(canonical JSON, its SHA-256) of a sweep: kind, swept values, fixed values, seed."""
    seed = v.positive_int("seed", seed, minimum=0)
    spec = {
        "kind": kind,
        "dims": [[name, list(values)] for name, values in grid.dims],
        "fixed": dict(grid.fixed),
        "seed": seed,
    }
    text = json.dumps(spec, sort_keys=True, allow_nan=False)
    return text, hashlib.sha256(text.encode()).hexdigest()


def _plain(x: Any) -> Any:
    """numpy scalars -> Python scalars, so points pickle and print plainly."""
    return x.item() if isinstance(x, np.generic) else x
