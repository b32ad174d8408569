"""One scene per figure of the paper; :data:`SCENES` maps figure numbers to scenes.

Each scene declares the least model it needs and computes only that (see
:class:`~sinktheory.scenes.base.Scene`).
"""

from .base import Claim, Scene, SceneResult
from .orbits import FIG3, FIG11
from .wells import FIG2, FIG10

SCENES: dict[int, Scene] = {s.number: s for s in (FIG2, FIG3, FIG10, FIG11)}

__all__ = ["SCENES", "Claim", "Scene", "SceneResult"]
