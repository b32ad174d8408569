"""Parameter sweeps: parallel (local processes or Dask), resumable, labelled (xarray/Zarr).

A sweep is a grid of parameter points, each computed by a pure function of (parameters,
point seed).  The bifurcation diagrams, stability charts and ensemble studies are all such
sweeps over beta, n, k, runs and seeds:

* :mod:`~sinktheory.sweep.grid` -- grids, ``NAME=LO:HI:COUNT`` / ``NAME=V1,V2,...``
  parsing, per-point seeds from ``numpy.random.SeedSequence(seed, spawn_key=(i,))``;
* :mod:`~sinktheory.sweep.kinds` -- the point functions (floquet, bifurcation, ensemble);
* :mod:`~sinktheory.sweep.plan` -- a checked sweep and the layout of its results;
* :mod:`~sinktheory.sweep.store` -- the Zarr store, written point by point, resumable;
* :mod:`~sinktheory.sweep.runner` -- :func:`run_sweep`: in this process, on local
  processes, or on a Dask cluster;
* :mod:`~sinktheory.sweep.views` -- results back as the analyses' types
  (:func:`~sinktheory.sweep.views.bifurcation_diagram`).

The same sweep and seed give bitwise the same numbers however and wherever they run.

Examples
--------
In memory, here in this process (``workers=1``; by default all cores are used):

>>> from sinktheory.sweep import run_sweep
>>> ds = run_sweep("bifurcation", {"alpha": 0.5, "beta": [0.1, 0.3], "n": 4,
...                                "transient": 2, "count": 3}, workers=1, progress=False)
>>> dict(ds.section.sizes), ds.attrs["count"]
({'beta': 2, 'sample': 3}, 3)

Into a Zarr store, then resumed (nothing left to compute) and read back with xarray:

>>> import tempfile, pathlib, xarray as xr
>>> path = pathlib.Path(tempfile.mkdtemp()) / "chart.zarr"
>>> params = {"alpha": 0.5, "beta": [-0.2, 0.3], "n": [2, 10]}
>>> _ = run_sweep("floquet", params, store=path, workers=1, progress=False)
>>> again = run_sweep("floquet", params, store=path, resume=True, progress=False)
>>> chart = xr.open_zarr(path)
>>> chart.stable.sel(beta=-0.2, n=10).values.item(), bool(chart.done.all())
(True, True)

On a Dask cluster: ``run_sweep(..., scheduler="tcp://host:8786")`` (or set
``DASK_SCHEDULER_ADDRESS``).  From the shell::

    sinktheory sweep bifurcation --param alpha=0.5 --param beta=-0.7:0.45:161 \\
        --param n=10 --param count=150 --out fig3.zarr [--scheduler tcp://host:8786]
    # killed? the same command with --resume computes only the missing points
"""

from importlib import import_module

from .grid import Grid, parse_param, point_seed
from .kinds import KINDS, get_kind

#: Loaded on first use, so that importing the command line does not import xarray, zarr
#: and dask.
_LAZY = {
    "Sweep": "plan",
    "DamagedStoreWarning": "runner",
    "SweepPointError": "runner",
    "SweepRun": "runner",
    "execute": "runner",
    "run_sweep": "runner",
    "SweepStore": "store",
    "bifurcation_diagram": "views",
}


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "KINDS",
    "DamagedStoreWarning",
    "Grid",
    "Sweep",
    "SweepPointError",
    "SweepRun",
    "bifurcation_diagram",
    "execute",
    "get_kind",
    "parse_param",
    "point_seed",
    "run_sweep",
]
