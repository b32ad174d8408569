"""Compiled kernels of the rigid-billiard engine (numba).

A table is the set where every wall function f_i(x, y) >= 0 (container frame); each
f_i is C^1 with a Lipschitz gradient.  Kinds: :data:`POLYNOMIAL` (coefficients c[a, b]
of x^a y^b, printed from the shape's SymPy definition by :mod:`.table`) and
:data:`CAPSULE` (points within R of the segment |x| <= a, y = 0: two segments and two
half circles, the Bunimovich stadium).

Flights are exact: particles move on straight lines (absolute frame), the container on
its spring X(t) = X cos t + V sin t between impacts.  Along a flight g(s) = f_i(x(s), y(s))
has |g''| <= M_i (a bound from the table's Hessian and gradient bounds, the relative
speed and the container amplitude), so g(s + h) >= g + g' h - M_i h^2 / 2 and the
largest h keeping that lower bound positive is a step on which no wall can be crossed:
*conservative advancement*.  Near a transversal crossing the steps converge
quadratically; a hit is declared when g_i <= eps_i (a few rounding units of f_i) while
the particle approaches (g_i' < 0), so the particle never leaves the table and no
crossing, grazing or closely spaced, is stepped over.

Status codes returned by the drivers: 0 fine, 1 a flight took more than
:data:`MAX_ITERATIONS` steps (a root that could not be approached) or more than
:data:`MAX_REPEATS` impacts happened at one instant.
"""

from __future__ import annotations

import math

import numba
import numpy as np

__all__ = [
    "MAX_ITERATIONS",
    "MAX_REPEATS",
]

POLYNOMIAL, CAPSULE = 0, 1
#: Conservative-advancement steps allowed in one search before giving up (status 1).
MAX_ITERATIONS = 100_000
#: Impacts at one instant allowed in a row (a corner takes two; grazing rounding a few).
MAX_REPEATS = 64
OK, STUCK = 0, 1


@numba.njit(cache=True)
def _power(z, e):
    out = 1.0
    for _ in range(e):
        out *= z
    return out


@numba.njit(cache=True)
def wall_value(kind, coef, cap, x, y):
    """(f, f_x, f_y) of one wall function at (x, y)."""
    if kind == CAPSULE:
        a, r = cap[0], cap[1]
        d = abs(x) - a
        if d > 0.0:
            return r * r - y * y - d * d, -2.0 * d * math.copysign(1.0, x), -2.0 * y
        return r * r - y * y, 0.0, -2.0 * y
    deg = coef.shape[0]
    f = 0.0
    fx = 0.0
    fy = 0.0
    for a in range(deg):
        for b in range(deg):
            c = coef[a, b]
            if c == 0.0:
                continue
            f += c * _power(x, a) * _power(y, b)
            if a > 0:
                fx += a * c * _power(x, a - 1) * _power(y, b)
            if b > 0:
                fy += b * c * _power(x, a) * _power(y, b - 1)
    return f, fx, fy


@numba.njit(cache=True)
def wall_hessian(kind, coef, cap, x, y):
    """(f_xx, f_xy, f_yy) of one wall function at (x, y)."""
    if kind == CAPSULE:
        return (-2.0 if abs(x) > cap[0] else 0.0), 0.0, -2.0
    deg = coef.shape[0]
    fxx = 0.0
    fxy = 0.0
    fyy = 0.0
    for a in range(deg):
        for b in range(deg):
            c = coef[a, b]
            if c == 0.0:
                continue
            if a >= 2:
                fxx += a * (a - 1) * c * _power(x, a - 2) * _power(y, b)
            if a >= 1 and b >= 1:
                fxy += a * b * c * _power(x, a - 1) * _power(y, b - 1)
            if b >= 2:
                fyy += b * (b - 1) * c * _power(x, a) * _power(y, b - 2)
    return fxx, fxy, fyy


