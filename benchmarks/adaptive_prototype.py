"""Prototype: an adaptive, time-reversible step whose cost grows far more slowly with n.

Exploratory (issue 22 item 5), not used by the package; any registered shape
(``--shape``). The fixed-step engine resolves the wall contact, whose duration shrinks
like 1/n, in every step, so its steps per period grow like n (1197 at n = 4, 37077 at n =
100 for Fig. 8's ensemble at tol 1e-8). Here each run takes plain steps of the same
symmetric splitting (blanes-moan6) in physical time, with its own step h = eps / rho
chosen by an explicit, reversible
controller in the spirit of Hairer & Soederlind (2005, SIAM J. Sci. Comput. 26, 1838):

    rho_{n+1/2} - rho_{n-1/2} = dOmega/dt(y_n) (h_{n+1/2} + h_{n-1/2}) / 2,

solved in closed form for rho_{n+1/2} (symmetric under reversal, since dOmega/dt is odd in
the velocities); rho is set back to Omega at period ends.  The rate Omega(q, v) sums, per
particle: the local frequency |grad V|^2 / (m V) of a power-law wall; the approach to each
wall i of the shape, (v . grad phi_i)^2 / d(w_i)^2 with w_i the wall ratio (1 on the rigid
wall), phi_i = w_i^p / p and d = 1/(2n) at the wall, b (1 - w) inside (a step covers a
fraction of the distance still to go, then of the contact layer); and the crossing rate
C0^2 |v|^2 sum_i |grad r_i|^2.  The wall ratios r_i and their derivatives are derived from
the shape registry (:func:`wall_kernel`); dOmega/dt needs the Hessian of V, which the
engine prints for the tangent map.

What was learnt (25 runs x 40 periods, one thread; the table and chart in
docs/guide/billiard.rst, "Cost against the wall stiffness", come from
``python benchmarks/adaptive_prototype.py --n 4 10 20 50 100 --eps 0.25 0.15 --periods 40
--chart docs/guide/adaptive_cost.png``):

* steps per period at eps = 0.25: 384 (n = 4), 972 (n = 20), 2228 (n = 100), with
  |dH|/H0 <= 1.9e-8 (eps = 0.15: <= 8.7e-10); the fixed step needs 1197, 6970 and 37077.
  The count still grows (about n^0.55): the approach costs ln(1 + 2n)/b steps, and a
  particle pressed against a stiff wall by the container vibrates at a frequency ~ n that
  any soft-wall integrator must resolve;
* a step costs about 3x a fixed one here (hessian + energies every step, unfused kernels
  called through function pointers), so it is faster than the fixed step from n ~ 10 on
  and 6x faster at n = 100 (1.34 against 8.0 ms per run and period); cost(n = 100) /
  cost(n = 4) is about 10 for the prototype, against the issue's target of 2;
* what failed on the way: a rate of the positions alone (Mikkola-Aarseth time-transformed
  leapfrog) must assume a top speed and over-resolves particles resting at a wall (15x
  the steps at n = 20); the total wall ratio (the 2n-norm of all walls) hides a second wall
  approached while the first dominates (energy jumps of 1e-5); without the crossing term a
  fast particle at the centre of a narrow well reaches the wall in one step (NaN at
  n = 100).
"""

from __future__ import annotations

import argparse
import functools
import math
import time

import numba
import numpy as np
from machine import describe

C0 = 1.0  # crossing-rate factor (prototype constant)


def _setup(n: int, runs: int, seed: int, particles: int = 5, shape: str = "flat"):
    from sinktheory import RunSettings, Sink, Well
    from sinktheory.engine.cache import load
    from sinktheory.simulate import (
        engine_name,
        engine_params,
        random_positions,
        split_values,
        start_state,
    )

    sink = Sink(Well(0.5, 0.3, n, shape=shape), particles=particles, mass=0.2)
    settings = RunSettings(runs=runs, periods=1, seed=seed)
    values = start_state(sink, settings.energy, random_positions(settings, sink.particles))
    q, v = split_values(values)
    engine = load(engine_name(sink))
    T = engine.table_of(engine_params(sink), q.shape[1])
    return sink, engine, np.ascontiguousarray(q), np.ascontiguousarray(v), T


# ----------------------------------------------------------------------------------------
# Velocity-aware rate with the explicit reversible step-size controller of Hairer &
# Soederlind (2005, SIAM J. Sci. Comput. 26, 1838): h = eps / rho, rho_{n+1/2} =
# rho_{n-1/2} + eps G(y_n), G = dOmega/dt / Omega, the steps themselves plain symmetric
# splitting steps (any scheme, RKN ones included) in physical time.


