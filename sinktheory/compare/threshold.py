r"""The cubic NES's energy threshold: what the 1:1-resonance averaged flow predicts, and what
a window of simulation calls the threshold.

The cubic NES of :mod:`sinktheory.attachments` (one particle of mass mu on the line of a
well with n = 2: force k3 v^3 on the relative displacement v, k3 = gamma / D^4 with D the
clearance alpha - beta; container mass 1, spring 1; a dashpot c on the relative velocity)
has no sharp threshold.  Averaged over the 1:1 resonance (complexification-averaging,
phi = xdot + i x of the container and of the particle, phi_2 their difference), three
energies describe the change from "the particle hardly moves" to "the energy goes into the
particle":

* :func:`averaged_share`: the largest share of the impulse's energy the particle ever
  takes in the undamped averaged flow, a function of the impulse energy E.  With
  mu = 0.2 it rises steeply but continuously (0.08 at 3.2e-5, 0.36 at 3.8e-5, 0.74 at
  4.6e-5): there is no jump, and "the threshold" is a convention, the energy where the
  share crosses 1/2 (:func:`half_share_energy`).
* :func:`full_exchange_energy`: where that share peaks (nearly all the energy reaches
  the particle), above which the exchange becomes partial again.
* :func:`fold_energy`: the damped flow's slow invariant manifold,
  mu^2 |phi_1|^2 / 4 = Z [(a Z - mu/2)^2 + d^2], Z = |phi_2|^2, a = 3 k3 (1 + mu) / 8,
  d = c (1 + mu) / 2 (the fast equation of phi_2 at its fixed points, to leading order in
  mu).  It folds (for c < mu / sqrt(3)); an impulse whose container energy
  E = |phi_1|^2 / 2 exceeds the energy at the lower fold can only land on the upper,
  capturing branch: the classic estimate of the threshold of resonance capture
  (Vakakis et al., *Nonlinear Targeted Energy Transfer*, 2008, ch. 3).

What a simulation calls the threshold depends on its window: the measured fraction
dissipated crosses half-way from the Lanchester floor 1 - exp(-c t) to its plateau near
the averaged flow's 1/2 crossing over 20 periods; over longer windows impulses below it
are captured too (docs/guide/make_nes_threshold.py measures both).

Examples
--------
>>> mu, k3 = 0.2, 625.0
>>> round(fold_energy(mu, k3, 0.0) / (8 * mu / (81 * k3 * (1 + mu))), 12)  # small-c limit
1.0
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..glossary import renamed
from ..worklimit import check_particle_steps

__all__ = [
    "AVERAGED_HORIZON",
    "averaged_share",
    "AVERAGED_STEP",
    "fold_energy",
    "full_exchange_energy",
    "half_share_energy",
]

#: Time over which the averaged flow's largest share is taken (the share's oscillation
#: has a period of a few tens of time units near the threshold; 1000 gives the same
#: shares to four digits at mu = 0.2).
AVERAGED_HORIZON = 300.0
#: Step of the averaged flow's RK4 integration (its fastest rate, the particle's 1/2,
#: is resolved 40 times over; halving it changes the shares by < 1e-6).
AVERAGED_STEP = 0.05


def _check(mu: float, k3: float) -> tuple[float, float]:
    """mu and k3 > 0 whose energy scale :func:`_scale` is well inside float range."""
    mu, k3 = v.positive("mu", mu), v.positive("k3", k3)
    if mu > 1e300:
        raise ParameterError("mu", mu, "a finite number in (0, 1e300]")
    scale = _scale(mu, k3)
    if not 1e-290 < scale < 1e290:
        raise ParameterError("k3", k3, "a stiffness whose energy scale 8 mu / (81 k3 (1 + mu)) "
                             f"is in (1e-290, 1e290), not {scale:.3g}")  # fmt: skip
    return mu, k3


@renamed(energy="container_energy")
def averaged_share(mu: float, k3: float, container_energy, horizon: float = AVERAGED_HORIZON):
    """Largest share of the impulse energy E0 = ``container_energy`` (a number or an
    array) that the particle takes in the undamped 1:1-averaged flow (module docstring)
    over ``horizon`` time units, the container started with |phi_1|^2 = 2 E0 and the
    particle at rest:

        phi_1' = -(3i k3/8) |phi_2|^2 phi_2,
        phi_u' = -(i/2) phi_u + (3i k3/(8 mu)) |phi_2|^2 phi_2,   phi_2 = phi_u - phi_1,

    integrated by classical RK4 with step :data:`AVERAGED_STEP`, all energies at once.

    Examples
    --------
    >>> s = averaged_share(0.2, 625.0, [1e-5, 8e-5])
    >>> bool(s[0] < 0.01 < 0.99 < s[1])
    True
    """
    mu, k3 = _check(mu, k3)
    e = v.real_array("container_energy", container_energy, "energies > 0")
    if not (np.all(np.isfinite(e)) and np.all(e > 0)):
        raise ParameterError("container_energy", container_energy, "finite energies > 0")
    horizon = v.positive("horizon", horizon)
    steps = horizon / AVERAGED_STEP  # inf beyond float range: refused below
    check_particle_steps("horizon", horizon, steps * e.size, "the averaged flow's RK4 steps")
    steps = math.ceil(steps)
    amp = np.sqrt(2 * e.ravel())
    # in units of the start amplitude: the cubic term's coefficient carries amp^2
    low = _lowest_container_share(0.375 * k3 * amp**2, mu, AVERAGED_STEP, steps)
    out = 1 - low
    return float(out[0]) if np.ndim(container_energy) == 0 else out.reshape(e.shape)


@numba.njit(cache=True)
def _lowest_container_share(g, mu, h, steps):  # pragma: no cover (compiled)
    """min over t of |phi_1|^2 / |phi_1(0)|^2 for each cubic coefficient g (RK4)."""
    out = np.ones(g.size)
    for n in range(g.size):
        p1, pu = 1.0 + 0j, 0j
        for _ in range(steps):
            a1, b1 = _slope(p1, pu, g[n], mu)
            a2, b2 = _slope(p1 + 0.5 * h * a1, pu + 0.5 * h * b1, g[n], mu)
            a3, b3 = _slope(p1 + 0.5 * h * a2, pu + 0.5 * h * b2, g[n], mu)
            a4, b4 = _slope(p1 + h * a3, pu + h * b3, g[n], mu)
            p1 += (h / 6) * (a1 + 2 * a2 + 2 * a3 + a4)
            pu += (h / 6) * (b1 + 2 * b2 + 2 * b3 + b4)
            out[n] = min(out[n], p1.real**2 + p1.imag**2)
    return out


@numba.njit(cache=True)
def _slope(p1, pu, g, mu):  # pragma: no cover (compiled)
    p2 = pu - p1
    cubic = 1j * g * (p2.real**2 + p2.imag**2) * p2
    return -cubic, -0.5j * pu + cubic / mu


def _scale(mu: float, k3: float) -> float:
    """The fold estimate without damping, 8 mu / (81 k3 (1 + mu)): the energy scale."""
    return 8 * mu / (81 * k3 * (1 + mu))


def half_share_energy(mu: float, k3: float) -> float:
    """The conventional threshold: the energy where :func:`averaged_share` first crosses
    1/2, on a log grid of 160 points over [scale / 3, 30 scale] (scale: the undamped fold
    estimate), interpolated linearly in log E between the two grid points around it."""
    mu, k3 = _check(mu, k3)
    grid = np.geomspace(_scale(mu, k3) / 3, 30 * _scale(mu, k3), 160)
    share = averaged_share(mu, k3, grid)
    above = np.nonzero(share >= 0.5)[0]
    if not above.size or above[0] == 0:
        raise ParameterError("mu, k3", (mu, k3), "a set-up whose share crosses 1/2 on the grid")
    i = above[0]
    x = np.log(grid[i - 1 : i + 1])
    return float(np.exp(np.interp(0.5, share[i - 1 : i + 1], x)))


def full_exchange_energy(mu: float, k3: float) -> tuple[float, float]:
    """(energy, share) where :func:`averaged_share` peaks, the largest exchange: the
    largest share on a log grid of 160 points over [scale / 3, 30 scale], refined by a
    parabola through it and its neighbours in log E.

    """
    mu, k3 = _check(mu, k3)
    grid = np.geomspace(_scale(mu, k3) / 3, 30 * _scale(mu, k3), 160)
    share = averaged_share(mu, k3, grid)
    i = int(np.clip(np.argmax(share), 1, grid.size - 2))
    x = np.log(grid[i - 1 : i + 2])
    c2, c1, _ = np.polyfit(x - x[1], share[i - 1 : i + 2], 2)
    top = x[1] - c1 / (2 * c2) if c2 < 0 else x[1]
    return float(np.exp(top)), float(averaged_share(mu, k3, float(np.exp(top))))


def fold_energy(mu: float, k3: float, damping: float) -> float:
    """Container energy E = |phi_1|^2 / 2 at the lower fold of the damped slow invariant
    manifold (module docstring): the largest container amplitude on its particle-localised
    branch.

    Raises ParameterError when the manifold has no fold (c >= mu / sqrt(3)).

    Examples
    --------
    >>> e0, e1 = fold_energy(0.2, 625.0, 0.0), fold_energy(0.2, 625.0, 0.002)
    >>> round(e1 / e0, 5)  # a dashpot c << mu raises it by a hair
    1.00032
    """
    mu, k3 = _check(mu, k3)
    c = v.nonnegative("damping", damping)
    a, b, d = 0.375 * k3 * (1 + mu), 0.5 * mu, 0.5 * c * (1 + mu)
    disc = b * b - 3 * d * d
    if disc <= 0:
        raise ParameterError("damping", damping, f"< mu / sqrt(3) = {mu / math.sqrt(3):.6g} "
                             "(beyond it the slow invariant manifold has no fold)")  # fmt: skip
    z = (2 * b - math.sqrt(disc)) / (3 * a)
    phi1_sq = z * ((a * z - b) ** 2 + d * d) / (b * b)
    return 0.5 * phi1_sq
