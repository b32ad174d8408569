"""Initial deviation vectors: seeded, orthonormal, optionally confined to a subspace.

Deviation vectors live in the engine's coordinates (q, v) (positions and velocities, see
:class:`sinktheory.engine.core.Ensemble`).  Run r draws its vectors from
``SeedSequence(seed, spawn_key=(r, 0))`` -- the first child of the seed that
:func:`sinktheory.ensemble.random_positions` gives run r -- so they depend only on the seed
and r, never on how runs are spread over threads.  The columns are orthonormalised by
modified Gram-Schmidt in plain numpy (no LAPACK, whose results may depend on threads).

Examples
--------
>>> dq, dv = random_vectors(dim=2, count=3, runs=2, seed=1)
>>> dq.shape
(2, 3, 2)
>>> W = np.concatenate([dq[:, :, 0], dv[:, :, 0]])  # the 3 vectors of run 0, (4, 3)
>>> bool(np.allclose(W.T @ W, np.eye(3), atol=1e-14))
True
>>> mask = [False, False, True, False, False, False]  # the direction of q_2 only
>>> dq, dv = random_vectors(dim=3, count=1, runs=1, seed=0, mask=mask)
>>> dq[:, 0, 0].tolist(), dv[:, 0, 0].tolist()
([0.0, 0.0, 1.0], [0.0, 0.0, 0.0])
"""

from __future__ import annotations

import numpy as np

from .. import validation as v
from ..errors import ParameterError

__all__ = ["MAX_DIM", "ORTHONORMALISE_SECONDS", "random_vectors"]

#: Largest number of coordinates D (1 + 2k for k = 10^5 particles).
MAX_DIM = 200_001
#: Seconds :func:`orthonormalise` takes per component and squared column (n^3 columns of
#: n components: 1.7e-8 at n = 400, 1.4e-8 at n = 1000, measured 2026-11 on the 2-core
#: development machine; 13.7 s at n = 1000); rounded up, so the set-up of a spectrum is
#: not priced optimistically (the goal of :mod:`sinktheory.worklimit`'s estimates).
ORTHONORMALISE_SECONDS = 2e-8


def orthonormalise(W: np.ndarray) -> np.ndarray:
    """Modified Gram-Schmidt of the columns of W (n, m), m <= n, in a fixed order."""
    W = np.array(W, dtype=float)
    for m in range(W.shape[1]):
        for l in range(m):  # noqa: E741 - the usual index name
            W[:, m] -= (W[:, l] @ W[:, m]) * W[:, l]
        norm = np.sqrt(W[:, m] @ W[:, m])
        if not norm > 0:
            raise ParameterError("vectors", "linearly dependent vectors", "independent vectors")
        W[:, m] /= norm
    return W


def vector_seed(seed: int, run: int) -> np.random.SeedSequence:
    """The seed of run ``run``'s deviation vectors (first child of its position seed)."""
    return np.random.SeedSequence(seed, spawn_key=(int(run), 0))


def random_vectors(
    dim: int, count: int, runs: int, seed: int, *, mask=None
) -> tuple[np.ndarray, np.ndarray]:
    """``count`` orthonormal random deviation vectors for each of ``runs`` runs.

    Parameters
    ----------
    dim : int
        Number of coordinates D (the phase space has 2D dimensions).
    count : int
        Vectors per run M, at most the number of free phase-space directions.
    runs, seed : int
        Ensemble size and seed (see the module docstring).
    mask : array of bool (2D,), optional
        Phase-space directions (q_0..q_{D-1}, v_0..v_{D-1}) the vectors may use; the others
        stay exactly zero.

    Returns
    -------
    dq, dv : arrays (D, M, R)
    """
    from ..model import MAX_RUNS

    dim = v.positive_int("dim", dim, maximum=MAX_DIM)
    runs = v.positive_int("runs", runs, maximum=MAX_RUNS)
    seed = v.positive_int("seed", seed, minimum=0)
    if mask is None:
        mask = np.ones(2 * dim, bool)
    else:
        mask = v.real_array("mask", mask)
        if mask.shape != (2 * dim,) or not np.isin(mask, (0, 1)).all():
            raise ParameterError("mask", f"an array of shape {mask.shape}",
                                 f"{2 * dim} booleans")  # fmt: skip
        mask = mask.astype(bool)
    free = int(mask.sum())
    count = v.positive_int("count", count, maximum=max(free, 1))
    if count > free:  # an all-False mask
        raise ParameterError("mask", "no free direction", "at least one True")
    # the square draw per run below: free^2 numbers, besides the vectors themselves
    v.fits_memory("runs", runs, 8.0 * (2 * dim * count * runs + free * free), "the vectors",
                  "smaller")  # fmt: skip
    W = np.zeros((2 * dim, count, runs))
    for r in range(runs):
        g = np.random.default_rng(vector_seed(seed, r))
        # a full square draw, so vector m does not depend on how many are asked for
        W[mask, :, r] = orthonormalise(g.standard_normal((free, free))[:, :count])
    return np.ascontiguousarray(W[:dim]), np.ascontiguousarray(W[dim:])
