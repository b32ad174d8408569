"""Ensemble statistics and sink measures against direct computation."""

import numpy as np
import pytest

from sinktheory import ParameterError
from sinktheory.sinkstats import (
    ensemble_mean,
    equipartition_container_energy,
    first_fall_below,
    running_mean,
    sink_measures,
)


def test_ensemble_mean_matches_loops():
    rng = np.random.default_rng(1)
    e = rng.random((7, 30))
    m, se = ensemble_mean(e)
    for j in range(30):
        col = e[:, j]
        mu = sum(col) / 7
        var = sum((c - mu) ** 2 for c in col) / 6
        assert m[j] == pytest.approx(mu, rel=1e-14)
        assert se[j] == pytest.approx((var / 7) ** 0.5, rel=1e-12)


def test_running_mean_matches_loop():
    s = np.random.default_rng(2).random(200)
    for w in (1, 5, 50):
        out = running_mean(s, w)
        assert out.size == 200 - w + 1
        for j in (0, 17, out.size - 1):
            assert out[j] == pytest.approx(sum(s[j : j + w]) / w, rel=1e-12)


def test_first_fall_below_and_measures():
    P = 100
    t = np.arange(P + 1)
    runs = np.vstack([0.5 * np.exp(-t / 10) + 0.1 + 0.01 * r for r in range(4)])
    m = sink_measures(runs, e0=0.5, total_energy=0.5, particles=5, n=6, transient=50)
    # mean curve 0.5 e^{-t/10} + 0.115 first drops below 0.5*0.5: e^{-t/10} < 0.27
    assert m.first_below[0.5] == int(np.floor(-10 * np.log(0.27))) + 1
    assert m.long_time_mean == pytest.approx(runs[:, 50:].mean(), rel=1e-13)
    per_run = runs[:, 50:].mean(axis=1)
    assert m.run_spread == pytest.approx(np.std(per_run, ddof=1), rel=1e-12)
    assert m.long_time_stderr == pytest.approx(np.std(per_run, ddof=1) / 2, rel=1e-12)
    assert m.particle_fraction == pytest.approx(1 - m.long_time_mean / 0.5)
    assert first_fall_below([0.5, 0.5], [0.1], 0.5) == {0.1: None}


def test_equipartition_hand_values():
    # k = 1, n = 10: 1 + 1 + 1/10 = 2.1 shares
    assert equipartition_container_energy(0.5, 1, 10) == pytest.approx(0.5 / 2.1)
    # n -> large: the particles' potential share vanishes, 1 + k shares remain
    assert equipartition_container_energy(1.0, 3, 1000) == pytest.approx(1 / 4.003)


@pytest.mark.parametrize(
    "call,name",
    [
        (lambda: ensemble_mean([[1.0, np.nan]]), "energy_runs"),
        (lambda: running_mean([1.0, 2.0], 3), "window"),
        (lambda: first_fall_below([1.0], [0.5], 0.0), "e0"),
        (lambda: equipartition_container_energy(0.5, 0, 2), "particles"),
    ],
)
def test_bad_input(call, name):
    with pytest.raises(ParameterError, match=f"^{name} = "):
        call()
