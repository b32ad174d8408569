"""Accuracy against cost for x'' + x^(2n-1) = 0 over one period: four ways to get x(t).

Paths, each evaluating x(t) at N = 2001 equally spaced times over one period (A0 = 1):

* series U_i, orders 1 ... 6 (sinktheory.series; coefficient build timed separately),
* exact float (sinktheory.oscillator.exact_solution: betaincinv + Newton polish),
* exact mp at 30 digits (exact_solution_mp; timed on 40 points, scaled to N),
* ODE: scipy solve_ivp DOP853 at rtol = atol = 1e-13 and 1e-8 (dense t_eval).

Error = max |x - x_ref| / A0 with x_ref the exact float path (accurate to ~1e-15); the
float and mp30 paths themselves are measured against a 50-digit mp run on 40 points.
The series is compared on its own period (shape error; its period error is printed
separately).  Timings are the best of 3 and noisy when other work shares the machine.

Usage: python benchmarks/bench_series.py [OUT.png]   (default ./bench_series.png)
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from scipy.integrate import solve_ivp

from sinktheory.oscillator import exact_solution, exact_solution_mp, period, triangle_wave
from sinktheory.series import error_table, triangle_series

sys.path.insert(0, str(Path(__file__).parent))
from machine import best_of, describe  # noqa: E402

N_VALUES = (2, 3, 5, 10, 20, 50)
ORDERS = range(1, 7)
POINTS = 2001
MP_POINTS = 40


def measure(n: int) -> tuple[list[dict], float]:
    t_n = float(period(n, amplitude=1, dps=20))
    ts = np.linspace(0.0, t_n, POINTS)
    rows = []

    dt, ref = best_of(lambda: exact_solution(ts, n, 1.0, start="zero"))
    sub = ts[:: POINTS // MP_POINTS][:MP_POINTS]
    dt_mp, x_mp = best_of(
        lambda: [exact_solution_mp(float(t), n, 1.0, start="zero", dps=30) for t in sub], 1
    )
    x_50 = [exact_solution_mp(float(t), n, 1.0, start="zero", dps=50) for t in sub]
    float_err = float(np.max(np.abs(exact_solution(sub, n, 1.0, start="zero") - np.array(x_50))))
    mp_err = float(max(abs(a - b) for a, b in zip(x_mp, x_50, strict=True)))
    rows.append({"path": "exact float", "error": float_err, "time": dt})
    rows.append({"path": "exact mp30", "error": mp_err, "time": dt_mp * POINTS / len(sub)})

    build, series = best_of(lambda: triangle_series(n, max(ORDERS)))
    table = error_table(n, max(ORDERS), samples=POINTS)
    tau = triangle_wave(ts / t_n)
    for i in ORDERS:
        dt_i, u = best_of(lambda i=i: series.shape(tau, i))
        rows.append(
            {
                "path": f"series i={i}",
                "error": float(np.max(np.abs(u - ref))),
                "time": dt_i,
                "period_error": table[i - 1].period_relative_error,
            }
        )

    def rhs(_, y):
        return [y[1], -(y[0] ** (2 * n - 1))]

    y0 = [0.0, 1.0 / np.sqrt(n)]  # x(0) = 0, x'(0) = sqrt(2E) = A0^n / sqrt(n)
    for tol in (1e-13, 1e-8):
        # large n: trial steps of the step-size controller can overflow x^(2n-1); they are
        # rejected by the controller, so the warnings are silenced (the result is checked).
        with np.errstate(over="ignore", invalid="ignore"):
            dt_ode, sol = best_of(
                lambda tol=tol: solve_ivp(
                    rhs, (0.0, t_n), y0, "DOP853", t_eval=ts, rtol=tol, atol=tol
                )
            )
        if not sol.success:
            raise RuntimeError(f"solve_ivp failed for n = {n}, tol = {tol}: {sol.message}")
        rows.append(
            {
                "path": f"ODE DOP853 {tol:.0e}",
                "error": float(np.max(np.abs(sol.y[0] - ref))),
                "time": dt_ode,
            }
        )
    return rows, build


def main(argv: list[str]) -> None:
    out = argv[1] if len(argv) > 1 else "bench_series.png"
    results = {}
    print(describe())
    print(f"x'' + x^(2n-1) = 0, A0 = 1, one period, N = {POINTS} points; time = best of 3")
    print(f"{'n':>3} {'path':<20} {'max error/A0':>13} {'time [ms]':>10} {'T_i/T_n - 1':>12}")
    for n in N_VALUES:
        rows, build = measure(n)
        results[n] = rows
        for r in rows:
            pe = f"{r['period_error']:+.2e}" if "period_error" in r else ""
            print(f"{n:>3} {r['path']:<20} {r['error']:>13.2e} {1e3 * r['time']:>10.3f} {pe:>12}")
        print(f"{n:>3} {'(series build)':<20} {'':>13} {1e3 * build:>10.3f}")

    fig = Figure(figsize=(13, 8), layout="constrained")
    axes = fig.subplots(2, 3).ravel()
    for ax, n in zip(axes, N_VALUES, strict=True):
        rows = results[n]
        ser = [r for r in rows if r["path"].startswith("series")]
        ax.loglog([r["time"] for r in ser], [r["error"] for r in ser], "o-", label="series $U_i$")
        for r in (ser[0], ser[-1]):  # label the first and last order
            ax.annotate(
                f"$i = {r['path'][-1]}$",
                (r["time"], r["error"]),
                fontsize=8,
                textcoords="offset points",
                xytext=(6, 0),
            )
        for r, m in zip(
            [r for r in rows if not r["path"].startswith("series")], "s^Dv", strict=True
        ):
            ax.loglog(r["time"], max(r["error"], 1e-40), m, ms=8, label=r["path"])
        ax.set_title(f"$n = {n}$")
        ax.set_xlabel(f"time for {POINTS} points [s]")
        ax.set_ylabel(r"max $|x - x_\mathrm{exact}| / A_0$")
        ax.grid(True, which="major", alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(r"$\ddot x + x^{2n-1} = 0$ over one period: accuracy against cost")
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv)
