"""Run (or resume) a design sweep and get the measures, the ranking and the report.

:func:`explore` is the Python side of ``sinktheory design``: a grid over shape, alpha,
beta, n, k (``particles``), m (``mass``), E0 (``container_energy``), the contact damping c0
(``damping``: inelastic wall contact, :mod:`sinktheory.damped`; 0 is the
conservative model) and the attachment (``"well"``, the default; ``"nes"`` and
``"impact"``, the 1-D absorbers, see :mod:`sinktheory.design.point`) -- each a value or a
list -- computed on the sweep layer
(:func:`sinktheory.sweep.runner.execute`: this process, local processes or a Dask
cluster; a Zarr store written point by point and resumable).

Examples
--------
>>> run = explore({"beta": 0.3, "n": 4, "particles": [1, 2], "runs": 2, "periods": 12,
...                "horizons": "6+12", "lyapunov_runs": 0, "bootstrap": 10},
...               workers=1, progress=False, estimate_first=False)
>>> run.computed, [r["particles"] for r in run.ranked][:2] in ([1, 2], [2, 1])
(2, True)
"""

from __future__ import annotations

import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .ranking import rank

__all__ = ["DesignRun", "explore", "plan"]


@dataclass(frozen=True)
class DesignRun:
    """A finished design sweep.

    Attributes
    ----------
    dataset : xarray.Dataset
        The results over the swept parameters (see :mod:`sinktheory.sweep.kinds`, kind
        ``design``).
    ranked : list of dict
        :func:`~sinktheory.design.ranking.rank` of the dataset (best first).
    store : Path or None
    computed, skipped : int
        Points computed by this call and points already done in the store.
    seconds : float
    where : str
    estimate : Estimate or None
        The calibrated estimate made before starting (None if not asked for).
    repaired : int
        Points found damaged in the store and computed again (part of ``computed``).
    """

    dataset: Any
    ranked: list
    store: Path | None
    computed: int
    skipped: int
    seconds: float
    where: str
    estimate: Any = None
    repaired: int = 0

    @classmethod
    def _of(cls, done, estimate=None, repaired: int = 0) -> DesignRun:
        """The design run of a finished :class:`~sinktheory.sweep.runner.SweepRun`, ranked.

        ``repaired``: damaged points :func:`todo_of` found before ``done`` ran; opening
        the store again counts them once more (their checksums stay), except where a
        removed checksum chunk took the checksums with it, hence the larger of the two.
        """
        return cls(
            done.dataset,
            rank(done.dataset),
            done.store,
            done.computed,
            done.skipped,
            done.seconds,
            done.where,
            estimate,
            max(repaired, done.repaired),
        )


def plan(params: Mapping[str, Any], seed: int = 0):
    """The checked design :class:`~sinktheory.sweep.plan.Sweep` (ParameterError if bad)."""
    from ..sweep.plan import Sweep

    return Sweep.make("design", params, seed)


def todo_of(
    sweep, store: str | Path | None, resume: bool, repair: bool = False
) -> tuple[np.ndarray, int]:
    """(indices of the points still to compute, points found damaged): all of them, and
    none damaged, unless resuming a store.  Opening the store checks it (see
    :meth:`sinktheory.sweep.store.SweepStore.open`; ``repair`` removes chunks that no
    longer decode) and flags damaged points not done, so they are among the indices."""
    if store is None or not resume or not Path(store).exists():
        return np.arange(sweep.grid.size), 0
    from ..sweep.store import SweepStore

    target = SweepStore.open(store, sweep, repair=repair)
    try:
        done = np.asarray(target.done()).reshape(-1)
    finally:
        target.close()
    return np.flatnonzero(~done), target.repaired


def explore(
    params: Mapping[str, Any],
    seed: int = 0,
    *,
    store: str | Path | None = None,
    scheduler: Any = None,
    workers: int | None = None,
    resume: bool = False,
    repair: bool = False,
    progress: bool = True,
    estimate_first: bool = True,
    report: str | Path | None = None,
    top: int = 10,
) -> DesignRun:
    """Explore a grid of absorber designs.

    Parameters
    ----------
    params : dict
        name -> value or list of values: the design parameters
        :data:`~sinktheory.design.ranking.DESIGN_PARAMS` and any setting of the
        ``design`` kind (runs, periods, horizons, tol, transient,
        sigmas, risk_level, rqa_eps, bootstrap, lyapunov_runs, lyapunov_periods, ...).
        beta and n are required.
    seed : int >= 0
        Sweep seed (point i gets ``SeedSequence(seed, spawn_key=(i,))``).
    store : path, optional
        Zarr store (None: in memory).
    scheduler, workers, resume, repair, progress
        As for :func:`sinktheory.sweep.run_sweep`.
    estimate_first : bool
        Calibrate and print the estimated time on stderr before starting.
    report : path, optional
        Directory to write the charts, the ranked table and ``report.md`` into.
    top : int
        Rows of the recommended designs in the report.

    Returns
    -------
    DesignRun
    """
    from .. import validation as v
    from ..errors import ParameterError
    from ..sweep.runner import execute

    for name, value in (("progress", progress), ("estimate_first", estimate_first)):
        v.flag(name, value)
    top = v.positive_int("top", top)
    if report is not None:  # refused before the work, not after it
        if not isinstance(report, str | Path) or not str(report).strip():
            raise ParameterError("report", report, "the path of a directory (a str or Path)")
        v.writable_directory("report", report, Path(report).parent)
    sweep = plan(params, seed)
    todo, repaired = todo_of(sweep, store, resume, repair)
    est = None
    if estimate_first:
        from .cost import estimate

        est = estimate(sweep, workers=workers, todo=todo)
        if est.points:
            print(est.describe(), file=sys.stderr, flush=True)
    done = execute(
        sweep,
        store=store,
        scheduler=scheduler,
        workers=workers,
        resume=resume,
        progress=progress,
        repair=repair,
    )
    run = DesignRun._of(done, est, repaired)
    ranked = run.ranked
    if run.repaired:
        import warnings

        from ..sweep.runner import DamagedStoreWarning

        warnings.warn(
            f"{run.repaired} damaged design(s) found in the store {run.store} and recomputed",
            DamagedStoreWarning,
            stacklevel=2,
        )
    if report is not None:
        from .report import write_report

        write_report(run.dataset, report, ranked=ranked, top=top, run=run)
    return run
