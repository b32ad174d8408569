"""One protocol for every result object: ``as_dict()`` and ``to_dataset()``.

A result is a frozen dataclass that inherits :class:`Result` and declares in ``DIMS`` the
dimension names of its array fields.  Then

* ``as_dict()`` gives plain JSON-ready types: lists for arrays, ``None`` for NaN and
  infinities (JSON has neither), ``[re, im]`` for complex numbers, decimal strings for
  mpmath numbers (as many digits as their mantissa holds), nested results as their own
  dicts;
* ``to_dataset()`` gives an :class:`xarray.Dataset` (xarray imported then): each field
  listed in ``DIMS`` is a variable over those named dimensions (a 1-D field named like its
  dimension, or mapped to one in ``COORDS``, is that dimension's coordinate), nested
  results add their variables with their field name as prefix, and the remaining fields
  are attributes (numbers and strings as they are, anything
  else as JSON text).

The command line prints ``as_dict()`` with ``--json``; the sweep kinds and the report read
results through the same two methods, so no caller builds these dicts by hand.

Examples
--------
>>> from dataclasses import dataclass
>>> import numpy as np
>>> @dataclass(frozen=True)
... class Curve(Result):
...     DIMS = {"t": ("t",), "y": ("t",)}
...     t: np.ndarray
...     y: np.ndarray
...     label: str
>>> c = Curve(np.arange(3.0), np.array([1.0, np.nan, np.inf]), "demo")
>>> c.as_dict()
{'t': [0.0, 1.0, 2.0], 'y': [1.0, None, None], 'label': 'demo'}
>>> ds = c.to_dataset()
>>> ds.y.dims, ds.attrs["label"]
(('t',), 'demo')
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import fields, is_dataclass
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

__all__ = ["Result"]


def plain(x: Any) -> Any:
    """``x`` as plain JSON-ready Python (see the module docstring for the rules).

    Examples
    --------
    >>> import mpmath
    >>> plain({"a": np.array([1, 2]), "b": complex(1, -2), "c": np.float64("nan"),
    ...        "d": mpmath.mpf("0.1"), "e": (True, None)})
    {'a': [1, 2], 'b': [1.0, -2.0], 'c': None, 'd': '0.10000000000000001', 'e': [True, None]}
    """
    if isinstance(x, np.generic):
        return plain(x.item())
    if x is None or isinstance(x, bool | str | int):
        return x
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    if isinstance(x, complex):
        return [plain(x.real), plain(x.imag)]
    if isinstance(x, np.ndarray):
        return plain(x.tolist())
    if isinstance(x, Result):
        return x.as_dict()
    if isinstance(x, Mapping):
        return {str(k): plain(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [plain(v) for v in x]
    if is_dataclass(x) and not isinstance(x, type):
        return {f.name: plain(getattr(x, f.name)) for f in fields(x)}
    if isinstance(x, Path):
        return str(x)
    if type(x).__module__.startswith("mpmath") and hasattr(x, "_mpf_"):
        import mpmath
        from mpmath.libmp import repr_dps

        return mpmath.nstr(x, repr_dps(max(x._mpf_[3], 53)))  # the digits its bits hold
    raise TypeError(f"{type(x).__name__} has no plain JSON form")


def attribute(x: Any) -> Any:
    """``x`` as a dataset attribute: numbers and strings as they are (bools as 0/1, which
    every store format accepts), anything else as its JSON text."""
    if isinstance(x, bool | np.bool_):
        return int(x)
    if isinstance(x, str | int | float | np.integer | np.floating):
        return x.item() if isinstance(x, np.generic) else x
    return json.dumps(plain(x), allow_nan=False)


class Result:
    """Mixin of the result protocol for frozen dataclasses (see the module docstring)."""

    #: Array field (or name from :meth:`items`) -> its dimension names.
    DIMS: ClassVar[Mapping[str, tuple[str, ...]]] = {}
    #: 1-D field -> the dimension it labels (its coordinate in the dataset).
    COORDS: ClassVar[Mapping[str, str]] = {}

    def items(self) -> dict[str, Any]:
        """Name -> value of what the result holds: its dataclass fields, in order.
        A result with derived quantities worth keeping (ensemble means, ...) adds them."""
        return {f.name: getattr(self, f.name) for f in fields(self)}

    def coords(self) -> dict[str, Any]:
        """Labels of dimensions that are not fields (e.g. the names of the state rows)."""
        return {}

    def as_dict(self) -> dict[str, Any]:
        """Everything the result holds as plain JSON-ready Python."""
        return {name: plain(value) for name, value in self.items().items()}

    def to_dataset(self):
        """The result as an :class:`xarray.Dataset` with named dimensions and coordinates."""
        import xarray as xr

        data, coords, attrs = {}, dict(self.coords()), {}
        for name, value in self.items().items():
            if value is None:
                continue
            dims = self.DIMS.get(name)
            if name in self.COORDS:
                coords[self.COORDS[name]] = np.asarray(value)
            elif isinstance(value, Result):
                nested = value.to_dataset()
                for key, var in nested.data_vars.items():
                    data[f"{name}_{key}"] = var
                coords.update(nested.coords)
                attrs.update({f"{name}_{k}": v for k, v in nested.attrs.items()})
            elif dims is None:
                attrs[name] = attribute(value)
            elif dims == (name,):
                coords[name] = np.asarray(value)
            else:
                data[name] = (dims, np.asarray(value))
        return xr.Dataset(data, coords=coords, attrs=attrs)