@numba.njit(cache=True)
def next_hit(x, y, vu, vy, X, V, limit, kinds, coef, cap, hneg, gx, eps, reach):
    """First wall hit of a particle within ``limit`` time units.

    (x, y) relative position, (vu, vy) absolute velocity, (X, V) the container now (both
    0 for a fixed container).  Returns (h, wall, status): h <= limit the time of the hit
    (or ``limit`` with wall = -1 if none), status 0 or STUCK.
    """
    amp = math.sqrt(X * X + V * V)
    vr = math.sqrt((abs(vu) + amp) ** 2 + vy * vy)
    if vr == 0.0:
        return limit, -1, OK
    hmax = reach / vr  # displacement per step <= reach: the bounds hold on the step
    nw = kinds.shape[0]
    s = 0.0
    for _ in range(MAX_ITERATIONS):
        cs = math.cos(s)
        sn = math.sin(s)
        Xs = X * cs + V * sn
        Vs = V * cs - X * sn
        xs = x + vu * s - (Xs - X)
        ys = y + vy * s
        wx = vu - Vs
        step = hmax
        for i in range(nw):
            f, fx, fy = wall_value(kinds[i], coef[i], cap[i], xs, ys)
            df = fx * wx + fy * vy
            if f <= eps[i]:
                # approaching: the relative normal velocity, computed exactly as the
                # impact computes it, so that a hit always changes the velocity
                g = math.hypot(fx, fy)
                if wx * (-fx / g) + vy * (-fy / g) > 0.0:
                    return s, i, OK
                df = max(df, 0.0)  # not approaching (agree with the impact's sign)
            m = hneg[i] * vr * vr + gx[i] * amp
            fc = max(f, 0.0)
            if m > 0.0:
                hi = (df + math.sqrt(df * df + 2.0 * m * fc)) / m
            elif df < 0.0:
                hi = fc / -df
            else:
                hi = hmax
            step = min(step, hi)
        # at a wall with zero normal speed the bound allows no step: move on by rounding
        step = max(step, 4.0 * np.finfo(np.float64).eps * (s + hmax))
        if s + step >= limit:
            return limit, -1, OK
        s += step
    return s, -1, STUCK


@numba.njit(cache=True)
def outward_normal(kind, coef, cap, x, y):
    """(n_x, n_y, |grad f|): unit outward normal (f decreases outward) at (x, y)."""
    f, fx, fy = wall_value(kind, coef, cap, x, y)
    g = math.hypot(fx, fy)
    return -fx / g, -fy / g, g


@numba.njit(cache=True)
def impulse(mu, w, nx):
    """J of the elastic impact of a particle (mass mu) on the container (mass 1, moving
    along x only): relative normal speed w, wall normal x-component nx.  The particle's
    momentum changes by -J n, the container's by +J n_x (derivations/billiard.py)."""
    return 2.0 * mu * w / (1.0 + mu * nx * nx)


@numba.njit(cache=True)
def impact(v, cont, mu, nx, ny):
    """Elastic impact of a particle (velocity v (2,), mass mu) on the container
    (cont = (X, V)) across the wall normal (nx, ny); in place.  Nothing happens unless
    the particle approaches the wall (relative normal velocity > 0)."""
    w = (v[0] - cont[1]) * nx + v[1] * ny
    if w > 0.0:
        J = impulse(mu, w, nx)
        v[0] -= J / mu * nx
        v[1] -= J / mu * ny
        cont[1] += J * nx


@numba.njit(cache=True)
def reflect_tangent(x, y, v, dq, dv, kind, coef, cap):
    """Specular reflection of velocity ``v`` (2,) at (x, y) on a fixed wall, and the
    tangent map of the reflection for the deviation (dq, dv) (Dellago, Posch & Hoover,
    Phys. Rev. E 53, 1485 (1996)); the wall's curvature enters through the Hessian of
    f.  Updates v, dq, dv in place."""
    nx, ny, g = outward_normal(kind, coef, cap, x, y)
    vn = v[0] * nx + v[1] * ny
    dtau = -(dq[0] * nx + dq[1] * ny) / vn
    qx = dq[0] + v[0] * dtau
    qy = dq[1] + v[1] * dtau
    fxx, fxy, fyy = wall_hessian(kind, coef, cap, x, y)
    hx = fxx * qx + fxy * qy
    hy = fxy * qx + fyy * qy
    hn = hx * nx + hy * ny
    dnx = -(hx - hn * nx) / g
    dny = -(hy - hn * ny) / g
    v0 = v[0] - 2.0 * vn * nx
    v1 = v[1] - 2.0 * vn * ny
    dvn = dv[0] * nx + dv[1] * ny
    vdn = v[0] * dnx + v[1] * dny
    dv0 = dv[0] - 2.0 * dvn * nx - 2.0 * (vdn * nx + vn * dnx)
    dv1 = dv[1] - 2.0 * dvn * ny - 2.0 * (vdn * ny + vn * dny)
    dq[0] = qx - v0 * dtau
    dq[1] = qy - v1 * dtau
    dv[0] = dv0
    dv[1] = dv1
    v[0] = v0
    v[1] = v1


