"""Issue 5, item 7: the full simulator's y-growth equals the Floquet exponent.

A single light particle (mu = 1e-4) starts at rest at x0 = alpha - beta (rescaled
amplitude A0 = 1; less 1e-13 relative, so the start lies strictly inside the walls as
``simulate`` requires, which changes the rate by ~1e-13) with y0 = 1e-250, the container
almost at rest (E0 = 1e-12).  The
normal mode is Floquet-unstable for beta = 0.2 (lambda < 0), so y grows like
exp(rate t) with rate = (Floquet exponent per rescaled time) * sqrt(gamma/mu)/(alpha - beta):
by ~1e139 over one container period, far inside the linear regime.  The simulator knows
nothing of Hill's equation; the agreement checks the linearisation, the rescaling (eq.
rescale) and both integrators.  Tolerance 1e-4: the container's recoil changes the rate
by O(mu) = 1e-4 (measured: 4e-6), and the envelope is read off a grid of 40000 samples.
"""

import math

import numpy as np

from sinktheory import RunSettings, Sink, Well
from sinktheory._generated import oscillator as _osc
from sinktheory.bifurcation import sampled_run
from sinktheory.floquet import model_hill


def test_growth_of_y_matches_the_floquet_exponent():
    alpha, beta, n, gamma, mu = 0.5, 0.2, 4, 1.0, 1e-4
    L = alpha - beta
    chart = model_hill(alpha, [beta], n)
    assert not chart.stable[0] and chart.phi_half[0] > 1  # both multipliers positive
    rate = chart.floquet_exponent[0] * math.sqrt(gamma / mu) / L
    half_period = 0.5 * _osc.period(n, 1.0) * L * math.sqrt(mu / gamma)

    sink = Sink(Well(alpha, beta, n, gamma=gamma), particles=1, mass=mu)
    per_period = 40_000
    rows = sampled_run(
        sink,
        RunSettings(container_energy=1e-12, runs=1, periods=1),
        (L * (1 - 1e-13), 1e-250),
        per_period=per_period,
    )
    t = np.linspace(0.0, 2 * np.pi, rows.shape[0])
    y = np.abs(rows[:, 3])
    assert y.max() < 1e-20  # still linear: y^(2n-1) terms are nothing

    # envelope: max |y| over consecutive half periods of the coefficient x^(2n)
    edges = np.arange(0.0, t[-1], half_period)
    idx = np.searchsorted(t, edges)
    peaks = np.array([y[a:b].max() for a, b in zip(idx[:-1], idx[1:], strict=True)])
    centres = 0.5 * (edges[:-1] + edges[1:])
    keep = slice(10, None)  # let the decaying Floquet mode die out first
    slope = np.polyfit(centres[keep], np.log(peaks[keep]), 1)[0]
    assert abs(slope / rate - 1) < 1e-4, (slope, rate)
