"""Chaotic or regular: the verdict on finite-time exponents, and its statistical basis.

On a regular orbit deviations grow at most linearly (shear), so the finite-time exponent
decays like ln t / t (tests/chaos/test_chaos.py: the integrable case gives lambda_1 t / ln t ~ 1).
An exponent is called *chaotic* when its mean over runs exceeds that envelope with margin,
by two standard errors:

    mean - 2 s.e. > THRESHOLD_FACTOR ln(t) / t,    t = P T,

and *regular* otherwise.  The Floquet theory predicts regular motion where y = 0 is stable
(with the container fixed); :func:`agreement` gives the share of betas of a chaos map
(:func:`sinktheory.sweep.chaosmap.chaos_map`) where the two coincide, judging the map run
by run (:func:`map_calls`: every run regular, every run chaotic, or mixed, which is
listed with its regular fraction and not scored).  The transverse exponent's verdict
(the test above on its mean) measures how much of the chaos comes from the instability
of y = 0 itself.

**Mixed ensembles are split, not averaged.**  Where the phase space holds islands, some
runs of an ensemble are regular and the others chaotic, and the mean lambda_1 depends on
how many start in an island, that is on the start distribution.  :func:`split` judges
each run on its own, by the same envelope:

    run regular  <=>  lambda_1(run) <= THRESHOLD_FACTOR ln(t) / t,   t the span it was
    averaged over,

and reports the fraction of regular runs and lambda_1 of each group with their standard
errors (:class:`Split`; one run in a group gives NaN, the single-run rule of
:mod:`sinktheory.runstats`).  On a regular orbit the finite-time exponent sits near
ln(t) / t (within a factor of about 1.5 on the rigid billiard's island and rectangle),
while the chaotic runs seen so far stay far above the envelope (lambda_1 > 0.3 at
t ~ 10^3), so the rule falls in the gap of the per-run distribution; :attr:`Split.gap`
gives the largest regular and the smallest chaotic value, to check that it does.

Examples
--------
>>> round(threshold(300), 5)
0.012
>>> chaotic([0.1, 0.01], [0.01, 0.01], 300).tolist()
[True, False]
>>> s = split([0.002, 0.004, 0.43, 0.44], 300)
>>> s.regular, s.runs, round(s.chaotic_mean, 3)
(2, 4, 0.435)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..limits import MAX_PERIODS
from ..runstats import mean_stderr, plus_minus

__all__ = [
    "THRESHOLD_FACTOR",
    "Split",
    "SPLIT_RESULTS",
    "agreement",
    "chaotic",
    "map_calls",
    "split",
    "threshold",
    "verdicts",
]

#: The finite-time exponent of a regular orbit is ~ ln t / t; a chaotic verdict needs the
#: mean minus two standard errors above this factor times ln t / t.
THRESHOLD_FACTOR = 3.0


def threshold(periods: int) -> float:
    """THRESHOLD_FACTOR ln(t) / t at t = periods x 2 pi (per unit time)."""
    count = v.positive("periods", periods)
    if count > MAX_PERIODS:
        raise ParameterError("periods", periods, f"a number in (0, {MAX_PERIODS:g}]")
    t = count * 2.0 * math.pi
    return THRESHOLD_FACTOR * math.log(t) / t


def chaotic(mean, se, periods: int):
    """True where an exponent is chaotic: its mean less two standard errors above
    :func:`threshold` (arrays or numbers).

    No verdict without a standard error (the rule for a single run,
    :mod:`sinktheory.runstats`): a NaN ``se`` is refused, never read as regular.

    >>> chaotic([0.1], [float("nan")], 300)
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: se = nan is not allowed: must be finite standard \
errors >= 0 (from two runs or more: one run has none, so no verdict)
    """
    mean, se = v.real_array("mean", mean), v.real_array("se", se)
    try:
        np.broadcast_shapes(mean.shape, se.shape)
    except ValueError:
        raise ParameterError(
            "se", f"shape {se.shape}", f"one per mean, shape {mean.shape}"
        ) from None
    bad = ~(np.isfinite(se) & (se >= 0))
    if bad.any():
        raise ParameterError(
            "se",
            float(se[bad].flat[0]),
            "finite standard errors >= 0 (from two runs or more: one run has none, so no verdict)",
        )
    return mean - 2 * se > threshold(periods)


@dataclass(frozen=True)
class Split:
    """An ensemble's lambda_1 split into regular and chaotic runs (:func:`split`).

    Attributes
    ----------
    threshold : the per-run envelope THRESHOLD_FACTOR ln(t) / t
    runs, regular : how many runs, how many of them regular
    fraction, fraction_se : regular / runs and its standard error (that of the mean of the
        0/1 indicator over the runs; NaN from one run)
    regular_mean, regular_se, chaotic_mean, chaotic_se : lambda_1 of each group, mean and
        standard error (NaN for an empty group; the standard error NaN for one run)
    gap : (largest regular lambda_1, smallest chaotic lambda_1), NaN where a group is empty
    starts : the start distribution, in words (it sets the fraction)
    """

    threshold: float
    runs: int
    regular: int
    fraction: float
    fraction_se: float
    regular_mean: float
    regular_se: float
    chaotic_mean: float
    chaotic_se: float
    gap: tuple[float, float]
    starts: str = ""

    @property
    def mixed(self) -> bool:
        """Both groups hold runs: the ensemble mean of lambda_1 depends on the starts."""
        return 0 < self.regular < self.runs

    def stored(self) -> dict[str, float]:
        """What a sweep point stores of the split (:data:`SPLIT_RESULTS`; read back by
        :func:`stored_split`).

        >>> split([0.002, 0.004, 0.43], 300).stored()["regular_runs"]
        2.0
        """
        return {"regular_runs": float(self.regular), "lambda1_regular": self.regular_mean,
                "lambda1_regular_se": self.regular_se, "lambda1_chaotic": self.chaotic_mean,
                "lambda1_chaotic_se": self.chaotic_se}  # fmt: skip

    def as_dict(self) -> dict:
        """JSON-ready (NaN as None)."""

        def f(x):
            return None if math.isnan(x) else float(x)

        return {
            "rule": "regular when lambda_1 <= 3 ln(t)/t of the span it was averaged over",
            "threshold": self.threshold, "runs": self.runs, "regular": self.regular,
            "mixed": self.mixed, "regular_fraction": f(self.fraction),
            "regular_fraction_stderr": f(self.fraction_se),
            "regular_lambda1": {"mean": f(self.regular_mean), "stderr": f(self.regular_se)},
            "chaotic_lambda1": {"mean": f(self.chaotic_mean), "stderr": f(self.chaotic_se)},
            "gap": [f(g) for g in self.gap], "starts": self.starts,
        }  # fmt: skip

    def text(self) -> str:
        """One line for the commands' text output.

        Examples
        --------
        >>> print(split([0.003, 0.41, 0.45], 300).text())  # doctest: +NORMALIZE_WHITESPACE
        runs: 1 of 3 regular (lambda_1 <= 3 ln t/t = 0.012), regular 0.003
        (no standard error from one run), chaotic 0.43 +- 0.02
        """

        def group(count, mean, se):
            return "none" if count == 0 else plus_minus(mean, se, ".3g")

        where = f"; starts: {self.starts}" if self.starts else ""
        return (
            f"runs: {self.regular} of {self.runs} regular (lambda_1 <= "
            f"{THRESHOLD_FACTOR:g} ln t/t = {self.threshold:.3g}{where}), regular "
            f"{group(self.regular, self.regular_mean, self.regular_se)}, chaotic "
            f"{group(self.runs - self.regular, self.chaotic_mean, self.chaotic_se)}"
        )


#: The results a sweep point stores of its Lyapunov runs' split (:meth:`Split.stored`),
#: name -> description; all NaN where the point has no Lyapunov runs.
SPLIT_RESULTS = {
    "regular_runs": "Lyapunov runs with lambda_1 <= 3 ln t / t (regular; NaN without)",
    "lambda1_regular": "lambda_1 of the regular Lyapunov runs (NaN if none)",
    "lambda1_regular_se": "its standard error (NaN for fewer than two runs)",
    "lambda1_chaotic": "lambda_1 of the chaotic Lyapunov runs (NaN if none)",
    "lambda1_chaotic_se": "its standard error (NaN for fewer than two runs)",
}


def split(lambda1, periods: float, starts: str = "") -> Split:
    """Regular and chaotic runs of an ensemble (module docstring): ``lambda1`` one value
    per run, averaged over ``periods`` periods of T = 2 pi (after any transient).

    Runs whose lambda_1 is not finite are refused, not dropped.

    Examples
    --------
    >>> s = split([0.003, 0.004, 0.5], 300, starts="uniform in the table")
    >>> s.mixed, round(s.fraction, 3), s.gap
    (True, 0.667, (0.004, 0.5))
    >>> split([1.2], 300).chaotic_se
    nan
    """
    from ..errors import ParameterError

    lam = v.real_array("lambda1", lambda1).ravel()
    if lam.size == 0 or not np.all(np.isfinite(lam)):
        raise ParameterError("lambda1", "empty or not finite", "finite values, one per run")
    cut = threshold(periods)
    low = lam <= cut
    fraction, fraction_se = mean_stderr(low.astype(float))
    rm, rse = mean_stderr(lam[low])
    cm, cse = mean_stderr(lam[~low])
    gap = (float(lam[low].max()) if low.any() else math.nan,
           float(lam[~low].min()) if (~low).any() else math.nan)  # fmt: skip
    return Split(cut, int(lam.size), int(low.sum()), fraction, fraction_se, rm, rse, cm, cse,
                 gap, starts)  # fmt: skip


def point_values(ds, name: str, default):
    """Parameter ``name`` of each point of a sweep, in the order of
    ``ds.lambda1.values.ravel()``: its coordinate where it was swept, else its fixed value
    (an attribute), else ``default``."""
    if name in ds.coords and ds[name].dims:
        return ds[name].broadcast_like(ds.lambda1).transpose(*ds.lambda1.dims).values.ravel()
    return np.full(ds.lambda1.size, ds.attrs.get(name, default), dtype=object)


def box_starts(box) -> str:
    """The sink's start distribution in words, for a start box of half-width ``box``."""
    return "" if box is None else (
        f"particles at rest, uniform in (-{box:g}, {box:g})^2 around the centre; container "
        "at X = sqrt(2 E0) at rest")  # fmt: skip


