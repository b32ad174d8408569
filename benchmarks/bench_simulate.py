"""Work-precision benchmark of the full-dynamics simulator against scipy (and heyoka).

Usage::

    python benchmarks/bench_simulate.py [--quick] [PNG]

Two workloads: the Fig. 8 ensemble (flat, alpha = 1/2, beta = 0.3, gamma = 1, n = 4, k = 5,
m = 0.2, 25 runs x 1500 periods) and a stiffer one (same with n = 10).  For each of our
splitting schemes across step sizes, scipy's solve_ivp (DOP853, LSODA) across tolerances
and heyoka (only when installed) it measures

* the error of the final state after ``SHORT`` period(s) of one run, started from a state of
  the energised regime (after ``WARM`` periods), against a tight reference (suzuki-umeno8 at
  1/8 of its default step, cross-checked with DOP853 at rtol 1e-13), and
* the largest relative total-energy error over a sweep horizon, sampled every period;

and the wall time, scaled linearly to the full workload (fixed-step cost is exactly linear in
runs x periods; the scaling factor is printed).  scipy's RHS is
:func:`sinktheory.simulate.first_order_rhs` (the generated kernel called from Python, as a
user would write it); it is timed on one run over a short horizon started from the
energised state and scaled.  Its energy
error is that of the short horizon: its drift grows with time, so the comparison favours
scipy.  Finally the default method is run on the real full workload (no scaling) and its wall
time and audited energy error are printed next to scipy's scaled time at equal energy error.

Timings: each point is the best of ``REPEAT`` runs, as wall time and as CPU time of this
process (all threads).  On a shared machine the wall time depends on the other load, the CPU
time hardly does; on an idle 2-core machine our wall time is about CPU / 2 (runs are spread
over both cores), scipy's equals its CPU time (one core).  The plot uses CPU time.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from dataclasses import dataclass

import numba
import numpy as np
from matplotlib.figure import Figure
from scipy.integrate import solve_ivp

from sinktheory import RunSettings, Sink, Well
from sinktheory.errors import NumericalError
from sinktheory.integrators import DEFAULT_SCHEME, SCHEMES
from sinktheory.simulate import (
    PERIOD,
    default_step,
    first_order_rhs,
    simulate,
    total_energy,
)

SHORT = 1  # periods of the final-state comparison (chaos amplifies differences ~100x/period)
WARM = 100  # periods of the default method before the scipy and final-state comparisons
REPEAT = 2
FACTORS = (2.0, 1.0, 0.5)  # step / default step of each scheme


@dataclass
class Point:
    solver: str
    setting: str
    time_full: float  # wall seconds, scaled to the full workload
    cpu_full: float  # CPU seconds of this process (all threads), scaled likewise
    state_error: float
    energy_error: float


def _best_time(fn, repeat=REPEAT):
    """Best wall and CPU time of ``repeat`` calls (a single call when it takes over 5 s).

    CPU time (time.process_time, summed over our threads) hardly depends on other load on
    a shared machine, wall time does.
    """
    wall, cpu, out = math.inf, math.inf, None
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        out = fn()
        wall = min(wall, time.perf_counter() - t)
        cpu = min(cpu, time.process_time() - c)
        if wall > 5:
            break
    return wall, cpu, out


def _reference(sink: Sink, z0: np.ndarray) -> np.ndarray:
    dt, _ = default_step(sink, float(total_energy(sink, z0[None])[0]), "suzuki-umeno8")
    ref = _ours_short(sink, z0, "suzuki-umeno8", dt / 8)
    with np.errstate(all="ignore"):
        dop = solve_ivp(
            first_order_rhs(sink), (0, SHORT * PERIOD), z0, method="DOP853", rtol=1e-13, atol=1e-15
        ).y[:, -1]
    print(f"  reference check: |SU8(dt/8) - DOP853(rtol 1e-13)| = {np.abs(ref - dop).max():.1e}")
    return ref


def _ours_short(sink, z0, method, dt):
    from sinktheory.simulate import SimulationState

    state = SimulationState(z0[None].copy(), 0.0, total_energy(sink, z0[None]), dt, method)
    res = simulate(
        sink,
        RunSettings(runs=1, periods=SHORT),
        method=method,
        dt=dt,
        initial_state=state,
        record=("final",),
        energy_bound=1.0,
        progress=False,
    )
    return res.final_state.values[0]


def sweep_ours(sink, sweep: RunSettings, full: RunSettings, z0, ref) -> list[Point]:
    points = []
    scale = (full.runs * full.periods) / (sweep.runs * sweep.periods)
    for name in SCHEMES:
        dt0, _ = default_step(sink, 0.5 + 1e-9, name)
        for f in FACTORS:
            try:
                seconds, cpu, res = _best_time(
                    lambda name=name, dt=f * dt0: simulate(
                        sink, sweep, method=name, dt=dt, energy_bound=1.0, progress=False
                    )
                )
                state_err = np.abs(_ours_short(sink, z0, name, f * dt0) - ref).max()
                energy_err = res.max_relative_energy_error
            except NumericalError:
                seconds, cpu, state_err, energy_err = math.nan, math.nan, math.inf, math.inf
            points.append(
                Point(
                    name,
                    f"dt={f:g}x default",
                    seconds * scale,
                    cpu * scale,
                    state_err,
                    energy_err,
                )
            )
    return points


def sweep_scipy(sink, full: RunSettings, horizon: int, z0, ref, quick: bool) -> list[Point]:
    points = []
    f = first_order_rhs(sink)
    scale = full.runs * full.periods / horizon
    tols = {"DOP853": (1e-6, 1e-8, 1e-10, 1e-12), "LSODA": (1e-6, 1e-8, 1e-10)}
    if quick:
        tols = {"DOP853": (1e-8, 1e-11), "LSODA": (1e-8,)}
    times = PERIOD * np.arange(horizon + 1)
    for method, rtols in tols.items():
        for rtol in rtols:
            atol = rtol * 1e-2

            def run(method=method, rtol=rtol, atol=atol):
                return solve_ivp(
                    f, (0, times[-1]), z0, method=method, rtol=rtol, atol=atol, t_eval=times
                )

            with np.errstate(all="ignore"):  # rejected trial steps may overflow x^(2n-1)
                seconds, cpu, sol = _best_time(run, repeat=1)
            H = total_energy(sink, sol.y.T)
            energy_err = float(np.max(np.abs(H / H[0] - 1)))
            with np.errstate(all="ignore"):
                short = solve_ivp(f, (0, SHORT * PERIOD), z0, method=method, rtol=rtol, atol=atol)
            state_err = float(np.abs(short.y[:, -1] - ref).max())
            points.append(
                Point(
                    f"scipy {method}",
                    f"rtol={rtol:g}",
                    seconds * scale,
                    cpu * scale,
                    state_err,
                    energy_err,
                )
            )
    return points


def sweep_heyoka() -> list[Point]:
    try:
        import heyoka  # noqa: F401
    except ImportError:
        print("  heyoka not installed: skipped")
        return []
    print("  heyoka is installed but no driver is written for it yet: skipped")
    return []


def table(points: list[Point]) -> None:
    print(
        f"  {'solver':16s} {'setting':18s} {'wall (full, s)':>15s} {'CPU (full, s)':>14s} "
        f"{'state err':>10s} {'energy err':>10s}"
    )
    for p in points:
        print(
            f"  {p.solver:16s} {p.setting:18s} {p.time_full:15.3g} {p.cpu_full:14.3g} "
            f"{p.state_error:10.2e} {p.energy_error:10.2e}"
        )


def headline(sink, full: RunSettings, points: list[Point], factor: float = 1.0) -> dict:
    """The default method at ``factor`` x its default step on the real full workload vs
    scipy DOP853 at equal energy error."""
    threads = numba.get_num_threads()
    dt = factor * default_step(sink, 0.5 + 1e-9)[0]
    wall, cpu, res = _best_time(
        lambda: simulate(sink, full, dt=dt, progress=False, energy_bound=1e-4),
        repeat=1 if full.periods > 500 else REPEAT,
    )
    err = res.max_relative_energy_error
    print(
        f"  {res.method} at {factor:g} x default step on the full workload ({full.runs} runs x "
        f"{full.periods} periods, dt = {res.dt:.3g}, {threads} threads), measured, not "
        f"scaled: wall {wall:.1f} s, CPU {cpu:.1f} s (on an otherwise idle machine wall ~ "
        f"CPU/{threads} = {cpu / threads:.1f} s); max relative energy error {err:.2e}"
    )
    dop = [p for p in points if p.solver == "scipy DOP853"]
    ok = [p for p in dop if p.energy_error <= err]
    note = "scipy: one run over a short horizon, scaled to the full workload; single-threaded"
    if ok:
        fastest = min(ok, key=lambda p: p.cpu_full)
        print(
            f"  scipy DOP853 at energy error <= {err:.1e} ({fastest.setting}): wall "
            f"{fastest.time_full:.3g} s, CPU {fastest.cpu_full:.3g} s ({note}) -> speed-up "
            f"{fastest.time_full / wall:.0f}x in wall time, {fastest.cpu_full / cpu:.0f}x in CPU"
        )
    else:
        best = min(dop, key=lambda p: p.energy_error)
        print(
            f"  scipy DOP853 never reached energy error {err:.1e} (best {best.energy_error:.1e} "
            f"at {best.setting}: wall {best.time_full:.3g} s, CPU {best.cpu_full:.3g} s; {note})"
            f" -> speed-up > {best.time_full / wall:.0f}x in wall time, "
            f"> {best.cpu_full / cpu:.0f}x in CPU"
        )
    return {"time": cpu, "error": err}


def plot(results: dict, path: str) -> None:
    fig = Figure(figsize=(12, 9), layout="constrained")
    axes = fig.subplots(len(results), 2, squeeze=False)
    for row, (label, (points, head)) in enumerate(results.items()):
        for col, (attr, name) in enumerate(
            [
                ("state_error", f"final-state error after {SHORT} T"),
                ("energy_error", "max |H/H0 - 1|"),
            ]
        ):
            ax = axes[row, col]
            for solver in dict.fromkeys(p.solver for p in points):
                pts = [p for p in points if p.solver == solver and math.isfinite(getattr(p, attr))]
                if pts:
                    ax.loglog(
                        [p.cpu_full for p in pts],
                        [max(getattr(p, attr), 1e-17) for p in pts],
                        "o-" if solver.startswith("scipy") else "s-",
                        label=solver,
                    )
            if col == 1:
                ax.loglog(
                    [head["time"]], [head["error"]], "k*", ms=14, label="default, measured full run"
                )
            ax.set_xlabel("CPU time for the full workload (s)")
            ax.set_ylabel(name)
            ax.set_title(label)
            ax.grid(alpha=0.3, which="both")
            ax.legend(fontsize=8)
    fig.savefig(path, dpi=110)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("png", nargs="?", default="bench_simulate.png")
    parser.add_argument("--quick", action="store_true", help="short horizons (a smoke test)")
    args = parser.parse_args(argv)
    full = RunSettings(runs=25, periods=1500, seed=0)
    sweep = RunSettings(runs=5, periods=150, seed=0)
    scipy_horizon = 20  # long enough to include some of scipy's secular energy drift
    if args.quick:
        full = RunSettings(runs=4, periods=100, seed=0)
        sweep = RunSettings(runs=2, periods=20, seed=0)
        scipy_horizon = 1
    workloads = {
        "Fig. 8: flat, beta=0.3, n=4, k=5": Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2),
        "stiff: flat, beta=0.3, n=10, k=5": Sink(Well(0.5, 0.3, 10), particles=5, mass=0.2),
    }
    ours_scale = full.runs * full.periods / (sweep.runs * sweep.periods)
    scipy_scale = full.runs * full.periods / scipy_horizon
    print(
        f"Full workload: {full.runs} runs x {full.periods} periods.  Our sweep: {sweep.runs} "
        f"runs x {sweep.periods} periods, times scaled x{ours_scale:g}.  scipy: 1 run x "
        f"{scipy_horizon} period(s) from an energised state, times scaled x{scipy_scale:g}."
    )
    simulate(
        workloads[next(iter(workloads))], RunSettings(runs=1, periods=1), progress=False
    )  # compile
    results = {}
    for label, sink in workloads.items():
        print(f"\n== {label} (default method {DEFAULT_SCHEME})")
        # a state from the energised regime (after WARM periods), where the particles are
        # fast and the walls are hit hard: the first periods are unrepresentatively easy
        z0 = simulate(
            sink, RunSettings(runs=1, periods=WARM, seed=0), record=("final",), progress=False
        ).final_state.values[0]
        ref = _reference(sink, z0)
        points = sweep_ours(sink, sweep, full, z0, ref)
        points += sweep_scipy(sink, full, scipy_horizon, z0, ref, args.quick)
        points += sweep_heyoka()
        table(points)
        head = headline(sink, full, points)
        # the default step is set by the k = 1 cases and the short sweep suggests k = 5
        # tolerates twice the step; the full workload shows whether rare hard wall
        # encounters over 25 x 1500 periods agree (measured: they do not, 6e-7 and 3e-6)
        headline(sink, full, points, factor=2.0)
        results[label] = (points, head)
    plot(results, args.png)
    print(f"\nwrote {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
