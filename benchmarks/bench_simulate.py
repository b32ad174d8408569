"""Work-precision and scaling benchmark of the ensemble engine, against heyoka, plain C and
scipy, all measured in one run.

Usage::

    python benchmarks/bench_simulate.py [--quick] [--png FILE] [--baseline REV]

Workloads: the Fig. 8 ensemble (flat, alpha = 1/2, beta = 0.3, gamma = 1, n = 4, k = 5,
m = 0.2, 25 runs x 1500 periods, E0 = 0.5) and the stiffer n = 10 variant.  Accuracy is the
largest relative total-energy error |H/H0 - 1| over all runs, sampled every period (the
quantity ``simulate`` audits).  Contenders, each across its accuracy knob:

* ours: ``simulate(tol=...)`` (scheme and step picked by the calibration of
  :mod:`sinktheory.stepsize`), and every scheme forced at the same tolerances;
* heyoka (``pip install ".[bench]"``): Taylor integrator, ``ensemble_propagate_grid`` over the
  runs (its own thread pool), across tolerances, on the same equations (converted from the
  symbolic model with ``heyoka.from_sympy``);
* plain C: the same splitting scheme and step as ours, forces printed from the same symbolic
  model with SymPy's C printer, one run at a time per OpenMP thread, compiled here with
  ``cc -O3 -march=native -fopenmp`` (no fast-math) -- what a careful user would write by hand;
* scipy ``solve_ivp`` (DOP853) on :func:`sinktheory.simulate.first_order_rhs`: one run over a
  short horizon, timed and scaled to the workload (it is far too slow to run whole).

Wall times are for the whole workload on this machine (2 cores); scaled entries say so.  A
second part measures the per-run cost of ensembles of 1 to 4096 runs (5 periods) for ours and
the C reference, and with ``--baseline REV`` for the engine of an earlier commit (checked
out into a temporary git worktree and run in a subprocess).  A PNG with the work-precision
charts and the scaling chart is written.
"""

from __future__ import annotations

import argparse
import ctypes
import math
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.printing.c import C99CodePrinter

sys.path.insert(0, str(Path(__file__).parent))
from baseline import run_at  # noqa: E402
from machine import describe  # noqa: E402

from sinktheory import RunSettings, Sink, Well  # noqa: E402
from sinktheory import symbolic as S
from sinktheory.codegen import chain
from sinktheory.engine.systems import sink_system
from sinktheory.ensemble import random_positions, start_state, total_energy
from sinktheory.errors import NumericalError
from sinktheory.integrators import SCHEMES, get_scheme
from sinktheory.simulate import PERIOD, first_order_rhs, simulate
from sinktheory.stepsize import choose

TOLS = (1e-6, 1e-8, 1e-10)
HEYOKA_TOLS = (1e-8, 1e-10, 1e-12, 1e-14)
SCIPY_RTOLS = (1e-8, 1e-10, 1e-12)


@dataclass
class Point:
    solver: str
    setting: str
    wall: float  # seconds for the whole workload (measured or scaled, see ``scaled``)
    error: float  # largest relative total-energy error
    scaled: float = 1.0  # factor applied to a shorter measurement


def _timed(fn):
    t = time.perf_counter()
    out = fn()
    return time.perf_counter() - t, out


def _warm(sink) -> None:
    """Load (or compile) the sink's engine before any timing, as the other contenders'
    set-up is also left out of their times."""
    simulate(sink, RunSettings(runs=1, periods=1), progress=False)


# --------------------------------------------------------------------------- ours
def ours(sink, full: RunSettings, sweep: RunSettings | None) -> tuple[list[Point], Point]:
    """Each scheme at each tolerance on ``sweep`` (scaled; skipped when None), and the
    automatic choice on the whole workload at tol 1e-8 (measured, not scaled)."""
    _warm(sink)
    points = []
    scale = full.runs * full.periods / (sweep.runs * sweep.periods) if sweep else 1.0
    for tol in TOLS if sweep else ():
        for method in SCHEMES:
            if method == "verlet" and tol < 1e-6:
                continue  # millions of steps per period
            try:
                wall, res = _timed(
                    lambda m=method, t=tol: simulate(
                        sink, sweep, scheme=m, tol=t, energy_bound=1.0, progress=False
                    )
                )
            except NumericalError:
                continue
            points.append(Point(method, f"tol={tol:g}", wall * scale, res.run_errors.max(), scale))
    wall, res = _timed(lambda: simulate(sink, full, tol=1e-8, progress=False))
    head = Point(f"ours auto ({res.scheme})", "tol=1e-8", wall, res.max_relative_energy_error)
    return points, head