def check_map(ds, *names: str, attrs: tuple[str, ...] = (), name: str = "ds") -> None:
    """Refuse ``ds`` (naming ``name``) unless it is an xarray Dataset holding the variables
    ``names`` and the attributes ``attrs`` (a chaos map of
    :func:`sinktheory.sweep.chaosmap.chaos_map` holds them all)."""
    import xarray as xr

    allowed = ("a chaos map (an xarray Dataset of sinktheory.sweep.chaosmap.chaos_map) with "
               + ", ".join((*names, *(f"attribute {a}" for a in attrs))))  # fmt: skip
    if not isinstance(ds, xr.Dataset):
        raise ParameterError(name, type(ds).__name__, allowed)
    missing = [n for n in names if n not in ds] + [a for a in attrs if a not in ds.attrs]
    if missing:
        raise ParameterError(name, f"a Dataset without {', '.join(missing)}", allowed)


def map_split(ds) -> list[Split]:
    """:func:`split` at every point of a chaos map (the ``chaos`` sweep kind; its per-run
    ``lambda1_runs``), in the order of ``ds.lambda1.values.ravel()``.  Each point's span
    is the periods its lambda_1 ran less the transient; the starts are the map's box
    (transient and box read per point where they were swept)."""
    check_map(ds, "lambda1", "lambda1_runs", "lambda1_periods")
    runs = ds.lambda1_runs.transpose(..., "run").values
    runs = runs.reshape(-1, runs.shape[-1])
    ran = np.broadcast_to(ds.lambda1_periods.values, ds.lambda1.shape).ravel()
    span = ran - point_values(ds, "transient", 0).astype(float)
    starts = [box_starts(b) for b in point_values(ds, "box", None)]
    return [split(r, p, s) for r, p, s in zip(runs, span, starts, strict=True)]


