"""The settling time of the ensemble mean: synthetic runs whose mean curve and crossing are
known exactly, then the Fig. 8 set-up (k = 5), whose settling must not move with the
number of runs."""

import math

import numpy as np
import pytest
from scipy import signal

from sinktheory import RunSettings
from sinktheory.canonical import FIG8_SINK
from sinktheory.equilibrium import equilibrium_law
from sinktheory.equilibrium.relaxation import measure_relaxation
from sinktheory.errors import ParameterError
from sinktheory.simulate import simulate

#: The synthetic approach x(t) = A exp(-(t / TAU)^B) to a law's mean 1, and its exact 5 %
#: crossing TAU ln(A / 0.05)^(1 / B) = 4722 periods.
A, TAU, B = 5.0, 700.0, 0.8
EXACT = TAU * math.log(A / 0.05) ** (1 / B)


def synthetic_runs(runs, steps, rng, phi=0.98, sigma=2.0):
    """Runs with mean 1 + x(t) and AR(1) noise of standard deviation ``sigma`` and
    integrated correlation time (1 + phi) / (1 - phi) = 99 samples."""
    t = np.arange(steps)
    noise = signal.lfilter([1.0], [1.0, -phi], rng.standard_normal((runs, steps)), axis=1)
    return 1 + A * np.exp(-((t / TAU) ** B)) + sigma * math.sqrt(1 - phi**2) * noise


def test_more_runs_narrow_the_interval_and_do_not_move_it():
    # 6 independent sets of 64 runs; the first 16 and 32 runs of each give the smaller
    # ensembles.  Expected: the 95 % intervals contain the exact crossing about 95 % of
    # the time (17.1 of 18; 15 or more has probability 0.99 at the nominal level, 0.90
    # at a coverage of 0.9), widths shrink like 1 / sqrt(R) from 32 runs on (w32 / w64
    # = 1.41; over 40 sets benchmarks/bench_relaxation.py measured 1.52) and faster from
    # 16, where the noise leaves the fit non-linear (4.0 for w16 / w64), the intervals
    # of one set overlap, and the mean estimate does not drift with R beyond its errors
    # (the benchmark: 4843 +- 330, 4602 +- 135, 4651 +- 93 for 16, 32, 64 runs).
    inside, ratios, estimates = 0, {16: [], 32: []}, {16: [], 32: [], 64: []}
    for seed in range(6):
        runs = synthetic_runs(64, 8001, np.random.default_rng(seed))
        r = {
            R: measure_relaxation(runs[:R], 1.0, window=100, resamples=199, seed=seed)
            for R in (16, 32, 64)
        }
        inside += sum(x.settle_low <= EXACT <= x.settle_high for x in r.values())
        assert max(x.settle_low for x in r.values()) < min(x.settle_high for x in r.values())
        width = {R: x.settle_high - x.settle_low for R, x in r.items()}
        for R in ratios:
            ratios[R].append(width[R] / width[64])
        for R, x in r.items():
            estimates[R].append(x.settle_time)
            assert x.chi2 < 2 and abs(x.late_z) < 4 and x.tail_start < EXACT
    assert inside >= 15, inside
    assert 1.15 < np.median(ratios[32]) < 2.0 and np.median(ratios[16]) > 1.4, ratios
    drift = np.mean(estimates[16]) - np.mean(estimates[64])
    assert abs(drift) < 3 * np.std(estimates[16], ddof=1) / math.sqrt(6), estimates


def test_one_exponential_and_an_approach_from_below():
    # x(t) = -2 exp(-t / 300): the fitted stretch is 1 and the crossing 300 ln(40)
    rng = np.random.default_rng(3)
    t = np.arange(3001)
    runs = 0.5 * (1 - 2 * np.exp(-t / 300.0)) + 0.05 * rng.standard_normal((16, t.size))
    r = measure_relaxation(runs, 0.5, resamples=99)
    assert r.amplitude == pytest.approx(-2, rel=0.05)
    assert r.stretch == pytest.approx(1, abs=0.05) and r.rate_time == pytest.approx(300, rel=0.05)
    assert r.settle_low < 300 * math.log(40) < r.settle_high
    assert np.all(r.low <= r.means) and np.all(r.means <= r.high)
    assert r.stderr[-1] == pytest.approx(0.05 / math.sqrt(16 * 50), rel=0.4)


def test_never_settling_is_flagged_and_bad_input_is_refused():
    runs = 0.3 + 0.001 * np.random.default_rng(1).standard_normal((5, 400))
    r = measure_relaxation(runs, 0.2, window=20, resamples=20)
    assert r.extrapolated and r.settle_time > 400 and r.late_z > 10
    for name, kwargs in [
        ("target", {"target": -1}),
        ("target", {"target": 0}),
        ("fraction", {"fraction": 0}),
        ("window", {"window": 200}),
        ("tail", {"tail": 0.05}),
        ("level", {"level": 1}),
        ("resamples", {"resamples": 0}),
        ("seed", {"seed": -1}),
    ]:
        with pytest.raises(ParameterError, match=name):
            measure_relaxation(runs, **{"target": 0.2, "window": 20, **kwargs})
    with pytest.raises(ParameterError, match="energy_runs"):
        measure_relaxation(runs[:2], 0.2)
    with pytest.raises(ParameterError, match="energy_runs"):
        measure_relaxation(np.where(runs > 0.3, np.nan, runs), 0.2)


@pytest.mark.slow
def test_fig8_k5_settling_is_stable_in_ensemble_size():
    # The acceptance check: Fig. 8 (flat, alpha 0.5, beta 0.3, n 4, m 0.2,
    # E0 0.5), five particles, 64 runs x 8000 periods at tol 1e-6 (energy audit holds to
    # 1e-6; ~20 s on a quiet machine); its first 16 and 32 runs give the smaller
    # ensembles.  The 5 % crossing is near 5200 periods (benchmarks/bench_relaxation.py:
    # 5241, 4137-6514 from 192 runs; these 64 runs give 5138, 3803-7047).  The three
    # 95 % intervals overlap, the 64-run one is narrower than the 16-run one, none needs
    # an extrapolation, and the late mean agrees with the law's, computed independently.
    sink = FIG8_SINK
    sim = simulate(
        sink,
        RunSettings(container_energy=0.5, runs=64, periods=8000, seed=1),
        tol=1e-6,
        progress=False,
    )
    assert sim.max_relative_energy_error < 1e-5
    law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
    e = sim.container_energy
    r = {R: measure_relaxation(e[:R], law.mean, resamples=199) for R in (16, 32, 64)}
    assert max(x.settle_low for x in r.values()) < min(x.settle_high for x in r.values()), r
    widths = {R: x.settle_high - x.settle_low for R, x in r.items()}
    assert widths[64] < widths[16], widths
    assert not any(x.extrapolated for x in r.values())
    assert abs(r[64].late_z) < 3 and r[64].chi2 < 2
