"""Is the container energy Markov?  Implied timescales of E_c against the lag, alone and
with a second variable, for Fig. 8's well.

Usage::

    python benchmarks/bench_markov.py [--quick] [--seeds 2] [--particles 1 5]

1. Runs started on the shell at 16 Gauss-grid energies x 100 runs (measure_kramers_moyal,
   tol 1e-6, seeds 0 .. seeds - 1), raw increments at lags 4 ... 128 periods:
   * the slowest implied timescale -tau / ln |lambda_2| of the transition matrix between
     the energies' cells (a Markov state model in E_c; for a Markov process it does not
     depend on the lag);
   * the same for the linear observable: ln lambda(tau) = ln(1 + b), b the slope of the
     conditional mean increment against the starting energy (what predict_relaxation
     fits), and -tau / ln lambda;
   * the one-slow-mode reading ITS(tau) = t_r tau / (tau + t_r ln(1 / c)) with t_r, c
     fitted to ln lambda over lags 32 ... 128.
2. k = 1 from the shell's stationary measure (E_c drawn from the law, the rest from the
   shell given it): 600 runs x 256 periods, the state 16 times a period.  Implied
   timescales of E_c alone (6 and 18 cells of equal law mass) and of (E_c, Y) with Y the
   particles' transverse share of kinetic energy sum ydot^2 / sum (udot^2 + ydot^2)
   averaged over the period (6 x 2 and 6 x 3 cells): if Y carried the slow mode's hidden
   part, the 2-D timescales would stop growing with the lag.  Transitions are counted
   from every period of every run and symmetrised (the dynamics is reversible in E_c).

3. Second variables from the paper's start (k = 3, m = 0.2, beta = 0.3 and 0.1, 64 runs
   x 3000 periods, seed 21, the step of tol 1e-6; the particles' energies once a period,
   the state 4 times a period): the means given E_c, in bins of E_c, over windows of
   time, of the energy split's unevenness Q = sum_j (e_j / sum e)^2 (1 / k for an even
   split, 1 when one particle holds all) and of the transverse share Y of part 2.  If
   either carried the slow part of the approach, its mean given E_c would keep moving for
   as long as <E_c> does.

``--quick``: 40 runs, one seed, k = 1, 150 runs in part 2, 16 runs x 1000 periods in
part 3.
"""

from __future__ import annotations

import argparse
import math
import sys
import time

import numpy as np

from sinktheory.canonical import FIG8_WELL
from sinktheory.ensemble import SimulationState, total_energy
from sinktheory.equilibrium import equilibrium_law, measure_kramers_moyal, shell_states
from sinktheory.equilibrium.prediction import log_lambdas, slow_mode
from sinktheory.layout import StateLayout
from sinktheory.model import RunSettings, Sink
from sinktheory.simulate import simulate

LAGS = (4, 8, 16, 32, 64, 128)
ENERGY = 0.5


def slowest(transitions: np.ndarray) -> float:
    """|lambda_2| of a row-stochastic matrix."""
    return float(np.sort(np.abs(np.linalg.eigvals(transitions)))[::-1][1])