def stored_split(
    regular: int,
    runs: int,
    periods: float,
    regular_lambda1: tuple,
    chaotic_lambda1: tuple,
    starts: str = "",
) -> Split:
    """A :class:`Split` from what a sweep stores of it (the count of regular runs and each
    group's (mean, standard error); the per-run values, hence the gap, are not kept).

    >>> s = stored_split(3, 4, 200, (0.01, 0.001), (0.4, float("nan")))
    >>> s.mixed, s.fraction, round(s.fraction_se, 3), s.gap
    (True, 0.75, 0.25, (nan, nan))
    """
    regular, runs = int(regular), int(runs)
    if not 0 <= regular <= runs or runs < 1:
        raise ParameterError("regular", regular, f"a count of runs in [0, {runs}]")
    fraction, fraction_se = mean_stderr([1.0] * regular + [0.0] * (runs - regular))
    return Split(threshold(periods), runs, regular, fraction, fraction_se,
                 *map(float, regular_lambda1), *map(float, chaotic_lambda1),
                 (math.nan, math.nan), starts)  # fmt: skip


def stored_splits(ds) -> list[Split | None]:
    """:func:`stored_split` at every point of a sweep that stores the split
    (:data:`SPLIT_RESULTS`: the ``ergodicity`` and ``design`` kinds), in the order of
    ``ds.lambda1.values.ravel()``; None where a point has no Lyapunov runs (or is not
    done).  Runs, periods and box are read per point where they were swept."""
    count = point_values(ds, "lyapunov_runs", 0)
    periods = point_values(ds, "lyapunov_periods", 0)
    box = point_values(ds, "box", None)
    cols = [ds[name].values.ravel() for name in SPLIT_RESULTS]  # Split.stored() order
    return [
        None if not r > 0 or not np.isfinite(reg) else
        stored_split(reg, r, p, (rm, rse), (cm, cse), box_starts(b))
        for r, p, b, reg, rm, rse, cm, cse in zip(count, periods, box, *cols, strict=True)
    ]  # fmt: skip


