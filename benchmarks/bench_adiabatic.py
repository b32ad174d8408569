"""Why light particles relax the container slowly: the dragged gas and its linear response.

Usage::

    python benchmarks/bench_adiabatic.py [--particles 3] [--cases M:E:BETA ...]
        [--seed 0] [--spectrum-runs 16] [--spectrum-time 4000] [--spectrum-seed 0]

The random-impact theory (sinktheory.billiard.kinetic) lets the particles hit a container
that moves through a gas at rest.  A confined particle crosses the table several times per
container period, so the gas is carried along with the container; what is left is the
particles' response to the inertial force -mu X'' = mu X they feel in the container's
frame.  To first order in mu (linear response, a harmonic container X = A cos t) the
force f = -mu dv_x/dt of one particle on the container has the spectrum
S_f(1) = mu^2 S_x(1) at the container's frequency, S_x the spectrum of the particle's
x-position in the fixed table, and the container energy diffuses with

    D2(E_c) = (mu^2 / 2) E_c sum_j S_x(1; c_j),    S_x(1; c) = S(1 / c) / c,

where S(q) is the spectrum at unit speed (the fixed table's motion at speed c is the
unit-speed motion with time scaled by c).  D1 follows from fluctuation-dissipation with the
rigid law Beta(1, k), the particles' energies uniform on the simplex.  The slowest
relaxation time of that Fokker-Planck equation (law_chain) is the "linear response" t_r:
no parameter is fitted.  Random impacts would have S_x(1) of a free gas; a bouncing
particle has little spectral weight at frequencies well below its bouncing, so the
response falls steeply as c grows (c ~ sqrt(E / m)).

For each table beta: S(q) from ``--spectrum-runs`` unit-speed particles, uniform over the
fixed table in random directions (seed ``--spectrum-seed``), x sampled every 0.05 over
``--spectrum-time`` (Welch, segments of 800, Hann window), its bootstrap over the runs;
from the same runs the autocorrelation of the x-share v_x^2 / c^2 of a particle's energy
at t = 1, 10, 100 and its integral up to 100 (how fast the direction mixes; divide the
times by c for a particle of speed c).
For each case m:E:beta (k = ``--particles``, flat well, alpha 0.5): the slow mode's t_r
measured by predict_rigid_relaxation (12 x 100 rigid billiards from the shell, seed
``--seed``, lags 16-128), the linear-response t_r (95 % over the spectrum's runs), the
random-impact t_r (kinetic_relaxation), and the speed c of a particle holding the mean
share E / (k + 1) with the impact rate per unit time it gives (perimeter c / (pi area)).

Prints the machine, the spectra at a few q, then one line per case.
"""

from __future__ import annotations

import argparse
import math
import sys
import time

import numpy as np
from scipy import signal, stats

from sinktheory.billiard import kernels as K
from sinktheory.billiard.kinetic import kinetic_relaxation
from sinktheory.billiard.relaxation import predict_rigid_relaxation, rigid_shell_states
from sinktheory.billiard.run import _table_arrays
from sinktheory.billiard.table import rigid_table
from sinktheory.equilibrium.prediction import law_chain

DT, SEGMENT, ALPHA, RESAMPLES = 0.05, 800.0, 0.5, 99
SHARE_LAGS = [1.0, 10.0, 100.0]  # time units at unit speed
CASES = ["0.2:0.125:0.3", "0.2:0.5:0.3", "0.2:2.0:0.3", "0.05:0.125:0.3", "0.1:0.25:0.3",
         "0.4:1.0:0.3", "0.1:0.5:0.3", "0.4:0.5:0.3", "0.2:0.5:0.1", "0.2:0.5:-0.3"]  # fmt: skip


def fixed_table_motion(beta, runs, duration, seed):
    """(omega, S (run, omega), variance of x, C (lag,) at SHARE_LAGS, its integral to
    the last lag) of unit-speed particles in the fixed table (module docstring): S the
    two-sided spectrum of x, C the autocorrelation of the x-share v_x^2 / c^2 of the
    energy (how fast the direction mixes)."""
    table = rigid_table("flat", ALPHA, beta)
    pos, vel, _ = rigid_shell_states(table, 1, 1.0, 0.5, 0.0, runs, np.random.default_rng(seed))
    arrays = _table_arrays(table)
    steps = int(duration / DT)
    xs, share = np.empty((runs, steps)), np.empty((runs, steps))
    out = (np.zeros((runs, steps + 1)), np.zeros((runs, steps + 1)),
           np.zeros((runs, len(arrays[0])), dtype=np.int64), np.zeros(runs, dtype=np.int64),
           np.zeros((runs, 2)))  # fmt: skip
    for j in range(steps):  # one record every DT: the kernel's "period" is DT
        K.run_fixed(pos, vel, np.zeros((runs, 0, 4)), j, j + 1, DT, *arrays, out)
        xs[:, j] = pos[:, 0, 0]
        share[:, j] = vel[:, 0, 0] ** 2
    if out[3].any():
        raise RuntimeError("fixed billiard failed")
    speed = np.sqrt((vel**2).sum(axis=-1))
    assert np.allclose(speed, 1.0, atol=1e-9), "unit speed not kept"
    f, p = signal.welch(xs, fs=1 / DT, nperseg=int(SEGMENT / DT), axis=-1)
    y = share - share.mean()
    spec = np.abs(np.fft.rfft(y, 2 * steps, axis=1)) ** 2
    corr = np.fft.irfft(spec, axis=1)[:, :steps].mean(axis=0) / (steps - np.arange(steps))
    corr /= corr[0]
    last = int(SHARE_LAGS[-1] / DT)
    picks = corr[[int(t / DT) for t in SHARE_LAGS]]
    # one-sided density per Hz -> two-sided per omega
    return (2 * math.pi * f, p / 2, float(xs.var()), picks,
            float(np.trapezoid(corr[: last + 1], dx=DT)))  # fmt: skip