@numba.njit(cache=True)
def advance_fixed(pos, vel, tan, duration, kinds, coef, cap, hneg, gx, eps, reach, hits):
    """Advance k particles in a fixed table by ``duration`` (each independently),
    with their deviation vectors ``tan`` (k, 4) = (dq, dv) if tan.shape[0] > 0.
    ``hits`` (walls,) counts the collisions.  Returns (status, particle, time)."""
    zeros = np.zeros(2)
    for j in range(pos.shape[0]):
        t = 0.0
        v = vel[j]
        repeats = 0
        while True:
            h, w, status = next_hit(
                pos[j, 0], pos[j, 1], v[0], v[1], 0.0, 0.0, duration - t,
                kinds, coef, cap, hneg, gx, eps, reach,
            )  # fmt: skip
            pos[j, 0] += v[0] * h
            pos[j, 1] += v[1] * h
            t += h
            if tan.shape[0] > 0:
                tan[j, 0] += tan[j, 2] * h
                tan[j, 1] += tan[j, 3] * h
            repeats = repeats + 1 if h == 0.0 else 0
            if status != OK or repeats > MAX_REPEATS:
                return STUCK, j, t
            if w < 0:
                break
            hits[w] += 1
            if tan.shape[0] > 0:
                dq, dv = tan[j, 0:2], tan[j, 2:4]  # views: updated in place
            else:
                dq, dv = zeros, zeros  # a zero deviation stays zero
            reflect_tangent(pos[j, 0], pos[j, 1], v, dq, dv, kinds[w], coef[w], cap[w])
    return OK, -1, duration


@numba.njit(cache=True)
def advance_moving(cont, pos, vel, mu, duration, kinds, coef, cap, hneg, gx, eps, reach, hits):
    """Advance the container (X, V) ``cont`` and k particles by ``duration``: the next
    impact of any particle ends each exact flight; the impact exchanges the impulse of
    :func:`impulse` along the wall normal.  Returns (status, particle, time)."""
    k = pos.shape[0]
    t = 0.0
    repeats = 0
    while True:
        best = duration - t
        bj = -1
        bw = -1
        for j in range(k):
            h, w, status = next_hit(
                pos[j, 0], pos[j, 1], vel[j, 0], vel[j, 1], cont[0], cont[1], best,
                kinds, coef, cap, hneg, gx, eps, reach,
            )  # fmt: skip
            if status != OK:
                return status, j, t + h
            if w >= 0:
                best = h
                bj = j
                bw = w
        X, V = cont[0], cont[1]
        cs = math.cos(best)
        sn = math.sin(best)
        X1 = X * cs + V * sn
        V1 = V * cs - X * sn
        for j in range(k):
            pos[j, 0] += vel[j, 0] * best - (X1 - X)
            pos[j, 1] += vel[j, 1] * best
        cont[0] = X1
        cont[1] = V1
        t += best
        if bj < 0:
            return OK, -1, duration
        repeats = repeats + 1 if best == 0.0 else 0
        if repeats > MAX_REPEATS:
            return STUCK, bj, t
        hits[bw] += 1
        nx, ny, _ = outward_normal(kinds[bw], coef[bw], cap[bw], pos[bj, 0], pos[bj, 1])
        impact(vel[bj], cont, mu, nx, ny)


@numba.njit(cache=True)
def energies(cont, vel, mu):
    """(container energy, total energy) of one run."""
    ec = 0.5 * (cont[0] * cont[0] + cont[1] * cont[1])
    ep = 0.0
    for j in range(vel.shape[0]):
        ep += 0.5 * mu * (vel[j, 0] * vel[j, 0] + vel[j, 1] * vel[j, 1])
    return ec, ec + ep


