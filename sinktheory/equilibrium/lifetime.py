"""Measured against predicted: how long the container stays drained, and whether the
runs reach the equilibrium law.

Which return time
-----------------
Sample the container energy once per period, s_j = E_c(jT) / E, and let A = {s >= f}.
For the period map, which preserves the microcanonical measure, Kac's lemma says that
points of A come back to A after a mean of

    tau_Kac = 1 / P(A)   periods,

P(A) = P(E_c >= f E) from the law (:meth:`EquilibriumLaw.tail`) -- if the map is ergodic.
The dynamical test measures the returns themselves: every visit j (a period with s_j in
A) has a return time T_j, the number of periods until the next visit.  A record of N
periods sees T_j only when the next visit falls inside it; the last visit of each run
has a return cut by the record's end, and long returns are the likelier to be cut.  The
mean of the returns seen whole (``observed_return``) is therefore biased short when
excursions last a sizeable part of a run (k = 1, f = 0.8 on the Fig. 8 well, 32 runs
x 3000 periods: 8.36 seen whole, 8.97 censoring-corrected, Kac's 1/P 8.50;
benchmarks/bench_relaxation.py).

``return_time`` corrects for the censoring with the Kaplan-Meier estimator: each run's
last visit is a censored return, known only to exceed c = N - 1 - j.  At every lag t,
the hazard h(t) = d(t) / n(t) counts the returns of length t, d(t), among the visits
still at risk, n(t) (returns seen whole of length >= t plus censored ones with c >= t);
the survival S(t) = prod_{s <= t} (1 - h(s)) and the mean return time sum_{t >= 0} S(t).
The estimator is consistent because, by stationarity, a visit's return time does not
depend on where in the record the visit lies, so the censoring is independent of it.
The sum stops at the longest return or censoring time seen (a restricted mean: returns
longer than a run cannot be seen by any estimator).  Comparing it with 1/P tests
Kac's lemma dynamically; the occupation (fraction of samples in A; record length over
visits is its inverse) tests only the law's tail probability P(A).

A different time is the **lifetime of the drained state**: the mean time between
*entries* into A (from outside), that is, how often the container recovers a fraction
f of the energy (estimated as record length over entries).
Kac's lemma applied to the entry set gives tau_entry = sigma / P(A), sigma the mean
sojourn (consecutive periods spent in A per visit), which depends on the dynamics, not
on the law alone.  Both are reported: ``entry_interval`` measured, and
``entry_interval_predicted`` = measured sigma / P(A).
When visits are rare (k = 5, f = 0.8: 1/P ~ 4e4 periods) runs cannot observe returns;
the law's 1/P is then the prediction and the measured values are NaN (fewer than two
visits in every run).

Statistical errors
------------------
Runs start from independent positions, so they are independent replicates: every
measured ratio (return time = total gap / number of gaps, sojourn, entry interval,
occupation) is pooled over runs and its standard error is the delete-one-run jackknife,
which accounts for any autocorrelation inside a run.  The distribution of the late-time
samples is compared with the law by the Kolmogorov-Smirnov distance D = sup |F_hat - F|
of the pooled sample, whose null distribution is estimated by resampling whole runs
(bootstrap of D* = sup |F_hat* - F_hat|), again with the autocorrelation left inside
each run.  The integrated autocorrelation time of E_c (Sokal's automatic window) is
reported with its standard error (Madras and Sokal's) and the effective number of
samples it implies, never more than the samples taken.

Examples
--------
>>> rng = np.random.default_rng(1)
>>> inside = rng.random((4, 20000)) < 0.25  # independent draws: returns are geometric
>>> v = visit_statistics(inside)
>>> round(v.return_time[0], 1), round(v.occupation[0], 2)
(4.0, 0.25)
>>> v = visit_statistics(rng.random((200, 100)) < 0.05)  # Kac: 20; runs of 100 cut them
>>> round(v.observed_return[0]), bool(abs(v.return_time[0] / 20 - 1) < 0.1)  # error ~3 %
(15, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import runstats
from .. import validation as v
from ..errors import ParameterError
from ..limits import MAX_RESAMPLES
from ..results import Result
from .law import EquilibriumLaw, check_fractions

__all__ = [
    "autocorrelation_time",
    "BOOTSTRAP",
    "check_one_shell",
    "one_shell_box",
    "compare_with_law",
    "ENERGY_SLACK",
    "jackknife_ratio",
    "kaplan_meier_mean",
    "ks_distance",
    "KS_GRID",
    "LawComparison",
    "measure_lifetimes",
    "SOKAL_C",
    "visit_statistics",
    "VisitStatistics",
]

#: Bootstrap resamples of whole runs for the p-value of the KS distance.
BOOTSTRAP = 999
#: Points of the grid (equally spaced in the law's probability) where the empirical and
#: the law's distribution functions are compared.
KS_GRID = 2001
#: Relative excess of a container energy over the law's total energy E tolerated in
#: compare_with_law: the simulations' energy audit lets the total drift by up to 1e-2
#: (tol 1e-4).
ENERGY_SLACK = 1e-2
#: Sokal's window constant: the autocorrelation sum stops at the first lag W >= C tau(W).
SOKAL_C = 6.0


def jackknife_ratio(numerators, denominators) -> tuple[float, float]:
    """sum(numerators) / sum(denominators) and its delete-one-group jackknife standard
    error (groups = runs; NaN when fewer than two groups have a denominator > 0).

    Examples
    --------
    >>> value, se = jackknife_ratio([2.0, 4.0, 6.0], [1.0, 2.0, 3.0])
    >>> value, se
    (2.0, 0.0)
    """
    allowed = "finite 1-D arrays of equal length (one value per run)"
    num = v.real_array("numerators", numerators, allowed)
    den = v.real_array("denominators", denominators, allowed)
    for name, a in (("numerators", num), ("denominators", den)):
        if a.ndim != 1 or a.shape != num.shape or not np.isfinite(a).all():
            raise ParameterError(name, f"an array of shape {a.shape}", allowed)
    total_den = den.sum()
    if total_den <= 0:
        return math.nan, math.nan
    value = float(num.sum() / total_den)
    used = den > 0
    g = int(used.sum())
    if g < 2:
        return value, math.nan
    num, den = num[used], den[used]
    loo = (num.sum() - num) / (den.sum() - den)
    return value, float(math.sqrt((g - 1) / g * np.sum((loo - loo.mean()) ** 2)))


@dataclass(frozen=True)
class VisitStatistics(Result):
    """Visits of period-sampled runs to a set A, pooled over runs with jackknife errors.

    Each field is (value, standard error); times are in sampling periods.

    Attributes
    ----------
    occupation : fraction of samples in A
    return_time : mean number of periods from a visit to the next visit (Kac: 1 / P(A)),
        Kaplan-Meier estimate with the returns cut by the record's end as censored
        (module docstring); NaN when no run sees a return whole
    observed_return : mean of the returns seen whole (biased short)
    sojourn : mean length of a stay in A (consecutive visits)
    entry_interval : mean number of periods between entries into A from outside (record
        length over entries)
    entries : number of entries counted, over all runs
    """

    occupation: tuple[float, float]
    return_time: tuple[float, float]
    observed_return: tuple[float, float]
    sojourn: tuple[float, float]
    entry_interval: tuple[float, float]
    entries: int


def kaplan_meier_mean(events, at_risk) -> float:
    """Restricted mean sum_{t=0}^{t_max} S(t) of a return time T >= 1 from the counts of
    returns of length t, ``events[t]``, and of visits at risk at t, ``at_risk[t]``
    (index t = 0 .. N; t_max the last t with visits at risk).  NaN without any event.

    Examples
    --------
    >>> kaplan_meier_mean([0, 1, 1, 1], [0, 4, 2, 1])  # returns 1, 2, 3 and one > 1
    2.125
    """
    allowed = "finite counts >= 0, 1-D arrays of equal length"
    d = v.real_array("events", events, allowed)
    n = v.real_array("at_risk", at_risk, allowed)
    for name, a in (("events", d), ("at_risk", n)):
        if a.ndim != 1 or a.shape != d.shape or not (np.isfinite(a) & (a >= 0)).all():
            raise ParameterError(name, f"an array of shape {a.shape}", allowed)
    if d.sum() == 0:
        return math.nan
    last = int(np.flatnonzero(n > 0)[-1])
    hazard = d[1 : last + 1] / n[1 : last + 1]
    return float(1 + np.sum(np.cumprod(1 - hazard)))


def _return_counts(row: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(events, at risk) over lags 0..N of one run's returns (module docstring)."""
    size = row.size + 1
    visits = np.flatnonzero(row)
    if visits.size == 0:
        return np.zeros(size), np.zeros(size)
    events = np.bincount(np.diff(visits), minlength=size).astype(float)
    censored = np.bincount([row.size - 1 - visits[-1]], minlength=size).astype(float)
    # at risk at t: returns of length >= t and censoring times >= t
    return events, np.cumsum((events + censored)[::-1])[::-1]


