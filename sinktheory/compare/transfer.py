r"""Targeted energy transfer seen through a wavelet: the container's instantaneous
frequency against the energy left, over the normal modes' frequency-energy curves.

:func:`transfer_map` runs one impulsive start of an attachment
(:func:`sinktheory.attachments.impulse_response`), takes the Morlet wavelet map of the
recorded container displacement X(t) (:func:`sinktheory.compare.wavelet.wavelet_map`)
and pairs its ridge omega(t) with the total energy left at that time,
H(t) = H(0) - W(t) (W the dashpot's work: the audited balance of the run).
:func:`backbone` continues the in-plane normal modes (all particles on y = 0, moving
together; :func:`sinktheory.nnm.continuation.continue_both`) of the attachment's sink
over the same energies: the frequency-energy plot the ridge is drawn on
(:func:`sinktheory.plot.compare.plot_transfer`).  A ridge that follows a branch as the
energy falls is energy held in that mode; a ridge that leaves every branch is energy
transferred elsewhere -- for the 2-D sink, out of the invariant plane.

For the 1-D NES the backbone is its in-phase 1:1 family
(:mod:`sinktheory.nnm.backbone`); the figure marks where that family changes from
particle- to container-localised (:func:`sinktheory.nnm.backbone.localisation_energy`),
the energy near which the NES's transfer threshold lies.  The vibro-impact attachment
has no smooth normal modes in :mod:`sinktheory.nnm`; its backbone is empty.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..attachments import Attachment
from ..errors import ParameterError
from ..glossary import old_attribute, renamed
from ..results import Result
from .wavelet import DEFAULT_WAVELET, WaveletMap, wavelet_map

__all__ = [
    "backbone",
    "BACKBONE_POINTS",
    "BACKBONE_STEPS",
    "START_TRIES",
    "transfer_map",
    "TransferMap",
]

#: Shooting steps per period and largest points per direction of the backbone.
BACKBONE_STEPS = 200
BACKBONE_POINTS = 150
#: Start energies tried for a mode, log-spaced from lo, before it is left out.
START_TRIES = 4


@renamed(energy="impulse_energy")
@dataclass(frozen=True)
class TransferMap(Result):
    """One run's wavelet map and its ridge against the energy left.

    Attributes
    ----------
    wavelet : WaveletMap
        Of the container displacement X(t).
    energy_left : (S,) total energy H(t) = H(0) - W(t) of the run
    container_energy : (S,) the container's energy (X^2 + Xdot^2) / 2
    label : str
        The attachment's label.
    impulse_energy, damping : float
        The impulse's container energy E0 and the dashpot coefficient.
    run : int
        Which run of the seeded ensemble.
    """

    wavelet: WaveletMap
    energy_left: np.ndarray
    container_energy: np.ndarray
    label: str
    impulse_energy: float
    damping: float
    run: int

    DIMS = {"energy_left": ("t",), "container_energy": ("t",)}

    energy = old_attribute("impulse_energy")


@renamed(energy="container_energy")
def transfer_map(
    att,
    container_energy: float,
    *,
    damping: float,
    periods: int,
    seed: int = 0,
    run: int = 0,
    samples_per_period: int = 16,
    omega=(0.3, 3.0, 160),
    wavelet: str = DEFAULT_WAVELET,
    tol: float | None = None,
) -> TransferMap:
    """The wavelet map of run ``run`` of an impulsive start (module docstring).

    Parameters
    ----------
    att : Attachment
    container_energy, damping, periods, seed, samples_per_period, tol
        As :func:`sinktheory.attachments.impulse_response`.
    run : int >= 0
        The run of the seeded ensemble (runs ``0..run`` are integrated).
    omega, wavelet
        As :func:`sinktheory.compare.wavelet.wavelet_map`.

    Examples
    --------
    >>> from sinktheory.attachments import Attachment
    >>> m = transfer_map(Attachment("nes", n=2), 0.05, damping=0.01, periods=30,
    ...                  omega=(0.5, 2.0, 40))
    >>> ridge = m.wavelet.ridge[np.isfinite(m.wavelet.ridge)]
    >>> bool(ridge.size > 0 and (m.energy_left[-1] < m.energy_left[0]))
    True
    """
    from ..attachments import impulse_response
    from .efficiency import check_attachments, check_damping

    check_damping(damping, check_attachments([att]))
    run = v.positive_int("run", run, minimum=0, maximum=10**6)
    res = impulse_response(
        att,
        container_energy,
        damping=damping,
        periods=periods,
        runs=run + 1,
        seed=seed,
        samples_per_period=samples_per_period,
        tol=tol,
    )
    w = wavelet_map(res.t, res.container_x[run], omega=omega, wavelet=wavelet)
    left = res.initial_energy[run] - res.dissipated[run]
    return TransferMap(
        w,
        left,
        res.container_energy[run],
        att.label,
        float(res.impulse_energy),
        float(res.damping),
        run,
    )


def transfer_maps(
    attachments,
    wavelet_energy: float | None = None,
    *,
    energies=(),
    damping: float,
    periods: int,
    seed: int = 0,
    samples_per_period: int = 16,
    tol: float | None = None,
) -> tuple[list[TransferMap], list[list], list[str]]:
    """What ``compare --wavelet-plot`` draws: the map of run 0 of each attachment after an
    impulse E0 = ``wavelet_energy`` (:func:`transfer_map`), and the backbones of each
    kind of sink (:func:`backbone`; the in-plane normal modes do not depend on the particle
    count or the shape) over total energies from half the lowest to twice the highest of
    ``wavelet_energy`` and ``energies`` (the grid the maps are set beside).

    Parameters
    ----------
    attachments : sequence of Attachment
    wavelet_energy : float > 0, optional
        E0 of the maps' impulse (default the highest of ``energies``).
    energies : sequence of float > 0
        Initial container energies the backbones must cover too.
    damping, periods, seed, samples_per_period, tol
        As :func:`transfer_map`.

    Returns
    -------
    (maps, backbones, notes)
        One map and one list of branches per attachment (:func:`plot.compare.plot_transfer
        <sinktheory.plot.compare.plot_transfer>` draws them); ``notes`` names each mode left
        out, prefixed by its attachment's label.
    """
    for att in attachments:  # before any run
        _check_backbone(att)
    grid = [float(e) for e in energies]
    if wavelet_energy is None:
        if not grid:
            raise ParameterError("wavelet_energy", None, "given when energies is empty")
        wavelet_energy = max(grid)
    energy = v.positive("wavelet_energy", wavelet_energy)
    lo = min([energy, *grid]) / 2
    hi = 2.0 * max([energy, *grid])
    maps, bones, notes, cache = [], [], [], {}
    for att in attachments:
        maps.append(transfer_map(att, energy, damping=damping, periods=periods, seed=seed,
                                 samples_per_period=samples_per_period, tol=tol))  # fmt: skip
        key = (att.kind, att.n, att.shape)
        if key not in cache:
            cache[key] = backbone(att, lo, hi)
            notes += [f"{att.label}: {note}" for note in cache[key][1]]
        bones.append(cache[key][0])
    return maps, bones, notes


def _check_backbone(att) -> None:
    """Refuse an attachment whose backbone :func:`backbone` cannot draw: a user's well."""
    if not isinstance(att, Attachment):
        raise ParameterError("att", att, "a sinktheory.attachments.Attachment")
    if att.user_well is not None:
        raise ParameterError(
            "attachments", att.label, "attachments of registered shapes for the backbones",
            why="the normal modes are continued in a registered shape's well (alpha, beta, "
            "n), not in a user's well",
        )  # fmt: skip