@functools.cache
def wall_kernel(shape: str):
    """Compiled (x, y, alpha, beta) -> (r_i, dr_i/dx, dr_i/dy, d2r_i/dx2, d2r_i/dxdy,
    d2r_i/dy2 for each wall ratio r_i of the shape), derived from the symbolic model."""
    import sympy as sp

    from sinktheory import symbolic as S

    x, y = S.x, S.y
    values = []
    for r in S.wall_ratios(shape):
        rx, ry = sp.diff(r, x), sp.diff(r, y)
        values += [r, rx, ry, sp.diff(rx, x), sp.diff(rx, y), sp.diff(ry, y)]
    body = ", ".join(f"float({sp.pycode(e)})" for e in values)  # one type for the tuple
    namespace = {"math": math}
    exec(f"def walls(x, y, alpha, beta):\n    return ({body},)", namespace)
    return numba.njit(namespace["walls"])


@numba.njit(inline="always")
def _approach(w, wx, wy, hxx, hxy, hyy, vx, vy, ax, ay, ell, b, pw):
    """(v . grad phi)^2 / d(w)^2 and its time derivative for a wall ratio w with gradient
    (wx, wy) and Hessian (hxx, hxy, hyy); phi = w^p / p, d = ell at the wall, b (1 - w) inside."""
    wp2 = w ** (pw - 2.0)
    wp1 = wp2 * w
    gv = wx * vx + wy * vy
    u = wp1 * gv
    vHv = vx * (hxx * vx + hxy * vy) + vy * (hxy * vx + hyy * vy)
    udot = wp1 * (wx * ax + wy * ay + vHv) + (pw - 1.0) * wp2 * gv * gv
    z = b * (1.0 - w)
    root = math.sqrt(z * z + 4.0 * ell * ell)
    d = 0.5 * (z + root)
    dd = -0.5 * b * (1.0 + z / root)
    ddot = dd * gv
    return u * u / (d * d), 2.0 * u * udot / (d * d) - 2.0 * u * u * ddot / (d * d * d)


