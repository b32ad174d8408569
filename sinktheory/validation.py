"""Tiny validators shared by every input check of the package.

Each returns the value in canonical form or raises :class:`~sinktheory.errors.ParameterError`
whose message names the parameter.  The model objects in :mod:`sinktheory.model` and the
analyses' entry points call these; no other module re-implements a check.

Examples
--------
>>> positive("gamma", 2)
2.0
>>> positive_int("n", 3.0)
3
>>> positive("gamma", -1)
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: gamma = -1 is not allowed: must be a finite number > 0
"""

from __future__ import annotations

import math
import numbers
import os
import tempfile
from pathlib import Path

from .errors import ParameterError
from .limits import MAX_STEPS_PER_PERIOD

__all__ = [
    "BOOLS",
    "finite",
    "finite_array",
    "flag",
    "MAX_STEPS_PER_PERIOD",
    "memory_limit",
    "nonnegative",
    "positive",
]


def _is_bool(value: object) -> bool:
    """True for Python and numpy booleans (which float() would quietly turn into 0 or 1)."""
    kind = type(value)
    return isinstance(value, bool) or (kind.__module__ == "numpy" and kind.__name__ in BOOLS)


#: Names of numpy's boolean scalar type (numpy 1: ``bool_``; numpy 2: ``bool``).
BOOLS = ("bool_", "bool")


def finite(name: str, value: object) -> float:
    """A finite real number (bools are refused)."""
    if _is_bool(value):
        raise ParameterError(name, value, "a finite real number (not a bool)")
    if not isinstance(value, numbers.Real):
        try:
            value = float(value)  # numpy scalars, mpmath mpf, numeric strings
        except (TypeError, ValueError):
            raise ParameterError(name, value, "a finite real number") from None
    x = float(value)
    if not math.isfinite(x):
        raise ParameterError(name, value, "a finite real number")
    return x


def _finite_where(name: str, value: object, ok, allowed: str) -> float:
    """A finite real number for which ``ok(x)`` holds; else refused as ``allowed``."""
    try:
        x = finite(name, value)
    except ParameterError:
        raise ParameterError(name, value, allowed) from None
    if not ok(x):
        raise ParameterError(name, value, allowed)
    return x


def positive(name: str, value: object) -> float:
    """A finite real number > 0."""
    return _finite_where(name, value, lambda x: x > 0, "a finite number > 0")


def nonnegative(name: str, value: object) -> float:
    """A finite real number >= 0."""
    return _finite_where(name, value, lambda x: x >= 0, "a finite number >= 0")


def positive_int(
    name: str,
    value: object,
    *,
    minimum: int = 1,
    maximum: int | None = None,
    why=None,
) -> int:
    """An integer in ``[minimum, maximum]`` (floats with an integral value are accepted).

    ``why(i)``, if given, explains in the message why an integer above ``maximum`` is
    refused (a memory or time estimate, say)."""
    allowed = (
        f"an integer >= {minimum}" if maximum is None else (f"an integer in [{minimum}, {maximum}]")
    )
    if _is_bool(value):
        raise ParameterError(name, value, allowed)
    if isinstance(value, numbers.Integral):
        i = int(value)
    else:
        try:
            x = float(value)
        except (TypeError, ValueError):
            raise ParameterError(name, value, allowed) from None
        if not math.isfinite(x) or x != int(x):
            raise ParameterError(name, value, allowed)
        i = int(x)
    if maximum is not None and i > maximum:
        shown = value if len(str(i)) <= 20 else _compact(i)  # not 300 digits of an int
        raise ParameterError(name, shown, allowed, why=why(i) if why else None)
    if i < minimum or (maximum is not None and i > maximum):
        raise ParameterError(name, value, allowed)
    return i


def stiffness(name: str, value: object) -> int | float:
    """A wall stiffness n: an integer >= 1, or ``math.inf`` (also the text "inf") for the
    rigid limit n -> oo.  The model's upper bound on a finite n is checked by the model.

    Examples
    --------
    >>> stiffness("n", 10.0), stiffness("n", "inf"), stiffness("n", math.inf)
    (10, inf, inf)
    >>> stiffness("n", -math.inf)
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: n = -inf is not allowed: must be an integer >= 1 or \
inf (the rigid limit)
    """
    allowed = "an integer >= 1 or inf (the rigid limit)"
    if isinstance(value, str) and value.strip().lower() in ("inf", "+inf", "infinity"):
        return math.inf
    if not _is_bool(value) and isinstance(value, numbers.Real) and value == math.inf:
        return math.inf
    try:
        return positive_int(name, value)
    except ParameterError:
        raise ParameterError(name, value, allowed) from None


def _compact(i: int) -> float:
    try:
        return float(i)
    except OverflowError:
        return math.inf


def flag(name: str, value: object) -> bool:
    """True or False (Python's or numpy's bool; 1, "yes" and None are refused).

    Examples
    --------
    >>> flag("megno", True)
    True
    >>> flag("megno", "yes")
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: megno = 'yes' is not allowed: must be True or False
    """
    if not _is_bool(value):
        raise ParameterError(name, value, "True or False")
    return bool(value)


def choice(name: str, value: object, options: tuple[str, ...]) -> str:
    """One of a fixed set of names."""
    if not isinstance(value, str) or value not in options:
        raise ParameterError(name, value, "one of " + ", ".join(repr(o) for o in options))
    return str(value)


