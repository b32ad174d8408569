"""Chaotic or regular: the verdict on finite-time exponents, and its statistical basis.

On a regular orbit deviations grow at most linearly (shear), so the finite-time exponent
decays like ln t / t (tests/chaos/test_chaos.py: the integrable case gives lambda_1 t / ln t ~ 1).
An exponent is called *chaotic* when its mean over runs exceeds that envelope with margin,
by two standard errors:

    mean - 2 s.e. > THRESHOLD_FACTOR ln(t) / t,    t = P T,

and *regular* otherwise.  The Floquet theory predicts regular motion where y = 0 is stable
(with the container fixed); :func:`agreement` gives the share of betas of a chaos map
(:func:`sinktheory.sweep.chaosmap.chaos_map`) where the two verdicts coincide.  The
transverse exponent's verdict (the same test on it) measures how much of the chaos comes
from the instability of y = 0 itself.

Examples
--------
>>> round(threshold(300), 5)
0.012
>>> chaotic([0.1, 0.01], [0.01, 0.01], 300).tolist()
[True, False]
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import ParameterError

__all__ = ["THRESHOLD_FACTOR", "agreement", "chaotic", "threshold", "verdicts"]

#: The finite-time exponent of a regular orbit is ~ ln t / t; a chaotic verdict needs the
#: mean minus two standard errors above this factor times ln t / t.
THRESHOLD_FACTOR = 3.0


def threshold(periods: int) -> float:
    """THRESHOLD_FACTOR ln(t) / t at t = periods x 2 pi (per unit time)."""
    t = periods * 2.0 * math.pi
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
    mean, se = np.asarray(mean, dtype=float), np.asarray(se, dtype=float)
    bad = ~(np.isfinite(se) & (se >= 0))
    if bad.any():
        raise ParameterError(
            "se",
            float(se[bad].flat[0]),
            "finite standard errors >= 0 (from two runs or more: one run has none, so no verdict)",
        )
    return mean - 2 * se > threshold(periods)


def verdicts(ds) -> dict:
    """Chaotic / regular per beta from lambda_1 and from the transverse exponent."""
    periods = int(ds.attrs["periods"])
    out = {"threshold": threshold(periods),
           "chaotic": chaotic(ds.lambda1.values, ds.lambda1_se.values, periods)}  # fmt: skip
    if "transverse" in ds and np.isfinite(ds.transverse.values).all():
        out["transverse_chaotic"] = chaotic(ds.transverse.values, ds.transverse_se.values, periods)
    return out


def agreement(ds, stable: np.ndarray) -> dict:
    """Shares of betas where the chaos map agrees with (a) Floquet stability of y = 0
    (stable <-> regular) and (b) the transverse exponent's verdict."""
    v = verdicts(ds)
    out = {
        "threshold": v["threshold"],
        "betas": int(ds.beta.size),
        "chaotic": int(v["chaotic"].sum()),
        "floquet": float(np.mean(np.asarray(stable) == ~v["chaotic"])),
    }
    if "transverse_chaotic" in v:
        out["transverse"] = float(np.mean(v["transverse_chaotic"] == v["chaotic"]))
    return out
