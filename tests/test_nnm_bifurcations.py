"""Issue 15: period doubling and branch switching, checked against independent integrations.

The Henon-Heiles orbit on the y axis (x = 0: y'' = -y + y^2) loses transverse stability
through a period doubling as its energy grows: its transverse motion obeys the Hill
equation x'' + (1 + 2 y(t)) x = 0.  References (scipy DOP853, rtol 1e-13, written out here
from the Hamiltonian, not from the engine):

* the located period doubling: the Hill equation's half-trace over the exact period at the
  event energy is -1 to 1e-7 (the discrete map at 256 steps moves it by ~1e-9, the
  location stops at ~1e-9 in energy);
* the switched branch: its orbits have period 2T to 1e-2 near the bifurcation (T of the
  parent orbit), return to their start after 2T under the exact flow to 1e-8 (a genuine
  period-2T orbit), are not back at the start after T (so not the parent traversed
  twice: ||z(T) - z0|| > 1e-2), and leave the line x = 0.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from sinktheory.nnm.continuation import continue_orbits, switch_branch
from sinktheory.nnm.system import FlowSystem

RTOL = dict(method="DOP853", rtol=1e-13, atol=1e-14)


def _henon_heiles(_t, z):
    x, y, vx, vy = z
    return [vx, vy, -x - 2 * x * y, -y - x * x + y * y]


@pytest.fixture(scope="module")
def y_axis_branch():
    s = FlowSystem("henon_heiles", [])
    return continue_orbits(s, np.array([0, 0.1, 0, 0]), 2 * np.pi, steps=256,
                           stop=(1e-3, 0.15), ds=0.1, phase_index=1)  # fmt: skip


def test_period_doubling_of_the_y_axis_orbit_is_located(y_axis_branch):
    pds = [e for e in y_axis_branch.events if e.kind == "period-doubling"]
    assert len(pds) == 1, y_axis_branch.events
    E = pds[0].value
    assert abs(pds[0].multiplier + 1) < 1e-3  # the critical multiplier (split ~sqrt(eps))

    def hill(_t, w):
        y, vy, x1, v1, x2, v2 = w
        k = 1 + 2 * y
        return [vy, -y + y * y, v1, -k * x1, v2, -k * x2]

    y0 = brentq(lambda y: y * y / 2 - y**3 / 3 - E, 0, 1)  # turning point at energy E

    def bottom(_t, w):
        return w[1]

    bottom.direction, bottom.terminal = 1, True
    half = solve_ivp(hill, (0, 100), [y0, 0, 1, 0, 0, 1], events=bottom, **RTOL)
    T = 2 * half.t_events[0][0]
    w = solve_ivp(hill, (0, T), [y0, 0, 1, 0, 0, 1], **RTOL).y[:, -1]
    assert abs((w[2] + w[5]) / 2 + 1) < 1e-7, (w[2] + w[5]) / 2
    assert abs(pds[0].orbit.period - T) < 1e-9 * T


def test_switching_at_the_period_doubling_gives_a_genuine_period_2T_orbit(y_axis_branch):
    pd = next(e for e in y_axis_branch.events if e.kind == "period-doubling")
    new = switch_branch(y_axis_branch, pd, amplitude=1e-2, ds=0.05, max_points=4,
                        stop=(0.1, 0.16))  # fmt: skip
    assert len(new.orbits) == 4, new.stop_reason
    T = pd.orbit.period
    for o in new.orbits[1:]:
        assert abs(o.period / (2 * T) - 1) < 1e-2, o.period / T
        flow = solve_ivp(_henon_heiles, (0, o.period), o.z0, dense_output=True, **RTOL)
        assert np.max(np.abs(flow.y[:, -1] - o.z0)) < 1e-8  # periodic with period ~2T
        assert np.max(np.abs(flow.sol(o.period / 2) - o.z0)) > 1e-2  # not period T
        assert abs(o.z0[0]) > 1e-2  # off the invariant line x = 0
        assert abs(o.energy - (o.z0[2:] @ o.z0[2:] / 2 + o.z0[0] ** 2 / 2 + o.z0[1] ** 2 / 2
                               + o.z0[0] ** 2 * o.z0[1] - o.z0[1] ** 3 / 3)) < 1e-14  # fmt: skip
