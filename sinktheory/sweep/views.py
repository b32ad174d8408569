"""Sweep results back as the analyses' own types, so plotting code can stay as it is;
and the lambda_1 runs of chaos and ergodicity sweeps split into regular and chaotic ones.

Examples
--------
>>> from sinktheory.sweep import run_sweep
>>> ds = run_sweep("bifurcation", {"alpha": 0.5, "beta": [0.1, 0.3], "n": 4,
...                                "transient": 2, "count": 3}, workers=1, progress=False)
>>> d = bifurcation_diagram(ds)
>>> d.beta.tolist(), d.section.shape, d.n
([0.1, 0.3], (2, 3), 4)
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..bifurcation import BifurcationDiagram, WellBifurcation
from ..errors import ParameterError

__all__ = ["bifurcation_diagram", "split_points"]


def bifurcation_diagram(dataset: xr.Dataset) -> BifurcationDiagram | WellBifurcation:
    """The :class:`~sinktheory.bifurcation.BifurcationDiagram` of a bifurcation sweep over
    beta alone (every other parameter fixed, every point done); of a sweep of a user's
    well over one of its own parameters, the
    :class:`~sinktheory.bifurcation.WellBifurcation`."""
    _check_dataset(dataset)
    attrs = dataset.attrs
    if "well" in attrs:
        return _well_diagram(dataset)
    if attrs.get("sweep_kind") != "bifurcation" or dataset.section.dims != ("beta", "sample"):
        raise ParameterError(
            "dataset", attrs.get("sweep_kind"), "a bifurcation sweep over beta alone"
        )
    _check_done(dataset)
    return BifurcationDiagram(
        np.asarray(dataset.beta.values, dtype=float),
        np.asarray(dataset.section.values),
        attrs["quantity"],
        attrs["alpha"],
        attrs["n"],
        attrs["gamma"],
        attrs["shape"],
        attrs["mass"],
        attrs["container_energy"],
        attrs["transient"],
        attrs["count"],
    )


def _well_diagram(dataset: xr.Dataset) -> WellBifurcation:
    """:func:`bifurcation_diagram` of a bifurcation sweep of a user's well."""
    from ..userwell import read_well

    attrs = dataset.attrs
    well = read_well(attrs["well"])
    dims = dataset.section.dims
    if (
        attrs.get("sweep_kind") != "bifurcation"
        or len(dims) != 2
        or dims[0] not in (well.parameter_names)
    ):
        raise ParameterError("dataset", attrs.get("sweep_kind"), "a bifurcation sweep over "
                             "one parameter of its well alone")  # fmt: skip
    _check_done(dataset)
    parameter = dims[0]
    fixed = {k: attrs[k] for k in well.parameter_names if k != parameter}
    return WellBifurcation(
        well.name, parameter, np.asarray(dataset[parameter].values, dtype=float),
        np.asarray(dataset.section.values), fixed, attrs["quantity"], attrs["mass"],
        attrs["container_energy"], attrs["transient"], attrs["count"],
    )  # fmt: skip


def _check_dataset(dataset: object) -> None:
    """Refuse a ``dataset`` that is no xarray Dataset (what ``run_sweep`` returns and
    :func:`sinktheory.sweep.store.read` reads)."""
    if not isinstance(dataset, xr.Dataset):
        shown = dataset if isinstance(dataset, str | int | float | None) else type(dataset).__name__
        raise ParameterError("dataset", shown, "the xarray Dataset of a sweep")


def _check_done(dataset: xr.Dataset) -> None:
    if not bool(dataset.done.all()):
        missing = int((~dataset.done).sum())
        raise ParameterError("dataset", f"{missing} point(s) not done", "a finished sweep")


def split_points(dataset: xr.Dataset) -> list[tuple[dict, object]]:
    """Every point of a finished ``chaos``, ``ergodicity`` or ``design`` sweep with its
    lambda_1 runs split into regular and chaotic ones (a
    :class:`~sinktheory.chaos.verdicts.Split`; a run is regular when its lambda_1 <=
    3 ln t / t), as (swept coordinates, split) in C order; [] for other kinds, for
    points without Lyapunov runs and for design stores written before the split was kept.

    A chaos point is split from its stored per-run exponents
    (:func:`~sinktheory.chaos.verdicts.map_split`); an ergodicity or design point from
    the counts and group means it stores
    (:func:`~sinktheory.chaos.verdicts.stored_split`: no gap).
    """
    from ..chaos.verdicts import map_split, stored_splits

    _check_dataset(dataset)
    kind = dataset.attrs.get("sweep_kind")
    if kind == "chaos":
        splits = map_split(dataset)
    elif kind in ("ergodicity", "design") and "regular_runs" in dataset:
        splits = stored_splits(dataset)
    else:
        return []
    dims = dataset.lambda1.dims
    out = []
    for index, s in zip(np.ndindex(dataset.lambda1.shape), splits, strict=True):
        if s is not None:
            where = {d: dataset[d].values[i].item() for d, i in zip(dims, index, strict=True)}
            out.append((where, s))
    return out