@numba.njit(cache=True, nogil=True)  # a signal's watcher runs meanwhile
def run_fixed(
    pos, vel, tan, first, last, period, kinds, coef, cap, hneg, gx, eps, reach, out
):  # fmt: skip
    """Fixed container, R runs (pos, vel (R, k, 2); tan (R, k, 4) or (R, 0, 4)), periods
    ``first`` .. ``last`` - 1 (the caller runs them in chunks; a run whose status is set
    is not advanced).

    ``out`` = (logs (R, P + 1) accumulated log growth of the deviation vector
    (renormalised every period), sum of |v|^2 over the particles (R, P + 1), hits
    (R, walls), status (R,), where (R, 2)), filled at records first + 1 .. last (and 0 if
    first is 0)."""
    logs, v2, hits, status, where = out
    for r in range(pos.shape[0]):
        if first == 0:
            v2[r, 0] = np.sum(vel[r] ** 2)
        if status[r] != OK:
            continue
        for p in range(first, last):
            st, j, t = advance_fixed(
                pos[r], vel[r], tan[r], period, kinds, coef, cap, hneg, gx, eps, reach, hits[r]
            )
            if st != OK:
                status[r] = st
                where[r, 0] = j
                where[r, 1] = p * period + t
                break
            v2[r, p + 1] = np.sum(vel[r] ** 2)
            logs[r, p + 1] = logs[r, p]
            if tan.shape[1] > 0:
                norm = math.sqrt(np.sum(tan[r] ** 2))
                logs[r, p + 1] += math.log(norm)
                tan[r] /= norm


@numba.njit(cache=True)
def _distance(c1, p1, v1, c2, p2, v2):
    d = (c1[0] - c2[0]) ** 2 + (c1[1] - c2[1]) ** 2
    d += np.sum((p1 - p2) ** 2) + np.sum((v1 - v2) ** 2)
    return math.sqrt(d)


@numba.njit(cache=True, nogil=True)  # a signal's watcher runs meanwhile
def run_moving(
    cont, pos, vel, mu, first, last, period, kinds, coef, cap, hneg, gx, eps, reach, shadow,
    d0, renorm, out,
):  # fmt: skip
    """Moving container, R runs: cont (R, 2), pos, vel (R, k, 2), periods ``first`` ..
    ``last`` - 1 (the caller runs them in chunks; a run whose status is set is not
    advanced).  ``shadow`` is a tuple (cont, pos, vel) of nearby copies (R = 0 rows: no
    Lyapunov exponent), pulled back to distance d0 from their run ``renorm`` times a
    period (two-trajectory method: often enough that the pair stays close and its
    impacts nearly simultaneous).

    ``out`` = (container energy (R, P + 1), total energy (R, P + 1), logs (R, P + 1),
    hits (R, walls), status (R,), where (R, 2)), filled at records first + 1 .. last (and
    0 if first is 0)."""
    ec, et, logs, hits, status, where = out
    sc, sp, sv = shadow
    lyap = sc.shape[0] > 0
    chunks = renorm if lyap else 1
    spare = np.zeros(kinds.shape[0], dtype=np.int64)
    for r in range(pos.shape[0]):
        if first == 0:
            ec[r, 0], et[r, 0] = energies(cont[r], vel[r], mu)
        if status[r] != OK:
            continue
        for p in range(first, last):
            logs[r, p + 1] = logs[r, p]
            st = OK
            for c in range(chunks):
                st, j, t = advance_moving(
                    cont[r], pos[r], vel[r], mu, period / chunks, kinds, coef, cap, hneg, gx,
                    eps, reach, hits[r],
                )  # fmt: skip
                if st == OK and lyap:
                    st, j, t = advance_moving(
                        sc[r], sp[r], sv[r], mu, period / chunks, kinds, coef, cap, hneg, gx,
                        eps, reach, spare,
                    )  # fmt: skip
                if st != OK:
                    status[r] = st
                    where[r, 0] = j
                    where[r, 1] = (p + c / chunks) * period + t
                    break
                if lyap:
                    d = _distance(cont[r], pos[r], vel[r], sc[r], sp[r], sv[r])
                    logs[r, p + 1] += math.log(d / d0)
                    f = d0 / d
                    sc[r] = cont[r] + (sc[r] - cont[r]) * f
                    sp[r] = pos[r] + (sp[r] - pos[r]) * f
                    sv[r] = vel[r] + (sv[r] - vel[r]) * f
            if st != OK:
                break
            ec[r, p + 1], et[r, p + 1] = energies(cont[r], vel[r], mu)