# --------------------------------------------------------------------------- heyoka
def _sympy_accelerations(sink):
    """(coordinates, velocities, accelerations) of the sink as SymPy expressions."""
    sh = S.separable_hamiltonian(sink.particles, sink.well.shape)
    w = sink.well
    values = {S.alpha: w.alpha, S.beta: w.beta, S.gamma: w.gamma, S.mu: sink.mu, S.n: w.n}
    U = sh.potential.subs(values)
    masses = [m.subs(values) for m in sh.masses]
    acc = [-sp.diff(U, q) / m for q, m in zip(sh.coordinates, masses, strict=True)]
    return sh.coordinates, acc


def heyoka_points(sink, full: RunSettings, periods: int) -> list[Point]:
    try:
        import heyoka as hy
    except ImportError:
        print("  heyoka not installed (pip install '.[bench]'): skipped")
        return []
    coords, acc = _sympy_accelerations(sink)
    D = len(coords)
    qs = hy.make_vars(*[f"q{i}" for i in range(D)])
    vs = hy.make_vars(*[f"v{i}" for i in range(D)])
    table = dict(zip(coords, qs, strict=True))
    sys_ = [(q, v) for q, v in zip(qs, vs, strict=True)]
    sys_ += [(v, hy.from_sympy(a, s_dict=table)) for v, a in zip(vs, acc, strict=True)]
    values = start_state(sink, 0.5, random_positions(full, sink.particles))
    k = sink.particles
    q0 = np.concatenate([values[:, :1], values[:, 2 : 2 + 2 * k]], axis=1)
    v0 = np.concatenate([values[:, 1:2], values[:, 2 + 2 * k :]], axis=1)
    h0 = total_energy(sink, values)
    grid = PERIOD * np.arange(periods + 1)
    points = []
    for tol in HEYOKA_TOLS:
        ta = hy.taylor_adaptive(sys_, np.zeros(2 * D), tol=tol)

        def gen(ta_copy, i):
            ta_copy.time = 0.0
            ta_copy.state[:] = np.concatenate([q0[i], v0[i]])
            return ta_copy

        wall, out = _timed(
            lambda ta=ta, gen=gen: hy.ensemble_propagate_grid(ta, grid, full.runs, gen)
        )
        outcomes = sorted({str(res[1]).split(".")[-1] for res in out})
        if outcomes != ["time_limit"]:
            print(f"  heyoka tol={tol:g}: propagation outcomes {outcomes}")
        worst = 0.0
        for i, res in enumerate(out):
            states = res[-1]
            rows = np.concatenate(
                [states[:, :1], states[:, D : D + 1], states[:, 1:D], states[:, D + 1 :]], axis=1
            )
            worst = max(worst, float(np.max(np.abs(total_energy(sink, rows) / h0[i] - 1))))
        scale = full.periods / periods
        points.append(Point("heyoka", f"tol={tol:g}", wall * scale, worst, scale))
    return points


# --------------------------------------------------------------------------- plain C
class _CPrinter(C99CodePrinter):
    def _print_Pow(self, expr):
        if expr.exp.is_Integer and abs(int(expr.exp)) >= 2:
            text = chain(self.parenthesize(expr.base, 1000), abs(int(expr.exp)))
            return f"(1.0/{text})" if expr.exp < 0 else text
        return super()._print_Pow(expr)


