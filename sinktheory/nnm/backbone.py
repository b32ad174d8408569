r"""The in-phase 1:1 backbone of a particle on the invariant line: the nonlinear energy
sink's frequency-energy curve.

On the line y = 0 the particles moving together are one mass m (the sink's total) on the
container, held by the force k gamma / L^(2n) x^(2n - 1) (L = alpha - beta, x = u - X,
k particles): for n = 2 the cubic nonlinear energy sink (NES).  Its linearisation has a
zero-frequency mode (the free particle), so the container mode started at low energy
(:func:`sinktheory.nnm.modes.mode_guess`) leaves the in-phase family at once.  The
in-phase family (container and particle moving the same way, frequency below
1 / sqrt(1 + m)) is instead started here from its single-harmonic balance,

    X = A cos(w t),  u = B cos(w t),  r = B / A = (1 - w^2) / (m w^2) > 1,
    m w^2 r A = kappa c (r - 1)^(2n-1) A^(2n-1),   c = binom(2n-1, n-1) / 2^(2n-2),

(the fixed points of the 1:1 complexification-averaged flow: the same algebra), and
continued both ways in energy by :func:`sinktheory.nnm.continuation.continue_orbits`
with the particles kept on the line.  The family bends from w -> 1 / sqrt(1 + m) at high
energy (particle and container locked) down to w -> 0 at low energy (motion localised in
the particle, whose cubic spring softens as the amplitude falls).  At both ends it runs
into tongues of subharmonic orbits (folds in energy); the backbone proper is cut at the
first fold on each side.

Where the family changes localisation.  At a turning point of a synchronous mode all
the energy is potential: A^2 / 2 in the container's spring, the rest in the particle's
well.  :func:`localisation_energy` is the energy at which the container's spring holds
half of it; below, the mode lives in the particle, above, in the container.  A
container struck above this energy starts near the container-localised part of the
family and the dashpot walks it down the backbone into the particle-localised part: the
resonance-capture picture of targeted energy transfer read off the frequency-energy
plot (Kerschen, Vakakis, Lee, McFarland, Kowtko and Bergman, Nonlinear Dyn. 42, 2005;
Vakakis et al., "Nonlinear Targeted Energy Transfer in Mechanical and Structural
Systems", 2008).  For the cubic NES of :mod:`sinktheory.attachments` (m = 0.2, kappa =
625) it is 4.6e-5, against the impulse threshold 4.0e-5 of the averaged flow and 3.8e-5
measured with a weak dashpot (``tests/studies/test_attachments.py``).

Examples
--------
>>> from sinktheory import Sink, Well
>>> sink = Sink(Well(0.5, 0.3, 2), particles=1, mass=0.2)
>>> A, B, E = harmonic_balance(sink, 0.75)
>>> round(B / A, 4)  # r = (1 - w^2) / (m w^2)
3.8889
>>> bool(abs(harmonic_balance_frequency(sink, E) - 0.75) < 1e-12)
True
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from .. import validation as v
from ..errors import ParameterError
from ..glossary import renamed
from ..model import Sink
from .continuation import Branch, check_stop, continue_orbits, merge

__all__ = [
    "harmonic_balance",
    "harmonic_balance_frequency",
    "HB_AGREEMENT",
    "inphase_backbone",
    "inphase_pieces",
    "localisation_energy",
    "START_TRIES",
]

#: Start energies of :func:`inphase_pieces` (log-spaced over the range).
START_TRIES = 6
#: Largest relative gap between a piece's frequency and the one-harmonic balance at its
#: start (measured: below 1 % between 1e-6 and 0.2 for the default cubic NES, 5 % at the
#: edge of the 1:3 tongue): a start that converged farther off landed on a tongue.
HB_AGREEMENT = 0.03


def _line_force(sink: Sink) -> tuple[float, int]:
    """(kappa, n): the particles' total force on the line is kappa x^(2n-1)."""
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    w = sink.well
    if w.n < 2:
        raise ParameterError("n", w.n, ">= 2 for an in-phase backbone (n = 1 is linear: "
                             "its frequency does not depend on the energy)")  # fmt: skip
    return sink.particles * w.gamma / w.wall_distance ** (2 * w.n), w.n


def harmonic_balance(sink: Sink, omega: float) -> tuple[float, float, float]:
    """(A, B, E): container and particle amplitudes and total energy of the in-phase
    mode at frequency ``omega`` in (0, 1 / sqrt(1 + m)), one harmonic (module
    docstring).  E is the energy at the turning point: A^2 / 2 + the well's potential."""
    kappa, n = _line_force(sink)
    m = sink.mass
    top = 1 / math.sqrt(1 + m)
    omega = v.positive("omega", omega)
    if not omega < top:
        raise ParameterError("omega", omega, f"a frequency in (0, 1/sqrt(1 + m) = {top:.6g})")
    p = 2 * n - 1
    c = math.comb(p, n - 1) / 2 ** (p - 1)
    try:
        r = (1 - omega**2) / (m * omega**2)
        A = (m * omega**2 * r / (kappa * c * (r - 1) ** p)) ** (1 / (p - 1))
        B = r * A
        with np.errstate(over="ignore"):
            well = sink.particles * float(sink.well.potential(B - A, 0.0))  # k V(x, 0)
        E = 0.5 * A**2 + well
    except (ZeroDivisionError, OverflowError):
        E = math.inf
    if not 0 < E < math.inf:
        raise ParameterError("omega", omega, f"a frequency in (0, {top:.6g}) whose mode's "
                             "amplitudes and energy are finite floats")  # fmt: skip
    return A, B, E


