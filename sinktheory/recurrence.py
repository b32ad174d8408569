"""Recurrence plots and recurrence quantification of an energy series E_k = E(kT).

The recurrence matrix of paper eq. (Rij) is R(i, j) = 1 if |E_i - E_j| <= eps, else 0,
for a scalar series sampled once per container period.  Everything here works on the
series itself, never on an N x N float matrix: line statistics are gathered column by
column (or diagonal by diagonal) in compiled loops with O(N) memory, so N = 10^4 costs
10^8 comparisons and a few kilobytes.

Conventions (Marwan, Romano, Thiel & Kurths, Phys. Rep. 438 (2007) 237)
--------------------------------------------------------------------------
* Recurrence means ``|E_i - E_j| <= eps`` (closed neighbourhood, as in eq. Rij).
* A Theiler window ``w`` removes the points with ``|i - j| < w`` from every measure.  The
  default ``w = 1`` removes exactly the main diagonal (which is 1 by construction and
  says nothing); ``w = 0`` keeps it.
* Recurrence rate RR = (recurrent pairs outside the window) / (pairs outside the window).
* Diagonal lines are maximal runs of ones along i - j = const (both triangles, each
  counted separately), vertical lines maximal runs of ones along a column; runs are cut
  by the Theiler window.  DET = sum over lines with l >= l_min of l P(l) / sum of l P(l);
  LAM likewise for vertical lines with v_min; trapping time TT = mean length of the
  vertical lines with v >= v_min.
* Mean recurrence time: in each column, the time (in periods T) from the last point of
  one run of recurrences to the first point of the next run, i.e. a white vertical gap
  of length g counts as g + 1; only gaps bounded by recurrences on both sides count
  (gaps running into the matrix edge or the Theiler window are incomplete).

Choosing eps
------------
:func:`epsilon_for_rate` returns the eps at which RR takes a prescribed value (default
:data:`DEFAULT_RATE` = 5 %), found exactly from the sorted series; a fixed recurrence
rate makes plots of different runs comparable whatever the energy scale.
"""

from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from . import validation as v
from .errors import ParameterError
from .glossary import renamed
from .results import Result, plain

__all__ = [
    "DEFAULT_RATE",
    "epsilon_for_rate",
    "recurrence_image",
    "recurrence_rate",
    "RQA",
    "rqa",
    "rqa_matrix",
]

#: Default recurrence rate used to pick eps.
DEFAULT_RATE = 0.05


def _series(series, name: str = "series") -> np.ndarray:
    e = v.real_array(name, series, "a 1-D series of length >= 2")
    if e.ndim != 1 or e.size < 2:
        raise ParameterError(name, f"array of shape {e.shape}", "a 1-D series of length >= 2")
    if not np.all(np.isfinite(e)):
        raise ParameterError(name, "a series with NaN or inf", "finite values")
    return e


@numba.njit(cache=True)
def _pairs_within(sorted_e, eps):
    """Number of unordered pairs i < j with |e_i - e_j| <= eps (two pointers, O(N))."""
    count = 0
    lo = 0
    for hi in range(sorted_e.size):
        while sorted_e[hi] - sorted_e[lo] > eps:
            lo += 1
        count += hi - lo
    return count


@renamed(energy="series")
def recurrence_rate(series, eps: float) -> float:
    """RR with the main diagonal excluded (Theiler window 1), in O(N log N).

    Examples
    --------
    >>> recurrence_rate([0.0, 0.1, 0.5, 0.55], eps=0.1)
    0.3333333333333333
    """
    e = np.sort(_series(series))
    eps = v.nonnegative("eps", eps)
    n = e.size
    return _pairs_within(e, eps) / (n * (n - 1) / 2)


@renamed(energy="series")
def epsilon_for_rate(series, rate: float = DEFAULT_RATE) -> float:
    """The smallest eps whose recurrence rate (diagonal excluded) is at least ``rate``.

    Exact: the candidate values are the pairwise distances, searched by bisection on the
    sorted series.
    """
    e = np.sort(_series(series))
    if not (isinstance(rate, int | float) and 0 < rate <= 1):
        raise ParameterError("rate", rate, "a number in (0, 1]")
    n = e.size
    need = int(np.ceil(rate * n * (n - 1) / 2 - 1e-9))
    lo, hi = 0.0, float(e[-1] - e[0])
    if _pairs_within(e, lo) >= need:
        return lo
    for _ in range(200):  # bisection down to adjacent floats
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if _pairs_within(e, mid) >= need:
            hi = mid
        else:
            lo = mid
    return hi


