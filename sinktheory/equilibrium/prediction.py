"""Predicted relaxation of the container energy, and how long an ensemble must run.

The model
---------
E_c is treated as a one-dimensional reversible diffusion on [0, E] whose stationary
density is the exact law p (:mod:`sinktheory.equilibrium.law`).  Only the drift D1 is
measured (:func:`~sinktheory.equilibrium.kramers.measure_kramers_moyal`: its slow part,
from the moments' growth between the base lag tau_0 and the lag tau, at the Gauss grid's
energies), and it is fitted by a straight line D1 = a + b E_c (least squares weighted by
the runs' standard errors): the measured drift is close to linear, and a free
interpolation through the points is dominated by their noise where the law lives (there
the drift is 0 within its errors for k >= 3, and the settling time then scatters by
factors between seeds).  The diffusion follows from the fluctuation-dissipation relation
D1 p = d(D2 p)/dE with zero flux at both ends,

    D2(E) p(E) = -\\int_E^{E_tot} D1 p dE',

after D1 is shifted by its law average (which must vanish: d<E_c>/dt = <D1> = 0 at
equilibrium).  For the line this gives D2 p = -b \\int_E^{E_tot} (E' - <E_c>) p dE' >= 0,
and the mean relaxes exactly as <E_c>(t) - mu = (E0 - mu) exp(-t / t_r), t_r = -1 / b,
so the settling time is t_r ln(|E0 - mu| / (f mu)).  The spread of E_c comes from the
Fokker-Planck flux J = -D2 p_eq d(p / p_eq)/dE, discretised on ``cells`` cells of
s = E_c / E as a reversible birth-death chain with the law's cell masses pi_i as its
stationary state (exactly) and rates G_{i+1/2} / (h pi_i) across face i + 1/2 (G = D2 p
in s), solved exactly in time by the eigenvectors of the symmetrised generator.  So the
prediction ends at the law's mean and spread by construction.

What it is worth
----------------
E_c is not Markov: the rate of any one-variable model fitted at lag tau grows with tau
(the slowest implied timescale of the E_c transition matrix, Fig. 8 well, 16 points x
100 runs, seeds 0 and 1: 11-12, 19-22, 39, 54-57, 75-80, 101-110 periods at lags 4 ... 128
for k = 1, whose measured tail time is 118; 15-20, 35-37, 73, 135, 219-257, 313-393 for
k = 5, tail time 1260).  The base-lag drift removes the fast exchange of the first
periods, but what is left still depends on tau_0 and tau.  Against measured settling
times the prediction is off by a factor up to :data:`MODEL_FACTOR`
(docs/guide/equilibrium.rst, benchmarks/bench_prediction.py); treat it as an estimate of
the order of magnitude and of trends in k, m, beta and n, and measure
(:func:`~sinktheory.equilibrium.relaxation.measure_relaxation`) when the number matters.

Examples
--------
The law-constrained chain of a Jacobi diffusion (drift c (a (1 - s) - b s), Beta(a, b)
law) has the diffusion c s (1 - s) and relaxes its mean as exp(-c (a + b) t):

>>> from scipy import stats
>>> s = np.linspace(0, 1, 41)
>>> chain = law_chain(stats.beta(2, 3).pdf, s, 0.01 * (2 * (1 - s) - 3 * s), cells=400)
>>> mean, _ = chain.moments(0.999, np.array([0.0, 40.0]))
>>> exact = 0.4 + (chain.centres[-1] - 0.4) * np.exp(-0.05 * 40)
>>> bool(abs(mean[1] - exact) < 2e-3)
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .. import validation as v
from ..errors import NumericalError, ParameterError
from ..model import RunSettings, Sink
from ..results import Result
from .kramers import KramersMoyal, measure_kramers_moyal
from .law import equilibrium_law

__all__ = [
    "law_chain",
    "LawChain",
    "measure_settling",
    "MODEL_FACTOR",
    "predict_relaxation",
    "RelaxationPrediction",
    "Settling",
    "settling_periods",
    "start_total_energy",
]

#: Largest factor between predicted and measured settling times found on the benchmark's
#: cases (benchmarks/bench_prediction.py); the predicted interval of
#: :func:`settling_periods` is widened by it.
MODEL_FACTOR = 2.5
#: Default lag, base lag (periods), grid points and runs per point of the drift.
LAG, BASE_LAG, POINTS, RUNS = 64, 8, 12, 100
#: Sub-cell Gauss nodes of the cell integrals of the law.
_NODES = 6


@dataclass(frozen=True)
class LawChain:
    """The discretised law-constrained diffusion (module docstring), in s = E_c / E.

    Attributes
    ----------
    centres : the law's mean of s in each cell
    masses : pi_i, the law's mass of each cell (sum 1)
    conductance : G at the interior faces (D2 p in s units, per period)
    shift : the law average of the drift that was removed (s per period)
    clipped : interior faces where G came out negative and was set to 0
    """

    centres: np.ndarray
    masses: np.ndarray
    conductance: np.ndarray
    shift: float
    clipped: int

    @cached_property
    def spectrum(self) -> tuple[np.ndarray, np.ndarray]:
        """Eigenvalues (ascending, <= 0) and eigenvectors of the symmetrised generator."""
        from scipy.linalg import eigh_tridiagonal

        h = 1.0 / self.masses.size
        pi = np.maximum(self.masses, 1e-300)
        g = self.conductance / h
        diag = np.zeros(pi.size)
        diag[:-1] -= g / pi[:-1]
        diag[1:] -= g / pi[1:]
        return eigh_tridiagonal(diag, g / np.sqrt(pi[:-1] * pi[1:]))

    def moments(self, start: float, times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Mean and standard deviation of s at ``times`` (periods), started in the cell of
        s = ``start``."""
        lam, vec = self.spectrum
        j = min(int(start * self.masses.size), self.masses.size - 1)
        root = np.sqrt(np.maximum(self.masses, 1e-300))
        decay = np.exp(np.outer(np.minimum(lam, 0.0), times))  # (mode, time)
        weights = vec[j] / root[j]
        first = ((self.centres * root) @ vec * weights) @ decay
        second = ((self.centres**2 * root) @ vec * weights) @ decay
        return first, np.sqrt(np.maximum(second - first**2, 0.0))


