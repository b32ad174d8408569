"""Issue 15: period doubling and branch switching, checked against independent integrations.

The Henon-Heiles orbit on the y axis (x = 0: y'' = -y + y^2) loses transverse stability
through a period doubling as its energy grows: its transverse motion obeys the Hill
equation x'' + (1 + 2 y(t)) x = 0.  References (scipy DOP853, rtol 1e-13, written out here
from the Hamiltonian, not from the engine):

* the located period doubling: the Hill equation's half-trace over the exact period at the
  event energy is -1 to 1e-7 (the discrete map at 256 steps moves it by ~1e-9, the
  location stops at ~1e-9 in energy);
* crossings inside one step: with long steps near the escape energy 1/6, where the
  stability windows are narrow, every window is still reported (the step limit on the
  multipliers' turning, and, without it, the refinement of a dip between two points), at
  energies where the Hill half-trace is -1 (period doubling) or +1 (branch point) to
  1e-6, the same events as with 30 times shorter steps;
* the switched branch: its orbits have period 2T to 1e-2 near the bifurcation (T of the
  parent orbit), return to their start after 2T under the exact flow to 1e-8 (a genuine
  period-2T orbit), are not back at the start after T (so not the parent traversed
  twice: ||z(T) - z0|| > 1e-2), and leave the line x = 0.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from sinktheory import Sink, Well
from sinktheory.canonical import HENON_HEILES
from sinktheory.nnm import continuation
from sinktheory.nnm.continuation import continue_orbits, switch_branch
from sinktheory.nnm.modes import mode_guess, sink_flow
from sinktheory.nnm.shooting import shoot
from sinktheory.nnm.system import FlowSystem

RTOL = dict(method="DOP853", rtol=1e-13, atol=1e-14)


def _henon_heiles(_t, z):
    x, y, vx, vy = z
    return [vx, vy, -x - 2 * x * y, -y - x * x + y * y]


@pytest.fixture(scope="module")
def y_axis_branch():
    s = FlowSystem(HENON_HEILES, [])
    return continue_orbits(s, np.array([0, 0.1, 0, 0]), 2 * np.pi, steps=256,
                           interval=(1e-3, 0.15), ds=0.1, phase_index=1)  # fmt: skip


def _hill_half_trace(E):
    """(half-trace of the transverse Hill equation over the exact period, period) of the
    y-axis orbit at energy E."""

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
    return (w[2] + w[5]) / 2, T


def test_period_doubling_of_the_y_axis_orbit_is_located(y_axis_branch):
    pds = [e for e in y_axis_branch.events if e.kind == "period-doubling"]
    assert len(pds) == 1, y_axis_branch.events
    assert abs(pds[0].multiplier + 1) < 1e-3  # the critical multiplier (split ~sqrt(eps))
    phi, T = _hill_half_trace(pds[0].value)
    assert abs(phi + 1) < 1e-7, phi
    assert abs(pds[0].orbit.period - T) < 1e-9 * T


def test_switching_at_the_period_doubling_gives_a_genuine_period_2T_orbit(y_axis_branch):
    pd = next(e for e in y_axis_branch.events if e.kind == "period-doubling")
    new = switch_branch(y_axis_branch, pd, amplitude=1e-2, ds=0.05, max_points=4,
                        interval=(0.1, 0.16))  # fmt: skip
    assert len(new.orbits) == 4, new.stop_reason
    T = pd.orbit.period
    for o in new.orbits[1:]:
        assert abs(o.period / (2 * T) - 1) < 1e-2, o.period / T
        flow = solve_ivp(_henon_heiles, (0, o.period), o.z0, dense_output=True, **RTOL)
        assert np.max(np.abs(flow.y[:, -1] - o.z0)) < 1e-8  # periodic with period ~2T
        assert np.max(np.abs(flow.sol(o.period / 2) - o.z0)) > 1e-2  # not period T
        assert abs(o.z0[0]) > 1e-2  # off the invariant line x = 0
        assert abs(o.total_energy - (o.z0[2:] @ o.z0[2:] / 2 + o.z0[0] ** 2 / 2 + o.z0[1] ** 2 / 2
                               + o.z0[0] ** 2 * o.z0[1] - o.z0[1] ** 3 / 3)) < 1e-14  # fmt: skip


def _signs_agree(branch, e):
    key = {"period-doubling": "inplane_minus", "branch-point": "inplane_plus"}[e.kind]
    a, b = branch.orbits[e.index], branch.orbits[e.index + 1]
    return np.sign(a.floquet.tests()[key]) == np.sign(b.floquet.tests()[key])


def test_long_steps_still_report_every_window():
    """Steps of 0.6 requested: the turning-angle limit shortens them where multipliers
    rotate fast, and the events are those of steps 30 times shorter, at the Hill
    equation's +-1 (to 1e-6)."""
    s = FlowSystem(HENON_HEILES, [])
    kw = dict(steps=256, interval=(1e-3, 0.1664), max_points=2000, phase_index=1)
    z0 = np.array([0, 0.1, 0, 0])
    coarse = continue_orbits(s, z0, 2 * np.pi, ds=0.6, ds_max=0.6, **kw)
    fine = continue_orbits(s, z0, 2 * np.pi, ds=0.02, ds_max=0.02, **kw)
    assert len(fine.orbits) > 3 * len(coarse.orbits)
    # the last step may overshoot the range's end: compare inside it
    key = sorted((e.kind, round(e.value, 8)) for e in coarse.events if e.value < 0.1664)
    ref = sorted((e.kind, round(e.value, 8)) for e in fine.events if e.value < 0.1664)
    assert key == ref and len(key) == 6, (key, ref)
    for e in coarse.events:
        phi, _ = _hill_half_trace(e.value)
        assert abs(phi - (-1 if e.kind == "period-doubling" else 1)) < 1e-6, (e, phi)