_C_TEMPLATE = """
#include <math.h>
static void accel(int K, const double *q, double *a, const double *P) {
    const double alpha = P[0], beta = P[1], gamma = P[2], mu = P[3];
    const double X = q[0];
    a[0] = -X;
    for (int j = 0; j < K; ++j) {
        const double x = q[1 + j] - X, y = q[1 + K + j];
        ATOMS
        FORCES
    }
}
static double energy(int K, const double *q, const double *v, const double *P) {
    const double alpha = P[0], beta = P[1], gamma = P[2], mu = P[3];
    const double X = q[0];
    double H = 0.5 * v[0] * v[0] + 0.5 * X * X;
    for (int j = 0; j < K; ++j) {
        const double x = q[1 + j] - X, y = q[1 + K + j];
        ATOMS
        H += 0.5 * mu * (v[1 + j] * v[1 + j] + v[1 + K + j] * v[1 + K + j]) + POTENTIAL;
    }
    return H;
}
void run(int R, int K, double *Q, double *V, int periods, int steps, int S,
         const double *A, const double *Bw, double dt, const double *P, double *worst) {
    const int D = 1 + 2 * K;
    #pragma omp parallel for schedule(dynamic, 1)
    for (int r = 0; r < R; ++r) {
        double q[64], v[64], a[64];
        for (int i = 0; i < D; ++i) { q[i] = Q[r * D + i]; v[i] = V[r * D + i]; }
        const double h0 = energy(K, q, v, P);
        double w = 0.0;
        accel(K, q, a, P);
        for (int p = 0; p < periods; ++p) {
            for (int s = 0; s < steps; ++s) {
                for (int st = 0; st < S; ++st) {
                    const double cb = Bw[st] * dt, ca = A[st] * dt;
                    for (int i = 0; i < D; ++i) v[i] += cb * a[i];
                    for (int i = 0; i < D; ++i) q[i] += ca * v[i];
                    accel(K, q, a, P);
                }
                const double cb = Bw[S] * dt;
                for (int i = 0; i < D; ++i) v[i] += cb * a[i];
            }
            const double e = fabs(energy(K, q, v, P) / h0 - 1.0);
            if (!(e <= w)) w = e;
        }
        worst[r] = w;
        for (int i = 0; i < D; ++i) { Q[r * D + i] = q[i]; V[r * D + i] = v[i]; }
    }
}
"""


def _c_source(sink) -> str:
    term = sink_system(sink.well.shape).member_terms[0]  # n fixed in the C text, as by hand
    pr = _CPrinter()
    n = {S.n: sink.well.n}
    atoms = " ".join(f"const double {a.name} = {pr.doprint(e.subs(n))};" for a, e in term.atoms)
    gx, gy = (g.subs(n) for g in term.gradient)
    forces = (
        f"const double gx = {pr.doprint(gx)}, gy = {pr.doprint(gy)};"
        " a[0] += gx; a[1 + j] = -gx / mu; a[1 + K + j] = -gy / mu;"
    )
    return (
        _C_TEMPLATE.replace("ATOMS", atoms)
        .replace("FORCES", forces)
        .replace("POTENTIAL", pr.doprint(term.value.subs(n)))
    )


def c_reference(sink):
    """The compiled C ``run`` function, or None without a C compiler."""
    cc = shutil.which(os.environ.get("CC", "cc")) or shutil.which("gcc")
    if cc is None:
        print("  no C compiler: C reference skipped")
        return None
    folder = Path(tempfile.mkdtemp(prefix="sinktheory-cref-"))
    src, lib = folder / "ref.c", folder / "ref.so"
    src.write_text(_c_source(sink))
    subprocess.run(
        [cc, "-O3", "-march=native", "-fopenmp", "-shared", "-fPIC", str(src), "-o", str(lib)],
        check=True,
    )
    fn = ctypes.CDLL(str(lib)).run
    dp = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")
    fn.argtypes = [ctypes.c_int, ctypes.c_int, dp, dp, ctypes.c_int, ctypes.c_int, ctypes.c_int]
    fn.argtypes += [dp, dp, ctypes.c_double, dp, dp]
    return fn


def c_run(fn, sink, settings: RunSettings, method: str, dt: float, steps: int):
    values = start_state(
        sink, settings.container_energy, random_positions(settings, sink.particles)
    )
    k = sink.particles
    Q = np.ascontiguousarray(np.concatenate([values[:, :1], values[:, 2 : 2 + 2 * k]], 1))
    V = np.ascontiguousarray(np.concatenate([values[:, 1:2], values[:, 2 + 2 * k :]], 1))
    a, b = get_scheme(method).arrays()
    P = np.array([sink.well.alpha, sink.well.beta, sink.well.gamma, sink.mu])
    worst = np.zeros(settings.runs)
    wall, _ = _timed(
        lambda: fn(settings.runs, k, Q, V, settings.periods, steps, len(a), a, b, dt, P, worst)
    )
    return wall, float(worst.max())