def _censored_return(a: np.ndarray) -> tuple[float, float]:
    """Kaplan-Meier mean return time of runs ``a`` (R, N) and its delete-one-run
    jackknife error."""
    counts = [_return_counts(row) for row in a]
    events = np.array([c[0] for c in counts])
    risk = np.array([c[1] for c in counts])
    value = kaplan_meier_mean(events.sum(axis=0), risk.sum(axis=0))
    used = np.flatnonzero(risk.sum(axis=1) > 0)
    if used.size < 2 or not math.isfinite(value):
        return value, math.nan
    loo = np.array(
        [kaplan_meier_mean(events.sum(0) - events[r], risk.sum(0) - risk[r]) for r in used]
    )
    g = used.size
    return value, float(math.sqrt((g - 1) / g * np.sum((loo - loo.mean()) ** 2)))


def visit_statistics(inside) -> VisitStatistics:
    """Visit, return, sojourn and entry statistics of a boolean array (runs, samples).

    Examples
    --------
    >>> v = visit_statistics([[True, False, False, True, True, False, True, False]])
    >>> v.return_time[0], v.observed_return[0], v.sojourn[0]
    (2.125, 2.0, 1.5)
    >>> v.entry_interval[0], v.entries
    (4.0, 2)
    """
    a = np.asarray(inside, dtype=bool)
    if a.ndim == 1:
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] < 2:
        raise ParameterError("inside", f"an array of shape {a.shape}", "shape (runs, samples >= 2)")
    gap_sum, gap_n, stay_sum, stay_n, entry_n = (np.zeros(a.shape[0]) for _ in range(5))
    for r, row in enumerate(a):
        visits = np.flatnonzero(row)
        if visits.size >= 2:
            gap_sum[r], gap_n[r] = visits[-1] - visits[0], visits.size - 1
        starts = np.flatnonzero(row & ~np.r_[False, row[:-1]])
        ends = np.flatnonzero(row & ~np.r_[row[1:], False])
        complete = (starts > 0) & (ends < row.size - 1)  # stays seen from entry to exit
        stay_sum[r], stay_n[r] = np.sum(ends[complete] - starts[complete] + 1), complete.sum()
        entry_n[r] = np.count_nonzero(starts > 0)  # entries seen: outside just before
    length = np.full(a.shape[0], float(a.shape[1]))
    visits = a.sum(axis=1).astype(float)
    return VisitStatistics(
        occupation=jackknife_ratio(visits, length),
        return_time=_censored_return(a),
        observed_return=jackknife_ratio(gap_sum, gap_n),
        sojourn=jackknife_ratio(stay_sum, stay_n),
        entry_interval=jackknife_ratio(length, entry_n),
        entries=int(entry_n.sum()),
    )