def linear_response_time(omega, spec, k, m, energy):
    """Slowest relaxation time (periods) of E_c with the linear-response D2 (module
    docstring) for the unit-speed spectrum ``spec`` at ``omega``."""
    mu = m / k
    lw, ls = np.log(omega[1:]), np.log(np.maximum(spec[1:], 1e-300))

    def s_x(c):
        return np.exp(np.interp(np.log(1 / c), lw, ls, left=ls[0], right=-np.inf)) / c

    if k == 1:
        b, wb = np.ones(1), np.ones(1)
    else:
        x, w = np.polynomial.legendre.leggauss(400)
        b = 0.5 * (x + 1)
        wb = 0.5 * w * stats.beta(1, k - 1).pdf(b)
    s = np.linspace(0.0, 1.0, 401)
    ep = energy * (1 - s[:-1])
    sums = np.array([k * np.sum(wb * s_x(np.sqrt(2 * e * b / mu))) for e in ep] + [0.0])
    d2 = 0.5 * mu**2 * energy * s * sums * 2 * math.pi / energy**2  # s^2 per period
    p = stats.beta(1, k).pdf(s)
    d1 = np.gradient(d2 * p, s) / np.maximum(p, 1e-300)  # fluctuation-dissipation
    d1[-1] = d1[-2]
    lam = np.sort(law_chain(stats.beta(1, k).pdf, s, d1, cells=300).spectrum[0])
    return -1 / float(lam[-2])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--particles", type=int, default=3)
    parser.add_argument("--cases", nargs="+", default=CASES)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--spectrum-runs", type=int, default=16)
    parser.add_argument("--spectrum-time", type=float, default=4000.0)
    parser.add_argument("--spectrum-seed", type=int, default=0)
    args = parser.parse_args()
    sys.path.insert(0, __file__.rsplit("/", 1)[0])
    from machine import describe

    print(describe())
    k = args.particles
    cases = [tuple(float(x) for x in c.split(":")) for c in args.cases]
    spectra, mixing = {}, []
    print(f"S(q) of x at unit speed, {args.spectrum_runs} runs x {args.spectrum_time:g} "
          f"(seed {args.spectrum_seed}):")  # fmt: skip
    qs = [0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0]
    print("  beta   " + " ".join(f"{q:>7g}" for q in qs) + "   int S / pi, <x^2>")
    for beta in sorted({c[2] for c in cases}):
        t0 = time.perf_counter()
        omega, spec, var_x, share, tau = fixed_table_motion(
            beta, args.spectrum_runs, args.spectrum_time, args.spectrum_seed
        )
        spectra[beta] = omega, spec
        mixing.append(f"  {beta:5.2f}  C(1, 10, 100) = " + ", ".join(f"{c:.3f}" for c in share)
                      + f"; integral to 100: {tau:.1f}")  # fmt: skip
        mean = spec.mean(axis=0)
        near = [mean[np.abs(omega - q) < 0.05].mean() for q in qs]
        var = np.trapezoid(mean, omega) / math.pi
        took = time.perf_counter() - t0
        print(f"  {beta:5.2f}  " + " ".join(f"{x:7.4f}" for x in near)
              + f"   {var:.4f}, {var_x:.4f}  [{took:.0f} s]", flush=True)  # fmt: skip
    print("direction mixing at unit speed: autocorrelation C(t) of v_x^2 / c^2")
    print("\n".join(mixing))
    print(f"k = {k}, flat, alpha {ALPHA}; t_r in periods; shell seed {args.seed}")
    print("   m      E    beta   c_eq  hits/t  measured t_r (95 %)   linear response (95 %)"
          "   ratio   random impacts")  # fmt: skip
    rng = np.random.default_rng([args.spectrum_seed, 7])
    for m, energy, beta in cases:
        t0 = time.perf_counter()
        table = rigid_table("flat", ALPHA, beta)
        c_eq = math.sqrt(2 * energy / (k + 1) / (m / k))
        hits = table.perimeter * c_eq / (math.pi * table.area)
        p = predict_rigid_relaxation("flat", ALPHA, beta, particles=k, mass=m,
                                     container_energy=energy, seed=args.seed)  # fmt: skip
        omega, spec = spectra[beta]
        lr = linear_response_time(omega, spec.mean(axis=0), k, m, energy)
        boot = [linear_response_time(omega, spec[rng.integers(0, len(spec), len(spec))].mean(0),
                                     k, m, energy) for _ in range(RESAMPLES)]  # fmt: skip
        lo, hi = np.quantile(boot, [0.025, 0.975])
        kin = kinetic_relaxation(table, k, m, energy)[1]
        print(f"{m:5.2f} {energy:6.3f} {beta:6.2f} {c_eq:6.2f} {hits:6.2f}  "
              f"{p.rate_time:6.0f} ({p.rate_low:.0f}-{p.rate_high:.0f}){' ':>6}"
              f"{lr:6.0f} ({lo:.0f}-{hi:.0f}){' ':>6}{lr / p.rate_time:6.2f}   {kin:.3f}"
              f"  [{time.perf_counter() - t0:.0f} s]", flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