# --------------------------------------------------------------------------- scipy
def scipy_points(sink, full: RunSettings, horizon: int) -> list[Point]:
    f = first_order_rhs(sink)
    z0 = start_state(sink, 0.5, random_positions(RunSettings(runs=1, seed=0), sink.particles))[0]
    times = PERIOD * np.arange(horizon + 1)
    points = []
    for rtol in SCIPY_RTOLS:
        with np.errstate(all="ignore"):
            wall, sol = _timed(
                lambda r=rtol: solve_ivp(
                    f, (0, times[-1]), z0, method="DOP853", rtol=r, atol=r * 1e-2, t_eval=times
                )
            )
        H = total_energy(sink, sol.y.T)
        scale = full.runs * full.periods / horizon
        err = float(np.max(np.abs(H / H[0] - 1)))
        points.append(Point("scipy DOP853", f"rtol={rtol:g}", wall * scale, err, scale))
    return points


# --------------------------------------------------------------------------- scaling
def scaling(sink, counts, periods: int, cfn, baseline: str | None) -> dict[str, list[float]]:
    choice = choose(sink, 0.5, 1e-8)
    _warm(sink)
    out: dict[str, list[float]] = {"ours": [], "C": [], "baseline": []}
    for R in counts:
        st = RunSettings(runs=R, periods=periods, seed=2)
        wall, _ = _timed(
            lambda st=st: simulate(sink, st, dt=choice.dt, scheme=choice.scheme, progress=False)
        )
        out["ours"].append(wall / R)
        if cfn is not None:
            out["C"].append(
                c_run(cfn, sink, st, choice.scheme, choice.dt, choice.steps_per_period)[0] / R
            )
        if baseline:
            out["baseline"].append(_baseline_time(baseline, R, periods, choice) / R)
        print(
            f"  R = {R:5d}: per run ours {out['ours'][-1] * 1e3:8.2f} ms"
            + (f", C {out['C'][-1] * 1e3:8.2f} ms" if out["C"] else "")
            + (f", {baseline} {out['baseline'][-1] * 1e3:8.2f} ms" if out["baseline"] else ""),
            flush=True,
        )
    return out


def _baseline_time(rev: str, runs: int, periods: int, choice) -> float:
    """Wall time of ``simulate`` at an earlier commit, same workload and step."""
    script = textwrap.dedent(
        f"""
        import time
        from sinktheory import RunSettings, Sink, Well
        from sinktheory.simulate import simulate
        sink = Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2)
        kw = dict(scheme={choice.scheme!r}, dt={choice.dt!r}, progress=False)
        simulate(sink, RunSettings(runs=1, periods=1), **kw)
        t = time.perf_counter()
        simulate(sink, RunSettings(runs={runs}, periods={periods}, seed=2), **kw)
        print(time.perf_counter() - t)
        """
    )
    return float(run_at(rev, script))


# --------------------------------------------------------------------------- report
def at_error(points: list[Point], error: float) -> float:
    """Wall time a contender needs for energy error <= ``error`` (log-log interpolation
    between its two bracketing points; inf if it never gets there)."""
    pts = sorted((p.error, p.wall) for p in points if math.isfinite(p.error))
    ok = [w for e, w in pts if e <= error]
    if not ok:
        return math.inf
    for (e1, w1), (e2, w2) in zip(pts, pts[1:], strict=False):
        if e1 <= error <= e2 and e1 > 0 and e2 > e1:
            t = math.log(error / e1) / math.log(e2 / e1)
            return math.exp(math.log(w1) + t * (math.log(w2) - math.log(w1)))
    return min(ok)


def table(points: list[Point]) -> None:
    print(f"  {'solver':22s} {'setting':12s} {'wall (s)':>10s} {'energy err':>11s}  note")
    for p in points:
        note = f"scaled x{p.scaled:g}" if p.scaled != 1 else "measured"
        print(f"  {p.solver:22s} {p.setting:12s} {p.wall:10.3g} {p.error:11.2e}  {note}")


