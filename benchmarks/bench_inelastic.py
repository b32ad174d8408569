"""Speed-up of the engine with contact damping over the NumPy version of the same
splitting, at equal accuracy, in one run.

Usage::

    python benchmarks/bench_inelastic.py [--quick] [--repeat N] [--png FILE]

Workload: the design explorer's (Fig. 8 well: flat, alpha = 1/2, beta = 0.3, n = 4,
m = 0.2, E0 = 0.5; 25 runs; tolerance 1e-6, i.e. the simulator's scheme and step for it)
with contact damping c0 = 0.5, for k = 1, 3, 5 particles.  Both integrators run the same
splitting with the same step from the same start states, so their accuracy is the same
by construction; the table shows it: the largest difference between them (round-off,
grown by the chaotic dynamics), the audit |H + W - H0|/H0 of each, and for one run of
k = 1 over one period the error of both against solve_ivp (DOP853, rtol 1e-12) of the
damped equations.

Timings are wall times after a warm-up (compilation excluded and shown apart), on one
thread; the machine's load average is printed with them.  The NumPy version is timed
over ``P`` = 3 periods (it is slow), the compiled one over the same periods (equal work,
so the fixed per-call set-up -- start states, step choice -- is in both) and over 1500
periods (the design explorer's run), where the set-up no longer matters: the speed-up
per step is the NumPy version's seconds per step x run over the compiled one's in the
long run.  The conservative engine (:func:`sinktheory.simulate.simulate`, same scheme
and step) is timed over the long run too: the ratio is what the contact damping costs a
design point (:data:`sinktheory.design.cost.DISSIPATIVE`).  ``--quick``: one and 150
periods.
"""

from __future__ import annotations

import argparse
import os
import time

import numba
import numpy as np

from sinktheory import RunSettings, Sink, Well
from sinktheory.damped import simulate_inelastic
from sinktheory.design.inelastic_reference import simulate_inelastic_reference, solve_damped_ivp
from sinktheory.simulate import simulate

WELL = Well(0.5, 0.3, 4)
DAMPING = 0.5
TOL = 1e-6


def best(repeat, f, *args, **kw):
    """(shortest wall time of ``repeat`` calls of f(*args, **kw), its result)."""
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = f(*args, **kw)
        times.append(time.perf_counter() - t)
    return min(times), out


def against_solve_ivp() -> tuple[float, float]:
    """|error| of W(T) + |error| of E(T) of both integrators, one run of k = 1, one period,
    against DOP853 (:func:`sinktheory.design.inelastic_reference.solve_damped_ivp`)."""
    sink = Sink(WELL, particles=1, mass=0.2)
    st = RunSettings(runs=1, periods=1, seed=2)
    ec, w, _ = solve_damped_ivp(sink, st, DAMPING, 1)
    out = []
    for f in (simulate_inelastic, simulate_inelastic_reference):
        r = f(sink, st, damping=DAMPING, tol=TOL)
        out.append(abs(r.dissipated[0, -1] - w) + abs(r.container_energy[0, -1] - ec))
    return out[0], out[1]


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--png", default="bench_inelastic.png")
    args = ap.parse_args()
    numba.set_num_threads(1)
    periods = 1 if args.quick else 3
    print(f"load average before: {os.getloadavg()}")
    rows = []
    for k in (1, 3, 5):
        sink = Sink(WELL, particles=k, mass=0.2)
        st = RunSettings(runs=25, periods=periods, seed=0)
        t0 = time.perf_counter()
        simulate_inelastic(sink, RunSettings(runs=2, periods=1), damping=DAMPING, tol=TOL)
        compile_s = time.perf_counter() - t0
        kw = {"damping": DAMPING, "tol": TOL}
        t_fast, fast = best(args.repeat, simulate_inelastic, sink, st, **kw)
        t_slow, slow = best(1, simulate_inelastic_reference, sink, st, **kw)
        long = RunSettings(runs=25, periods=150 if args.quick else 1500, seed=0)
        t_long, res_long = best(1, simulate_inelastic, sink, long, **kw)
        simulate(sink, RunSettings(runs=2, periods=1), tol=TOL, progress=False)  # warm-up
        t_sim, _ = best(1, simulate, sink, long, tol=TOL, progress=False)
        per = 1e6 / (fast.steps_per_period * 25)  # microseconds per step and run, per period
        slow_us, fast_us = t_slow * per / periods, t_fast * per / periods
        long_us, sim_us = t_long * per / long.periods, t_sim * per / long.periods
        diff = float(np.max(np.abs(fast.container_energy - slow.container_energy)))
        rows.append(
            (k, fast.scheme, fast.steps_per_period, compile_s, slow_us, fast_us,
             slow_us / fast_us, long_us, slow_us / long_us, sim_us, long_us / sim_us, diff,
             fast.max_audit_error, slow.max_audit_error, res_long.max_audit_error)
        )  # fmt: skip
    print(f"load average after: {os.getloadavg()}")
    head = ("k", "scheme", "steps/T", "compile s", f"numpy us/step/run ({periods} T)",
            f"numba ({periods} T)", "speed-up equal work", f"numba ({long.periods} T)",
            "speed-up per step", f"simulate ({long.periods} T)", "inelastic/simulate",
            "max |dE| numba-numpy", "audit numba", "audit numpy",
            f"audit {long.periods} T")  # fmt: skip
    print(" | ".join(head))
    for r in rows:
        print(
            f"{r[0]} | {r[1]} | {r[2]} | {r[3]:.1f} | {r[4]:.2f} | {r[5]:.3f} | {r[6]:.0f}x | "
            f"{r[7]:.3f} | {r[8]:.0f}x | {r[9]:.3f} | {r[10]:.2f} | {r[11]:.1e} | {r[12]:.1e} | "
            f"{r[13]:.1e} | {r[14]:.1e}"
        )
    e_fast, e_slow = against_solve_ivp()
    print(
        f"error against solve_ivp (k = 1, one period, |dW| + |dE|): numba {e_fast:.3e}, "
        f"numpy {e_slow:.3e}"
    )
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6, 4), layout="constrained")
    ax = fig.subplots()
    ks = [r[0] for r in rows]
    ax.semilogy(ks, [r[4] for r in rows], "o-", label="NumPy (inelastic_reference)")
    ax.semilogy(ks, [r[7] for r in rows], "s-", label="numba (inelastic), long run")
    ax.semilogy(ks, [r[9] for r in rows], "^--", label="simulate (conservative engine)")
    for r in rows:
        ax.annotate(f"{r[8]:.0f}x", (r[0], r[7]), textcoords="offset points", xytext=(6, 6))
    ax.set_xlabel("particles k")
    ax.set_ylabel("wall time per step and run (µs)")
    ax.set_xticks(ks)
    ax.set_title(f"Inelastic contact, 25 runs, c0 = {DAMPING}, tol {TOL:g}")
    ax.legend()
    fig.savefig(args.png, dpi=110)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
