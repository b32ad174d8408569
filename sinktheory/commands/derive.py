"""``sinktheory derive``: print the equations derived from the Lagrangian.

With ``--json`` every value is a string that :func:`sympy.sympify` reads back.

The derivation takes SymPy seconds for equations that change only with the code, so its
three renderings (JSON strings, pretty text, LaTeX) are kept in a cache file named by a
digest of what produces them (:data:`SOURCES`, the sinktheory and SymPy versions), in the
engine's cache directory (:func:`sinktheory.engine.cache.cache_dir`); a later call reads
that file without importing SymPy.  Editing any source changes the digest, so a stale
file is never read; ``--fresh`` derives again and rewrites it.

``--well FILE`` derives the ladder of a user's well file instead
(:func:`sinktheory.symbolic.ladder`: potential, Lagrangian, Hamiltonian, equations of
motion, the separable form, force, Hessian, and Hill's coefficient on y = 0 where y = 0
is invariant), after the file and the well at its parameter values (``--well-param
NAME=VALUE``, the defaults otherwise) pass :func:`sinktheory.userwell.check_well`; the
escape energy found there is printed with how it was found.  Its JSON strings are in the
well file's own syntax (:func:`sinktheory.userwell.expression_text`): a parameter prints
by its plain name even where SymPy has a function or constant of that name (``gamma``,
``beta``, ``E``, ``I``, ``N``, ...), so ``sympify`` reads them back given those names as
symbols, ``sympy.sympify(text, locals={name: sympy.Symbol(name) for name in
data["parameters"]})``; ``parameters`` holds the values the well was checked at.  A
refused well is one line on stderr, exit status 2; nothing is written (no cache: the file
is read each time).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import tempfile
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import TYPE_CHECKING

from . import HELP as HELPS
from ._common import Output, add_json, add_well_file, user_well_from_args

__all__ = ["HELP", "NAME", "SOURCES"]

if TYPE_CHECKING:
    import sympy as sp

NAME = "derive"
HELP = HELPS[NAME]

#: The files whose text decides the derived equations and how they print.
SOURCES = (Path(__file__).parents[1] / "symbolic.py", Path(__file__))


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--latex", action="store_true", help="print LaTeX instead of text")
    parser.add_argument(
        "--fresh", action="store_true", help="derive again instead of reading the cached result"
    )
    add_well_file(parser)
    add_json(parser)


def equations() -> dict[str, sp.Expr]:
    """The derived equations, keyed as in the JSON output.

    ``x_equation`` and ``y_equation`` are expressions equal to zero in the plain symbols
    x, y, X, xdd, ydd (second time derivatives), n, mu, alpha, beta, gamma of the rescaled
    single-particle system; ``y_equation`` is linear in y (general n >= 2) and the
    ``y_equation_n1_*`` keys give the n = 1 forms with their extra term.
    """
    from .. import symbolic as S

    flat = S.rescaled_equations("flat")
    return {
        "potential_flat": S.potential("flat"),
        "potential_symmetric": S.potential("symmetric"),
        "hamiltonian": S.hamiltonian(1, "flat"),
        "hamiltonian_symmetric": S.hamiltonian(1, "symmetric"),
        "x_equation": flat.x_equation,
        "y_equation": flat.y_equation,
        "y_equation_n1_flat": S.rescaled_equations("flat", 1).y_equation,
        "y_equation_n1_symmetric": S.rescaled_equations("symmetric", 1).y_equation,
        "lambda": S.lambda_coefficient(),
        "period": S.period_closed_form(),
        "curvature": S.rigid_wall_curvature(),
    }


def sympifiable(expr: sp.Expr) -> str:
    """A string of ``expr`` that :func:`sympy.sympify` turns back into the same expression
    (up to symbol assumptions).

    Examples
    --------
    >>> from sinktheory.symbolic import beta, gamma, x
    >>> sympifiable(gamma * x**2 - beta)
    "-Symbol('beta') + Symbol('gamma')*x**2"
    """
    import sympy as sp
    from sympy.printing.str import StrPrinter

    class SympifiableStr(StrPrinter):
        """str() that sympify reads back: symbols whose names sympify would take for a
        function or constant (beta, gamma, E, ...) are written as Symbol('name')."""

        def _print_Symbol(self, expr):  # noqa: D102 - printer protocol
            name = expr.name
            if isinstance(sp.sympify(name), sp.Symbol):
                return name
            return f"Symbol({name!r})"

    return SympifiableStr().doprint(expr)


def renderings() -> dict[str, dict[str, str] | str]:
    """Derive the equations and render them: ``{"json": {key: sympifiable string},
    "text": pretty text, "latex": LaTeX text}`` (what the cache file holds)."""
    import sympy as sp

    eqs = equations()
    return {
        "json": {key: sympifiable(expr) for key, expr in eqs.items()},
        "text": "\n\n".join(
            f"{key}:\n{sp.pretty(expr, use_unicode=True, wrap_line=False)}"
            for key, expr in eqs.items()
        ),
        "latex": "\n".join(f"% {key}\n{sp.latex(expr)}" for key, expr in eqs.items()),
    }


def well_renderings(well, given: dict, report) -> dict:
    """The ladder of a user's ``well`` (at the parameter values ``given``, its defaults for
    the others; ``report`` its :func:`~sinktheory.userwell.check_well` there) rendered as
    :func:`renderings` renders the paper's equations, the JSON strings in the well file's
    syntax (module docstring), plus ``parameters`` (their values), ``escape_energy`` (measured
    from V(0, 0), as everywhere: :attr:`sinktheory.basin.Basin.escape_energy`), ``escape``
    (how it was found) and ``normal_mode`` (why y = 0 is or is not a normal mode) in the
    JSON."""
    import sympy as sp

    from .. import symbolic as S
    from ..userwell import expression_text

    steps = S.ladder(well, well.values(**given))
    eqs = steps.items()
    escape, e_star = report.basin.escape, report.basin.escape_energy
    mode = steps.normal_mode
    why = (
        f"y = 0 is a normal mode ({mode.reason})"
        if mode.invariant
        else f"y = 0 is not invariant ({mode.reason}): Floquet multipliers, normal modes "
        "and transverse exponents do not apply"
    )
    values = ", ".join(f"{k} = {v}" for k, v in report.values.items()) or "none"
    which = "at their defaults" if not given else "(--well-param, defaults for the others)"
    notes = [f"well {well.name}; parameters {which}: {values}",
             f"at these values, {escape.describe(report.basin.well.v0)}", why]  # fmt: skip
    text = "\n\n".join(
        f"{key}:\n{sp.pretty(expr, use_unicode=True, wrap_line=False)}" for key, expr in eqs.items()
    )
    latex = "\n".join(f"% {key}\n{sp.latex(expr)}" for key, expr in eqs.items())
    data = {key: expression_text(expr) for key, expr in eqs.items()}
    data |= {
        "well": well.name,
        "parameters": {name: float(value) for name, value in report.values.items()},
        "escape_energy": e_star if math.isfinite(e_star) else None,
        "escape": escape.describe(report.basin.well.v0),
        "normal_mode": why,
    }
    return {
        "json": data,
        "text": "\n".join(notes) + "\n\n" + text,
        "latex": "\n".join(f"% {line}" for line in notes) + "\n" + latex,
    }


def digest() -> str:
    """Digest of :data:`SOURCES` and the sinktheory and SymPy versions (12 hex digits)."""
    h = hashlib.sha256()
    for package in ("sinktheory", "sympy"):
        try:
            h.update(f"{package} {version(package)}\n".encode())
        except PackageNotFoundError:  # a source tree that is not installed
            h.update(f"{package} ?\n".encode())
    for path in SOURCES:
        h.update(Path(path).read_bytes())
    return h.hexdigest()[:12]


def cache_file() -> Path:
    """The cache file of the current :func:`digest`."""
    from ..engine.cache import cache_dir

    return cache_dir() / f"derive-{digest()}.json"


def cached_renderings(*, fresh: bool = False) -> dict:
    """:func:`renderings`, read from :func:`cache_file` when it is there (and not
    ``fresh``), else derived and written there (atomically; a cache that cannot be
    written is skipped, the result is the same)."""
    path = cache_file()
    if not fresh:
        try:
            return json.loads(path.read_text())
        except (OSError, ValueError):
            pass
    out = renderings()
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".derive-", suffix=".json")
    except OSError:
        return out
    try:
        with os.fdopen(fd, "w") as f:
            json.dump(out, f)
        os.replace(tmp, path)
    except OSError:
        Path(tmp).unlink(missing_ok=True)
    return out


def run(args: argparse.Namespace) -> Output:
    user = user_well_from_args(args)
    if user is not None:
        out = well_renderings(*user)
    else:
        out = cached_renderings(fresh=args.fresh)
    return Output(out["json"], out["latex"] if args.latex else out["text"])
