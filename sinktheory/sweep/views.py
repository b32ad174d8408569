"""Sweep results back as the analyses' own types, so plotting code can stay as it is.

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

from ..bifurcation import BifurcationDiagram
from ..errors import ParameterError

__all__ = ["bifurcation_diagram"]


def bifurcation_diagram(dataset: xr.Dataset) -> BifurcationDiagram:
    """The :class:`~sinktheory.bifurcation.BifurcationDiagram` of a bifurcation sweep over
    beta alone (every other parameter fixed, every point done)."""
    attrs = dataset.attrs
    if attrs.get("sweep_kind") != "bifurcation" or dataset.section.dims != ("beta", "sample"):
        raise ParameterError(
            "dataset", attrs.get("sweep_kind"), "a bifurcation sweep over beta alone"
        )
    if not bool(dataset.done.all()):
        missing = int((~dataset.done).sum())
        raise ParameterError("dataset", f"{missing} point(s) not done", "a finished sweep")
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
