"""Statistics over independent runs: the one place for the mean, its standard error, the
spread, and the rule for a single run.

Runs of an ensemble are independent (each has its own seeded start), so the standard
error of a mean over R runs is the sample standard deviation (ddof = 1) over sqrt(R).

**The rule for a single run**: its spread is unknown, so the spread and the standard error
of one run are NaN: undefined, never 0 (which would claim an exact mean) and never an
error (one run is a valid simulation).  ``as_dict()`` turns NaN into ``null`` in JSON, the
text of the commands says "no standard error from one run" (:func:`plus_minus`), and a
verdict that needs a standard error (chaotic or regular, agreement with a law) is not
given from one run.  Where a quantity is computed *for* its standard error or its
verdict (a sweep point's lambda_1, a statistic across runs), asking for one run is
refused instead, by one check (:func:`check_runs`): 0 runs (none) where the quantity is
optional, else at least 2, and the range quoted is the set allowed.

Examples
--------
>>> m, se = ensemble_mean([[1.0, 2.0], [3.0, 6.0]])
>>> m.tolist(), se.tolist()
([2.0, 4.0], [1.0, 2.0])
>>> mean_stderr([0.5])
(0.5, nan)
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from .errors import ParameterError

__all__ = ["as_runs", "check_runs", "ensemble_mean", "mean_stderr", "plus_minus", "spread"]


def as_runs(energy_runs) -> np.ndarray:
    """``energy_runs`` as a finite (R, N) float array (a 1-D series is one run).

    Examples
    --------
    >>> as_runs([1.0, 2.0]).shape
    (1, 2)
    """
    from .validation import real_array

    e = real_array("energy_runs", energy_runs, "a finite array of shape (runs, samples)")
    if e.ndim == 1:
        e = e[None, :]
    if e.ndim != 2 or e.shape[1] < 1:
        raise ParameterError("energy_runs", f"array of shape {e.shape}", "shape (runs, samples)")
    if not np.all(np.isfinite(e)):
        raise ParameterError("energy_runs", "an array with NaN or inf", "finite values")
    return e


def check_runs(name: str, value: object, *, maximum: int | None = None, none: bool = False) -> int:
    """The number of runs ``name`` of a quantity given with its standard error or a
    verdict that needs one: an integer in [2, ``maximum``] (default the model's
    MAX_RUNS), or 0 (none) where ``none`` is allowed; anything else is refused with that
    set as the range (module docstring: one run has no standard error).

    Examples
    --------
    >>> check_runs("lyapunov_runs", 0, none=True), check_runs("runs", 2.0)
    (0, 2)
    >>> try:
    ...     check_runs("lyapunov_runs", 1, none=True)
    ... except ParameterError as e:
    ...     print(e.allowed)
    0 (none) or an integer in [2, 10000000]
    """
    from .limits import MAX_RUNS
    from .validation import positive_int

    maximum = MAX_RUNS if maximum is None else maximum
    allowed = f"{'0 (none) or ' if none else ''}an integer in [2, {maximum}]"
    why = "a standard error needs two runs"
    try:
        runs = positive_int(name, value, minimum=0, maximum=maximum)
    except ParameterError as e:
        raise ParameterError(name, e.value, allowed, why=why) from None
    if runs == 1 or (runs == 0 and not none):
        raise ParameterError(name, value, allowed, why=why)
    return runs


def ensemble_mean(energy_runs) -> tuple[np.ndarray, np.ndarray]:
    """Mean over runs (axis 0 of an (R, N) array) and its standard error, std (ddof = 1)
    over sqrt(R); NaN for a single run (module docstring).

    Examples
    --------
    >>> m, se = ensemble_mean([[1.0, 2.0]])
    >>> m.tolist(), np.isnan(se).tolist()
    ([1.0, 2.0], [True, True])
    """
    e = as_runs(energy_runs)
    mean = e.mean(axis=0)
    if e.shape[0] == 1:
        return mean, np.full_like(mean, np.nan)
    return mean, e.std(axis=0, ddof=1) / np.sqrt(e.shape[0])


def spread(values) -> float:
    """Standard deviation (ddof = 1) of the values, one per run; NaN for fewer than two.
    The values must be finite (callers that drop failed runs do so first, and say so).

    Examples
    --------
    >>> spread([1.0, 3.0]), spread([2.0])
    (1.4142135623730951, nan)
    """
    x = _finite_values(values)
    return float(x.std(ddof=1)) if x.size > 1 else math.nan


def mean_stderr(values) -> tuple[float, float]:
    """(mean, standard error) of the values, one per run; the standard error is NaN for
    one value and both are NaN for none.

    Examples
    --------
    >>> mean_stderr([1.0, 2.0, 3.0, 4.0])
    (2.5, 0.6454972243679028)
    """
    x = _finite_values(values)
    if not x.size:
        return math.nan, math.nan
    return float(x.mean()), spread(x) / math.sqrt(x.size)


def _finite_values(values) -> np.ndarray:
    """``values`` as a flat float array of finite numbers, else ParameterError naming
    ``values`` (None, text, NaN, infinities)."""
    from .validation import finite_array

    return finite_array("values", values, "finite real numbers, one per run").ravel()


def plus_minus(
    mean: float, stderr: float | None, digits: str = ".6g", se_digits: str = ".2g"
) -> str:
    """``mean +- stderr`` as the commands print it, or the mean and "(no standard error
    from one run)" when the standard error is NaN (None, as ``as_dict()`` gives it).

    Examples
    --------
    >>> plus_minus(0.25, 0.01), plus_minus(0.25, None)
    ('0.25 +- 0.01', '0.25 (no standard error from one run)')
    >>> plus_minus(np.array(0.25), np.float64(0.01))  # numpy's scalars and 0-d arrays too
    '0.25 +- 0.01'

    """
    for name, x in (("mean", mean), ("stderr", stderr)):
        if x is None and name == "stderr":
            continue
        scalar = x.item() if isinstance(x, np.ndarray) and x.ndim == 0 else x  # as numpy gives
        if isinstance(scalar, bool | np.bool_) or not isinstance(scalar, numbers.Real):
            raise ParameterError(
                name, x, "a real number" + (" or None" if name == "stderr" else "")
            )
    for name, spec in (("digits", digits), ("se_digits", se_digits)):
        try:
            format(0.0, spec)
        except (TypeError, ValueError):
            raise ParameterError(name, spec, "a format spec of a float, such as '.6g'") from None
    if stderr is None or math.isnan(stderr):
        return f"{mean:{digits}} (no standard error from one run)"
    return f"{mean:{digits}} +- {stderr:{se_digits}}"