def shell_part(k: int, runs: int, seed: int) -> None:
    sink = Sink(FIG8_WELL, particles=k, mass=0.2)
    t0 = time.perf_counter()
    km = measure_kramers_moyal(sink, ENERGY, points=16, lags=LAGS, runs=runs, seed=seed)
    s = km.container_energies / ENERGY
    edges = np.r_[0.0, (s[1:] + s[:-1]) / 2, 1.0]
    its = []
    for j, lag in enumerate(km.lags):
        end = np.clip(s[:, None] + km.increments[:, j] / ENERGY, 0, 1)
        cell = np.clip(np.searchsorted(edges, end, side="right") - 1, 0, s.size - 1)
        t = np.array([np.bincount(row, minlength=s.size) / row.size for row in cell])
        its.append(-lag / math.log(slowest(t)))
    inc = km.increments / ENERGY
    se = np.maximum(inc.std(axis=2, ddof=1), 1e-12) / math.sqrt(runs)
    ll = log_lambdas(s, inc, se)
    t_r, c = slow_mode(km.lags[3:], ll[3:], np.ones(3))  # lags 32, 64, 128
    reading = [t_r * lag / (lag + t_r * math.log(1 / c)) for lag in km.lags]
    print(f"  k = {k}, seed {seed} [{time.perf_counter() - t0:.0f} s]: lag "
          + " ".join(f"{x:>5d}" for x in km.lags))  # fmt: skip
    print("    cells' implied timescale      " + " ".join(f"{x:5.0f}" for x in its))
    linear = (f"{-t / x:5.0f}" for t, x in zip(km.lags, ll, strict=True))
    print("    linear: -tau / ln lambda      " + " ".join(linear))
    print(
        f"    one slow mode t_r = {t_r:.0f}, c = {c:.2f}:  "
        + " ".join(f"{x:5.0f}" for x in reading)
    )


def quantile_cells(x: np.ndarray, m: int) -> np.ndarray:
    return np.searchsorted(np.quantile(x, np.linspace(0, 1, m + 1)[1:-1]), x)


def stationary_its(states: np.ndarray, count: int, lags) -> list[float]:
    out = []
    for lag in lags:
        a, b = states[:, :-lag].ravel(), states[:, lag:].ravel()
        c = np.zeros((count, count))
        np.add.at(c, (a, b), 1)
        c = c + c.T
        out.append(-lag / math.log(slowest(c / c.sum(axis=1, keepdims=True))))
    return out