def law_chain(pdf, s_points, drift, *, cells: int = 150) -> LawChain:
    """The law-constrained chain of the density ``pdf`` of s on [0, 1] with the drift
    ``drift`` (s per period) given at ``s_points`` (linear in between, constant beyond).

    Examples
    --------
    >>> from scipy import stats
    >>> c = law_chain(stats.beta(1, 2).pdf, [0.0, 1.0], [0.01, -0.02], cells=50)
    >>> round(float(c.masses.sum()), 12), round(float(c.masses @ c.centres), 6)
    (1.0, 0.333333)
    """
    cells = v.positive_int("cells", cells, minimum=10)
    s_points = np.asarray(s_points, dtype=float)
    drift = np.asarray(drift, dtype=float)
    x, w = np.polynomial.legendre.leggauss(_NODES)
    h = 1.0 / cells
    nodes = (np.arange(cells)[:, None] + 0.5 * (x + 1)) * h  # (cell, node)
    weights = 0.5 * w * h
    p = np.asarray(pdf(nodes), dtype=float) * weights
    masses = p.sum(axis=1)
    total = masses.sum()
    p, masses = p / total, masses / total
    centres = (p * nodes).sum(axis=1) / np.maximum(masses, 1e-300)
    d1 = np.interp(nodes, s_points, drift)
    shift = float(np.sum(d1 * p))
    flux = ((d1 - shift) * p).sum(axis=1)  # \int_cell (D1 - shift) p
    above = np.cumsum(flux[::-1])[::-1]  # \int from cell i's lower face to 1
    g = -above[1:]  # at the faces i + 1/2, i = 0 .. cells - 2
    clipped = int(np.sum(g < 0))
    return LawChain(centres, masses, np.maximum(g, 0.0), shift, clipped)


