"""Ranking designs: speed, depth and reliability, Pareto layers, a table of recommendations.

Three objectives per design (all from the ``design`` sweep's results):

* **speed** -- the settling time t50 (periods): the first period from which <E> stays
  below 50 % of E0 for the settling window (``passage`` at level 0.5, see
  :func:`sinktheory.design.measures.sustained_crossing`; an early dip that comes back
  does not count);
* **depth** -- the long-time fraction of E0 absorbed, 1 - <E>_long / E0 (``depth``);
* **reliability** -- the run-to-run spread of the long-time means relative to E0
  (``spread / energy``); smaller is more reliable.

A design whose <E> never settles below 50 % of E0 within the run has no t50:
it counts as the slowest of all, *whatever* its depth and spread -- every design that
reaches 50 % dominates it (constrained domination: reaching the level is a feasibility
condition, not one more coordinate a design can trade against reliability; a design that
absorbs little is also very "reliable", and would otherwise sit on the front for that
alone).  Among themselves, designs that reach the level, and designs that do not, are
compared as usual: one dominates another if it is no worse in all three objectives (two
for those that never reach it) and better in one.  The Pareto layers are found by
repeatedly peeling off the non-dominated designs (layer 1 is the Pareto front), so every
design that never reaches 50 % is in a deeper layer than every design that does.  The
ranked table orders designs by layer, then by depth (deepest first), then by speed; the
first rows are the recommended designs.

Examples
--------
>>> import numpy as np
>>> speed = np.array([10.0, 20.0, 5.0, np.nan])
>>> depth = np.array([0.6, 0.7, 0.5, 0.1])
>>> spread = np.array([0.02, 0.02, 0.03, 0.01])   # the last: the most reliable, never 50 %
>>> pareto_layers(speed, depth, spread).tolist()
[1, 1, 1, 2]
>>> pareto_layers(speed, np.array([0.6, 0.5, 0.5, 0.1]), spread).tolist()  # 0 beats 1
[1, 2, 1, 3]
"""

from __future__ import annotations

import math

import numpy as np

from .. import validation as v
from ..errors import ParameterError

__all__ = ["DESIGN_PARAMS", "pareto_front", "pareto_layers", "rank"]

#: The design parameters a user sweeps (any other parameter of the kind may be given too).
DESIGN_PARAMS = (
    "shape",
    "alpha",
    "beta",
    "n",
    "particles",
    "mass",
    "container_energy",
    "damping",
    "attachment",
    "damping_kind",
)


def pareto_layers(speed, depth, spread) -> np.ndarray:
    """Pareto layer (1 = front) of each design: minimise speed and spread, maximise depth.

    A non-finite speed (never reached) is infeasible: dominated by every finite one (see
    the module docstring).  A non-finite depth or spread counts as the worst value of its
    objective.
    """
    speed, depth, spread = (
        v.real_array(name, x, "a 1-d array of real numbers, one per design")
        for name, x in (("speed", speed), ("depth", depth), ("spread", spread))
    )
    for name, x in (("speed", speed), ("depth", depth), ("spread", spread)):
        if x.ndim != 1 or x.shape != speed.shape:
            raise ParameterError(name, f"an array of shape {x.shape}", f"{speed.size} values")
    reached = np.isfinite(speed)
    s = np.where(reached, speed, np.inf)
    d = np.where(np.isfinite(depth), depth, -np.inf)
    r = np.where(np.isfinite(spread), spread, np.inf)
    costs = np.stack([s, -d, r], axis=1)  # all minimised
    layer = np.zeros(len(s), dtype=int)
    current = 1
    # the designs that reach the level first, then those that never do, below all of them
    for group in (np.flatnonzero(reached), np.flatnonzero(~reached)):
        left = group
        while left.size:
            c = costs[left]
            no_worse = (c[:, None, :] <= c[None, :, :]).all(axis=2)  # [i, j]: i no worse than j
            better = (c[:, None, :] < c[None, :, :]).any(axis=2)
            dominated = (no_worse & better).any(axis=0)
            layer[left[~dominated]] = current
            left = left[dominated]
            current += 1
    return layer


def pareto_front(speed, depth, spread) -> np.ndarray:
    """Boolean mask of the non-dominated designs (layer 1)."""
    return pareto_layers(speed, depth, spread) == 1


