"""Kramers-Moyal coefficients of the container energy for Fig. 8's well, and the
fluctuation-dissipation (stationarity) check against the exact law and wrong laws.

Usage::

    python benchmarks/bench_kramers.py [--quick] [--runs 200] [--points 12] [--seeds 3]
                                       [--particles 1 2 5] [--plot kramers.png]

For each k (flat, alpha 0.5, beta 0.3, n 4, m 0.2, E = 0.5), ``--points`` starting
energies (Gauss grid in w = (1 - E_c/E)^(1/4)) x ``--runs`` runs from the shell
(sinktheory.equilibrium.measure_kramers_moyal, tol 1e-6), lags 1 ... 64 periods:

1. the raw moments <Delta E> and <Delta E^2> against the lag at three energies: a fast
   part reached within one period (a plateau up to ~8 periods), then slow growth;
2. the slow coefficients from the moments' growth after tau_0 = 8 periods (base lag):
   D1 and D2 at lags 32 and 64 on the grid, with standard errors over runs;
3. the stationarity check (chi^2 with M Legendre test functions; M = 2 is exact at any
   lag, M >= 3 also needs jumps small enough for a second-order expansion; "exact" uses
   the runs' own increments of f, M = 6, and needs no expansion) against the law, the
   homogeneous (beta = 0) law, and the laws of k - 1 and k + 1 particles, for
   the raw lag 1 and for the base-lag coefficients at lag 64, over ``--seeds`` seeds;
4. k = 1 at ten times the runs (lag 1): whether the check separates the exact law from
   the homogeneous one (4 % apart in mean);
5. k = 1 from the paper's start (E0 = 0.5, particles at rest): <E_c>(t), its spread and
   the 5 % settling time from the Fokker-Planck equation with the measured coefficients
   (base 8 at lags 32 and 64, and the raw lag 8 with its fast part left in), one
   measurement per seed, against 128 runs x 2000 periods (measure_relaxation).

``--quick``: 40 runs, one seed, k = 1 (shows only that it runs).
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from sinktheory import RunSettings, Sink, Well
from sinktheory.equilibrium import (
    check_fluctuation_dissipation,
    equilibrium_law,
    measure_kramers_moyal,
    measure_relaxation,
)
from sinktheory.equilibrium.kramers import solve_fokker_planck
from sinktheory.simulate import simulate

FIG8 = Well(0.5, 0.3, 4)
HOMOGENEOUS = Well(0.5, 0.0, 4)
LAGS = (1, 2, 4, 8, 16, 32, 64)
ENERGY = 0.5


def laws(k: int) -> dict:
    out = {"law": equilibrium_law(Sink(FIG8, k, 0.2), ENERGY)}
    out["beta=0"] = equilibrium_law(Sink(HOMOGENEOUS, k, 0.2), ENERGY)
    if k > 1:
        out[f"k={k - 1}"] = equilibrium_law(Sink(FIG8, k - 1, 0.2), ENERGY)
    out[f"k={k + 1}"] = equilibrium_law(Sink(FIG8, k + 1, 0.2), ENERGY)
    return out


def check_table(km, k: int, lag: int, label: str) -> None:
    for tests in (2, 3, 4):
        cells = []
        for name, law in laws(k).items():
            f = check_fluctuation_dissipation(km, law, lag=lag, tests=tests)
            cells.append(f"{name} {f.p_value:8.2g}")
        print(f"  {label} M={tests}: " + "  ".join(cells))
    cells = []
    for name, law in laws(k).items():
        f = check_fluctuation_dissipation(km, law, lag=lag, tests=6, exact=True)
        cells.append(f"{name} {f.p_value:8.2g}")
    print(f"  {label} M=6 exact: " + "  ".join(cells))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--runs", type=int, default=200)
    parser.add_argument("--points", type=int, default=12)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--particles", type=int, nargs="+", default=[1, 2, 5])
    parser.add_argument("--plot", default=None)
    args = parser.parse_args()
    if args.quick:
        args.runs, args.seeds, args.particles = 40, 1, [1]
    import sys

    sys.path.insert(0, __file__.rsplit("/", 1)[0])
    from machine import describe

    print(describe())
    keep = {}
    for k in args.particles:
        sink = Sink(FIG8, k, 0.2)
        law = equilibrium_law(sink, ENERGY)
        print(f"\nk = {k}: law mean {law.mean:.5f} (beta = 0 law {law.homogeneous_mean:.5f})")
        for seed in range(args.seeds):
            start = time.perf_counter()
            raw = measure_kramers_moyal(
                sink, ENERGY, points=args.points, lags=LAGS, runs=args.runs, seed=seed
            )
            wall = time.perf_counter() - start
            slow = measure_kramers_moyal(
                sink, ENERGY, points=args.points, lags=LAGS, runs=args.runs, seed=seed,
                base_lag=8,
            )  # fmt: skip
            print(f" seed {seed}: {raw.message} [{wall:.1f} s]")
            if seed == 0:
                keep[k] = slow
                print("  1. raw moments: E_c | <dE> at lags " + str(LAGS) + " | <dE^2>")
                for i in (1, args.points // 2, args.points - 1):
                    m1 = raw.drift[i] * raw.lags
                    m2 = 2 * raw.diffusion[i] * raw.lags
                    print(f"   {raw.container_energies[i]:.4f} | "
                          + " ".join(f"{x:+.4f}" for x in m1) + " | "
                          + " ".join(f"{x:.4f}" for x in m2))  # fmt: skip
                print("  2. slow coefficients (base lag 8): E_c | D1 x 1e3 at lag 32, 64 "
                      "| D2 x 1e4 at lag 32, 64")  # fmt: skip
                for i, ec in enumerate(slow.container_energies):
                    j32, j64 = slow.lag_index(32), slow.lag_index(64)
                    d1 = [f"{1e3 * slow.drift[i, j]:+6.3f} ± {1e3 * slow.drift_stderr[i, j]:.3f}"
                          for j in (j32, j64)]  # fmt: skip
                    d2 = [f"{1e4 * slow.diffusion[i, j]:6.3f} ± "
                          f"{1e4 * slow.diffusion_stderr[i, j]:.3f}"
                          for j in (j32, j64)]  # fmt: skip
                    print(f"   {ec:.4f} | " + "  ".join(d1) + " | " + "  ".join(d2))
            print("  3. stationarity check, p-values:")
            check_table(raw, k, 1, "raw lag 1      ")
            check_table(slow, k, 64, "base 8, lag 64 ")
    if 1 in args.particles and not args.quick:
        sink = Sink(FIG8, 1, 0.2)
        km = measure_kramers_moyal(sink, ENERGY, points=args.points, lags=(1,),
                                   runs=10 * args.runs, seed=100)  # fmt: skip
        print(f"\n4. k = 1, {10 * args.runs} runs per point, lag 1:")
        check_table(km, 1, 1, "raw lag 1      ")
    if 1 in args.particles:
        fokker_planck(args)
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(1, 2, figsize=(10, 4))
        for k, km in keep.items():
            j = km.lag_index(64)
            axes[0].errorbar(km.container_energies, km.drift[:, j], km.drift_stderr[:, j],
                             fmt="o-", label=f"k = {k}")  # fmt: skip
            axes[1].errorbar(km.container_energies, km.diffusion[:, j],
                             km.diffusion_stderr[:, j], fmt="o-", label=f"k = {k}")  # fmt: skip
        axes[0].set_ylabel("D1 (energy / period)")
        axes[1].set_ylabel("D2 (energy^2 / period)")
        for ax in axes:
            ax.set_xlabel("E_c")
            ax.axhline(0, color="grey", lw=0.5)
            ax.legend()
        fig.suptitle("Fig. 8 well, E = 0.5: slow coefficients (base lag 8, lag 64 periods)")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print(f"wrote {args.plot}")


def settle(mean: np.ndarray, target: float, fraction: float = 0.05):
    inside = np.abs(mean - target) < fraction * target
    return int(np.argmax(inside)) if inside.any() else None


def fokker_planck(args) -> None:
    sink = Sink(FIG8, 1, 0.2)
    runs, periods = (16, 600) if args.quick else (128, 2000)
    start = time.perf_counter()
    sim = simulate(sink, RunSettings(runs=runs, periods=periods, seed=1), tol=1e-6,
                   progress=False)  # fmt: skip
    law = equilibrium_law(sink, float(sim.initial_energy.mean()))
    r = measure_relaxation(sim.container_energy, law.mean, resamples=199)
    ens = sim.container_energy
    mean, sd, se = ens.mean(0), ens.std(0, ddof=1), ens.std(0, ddof=1) / np.sqrt(runs)
    s = np.linspace(0, 1, 4001)
    law_sd = float(
        np.sqrt(np.sum((s * law.total_energy - law.mean) ** 2 * law.pdf(s)) / law.pdf(s).sum())
    )
    wall = time.perf_counter() - start
    print(f"\n5. k = 1 from the paper's start: {runs} runs x {periods} periods [{wall:.1f} s]; "
          f"law mean {law.mean:.4f}, sd {law_sd:.4f}")  # fmt: skip
    print(f"  simulated: settles at {r.settle_time:.0f} ({r.settle_low:.0f}-{r.settle_high:.0f}), "
          f"tail tau {r.rate_time:.0f} ± {r.rate_stderr:.0f}")  # fmt: skip
    times = [t for t in (10, 50, 100, 200, 400, 800, 1500, 2000) if t <= periods]
    print("  model                  settles  " + "  ".join(f"t={t:<5d}" for t in times)
          + "  sd at end")  # fmt: skip
    print("  simulated              " + f"{r.settle_time:7.0f}  "
          + "  ".join(f"{mean[t]:.3f}±{se[t]:.3f}"[:13].ljust(7) for t in times)
          + f"  {sd[-1]:.3f}")  # fmt: skip
    for seed in range(args.seeds):
        raw = measure_kramers_moyal(sink, 0.5, points=args.points, lags=(8,), runs=args.runs,
                                    seed=seed)  # fmt: skip
        slow = measure_kramers_moyal(sink, 0.5, points=args.points, lags=(32, 64),
                                     runs=args.runs, seed=seed, base_lag=8)  # fmt: skip
        for label, km, lag in (("base 8, lag 32", slow, 32), ("base 8, lag 64", slow, 64),
                               ("raw lag 8", raw, 8)):  # fmt: skip
            j = km.lag_index(lag)
            m, d = solve_fokker_planck(0.5, km.container_energies, km.drift[:, j],
                                       km.diffusion[:, j], 0.5, periods)  # fmt: skip
            t_f = settle(m, law.mean)
            print(f"  seed {seed} {label:15s} " + (f"{t_f:7d}" if t_f is not None else "  never")
                  + "  " + "  ".join(f"{m[t]:.3f}".ljust(13) for t in times)
                  + f"  {d[-1]:.3f}")  # fmt: skip


if __name__ == "__main__":
    main()
