"""Design measures of one energy absorber: how much, how fast, how reliably.

Everything is computed from the container energy of an ensemble sampled once per period,
E[r, j] = E(jT) (runs r = 0..R-1, j = 0..P), in the paper's units (container mass 1,
spring 1, period T = 2 pi), energies relative to the container's initial energy E0:

* **absorbed fraction** at a horizon h: 1 - <E>(hT)/E0, with the standard error of the
  ensemble mean (:func:`sinktheory.runstats.ensemble_mean`);
* **settling times** t50, t80 (``passage``): the first period j at which <E> falls below
  (1 - a) E0 (a = 50 % and 80 % absorbed) *and stays below* for the ``window`` periods
  that follow, j + 1, ..., j + window (:func:`sustained_crossing`; default window a tenth
  of the run, :func:`default_window`).  A dip below the level that comes back above it
  within the window does not count, so an ensemble that dips early and then returns does
  not pass for fast; a crossing later than P - window cannot be confirmed within the run
  and gives NaN, as does a level never reached;
* **long-time share**: the time average of E after ``transient`` periods, mean over runs
  +- standard error (:func:`sinktheory.sinkstats.sink_measures`), against the
  equipartition prediction E/(1 + k(1 + 1/n)) with a verdict (:data:`VERDICTS`); for a
  1-D attachment E/(1 + k(1 + 1/n)/2)
  (:func:`~sinktheory.sinkstats.equipartition_container_energy` with d = 1);
* **run-to-run spread**: the standard deviation of the runs' long-time averages;
* **recurrence risk**: the longest excursion of <E> back above the level (1 - a_risk) E0
  after it first fell below it (periods; 0 if it never came back, NaN if it never fell
  below), and the recurrence quantification of <E> (:func:`sinktheory.recurrence.rqa`,
  eps a fixed fraction of E0 so that designs compare).

Standard errors of the quantities that are not plain means (settling times, the
excursion and the RQA measures of <E>) come from a bootstrap over runs: ``bootstrap``
resamples of the R runs with replacement, each giving a resampled <E>(jT) and the measure
of it; the standard error is the standard deviation (ddof = 1) of the resampled values
that are finite.  The resampling is seeded from the point's seed, so it is reproducible.
The standard error of the spread s is s / sqrt(2 (R - 1)) (normal approximation).

Examples
--------
>>> import numpy as np
>>> e = np.array([[0.5, 0.3, 0.2, 0.1, 0.3, 0.1], [0.5, 0.2, 0.1, 0.1, 0.1, 0.1]])
>>> m = design_measures(e, e0=0.5, total_energy=0.5, particles=1, n=4, horizons=(1, 5),
...                     transient=2, bootstrap=20, seed=0)
>>> m.absorbed.round(3).tolist(), m.passage.tolist()  # <E> = 0.5, 0.25, 0.15, 0.1, 0.2, 0.1
([0.5, 0.8], [2.0, nan])
>>> m.window  # a tenth of the 5 periods, at least one
1
>>> m.excursion, m.verdict_name, round(m.long_time_mean, 4), round(m.equipartition, 4)
(0.0, 'equipartition', 0.1375, 0.2222)
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..results import Result
from ..runstats import ensemble_mean, spread
from ..sinkstats import equipartition_container_energy, sink_measures

__all__ = [
    "ABSORBED_LEVELS",
    "ATTACHMENTS",
    "BOOTSTRAP_TAG",
    "design_measures",
    "DesignMeasures",
    "horizons_of",
    "LINE_ATTACHMENTS",
    "MAX_BOOTSTRAP",
    "RQA_MEASURES",
    "VERDICTS",
    "WINDOW_FRACTION",
]

#: Fractions of E0 absorbed whose settling times are measured.
ABSORBED_LEVELS = (0.5, 0.8)
#: Default settling window as a fraction of the run length (:func:`default_window`).
WINDOW_FRACTION = 0.1
#: <E> below (1 - level) E0, as the fraction of E0 it compares with (exact decimals).
_REMAINING = {a: round(1.0 - a, 12) for a in ABSORBED_LEVELS}
#: Verdict codes of the long-time share against equipartition: within ``sigmas`` standard
#: errors (0), the container keeps more (+1: the drain is incomplete), or less (-1).
VERDICTS = {0: "equipartition", 1: "above", -1: "below"}
#: RQA measures of <E> kept per design.
RQA_MEASURES = (
    "recurrence_rate",
    "determinism",
    "laminarity",
    "trapping_time",
    "mean_recurrence_time",
)
#: Tag mixed into the point seed for the bootstrap (independent of the runs' seeds).
BOOTSTRAP_TAG = 0xB007
#: Most bootstrap resamples: the bootstrap's own relative error ~ 1 / sqrt(2 B) is 0.2 %
#: at 1e5 resamples, and each resample is a pass over the point's (P + 1) means.
MAX_BOOTSTRAP = 10**5


@dataclass(frozen=True)
class DesignMeasures(Result):
    """The measures of one design (see the module docstring); ``*_se`` standard errors.

    Attributes
    ----------
    horizons : ndarray (H,) of int
        Periods at which the absorbed fraction is given.
    absorbed, absorbed_se : ndarray (H,)
        1 - <E>(hT)/E0 and its standard error.
    levels : ndarray (2,)
        Absorbed fractions of the settling times (:data:`ABSORBED_LEVELS`).
    passage, passage_se : ndarray (2,)
        Settling time t50, t80: the first period from which <E> < (1 - level) E0 holds
        for ``window`` more periods (NaN if never; :func:`sustained_crossing`), and its
        bootstrap standard error.
    passage_reach : ndarray (2,)
        Share of the bootstrap resamples that settled below the level (1: robust, < 1:
        the settling depends on which runs are in the ensemble).
    long_time_mean, long_time_se : float
        Long-time container energy (after ``transient`` periods).
    equipartition : float
        E_total / (1 + k (1 + 1/n)) (1-D attachments:
        :func:`~sinktheory.sinkstats.equipartition_container_energy` with d = 1).
    equipartition_z : float
        (long_time_mean - equipartition) / long_time_se (inf when the s.e. is 0).
    verdict : int
        -1, 0 or +1 (:data:`VERDICTS`) with the threshold ``sigmas``.
    depth, depth_se : float
        Long-time fraction of E0 absorbed, 1 - long_time_mean / E0.
    spread, spread_se : float
        Run-to-run spread (std, ddof = 1) of the runs' long-time means, in energy units.
    excursion, excursion_se : float
        Longest excursion (periods) of <E> back above (1 - risk_level) E0 after its first
        passage below it.
    rqa, rqa_se : dict name -> float
        :data:`RQA_MEASURES` of <E> with eps = rqa_eps E0 (Theiler window 1).
    transient, sigmas, risk_level, rqa_eps, window : the settings used
    """

    horizons: np.ndarray
    absorbed: np.ndarray
    absorbed_se: np.ndarray
    levels: np.ndarray
    passage: np.ndarray
    passage_se: np.ndarray
    passage_reach: np.ndarray
    long_time_mean: float
    long_time_se: float
    equipartition: float
    equipartition_z: float
    verdict: int
    depth: float
    depth_se: float
    spread: float
    spread_se: float
    excursion: float
    excursion_se: float
    rqa: dict
    rqa_se: dict
    transient: int
    sigmas: float
    risk_level: float
    rqa_eps: float
    window: int

    @property
    def verdict_name(self) -> str:
        return VERDICTS[self.verdict]

    DIMS = {
        "horizons": ("horizon",),
        "absorbed": ("horizon",),
        "absorbed_se": ("horizon",),
        "levels": ("level",),
        "passage": ("level",),
        "passage_se": ("level",),
        "passage_reach": ("level",),
    }
    COORDS = {"horizons": "horizon", "levels": "level"}

    def items(self) -> dict:
        return {**super().items(), "verdict_name": self.verdict_name}


def horizons_of(text: str | Sequence[int], periods: int) -> tuple[int, ...]:
    """The horizons (periods) of the absorbed fraction: ``"auto"`` (P/10, P/3, P), or
    integers 1..P given as a sequence or a string separated by ``+`` or ``,``.

    Examples
    --------
    >>> horizons_of("auto", 1500), horizons_of("100+500", 1500), horizons_of([7], 10)
    ((150, 500, 1500), (100, 500), (7,))
    """
    periods = v.positive_int("periods", periods)
    if isinstance(text, str):
        if text.strip() == "auto":
            values = sorted({max(1, periods // 10), max(1, periods // 3), periods})
            return tuple(values)
        parts = [p for p in text.replace(",", "+").split("+")]
        if not parts or any(not p.strip() for p in parts):
            raise ParameterError(
                "horizons", text, "'auto' or periods separated by '+', e.g. 100+500+1500"
            )
        try:
            values = [float(p) for p in parts]
        except ValueError:
            raise ParameterError(
                "horizons", text, "'auto' or periods separated by '+', e.g. 100+500+1500"
            ) from None
    elif isinstance(text, Iterable):
        values = list(text)
    else:
        raise ParameterError("horizons", text, "'auto', periods separated by '+', or a list")
    out = [v.positive_int("horizons", x, maximum=periods) for x in values]
    if len(set(out)) != len(out) or not out:
        raise ParameterError("horizons", text, "distinct periods (at least one)")
    return tuple(sorted(out))


def _bootstrap_means(e: np.ndarray, replicates: int, seed: int) -> np.ndarray:
    """Resampled ensemble means (B, P + 1): runs drawn with replacement."""
    runs = e.shape[0]
    rng = np.random.default_rng(np.random.SeedSequence([int(seed), BOOTSTRAP_TAG]))
    idx = rng.integers(0, runs, size=(replicates, runs))
    counts = np.zeros((replicates, runs))
    np.add.at(counts, (np.arange(replicates)[:, None], idx), 1.0)
    return counts @ e / runs


def default_window(periods: int) -> int:
    """The default settling window: :data:`WINDOW_FRACTION` of the run, at least 1 period.

    Examples
    --------
    >>> default_window(1500), default_window(150), default_window(8)
    (150, 15, 1)
    """
    return max(1, round(WINDOW_FRACTION * int(periods)))


def sustained_crossing(mean, threshold: float, window: int) -> float:
    """First period j with ``mean[j], ..., mean[j + window]`` all below ``threshold``
    (NaN if there is none; j + window must be within the series).

    Examples
    --------
    >>> e = [1.0, 0.4, 0.6, 0.45, 0.4, 0.3, 0.3]   # dips at 1, back above at 2
    >>> sustained_crossing(e, 0.5, 0), sustained_crossing(e, 0.5, 2)
    (1.0, 3.0)
    >>> sustained_crossing(e, 0.5, 4), sustained_crossing(e, 0.2, 0)
    (nan, nan)
    """
    below = np.asarray(mean, dtype=float) < threshold
    window = int(window)
    if window + 1 > below.size:
        return math.nan
    held = np.lib.stride_tricks.sliding_window_view(below, window + 1).all(axis=1)
    first = np.flatnonzero(held)
    return float(first[0]) if first.size else math.nan


def longest_excursion(mean, threshold: float) -> float:
    """Longest run of consecutive periods with ``mean`` >= ``threshold`` after the first
    period with ``mean`` < ``threshold`` (0 if none; NaN if it never falls below).

    Examples
    --------
    >>> longest_excursion([0.5, 0.2, 0.3, 0.3, 0.1, 0.3], 0.25)
    2.0
    >>> longest_excursion([0.5, 0.4], 0.25)
    nan
    """
    m = np.asarray(mean, dtype=float)
    below = np.flatnonzero(m < threshold)
    if not below.size:
        return math.nan
    above = m[below[0] :] >= threshold
    best = run = 0
    for flag in above:
        run = run + 1 if flag else 0
        best = max(best, run)
    return float(best)


def _se(values: np.ndarray) -> float:
    """Standard deviation (ddof = 1) of the finite values (NaN if fewer than two)."""
    x = np.asarray(values, dtype=float)
    return spread(x[np.isfinite(x)])


def _rqa(series: np.ndarray, eps: float) -> dict:
    from ..recurrence import rqa  # imports numba kernels: lazily

    r = rqa(series, eps=eps)
    return {name: float(getattr(r, name)) for name in RQA_MEASURES}


#: Attachments whose particles move on a line (one degree of freedom each).
LINE_ATTACHMENTS = ("nes", "impact")
#: Every attachment the design explorer compares: the 2-D well and the 1-D absorbers.
ATTACHMENTS = ("well", *LINE_ATTACHMENTS)


def design_measures(
    energy_runs,
    *,
    e0: float,
    total_energy: float,
    particles: int,
    n: float,
    horizons: Sequence[int],
    transient: int | None = None,
    sigmas: float = 3.0,
    risk_level: float = 0.5,
    rqa_eps: float = 0.01,
    bootstrap: int = 50,
    seed: int = 0,
    window: int | None = None,
    attachment: str = "well",
) -> DesignMeasures:
    """The design measures of an ensemble (see the module docstring).

    Parameters
    ----------
    energy_runs : array (R, P + 1)
        Container energy E(jT) of every run.
    e0, total_energy : float > 0
        Initial container energy and the conserved total (mean over runs of H0).
    particles : int
        k.
    n : float > 0
        The wall stiffness: half the well's degree (equipartition prediction; a user's
        well's :func:`~sinktheory.design.point.equipartition_n`).
    horizons : sequence of int in 1..P, or text
        Periods at which to give the absorbed fraction (:func:`horizons_of`).
    transient : int, optional
        First period of the long-time window (default P // 2).
    sigmas : float > 0
        Verdict threshold in standard errors (default 3, as in the reproduction report).
    risk_level : float in (0, 1)
        Absorbed fraction whose level the recurrence risk watches (default 0.5).
    rqa_eps : float > 0
        RQA neighbourhood as a fraction of E0 (default 0.01, as for Fig. 9).
    bootstrap : int in [2, MAX_BOOTSTRAP]
        Bootstrap resamples of the runs for the standard errors.
    seed : int >= 0
        Seed of the bootstrap (mixed with :data:`BOOTSTRAP_TAG`).
    window : int in 0..P, optional
        Periods <E> must stay below a level after crossing it for the settling time
        (default :func:`default_window` of P; 0 gives the plain first passage).
    attachment : {"well", "nes", "impact"}
        The equipartition share of the 2-D sink (``"well"``) or of particles on a line
        (:func:`~sinktheory.sinkstats.equipartition_container_energy` with d = 1;
        ``"impact"``: rigid walls, n = inf).

    Returns
    -------
    DesignMeasures
    """
    e0 = v.positive("e0", e0)
    sigmas = v.positive("sigmas", sigmas)
    risk_level = v.positive("risk_level", risk_level)
    if not risk_level < 1:
        raise ParameterError("risk_level", risk_level, "a fraction in (0, 1)")
    rqa_eps = v.positive("rqa_eps", rqa_eps)
    bootstrap = v.positive_int("bootstrap", bootstrap, minimum=2, maximum=MAX_BOOTSTRAP)
    seed = v.positive_int("seed", seed, minimum=0)
    e = v.real_array("energy_runs", energy_runs, "an array (runs, periods + 1) of energies")
    s = sink_measures(
        e,
        e0=e0,
        total_energy=total_energy,
        particles=particles,
        n=n,
        transient=transient,
        fractions=(),  # the settling times below replace the plain first passages
    )
    P = e.shape[1] - 1
    window = (
        default_window(P)
        if window is None
        else v.positive_int("window", window, minimum=0, maximum=P)
    )
    horizons = np.array(horizons_of(horizons, P), dtype=int)
    mean, stderr = ensemble_mean(e)
    runs = e.shape[0]
    v.fits_memory("bootstrap", bootstrap, 8.0 * bootstrap * (runs + P + 1),
                  f"{bootstrap} resample(s) of {runs} run(s) x {P + 1} values",
                  "smaller")  # fmt: skip

    # settling times and their bootstrap
    passage = np.array([sustained_crossing(mean, f * e0, window) for f in _REMAINING.values()])
    boot = _bootstrap_means(e, bootstrap, seed)
    b_pass = np.array(
        [[sustained_crossing(b, f * e0, window) for f in _REMAINING.values()] for b in boot]
    )  # (B, 2)
    passage_se = np.array(
        [_se(b_pass[:, i]) if np.isfinite(passage[i]) else math.nan for i in range(2)]
    )
    reach = np.isfinite(b_pass).mean(axis=0)

    # long-time share and its verdict
    share = s.equipartition
    if v.choice("attachment", attachment, ATTACHMENTS) != "well":
        rigid = math.inf if attachment == "impact" else n
        share = equipartition_container_energy(total_energy, particles, rigid, dimension=1)
    se = s.long_time_stderr
    diff = s.long_time_mean - share
    z = diff / se if se > 0 else (0.0 if diff == 0 else math.copysign(math.inf, diff))
    verdict = 0 if abs(z) <= sigmas else (1 if z > 0 else -1)

    # recurrence risk
    level = (1.0 - risk_level) * e0
    excursion = longest_excursion(mean, level)
    excursion_se = (
        _se(np.array([longest_excursion(b, level) for b in boot]))
        if np.isfinite(excursion)
        else math.nan
    )
    eps = rqa_eps * e0
    rq = _rqa(mean, eps)
    b_rqa = [_rqa(b, eps) for b in boot]
    rq_se = {name: _se(np.array([r[name] for r in b_rqa])) for name in RQA_MEASURES}

    return DesignMeasures(
        horizons=horizons,
        absorbed=1.0 - mean[horizons] / e0,
        absorbed_se=stderr[horizons] / e0,
        levels=np.array(ABSORBED_LEVELS),
        passage=passage,
        passage_se=passage_se,
        passage_reach=reach,
        long_time_mean=s.long_time_mean,
        long_time_se=se,
        equipartition=share,
        equipartition_z=float(z),
        verdict=verdict,
        depth=1.0 - s.long_time_mean / e0,
        depth_se=se / e0,
        spread=s.run_spread,
        spread_se=s.run_spread / math.sqrt(2 * (runs - 1)) if runs > 1 else math.nan,
        excursion=excursion,
        excursion_se=excursion_se,
        rqa=rq,
        rqa_se=rq_se,
        transient=s.transient,
        sigmas=sigmas,
        risk_level=risk_level,
        rqa_eps=rqa_eps,
        window=window,
    )