def design_dataset(ds, name: str = "ds"):
    """``ds`` if it is the dataset of a design sweep (an ``xarray.Dataset`` with the
    ``design`` kind's results and ``done``), else ParameterError naming ``name``."""
    import xarray as xr

    if not isinstance(ds, xr.Dataset) or not {"done", "depth", "passage"} <= set(ds.data_vars):
        allowed = "the xarray.Dataset of a design sweep (explore(...).dataset, or its store)"
        raise ParameterError(name, type(ds).__name__, allowed)
    return ds


def design_table(ds) -> list[dict]:
    """One row per computed design point: its parameters and measures (plain floats).

    ``ds`` is the dataset of a design sweep (:func:`sinktheory.design.explorer.explore`
    or ``xarray.open_zarr`` of its store).  Points not done are left out.
    ``lambda1_split`` is the point's Lyapunov runs split into regular and chaotic ones (a
    :class:`~sinktheory.chaos.verdicts.Split`), None without Lyapunov runs or in a store
    written before the split was kept.
    """
    from ..chaos.verdicts import SPLIT_RESULTS, stored_splits

    ds = design_dataset(ds).load()
    dims = [d for d in ds.done.dims]
    fixed = {k: ds.attrs[k] for k in DESIGN_PARAMS if k in ds.attrs}
    splits = [None] * ds.done.size  # a store written before the split was kept
    if "regular_runs" in ds:
        splits = stored_splits(ds.transpose(*dims, ...))
    rows = []
    for flat, index in enumerate(np.ndindex(*ds.done.shape)):
        where = dict(zip(dims, index, strict=True))
        point = ds.isel(where)
        if not bool(point.done):
            continue
        row = {**fixed, **{d: _plain(point[d].values) for d in dims}}
        row["lambda1_split"] = splits[flat]
        e0 = float(row["container_energy"])
        for name in (
            "depth",
            "depth_se",
            "long_time_mean",
            "long_time_se",
            "equipartition",
            "equipartition_z",
            "verdict",
            "spread",
            "spread_se",
            "excursion",
            "excursion_se",
            "lambda1",
            "lambda1_se",
            "rqa_recurrence_rate",
            "rqa_determinism",
            "rqa_determinism_se",
            "max_relative_energy_error",
        ):
            row[name] = float(point[name])
        for name in SPLIT_RESULTS:  # stores written before the split was kept: NaN
            row[name] = float(point[name]) if name in point else math.nan
        for name in ("zeta_eq", "zeta_eq_se", "dissipated", "dissipated_se", "dashpot"):
            # stores written before the contact damping was a parameter: conservative
            row[name] = float(point[name]) if name in point else 0.0
        row.setdefault("damping", 0.0)
        row["rel_spread"] = row["spread"] / e0
        row["rel_spread_se"] = row["spread_se"] / e0
        for level in point.level.values:
            lv = float(level)
            row[("passage", lv)] = float(point.passage.sel(level=level))
            row[("passage_se", lv)] = float(point.passage_se.sel(level=level))
            row[("passage_reach", lv)] = float(point.passage_reach.sel(level=level))
        for h in point.horizon.values:
            row[("absorbed", int(h))] = float(point.absorbed.sel(horizon=h))
            row[("absorbed_se", int(h))] = float(point.absorbed_se.sel(horizon=h))
        rows.append(row)
    return rows


def rank(ds) -> list[dict]:
    """The designs of a sweep, best first, each with ``layer`` (Pareto layer) and ``rank``.

    Ordered by Pareto layer of (speed, depth, spread/E0), then depth (deepest first), then
    speed (fastest first).
    """
    rows = design_table(ds)
    if not rows:
        return []
    speed = np.array([r[("passage", 0.5)] for r in rows])
    depth = np.array([r["depth"] for r in rows])
    spread = np.array([r["rel_spread"] for r in rows])
    layers = pareto_layers(speed, depth, spread)
    for r, layer in zip(rows, layers, strict=True):
        r["layer"] = int(layer)
    rows.sort(key=lambda r: (r["layer"], -_num(r["depth"], -math.inf), _num(r[("passage", 0.5)])))
    for i, r in enumerate(rows, 1):
        r["rank"] = i
    return rows


def _num(x: float, bad: float = math.inf) -> float:
    return x if math.isfinite(x) else bad


def _plain(x):
    x = np.asarray(x).item()
    return x
