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


def finite(name: str, value: object) -> float:
    """A finite real number (bools are refused)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
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


def positive_int(name: str, value: object, *, minimum: int = 1, maximum: int | None = None) -> int:
    """An integer in ``[minimum, maximum]`` (floats with an integral value are accepted)."""
    allowed = (
        f"an integer >= {minimum}" if maximum is None else (f"an integer in [{minimum}, {maximum}]")
    )
    if isinstance(value, bool):
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
    if i < minimum or (maximum is not None and i > maximum):
        raise ParameterError(name, value, allowed)
    return i


def choice(name: str, value: object, options: tuple[str, ...]) -> str:
    """One of a fixed set of names."""
    if value not in options:
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
