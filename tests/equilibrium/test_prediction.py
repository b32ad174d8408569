"""The predicted relaxation: the law-constrained chain against a diffusion with known
coefficients and against the law's own moments, then the prediction from measured drift
and how long an ensemble must run."""

import math

import numpy as np
import pytest
from scipy import integrate, stats

from sinktheory import RunSettings
from sinktheory.canonical import FIG8_WELL
from sinktheory.equilibrium import equilibrium_law, measure_relaxation
from sinktheory.equilibrium.kramers import gauss_grid, jacobi_increments
from sinktheory.equilibrium.prediction import (
    MODEL_FACTOR,
    law_chain,
    log_lambdas,
    measure_settling,
    predict_relaxation,
    settling_periods,
    slow_mode,
)
from sinktheory.errors import ParameterError
from sinktheory.model import Sink
from sinktheory.simulate import simulate


def law_moments(law):
    """Mean and standard deviation of s = E_c / E by adaptive quadrature of the density."""
    norm = integrate.quad(law.pdf, 0, 1, limit=200)[0]
    mean = integrate.quad(lambda s: s * law.pdf(s), 0, 1, limit=200)[0] / norm
    second = integrate.quad(lambda s: s * s * law.pdf(s), 0, 1, limit=200)[0] / norm
    return mean, math.sqrt(second - mean**2)


def test_the_diffusion_from_fluctuation_dissipation_is_the_jacobi_one():
    # ds = c (a (1 - s) - b s) dt + sqrt(2 c s (1 - s)) dW has the Beta(a, b) law; given
    # that law and the drift, D2 p = -int_s^1 D1 p must give back D2 = c s (1 - s).
    a, b, c = 2.0, 3.0, 0.01
    s = np.linspace(0, 1, 11)
    chain = law_chain(stats.beta(a, b).pdf, s, c * (a * (1 - s) - b * s), cells=200)
    faces = np.arange(1, 200) / 200
    d2 = chain.conductance / stats.beta(a, b).pdf(faces)
    assert np.allclose(d2, c * faces * (1 - faces), rtol=1e-7, atol=0)
    assert abs(chain.shift) < 1e-12 and chain.clipped == 0


def test_a_drift_inconsistent_with_the_law_is_reported_as_clipped_faces():
    # a drift pushing up at the top would need a negative diffusion there to keep Beta(2, 3)
    s = np.linspace(0, 1, 11)
    chain = law_chain(stats.beta(2, 3).pdf, s, np.where(s < 0.75, -0.01, 0.05), cells=100)
    assert chain.clipped > 0


@pytest.mark.parametrize("k", [1, 5])
def test_the_chain_ends_at_the_law_and_relaxes_a_linear_drift_exponentially(k):
    law = equilibrium_law(Sink(FIG8_WELL, particles=k), 0.5)
    mean, sd = law_moments(law)
    s = np.linspace(0, 1, 12)
    drift = -0.002 * (s - 0.3)  # any line with a negative slope: rate 0.002 per period
    chain = law_chain(law.pdf, s, drift)
    t = np.array([0.0, 200.0, 600.0, 2e4])
    m, spread = chain.moments(1.0, t)
    assert abs(m[-1] - mean) < 1e-4 and abs(spread[-1] / sd - 1) < 2e-3
    # the generator maps s to -0.002 (s - mean): the mean relaxes as one exponential
    exact = mean + (m[0] - mean) * np.exp(-0.002 * t)
    assert np.max(np.abs(m - exact)) < 2e-3, (m, exact)


