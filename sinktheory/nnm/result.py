"""Labelled arrays of a continued branch: :class:`BranchResult` (dict / xarray).

Arrays are indexed by ``point`` (along the branch, in continuation order); multipliers
by ``point`` and ``multiplier`` (complex, sorted by real then imaginary part).  The
result follows :mod:`sinktheory.results`: ``as_dict()`` writes each multiplier as
``[re, im]`` (JSON has no complex numbers), ``to_dataset()`` keeps them complex.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..glossary import old_attribute
from ..results import Result

__all__ = ["BranchResult"]


def _pad(rows: list[np.ndarray]) -> np.ndarray:
    width = max((r.size for r in rows), default=0)
    out = np.full((len(rows), width), complex("nan"))
    for i, r in enumerate(rows):
        out[i, : r.size] = r
    return out


@dataclass(frozen=True)
class BranchResult(Result):
    """One branch of periodic orbits as labelled arrays.

    Attributes
    ----------
    meta : dict
        system, params, continue_in (the continuation parameter), steps, scheme,
        stop_reason, ...;
        ``as_dict()`` and ``to_dataset()`` list its entries beside the arrays (as keys,
        as attributes), followed by ``max_trivial_error`` and ``max_abs_sigma``.
    value : (P,) continuation parameter (energy or the well parameter)
    total_energy : (P,) the total energy H of each orbit (the fixed one, at every point,
        of a branch in a well parameter)
    period, frequency : (P,)
    sigma, residual, trivial_error : (P,) checks (unfolding parameter, max |Phi(z0) - z0|,
        distance of the trivial multipliers from 1)
    stable, stable_inplane, stable_transverse : (P,) bool
    nontrivial, transverse, multipliers : (P, m) complex
    z0 : (P, 2D) start states
    phi_half : (P, k) transverse half-period half-traces (nan when not computed)
    symmetry_error : (P,) max |z(T/2) + z0| (nan when not computed)
    events : list of dict (kind, index, value, total_energy, frequency, multiplier)
    """

    meta: dict
    value: np.ndarray
    total_energy: np.ndarray
    period: np.ndarray
    frequency: np.ndarray
    sigma: np.ndarray
    residual: np.ndarray
    trivial_error: np.ndarray
    stable: np.ndarray
    stable_inplane: np.ndarray
    stable_transverse: np.ndarray
    nontrivial: np.ndarray
    transverse: np.ndarray
    multipliers: np.ndarray
    z0: np.ndarray
    phi_half: np.ndarray
    symmetry_error: np.ndarray
    events: list = field(default_factory=list)

    energy = old_attribute("total_energy")

    DIMS = {
        **dict.fromkeys(
            (
                "value",
                "total_energy",
                "period",
                "frequency",
                "sigma",
                "residual",
                "trivial_error",
                "stable",
                "stable_inplane",
                "stable_transverse",
                "symmetry_error",
            ),
            ("point",),
        ),
        "nontrivial": ("point", "inplane_multiplier"),
        "transverse": ("point", "transverse_multiplier"),
        "multipliers": ("point", "multiplier"),
        "z0": ("point", "state"),
        "phi_half": ("point", "particle"),
    }

    @classmethod
    def _from_branch(cls, branch, *, half_traces: bool = False, **meta) -> BranchResult:
        """Collect a :class:`~sinktheory.nnm.continuation.Branch` (``half_traces``: also
        the transverse phi_half of every point, one more half-period run each)."""
        orbits = branch.orbits
        fl = [o.floquet for o in orbits]
        k = len(orbits[0].z0) // 2 - len(orbits[0].free) // 2 if orbits else 0
        phi = np.full((len(orbits), k), np.nan)
        sym = np.full(len(orbits), np.nan)
        if half_traces and k and orbits[0].steps % 2 == 0:
            for i, o in enumerate(orbits):
                phi[i] = o.transverse_half_traces()
                sym[i] = o.half_period()[2]
        p = branch.problem
        info = {
            "system": p.system.system,
            "params": dict(zip(p.system.parameter_names, p.system.params.tolist(), strict=True)),
            "continue_in": p.continue_in,
            "steps": p.steps,
            "scheme": p.system.scheme,
            "free": [int(i) for i in p.free],
            "stop_reason": branch.stop_reason,
        }
        info.update(meta)
        events = [
            {
                "kind": e.kind,
                "index": e.index,
                "value": e.value,
                "total_energy": e.orbit.total_energy,
                "frequency": e.orbit.frequency,
                "multiplier": None
                if np.isnan(e.multiplier)
                else [float(np.real(e.multiplier)), float(np.imag(e.multiplier))],
            }
            for e in branch.events
        ]
        return cls(
            meta=info,
            value=branch.values,
            total_energy=branch.total_energy,
            period=branch.period,
            frequency=branch.frequency,
            sigma=np.array([o.sigma for o in orbits]),
            residual=np.array([o.residual for o in orbits]),
            trivial_error=np.array([f.trivial_error for f in fl]),
            stable=np.array([f.stable for f in fl]),
            stable_inplane=np.array([f.stable_inplane for f in fl]),
            stable_transverse=np.array([f.stable_transverse for f in fl]),
            nontrivial=_pad([f.nontrivial for f in fl]),
            transverse=_pad([f.transverse for f in fl]),
            multipliers=_pad([f.all for f in fl]),
            z0=np.array([o.z0 for o in orbits]),
            phi_half=phi,
            symmetry_error=sym,
            events=events,
        )

    @property
    def points(self) -> int:
        return int(self.value.size)

    def items(self) -> dict:
        out = super().items()
        out = {**out.pop("meta"), **out}
        out["max_trivial_error"] = float(np.max(self.trivial_error)) if self.points else None
        out["max_abs_sigma"] = float(np.max(np.abs(self.sigma))) if self.points else None
        return out

    def coords(self) -> dict:
        return {"point": np.arange(self.points)}