@numba.njit(error_model="numpy")
def _rate_hs(hess, energies, walls, q, v, zero, T, a, h, tot, sh, mem, ell, b, pw, om, G):
    """Omega(q, v) and G = dOmega/dt / Omega per run; ``a`` must hold a(q)."""
    D, R = q.shape
    K = (D - 1) // 2
    hess(q, h, T)
    energies(q, zero, T, tot, sh, mem)
    for r in range(R):
        om[r] = 1.0
        G[r] = 0.0
    for j in range(K):
        for r in range(R):
            V = mem[j, r]
            m = T[3, r]
            gx = -m * a[1 + j, r]
            gy = -m * a[1 + K + j, r]
            hxx = h[1 + j, r]
            hxy = h[1 + K + j, r]
            hyy = h[1 + 2 * K + j, r]
            vx = v[1 + j, r] - v[0, r]
            vy = v[1 + K + j, r]
            ax = a[1 + j, r] - a[0, r]
            ay = a[1 + K + j, r]
            gg = gx * gx + gy * gy
            gv = gx * vx + gy * vy
            Hvx = hxx * vx + hxy * vy
            Hvy = hxy * vx + hyy * vy
            gHv = gx * Hvx + gy * Hvy
            # local frequency^2 of a power-law wall: |grad V|^2 / (m V)
            A = 0.0
            Adot = 0.0
            if V > 1e-300:
                A = gg / (m * V)
                Adot = (2.0 * gHv * V - gg * gv) / (m * V * V)
            # approach to each wall i of the shape, (v . grad phi_i)^2 / d(w_i)^2 with
            # w_i = |r_i| and phi_i = w_i^p / p, and the crossing of the well,
            # C0^2 |v|^2 sum_i |grad r_i|^2 (a step covers a fraction of the well's width)
            f = walls(q[1 + j, r] - q[0, r], q[1 + K + j, r], T[0, r], T[1, r])
            vv = vx * vx + vy * vy
            B = 0.0
            Bdot = 0.0
            for i in range(len(f) // 6):
                k6 = 6 * i
                ri, rx, ry = f[k6], f[k6 + 1], f[k6 + 2]
                rxx, rxy, ryy = f[k6 + 3], f[k6 + 4], f[k6 + 5]
                sg = 1.0 if ri >= 0.0 else -1.0
                Bi, Bidot = _approach(sg * ri, sg * rx, sg * ry, sg * rxx, sg * rxy, sg * ryy,
                                      vx, vy, ax, ay, ell, b, pw)  # fmt: skip
                gr = rx * rx + ry * ry
                grdot = 2.0 * (rx * (rxx * vx + rxy * vy) + ry * (rxy * vx + ryy * vy))
                B += Bi + C0 * C0 * vv * gr
                Bdot += Bidot + C0 * C0 * (2.0 * (vx * ax + vy * ay) * gr + vv * grdot)
            om[r] += A + B
            G[r] += Adot + Bdot
    for r in range(R):
        om[r] = math.sqrt(om[r])
        G[r] = G[r] / (2.0 * om[r] * om[r])


@numba.njit(error_model="numpy")
def _plain_step(acc, q, v, T, a, A, Bk, hstep):
    """One step of the splitting (kick first) with a step per run; a holds a(q) on entry
    and on exit."""
    D, R = q.shape
    S = A.shape[0]
    for i in range(S + 1):
        if i > 0:
            acc(q, a, T)
        for d in range(D):
            for r in range(R):
                v[d, r] += Bk[i] * hstep[r] * a[d, r]
        if i < S:
            for d in range(D):
                for r in range(R):
                    q[d, r] += A[i] * hstep[r] * v[d, r]


@numba.njit(error_model="numpy")
def run_hs(acc, hess, energies, walls, q, v, T, A, Bk, eps, ell, b, pw, periods, period, resync):
    """Advance every run ``periods`` periods; returns (steps per run, |dH|/H0 per period,
    rho / Omega at the end)."""
    D, R = q.shape
    K = (D - 1) // 2
    a = np.empty((D, R))
    h = np.empty((1 + 3 * K, R))
    zero = np.zeros((D, R))
    tot = np.empty(R)
    sh = np.empty(R)
    mem = np.empty((K, R))
    om = np.empty(R)
    G = np.empty(R)
    rho = np.empty(R)
    t = np.zeros(R)
    hstep = np.empty(R)
    steps = np.zeros(R, dtype=np.int64)
    errors = np.empty((periods, R))
    energies(q, v, T, tot, sh, mem)
    H0 = tot.copy()
    acc(q, a, T)
    _rate_hs(hess, energies, walls, q, v, zero, T, a, h, tot, sh, mem, ell, b, pw, om, G)
    for r in range(R):
        rho[r] = om[r]
    for p in range(periods):
        t_end = (p + 1) * period
        while True:
            active = 0
            for r in range(R):
                hr = eps / rho[r]
                if t[r] < t_end:
                    hstep[r] = min(hr, t_end - t[r])
                    active += 1
                    steps[r] += 1
                else:
                    hstep[r] = 0.0
            if active == 0 or steps.max() > 200000 * (p + 1):
                break
            _plain_step(acc, q, v, T, a, A, Bk, hstep)
            _rate_hs(hess, energies, walls, q, v, zero, T, a, h, tot, sh, mem, ell, b, pw, om, G)
            for r in range(R):
                if hstep[r] > 0.0:
                    t[r] = t[r] + hstep[r] if t[r] + hstep[r] < t_end else t_end
                    # rho+ - rho- = dOmega/dt (h+ + h-) / 2 with h = eps / rho: symmetric
                    c = 0.5 * eps * G[r] * om[r]
                    sr = rho[r] + c / rho[r]
                    disc = sr * sr + 4.0 * c
                    rho[r] = 0.5 * (sr + math.sqrt(disc)) if disc > 0.0 else 0.0
                    if rho[r] < 0.5 * om[r]:
                        rho[r] = om[r]
        ratio = rho / om
        if resync:
            for r in range(R):
                rho[r] = om[r]
        energies(q, v, T, tot, sh, mem)
        for r in range(R):
            errors[p, r] = abs(tot[r] - H0[r]) / H0[r]
    return steps, errors, ratio


def _adaptive(n, eps, args, A, Bk, periods):
    """(seconds, steps per period, max |dH|/H0, rho/Omega range) of the prototype."""
    sink, engine, q, v, T = _setup(n, args.runs, 0, shape=args.shape)
    t0 = time.perf_counter()
    steps, err, ratio = run_hs(
        engine.accelerations, engine.hessian, engine.energies, wall_kernel(sink.well.shape),
        q, v, T, A, Bk, eps,
        1.0 / (2 * n), args.b, args.p, periods, 2 * math.pi, True,
    )  # fmt: skip
    return time.perf_counter() - t0, steps.mean() / periods, err.max(), ratio


def _fixed(n, args, periods):
    """(seconds, steps per period, max |dH|/H0) of the package's fixed step at tol 1e-8."""
    from sinktheory import RunSettings, Sink, Well
    from sinktheory.simulate import simulate

    sink = Sink(Well(0.5, 0.3, n, shape=args.shape), particles=5, mass=0.2)
    t0 = time.perf_counter()
    res = simulate(sink, RunSettings(runs=args.runs, periods=periods, seed=0), tol=1e-8)
    return time.perf_counter() - t0, res.steps_per_period, res.max_relative_energy_error


def _rigid(args, periods):
    """Seconds of the rigid billiard engine (moving container) from the same starts."""
    from sinktheory import RunSettings
    from sinktheory.billiard.convergence import measure

    t0 = time.perf_counter()
    measure(args.shape, 0.5, 0.3, math.inf, particles=5, mass=0.2, lyapunov=False,
            settings=RunSettings(runs=args.runs, periods=periods, seed=0))  # fmt: skip
    return time.perf_counter() - t0


def main(argv=None) -> None:
    from sinktheory.integrators import get_scheme

    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, nargs="+", default=[4, 10, 20, 50, 100])
    p.add_argument("--eps", type=float, nargs="+", default=[0.15])
    p.add_argument("--shape", default="flat", help="well shape (default flat: Fig. 8)")
    p.add_argument("--b", type=float, default=1.0)
    p.add_argument("--p", type=float, default=3.0)
    p.add_argument("--scheme", default="blanes-moan6")
    p.add_argument("--compare", action="store_true", help="also time the fixed step")
    p.add_argument("--chart", help="PNG of seconds per run-period against n (implies --compare)")
    p.add_argument("--runs", type=int, default=25)
    p.add_argument("--periods", type=int, default=50)
    args = p.parse_args(argv)
    numba.set_num_threads(1)
    print(describe(), flush=True)
    A, Bk = (np.asarray(x, dtype=float) for x in get_scheme(args.scheme).arrays())
    compare = args.compare or bool(args.chart)
    work = args.runs * args.periods
    rows = []
    for n in args.n:
        _adaptive(n, args.eps[0], args, A, Bk, 1)  # compile and warm up
        if compare:
            _fixed(n, args, 1)
            fixed = _fixed(n, args, args.periods)
            print(f"fixed    n={n:4d} steps/period={fixed[1]:8d}  max |dH|/H0={fixed[2]:.1e}  "
                  f"{1e3 * fixed[0] / work:.3f} ms per run-period", flush=True)  # fmt: skip
        for eps in args.eps:
            wall, steps, err, ratio = _adaptive(n, eps, args, A, Bk, args.periods)
            print(
                f"adaptive n={n:4d} eps={eps:.3g} steps/period={steps:8.1f}  max |dH|/H0={err:.1e}"
                f"  {1e3 * wall / work:.3f} ms per run-period  rho/Omega "
                f"{ratio.min():.3g}..{ratio.max():.3g}",
                flush=True,
            )
            if compare:
                rows.append((n, eps, fixed[0] / work, wall / work, fixed[2], err))
    if args.chart:
        _rigid(args, 1)
        rigid = _rigid(args, args.periods) / work
        print(f"rigid billiard engine: {1e3 * rigid:.3f} ms per run-period", flush=True)
        _chart(args.chart, rows, rigid)


def _chart(path, rows, rigid) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.5, 4.2), layout="constrained")
    ns = sorted({r[0] for r in rows})
    fixed = [next(r[2] for r in rows if r[0] == n) for n in ns]
    ax.loglog(ns, 1e3 * np.array(fixed), "o-", label="fixed step (tol 1e-8)")
    for eps in sorted({r[1] for r in rows}):
        sel = [r for r in rows if r[1] == eps]
        ax.loglog([r[0] for r in sel], [1e3 * r[3] for r in sel], "s-",
                  label=f"adaptive prototype, eps {eps:g}")  # fmt: skip
    ax.axhline(1e3 * rigid, color="k", ls="--", label="rigid billiard (n = inf)")
    ax.set_xlabel("wall exponent n")
    ax.set_ylabel("ms per run and period (1 thread)")
    ax.set_title("Fig. 8 ensemble (flat, k = 5): cost against wall stiffness", fontsize=10)
    ax.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    print(f"chart: {path}")


if __name__ == "__main__":
    main()
