"""The cubic NES's threshold estimates (sinktheory.compare.threshold) against independent
computations: scipy's adaptive integrator for the averaged flow and a numerical search of
the slow invariant manifold for its fold.  The simulation's long-window capture below the
conventional threshold is checked in test_attachments.py, beside the short window (one
compiled kernel for both)."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from sinktheory.compare.threshold import (
    averaged_share,
    fold_energy,
    full_exchange_energy,
    half_share_energy,
)
from sinktheory.errors import ParameterError

MU, K3 = 0.2, 625.0  # the guide's NES: mass 0.2, gamma / (alpha - beta)^4 = 1 / 0.2^4


def _share_by_solve_ivp(E, horizon=300):
    """The averaged flow written out again and integrated adaptively (DOP853)."""

    def rhs(t, z):
        p1, pu = z[0] + 1j * z[1], z[2] + 1j * z[3]
        p2 = pu - p1
        d1 = -(3j * K3 / 8) * abs(p2) ** 2 * p2
        du = -0.5j * pu + (3j * K3 / (8 * MU)) * abs(p2) ** 2 * p2
        return [d1.real, d1.imag, du.real, du.imag]

    v = math.sqrt(2 * E)
    s = solve_ivp(rhs, (0, horizon), [v, 0, 0, 0], method="DOP853", rtol=1e-9, atol=1e-14,
                  dense_output=True)  # fmt: skip
    t = np.linspace(0, horizon, 30001)
    y = s.sol(t)
    return 1 - np.min(y[0] ** 2 + y[1] ** 2) / v**2


def test_averaged_share_against_an_adaptive_integrator():
    E = np.array([2e-5, 3.8e-5, 8.9e-5])
    ours = averaged_share(MU, K3, E)
    ref = np.array([_share_by_solve_ivp(e) for e in E])
    np.testing.assert_allclose(ours, ref, atol=2e-3)


def test_threshold_is_a_steep_continuous_rise_with_a_peak():
    """No jump: the share rises over a factor ~1.5 in energy; its 1/2 crossing is the
    convention (4.0e-5), the full exchange (share > 0.999) comes about twice higher."""
    e_half = half_share_energy(MU, K3)
    assert averaged_share(MU, K3, e_half) == pytest.approx(0.5, abs=0.02)
    assert 3.9e-5 < e_half < 4.2e-5
    grid = np.geomspace(2.5e-5, 6e-5, 60)
    steps = np.diff(averaged_share(MU, K3, grid))
    assert np.all(steps > 0) and steps.max() < 0.1  # continuous on a 1.5 % energy grid
    e_full, s_full = full_exchange_energy(MU, K3)
    assert s_full > 0.999 and 1.8 < e_full / e_half < 2.6
    assert averaged_share(MU, K3, [0.8 * e_full, 1.25 * e_full]).max() < s_full


@pytest.mark.parametrize("c", [0.0, 0.002, 0.05])
def test_fold_against_a_search_of_the_manifold(c):
    """The lower fold of mu^2 |phi_1|^2 / 4 = Z ((a Z - mu/2)^2 + d^2): the local maximum of
    the right-hand side, found on a fine grid of Z."""
    a, b, d = 3 * K3 * (1 + MU) / 8, MU / 2, c * (1 + MU) / 2
    Z = np.linspace(1e-9, b / a, 200001)
    f = Z * ((a * Z - b) ** 2 + d * d)
    energy = 0.5 * f.max() / b**2
    assert fold_energy(MU, K3, c) == pytest.approx(energy, rel=1e-6)
    with pytest.raises(ParameterError, match="damping"):
        fold_energy(MU, K3, 1.01 * MU / math.sqrt(3))
