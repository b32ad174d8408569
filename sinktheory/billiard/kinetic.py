"""Kinetic theory of the rigid limit: the container's friction from the particles' impacts.

``derivations/rigid_friction.py`` derives, from the impact law
(:mod:`sinktheory.billiard.impact`) and the particles' microcanonical measure (uniform
over the table, isotropic velocity), to first order in the particle mass mu and in the
container's speed over the particles':

* the friction rate of the container's momentum, gamma = g sqrt(e) per particle of energy
  e, g = 4 sqrt(2 mu) W / (pi A), with A the table's area and W = oint n_x^2 ds (the
  boundary's normals weighted by their x component: only walls facing the container's
  motion take momentum from it);
* the momentum diffusion D = (2 / 3) g e^(3/2) (so D / gamma = 2 e / 3);
* the container energy's drift and diffusion, for k particles of energies uniform on the
  simplex sum e_j = e_p = E - E_c (the rigid table's flat density of states):
  D1 = k g (-a_k E_c sqrt(e_p) + (2/3) b_k e_p^(3/2)), D2 = (2/3) k g b_k e_p^(3/2) E_c,
  a_k = Gamma(3/2) Gamma(k) / Gamma(k + 1/2), b_k = Gamma(5/2) Gamma(k) / Gamma(k + 3/2),
  per unit time.  They satisfy the fluctuation-dissipation relation with the rigid law
  Beta(1, k) exactly (the derivation checks it for every k).

Everything scales as k g ~ sqrt(k m) at fixed E (mu = m / k): rigid walls predict
relaxation times ~ (k m)^(-1/2).  The expansion needs the container slower than the
particles (V^2 ~ E_c against c^2 = 2 e / mu); from the paper's start (particles at rest)
it fails at first, and the coefficients vanish at e_p = 0.

Examples
--------
>>> from sinktheory.billiard.table import rigid_table
>>> t = rigid_table("flat", 0.5, 0.0)  # the rectangle 1 x 2: W = the two side walls
>>> round(wall_moment(t), 9)
4.0
>>> d1, d2 = kinetic_coefficients(t, 1, 0.2, 0.5, [0.25])
>>> bool(d2[0] > 0)
True
"""

from __future__ import annotations

import math

import numpy as np

from .. import validation as v
from ..errors import NumericalError, ParameterError
from ..glossary import renamed
from .table import Table

__all__ = ["kinetic_coefficients", "kinetic_relaxation", "wall_moment"]


def wall_moment(table: Table) -> float:
    """W = oint n_x^2 ds over the table's boundary (quadrature over its graph pieces: a
    piece x = +-W(y) has n_x^2 ds = dy / sqrt(1 + W'^2), a piece y = +-W(x) has
    W'^2 dx / sqrt(1 + W'^2))."""
    from scipy.integrate import quad

    if not isinstance(table, Table):
        raise ParameterError("table", table, "a sinktheory.billiard.table.Table")
    total = 0.0
    for piece in table.pieces:

        def integrand(s, piece=piece):
            d1 = float(piece.values(s)[1])
            if not math.isfinite(d1):  # an arc's vertical end (quad never samples it)
                return 0.0
            root = math.sqrt(1 + d1 * d1)
            return 1 / root if piece.axis == "x" else d1 * d1 / root

        total += quad(integrand, piece.lo, piece.hi, limit=200)[0]
    return total


@renamed(energy="total_energy")
def kinetic_coefficients(table: Table, particles: int, mass: float, total_energy: float,
                         container_energies) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """(D1, D2) of the container energy per period (module docstring) at the given E_c, for
    k = ``particles`` of total mass ``mass`` in the rigid ``table`` at total energy E."""
    from ..model import Sink

    k, m = Sink.check_particles(particles, mass)
    e = v.positive("total_energy", total_energy)
    allowed = f"energies in [0, {e:g}]"
    ec = v.real_array("container_energies", container_energies, allowed)
    if not np.all((ec >= 0) & (ec <= e)):
        raise ParameterError("container_energies", ec.tolist(), allowed)
    g = 4 * math.sqrt(2.0) * math.sqrt(m / k) * wall_moment(table) / (math.pi * table.area)
    a_k = math.exp(math.lgamma(1.5) + math.lgamma(k) - math.lgamma(k + 0.5))
    b_k = math.exp(math.lgamma(2.5) + math.lgamma(k) - math.lgamma(k + 1.5))
    ep = e - ec
    period = 2 * math.pi
    with np.errstate(over="ignore", invalid="ignore"):
        d1 = period * k * g * (-a_k * ec * np.sqrt(ep) + 2 / 3 * b_k * ep**1.5)
        d2 = period * k * g * 2 / 3 * b_k * ep**1.5 * ec
    if not (np.all(np.isfinite(d1)) and np.all(np.isfinite(d2))):
        raise ParameterError("total_energy", total_energy, "small enough that D1 and D2 are "
                             "finite", why=f"they overflow at mass = {m:g}")  # fmt: skip
    return d1, d2


@renamed(energy="total_energy")
def kinetic_relaxation(table: Table, particles: int, mass: float, total_energy: float = 0.5, *,
                       fraction: float = 0.05, start: float = 1 - 1e-3,
                       cells: int = 300) -> tuple[float, float]:  # fmt: skip
    """(settling time, slowest relaxation time), in periods, of the Fokker-Planck equation
    with the kinetic D1 on the rigid law Beta(1, k) (D2 from fluctuation-dissipation,
    which the kinetic D2 satisfies): when the mean started at s = E_c / E = ``start``
    comes within ``fraction`` of the law's mean 1 / (k + 1).

    Examples
    --------
    >>> from sinktheory.billiard.table import rigid_table
    >>> t_f, t_r = kinetic_relaxation(rigid_table("flat", 0.5, 0.3), 1, 0.2)
    >>> bool(0 < t_r < t_f)
    True
    """
    from scipy import stats
    from scipy.optimize import brentq

    from ..equilibrium.prediction import check_fraction, law_chain

    k = v.positive_int("particles", particles)
    e = v.positive("total_energy", total_energy)
    fraction = check_fraction(fraction)
    if not 0 < v.finite("start", start) <= 1:
        raise ParameterError("start", start, "a number in (0, 1]")
    law = stats.beta(1, k)
    s = np.linspace(0.0, 1.0, 201)
    d1 = kinetic_coefficients(table, k, mass, e, e * s)[0] / e
    if not np.all(np.isfinite(d1)):
        raise NumericalError(f"kinetic_relaxation: the drift D1 overflows at mass={mass:g}")
    chain = law_chain(law.pdf, s, d1, cells=cells)
    lam = chain.spectrum[0]
    mu = 1 / (k + 1)

    def excess(t):
        return abs(chain.moments(start, np.array([t]))[0][0] - mu) / mu - fraction

    t = 0.01
    while excess(t) > 0 and t < 1e7:
        t *= 1.5
    if excess(t) > 0:
        raise NumericalError(
            f"kinetic_relaxation: the mean is not within fraction={fraction:g} of the law's "
            f"after {t:.3g} periods"
        )
    settle = float(brentq(excess, t / 1.5, t, xtol=1e-3)) if t > 0.01 else 0.0
    return settle, -1 / float(np.sort(lam)[-2])
