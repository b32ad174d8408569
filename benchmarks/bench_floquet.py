"""Benchmark of the Floquet chart: accuracy against cost for every path, and n from 2 to 200.

Usage:  python benchmarks/bench_floquet.py [OUT.png]     (default ./bench_floquet.png)

1. The target: phi_half at 1000 beta values for alpha = 1/2, n = 10 (Fig. 7), the full
   scan with brentq-located boundaries, and the error against the 30-digit mpmath
   reference at sample points.
2. Accuracy against cost of each path on that chart: the compiled DOP853 quarter-period
   integration at several tolerances, scipy solve_ivp (DOP853, the alternative a user
   would pick; timed on a subset and scaled to 1000 points), the mpmath reference.
3. The compiled path for n = 2 ... 200 (stiffer walls), pure equation, Lam in [-1, 3].

Errors are max |phi_half - reference| / max(1, |reference|).  Timings are wall-clock on
a shared machine (best of 3) and therefore noisy.
"""

from __future__ import annotations

import sys
import time

import mpmath
import numpy as np
from matplotlib.figure import Figure

from sinktheory._generated.shapes import bundle
from sinktheory.floquet import model_problem, pure_problem, scan
from sinktheory.hill import monodromy_solve_ivp, quarter_period_mpmath

ALPHA, N, COUNT = 0.5, 10, 1000
FLAT = bundle("flat")
BETAS = np.linspace(-1.0, 0.499, COUNT)
SAMPLE = BETAS[:: COUNT // 5]  # 5 reference points across the chart


def best_of(fn, repeat=3):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def mp_phi(n, lam):
    y1, dy1, y2, dy2, _ = quarter_period_mpmath(n, lam, dps=30)
    return float(y1 * dy2 + y2 * dy1)


def rel_err(got, ref):
    got, ref = np.asarray(got), np.asarray(ref)
    return float(np.max(np.abs(got - ref) / np.maximum(1.0, np.abs(ref))))


def main(png: str) -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    print(f"Floquet chart benchmark: alpha = {ALPHA}, n = {N}, {COUNT} beta values in [-1, 0.499]")
    t0 = time.perf_counter()
    refs = np.array([mp_phi(N, FLAT.hill_lambda(ALPHA, b)) for b in SAMPLE])
    t_mp = (time.perf_counter() - t0) / len(SAMPLE)
    idx = [int(np.argmin(np.abs(BETAS - b))) for b in SAMPLE]

    problem = model_problem(ALPHA, N)
    problem.evaluate(BETAS[:2])  # compile / load the numba cache
    t_chart, chart = best_of(lambda: problem.evaluate(BETAS))
    t_scan, result = best_of(lambda: scan(problem, -1.0, 0.499, COUNT))
    err = rel_err(chart.phi_half[idx], refs)
    print(f"\n1. target ({COUNT} points, default rtol 1e-13)")
    print(f"   chart phi_half         {t_chart * 1e3:8.1f} ms   max rel. error {err:.1e}")
    print(
        f"   scan + {len(result.boundaries)} boundaries + {len(result.resonances)} resonance "
        f"{t_scan * 1e3:8.1f} ms   (goal < 2000 ms)"
    )
    print(f"   stable intervals {result.stable_intervals}")

    print("\n2. accuracy against cost, same chart (time for 1000 points)")
    print(f"   {'path':34s} {'time [s]':>10s} {'max rel. error':>15s}")
    rows = []
    for rtol in (1e-6, 1e-8, 1e-10, 1e-12, 1e-13, 1e-14):
        p = model_problem(ALPHA, N, rtol=rtol)
        t, c = best_of(lambda p=p: p.evaluate(BETAS))
        rows.append((f"compiled DOP853 rtol={rtol:.0e}", t, rel_err(c.phi_half[idx], refs)))
    for rtol in (1e-10, 1e-13):
        t0 = time.perf_counter()
        vals = [
            np.trace(
                monodromy_solve_ivp(N, b, coefficient=FLAT.hill_coefficient, alpha=ALPHA, rtol=rtol)
            )
            / 2
            for b in SAMPLE
        ]
        t = (time.perf_counter() - t0) / len(SAMPLE) * COUNT
        rows.append((f"solve_ivp DOP853 rtol={rtol:.0e} (scaled)", t, rel_err(vals, refs)))
    # the reference's own error: 30 digits against 45 digits at one point
    lam0 = FLAT.hill_lambda(ALPHA, SAMPLE[1])
    with mpmath.workdps(45):  # the products themselves at 45 digits
        y1, dy1, y2, dy2, _ = quarter_period_mpmath(N, lam0, dps=45)
        hi = y1 * dy2 + y2 * dy1
        y1, dy1, y2, dy2, _ = quarter_period_mpmath(N, lam0, dps=30)
        mp_err = float(abs(y1 * dy2 + y2 * dy1 - hi))
    rows.append(("mpmath odefun 30 digits (scaled)", t_mp * COUNT, max(mp_err, 1e-30)))
    for name, t, e in rows:
        print(f"   {name:34s} {t:10.3g} {e:15.1e}")

    print("\n3. compiled path against n (pure equation, 1000 Lam in [-1, 3], rtol 1e-13)")
    print(f"   {'n':>4s} {'steps':>6s} {'time [ms]':>10s} {'max rel. error':>15s}  (vs mpmath)")
    lams = np.linspace(-1.0, 3.0, COUNT)
    nrows = []
    for n in (2, 5, 10, 20, 50, 100, 200):
        p = pure_problem(n)
        t, c = best_of(lambda p=p: p.evaluate(lams))
        pick = [100, 700]
        e = rel_err(c.phi_half[pick], [mp_phi(n, lams[i]) for i in pick])
        nrows.append((n, c.quarter.steps, t, e))
        print(f"   {n:4d} {c.quarter.steps:6d} {t * 1e3:10.1f} {e:15.1e}")

    fig = Figure(figsize=(11, 4.5), layout="constrained")
    ax = fig.add_subplot(1, 2, 1)
    for name, t, e in rows:
        ax.loglog(t, e, "o")
        ax.annotate(name, (t, e), fontsize=7, xytext=(4, 2), textcoords="offset points")
    ax.axvline(2.0, color="tab:red", ls="--", lw=0.8, label="goal 2 s")
    ax.set_xlabel("time for 1000 points [s]")
    ax.set_ylabel(r"max $|\Delta\phi_{T/2}| / \max(1, |\phi_{T/2}|)$")
    ax.set_title(rf"Fig. 7 chart, $\alpha$ = {ALPHA}, n = {N}", fontsize=10)
    ax.legend(fontsize=8)
    ax = fig.add_subplot(1, 2, 2)
    ns = [r[0] for r in nrows]
    ax.semilogx(ns, [r[2] * 1e3 for r in nrows], "o-", label="time, 1000 points [ms]")
    ax.semilogx(ns, [r[1] for r in nrows], "s--", label="accepted steps")
    ax.set_xlabel("$n$")
    ax.set_ylabel("ms / steps")
    ax2 = ax.twinx()
    ax2.loglog(ns, [max(r[3], 1e-17) for r in nrows], "^:", color="tab:red", label="error")
    ax2.set_ylabel("max relative error", color="tab:red")
    ax.legend(fontsize=8, loc="upper left")
    ax.set_title(r"compiled path against $n$ (pure, $\Lambda \in [-1, 3]$)", fontsize=10)
    fig.savefig(png, dpi=120)
    print(f"\nwrote {png}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "bench_floquet.png")