@dataclass(frozen=True)
class RelaxationPrediction(Result):
    """Predicted <E_c>(t) from the start (E0, particles at rest) by the law-constrained
    diffusion (module docstring), with bootstrap errors from the measured drift.

    Attributes
    ----------
    energy : E0, the container's energy at t = 0
    total_energy : E, the start's E0 plus the particles' potential energy
    particles, mass : k and m
    target : the law's mean <E_c>
    fraction : f, the relative excess that counts as settled
    times : periods at which the curve is given
    means, spread : predicted ensemble mean of E_c and the run-to-run standard deviation
    low, high : pointwise bootstrap band of ``means`` at ``level``
    settle_time, settle_low, settle_high : predicted t_f and its bootstrap interval (the
        statistical error of the drift only; the model's own error is up to a factor
        :data:`MODEL_FACTOR`)
    rate_time, rate_low, rate_high : t_r, the relaxation time of the predicted mean
    level, resamples : confidence level and bootstrap resamples
    lag, base_lag, points, runs, seed : how the drift was measured
    drift_intercept, drift_slope : the fitted drift D1 = a + b E_c (a in energy per period,
        b per period; -1 / b is ``rate_time``)
    coefficients : one line on the drift's measurement
    model : one line on what the prediction is and what it is worth
    """

    energy: float
    total_energy: float
    particles: int
    mass: float
    target: float
    fraction: float
    times: np.ndarray
    means: np.ndarray
    spread: np.ndarray
    low: np.ndarray
    high: np.ndarray
    settle_time: float
    settle_low: float
    settle_high: float
    rate_time: float
    rate_low: float
    rate_high: float
    level: float
    resamples: int
    lag: int
    base_lag: int
    points: int
    runs: int
    seed: int
    drift_intercept: float
    drift_slope: float
    coefficients: str
    model: str

    DIMS = {name: ("time",) for name in ("means", "spread", "low", "high")}
    COORDS = {"times": "time"}


def _drifts(km: KramersMoyal, j: int, draws: np.ndarray | None) -> np.ndarray:
    """The drift at lag index ``j`` (point,), from runs drawn as ``draws`` (point, run)
    indices, or all runs."""
    col = int(np.flatnonzero(km.increment_lags == km.lags[j])[0])
    inc = km.increments[:, col]
    if km.base_lag:
        inc = inc - km.increments[:, int(np.flatnonzero(km.increment_lags == km.base_lag)[0])]
    if draws is not None:
        inc = np.take_along_axis(inc, draws, axis=1)
    return inc.mean(axis=1) / km.spans[j]


def fit_line(x, y, stderr) -> tuple[float, float]:
    """(a, b) of the straight line a + b x through ``y`` by least squares weighted with
    1 / stderr^2.

    Examples
    --------
    >>> [round(x, 12) for x in fit_line([0, 1, 2], [1, 3, 5], [1, 1, 1])]
    [1.0, 2.0]
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    w = 1 / np.asarray(stderr, dtype=float)
    design = np.column_stack([np.ones_like(x), x]) * w[:, None]
    (a, b), *_ = np.linalg.lstsq(design, y * w, rcond=None)
    return float(a), float(b)


def _settling(slope: float, s0: float, mu: float, fraction: float) -> tuple[float, float]:
    """(t_f, t_r) of the mean's exponential approach with rate -slope (inf if slope >= 0)."""
    if slope >= 0:
        return math.inf, math.inf
    t_r = -1 / slope
    return t_r * max(math.log(abs(s0 - mu) / (fraction * mu)), 0.0), t_r


def start_total_energy(sink: Sink, energy: float, seed: int = 0, runs: int = 16) -> float:
    """Total energy E of the paper's start (container at E0 = ``energy`` at rest, particles
    at rest at the seeded random positions of the start box): the mean over ``runs`` starts.

    Examples
    --------
    >>> from sinktheory.canonical import FIG8_SINK
    >>> abs(start_total_energy(FIG8_SINK, 0.5) - 0.5) < 1e-10
    True
    """
    from ..ensemble import random_positions, start_state, total_energy

    settings = RunSettings(energy=energy, runs=runs, seed=seed)
    settings.check(sink)
    rows = start_state(sink, energy, random_positions(settings, sink.particles))
    return float(np.mean(total_energy(sink, rows)))