def test_the_slow_mode_of_a_jacobi_diffusion_is_its_exact_rate():
    # a Jacobi diffusion's conditional mean relaxes as exp(-c (a + b) tau) exactly: one
    # slow mode, seen whole (lambda(0) = 1), rate 0.009 per period (t_r = 111.1)
    s0, _ = gauss_grid(8, 1)
    lags = np.array([16, 32, 64, 128])
    inc = jacobi_increments(s0, lags, 1500, np.random.default_rng(5), a=1.0, b=1.25,
                            c=0.004, substeps=10)  # fmt: skip
    se = inc.std(axis=2, ddof=1) / math.sqrt(inc.shape[2])
    log_lambda = log_lambdas(s0, inc, se)
    assert np.allclose(log_lambda, -0.009 * lags, atol=0.05), log_lambda
    t_r, visible = slow_mode(lags, log_lambda, np.ones(4))
    assert abs(t_r / 111.1 - 1) < 0.1 and abs(visible - 1) < 0.05, (t_r, visible)


def test_prediction_settles_where_the_chain_crosses_and_ends_with_the_law_spread():
    # 64 runs per shell energy: with 8, two seeds in eight saw no fall of ln lambda
    sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    p = predict_relaxation(sink, 0.5, shell_energies=4, shell_runs=64, lag=32, resamples=20, seed=3)
    law = equilibrium_law(sink, p.total_energy)
    mean, sd = law_moments(law)
    assert abs(p.spread[-1] / (sd * p.total_energy) - 1) < 0.02
    assert p.settle_low <= p.settle_time <= p.settle_high
    assert np.all(p.low <= p.means + 1e-15) and np.all(p.means <= p.high + 1e-15)
    # the settling formula against the chain's own mean at that time (a second method):
    # the slow mode's excess, a fraction c of it seen, is f of the law's mean
    s = np.linspace(0, 1, 5)
    chain = law_chain(law.pdf, s, -(s - mean) / p.rate_time)
    s0 = p.container_energy / p.total_energy
    at = chain.moments(s0, np.array([0.0, p.settle_time]))[0]
    excess = p.visible * (s0 - mean) * (at[1] - mean) / (at[0] - mean)
    assert abs(excess / (p.fraction * mean) - 1) < 0.01, excess / mean


@pytest.mark.parametrize(
    "kwargs,name",
    [
        ({"fraction": 1.0}, "fraction"),
        ({"fraction": 0.0}, "fraction"),
        ({"lag": 4}, "lag"),
        ({"shell_energies": 2}, "shell_energies"),
        ({"shell_runs": 3}, "shell_runs"),
        ({"resamples": 5}, "resamples"),
    ],
)
def test_bad_arguments_are_named(kwargs, name):
    with pytest.raises(ParameterError, match=f"^{name} = "):
        predict_relaxation(Sink(FIG8_WELL), 0.5, **kwargs)


def test_bad_energy_is_named():
    with pytest.raises(ParameterError, match="^container_energy = "):
        predict_relaxation(Sink(FIG8_WELL), -1.0)


def test_predicted_settling_is_the_prediction_widened_by_the_model_factor():
    sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    shell = dict(shell_energies=4, shell_runs=16, lag=64, seed=1)
    p = predict_relaxation(sink, 0.5, **shell)
    s = settling_periods(sink, 0.5, **shell)
    assert s.source == "predicted" and s.periods == p.settle_time
    assert (s.low, s.high) == (p.settle_low / MODEL_FACTOR, p.settle_high * MODEL_FACTOR)


def test_measured_settling_is_the_relaxation_of_the_same_runs():
    sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    m, _ = measure_settling(sink, 0.5, (6, 480), seed=2, resamples=40)
    sim = simulate(sink, RunSettings(runs=6, periods=480, seed=2), tol=1e-6, progress=False)
    law = equilibrium_law(sink, float(np.mean(sim.initial_energy)))
    r = measure_relaxation(sim.container_energy, law.mean, window=40, resamples=40, seed=2)
    assert (m.settle_time, m.settle_low, m.settle_high) == (r.settle_time, r.settle_low,
                                                            r.settle_high)  # fmt: skip
    with pytest.raises(ParameterError, match="^measure = "):
        settling_periods(sink, 0.5, measure=(2, 480))
