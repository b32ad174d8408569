"""How fast an ensemble's mean container energy settles at the law's mean.

The rule
--------
Let mu be the law's mean <E_c> and x(t) = (<E_c>(t) - mu) / mu the relative excess of
the ensemble mean.  The **settling time** t_f is when the excess has fallen to a stated
fraction f of the law's mean (default 5 %): |x(t_f)| = f.

Near t_f the excess is of the order of the run-to-run noise: for Fig. 8's five particles
one run's E_c fluctuates by about its own mean, with an autocorrelation time of ~1500
periods, so 64 runs see the mean curve only to ~10 % of mu in any window.  The first
time a noisy curve dips below f therefore comes earlier the noisier the curve, i.e. the
fewer the runs (the rule used before this one moved from 1150 periods with 8 runs to
3100 with 48).  The rule here reads t_f off curves fitted to the approach, so that its
expected value does not depend on the number of runs R:

1. Cut the runs (R, P + 1) into windows of W periods; window i has the ensemble mean
   x_i of the runs' window means (as excess over mu) and the standard error s_i of x_i
   from the spread of those R window means (runs are independent, so s_i needs no
   correction for the autocorrelation inside a run).
2. Locate the tail: fit the stretched exponential A' exp(-(t / tau')^b) to all x_i at
   the window centres t_i, by least squares weighted with 1 / s_i^2 (the relative
   weights, and so the fitted curve's expected value, do not depend on R), and let the
   tail start at t_tail, where this curve's excess falls to ``tail`` (default 1: the
   container holds twice the law's mean).  b says how far the whole approach is from one
   exponential (b < 1: it slows down as it goes on; the Fig. 8 set-up has b ~ 0.75, and
   an exponential's tau grows from ~800 to ~1080 periods as its fit starts later).
3. Fit one exponential x(t) = A exp(-t / tau) to the windows from t_tail on (at least
   6 windows), weighted alike: late in the approach only the slowest mode is left,
   while a stretched exponential fitted through a sum of modes (two exponentials, say)
   misses its crossing by ~20 % however many runs there are.  The reduced chi-square
   of this fit says whether one exponential describes the tail (near 1) or not (>> 1).
4. t_f = tau ln(|A| / f), the tail's crossing of f (0 when |A| <= f).  A crossing
   beyond the record is an extrapolation of the tail, flagged ``extrapolated`` (run
   longer); ``late_z``, the late half's mean minus mu in its standard errors, says
   whether the runs reach the law at all.

Errors come from the bootstrap over runs: B ensembles of R runs drawn with replacement
from the R runs (whole runs, which keeps each run's autocorrelation: a block bootstrap
with runs as blocks), each fitted like the data (steps 2 to 4).  The interval of t_f is
the expanded percentile interval at ``level`` (Hesterberg's: the bootstrap percentiles
at Phi(-/+ sqrt(R / (R - 1)) t_{R-1}), t_{R-1} Student's quantile, which widens the
plain percentile interval by 12 % at R = 16 and so corrects its narrowness for few
runs); tau and b get the bootstraps' standard deviations (from the central 68 %), and
the curve a pointwise band alike.  More runs narrow the interval about as 1 / sqrt(R)
and do not move it (tests/equilibrium/test_relaxation.py); benchmarks/bench_relaxation.py measures
the coverage and the bias on synthetic runs.

Examples
--------
>>> rng = np.random.default_rng(0)
>>> t = np.arange(4001)
>>> runs = 0.2 * (1 + 3 * np.exp(-t / 400.0)) + 0.02 * rng.standard_normal((16, t.size))
>>> r = measure_relaxation(runs, 0.2, resamples=99)
>>> exact = 400 * math.log(3 / 0.05)  # 1638 periods
>>> bool(r.settle_low < exact < r.settle_high), abs(r.stretch - 1) < 0.1
(True, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..limits import MAX_RESAMPLES
from ..results import Result

__all__ = ["BOOTSTRAP", "measure_relaxation", "Relaxation", "STRETCH_RANGE"]

#: Bootstrap ensembles of runs drawn for the errors.
BOOTSTRAP = 999
#: Range of the stretching exponent b allowed in the fit that locates the tail.
STRETCH_RANGE = (0.2, 5.0)
#: Fewest windows the tail's exponential is fitted to.
TAIL_WINDOWS = 6


@dataclass(frozen=True)
class Relaxation(Result):
    """The approach of the ensemble mean to ``target`` (module docstring).

    Attributes
    ----------
    target : the law's mean mu
    fraction : f, the relative excess that counts as settled
    tail : relative excess where the tail's exponential fit starts
    window, runs, level, resamples : periods per window, runs R, confidence level of the
        intervals, bootstrap ensembles B
    times : window centres (periods)
    means, stderr : ensemble mean of E_c per window and its standard error across runs
    low, high : pointwise bootstrap band of ``means`` at ``level``
    settle_time : t_f, the tail's crossing of f
    extrapolated : whether t_f lies beyond the record (then run longer)
    settle_low, settle_high : bootstrap percentile interval of t_f at ``level``
    tail_start : t_tail, where the tail's fit starts
    amplitude, rate_time, rate_stderr : A and tau of the tail, tau's bootstrap error
    stretch, stretch_stderr : b of the whole approach and its bootstrap error
    chi2 : reduced chi-square of the tail's fit (degrees of freedom: windows - 2)
    late_z : (mean over the second half of the windows - mu) / its standard error (NaN
        when the runs' late means are all equal: no standard error)
    """

    target: float
    fraction: float
    tail: float
    window: int
    runs: int
    level: float
    resamples: int
    times: np.ndarray
    means: np.ndarray
    stderr: np.ndarray
    low: np.ndarray
    high: np.ndarray
    settle_time: float
    extrapolated: bool
    settle_low: float
    settle_high: float
    tail_start: float
    amplitude: float
    rate_time: float
    rate_stderr: float
    stretch: float
    stretch_stderr: float
    chi2: float
    late_z: float

    DIMS = {name: ("time",) for name in ("means", "stderr", "low", "high")}
    COORDS = {"times": "time"}


def _curve(weights: np.ndarray, window_means: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Means and standard errors over runs of ``window_means`` (R, n) for ensembles given
    as run counts ``weights`` (E, R) summing to R: returns two arrays (E, n)."""
    R = window_means.shape[0]
    mean = weights @ window_means / R
    square = weights @ window_means**2 / R
    var = np.maximum(square - mean**2, 0.0) * R / (R - 1)
    return mean, np.sqrt(var / R)


def _expanded_tail(level: float, runs: int) -> float:
    """Lower tail probability of the expanded percentile interval at ``level`` for
    ``runs`` runs: Phi(-sqrt(R / (R - 1)) t_{R-1}) with t_{R-1} Student's quantile at
    (1 + level) / 2.

    Examples
    --------
    >>> round(_expanded_tail(0.95, 16), 4), round(_expanded_tail(0.95, 10**6), 4)
    (0.0139, 0.025)
    """
    from scipy import stats

    t = stats.t.ppf((1 + level) / 2, runs - 1)
    return float(stats.norm.cdf(-math.sqrt(runs / (runs - 1)) * t))


def _spread(values: np.ndarray) -> float:
    """Half the width of the central 68 % of ``values``: their standard deviation when
    they are normal, and not ruled by a few resamples at a bound of the fit when not."""
    low, high = np.quantile(values, [0.158655, 0.841345])
    return float((high - low) / 2)


def _draws(runs: int, resamples: int, seed: int) -> np.ndarray:
    """How often each run is drawn in each of ``resamples`` bootstrap ensembles (B, R)."""
    picks = np.random.default_rng(seed).integers(0, runs, size=(resamples, runs))
    return np.stack([np.bincount(row, minlength=runs) for row in picks]).astype(float)


def _model(p: np.ndarray, t: np.ndarray, sign: float) -> np.ndarray:
    """sign exp(p0 - (t / tau)^b) with p = (ln|A|, ln tau, ln b)."""
    return sign * np.exp(p[0] - (t / math.exp(p[1])) ** math.exp(p[2]))


def _fit(t, x, s, sign, start, stretched: bool) -> tuple[np.ndarray, float]:
    """Weighted least-squares parameters (ln|A|, ln tau, ln b) from ``start`` (b = 1 held
    unless ``stretched``) and the sum of squared normalised residuals."""
    from scipy.optimize import least_squares

    def residuals(q):
        return (_model(np.r_[q, 0.0][:3], t, sign) - x) / s

    def jacobian(q):
        p = np.r_[q, 0.0][:3]
        b = math.exp(p[2])
        u = (t / math.exp(p[1])) ** b
        m = _model(p, t, sign) / s
        columns = [m, m * b * u, -m * b * u * np.log(t / math.exp(p[1]))]
        return np.column_stack(columns[: q.size])

    span = float(t[-1] + t[0])
    lo = [-50.0, math.log(t[0] / 10), math.log(STRETCH_RANGE[0])]
    hi = [50.0, math.log(100 * span), math.log(STRETCH_RANGE[1])]
    size = 3 if stretched else 2
    lo, hi = lo[:size], hi[:size]
    q = np.clip(start[:size], np.add(lo, 1e-9), np.subtract(hi, 1e-9))
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        out = least_squares(residuals, q, jac=jacobian, bounds=(lo, hi))
    return np.r_[out.x, 0.0][:3], float(2 * out.cost)


def _crossing(p: np.ndarray, level: float) -> float:
    """Where the fitted curve's |excess| falls to ``level``: tau (ln(|A| / level))^(1 / b)
    (0 when |A| <= level)."""
    depth = p[0] - math.log(level)
    return math.exp(p[1]) * depth ** math.exp(-p[2]) if depth > 0 else 0.0


def _start(t: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Starting parameters: b = 1, tau at the first fall of |x| below |x_0| / e."""
    below = np.flatnonzero(np.abs(x) < abs(x[0]) / math.e)
    tau = float(t[below[0]] if below.size else t[-1])
    return np.array([math.log(abs(x[0]) + 1e-300) + t[0] / tau, math.log(tau), 0.0])


def _settle_fit(t, x, s, sign, start, tail) -> tuple[np.ndarray, np.ndarray, float, float]:
    """Steps 2 and 3 of the rule: (stretched parameters, tail's parameters, tail's sum
    of squares, t_tail); ``start`` holds starting values for both fits."""
    whole, _ = _fit(t, x, s, sign, start[0], stretched=True)
    t_tail = min(_crossing(whole, tail), float(t[-TAIL_WINDOWS]))
    keep = t >= t_tail
    p, chi2 = _fit(t[keep], x[keep], s[keep], sign, start[1], stretched=False)
    return whole, p, chi2, t_tail


def measure_relaxation(
    energy_runs,
    target: float,
    *,
    fraction: float = 0.05,
    tail: float = 1.0,
    window: int = 50,
    level: float = 0.95,
    resamples: int = BOOTSTRAP,
    seed: int = 0,
) -> Relaxation:
    """Settling time of the ensemble mean of ``energy_runs`` (R, P + 1) at ``target``
    (the law's mean), with bootstrap intervals, by the rule of the module docstring.

    Parameters
    ----------
    energy_runs : array (R >= 3, P + 1)
        Container energy E(jT) of independent runs, all started alike.
    target : float > 0
        The law's mean <E_c>.
    fraction : float > 0
        Relative excess |<E_c> - target| / target that counts as settled.
    tail : float > fraction
        Relative excess below which the approach is fitted by one exponential.
    window : int >= 1
        Periods per window (at least 2 TAIL_WINDOWS windows must fit).
    level : float in (0, 1)
        Confidence level of the intervals.
    resamples : int >= 20
        Bootstrap ensembles of runs.
    seed : int >= 0
        Seed of the bootstrap's draws.
    """
    e = v.real_array("energy_runs", energy_runs)
    if e.ndim != 2 or e.shape[0] < 3 or e.shape[1] < 2 * TAIL_WINDOWS or not np.all(np.isfinite(e)):
        shown = f"an array of shape {e.shape}" + ("" if np.all(np.isfinite(e)) else " with NaN")
        allowed = f"finite, of shape (runs >= 3, P + 1 >= {2 * TAIL_WINDOWS})"
        raise ParameterError("energy_runs", shown, allowed)
    target = v.positive("target", target)
    fraction = v.positive("fraction", fraction)
    if v.finite("tail", tail) <= fraction:
        raise ParameterError("tail", tail, f"a number > fraction = {fraction:g}")
    window = v.positive_int("window", window, maximum=e.shape[1] // (2 * TAIL_WINDOWS))
    if not 0 < v.finite("level", level) < 1:
        raise ParameterError("level", level, "a number in (0, 1)")
    resamples = v.positive_int("resamples", resamples, minimum=20, maximum=MAX_RESAMPLES)
    seed = v.positive_int("seed", seed, minimum=0)
    R, n = e.shape[0], e.shape[1] // window
    per_run = (e[:, : n * window].reshape(R, n, window).mean(axis=2) - target) / target
    if not np.abs(per_run).max() < 1e100:  # the fit squares it
        why = "the relative excess |<E_c> - target| / target is fitted"
        raise ParameterError("target", target, "within 1e100 of the energies' scale", why=why)
    if target > 1e15 * np.abs(e).max():  # the excess is -1 to the last bit: nothing to fit
        why = "beyond it the relative excess |<E_c> - target| / target is 1 in every bit"
        raise ParameterError("target", target, "at most 1e15 times the largest energy", why=why)
    times = (np.arange(n) + 0.5) * window
    means, stderr = _curve(np.vstack([np.ones(R), _draws(R, resamples, seed)]), per_run)
    stderr = np.where(stderr > 0, stderr, np.min(stderr[stderr > 0], initial=1.0))
    sign = 1.0 if means[0, 0] >= 0 else -1.0
    guess = _start(times, means[0])
    whole, p, chi2, t_tail = _settle_fit(times, means[0], stderr[0], sign, (guess, guess), tail)
    pairs = zip(means[1:], stderr[1:], strict=True)
    boot = [_settle_fit(times, m, s, sign, (whole, p), tail)[:2] for m, s in pairs]
    settles = np.array([_crossing(q, fraction) for _, q in boot])
    taus = np.exp([q[1] for _, q in boot])
    stretches = np.exp([w[2] for w, _ in boot])
    q = _expanded_tail(level, R)
    settle = _crossing(p, fraction)
    late = per_run[:, n // 2 :].mean(axis=1)
    return Relaxation(
        target=target,
        fraction=fraction,
        tail=float(tail),
        window=window,
        runs=R,
        level=level,
        resamples=resamples,
        times=times,
        means=target * (1 + means[0]),
        stderr=target * stderr[0],
        low=target * (1 + np.quantile(means[1:], q, axis=0)),
        high=target * (1 + np.quantile(means[1:], 1 - q, axis=0)),
        settle_time=settle,
        extrapolated=settle > n * window,
        settle_low=float(np.quantile(settles, q)),
        settle_high=float(np.quantile(settles, 1 - q)),
        tail_start=t_tail,
        amplitude=sign * math.exp(p[0]),
        rate_time=math.exp(p[1]),
        rate_stderr=_spread(taus),
        stretch=math.exp(whole[2]),
        stretch_stderr=_spread(stretches),
        chi2=chi2 / max(int(np.sum(times >= t_tail)) - 2, 1),
        late_z=_z(late),
    )


def _z(late: np.ndarray) -> float:
    """Mean of ``late`` (one value per run) over its standard error; NaN without one."""
    sd = float(late.std(ddof=1))
    return float(late.mean() / (sd / math.sqrt(late.size))) if sd > 0 else math.nan
