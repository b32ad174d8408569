"""States drawn from the microcanonical measure of the shell H = E at a prescribed E_c.

In the separable coordinates (:mod:`sinktheory.equilibrium.law`) the shell measure is the
container oscillator's times the k particles', restricted to E_c + sum_j e_j = E.  Given
E_c, the conditional measure is therefore:

* the container at phase phi uniform on [0, 2 pi): X = sqrt(2 E_c) cos phi,
  P = Xdot = sqrt(2 E_c) sin phi (an oscillator's shell measure is uniform in phase);
* the particles' energies (e_1, ..., e_k) on the simplex sum e_j = E - E_c with density
  prod_j g(e_j), g(e) = 2 pi mu A(e) (the k-fold convolution the law is built on);
* each particle, given e_j, at a position uniform in its basin {V < e_j} and with an
  absolute velocity of modulus sqrt(2 (e_j - V) / mu) in a uniform direction (the
  one-particle shell measure \\int delta(p^2 / (2 mu) + V - e) d^2p = 2 pi mu on the basin).

The energies are drawn by rejection: with A(e) = t F(t) (t = (2 n e / gamma)^(1/n)),
prod g(e_j) is prod e_j^(1/n) times prod F(t_j), so a Dirichlet(1 + 1/n, ...) proposal
(exact for a homogeneous well) is accepted with probability prod F(t_j) / F_max^k.  F is
the closed form of :data:`~sinktheory.equilibrium.area.CLOSED_FORMS` where there is one,
else a Chebyshev interpolant of the quadrature in u = (e / E_p)^(1/n) (trailing
coefficients below :data:`INTERPOLATION_TOL`, relative).  Positions are drawn by rejection
from the box :meth:`~sinktheory.model.Well.reach` of each energy.  Everything is exact
in distribution (up to that interpolation for shapes without closed form); the tests
check the energy split against the law of k - 1 particles, the basin's acceptance against
A(e), and <V> on the basin against its closed form.

Examples
--------
>>> from sinktheory.canonical import FIG8_SINK
>>> rows = shell_states(FIG8_SINK, 0.5, 0.2, 4, np.random.default_rng(1))
>>> rows.shape
(4, 22)
>>> from sinktheory.ensemble import total_energy
>>> bool(np.allclose(total_energy(FIG8_SINK, rows), 0.5, rtol=1e-12))
True
>>> bool(np.allclose((rows[:, 0] ** 2 + rows[:, 1] ** 2) / 2, 0.2, rtol=1e-12))
True
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial import chebyshev as C

from .. import validation as v
from ..errors import NumericalError, ParameterError
from ..glossary import renamed
from ..layout import StateLayout
from ..model import Sink, Well
from ..twins import python_kernel
from .area import CLOSED_FORMS, _check_well, area_ratio, scaled_energy

__all__ = [
    "basin_points",
    "INTERPOLATION_TOL",
    "particle_energies",
    "shell_states",
]

#: Largest trailing Chebyshev coefficient (relative to the largest) of the interpolant of
#: A / t for a shape without closed form.
INTERPOLATION_TOL = 1e-10
#: Safety factor on the largest F found on a grid (the acceptance ratio must stay <= 1).
_MARGIN = 1.0 + 1e-3
#: Ratio of successive energies whose reach boxes bound the basins drawn from.
_LADDER = 1.25


def _potential(well: Well):
    """V(x, y) of ``well`` on arrays.  The arguments are copied: the Python twin of the
    generated ``ipow`` squares its base in place, so an array passed as y would be
    overwritten by y^(2n)."""
    kernel = python_kernel(well.kernels.potential)
    args = (well.alpha, well.beta, well.gamma, well.n)
    return lambda x, y: kernel(np.array(x, dtype=float), np.array(y, dtype=float), *args)


def _check_rng(rng) -> np.random.Generator:
    if not isinstance(rng, np.random.Generator):
        raise ParameterError("rng", rng, "a numpy.random.Generator (seeded by the caller)")
    return rng


def _ratio_function(well: Well, top: float):
    """F(e) = A(e) / t(e) for energies in (0, top]: the closed form, or an interpolant."""
    closed = CLOSED_FORMS.get(well.shape)
    t_top = scaled_energy(well, top)
    if closed is not None:
        return lambda e: closed(well, t_top * (np.asarray(e) / top) ** (1 / well.n))
    for deg in (8, 16, 32, 64):
        series = C.Chebyshev.interpolate(
            lambda u: area_ratio(well, t_top * np.maximum(u, 1e-12)), deg, domain=[0.0, 1.0]
        )
        if np.max(np.abs(series.coef[-3:])) <= INTERPOLATION_TOL * np.max(np.abs(series.coef)):
            return lambda e: series((np.asarray(e) / top) ** (1 / well.n))
    raise NumericalError(
        f"microcanonical sampler: A(e)/t of the {well.shape} well did not interpolate to "
        f"{INTERPOLATION_TOL:g} with degree 64 up to e = {top:.6g}"
    )


def particle_energies(
    well: Well, particles: int, total: float, size: int, rng: np.random.Generator
) -> np.ndarray:
    """Energies (size, k) of k particles on the simplex sum e_j = ``total``, density
    prod_j A(e_j) (module docstring).

    Examples
    --------
    >>> e = particle_energies(Well(0.5, 0.3, 4), 3, 0.4, 5, np.random.default_rng(0))
    >>> e.shape, bool(np.allclose(e.sum(axis=1), 0.4))
    ((5, 3), True)
    """
    _check_well(well)
    k = v.positive_int("particles", particles, maximum=10**15)
    total = v.positive("total", total)
    size = v.positive_int("size", size, maximum=10**15)
    name, value = ("particles", k) if k > size else ("size", size)  # the larger one
    v.fits_memory(name, value, 8.0 * (2 * size + 16) * k * 4, f"{size} x {k} energies",
                  "smaller: the samples must fit in memory")  # fmt: skip
    rng = _check_rng(rng)
    well.check_energy(total, name="total_energy")
    if k == 1:
        return np.full((size, 1), total)
    ratio = _ratio_function(well, total)
    f_max = _MARGIN * float(np.max(ratio(np.linspace(0.0, 1.0, 2049)[1:] * total)))
    out = np.empty((0, k))
    while out.shape[0] < size:
        want = 2 * (size - out.shape[0]) + 16
        e = total * rng.dirichlet(np.full(k, 1 + 1 / well.n), size=want)
        e = np.maximum(e, 1e-300)  # Dirichlet components can underflow to 0
        accept = np.prod(ratio(e) / f_max, axis=1)
        if np.any(accept > 1):
            raise NumericalError("microcanonical sampler: A(e)/t exceeds its bound")
        out = np.concatenate([out, e[rng.random(want) < accept]])
    return out[:size] * (total / out[:size].sum(axis=1, keepdims=True))


def basin_points(well: Well, energies, rng: np.random.Generator) -> np.ndarray:
    """Points (x, y), shape energies.shape + (2,), uniform in the basins {V < e}.

    Examples
    --------
    >>> p = basin_points(Well(0.5, 0.3, 4), [0.1, 0.2], np.random.default_rng(0))
    >>> p.shape
    (2, 2)
    """
    _check_well(well)
    allowed = "finite numbers > 0, at least one"
    e = v.finite_array("energies", energies, allowed)
    if e.size == 0 or not np.all(e > 0):
        raise ParameterError("energies", e.tolist(), allowed)
    rng = _check_rng(rng)
    potential = _potential(well)
    flat = e.ravel()
    # boxes of the energies on a geometric ladder, each point in the box of the rung at
    # or above its energy (reach grows with the energy: a superset of its basin)
    ladder = flat.max() * _LADDER ** np.arange(0.0, -64.0, -1.0)
    ladder = ladder[ladder >= flat.min() / _LADDER]
    rungs = np.array([well.reach(x) for x in ladder])
    step = np.floor(np.log(flat.max() / flat) / np.log(_LADDER) + 1e-12).astype(int)
    boxes = rungs[np.clip(step, 0, len(ladder) - 1)]
    out = np.empty((flat.size, 2))
    pending = np.arange(flat.size)
    while pending.size:
        xy = boxes[pending] * rng.uniform(-1.0, 1.0, size=(pending.size, 2))
        inside = potential(xy[:, 0], xy[:, 1]) < flat[pending]
        out[pending[inside]] = xy[inside]
        pending = pending[~inside]
    return out.reshape(e.shape + (2,))


@renamed(energy="total_energy")
def shell_states(
    sink: Sink, total_energy: float, container_energy: float, runs: int, rng: np.random.Generator
) -> np.ndarray:
    """State rows (runs, 2 + 4k) drawn from the shell H = ``total_energy`` given E_c =
    ``container_energy`` (module docstring); columns as in
    :class:`~sinktheory.ensemble.SimulationState`.

    Parameters
    ----------
    sink : Sink
    total_energy : float
        Total energy E > 0 (the well must confine it).
    container_energy : float
        E_c in [0, E).
    runs : int
    rng : numpy.random.Generator

    Raises
    ------
    ParameterError
        Bad sink, energies or generator.
    """
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    e = v.positive("total_energy", total_energy)
    ec = v.nonnegative("container_energy", container_energy)
    if not ec < e:
        raise ParameterError("container_energy", ec, f"a number in [0, {e:g}) (below the total)")
    runs = v.positive_int("runs", runs)
    rng = _check_rng(rng)
    well, k = sink.well, sink.particles
    v.fits_memory("runs", runs, 8.0 * runs * (2 + 4 * k) * 4, f"{runs} state rows",
                  "smaller: the states must fit in memory")  # fmt: skip
    well.check_energy(e, name="total_energy")
    phase = rng.uniform(0.0, 2 * math.pi, size=runs)
    amplitude = math.sqrt(2 * ec)
    es = particle_energies(well, k, e - ec, runs, rng)
    xy = basin_points(well, es, rng)
    vpot = _potential(well)(xy[..., 0], xy[..., 1])
    speed = np.sqrt(2 * np.maximum(es - vpot, 0.0) / sink.mu)
    angle = rng.uniform(0.0, 2 * math.pi, size=es.shape)
    L = StateLayout(k)
    rows = np.empty((runs, L.width))
    rows[:, L.X] = amplitude * np.cos(phase)
    rows[:, L.XDOT] = amplitude * np.sin(phase)
    rows[:, L.u] = rows[:, [L.X]] + xy[..., 0]
    rows[:, L.y] = xy[..., 1]
    rows[:, L.udot] = speed * np.cos(angle)
    rows[:, L.ydot] = speed * np.sin(angle)
    return rows
