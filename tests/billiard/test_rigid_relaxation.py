"""The rigid shell's states against the microcanonical measure they must sample, and its
invariance under exact billiards."""

import math

import numpy as np
import pytest
from scipy import stats

from sinktheory.billiard.relaxation import predict_rigid_relaxation, rigid_shell_states
from sinktheory.billiard.run import simulate_billiard
from sinktheory.billiard.table import rigid_table
from sinktheory.errors import ParameterError

TABLE = rigid_table("flat", 0.5, 0.3)


def test_shell_states_at_a_given_container_energy():
    k, m, e, s, runs = 3, 0.2, 0.5, 0.25, 3000
    pos, vel, box = rigid_shell_states(TABLE, k, m, e, s, runs, np.random.default_rng(4))
    assert np.all(TABLE.wall_values(pos[..., 0], pos[..., 1]) > 0)
    assert np.allclose(0.5 * (box**2).sum(axis=1), s * e, rtol=1e-14)
    energies = 0.5 * (m / k) * (vel**2).sum(axis=2)  # (run, particle)
    assert np.allclose(energies.sum(axis=1), (1 - s) * e, rtol=1e-13)
    # a flat density of states per particle: each one's share of e_p is Beta(1, k - 1),
    # its direction uniform, the container's phase uniform
    share = energies[:, 0] / energies.sum(axis=1)
    assert stats.kstest(share, stats.beta(1, k - 1).cdf).pvalue > 1e-3
    direction = np.arctan2(vel[:, 0, 1], vel[:, 0, 0])
    assert stats.kstest(direction, stats.uniform(-math.pi, 2 * math.pi).cdf).pvalue > 1e-3
    phase = np.arctan2(box[:, 1], box[:, 0])
    assert stats.kstest(phase, stats.uniform(-math.pi, 2 * math.pi).cdf).pvalue > 1e-3
    # positions uniform over the table: the share in its left half is 1/2 (symmetric table)
    left = np.mean(pos[..., 0] < 0)
    assert abs(left - 0.5) < 4 * math.sqrt(0.25 / pos[..., 0].size)


def test_the_shell_with_the_rigid_law_is_invariant_under_billiards():
    # s drawn from Beta(1, k) and the rest from the shell: E_c's law must not move
    k, m, e, runs, periods = 2, 0.2, 0.5, 400, 20
    rng = np.random.default_rng(7)
    states = [rigid_shell_states(TABLE, k, m, e, float(si), 1, rng)
              for si in stats.beta(1, k).rvs(runs, random_state=rng)]  # fmt: skip
    pos, vel, box = (np.concatenate(part) for part in zip(*states, strict=True))
    res = simulate_billiard(TABLE, pos, vel, mu=m / k, container=box, periods=periods)
    s_end = res.container_energy[:, -1] / e
    assert abs(s_end.mean() - 1 / (k + 1)) < 3 * s_end.std() / math.sqrt(runs)
    assert stats.kstest(s_end, stats.beta(1, k).cdf).pvalue > 1e-3


def test_container_energy_fraction_is_checked():
    with pytest.raises(ParameterError, match="^s = "):
        rigid_shell_states(TABLE, 1, 0.2, 0.5, 1.0, 4, np.random.default_rng(0))


@pytest.mark.parametrize(
    "kwargs,name",
    [
        ({"fraction": 1.0}, "fraction"),
        ({"mass": -0.2}, "mass"),
        ({"particles": 0}, "particles"),
        ({"container_energy": 0.0}, "container_energy"),
        ({"shell_runs": 3}, "shell_runs"),
        ({"lag": 4}, "lag"),
    ],
)
def test_bad_arguments_of_the_rigid_prediction_are_named(kwargs, name):
    with pytest.raises(ParameterError, match=f"^{name} = "):
        predict_rigid_relaxation("flat", 0.5, 0.3, **kwargs)
