r"""Morlet wavelet map of a recorded signal and its ridge (the instantaneous frequency).

The standard diagnostic of targeted energy transfer: the container displacement X(t) is
transformed with a complex Morlet wavelet (PyWavelets' ``pywt.cwt`` with a ``cmorB-C``
wavelet: bandwidth B, centre frequency C), and the frequency of largest modulus at each
time -- the ridge -- is drawn over the frequency-energy plot of the normal modes
(:mod:`sinktheory.nnm`) against the energy left at that time.

Frequencies here are angular, omega = 2 pi f, in the paper's units (the container alone
has omega = 1, period T = 2 pi).  The scale of a frequency is ``C / (f dt)`` (the
wavelet's Fourier transform peaks at f = C / (scale dt)).  The ridge is taken on
``|W| / sqrt(scale)``: PyWavelets normalises the wavelet as 1 / sqrt(scale), which
multiplies the response to a pure tone by sqrt(scale) and would shift the modulus'
maximum to a lower frequency by about 1 / (4 pi^2 B C) relatively (1.7 % for B = 1.5,
C = 1); dividing it out puts the maximum exactly at the tone's frequency.  The maximum
on the frequency grid is refined by the parabola through it and its two neighbours
(in ln omega).

Near both ends of the record the wavelet reaches past the data (the cone of influence):
a coefficient is kept only where the Gaussian envelope of the wavelet, of standard
deviation ``scale dt sqrt(B / 2)`` in time, fits inside the record ``COI_WIDTHS`` times
over on either side; elsewhere the map is NaN, and the ridge is NaN at every time where
some frequency of the map is cut (so it starts and ends ``COI_WIDTHS`` envelopes of the
lowest frequency inside the record).

Examples
--------
>>> import numpy as np
>>> t = np.arange(0, 200.0, 2 * np.pi / 16)
>>> w = wavelet_map(t, np.cos(1.3 * t), omega=(0.5, 3.0, 120))
>>> ridge = w.ridge[np.isfinite(w.ridge)]
>>> bool(np.all(np.abs(ridge / 1.3 - 1) < 1e-3))
True
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..results import Result

__all__ = [
    "COI_WIDTHS",
    "DEFAULT_WAVELET",
    "MAX_FREQUENCIES",
    "morlet",
    "PRECISION",
    "wavelet_map",
    "WaveletMap",
]

#: The complex Morlet wavelet used unless another ``cmorB-C`` is asked for.
DEFAULT_WAVELET = "cmor1.5-1.0"
#: Envelope standard deviations that must fit inside the record on either side of a
#: kept coefficient (2: the envelope outside is below exp(-2) of its peak).
COI_WIDTHS = 2.0
#: Wavelet length 2**PRECISION in pywt.cwt: the wavelet is sampled on that grid and
#: stretched to each scale, and the grid's coarseness shows in the ridge of a pure tone
#: (largest error over omega = 1.3, 16 samples per period: 1.1e-2 at 10, 3.6e-3 at the
#: default 12, 2.4e-4 at 14, 2.0e-4 at 16).
PRECISION = 14
#: Most frequencies of one map.
MAX_FREQUENCIES = 2000
_CMOR = re.compile(r"^cmor(\d+(\.\d*)?|\.\d+)-(\d+(\.\d*)?|\.\d+)$")


def morlet(name: str) -> tuple[float, float]:
    """(B, C) of a complex Morlet wavelet name ``cmorB-C``; ParameterError otherwise.

    Examples
    --------
    >>> morlet("cmor1.5-1.0")
    (1.5, 1.0)
    >>> morlet("morl")
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: wavelet = 'morl' is not allowed: must be a complex \
Morlet wavelet named cmorB-C with B > 0 and C > 0 (e.g. cmor1.5-1.0)
    """
    allowed = "a complex Morlet wavelet named cmorB-C with B > 0 and C > 0 (e.g. cmor1.5-1.0)"
    match = _CMOR.match(name) if isinstance(name, str) else None
    if match is None:
        raise ParameterError("wavelet", name, allowed)
    b, c = float(match.group(1)), float(match.group(3))
    if b <= 0 or c <= 0:
        raise ParameterError("wavelet", name, allowed)
    return b, c


@dataclass(frozen=True)
class WaveletMap(Result):
    """The wavelet map of one signal.

    Attributes
    ----------
    t : (S,) sample times
    omega : (F,) angular frequencies of the map (log-spaced, increasing)
    modulus : (F, S) ``|W| / sqrt(scale)`` (NaN outside the cone of influence)
    ridge : (S,) angular frequency of the largest modulus at each time (NaN where the
        cone of influence leaves no frequency)
    wavelet : str
        The ``cmorB-C`` name.
    """

    t: np.ndarray
    omega: np.ndarray
    modulus: np.ndarray
    ridge: np.ndarray
    wavelet: str

    DIMS = {"t": ("t",), "omega": ("omega",), "modulus": ("omega", "t"), "ridge": ("t",)}


def _grid(omega, dt: float) -> np.ndarray:
    """The log-spaced angular frequencies of ``omega = (LO, HI, COUNT)``, checked against
    the sampling (HI at most the Nyquist frequency pi / dt)."""
    if not isinstance(omega, tuple | list) or len(omega) != 3:
        raise ParameterError("omega", omega, "(LO, HI, COUNT) angular frequencies")
    lo, hi = v.positive("omega", omega[0]), v.positive("omega", omega[1])
    count = v.positive_int("omega", omega[2], minimum=3, maximum=MAX_FREQUENCIES)
    nyquist = math.pi / dt
    if not lo < hi <= nyquist:
        raise ParameterError(
            "omega", tuple(omega), f"(LO, HI, COUNT) with 0 < LO < HI <= pi / dt = {nyquist:.4g}"
        )
    return np.geomspace(lo, hi, count)


def wavelet_map(t, x, *, omega=(0.3, 3.0, 160), wavelet: str = DEFAULT_WAVELET) -> WaveletMap:
    """The Morlet wavelet map of ``x`` sampled at the evenly spaced times ``t``.

    Parameters
    ----------
    t : (S,) array
        Evenly spaced sample times (at least 16 samples).
    x : (S,) array
        The signal (e.g. the container displacement X).
    omega : (LO, HI, COUNT)
        Angular frequencies of the map, COUNT of them log-spaced from LO to HI <= pi / dt.
    wavelet : str
        A complex Morlet wavelet ``cmorB-C`` of PyWavelets.

    Returns
    -------
    WaveletMap
    """
    import pywt  # only when a map is asked for

    b, c = morlet(wavelet)
    t = v.real_array("t", t)
    x = v.real_array("x", x)
    if t.ndim != 1 or t.size < 16:
        raise ParameterError("t", f"shape {t.shape}", "a 1-D array of at least 16 times")
    if x.shape != t.shape:
        raise ParameterError("x", f"shape {x.shape}", f"the shape of t, {t.shape}")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(x))):
        raise ParameterError("x", "non-finite values", "finite samples at finite times")
    steps = np.diff(t)
    dt = float(steps.mean())
    if dt <= 0 or np.max(np.abs(steps - dt)) > 1e-9 * max(abs(t[-1]), dt):
        raise ParameterError("t", "uneven or decreasing times", "evenly spaced increasing times")
    grid = _grid(omega, dt)
    scales = c * 2 * math.pi / (grid * dt)
    coef, _ = pywt.cwt(x, scales, wavelet, sampling_period=dt, method="fft", precision=PRECISION)
    modulus = np.abs(coef) / np.sqrt(scales)[:, None]
    # cone of influence: the envelope (sd scale dt sqrt(B/2)) inside the record
    width = COI_WIDTHS * scales * dt * math.sqrt(b / 2)
    inside = (t[None, :] - t[0] >= width[:, None]) & (t[-1] - t[None, :] >= width[:, None])
    modulus = np.where(inside, modulus, np.nan)
    return WaveletMap(t, grid, modulus, ridge_of(grid, modulus), wavelet)


def ridge_of(omega: np.ndarray, modulus: np.ndarray) -> np.ndarray:
    """The frequency of the largest modulus in each column, refined by the parabola in
    ln omega through the logarithms of the maximum and its two neighbours (exact for a
    Gaussian in ln omega).  NaN where the maximum lies on the edge of the frequencies kept
    (the grid's ends: the true maximum may lie outside) and in columns with any NaN (cut
    by the cone of influence at some frequency: the record's edges still show there as a
    broad-band transient that can put a spurious maximum among the kept frequencies).

    Examples
    --------
    >>> w = np.geomspace(0.5, 2.0, 5)
    >>> m = np.exp(-np.log(w / 1.1) ** 2)[:, None]       # a Gaussian in ln(omega)
    >>> float(np.round(ridge_of(w, m), 12)[0])
    1.1
    >>> bool(np.isnan(ridge_of(w, np.exp(-np.log(w / 3.0) ** 2)[:, None])[0]))
    True
    """
    out = np.full(modulus.shape[1], np.nan)
    with np.errstate(divide="ignore", invalid="ignore"):
        y = np.where(np.isfinite(modulus) & (modulus > 0), np.log(modulus), -np.inf)
    k = np.argmax(y, axis=0)
    cols = np.arange(y.shape[1])
    inner = (k > 0) & (k < omega.size - 1) & np.all(np.isfinite(modulus), axis=0)
    cols, k = cols[inner], k[inner]
    y0, y1, y2 = y[k - 1, cols], y[k, cols], y[k + 1, cols]
    ok = np.isfinite(y0) & np.isfinite(y1) & np.isfinite(y2)
    cols, k, y0, y1, y2 = cols[ok], k[ok], y0[ok], y1[ok], y2[ok]
    denom = y0 - 2 * y1 + y2  # < 0 at a strict maximum
    shift = np.where(denom < 0, 0.5 * (y0 - y2) / np.where(denom < 0, denom, -1.0), 0.0)
    logw = np.log(omega)
    h = logw[1] - logw[0]
    out[cols] = np.exp(logw[k] + np.clip(shift, -0.5, 0.5) * h)
    return out
