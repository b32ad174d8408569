r"""Start guesses for the normal modes of the container and its particles, and linear modes.

On the invariant plane y_j = 0 the sink with k identical particles moving together is a
two-degree-of-freedom system (container X, particle u = X + x) with two families of
synchronous normal modes, both starting at a turning point (all velocities zero):

* ``"container"``: the container oscillates, the particles ride in the well.  At low
  energy the particles barely feel the soft walls (V ~ x^(2n)), stay nearly at rest and
  the frequency tends to 1, the container's.
* ``"particle"``: the particles oscillate in the well, the container recoils by O(mu).
  As mu -> 0 this is the paper's normal mode y = 0 with the container held fixed: the
  particle's x = (alpha - beta) A0 X(s) with X the power-law oscillator of amplitude 1
  in the rescaled time s = t sqrt(gamma / mu) / (alpha - beta), so its period is
  T_n(A0) (alpha - beta) sqrt(mu / gamma), and the energy per particle
  gamma A0^(2n) / (2n).  A0 = 1, the amplitude of :mod:`sinktheory.floquet`, is the
  energy gamma / (2n) per particle.  The guess for finite mass m = k mu lets the
  container recoil freely (centre of mass at rest), which is exact as m -> 0 and good
  when the particles oscillate much faster than the container.

Examples
--------
>>> from sinktheory import Sink, Well
>>> sink = Sink(Well(0.5, 0.2, 4), particles=1, mass=1e-6)
>>> z0, T = mode_guess(sink, "particle", 0.125)
>>> z0.round(6).tolist(), round(T / (0.3 * 1e-3), 5)  # ~ T_4(1): the recoil is O(mu)
([-0.0, 0.3, 0.0, 0.0, 0.0, 0.0], 9.30874)
"""

from __future__ import annotations

import math

import numpy as np

from .. import validation as v
from .._generated import oscillator as _osc
from ..errors import ParameterError
from ..glossary import renamed
from ..model import Sink
from .system import FlowSystem

__all__ = [
    "check_user_well",
    "fixed_container_amplitude",
    "linear_modes",
    "mode_guess",
    "MODES",
    "sink_flow",
]

MODES = ("container", "particle")


def sink_flow(sink: Sink, scheme: str | None = None) -> FlowSystem:
    """The :class:`FlowSystem` of a :class:`~sinktheory.model.Sink` (engine name and
    parameters as :mod:`sinktheory.simulate` defines them)."""
    from ..ensemble import engine_name, engine_params

    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    kw = {} if scheme is None else {"scheme": scheme}
    return FlowSystem(engine_name(sink), engine_params(sink), members=sink.particles, **kw)


def check_user_well(well) -> None:
    """Refuse a user's well (:class:`~sinktheory.wellat.WellAt`) for the normal modes'
    start guesses, with the reason: y = 0 not invariant (no normal mode in the plane),
    else the guesses' formulas, which read a registered shape's alpha, beta, n and gamma.
    Its flow (:func:`sink_flow`, the engine derived from the user's potential) takes it:
    :func:`sinktheory.nnm.shoot` finds its periodic orbits from a guess of your own."""
    report = well.report
    if not report.y_invariant:
        raise ParameterError("well", well.shape, "a well in which y = 0 is invariant (normal "
                             f"modes in the plane y = 0)", why=report.y_invariant_reason)  # fmt: skip
    raise ParameterError("well", well.shape, "a registered shape for the start guesses of the "
                         "normal modes (they read alpha, beta, n, gamma); for a user's well "
                         "shoot from a guess of your own: sinktheory.nnm.shoot(sink_flow(sink), "
                         "z0, T, steps=...)")  # fmt: skip


@renamed(energy="total_energy")
def fixed_container_amplitude(sink: Sink, total_energy: float) -> float:
    """A0 of the particle mode at ``total_energy`` shared by k particles, container at rest."""
    w = sink.well
    return (2 * w.n * total_energy / (sink.particles * w.gamma)) ** (1 / (2 * w.n))


@renamed(energy="total_energy")
def mode_guess(sink: Sink, mode: str, total_energy: float) -> tuple[np.ndarray, float]:
    """(z0, T): a start state at a turning point and a period guess for ``mode``.

    Parameters
    ----------
    sink : Sink
    mode : "container" or "particle"
    total_energy : float > 0
        Total energy H.
    """
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    v.choice("mode", mode, MODES)
    if hasattr(sink.well, "definition"):
        check_user_well(sink.well)
    energy = v.positive("total_energy", total_energy)
    sink.well.check_energy(energy, name="total_energy")  # no particle can hold more than the total
    w, k = sink.well, sink.particles
    L = w.alpha - w.beta
    z0 = np.zeros(2 * (1 + 2 * k))
    if mode == "container":
        # container displaced, all at rest; the particles at absolute rest at u = 0 while
        # the walls allow it (x = -X), else just inside the trailing wall
        X0 = math.sqrt(2 * energy)
        z0[0] = X0
        z0[1 : 1 + k] = max(0.0, X0 - 0.9 * L)
        return z0, 2 * math.pi
    # the particles against the free container (spring neglected): centre of mass at
    # rest, X = -m x / (1 + m), u = x / (1 + m), reduced mass mu / (1 + m) per particle
    m = sink.mass
    A0 = fixed_container_amplitude(sink, energy)
    x0 = L * A0
    z0[0] = -m * x0 / (1 + m)
    z0[1 : 1 + k] = x0 / (1 + m)
    T = _osc.period(w.n, A0) * L * math.sqrt(sink.mu / ((1 + m) * w.gamma))
    return z0, T


def linear_modes(system: FlowSystem) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies, mode shapes as columns) of the linearisation at q = 0.

    Solves K phi = omega^2 M phi with K = -M da/dq from the engine's accelerations
    (central differences); zero frequencies belong to directions without linear
    stiffness (a particle in a soft well with n >= 2).

    Examples
    --------
    >>> w, _ = linear_modes(FlowSystem("duffing2", []))
    >>> np.round(w, 6).tolist()
    [1.0, 1.732051]
    """
    K = system.masses[:, None] * system.stiffness()
    m = np.sqrt(system.masses)
    A = K / m[:, None] / m[None, :]
    w2, vec = np.linalg.eigh(0.5 * (A + A.T))
    return np.sqrt(np.clip(w2, 0, None)), vec / m[:, None]
