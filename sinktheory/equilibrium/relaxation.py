"""How fast an ensemble's mean container energy settles at the law's mean.

The rule
--------
Cut the runs (R, P + 1) into windows of W periods.  Window i has the mean b_i over runs
and periods in it, and the standard error s_i of that mean from the spread of the runs'
own window means (runs are independent).  The **settling time** is the start (in periods)
of the first window whose mean lies within ``z`` standard errors of the law's mean mu,
|b_i - mu| <= z s_i; its error is the delete-one-run jackknife of the whole rule, and it
is NaN when no window gets there (run longer).  A first passage says when the mean
arrives, not that it stays: ``late_z`` = (mean of the second half of the windows - mu) /
its standard error says whether the runs' late mean agrees with the law.

Where the approach is exponential, b_i - mu = A exp(-t_i / tau) is fitted by weighted
least squares over the windows (t_i the window centres, weights 1 / s_i^2) with mu
fixed; tau's error is again the jackknife over runs, and the fit's reduced chi-square
says whether the exponential describes the approach (near 1) or not (>> 1).

Examples
--------
>>> rng = np.random.default_rng(0)
>>> t = np.arange(2001)
>>> runs = 0.2 + 0.3 * np.exp(-t / 150.0) + 0.02 * rng.standard_normal((16, t.size))
>>> r = measure_relaxation(runs, 0.2, window=50)
>>> abs(r.rate_time / 150 - 1) < 0.1, 300 < r.settle_time < 1200
(True, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..results import Result


@dataclass(frozen=True)
class Relaxation(Result):
    """The settling of the ensemble mean at ``target`` (module docstring).

    Attributes
    ----------
    target : the law's mean <E_c>
    window, z : window length (periods) and the tolerance in standard errors
    times : window centres (periods); ``means``, ``stderr``: b_i and s_i
    settle_time, settle_stderr : start of the first window in the band, jackknife error
    late_z : (late mean - mu) / its standard error, over the second half of the windows
    rate_time, rate_stderr : tau of the exponential fit and its jackknife error
    amplitude : A of the fit
    chi2 : reduced chi-square of the fit
    """

    target: float
    window: int
    z: float
    times: np.ndarray
    means: np.ndarray
    stderr: np.ndarray
    settle_time: float
    settle_stderr: float
    late_z: float
    rate_time: float
    rate_stderr: float
    amplitude: float
    chi2: float

    DIMS = {"means": ("time",), "stderr": ("time",)}
    COORDS = {"times": "time"}


def _windows(e: np.ndarray, window: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    count = e.shape[1] // window
    per_run = e[:, : count * window].reshape(e.shape[0], count, window).mean(axis=2)
    times = (np.arange(count) + 0.5) * window
    return times, per_run.mean(axis=0), per_run.std(axis=0, ddof=1) / math.sqrt(e.shape[0])


def _settle(times, means, stderr, target, z, window) -> float:
    inside = np.flatnonzero(np.abs(means - target) <= z * stderr)
    return float(times[inside[0]] - 0.5 * window) if inside.size else math.nan


def _fit(times, means, stderr, target) -> tuple[float, float, float]:
    """(tau, A, reduced chi2) of b - mu = A exp(-t / tau), weighted by 1 / s^2, with tau
    bounded to [t_0 / 10, 100 x the span] (NaN when the fit fails)."""
    from scipy.optimize import curve_fit

    d = means - target
    sigma = np.where(stderr > 0, stderr, np.min(stderr[stderr > 0], initial=1.0))
    if d[0] == 0 or times.size < 3:
        return math.nan, math.nan, math.nan
    span = float(times[-1] + times[0])
    below = np.flatnonzero(np.abs(d) < abs(d[0]) / math.e)  # first 1/e crossing
    guess = float(min(max(times[below[0]] if below.size else span, times[0]), 10 * span))

    def model(t, a, tau):
        return a * np.exp(-t / tau)

    try:
        with np.errstate(over="ignore", invalid="ignore"):
            (a, tau), _ = curve_fit(
                model,
                times,
                d,
                p0=(d[0] * math.exp(times[0] / guess), guess),
                sigma=sigma,
                absolute_sigma=True,
                bounds=([-np.inf, times[0] / 10], [np.inf, 100 * span]),
            )
    except (RuntimeError, ValueError):
        return math.nan, math.nan, math.nan
    chi2 = float(np.sum(((d - model(times, a, tau)) / sigma) ** 2) / max(times.size - 2, 1))
    return float(tau), float(a), chi2


def measure_relaxation(
    energy_runs, target: float, *, window: int = 50, z: float = 2.0
) -> Relaxation:
    """Settling time and exponential rate of the ensemble mean of ``energy_runs`` (R, P + 1)
    at ``target`` (the law's mean), by the rule of the module docstring.

    Parameters
    ----------
    energy_runs : array (R >= 3, P + 1)
        Container energy E(jT) of independent runs.
    target : float
        The law's mean <E_c>.
    window : int >= 1
        Periods per window (at least 3 windows must fit).
    z : float > 0
        Tolerance in standard errors.
    """
    e = v.real_array("energy_runs", energy_runs)
    if e.ndim != 2 or e.shape[0] < 3:
        raise ParameterError(
            "energy_runs", f"an array of shape {e.shape}", "shape (runs >= 3, P + 1)"
        )
    target = v.finite("target", target)
    window = v.positive_int("window", window, maximum=max(e.shape[1] // 3, 1))
    z = v.positive("z", z)
    times, means, stderr = _windows(e, window)
    settle = _settle(times, means, stderr, target, z, window)
    late = e[:, times.size // 2 * window : times.size * window].mean(axis=1)
    late_z = float((late.mean() - target) / (late.std(ddof=1) / math.sqrt(e.shape[0])))
    tau, amplitude, chi2 = _fit(times, means, stderr, target)
    R = e.shape[0]
    settles, taus = [], []
    for r in range(R):
        rest = np.delete(e, r, axis=0)
        t_, m_, s_ = _windows(rest, window)
        settles.append(_settle(t_, m_, s_, target, z, window))
        taus.append(_fit(t_, m_, s_, target)[0])

    def jack(values, full):
        x = np.asarray(values)
        if not math.isfinite(full) or not np.all(np.isfinite(x)):
            return math.nan
        return float(math.sqrt((R - 1) / R * np.sum((x - x.mean()) ** 2)))

    return Relaxation(
        target=target,
        window=window,
        z=z,
        times=times,
        means=means,
        stderr=stderr,
        settle_time=settle,
        settle_stderr=jack(settles, settle),
        late_z=late_z,
        rate_time=tau,
        rate_stderr=jack(taus, tau),
        amplitude=amplitude,
        chi2=chi2,
    )
