"""Rigid billiards: the n -> oo limit of the soft-wall sink.

:mod:`.table` builds the billiard table of each registered well shape from its wall
ratios (and test tables from segments and arcs), :mod:`.kernels` is the compiled event
engine (exact flights, conservative-advancement collision search, specular reflection or
the elastic impact on the moving container, the billiard tangent map), :mod:`.run` the
ensembles and their :class:`~sinktheory.results.Result`.
"""

from .run import (
    BilliardResult,
    RigidLimit,
    billiard,
    rigid_limit,
    simulate_billiard,
    well_billiard,
)
from .table import (
    Piece,
    Table,
    polynomial_table,
    rigid_table,
    sinai_table,
    stadium_table,
    well_table,
)

__all__ = [
    "BilliardResult",
    "Piece",
    "RigidLimit",
    "Table",
    "billiard",
    "polynomial_table",
    "rigid_limit",
    "rigid_table",
    "well_table",
    "simulate_billiard",
    "sinai_table",
    "stadium_table",
    "well_billiard",
]


from .._verbs import make_callable as _make_callable  # noqa: E402 (module complete here)

_make_callable(__name__, "billiard")
