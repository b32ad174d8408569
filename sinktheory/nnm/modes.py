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

In a user's well (:class:`~sinktheory.wellat.WellAt`, y = 0 invariant) the guesses are
the same with the well's own numbers (:func:`mode_guess`): alpha - beta becomes the
distance along -x at which a wall ratio reaches 1, and the power-law oscillator's period
a quadrature of the motion on the axis y = 0.

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
    """Refuse a user's well (:class:`~sinktheory.wellat.WellAt`) in which y = 0 is not
    invariant (decided symbolically at its values): it has no normal mode in that plane."""
    report = well.report
    if not report.y_invariant:
        raise ParameterError("well", well.shape, "a well in which y = 0 is invariant (normal "
                             "modes in the plane y = 0)",
                             why=report.y_invariant_reason)  # fmt: skip


#: Gauss-Legendre nodes and weights on [0, pi/2] for the period on the axis y = 0.
_NODES, _GAUSS = np.polynomial.legendre.leggauss(64)
_THETA, _WEIGHTS = np.pi / 4 * (_NODES + 1), np.pi / 4 * _GAUSS


def _user_guess(sink: Sink, mode: str, energy: float) -> tuple[np.ndarray, float]:
    """:func:`mode_guess` in a user's well, the registered shapes' guesses with the
    well's own numbers: the container mode's particles at absolute rest while the
    container stays inside the rigid wall along -x (where a wall ratio reaches 1; without
    wall ratios, always), else just inside it; the particle mode's turning point where
    V(x, 0) - V(0, 0) = E / k, and its period 2 (int over [x-, x+] of dx / v) with the
    reduced mass mu / (1 + m), by 64-point Gauss-Legendre in x = x+- sin(theta)."""
    w, k, m = sink.well, sink.particles, sink.mass
    z0 = np.zeros(2 * (1 + 2 * k))
    if mode == "container":
        X0 = math.sqrt(2 * energy)
        L = w.wall_distance(-1.0, 0.0, limit=X0 / 0.9)  # along -x: inf beyond it
        z0[0] = X0
        z0[1 : 1 + k] = max(0.0, X0 - 0.9 * L)
        return z0, 2 * math.pi
    e = energy / k
    x_plus, x_minus = (_turning_point(w, e, side) for side in (1.0, -1.0))
    reduced = sink.mu / (1 + m)
    T = 0.0
    for h in (x_plus, x_minus):
        x = h * np.sin(_THETA)
        speed = np.sqrt(2 * np.maximum(e - w.potential(x, 0.0), 0.0) / reduced)
        T += 2 * abs(h) * float(np.sum(_WEIGHTS * np.cos(_THETA) / speed))
    z0[0] = -m * x_plus / (1 + m)
    z0[1 : 1 + k] = x_plus / (1 + m)
    return z0, T


def _turning_point(well, e: float, side: float) -> float:
    """x on the side ``side`` (+1 or -1) of the axis y = 0 where V(x, 0) - V(0, 0) = e."""
    from scipy.optimize import brentq

    from ..errors import NumericalError

    reach = well.reach(e, name="total_energy")[0]
    hi = reach
    for _ in range(60):  # the basin's reach bounds it; a little past it if V bends back
        if float(well.potential(side * hi, 0.0)) >= e:
            return side * float(brentq(lambda x: float(well.potential(side * x, 0.0)) - e,
                                       0.0, hi, xtol=1e-15))  # fmt: skip
        hi *= 1.01
    raise NumericalError(
        f"normal-mode guess: no turning point of V(x, 0) - V(0, 0) = {e:g} "
        f"on the {'+' if side > 0 else '-'}x axis of the {well.shape} well"
    )


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
    if hasattr(sink.well, "definition"):
        return _user_guess(sink, mode, energy)
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
    if not isinstance(system, FlowSystem):
        raise ParameterError("system", system, "a sinktheory.nnm.system.FlowSystem")
    K = system.masses[:, None] * system.stiffness()
    m = np.sqrt(system.masses)
    A = K / m[:, None] / m[None, :]
    w2, vec = np.linalg.eigh(0.5 * (A + A.T))
    return np.sqrt(np.clip(w2, 0, None)), vec / m[:, None]
