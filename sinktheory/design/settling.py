"""Predicted settling times of the recommended designs.

A design's own ensemble says how fast it drains (t50, t80); how long its mean container
energy takes to come within 5 % of its long-time level (the exact equilibrium law) is
predicted here, for the designs a report shows, by
:func:`sinktheory.equilibrium.settling_periods`: the slow-mode model of
:mod:`sinktheory.equilibrium.prediction` from short runs on the energy shell (12 energies
x 100 runs over 128 periods with the defaults: about a second per design for one
particle, several for five), its interval widened by the model's known error
(:data:`~sinktheory.equilibrium.prediction.MODEL_FACTOR` either way).  The answer is marked
predicted: the model is within that factor of measured settling times on the cases of
docs/guide/make_relaxation.py, and leans short where the relaxation is slow (flagged
``+``).

Only the conservative 2-D well has a law to settle to: a 1-D attachment, or damped
contact, gets the reason instead of a number, and so does a design the model cannot
resolve (a relaxation faster than its shortest lag, for instance) and a user's well on
the shape axis (the relaxation model reads a registered shape's parameters).

Examples
--------
>>> predicted_settling({"attachment": "nes", "damping": 0.0})
'n/a: 1-D attachment'
>>> from sinktheory.equilibrium import Settling
>>> settling_text(Settling(433.2, 149.0, 1265.0, "predicted", True, 0.05, ""))
'433 (149-1265)+'
"""

from __future__ import annotations

from collections.abc import Mapping

from ..equilibrium.prediction import Settling, settling_periods
from ..errors import NumericalError

__all__ = ["SETTLING_FIELDS"]

#: The columns of ``designs.csv`` and the keys of the design JSON that hold a design's
#: predicted settling (:func:`settling_fields`).
SETTLING_FIELDS = ("settles", "settles_low", "settles_high", "settles_note")


def predicted_settling(point: Mapping, *, seed: int = 0, **shell) -> Settling | str:
    """The predicted settling time of one design (``point``: its parameters, as a ranked
    row with the sweep's fixed attributes), or why there is none.  ``shell``: the
    ``shell_energies``, ``shell_runs`` and ``lag`` of
    :func:`~sinktheory.equilibrium.settling_periods`."""
    if point.get("attachment", "well") != "well":
        return "n/a: 1-D attachment"
    if float(point.get("damping", 0.0)) > 0:
        return "n/a: damped contact"
    from .point import user_shape

    if user_shape(point):
        return "n/a: a user's well (the relaxation model takes a registered shape)"
    from ..ensemble import sink_of

    try:
        e0 = float(point["container_energy"])
        return settling_periods(sink_of(point), e0, seed=seed, **shell)
    except NumericalError as exc:
        return f"not predicted: {str(exc).split(' (')[0]}"


def settling_column(ranked: list, attrs: Mapping, top: int, **shell) -> dict[int, Settling | str]:
    """rank -> :func:`predicted_settling` of the first ``top`` ranked designs."""
    return {r["rank"]: predicted_settling({**attrs, **r}, **shell) for r in ranked[:top]}


def settling_fields(s: Settling | str | None) -> dict:
    """A design's predicted settling as plain values under :data:`SETTLING_FIELDS`: the
    settling time in periods and its interval (widened by the model's factor), and a note:
    ``"predicted"``, ``"predicted, probably short"`` (flagged ``+`` in the report), or the
    reason there is no number (``"not predicted"`` for None: a design below the top rows).

    Examples
    --------
    >>> settling_fields(Settling(433.2, 149.0, 1265.0, "predicted", True, 0.05, ""))
    {'settles': 433.2, 'settles_low': 149.0, 'settles_high': 1265.0, \
'settles_note': 'predicted, probably short'}
    >>> settling_fields("n/a: 1-D attachment")["settles"] is None
    True
    """
    if s is None or isinstance(s, str):
        values = (None, None, None, "not predicted" if s is None else s)
    else:
        note = s.source + (", probably short" if s.extrapolated else "")
        values = (float(s.periods), float(s.low), float(s.high), note)
    return dict(zip(SETTLING_FIELDS, values, strict=True))


def settling_text(s: Settling | str) -> str:
    """'t_f (low-high)' in periods, ``+`` when the model flags it as probably short; the
    reason when there is no number."""
    if isinstance(s, str):
        return s
    return f"{s.periods:.0f} ({s.low:.0f}-{s.high:.0f})" + ("+" if s.extrapolated else "")
