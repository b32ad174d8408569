"""Cost and accuracy of the chaos indicators against the plain ensemble, in one run.

Usage::

    python benchmarks/bench_chaos.py [--quick] [--png FILE]

1. lambda_1 of one k = 1 orbit (Fig. 8 well: flat, alpha = 1/2, beta = 0.3, n = 4, m = 0.2,
   E0 = 0.5) over 1000 periods (issue 12 target: < 1 s), next to the plain run of the same
   orbit; accuracy: agreement with the two-trajectory estimate (shadow orbit at 1e-9,
   renormalised every period) along the same orbit, and the energy audit.
2. The full spectrum (2 x 11 exponents) for k = 5 over 1500 periods for 25 runs, next to
   ``simulate`` of the same ensemble (target: < 3x); also lambda_1 alone and the half
   spectrum (11 vectors, the rest by the symplectic pairing).  Accuracy: the
   largest |lambda_i + lambda_(2D+1-i)| (0 for a symplectic flow), the two zero exponents,
   both against 1/t, and the energy audit.

All timings are wall times after a warm-up (compilation excluded), best of ``--repeat``;
the machine's load is printed with them.  ``--quick`` runs a tenth of the periods.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

from sinktheory import RunSettings, Sink, Well
from sinktheory.chaos import chaos, two_orbit_exponent
from sinktheory.chaos.sink import start_positions
from sinktheory.ensemble import engine_name, engine_params, split_values, start_state
from sinktheory.simulate import simulate

WELL = Well(0.5, 0.3, 4)


def best(f, repeat):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return min(times), out


def part1(periods: int, repeat: int) -> None:
    sink = Sink(WELL, particles=1, mass=0.2)
    st = RunSettings(runs=1, periods=periods, seed=0)
    chaos(sink, RunSettings(runs=1, periods=1), progress=False)  # warm-up
    simulate(sink, RunSettings(runs=1, periods=1), progress=False)
    t_l1, res = best(lambda: chaos(sink, st, progress=False), repeat)
    t_sim, sim = best(lambda: simulate(sink, st, progress=False), repeat)
    q, v = split_values(start_state(sink, st.container_energy, start_positions(sink, st)))
    p = res.parameters
    t_two, logs = best(
        lambda: two_orbit_exponent(
            engine_name(sink),
            q,
            v,
            engine_params(sink),
            dt=p["dt"],
            steps=p["steps_per_segment"],
            segments=periods,
            seed=0,
        ),
        1,
    )
    two = logs[0, -1] / res.duration
    print(f"\n1. lambda_1, one k = 1 orbit, {periods} periods ({p['steps_per_segment']} steps/T)")
    print(f"   {'':34s}{'wall s':>9s}{'x plain':>9s}")
    print(f"   {'plain orbit (simulate)':34s}{t_sim:9.3f}{1.0:9.2f}")
    print(f"   {'lambda_1 (tangent map)':34s}{t_l1:9.3f}{t_l1 / t_sim:9.2f}   target < 1 s")
    print(f"   {'two-orbit estimate (reference)':34s}{t_two:9.3f}{t_two / t_sim:9.2f}")
    print(
        f"   lambda_1 = {res.lambda1[0]:.8f} (tangent), {two:.8f} (two orbits): relative "
        f"difference {abs(res.lambda1[0] / two - 1):.1e}; energy error "
        f"{res.run_errors.max():.1e} (simulate: {sim.max_relative_energy_error:.1e})"
    )


def part2(periods: int, repeat: int, png: str | None) -> None:
    sink = Sink(WELL, particles=5, mass=0.2)
    st = RunSettings(runs=25, periods=periods, seed=0)
    warm = RunSettings(runs=25, periods=1)
    simulate(sink, warm, progress=False)
    chaos(sink, warm, spectrum=True, progress=False)
    t_sim, sim = best(lambda: simulate(sink, st, progress=False), repeat)
    t_l1, l1 = best(lambda: chaos(sink, st, progress=False), repeat)
    t_sp, sp = best(lambda: chaos(sink, st, spectrum=True, progress=False), 1)
    t_half, half = best(lambda: chaos(sink, st, spectrum="half", progress=False), 1)
    t = sp.duration
    s = sp.spectrum
    D = s.shape[1] // 2
    print(f"\n2. k = 5, 25 runs x {periods} periods ({sp.parameters['steps_per_segment']} steps/T)")
    print(f"   {'':34s}{'wall s':>9s}{'x plain':>9s}")
    print(f"   {'plain ensemble (simulate)':34s}{t_sim:9.2f}{1.0:9.2f}")
    print(f"   {'lambda_1 (1 vector)':34s}{t_l1:9.2f}{t_l1 / t_sim:9.2f}")
    print(f"   {'full spectrum (22 vectors, QR)':34s}{t_sp:9.2f}{t_sp / t_sim:9.2f}   target < 3x")
    print(f"   {'half spectrum (11 vectors, paired)':34s}{t_half:9.2f}{t_half / t_sim:9.2f}")
    print(
        "   half vs full: top half bitwise equal: "
        f"{np.array_equal(half.spectrum[:, :D], s[:, :D])}; largest difference of the paired "
        f"lower half {np.abs(half.spectrum - s).max():.1e}"
    )
    m, se = sp.mean("spectrum")
    print(
        "   spectrum (mean +- s.e.): "
        + ", ".join(f"{a:.4f}+-{b:.1g}" for a, b in zip(m, se, strict=True))
    )
    print(
        f"   largest |lambda_i + lambda_(2D+1-i)| = {np.abs(sp.pair_sums).max():.1e}, "
        f"zero exponents |lambda_D|, |lambda_D+1| <= {np.abs(s[:, D - 1 : D + 1]).max():.1e} "
        f"(1/t = {1 / t:.1e}); lambda_1 = {m[0]:.4f}; energy error {sp.run_errors.max():.1e} "
        f"(simulate: {sim.max_relative_energy_error:.1e})"
    )
    if png:
        from sinktheory.plot.chaos import plot_convergence

        plot_convergence(sp, png, title="flat, alpha=0.5, beta=0.3, n=4, k=5, m=0.2; 25 runs")
        print(f"   convergence plot: {png}")


def main(argv=None) -> int:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="a tenth of the periods")
    parser.add_argument("--repeat", type=int, default=2, help="best of this many (default 2)")
    parser.add_argument("--png", help="convergence plot of the k = 5 spectrum")
    args = parser.parse_args(argv)
    f = 10 if args.quick else 1
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} core(s)")
    part1(1000 // f, args.repeat)
    part2(1500 // f, args.repeat, args.png)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
