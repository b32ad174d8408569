"""Shared by the derivation scripts: print each result and compare it with the paper.

A script calls :func:`check` for every equation and :func:`finish` at the end, which
exits with status 1 if any derived expression differs from the expected (paper) form.
"""

from __future__ import annotations

import sys

import sympy as sp

_failures: list[str] = []


def show(title: str, expr) -> None:
    """Print a derived result under a heading."""
    print(f"\n== {title}")
    print(sp.pretty(expr, use_unicode=True, wrap_line=False))


def equal(derived, expected, probes=()) -> bool:
    """Symbolic identity: simplify(derived - expected) == 0, else exact rational probes.

    ``probes`` are substitution dicts (exact rationals and integer n) used when simplify
    cannot decide; every probe must give exactly zero.
    """
    if isinstance(derived, sp.MatrixBase):
        return derived.shape == expected.shape and all(
            equal(a, b, probes) for a, b in zip(derived, expected, strict=True)
        )
    diff = sp.simplify(sp.expand(derived - expected))
    if diff == 0:
        return True
    return bool(probes) and all(sp.nsimplify(diff.subs(p)) == 0 for p in probes)


def check(title: str, derived, expected, *, probes=(), note: str | None = None) -> bool:
    """Show ``derived``; record a failure unless it equals ``expected``."""
    show(title, derived)
    ok = equal(derived, expected, probes)
    print("   OK" if ok else "   MISMATCH with the expected form:")
    if not ok:
        print(sp.pretty(expected, use_unicode=True, wrap_line=False))
        _failures.append(title)
    if note:
        print(f"   note: {note}")
    return ok


def finish() -> None:
    """Exit 0 if every check passed, 1 otherwise."""
    if _failures:
        print(f"\nFAILED: {', '.join(_failures)}")
        sys.exit(1)
    print("\nall checks passed")
