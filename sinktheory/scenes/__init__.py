"""One scene per figure of the paper; :data:`SCENES` maps figure numbers to scenes.

Each scene declares the least model it needs and computes only that (see
:class:`~sinktheory.scenes.base.Scene`).
"""

from .base import Claim, Scene, SceneResult
from .ensembles import FIG5, FIG8, FIG9, FIG12
from .orbits import FIG3, FIG11
from .stability import FIG7
from .trajectories import FIG4
from .wells import FIG2, FIG10

SCENES: dict[int, Scene] = {
    s.number: s for s in (FIG2, FIG3, FIG4, FIG5, FIG7, FIG8, FIG9, FIG10, FIG11, FIG12)
}

__all__ = ["SCENES", "Claim", "Scene", "SceneResult"]
