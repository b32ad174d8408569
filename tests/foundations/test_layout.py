"""The named state layout against the simulator's own states and the engine's (q, v)."""

import numpy as np
import pytest

from sinktheory import ParameterError, RunSettings, Sink, Well
from sinktheory.canonical import FIG8_WELL
from sinktheory.ensemble import start_state
from sinktheory.layout import SINK_PARAMS, StateLayout, pack_params
from sinktheory.simulate import simulate


def test_blocks_partition_the_row():
    L = StateLayout(3)
    cols = [L.X, L.XDOT] + [c for s in (L.u, L.y, L.udot, L.ydot) for c in range(L.width)[s]]
    assert cols == list(range(L.width)) == list(range(14))
    assert sorted(np.r_[L.q, L.v].tolist()) == list(range(14))


def test_start_state_positions_come_back_relative():
    sink = Sink(FIG8_WELL, particles=3, mass=0.2)
    pos = np.random.default_rng(1).uniform(-0.01, 0.01, (2, 3, 2))
    rows = start_state(sink, 0.5, pos)
    L = StateLayout.of(rows)
    assert L.particles == 3 and np.all(rows[:, L.X] == 1.0)  # X(0) = sqrt(2 E0)
    np.testing.assert_allclose(L.relative_positions(rows), pos, atol=1e-16)
    assert not rows[:, L.v].any()  # everything at rest


def test_split_join_against_the_engine_state():
    """A continued run equals one long run: the layout's split/join of the final state is
    what the engine resumes from, bitwise."""
    sink = Sink(FIG8_WELL, particles=2, mass=0.2)
    kw = dict(record=("container", "final"), dt=0.01, progress=False)
    one = simulate(sink, RunSettings(runs=2, periods=2, seed=3), **kw)
    half = simulate(sink, RunSettings(runs=2, periods=1, seed=3), **kw)
    rest = simulate(sink, RunSettings(runs=2, periods=1), initial_state=half.final_state, **kw)
    assert np.array_equal(rest.final_state.values, one.final_state.values)
    L = StateLayout(2)
    q, v = L.split(one.final_state.values)
    assert q.shape == (5, 2) and np.array_equal(L.join(q, v), one.final_state.values)


def test_packed_parameters_and_bad_widths():
    sink = Sink(Well(0.5, -0.2, 6, gamma=2.0), particles=4, mass=0.2)
    assert dict(zip(SINK_PARAMS, pack_params(sink), strict=True)) == pytest.approx(
        {"alpha": 0.5, "beta": -0.2, "gamma": 2.0, "n": 6, "mu": 0.05}
    )
    for width in (0, 5, 7):
        with pytest.raises(ParameterError) as info:
            StateLayout.of(np.zeros((1, width)))
        assert info.value.name == "values"