def test_a_window_inside_one_step_is_found_between_its_end_points(monkeypatch):
    """Without the turning-angle limit, a step of 0.45 jumps over the window in which the
    pair is real beyond +1 (0.16155 < E < 0.16445): both ends have the same sign of the
    test function, and the margin's dip between them is refined into the two crossings."""
    monkeypatch.setattr(continuation, "MAX_TURN", np.inf)
    s = FlowSystem(HENON_HEILES, [])
    b = continue_orbits(s, np.array([0, 0.1, 0, 0]), 2 * np.pi, steps=256, interval=(1e-3, 0.1664),
                        ds=0.45, ds_max=0.45, phase_index=1)  # fmt: skip
    window = [e for e in b.events if e.kind == "branch-point" and 0.161 < e.value < 0.165]
    assert len(window) == 2 and window[0].index == window[1].index, b.events
    assert _signs_agree(b, window[0])  # invisible to the sign test
    for e in window:
        phi, _ = _hill_half_trace(e.value)
        assert abs(phi - 1) < 1e-6, (e, phi)


def test_transverse_touch_of_minus_one_is_reported():
    """The sink's transverse multipliers over one period are the squares of the
    half-period ones: phi_T = 2 phi_T/2^2 - 1 >= -1 touches -1 where phi_T/2 = 0 and the
    product test (mu + 1) never changes sign.  The touch is reported where an orbit shot
    independently at that beta has phi_T/2 = 0 (to 1e-6)."""
    sink = Sink(Well(0.5, 0.2, 4), particles=1, mass=0.2)
    z0, T = mode_guess(sink, "particle", 0.5)
    b = continue_orbits(sink_flow(sink), z0, T, steps=400, continue_in="beta", total_energy=0.5,
                        interval=(-0.45, 0.3), direction=-1, ds=0.3, subspace="plane")  # fmt: skip
    touches = [e for e in b.events if e.kind == "transverse-period-doubling-touch"]
    assert len(touches) == 1, b.events
    assert not [e for e in b.events if e.kind == "transverse-period-doubling"]
    beta = touches[0].value
    assert -0.3 < beta < -0.26
    s = sink_flow(Sink(Well(0.5, beta, 4), particles=1, mass=0.2))
    o = shoot(s, touches[0].orbit.z0, touches[0].orbit.period, steps=400, total_energy=0.5,
              subspace="plane")  # fmt: skip
    assert abs(o.transverse_half_traces()[0]) < 1e-6
    assert abs(touches[0].multiplier + 1) < 1e-6
