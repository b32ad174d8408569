"""Statistics over independent runs: one place for the mean, its standard error and the
rule for a single run.

Runs of an ensemble are independent (each has its own seeded start), so the standard
error of a mean over R runs is the sample standard deviation (ddof = 1) over sqrt(R).
With a single run the spread is unknown: the standard error is returned as zeros, and a
caller that must tell "no spread" from "unknown spread" checks the number of runs.

Examples
--------
>>> m, se = ensemble_mean([[1.0, 2.0], [3.0, 6.0]])
>>> m.tolist(), se.tolist()
([2.0, 4.0], [1.0, 2.0])
"""

from __future__ import annotations

import numpy as np

from .errors import ParameterError

__all__ = ["as_runs", "ensemble_mean"]


def as_runs(energy_runs) -> np.ndarray:
    """``energy_runs`` as a finite (R, N) float array (a 1-D series is one run).

    Examples
    --------
    >>> as_runs([1.0, 2.0]).shape
    (1, 2)
    """
    e = np.asarray(energy_runs, dtype=float)
    if e.ndim == 1:
        e = e[None, :]
    if e.ndim != 2 or e.shape[1] < 1:
        raise ParameterError("energy_runs", f"array of shape {e.shape}", "shape (runs, samples)")
    if not np.all(np.isfinite(e)):
        raise ParameterError("energy_runs", "an array with NaN or inf", "finite values")
    return e


def ensemble_mean(energy_runs) -> tuple[np.ndarray, np.ndarray]:
    """Mean over runs (axis 0 of an (R, N) array) and its standard error.

    The standard error is the sample std (ddof = 1) over sqrt(R); for a single run it is
    returned as zeros (module docstring).

    Examples
    --------
    >>> m, se = ensemble_mean([[1.0, 2.0]])
    >>> m.tolist(), se.tolist()
    ([1.0, 2.0], [0.0, 0.0])
    """
    e = as_runs(energy_runs)
    mean = e.mean(axis=0)
    if e.shape[0] == 1:
        return mean, np.zeros_like(mean)
    return mean, e.std(axis=0, ddof=1) / np.sqrt(e.shape[0])