def autocorrelation_time(series) -> tuple[float, float, int]:
    """Integrated autocorrelation time tau = 1 + 2 sum_{l=1}^{W} rho(l) of runs (R, P)
    (rho pooled over runs around the grand mean, by FFT) with Sokal's window: the first
    W >= SOKAL_C tau(W).  Returns (tau, stderr, W); tau is in samples (periods).  Runs too
    short for that window within half their length (lags beyond it are estimated from
    fewer than half the samples), i.e. shorter than about 12 tau, do not measure tau: the
    result is then (NaN, NaN, 0), as it is for a non-positive estimate.  A constant record
    has no autocorrelation to measure: (1, NaN, 0).

    The standard error is Madras and Sokal's, sqrt(2 (2W + 1) / N) tau for N = R P
    samples, with tau taken no smaller than 1: every rho(l) estimated from N samples has a
    variance of at least 1 / N (Bartlett's formula), so tau is never known better than
    from independent samples.  Without that floor a short record's low estimate came with
    a small error (2 x 21 independent samples: tau = 0.18, error 0.12, true tau 1).  On
    independent samples tau +- 2 stderr covered tau = 1 in 97-99 % of 1000 seeds (records
    2 x 21 to 8 x 1000, normal and Beta draws), on AR(1) samples with tau = 9 in 83 %
    (2 x 200), 90 % (4 x 500) and 98 % (8 x 2000) of 250: records of a few dozen tau
    under-cover, since a low estimate also shortens its window and its error
    (benchmarks/bench_autocorrelation.py).

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> x = np.zeros((4, 20000)); e = rng.standard_normal((4, 20000))
    >>> for j in range(1, 20000): x[:, j] = 0.8 * x[:, j - 1] + e[:, j]
    >>> tau, stderr, window = autocorrelation_time(x)
    >>> abs(tau / 9.0 - 1) < 2 * stderr / 9.0  # (1 + 0.8) / (1 - 0.8); error ~5 %
    True
    >>> autocorrelation_time(x[:, :20])  # 20 samples: too few to measure tau = 9
    (nan, nan, 0)
    """
    x = v.real_array("series", series)
    if x.ndim == 1:
        x = x[None, :]
    if x.ndim != 2 or x.shape[1] < 4:
        raise ParameterError("series", f"an array of shape {x.shape}", "shape (runs, samples >= 4)")
    x = x - x.mean()
    P = x.shape[1]
    size = 1 << (2 * P - 1).bit_length()
    spectrum = np.fft.rfft(x, size, axis=1)
    acov = np.fft.irfft(spectrum * np.conj(spectrum), size, axis=1)[:, :P].sum(axis=0)
    acov /= x.shape[0] * np.arange(P, 0, -1)
    if acov[0] <= 0:
        return 1.0, math.nan, 0
    rho = acov / acov[0]
    taus = 1 + 2 * np.cumsum(rho[1:])
    for w in range(1, P // 2 + 1):
        if w >= SOKAL_C * taus[w - 1]:
            tau = float(taus[w - 1])
            if tau <= 0:
                break
            return tau, math.sqrt(2 * (2 * w + 1) / x.size) * max(tau, 1.0), w
    return math.nan, math.nan, 0


def ks_distance(samples, cdf, *, resamples: int = BOOTSTRAP, seed: int = 0):
    """KS distance of pooled runs (R, P) from a distribution function ``cdf`` (values to
    probabilities), and its p-value by resampling whole runs (``resamples`` >= 19: the
    smallest p-value is 1 / (1 + resamples)).

    The comparison grid is the pooled sample's quantiles at KS_GRID equal steps of
    probability (the sup over it misses at most 1/KS_GRID of the exact sup).  Returns
    (D, p): D = sup |F_hat - F| on the grid, p = (1 + #{D* >= D}) / (1 + B) with
    D* = sup |F_hat* - F_hat| over B bootstrap ensembles of runs drawn with replacement.

    Examples
    --------
    >>> rng = np.random.default_rng(3)
    >>> d, p = ks_distance(rng.random((8, 500)), lambda s: np.clip(s, 0, 1))
    >>> bool(d < 0.05), bool(p > 0.01)
    (True, True)
    >>> d, p = ks_distance(rng.random((8, 500)) ** 1.3, lambda s: np.clip(s, 0, 1))
    >>> bool(p < 0.01)
    True
    """
    if not callable(cdf):
        raise ParameterError("cdf", type(cdf).__name__, "a function of s (the law's CDF)")
    x = v.real_array("samples", samples)
    if x.ndim != 2 or x.shape[0] < 2:
        raise ParameterError(
            "samples", f"an array of shape {x.shape}", "shape (runs >= 2, samples)"
        )
    resamples = v.positive_int("resamples", resamples, minimum=19, maximum=MAX_RESAMPLES)
    seed = v.positive_int("seed", seed, minimum=0)
    levels = (np.arange(KS_GRID) + 0.5) / KS_GRID
    grid = np.quantile(x, levels)
    per_run = np.stack([np.searchsorted(np.sort(r), grid, side="right") / r.size for r in x])
    pooled = per_run.mean(axis=0)
    d = float(np.max(np.abs(pooled - cdf(grid))))
    rng = np.random.default_rng(seed)
    picks = rng.integers(0, x.shape[0], size=(resamples, x.shape[0]))
    stars = np.max(np.abs(per_run[picks].mean(axis=1) - pooled), axis=1)
    return d, float((1 + np.count_nonzero(stars >= d)) / (1 + resamples))


@dataclass(frozen=True)
class LawComparison(Result):
    """Late-time samples of E_c against the law (``sinktheory lifetime``).

    Attributes
    ----------
    law : EquilibriumLaw at the runs' mean total energy
    transient, runs, samples : periods skipped, number of runs, periods kept per run
    mean, mean_stderr : <E_c> over the kept samples, and its error across runs
    autocorrelation_time, autocorrelation_time_stderr, window : integrated
        autocorrelation time of E_c (periods; NaN when the runs are too short to measure
        it), its standard error and Sokal's window (:func:`autocorrelation_time`)
    effective_samples : runs x samples / autocorrelation_time, at most runs x samples: a
        time below 1 (anticorrelated samples, or independent ones whose estimate came out
        low) is not counted as more samples than were taken, so the count is then a
        lower bound
    ks_distance, ks_pvalue : sup |F_hat - F| of E_c / E and its run-bootstrap p-value
    fractions : f
    tails : P(E_c >= f E) from the law; ``kac_periods`` = 1 / tails
    occupation, occupation_stderr : measured fraction of samples with E_c >= f E
    return_time, return_time_stderr : measured mean return time of visits (periods),
        censoring-corrected (Kaplan-Meier); NaN when no return is seen whole
    observed_return, observed_return_stderr : mean of the returns seen whole (biased
        short)
    sojourn, sojourn_stderr : measured mean stay in the set (periods)
    entry_interval, entry_interval_stderr : measured mean time between entries (periods)
    entry_interval_predicted : measured sojourn / law's P (Kac for the entry set)
    """

    law: EquilibriumLaw
    transient: int
    runs: int
    samples: int
    mean: float
    mean_stderr: float
    autocorrelation_time: float
    autocorrelation_time_stderr: float
    window: int
    effective_samples: float
    ks_distance: float
    ks_pvalue: float
    fractions: np.ndarray
    tails: np.ndarray
    kac_periods: np.ndarray
    occupation: np.ndarray
    occupation_stderr: np.ndarray
    return_time: np.ndarray
    return_time_stderr: np.ndarray
    observed_return: np.ndarray
    observed_return_stderr: np.ndarray
    sojourn: np.ndarray
    sojourn_stderr: np.ndarray
    entry_interval: np.ndarray
    entry_interval_stderr: np.ndarray
    entry_interval_predicted: np.ndarray

    DIMS = {
        name: ("fraction",)
        for name in (
            "fractions tails kac_periods occupation occupation_stderr return_time "
            "return_time_stderr observed_return observed_return_stderr sojourn sojourn_stderr "
            "entry_interval entry_interval_stderr "
            "entry_interval_predicted"
        ).split()
    }
    COORDS = {"fractions": "fraction"}

    def return_time_z(self) -> np.ndarray:
        """(measured - Kac) / standard error of each measured mean return time."""
        return (self.return_time - self.kac_periods) / self.return_time_stderr


def compare_with_law(
    energy_runs, law: EquilibriumLaw, *, transient: int, fractions=(0.2, 0.5, 0.8), seed: int = 0
) -> LawComparison:
    """Compare container energies E(jT) of runs (R, P + 1) after ``transient`` periods
    with ``law`` (module docstring for the statistics).

    Examples
    --------
    >>> from sinktheory.model import Sink, Well
    >>> from sinktheory.equilibrium import equilibrium_law
    >>> law = equilibrium_law(Sink(Well(0.5, 0.0, 4, shape="circular")), 0.5)
    >>> rng = np.random.default_rng(2)  # independent draws from the law: Beta(1, 1.25)
    >>> c = compare_with_law(0.5 * rng.beta(1, 1.25, (6, 4000)), law, transient=0)
    >>> bool(np.all(np.abs(c.return_time_z()) < 4)), bool(c.ks_pvalue > 0.01)
    (True, True)
    """
    if not isinstance(law, EquilibriumLaw):
        raise ParameterError("law", law, "an EquilibriumLaw")
    e = v.real_array("energy_runs", energy_runs)
    if e.ndim != 2 or e.shape[0] < 2:
        raise ParameterError(
            "energy_runs", f"an array of shape {e.shape}", "shape (runs >= 2, P + 1)"
        )
    top = law.total_energy * (1 + ENERGY_SLACK)
    outside = e[~((e >= 0) & (e <= top))]
    if outside.size:
        above = outside[0] > top
        raise ParameterError(
            "energy_runs",
            f"an array holding {outside[0]:.6g}",
            f"container energies in [0, {top:.6g}]",
            why=f"the law is that of one total energy E = {law.total_energy:.6g}, and a "
            f"run's E_c stays within {100 * ENERGY_SLACK:g} % of it only when every run has "
            "that energy: particles that start at rest high in the well give their run more "
            "(check_one_shell bounds it from the start box)" if above else None,
        )  # fmt: skip
    transient = v.positive_int("transient", transient, minimum=0, maximum=e.shape[1] - 4)
    fractions = check_fractions(fractions)
    s = e[:, transient:] / law.total_energy
    per_run = s.mean(axis=1)
    tau, tau_se, window = autocorrelation_time(s)
    d, p = ks_distance(s, law.cdf, seed=seed)
    tails = np.atleast_1d(law.tail(fractions))
    stats = [visit_statistics(s >= f) for f in fractions]

    def column(name: str, i: int) -> np.ndarray:
        return np.array([getattr(st, name)[i] for st in stats])

    sojourn = column("sojourn", 0)
    return LawComparison(
        law=law,
        transient=transient,
        runs=s.shape[0],
        samples=s.shape[1],
        mean=float(per_run.mean() * law.total_energy),
        mean_stderr=runstats.mean_stderr(per_run)[1] * law.total_energy,
        autocorrelation_time=tau,
        autocorrelation_time_stderr=tau_se,
        window=window,
        effective_samples=s.size / max(tau, 1.0),
        ks_distance=d,
        ks_pvalue=p,
        fractions=fractions,
        tails=tails,
        kac_periods=1 / tails,
        occupation=column("occupation", 0),
        occupation_stderr=column("occupation", 1),
        return_time=column("return_time", 0),
        return_time_stderr=column("return_time", 1),
        observed_return=column("observed_return", 0),
        observed_return_stderr=column("observed_return", 1),
        sojourn=sojourn,
        sojourn_stderr=column("sojourn", 1),
        entry_interval=column("entry_interval", 0),
        entry_interval_stderr=column("entry_interval", 1),
        entry_interval_predicted=sojourn / tails,
    )


def _check_run(sink, settings) -> None:
    """Refuse a ``sink`` that is no Sink, ``settings`` that are no RunSettings, or settings
    the sink does not allow (:meth:`~sinktheory.model.RunSettings.check`)."""
    from ..model import RunSettings, Sink

    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    if not isinstance(settings, RunSettings):
        raise ParameterError("settings", settings, "a sinktheory.model.RunSettings")
    settings.check(sink)


def one_shell_box(sink, settings) -> float:
    """The largest start box, up to ``settings.box``, whose runs share one energy shell:
    particles starting at rest in it add at most ENERGY_SLACK E0 to a run's total energy
    (k V at the box's corner, the bound :meth:`~sinktheory.model.RunSettings.total_energy_bound`
    takes).  ``settings.box`` itself where it does; else found by bisection (the corner's V
    grows with the box), to 1e-15 of it.

    >>> from sinktheory.model import RunSettings, Sink, Well
    >>> round(one_shell_box(Sink(Well(1.0, 0.99, 6, shape="symmetric")), RunSettings()), 5)
    0.00751
    """
    from dataclasses import replace

    _check_run(sink, settings)

    def fits(box: float) -> bool:
        spread = replace(settings, box=box).total_energy_bound(sink) - settings.container_energy
        return spread <= ENERGY_SLACK * settings.container_energy

    if fits(settings.box):
        return settings.box
    lo, hi = 0.0, settings.box
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if fits(mid) else (lo, mid)
    return lo


def check_one_shell(sink, settings) -> None:
    """Refuse, naming ``box``, a start box in which the runs' total energies could differ
    by more than ENERGY_SLACK of E0 (:func:`one_shell_box`).

    The law the runs are compared with is that of one total energy (the runs' mean); a
    particle that starts at rest high up in the well puts its run on another energy
    shell.  Near the symmetric well's corner saddle the well's centre is narrower than
    the default start box: at alpha = 1, beta = 0.99, n = 6 the box (-0.01, 0.01)^2
    reaches V = 0.148 at its corner, and 8 runs of docs/guide/make_ergodicity.py (seed 1)
    had total energies from 0.500 to 0.525, so no one law describes them.

    Examples
    --------
    >>> from sinktheory.model import RunSettings, Sink, Well
    >>> sink = Sink(Well(1.0, 0.99, 6, shape="symmetric"))
    >>> check_one_shell(sink, RunSettings(box=0.005))
    >>> check_one_shell(sink, RunSettings(box=0.01))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: box = 0.01 is not allowed: must be a start box whose \
runs share one energy shell (<= 0.0075 here) (particles starting at rest in it can add up to \
0.1481 (k V at its corner)...
    """
    largest = one_shell_box(sink, settings)
    if largest == settings.box:
        return
    e0 = settings.container_energy
    top = settings.total_energy_bound(sink) - e0
    raise ParameterError(
        "box", settings.box, f"a start box whose runs share one energy shell (<= "
        f"{largest:.2g} here)", why=f"particles starting at rest in it can add up to "
        f"{top:.4g} (k V at its corner) to a run's total energy, {100 * top / e0:.3g} % of "
        f"E0 = {e0:g}, while the law compared with is that of one total energy (runs within "
        f"{100 * ENERGY_SLACK:g} % of it)",
    )  # fmt: skip


def measure_lifetimes(
    sink,
    settings,
    *,
    transient: int,
    fractions=(0.2, 0.5, 0.8),
    tol: float | None = None,
    progress: bool | None = None,
) -> tuple[LawComparison, object]:
    """Simulate ``settings.runs`` runs of ``sink`` (:func:`sinktheory.simulate.simulate`)
    and compare their E_c after ``transient`` periods with the law at the runs' mean
    total energy.  Returns (comparison, simulation result).

    Examples
    --------
    >>> from sinktheory import RunSettings, Sink, Well
    >>> c, sim = measure_lifetimes(Sink(Well(0.5, 0.3, 4)), RunSettings(runs=2, periods=60),
    ...                            transient=20, fractions=[0.5], progress=False)
    >>> c.samples, c.runs, round(c.law.total_energy, 6)
    (41, 2, 0.5)
    """
    from ..simulate import simulate
    from .law import equilibrium_law

    _check_run(sink, settings)
    v.positive_int("transient", transient, minimum=0, maximum=settings.periods - 4)
    fractions = check_fractions(fractions)
    sim = simulate(sink, settings, tol=tol, progress=progress)
    law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
    return compare_with_law(
        sim.container_energy, law, transient=transient, fractions=fractions, seed=settings.seed
    ), sim
