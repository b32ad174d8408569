"""Draw the README's hero figure, docs/hero.png: the energy sink in one picture.

    python docs/make_hero.py [--out docs/hero.png] [--runs 16] [--periods 300]

Left: the container energy <E>(t) of a small ensemble (five particles in the symmetric
well of the paper's Fig. 12) falling from E0 = 0.5 to the equipartition level
E / (1 + k (1 + 1/n)), with the spread of the runs.  Right: level lines of the well, the
bold one at E0.  Takes a few seconds; the PNG is committed (keep it under ~150 KB).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import sinktheory as st
from sinktheory.runstats import ensemble_mean
from sinktheory.simulate import simulate
from sinktheory.sinkstats import equipartition_container_energy

ALPHA, BETA, N, K, MASS, E0, SEED = 1.0, 0.1, 6, 5, 0.2, 0.5, 2016


def hero(runs: int, periods: int) -> Figure:
    well = st.Well(alpha=ALPHA, beta=BETA, n=N, shape="symmetric")
    sink = st.Sink(well, particles=K, mass=MASS)
    res = simulate(
        sink,
        st.RunSettings(container_energy=E0, runs=runs, periods=periods, seed=SEED),
        progress=False,
    )
    e = res.container_energy  # (runs, periods + 1): E(jT)
    mean, stderr = ensemble_mean(e)
    level = equipartition_container_energy(float(res.initial_energy.mean()), K, N)
    t = np.arange(mean.size)

    fig = Figure(figsize=(8.0, 3.0), dpi=100, layout="constrained")
    ax, ax_w = fig.subplots(1, 2, width_ratios=(2.1, 1))
    for run in e[:5]:
        ax.plot(t, run, color="#9ab", lw=0.4, alpha=0.6)
    ax.fill_between(t, mean - 2 * stderr, mean + 2 * stderr, color="#f4a261", alpha=0.35, lw=0)
    ax.plot(t, mean, color="#d1495b", lw=1.6, label=rf"$\langle E\rangle$ over {runs} runs")
    ax.axhline(level, color="k", ls="--", lw=1.0, label=f"equipartition level {level:.3f}")
    ax.set_xlim(0, t[-1])
    ax.set_ylim(0, 1.05 * E0)
    ax.set_xlabel("time $t/T$ (container periods)")
    ax.set_ylabel("container energy $E$")
    ax.set_title(
        f"no damping, yet the container's energy drains into {K} light particles",
        fontsize=9.5,
    )
    ax.legend(loc="upper right", fontsize=8, frameon=False)

    x_max, y_max = well.reach(E0)
    half = 1.1 * max(x_max, y_max)
    xs = np.linspace(-half, half, 241)
    X, Y = np.meshgrid(xs, xs)
    V = np.minimum(well.potential(X, Y), 2 * E0)
    levels = E0 * np.array([0, 1e-3, 1e-2, 0.05, 0.15, 0.35, 0.65, 1.0])
    ax_w.contourf(X, Y, V, levels=levels, cmap="Blues_r")
    ax_w.contour(X, Y, V, levels=levels[1:-1], colors="white", linewidths=0.5)
    ax_w.contour(X, Y, V, levels=[E0], colors="k", linewidths=1.6)
    ax_w.set_aspect("equal")
    ax_w.set_xticks([-1, 0, 1])
    ax_w.set_yticks([-1, 0, 1])
    ax_w.set_xlabel("$x$")
    ax_w.set_ylabel("$y$")
    ax_w.set_title(f"the well $V(x, y)$: $n$ = {N}, $\\beta$ = {BETA}", fontsize=9.5)
    return fig


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(Path(__file__).with_name("hero.png")))
    parser.add_argument("--runs", type=int, default=16)
    parser.add_argument("--periods", type=int, default=300)
    args = parser.parse_args()
    fig = hero(args.runs, args.periods)
    fig.savefig(args.out)
    print(f"{args.out}: {Path(args.out).stat().st_size / 1024:.0f} KB")


if __name__ == "__main__":
    main()