@renamed(energy="total_energy")
def harmonic_balance_frequency(sink: Sink, total_energy: float) -> float:
    """The one-harmonic in-phase frequency at ``total_energy`` (E rises monotonically
    with omega from 0 to infinity as omega goes from 0 to 1 / sqrt(1 + m))."""
    _line_force(sink)
    energy = v.positive("total_energy", total_energy)
    top = 1 / math.sqrt(1 + sink.mass)

    def gap(omega):
        return math.log(harmonic_balance(sink, omega)[2]) - math.log(energy)

    lo, hi = 1e-9 * top, top * (1 - 1e-15)
    if gap(lo) > 0 or gap(hi) < 0:
        raise ParameterError("total_energy", energy, "an energy the one-harmonic balance reaches "
                             f"in ({harmonic_balance(sink, lo)[2]:.3g}, "
                             f"{harmonic_balance(sink, hi)[2]:.3g})")  # fmt: skip
    return float(brentq(gap, lo, hi, xtol=1e-15, rtol=1e-14))


def container_share(backbone) -> np.ndarray:
    """X0^2 / (2 E) at each point of a backbone (:func:`inphase_backbone`): the share of
    the container's spring in the energy at the start state, a turning point of the
    particle (the phase condition; at low energy the container's X(t) has extra turning
    points).  On a synchronous mode every velocity is 0 there, all energy is potential,
    and the rest is in the particle's well."""
    return 0.5 * np.asarray(backbone.z0)[:, 0] ** 2 / np.asarray(backbone.total_energy)


def localisation_energy(backbone, share: float = 0.5) -> float:
    """The energy at which the container's spring holds ``share`` of the energy of the
    in-phase mode (module docstring), interpolated linearly in log E.  ``backbone`` is
    a :class:`~sinktheory.nnm.result.BranchResult` of :func:`inphase_backbone`; a share
    it does not reach is refused (ParameterError naming ``share``, with the range of
    shares it spans).

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> b = inphase_backbone(Sink(Well(0.5, 0.3, 2), particles=1, mass=0.2), 2e-5, 1e-4,
    ...                      steps=100, points=40)
    >>> round(localisation_energy(b), 6)
    4.6e-05
    """
    from .result import BranchResult

    if not isinstance(backbone, BranchResult):
        raise ParameterError("backbone", type(backbone).__name__,
                             "a BranchResult of inphase_backbone")  # fmt: skip
    share = v.positive("share", share)
    if not share < 1:
        raise ParameterError("share", share, "a fraction in (0, 1)")
    f = container_share(backbone)
    logE = np.log(np.asarray(backbone.total_energy))
    order = np.argsort(logE)
    f, logE = f[order], logE[order]
    above = np.flatnonzero((f[:-1] - share) * (f[1:] - share) <= 0)
    if above.size == 0:
        spans = f"[{f.min():.3g}, {f.max():.3g}]" if f.size else "nothing"
        raise ParameterError("share", share, f"a share the backbone reaches (its {f.size} "
                             f"point(s) span {spans})")  # fmt: skip
    i = int(above[0])
    step = f[i + 1] - f[i]
    x = logE[i] + (share - f[i]) * (logE[i + 1] - logE[i]) / step if step else logE[i]
    return float(math.exp(x))


def _monotone(branch: Branch, start: int) -> Branch:
    """The part of a merged branch around point ``start`` on which the energy is
    monotone: the backbone up to the first fold on each side."""
    e = branch.total_energy
    d = np.sign(np.diff(e))
    if d.size == 0:
        return branch
    sign = d[start] if start < d.size else d[start - 1]
    a = start
    while a > 0 and d[a - 1] == sign:
        a -= 1
    b = start
    while b < d.size and d[b] == sign:
        b += 1
    out = Branch(branch.problem)
    out.orbits = branch.orbits[a : b + 1]
    out.tangents = branch.tangents[a : b + 1]
    out.events = [e for e in branch.events if a <= e.index < b]
    for ev in out.events:
        ev.index -= a
    cut = [side for side, at in (("low", a > 0), ("high", b < d.size)) if at]
    out.stop_reason = branch.stop_reason + (f"; cut at the first fold ({', '.join(cut)} "
                                            "energy side)" if cut else "")  # fmt: skip
    return out