@numba.njit(cache=True)
def _line_histograms(e, eps, matrix, use_matrix, w):
    """Histograms of diagonal lines, vertical lines and bounded white vertical gaps.

    R(i, j) is ``matrix[i, j]`` if ``use_matrix`` else ``|e_i - e_j| <= eps``; R must be
    symmetric.  Index l of each histogram counts the lines (or gaps) of length l.
    """
    n = matrix.shape[0] if use_matrix else e.size
    diag = np.zeros(n + 1, np.int64)
    vert = np.zeros(n + 1, np.int64)
    gaps = np.zeros(n + 1, np.int64)
    # diagonal lines at offsets k >= w; each k > 0 stands for two (mirrored) diagonals
    for k in range(w, n):
        weight = 1 if k == 0 else 2
        run = 0
        for i in range(n - k):
            if matrix[i, i + k] if use_matrix else abs(e[i] - e[i + k]) <= eps:
                run += 1
            else:
                if run > 0:
                    diag[run] += weight
                run = 0
        if run > 0:
            diag[run] += weight
    # vertical lines and gaps, column by column; the window cuts both
    for j in range(n):
        run = 0
        gap = 0
        seen = False
        for i in range(n):
            inside = abs(i - j) < w
            if inside:
                rec = False
            elif use_matrix:
                rec = matrix[i, j]
            else:
                rec = abs(e[i] - e[j]) <= eps
            if rec:
                run += 1
                if seen and gap > 0:
                    gaps[gap] += 1
                gap = 0
                seen = True
            else:
                if run > 0:
                    vert[run] += 1
                run = 0
                if inside:  # the window is neither recurrence nor gap: restart
                    gap = 0
                    seen = False
                else:
                    gap += 1
        if run > 0:
            vert[run] += 1
    return diag, vert, gaps


@dataclass(frozen=True)
class RQA(Result):
    """Recurrence quantification of one series (see the module docstring for conventions).

    Attributes
    ----------
    eps, theiler, l_min, v_min : the settings used
    recurrence_rate : RR
    determinism : DET (nan if there is no recurrence point)
    laminarity : LAM (nan if there is no recurrence point)
    trapping_time : TT in periods (nan if no vertical line reaches v_min)
    mean_recurrence_time : mean bounded white vertical gap + 1, in periods (nan if none)
    diagonal_lines, vertical_lines : histograms, index = line length

    ``as_dict()`` is the summary: the settings and the five measures (nan becomes None),
    without the histograms, which can be as long as the series; ``to_dataset()`` keeps
    them (dim ``length``) and :meth:`histograms` gives them as plain lists
    (:mod:`sinktheory.results`).

    Examples
    --------
    >>> r = rqa([0.0, 1.0, 0.0, 1.0, 0.0, 1.0], eps=0.1)
    >>> sorted(r.as_dict())  # doctest: +NORMALIZE_WHITESPACE
    ['determinism', 'eps', 'l_min', 'laminarity', 'mean_recurrence_time',
     'recurrence_rate', 'theiler', 'trapping_time', 'v_min']
    >>> r.histograms()["diagonal_lines"]  # diagonals j - i = +-2 (length 4), +-4 (length 2)
    [0, 0, 2, 0, 2, 0, 0]
    """

    eps: float
    theiler: int
    l_min: int
    v_min: int
    recurrence_rate: float
    determinism: float
    laminarity: float
    trapping_time: float
    mean_recurrence_time: float
    diagonal_lines: np.ndarray
    vertical_lines: np.ndarray

    DIMS = {"diagonal_lines": ("length",), "vertical_lines": ("length",)}

    def coords(self) -> dict:
        return {"length": np.arange(self.diagonal_lines.size)}

    def as_dict(self) -> dict:
        """The summary: every field but the histograms (see the class docstring)."""
        d = super().as_dict()
        for name in self.DIMS:
            del d[name]
        return d

    def histograms(self) -> dict[str, list[int]]:
        """The line-length histograms as plain lists (index = line length)."""
        return {name: plain(getattr(self, name)) for name in self.DIMS}


def _ratio(num: float, den: float) -> float:
    return num / den if den > 0 else float("nan")