def predict_relaxation(
    sink: Sink,
    energy: float = 0.5,
    *,
    fraction: float = 0.05,
    periods: int | None = None,
    points: int = POINTS,
    runs: int = RUNS,
    lag: int = LAG,
    base_lag: int = BASE_LAG,
    seed: int = 0,
    tol: float = 1e-6,
    level: float = 0.95,
    resamples: int = 199,
    cells: int = 150,
) -> RelaxationPrediction:
    """Predicted relaxation of <E_c> from the paper's start at E0 = ``energy``.

    The drift is measured at ``points`` energies x ``runs`` runs started on the shell
    (base lag ``base_lag``, lag ``lag``, seed ``seed``, simulator tolerance ``tol``; cost
    points x runs x lag run-periods), the model built and solved (module docstring), and
    the drift bootstrapped over the runs of each point ``resamples`` times.

    Parameters
    ----------
    sink : Sink
    energy : float > 0
        E0, the container's starting energy.
    fraction : float in (0, 1)
        Relative excess that counts as settled.
    periods : int >= 1, optional
        Length of the curve (default: 1.5 times the upper end of the settling interval).
    points, runs : int >= 3, int >= 4
    lag, base_lag : int
        The lag tau > tau_0 >= 0 of the drift.
    seed, tol, level, resamples, cells : see the module docstring.

    Examples
    --------
    >>> from sinktheory.canonical import FIG8_WELL
    >>> sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    >>> pred = predict_relaxation(sink, points=4, runs=8, lag=16, resamples=20, seed=3)
    >>> bool(pred.settle_low <= pred.settle_time <= pred.settle_high)
    True
    >>> bool(abs(pred.means[-1] - pred.target) < 0.05 * pred.target)
    True
    """
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    start = v.positive("energy", energy)  # E0
    fraction = v.positive("fraction", fraction)
    if not fraction < 1:
        raise ParameterError("fraction", fraction, "a number in (0, 1)")
    points = v.positive_int("points", points, minimum=3)
    runs = v.positive_int("runs", runs, minimum=4)
    base_lag = v.positive_int("base_lag", base_lag, minimum=0)
    lag = v.positive_int("lag", lag, minimum=base_lag + 1)
    seed = v.positive_int("seed", seed, minimum=0)
    if not 0 < v.finite("level", level) < 1:
        raise ParameterError("level", level, "a number in (0, 1)")
    resamples = v.positive_int("resamples", resamples, minimum=20)
    if periods is not None:
        periods = v.positive_int("periods", periods)
    total = start_total_energy(sink, start, seed)
    law = equilibrium_law(sink, total)  # checks the energy against the well
    km = measure_kramers_moyal(sink, total, points=points, lags=(lag,), runs=runs, seed=seed,
                               tol=tol, base_lag=base_lag)  # fmt: skip
    j = km.lag_index(lag)
    s = km.container_energies / total
    s0, mu = start / total, law.mean_fraction
    # the drift in s = E_c / E per period, ds/dt = a + b s
    stderr = np.maximum(km.drift_stderr[:, j], np.max(km.drift_stderr[:, j]) * 1e-6) / total
    rng = np.random.default_rng([seed, 1])
    slopes = np.array([fit_line(s, _drifts(km, j, rng.integers(0, runs, (points, runs))) / total,
                                stderr)[1] for _ in range(resamples)])  # fmt: skip
    a, b = fit_line(s, _drifts(km, j, None) / total, stderr)
    if b >= 0:
        raise NumericalError(
            f"predict_relaxation: the measured drift does not fall with E_c (slope {b:.3g} "
            f"per period); the model cannot relax (more runs or another lag)"
        )
    q = (1 - level) / 2
    settle, rate = _settling(b, s0, mu, fraction)
    boot = np.array([_settling(x, s0, mu, fraction) for x in slopes])
    settle_low, settle_high = np.quantile(boot[:, 0], [q, 1 - q], method="inverted_cdf").tolist()
    rate_low, rate_high = np.quantile(boot[:, 1], [q, 1 - q], method="inverted_cdf").tolist()
    ends = [x for x in (settle_high, settle, 10.0) if math.isfinite(x)]
    horizon = periods or int(math.ceil(1.5 * max(ends)))
    times = np.linspace(0.0, horizon, 401)
    chain = law_chain(law.pdf, s, a + b * s, cells=cells)
    spread = chain.moments(s0, times)[1]  # its mean is the exponential, to ~1e-3
    mean = mu + (s0 - mu) * np.exp(b * times)
    band = [mu + (s0 - mu) * np.exp(x * times) for x in np.quantile(slopes, [q, 1 - q])]
    model = (
        f"1-D Fokker-Planck in E_c with the law as its stationary state; drift measured "
        f"(base lag {base_lag}, lag {lag} periods) and fitted by a line, diffusion from "
        f"fluctuation-dissipation; E_c is not Markov, so the settling time is an estimate "
        f"within a factor of ~{MODEL_FACTOR:g} (docs/guide/equilibrium.rst)"
    )
    return RelaxationPrediction(
        energy=start,
        total_energy=total,
        particles=sink.particles,
        mass=sink.mass,
        target=law.mean,
        fraction=fraction,
        times=times,
        means=total * mean,
        spread=total * spread,
        low=total * np.minimum(*band),
        high=total * np.maximum(*band),
        settle_time=settle,
        settle_low=settle_low,
        settle_high=settle_high,
        rate_time=rate,
        rate_low=rate_low,
        rate_high=rate_high,
        level=level,
        resamples=resamples,
        lag=lag,
        base_lag=base_lag,
        points=points,
        runs=runs,
        seed=seed,
        drift_intercept=total * a,
        drift_slope=b,
        coefficients=km.message,
        model=model,
    )