def inphase_backbone(
    sink: Sink,
    lo: float,
    hi: float,
    *,
    steps: int = 200,
    points: int = 150,
    ds: float = 0.3,
    start: float | None = None,
):
    """The piece of the in-phase 1:1 backbone through ``start`` (default the geometric
    mean of ``lo`` and ``hi``) as a :class:`~sinktheory.nnm.result.BranchResult`
    (label ``"in-phase 1:1"``), within total energies [lo, hi].

    Started from the one-harmonic balance (:func:`harmonic_balance`) at ``start``,
    continued both ways with the particles on the line and cut at the first fold on each
    side (module docstring); ``meta["stop_reason"]`` says where each side ended.
    :func:`inphase_pieces` covers a whole range.

    Raises
    ------
    ShootingError
        If the shooting from the guess does not converge.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> sink = Sink(Well(0.5, 0.3, 2), particles=1, mass=0.2)
    >>> b = inphase_backbone(sink, 1e-5, 1e-4, steps=100, points=20)
    >>> bool(np.all(np.diff(b.total_energy) > 0) and np.all(np.diff(b.frequency) > 0))
    True
    >>> bool(b.total_energy[0] <= 1e-5 and b.total_energy[-1] >= 1e-4)  # the range is covered
    True
    """
    from .modes import sink_flow

    _line_force(sink)
    lo, hi = check_stop((lo, hi))
    v.positive("lo", lo)
    if not math.isfinite(hi):
        raise ParameterError("hi", hi, "a finite energy")
    start = math.sqrt(lo * hi) if start is None else v.positive("start", start)
    if not lo <= start <= hi:
        raise ParameterError("start", start, f"an energy in [{lo:g}, {hi:g}]")
    system = sink_flow(sink)
    k = sink.particles
    omega = harmonic_balance_frequency(sink, start)
    A, B, E = harmonic_balance(sink, omega)
    z0 = np.zeros(2 * (1 + 2 * k))
    z0[0], z0[1 : 1 + k] = A, B
    kw = dict(
        steps=steps,
        total_energy=E,
        interval=(lo, hi),
        ds=ds,
        max_points=points,
        subspace="plane",
        phase_index=1,
    )  # the particle turns: its motion is the simpler one
    back = continue_orbits(system, z0, 2 * math.pi / omega, direction=-1, **kw)
    fwd = continue_orbits(system, z0, 2 * math.pi / omega, direction=1, **kw)
    branch = _monotone(merge(back, fwd), len(back.orbits) - 1)
    w = sink.well
    return branch.result(mode="in-phase", shape=w.shape, alpha=w.alpha, beta=w.beta, n=w.n,
                         gamma=w.gamma, particles=k, mass=sink.mass, label="in-phase 1:1",
                         start=start)  # fmt: skip


def inphase_pieces(
    sink: Sink, lo: float, hi: float, *, steps: int = 200, points: int = 150, ds: float = 0.3
) -> tuple[list, list[str]]:
    """The in-phase backbone over [lo, hi] in pieces: (branches, notes).

    Tongues of subharmonic orbits cut the family (:func:`inphase_backbone` stops at their
    folds), so pieces are started at :data:`START_TRIES` log-spaced energies inside
    (lo, hi), from low to high (the shooting from the one-harmonic guess converges best
    at low energy, where the particle dominates), skipping those a piece already covers.
    A piece whose start is not within :data:`HB_AGREEMENT` of the one-harmonic
    frequency (a start that converged onto a tongue) is dropped, and starts that do not
    converge are skipped; both are named in ``notes``.  Pieces are labelled
    ``"in-phase 1:1"`` and, after the first, ``"in-phase 1:1 (piece j)"``.
    """
    from .shooting import ShootingError

    lo, hi = check_stop((lo, hi))
    pieces, notes, covered = [], [], []
    for start in np.geomspace(lo, hi, START_TRIES + 2)[1:-1]:
        start = float(start)
        if any(a <= start <= b for a, b in covered):
            continue
        try:
            b = inphase_backbone(sink, lo, hi, steps=steps, points=points, ds=ds, start=start)
        except ShootingError as e:
            notes.append(f"in-phase 1:1 from E = {start:.3g} not converged: {e}")
            continue
        i = int(np.argmin(np.abs(np.log(b.total_energy / start))))
        guess = harmonic_balance_frequency(sink, float(b.total_energy[i]))
        if abs(b.frequency[i] / guess - 1) > HB_AGREEMENT:
            notes.append(f"in-phase 1:1 from E = {start:.3g} converged on a tongue "
                         f"(frequency {b.frequency[i]:.4g}, one harmonic {guess:.4g})")  # fmt: skip
            continue
        covered.append((float(b.total_energy.min()), float(b.total_energy.max())))
        if pieces:
            b.meta["label"] = f"in-phase 1:1 (piece {len(pieces) + 1})"
        pieces.append(b)
    return pieces, notes