def _measures(diag, vert, gaps, n, eps, theiler, l_min, v_min) -> RQA:
    lengths = np.arange(n + 1)
    window = n + 2 * sum(n - k for k in range(1, theiler)) if theiler > 0 else 0
    recurrent = int((lengths * diag).sum())  # every recurrent point lies on one diagonal line
    v_total = float((lengths * vert).sum())
    return RQA(
        eps=eps,
        theiler=theiler,
        l_min=l_min,
        v_min=v_min,
        recurrence_rate=recurrent / (n * n - window),
        determinism=_ratio(float((lengths * diag)[l_min:].sum()), float(recurrent)),
        laminarity=_ratio(float((lengths * vert)[v_min:].sum()), v_total),
        trapping_time=_ratio(float((lengths * vert)[v_min:].sum()), float(vert[v_min:].sum())),
        mean_recurrence_time=_ratio(float(((lengths + 1) * gaps).sum()), float(gaps.sum())),
        diagonal_lines=diag,
        vertical_lines=vert,
    )


def _settings(n: int, theiler, l_min, v_min) -> tuple[int, int, int]:
    return (
        v.positive_int("theiler", theiler, minimum=0, maximum=n - 1),
        v.positive_int("l_min", l_min),
        v.positive_int("v_min", v_min),
    )


@renamed(energy="series")
def rqa(
    series, eps: float | None = None, *, theiler: int = 1, l_min: int = 2, v_min: int = 2
) -> RQA:
    """Recurrence quantification of ``series`` (such as the container energy E_k at
    t = kT), without an N x N matrix.

    Parameters
    ----------
    series : 1-D array, finite
    eps : float >= 0, optional
        Neighbourhood size; by default :func:`epsilon_for_rate` at 5 %.
    theiler : int >= 0
        Points with |i - j| < theiler are left out (1: only the main diagonal).
    l_min, v_min : int >= 1
        Shortest diagonal / vertical line counted as determinism / laminarity.

    Examples
    --------
    A period-2 series recurs on every second diagonal, never on a vertical line, and
    comes back every 2 periods:

    >>> r = rqa([0.0, 1.0, 0.0, 1.0, 0.0, 1.0], eps=0.1)
    >>> r.recurrence_rate, r.determinism, r.laminarity, r.mean_recurrence_time
    (0.4, 1.0, 0.0, 2.0)
    """
    e = _series(series)
    eps = epsilon_for_rate(e) if eps is None else v.nonnegative("eps", eps)
    theiler, l_min, v_min = _settings(e.size, theiler, l_min, v_min)
    dummy = np.zeros((1, 1), np.bool_)
    diag, vert, gaps = _line_histograms(e, eps, dummy, False, theiler)
    return _measures(diag, vert, gaps, e.size, eps, theiler, l_min, v_min)


def rqa_matrix(matrix, *, theiler: int = 1, l_min: int = 2, v_min: int = 2) -> RQA:
    """The same measures for an explicit symmetric 0/1 recurrence matrix (``eps`` is nan).

    Examples
    --------
    All ones, main diagonal left out: two lines of length 2 and two of length 1.

    >>> import numpy as np
    >>> rqa_matrix(np.ones((3, 3), bool)).determinism
    0.6666666666666666
    """
    R = np.asarray(matrix)
    if R.ndim != 2 or R.shape[0] != R.shape[1] or R.shape[0] < 2:
        raise ParameterError("matrix", f"array of shape {R.shape}", "a square matrix, N >= 2")
    if not np.isin(R, (0, 1)).all() or not (R == R.T).all():
        raise ParameterError("matrix", "the given array", "symmetric, with entries 0 or 1")
    n = R.shape[0]
    theiler, l_min, v_min = _settings(n, theiler, l_min, v_min)
    empty = np.zeros(0)
    diag, vert, gaps = _line_histograms(empty, 0.0, R.astype(np.bool_), True, theiler)
    return _measures(diag, vert, gaps, n, float("nan"), theiler, l_min, v_min)


@numba.njit(cache=True)
def _binned_recurrence(e, eps, size):
    """Fraction of recurrent pairs in each of size x size blocks (float32)."""
    n = e.size
    img = np.zeros((size, size), np.float32)
    cnt = np.zeros((size, size), np.float32)
    for i in range(n):
        bi = i * size // n
        for j in range(n):
            bj = j * size // n
            cnt[bi, bj] += 1.0
            if abs(e[i] - e[j]) <= eps:
                img[bi, bj] += 1.0
    return img / cnt


@renamed(energy="series")
def recurrence_image(series, eps: float, max_pixels: int = 1500) -> np.ndarray:
    """R(i, j) for plotting: exact 0/1 if N <= max_pixels, else block-averaged fractions.

    The image has at most ``max_pixels`` rows, so N = 10^4 needs no N x N array.
    """
    e = _series(series)
    eps = v.nonnegative("eps", eps)
    size = min(e.size, v.positive_int("max_pixels", max_pixels))
    return _binned_recurrence(e, eps, size)