def map_calls(ds) -> dict:
    """A chaos map judged run by run (:func:`map_split`): per point, +1 where every run is
    chaotic, -1 where every run is regular, 0 where the runs split (``calls``, shaped as
    ``ds.lambda1``), the regular fraction (``regular_fraction``) and the splits.

    A mixed point has no single verdict: its mean lambda_1 depends on how many runs start
    in an island, that is on the start distribution.
    """
    groups = map_split(ds)
    shape = ds.lambda1.shape
    calls = np.array([0 if g.mixed else (-1 if g.regular else 1) for g in groups])
    return {
        "calls": calls.reshape(shape),
        "regular_fraction": np.array([g.fraction for g in groups]).reshape(shape),
        "splits": groups,
    }


def verdicts(ds) -> dict:
    """Chaotic / regular per beta from lambda_1 and from the transverse exponent; with the
    per-run exponents, also the regular runs per beta (``regular_runs``, of ``runs``) and
    where the ensemble is mixed (:func:`map_split`)."""
    check_map(ds, "lambda1", "lambda1_se", attrs=("periods",))
    periods = int(ds.attrs["periods"])
    out = {"threshold": threshold(periods),
           "chaotic": chaotic(ds.lambda1.values, ds.lambda1_se.values, periods)}  # fmt: skip
    if "lambda1_runs" in ds and np.isfinite(ds.lambda1_runs.values).all():
        groups = map_split(ds)
        shape = ds.lambda1.shape
        out["runs"] = int(ds.sizes["run"])
        out["regular_runs"] = np.array([g.regular for g in groups]).reshape(shape)
        out["mixed"] = np.array([g.mixed for g in groups]).reshape(shape)
    if "transverse" in ds and np.isfinite(ds.transverse.values).all():
        out["transverse_chaotic"] = chaotic(ds.transverse.values, ds.transverse_se.values, periods)
    return out


def agreement(ds, stable: np.ndarray) -> dict:
    """How a theory's stability (``stable`` per beta) matches a chaos map judged run by run
    (:func:`map_calls`): stable <-> every run regular, unstable <-> every run chaotic.

    Returns the counts of betas whose runs are all chaotic (``chaotic``), all regular
    (``regular``) and split (``mixed``), and ``floquet``: the share of the ``scored``
    betas, those not mixed, where the theory matches (NaN when every beta is mixed).  A
    mixed beta is not scored but listed (``mixed_beta``, ``regular_fraction``): its
    runs are partly regular, so neither call fits it, and its mean lambda_1 is set by the
    start distribution.  With the transverse exponents, ``transverse``: the share of the
    scored betas where the transverse exponent's verdict (:func:`chaotic`, on its mean)
    calls chaotic exactly where every run is.
    """
    check_map(ds, "lambda1", "lambda1_se", "lambda1_runs", "lambda1_periods", "beta",
               attrs=("periods",))  # fmt: skip
    c = map_calls(ds)
    calls = c["calls"].ravel()
    allowed = f"True or False for each of the map's {calls.size} betas"
    flags = v.real_array("stable", stable, allowed)
    if flags.size != calls.size or not np.isin(flags, (0, 1)).all():
        simple = isinstance(stable, str | int | float | list | tuple) and len(repr(stable)) < 60
        shown = stable if simple else f"{flags.size} values"
        raise ParameterError("stable", shown, allowed)
    stable = flags.astype(bool).ravel()
    scored = calls != 0
    beta = np.asarray(ds.beta.values, dtype=float).ravel()
    out = {
        "threshold": threshold(int(ds.attrs["periods"])),
        "betas": int(ds.beta.size),
        "chaotic": int((calls == 1).sum()),
        "regular": int((calls == -1).sum()),
        "mixed": int((~scored).sum()),
        "mixed_beta": beta[~scored].tolist(),
        "regular_fraction": c["regular_fraction"].ravel()[~scored].tolist(),
        "scored": int(scored.sum()),
        "floquet": float(np.mean(stable[scored] == (calls[scored] == -1)))
        if scored.any() else math.nan,
    }  # fmt: skip
    judged = verdicts(ds)
    if "transverse_chaotic" in judged:
        t = judged["transverse_chaotic"].ravel()[scored]
        out["transverse"] = float(np.mean(t == (calls[scored] == 1))) if scored.any() else math.nan
    return out
