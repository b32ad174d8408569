"""Kinetic theory of the rigid limit: the boundary moment against closed forms, and the
kinetic coefficients against the fluctuation-dissipation relation with the rigid law."""

import math

import numpy as np
import pytest
from scipy import stats

from sinktheory.billiard.kinetic import kinetic_coefficients, wall_moment
from sinktheory.billiard.table import rigid_table
from sinktheory.equilibrium.prediction import law_chain
from sinktheory.errors import ParameterError


@pytest.mark.parametrize(
    "shape,alpha,beta,exact",
    [
        ("flat", 0.5, 0.0, 4.0),  # the rectangle |x| < 1/2, |y| < 1: two side walls of length 2
        ("circular", 0.7, 0.2, math.pi * 0.5),  # oint cos^2 R dphi = pi R, R = alpha - beta
    ],
)
def test_wall_moment_closed_forms(shape, alpha, beta, exact):
    assert abs(wall_moment(rigid_table(shape, alpha, beta)) - exact) < 1e-8


@pytest.mark.parametrize("k", [1, 3])
def test_kinetic_diffusion_is_the_one_the_law_requires(k):
    # the chain builds D2 from D1 and the law Beta(1, k); the kinetic D2 must agree
    table = rigid_table("flat", 0.5, 0.3)
    energy, cells = 0.5, 400
    s = np.linspace(0, 1, 801)
    d1 = kinetic_coefficients(table, k, 0.2, energy, energy * s)[0] / energy
    chain = law_chain(stats.beta(1, k).pdf, s, d1, cells=cells)
    faces = np.arange(1, cells) / cells
    from_law = chain.conductance / stats.beta(1, k).pdf(faces)
    kinetic = kinetic_coefficients(table, k, 0.2, energy, energy * faces)[1] / energy**2
    # to the quadrature of D1's sqrt(E - E_c) edge (a 2e-4 shift of D1's law average)
    error = np.max(np.abs(from_law - kinetic)) / np.max(kinetic)
    assert error < 2e-3, error
    assert abs(chain.shift) < 1e-3 * np.max(np.abs(d1))


def test_bad_container_energy_is_named():
    with pytest.raises(ParameterError, match="^container_energies = "):
        kinetic_coefficients(rigid_table("flat", 0.5, 0.3), 1, 0.2, 0.5, [0.7])