def backbone(att, lo: float, hi: float, *, points: int = BACKBONE_POINTS) -> tuple[list, list]:
    """The in-plane normal modes of ``att``'s sink between total energies ``lo`` and
    ``hi``: (branches, notes).

    The container mode is started at ``lo`` (where it is nearly linear), the particle
    mode at the geometric mean of ``lo`` and ``hi``; where the shooting does not converge
    from the mode's guess (:func:`sinktheory.nnm.modes.mode_guess`; the branches of an
    essentially nonlinear attachment fold and tongue, so a plain guess does not converge
    everywhere), the next of ``START_TRIES + 1`` log-spaced energies from ``lo`` is
    tried.  Each mode is continued both ways
    (:func:`sinktheory.nnm.continuation.continue_both`) until it leaves [lo, hi] or has
    ``points`` points a side; a mode that never converges is left out and named in
    ``notes``.  Empty for the vibro-impact attachment.

    For the 1-D NES (n >= 2) the container mode is replaced by the in-phase 1:1 backbone
    (:func:`sinktheory.nnm.backbone.inphase_pieces`): the free particle's zero
    frequency at low energy keeps the container mode's guess off that family, which the
    impulse excites and along which the dashpot walks the energy down.
    """
    from ..nnm.backbone import inphase_pieces
    from ..nnm.continuation import continue_both
    from ..nnm.shooting import ShootingError

    _check_backbone(att)
    lo, hi = v.positive("lo", lo), v.positive("hi", hi)
    if not lo < hi:
        raise ParameterError("hi", hi, f"an energy > lo = {lo:g}")
    points = v.positive_int("points", points, minimum=2, maximum=10_000)
    if att.kind == "impact":
        return [], ["the vibro-impact attachment has no smooth normal modes"]
    branches, notes = [], []
    modes = ("container", "particle")
    if att.kind == "nes" and att.n >= 2:
        pieces, why = inphase_pieces(att.sink, lo, hi, points=points)
        branches += pieces
        notes += why
        modes = ("particle",)
    tries = np.geomspace(lo, hi, START_TRIES + 2)[: START_TRIES + 1]
    starts_of = {"container": tries, "particle": [math.sqrt(lo * hi), *tries]}
    for mode in modes:
        error = None
        for start in starts_of[mode]:
            try:
                b = continue_both(
                    att.sink,
                    mode,
                    total_energy=float(start),
                    interval=(lo, hi),
                    steps=BACKBONE_STEPS,
                    points=points,
                    ds=0.5,
                )
            except ShootingError as e:
                error = e
                continue
            branches.append(b)
            break
        else:
            notes.append(f"{mode} mode not converged from any start guess: {error}")
    return branches, notes