def second_variable(runs: int, periods: int, seed: int) -> None:
    sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    law = equilibrium_law(sink, ENERGY)
    rng = np.random.default_rng(seed)
    ecs = np.minimum(law.quantile(rng.uniform(0, 1, runs)) * ENERGY, ENERGY * (1 - 1e-9))
    rows = np.concatenate([shell_states(sink, ENERGY, x, 1, rng) for x in ecs])
    state = SimulationState(rows, 0.0, total_energy(sink, rows), 0.0, "")
    t0 = time.perf_counter()
    probe = simulate(sink, RunSettings(runs=1, periods=1), tol=1e-6, progress=False)
    sub = max(1, probe.steps_per_period // 16)
    per = probe.steps_per_period // sub
    res = simulate(sink, RunSettings(runs=runs, periods=periods, seed=seed), tol=1e-6,
                   progress=False, initial_state=state, record=("container", "trajectory"),
                   stride=sub)  # fmt: skip
    L = StateLayout(1)
    tr = res.trajectory
    n = min(periods, (tr.shape[1] - 1) // per)
    ky = (tr[:, 1 : 1 + n * per, L.ydot] ** 2).sum(-1).reshape(runs, n, per).mean(-1)
    kx = (tr[:, 1 : 1 + n * per, L.udot] ** 2).sum(-1).reshape(runs, n, per).mean(-1)
    share = ky / (kx + ky)
    s = res.container_energy[:, :n] / ENERGY
    lags = [x for x in LAGS if x < n // 2]
    print(f"\n2. k = 1, {runs} runs x {periods} periods from the stationary measure "
          f"[{time.perf_counter() - t0:.0f} s]; {res.message}")  # fmt: skip
    print("  lag                         " + " ".join(f"{x:>5d}" for x in lags))
    for m in (6, 18):
        its = stationary_its(quantile_cells(s, m), m, lags)
        print(f"  E_c, {m:2d} cells               " + " ".join(f"{x:5.0f}" for x in its))
    for m in (2, 3):
        cells = quantile_cells(s, 6) * m + quantile_cells(share, m)
        its = stationary_its(cells, 6 * m, lags)
        print(f"  (E_c, Y), 6 x {m} cells        " + " ".join(f"{x:5.0f}" for x in its))


def given_ec(label: str, values: np.ndarray, ec: np.ndarray, periods: int) -> None:
    """Print the mean of ``values`` (runs, periods) given E_c in five bins, per window."""
    edges = np.linspace(0.0, 0.5, 6)
    print(f"  {label}: periods  <E_c>  "
          + " ".join(f"  E_c {a:.1f}-{b:.1f}  " for a, b in
                     zip(edges[:-1], edges[1:], strict=True)))  # fmt: skip
    cuts = [1, 50, 200, 500, 1000, 2000, 3000, periods]
    for a, b in zip(cuts[:-1], cuts[1:], strict=True):
        if a >= periods:
            break
        cells = []
        for lo, hi in zip(edges[:-1], edges[1:], strict=True):
            inside = (ec[:, a:b] >= lo) & (ec[:, a:b] < hi)
            n = int(inside.sum())
            cells.append(f"{values[:, a:b][inside].mean():.3f} ({n:6d})" if n > 50 else " " * 14)
        print(f"    {a:5d}-{b - 1:<5d}  {ec[:, a:b].mean():.3f}  " + "  ".join(cells))


def energy_split(runs: int, periods: int, seed: int, beta: float) -> None:
    """Part 3: the means of Q and Y given E_c over windows of time from the paper's start."""
    from sinktheory.layout import StateLayout
    from sinktheory.model import RunSettings, Sink, Well
    from sinktheory.simulate import simulate

    t0 = time.perf_counter()
    sink = Sink(Well(0.5, beta, 4), particles=3, mass=0.2)
    settings = RunSettings(container_energy=0.5, runs=runs, periods=periods, seed=seed)
    probe = simulate(sink, RunSettings(container_energy=0.5, runs=1, periods=1, seed=seed),
                     tol=1e-6, progress=False)  # fmt: skip
    steps = round(2 * math.pi / probe.dt)  # the step of tol 1e-6, 4 samples a period
    r = simulate(sink, settings, dt=probe.dt, stride=steps // 4, progress=False,
                 record=("container", "particles", "trajectory"))  # fmt: skip
    parts, ec = np.asarray(r.particle_energy)[:, :periods], np.asarray(r.container_energy)
    held = parts.sum(axis=2)
    q = ((parts / np.where(held > 0, held, 1.0)[..., None]) ** 2).sum(axis=2)
    lay, tr = StateLayout(3), np.asarray(r.trajectory)
    ydot2 = (tr[..., lay.ydot] ** 2).sum(axis=-1)
    share = ydot2 / np.maximum(ydot2 + (tr[..., lay.udot] ** 2).sum(axis=-1), 1e-300)
    per = (tr.shape[1] - 1) / periods
    y = np.stack([share[:, round(j * per) : round((j + 1) * per)].mean(axis=1)
                  for j in range(periods)], axis=1)  # fmt: skip
    print(f"\n3. k = 3, beta = {beta:g}, {runs} runs x {periods} periods from rest (seed "
          f"{seed}) [{time.perf_counter() - t0:.0f} s]: means given E_c (samples)")  # fmt: skip
    given_ec("Q, at the period's start", q, ec, periods)
    given_ec("Y, over the period", y, ec, periods)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--seeds", type=int, default=2)
    parser.add_argument("--particles", type=int, nargs="+", default=[1, 5])
    args = parser.parse_args()
    runs, part2, part3 = 100, (600, 256), (64, 3000)
    if args.quick:
        runs, part2, part3, args.seeds, args.particles = 40, (150, 128), (16, 1000), 1, [1]
    sys.path.insert(0, __file__.rsplit("/", 1)[0])
    from machine import describe

    print(describe())
    print("1. implied timescales (periods) of E_c from runs started on the shell")
    for k in args.particles:
        for seed in range(args.seeds):
            shell_part(k, runs, seed)
    second_variable(*part2, seed=0)
    for beta in (0.3, 0.1):
        energy_split(*part3, seed=21, beta=beta)


if __name__ == "__main__":
    main()
