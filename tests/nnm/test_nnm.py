"""Issue 15: normal modes of the container-particle system, checked against independent
references.  Two engine systems only (duffing2 and the flat n = 4 sink) to keep compile
time down.

References and tolerances:

* mass ratio -> 0: the coupled particle mode's transverse half-period half-trace against
  the fixed-container phi_half of :mod:`sinktheory.floquet` (DOP853, rtol 1e-13) to 1e-6;
  the recoil changes it by O(mu) (measured -0.27 mu), so mu = 1e-8 leaves ~3e-9.
* linear limit: Kerschen's system at H = 1e-8 has frequencies 1 and sqrt(3) to O(H).
* backbone of NNM1: a harmonic balance with 9 odd cosine harmonics solved by scipy
  (alternating frequency-time residual) at the continuation's energies, frequency to
  relative 1e-9 (measured 8e-13 up to H = 34: scheme error at 256 steps and series
  truncation both below it).
* multipliers: the monodromy by central differences of scipy's DOP853 flow at rtol 1e-12
  (step 1e-6: error ~1e-9 relative); nontrivial multipliers to 1e-6.
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root

from sinktheory import Sink, Well
from sinktheory.floquet import model_hill
from sinktheory.nnm.continuation import continue_orbits
from sinktheory.nnm.modes import linear_modes, mode_guess, sink_flow
from sinktheory.nnm.shooting import shoot
from sinktheory.nnm.stability import floquet
from sinktheory.nnm.system import FlowSystem

ALPHA, N = 0.5, 4


@pytest.fixture(scope="module")
def duffing():
    return FlowSystem("duffing2", [])


# --- 1. mass ratio -> 0 reproduces the paper's fixed-container normal mode -------------
@pytest.mark.parametrize("beta", [-0.6, 0.2, 0.4])
def test_small_mass_limit_reproduces_fixed_container_phi_half(beta):
    mu = 1e-8
    sink = Sink(Well(ALPHA, beta, N), particles=1, mass=mu)
    h = 1.0 / (2 * N)  # gamma A0^(2n) / (2n) with A0 = 1, the amplitude of floquet
    z0, T = mode_guess(sink, "particle", h)
    orbit = shoot(sink_flow(sink), z0, T, steps=500, total_energy=h, subspace="plane")
    phi = orbit.transverse_half_traces()[0]
    ref = model_hill(ALPHA, [beta], N).phi_half[0]
    assert abs(phi - ref) < 1e-6 * max(1.0, abs(ref)), (phi, ref)
    assert orbit.half_period()[2] < 1e-8  # odd under the half-period shift
    assert abs(orbit.sigma) < 1e-12 and orbit.floquet.trivial_error < 1e-4


def test_recoil_correction_is_first_order_in_the_mass():
    """The same comparison at mu = 1e-4 and 1e-5: the difference scales like mu (so the
    1e-6 agreement above is the limit, not a coincidence)."""
    diffs = []
    for mu in (1e-4, 1e-5):
        sink = Sink(Well(ALPHA, 0.2, N), particles=1, mass=mu)
        z0, T = mode_guess(sink, "particle", 0.125)
        o = shoot(sink_flow(sink), z0, T, steps=500, total_energy=0.125, subspace="plane")
        diffs.append(o.transverse_half_traces()[0] - model_hill(ALPHA, [0.2], N).phi_half[0])
    assert 9 < diffs[0] / diffs[1] < 11, diffs


# --- 2. linear limit --------------------------------------------------------------------
def test_linear_limit_gives_the_linear_normal_modes(duffing):
    w, shapes = linear_modes(duffing)
    assert np.allclose(w, [1.0, math.sqrt(3.0)], atol=1e-8)
    for k, target in enumerate((1.0, math.sqrt(3.0))):
        z0 = np.concatenate([1e-4 * shapes[:, k] / np.abs(shapes[:, k]).max(), [0, 0]])
        o = shoot(duffing, z0, 2 * math.pi / w[k], steps=128, total_energy=1e-8)
        assert abs(o.frequency - target) < 1e-6, (o.frequency, target)
        assert np.all(np.abs(np.abs(o.floquet.nontrivial) - 1) < 1e-9)  # stable, elliptic


def test_container_mode_frequency_tends_to_one():
    sink = Sink(Well(ALPHA, 0.3, N), particles=1, mass=0.2)
    z0, T = mode_guess(sink, "container", 1e-6)
    o = shoot(sink_flow(sink), z0, T, steps=200, total_energy=1e-6, subspace="plane")
    # the particle's force ~ (x / 0.2)^7 with |x| ~ 1.4e-3: frequency 1 to ~1e-12
    assert abs(o.frequency - 1.0) < 1e-9


# --- 3. Kerschen et al. (2009) backbone of NNM1 against harmonic balance --------------
def _harmonic_balance(energy, guess, harmonics=9, samples=128):
    """x_j(t) = sum_h a_jh cos(h w t), h odd; Galerkin residual by FFT; H(x(0)) = energy."""
    h = 2 * np.arange(harmonics) + 1
    tau = 2 * np.pi * (np.arange(samples) + 0.5) / samples
    C = np.cos(np.outer(tau, h))  # (samples, harmonics)

    def residual(p):
        a = p[:-1].reshape(2, harmonics)
        w = p[-1]
        x1, x2 = C @ a[0], C @ a[1]
        acc1, acc2 = C @ (-((h * w) ** 2) * a[0]), C @ (-((h * w) ** 2) * a[1])
        r1 = acc1 + 2 * x1 - x2 + 0.5 * x1**3
        r2 = acc2 + 2 * x2 - x1
        g = np.concatenate([C.T @ r1, C.T @ r2]) * 2 / samples
        X1, X2 = a[0].sum(), a[1].sum()
        U = X1**2 / 2 + (X2 - X1) ** 2 / 2 + X2**2 / 2 + 0.5 * X1**4 / 4
        return np.concatenate([g, [U - energy]])

    sol = root(residual, guess, method="hybr").x
    sol = root(residual, sol, method="lm", options={"xtol": 1e-15, "ftol": 1e-15}).x  # polish
    # converged: a residual of 1e-10 moves the frequency by ~1e-10
    assert np.max(np.abs(residual(sol))) < 1e-10 * max(1.0, energy), residual(sol)
    return sol


def test_backbone_of_the_first_nnm_matches_harmonic_balance(duffing):
    b = continue_orbits(
        duffing,
        np.array([0.1, 0.1, 0, 0]),
        2 * np.pi,
        steps=256,
        total_energy=0.01,
        interval=(1e-3, 30.0),
        ds=0.3,
    )
    assert b.stop_reason.startswith("parameter left") and len(b.orbits) > 10
    harmonics = 9
    worst = 0.0
    for o in b.orbits:  # HB started from the fundamental only (amplitudes, frequency)
        guess = np.zeros(2 * harmonics + 1)
        guess[0], guess[harmonics], guess[-1] = o.z0[0], o.z0[1], o.frequency
        sol = _harmonic_balance(o.total_energy, guess, harmonics)
        worst = max(worst, abs(o.frequency / sol[-1] - 1))
    assert worst < 1e-9, worst  # measured 8e-13
    assert b.frequency[-1] > 1.25  # hardening: ~1.27 at H = 30
    assert np.all(b.result().trivial_error < 1e-6)


# --- 4. multipliers against a finite-difference monodromy -----------------------------
def _fd_monodromy(system, z0, T, h=1e-6):
    def rhs(_t, z):
        return system.vector_field(z)

    def flow(z):
        return solve_ivp(rhs, (0, T), z, method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]

    n = z0.size
    M = np.empty((n, n))
    for j in range(n):
        e = np.zeros(n)
        e[j] = h
        M[:, j] = (flow(z0 + e) - flow(z0 - e)) / (2 * h)
    return M


@pytest.mark.parametrize("energy", [1.0, 45.0])  # stable, and past the +1 crossing
def test_multipliers_match_a_finite_difference_monodromy(duffing, energy):
    b = continue_orbits(
        duffing, np.array([0.1, 0.1, 0, 0]), 2 * np.pi, steps=256, total_energy=0.01,
        interval=(1e-3, energy), ds=0.3, ds_max=0.3,
    )  # fmt: skip
    last = b.orbits[-1]
    o = shoot(duffing, last.z0 * (energy / last.total_energy) ** 0.25, last.period, steps=256,
              total_energy=energy)  # fmt: skip
    M = _fd_monodromy(duffing, o.z0, o.period)
    ref = floquet(M, duffing.vector_field(o.z0), duffing.gradient(o.z0))
    assert np.allclose(np.sort_complex(ref.nontrivial), np.sort_complex(o.floquet.nontrivial),
                       atol=1e-6)  # fmt: skip
    assert np.max(np.abs(M - o.monodromy)) < 1e-6 * np.max(np.abs(M))
    assert o.floquet.stable == (energy < 40)


def test_transverse_multipliers_of_the_sink_match_finite_differences():
    sink = Sink(Well(ALPHA, 0.2, N), particles=1, mass=0.2)
    system = sink_flow(sink)
    z0, T = mode_guess(sink, "particle", 0.125)
    o = shoot(system, z0, T, steps=600, total_energy=0.125, subspace="plane")
    M = _fd_monodromy(system, o.z0, o.period)
    # transverse block (y, dy/dt) = indices 2, 5
    blk = M[np.ix_([2, 5], [2, 5])]
    ref = np.sort_complex(np.linalg.eigvals(blk))
    assert np.allclose(ref, np.sort_complex(o.floquet.transverse), rtol=1e-6, atol=1e-6)


# --- continuation events ------------------------------------------------------------
def test_fold_of_the_sink_branch_is_located():
    """Continuing the low-energy container mode of the flat n = 4 sink (mu = 0.2) meets
    the 1:1 resonance with the particle mode: the energy turns back (a fold).  The located
    fold must be the largest energy of the branch up to there."""
    sink = Sink(Well(ALPHA, 0.3, N), particles=1, mass=0.2)
    system = sink_flow(sink)
    z0, T = mode_guess(sink, "container", 1e-3)
    b = continue_orbits(system, z0, T, steps=400, total_energy=1e-3, interval=(1e-4, 0.05),
                        ds=0.2, subspace="plane")  # fmt: skip
    folds = [e for e in b.events if e.kind == "fold"]
    assert folds, b.events
    f = folds[0]
    assert 1.5e-3 < f.value < 2.5e-3
    e = [o.total_energy for o in b.orbits]
    assert max(e[: f.index + 2]) <= f.value * (1 + 1e-6)