def plot(results: dict, scale: dict, counts, path: str) -> None:
    from matplotlib.figure import Figure

    fig = Figure(figsize=(15, 4.8), layout="constrained")
    axes = np.atleast_1d(fig.subplots(1, len(results) + 1))
    for ax, (label, (points, head, cpts)) in zip(axes, results.items(), strict=False):
        for solver in dict.fromkeys(p.solver for p in points):
            pts = sorted((p for p in points if p.solver == solver), key=lambda p: p.error)
            ax.loglog([p.wall for p in pts], [max(p.error, 1e-17) for p in pts], "o-", label=solver)
        ax.loglog([head.wall], [head.error], "k*", ms=14, label=head.solver)
        if cpts:
            ax.loglog([cpts.wall], [cpts.error], "rP", ms=11, label="plain C, same scheme/step")
        ax.set_xlabel("wall time for 25 runs x 1500 periods (s)")
        ax.set_ylabel("max |H/H0 - 1|")
        ax.set_title(label, fontsize=10)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    ax = axes[-1]
    for name, values in scale.items():
        if values:
            ax.loglog(counts[: len(values)], np.array(values) * 1e3, "o-", label=name)
    ax.set_xlabel("runs in the ensemble")
    ax.set_ylabel("wall time per run (ms, 5 periods)")
    ax.set_title("per-run cost against ensemble size", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=100)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--png", default="bench_simulate.png")
    parser.add_argument("--quick", action="store_true", help="short horizons (a smoke test)")
    parser.add_argument("--baseline", help="git revision whose engine joins the scaling chart")
    parser.add_argument(
        "--scaling-only", action="store_true", help="only the per-run cost against ensemble size"
    )
    parser.add_argument(
        "--fig8-only",
        action="store_true",
        help="only the Fig. 8 headline: our automatic choice at tol 1e-8 against heyoka, plain "
        "C and DOP853 (no scheme sweep, no stiff workload, no scaling chart)",
    )
    args = parser.parse_args(argv)
    print(describe())
    full = RunSettings(runs=25, periods=1500, seed=0)
    sweep = RunSettings(runs=25, periods=300, seed=0)
    hy_periods, scipy_horizon, counts = 150, 5, [1, 4, 16, 64, 256, 1024, 4096]
    if args.quick:
        full = RunSettings(runs=8, periods=40, seed=0)
        sweep = RunSettings(runs=8, periods=10, seed=0)
        hy_periods, scipy_horizon, counts = 5, 1, [1, 16, 64]
    workloads = {
        "Fig. 8: flat, beta=0.3, n=4, k=5": Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2),
        "stiff: flat, beta=0.3, n=10, k=5": Sink(Well(0.5, 0.3, 10), particles=5, mass=0.2),
    }
    print(f"Workload: {full.runs} runs x {full.periods} periods, E0 = 0.5; {os.cpu_count()} cores")
    results = {}
    if args.fig8_only:
        workloads = dict(list(workloads.items())[:1])
    for label, sink in workloads.items() if not args.scaling_only else ():
        print(f"\n== {label}", flush=True)
        simulate(sink, RunSettings(runs=2, periods=1), progress=False)  # compile once
        points, head = ours(sink, full, None if args.fig8_only else sweep)
        cfn = c_reference(sink)
        cpoint = None
        if cfn is not None:
            choice = choose(sink, 0.5, 1e-8)
            wall, err = c_run(cfn, sink, full, choice.scheme, choice.dt, choice.steps_per_period)
            cpoint = Point(f"plain C ({choice.scheme})", "tol=1e-8", wall, err)
        others = heyoka_points(sink, full, hy_periods) + scipy_points(sink, full, scipy_horizon)
        table(points + others + [p for p in (cpoint, head) if p])
        for name in ("heyoka", "scipy DOP853"):
            t = at_error([p for p in others if p.solver == name], head.error)
            if math.isfinite(t):
                print(
                    f"  {name} at our energy error {head.error:.1e}: {t:.3g} s -> ours "
                    f"{t / head.wall:.1f}x faster"
                )
            elif any(p.solver == name for p in others):
                print(f"  {name} never reached energy error {head.error:.1e}")
        if cpoint:
            print(
                f"  plain C, same scheme and step: {cpoint.wall:.3g} s (energy error "
                f"{cpoint.error:.1e}) -> ours {cpoint.wall / head.wall:.1f}x faster"
            )
        results[label] = (points + others, head, cpoint)
    if args.fig8_only:
        return 0
    print("\n== per-run cost (Fig. 8 system, tol 1e-8 step, 5 periods)", flush=True)
    fig8 = next(iter(workloads.values()))
    scale = scaling(fig8, counts, 5 if not args.quick else 2, c_reference(fig8), args.baseline)
    plot(results, scale, counts, args.png)
    print(f"\nwrote {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
