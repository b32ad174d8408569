"""What a scene is: one figure of the paper, its parameters, and the claims it checks."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..errors import ParameterError
from ..results import Result
from ..validation import choice

__all__ = ["BEYOND", "Claim", "Scene", "SceneResult", "SIGN_CALL"]

HOLDS, FAILS, UNDECIDED = "holds", "does not hold", "cannot be decided"
#: Prefix of a claim the report adds to the paper's (not counted as the paper's own).
BEYOND = "(beyond the paper)"
#: Why a row judged by a chaos indicator needs no run of three relaxation times (the
#: report's rule for every "does not hold": a long enough run, or a stated reason).
SIGN_CALL = (
    "No run of three relaxation times is needed: the row calls the sign of an exponent, not "
    "a level approached over a relaxation time; a regular orbit's finite-time exponent "
    "decays like ln t / t, below the envelope 3 ln t / t at any horizon, and in this "
    "conservative system an orbit of the chaotic sea never settles onto a torus"
)


@dataclass(frozen=True)
class Claim(Result):
    """A statement of the paper, what we measured, a plain verdict, and (for the paper's
    own claims) the physics behind the verdict in a sentence or two, using only numbers
    of ``measured`` (the report's closing section collects them)."""

    statement: str
    measured: str
    verdict: str
    physics: str = ""

    def __post_init__(self) -> None:
        for name in ("statement", "measured", "physics"):
            if not isinstance(getattr(self, name), str):
                raise ParameterError(name, getattr(self, name), "text (a str)")
        choice("verdict", self.verdict, (HOLDS, FAILS, UNDECIDED))


@dataclass
class SceneResult:
    """A drawn figure with the parameters it used, claims checked and notes."""

    figure: Any  # a matplotlib.figure.Figure, drawn by sinktheory.plot
    parameters: dict[str, Any]
    claims: list[Claim] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class Scene:
    """One figure of the paper.

    Attributes
    ----------
    number : the paper's figure number
    title : what the figure shows
    needs : the least model the scene computes (documented; e.g. "potential contours")
    build : build(quick) -> SceneResult; ``quick`` lowers the fidelity (runs, periods,
        grid sizes) for a fast preview, never the physics parameters
    """

    number: int
    title: str
    needs: str
    build: Callable[[bool], SceneResult]