def writable_directory(name: str, value: object, directory: str | os.PathLike) -> None:
    """Raise ParameterError naming ``name`` unless a new file can be created in ``directory``.

    A probe file is created and removed at once: permissions alone do not tell (root may
    write anywhere, yet not in /proc nor on a read-only mount).
    """
    directory = Path(directory) if str(directory) else Path(".")
    if not directory.is_dir():
        raise ParameterError(name, value, "a path in an existing directory")
    try:
        fd, probe = tempfile.mkstemp(prefix=".sinktheory-probe-", dir=directory)
    except OSError as e:
        raise ParameterError(
            name, value, "a path in a writable directory", why=e.strerror or str(e)
        ) from None
    os.close(fd)
    os.unlink(probe)


def memory_limit() -> int:
    """Bytes one computation may allocate: half the machine's physical memory (8 GiB
    when that cannot be read)."""
    try:
        return os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE") // 2
    except (AttributeError, ValueError, OSError):
        return 8 * 2**30


def nbytes_text(n: float) -> str:
    """A byte count for people: ``'7.28 TiB'``.

    Examples
    --------
    >>> nbytes_text(8e12), nbytes_text(512)
    ('7.28 TiB', '512 B')
    """
    for unit, size in (("EiB", 2**60), ("PiB", 2**50), ("TiB", 2**40), ("GiB", 2**30)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    if n >= 2**20:
        return f"{n / 2**20:.3g} MiB"
    return f"{n:.0f} B"


def fits_memory(name: str, value: object, nbytes: float, what: str, allowed: str) -> None:
    """Refuse ``value`` of ``name`` when ``what`` would need more than :func:`memory_limit`
    bytes; the message gives the estimate."""
    limit = memory_limit()
    if nbytes > limit:
        raise ParameterError(
            name,
            value,
            allowed,
            why=f"{what} would need about {nbytes_text(nbytes)} of memory, over the "
            f"{nbytes_text(limit)} allowed (half of this machine's memory)",
        )


def time_step(name: str, value: object, period: float = 2 * math.pi) -> float:
    """A step dt > 0 with at most :data:`MAX_STEPS_PER_PERIOD` steps per ``period``.

    Examples
    --------
    >>> time_step("dt", 0.01)
    0.01
    >>> time_step("dt", 1e-300)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: dt = 1e-300 is not allowed: must be a number >= 6.28e-09 \
(at most 1000000000 steps per period T = 2 pi) (it would take 6.28e+300 steps per period)
    """
    dt = positive(name, value)
    smallest = period / MAX_STEPS_PER_PERIOD
    if dt < smallest:
        raise ParameterError(
            name,
            value,
            f"a number >= {smallest:.3g} (at most {MAX_STEPS_PER_PERIOD} steps per period "
            "T = 2 pi)",
            why=f"it would take {period / dt:.3g} steps per period",
        )
    return dt


def real_array(name: str, value: object, allowed: str = "an array of real numbers"):
    """``value`` as a float ndarray; ParameterError naming ``name`` if it cannot be one
    (text, None inside a list, ragged nesting, complex numbers).

    Examples
    --------
    >>> real_array("t", [0, 1.5]).tolist()
    [0.0, 1.5]
    >>> real_array("t", "abc")
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: t = 'abc' is not allowed: must be an array of real numbers
    >>> real_array("t", [1.0, None])
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: t = 'list' is not allowed: must be an array of real numbers
    """
    import warnings

    import numpy as np

    shown = value if isinstance(value, str | int | float | type(None)) else type(value).__name__
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", np.exceptions.ComplexWarning)
            out = np.asarray(value, dtype=float)
    except (TypeError, ValueError, np.exceptions.ComplexWarning):
        raise ParameterError(name, shown, allowed) from None
    # numpy reads None as NaN: refused as None, not shown as a NaN the caller never gave
    if np.isnan(out).any() and any(x is None for x in np.asarray(value, dtype=object).flat):
        raise ParameterError(name, shown, allowed)
    return out


def points(x: object, y: object):
    """The coordinates ``x`` and ``y`` as float ndarrays of finite numbers broadcast
    together, else ParameterError naming ``x`` or ``y`` (the points of a well's potential).

    Examples
    --------
    >>> [a.tolist() for a in points([0.0, 0.5], 1)]
    [[0.0, 0.5], [1.0, 1.0]]
    >>> points([0.0, 0.5], [1.0, 2.0, 3.0])
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: y = 'an array of shape (3,)' is not allowed: must be \
an array of finite real numbers broadcasting with x, of shape (2,)
    """
    import numpy as np

    x, y = finite_array("x", x), finite_array("y", y)
    try:
        return np.broadcast_arrays(x, y)
    except ValueError:
        allowed = f"an array of finite real numbers broadcasting with x, of shape {x.shape}"
        raise ParameterError("y", f"an array of shape {y.shape}", allowed) from None


def finite_array(name: str, value: object, allowed: str = "an array of finite real numbers",
                 ndim: int | None = None):  # fmt: skip
    """``value`` as a float ndarray of finite numbers (``ndim`` dimensions if given), else
    ParameterError naming ``name`` (None, text, complex numbers, NaN and infinities too).

    Examples
    --------
    >>> finite_array("tau", [0.5, 1]).tolist()
    [0.5, 1.0]
    >>> finite_array("tau", None)
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: tau = None is not allowed: must be an array of finite \
real numbers
    """
    import numpy as np

    if value is None or _is_bool(value):
        raise ParameterError(name, value, allowed)
    out = real_array(name, value, allowed)
    if (
        out.dtype == object
        or not np.all(np.isfinite(out))
        or (ndim is not None and out.ndim != ndim)
    ):
        shown = value if isinstance(value, str | int | float) else f"an array of shape {out.shape}"
        raise ParameterError(name, shown, allowed)
    return out