@dataclass(frozen=True)
class Settling(Result):
    """How long an ensemble started at E0 must run for its mean E_c to settle.

    Attributes
    ----------
    periods : the settling time t_f (periods)
    low, high : its interval: the bootstrap interval when measured; when predicted, the
        bootstrap interval widened by the model's factor (low / MODEL_FACTOR,
        high * MODEL_FACTOR)
    source : "measured" or "predicted"
    extrapolated : measured only: the crossing lies beyond the runs' record
    fraction : f
    note : one line on how it was obtained
    """

    periods: float
    low: float
    high: float
    source: str
    extrapolated: bool
    fraction: float
    note: str


def settling_periods(
    sink: Sink,
    energy: float = 0.5,
    *,
    fraction: float = 0.05,
    measure: tuple[int, int] | None = None,
    seed: int = 0,
    tol: float = 1e-6,
) -> Settling:
    """How many periods an ensemble of ``sink`` started at E0 = ``energy`` (particles at
    rest) takes until its mean E_c is within ``fraction`` of the law's mean.

    Without ``measure`` the answer is predicted (:func:`predict_relaxation` with its
    defaults: seconds to a minute, k = 1 to 5) and its interval is widened by the model's
    known error, a factor :data:`MODEL_FACTOR` either way: a scene that must show the
    settled state should run at least ``high`` periods.  With ``measure = (runs, periods)``
    that ensemble is simulated (at ``tol``) and the settling time read by
    :func:`~sinktheory.equilibrium.relaxation.measure_relaxation` (its interval is
    statistical only; ``extrapolated`` says the crossing lies beyond the record, then run
    longer).

    Examples
    --------
    >>> from sinktheory.canonical import FIG8_WELL
    >>> sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    >>> s = settling_periods(sink, measure=(8, 600))
    >>> s.source, bool(s.low <= s.periods <= s.high)
    ('measured', True)
    """
    if measure is None:
        p = predict_relaxation(sink, energy, fraction=fraction, seed=seed, tol=tol)
        return Settling(
            periods=p.settle_time,
            low=p.settle_low / MODEL_FACTOR,
            high=p.settle_high * MODEL_FACTOR,
            source="predicted",
            extrapolated=False,
            fraction=fraction,
            note=p.model,
        )
    r, sim = measure_settling(sink, energy, measure, fraction=fraction, seed=seed, tol=tol)
    return Settling(
        periods=r.settle_time,
        low=r.settle_low,
        high=r.settle_high,
        source="measured",
        extrapolated=r.extrapolated,
        fraction=fraction,
        note=sim.message,
    )


def measure_settling(sink: Sink, energy: float, measure, *, fraction: float = 0.05,
                     seed: int = 0, tol: float = 1e-6, resamples: int = 199):  # fmt: skip
    """(:class:`~sinktheory.equilibrium.relaxation.Relaxation`, the simulation) of
    ``measure = (runs, periods)`` runs from the paper's start at E0 = ``energy``."""
    from ..simulate import simulate
    from .relaxation import measure_relaxation

    try:
        runs, periods = measure
    except (TypeError, ValueError):
        raise ParameterError("measure", measure, "a pair (runs, periods)") from None
    runs = v.positive_int("measure", runs, minimum=3)
    periods = v.positive_int("measure", periods, minimum=24)
    settings = RunSettings(energy=energy, runs=runs, periods=periods, seed=seed)
    settings.check(sink)
    sim = simulate(sink, settings, tol=tol, progress=False)
    law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
    window = min(50, max(1, (periods + 1) // 12))
    r = measure_relaxation(sim.container_energy, law.mean, fraction=fraction, window=window,
                           resamples=resamples, seed=seed)  # fmt: skip
    return r, sim
