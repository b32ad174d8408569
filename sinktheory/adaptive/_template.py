"""The adaptive stepper that every generated adaptive module ends with.

Not imported: :func:`sinktheory.adaptive.kernels` copies the text below the
``template starts`` marker after a header that binds the sink engine's public kernels
(``accelerations``, ``hessian``, ``energies``, ``members_of``, ``hessian_rows``,
``SHARED_HESSIAN``), the well's generated ``walls(x, y, P, r)``, which returns (V - V(0, 0),
then r, dr/dx, dr/dy, d2r/dx2, d2r/dxdy, d2r/dy2 for each wall ratio r) at run r's
parameters, and ``MU_ROW``, the table's row of the particle mass.  numba compiles and
caches one module per well (n is a run-time value).  It is a real file so that linters
and readers see it whole.

Layout as in the engine: q[i, r], v[i, r] (runs last), P the per-run parameter table
(the well's parameters, then mu: alpha, beta, gamma, n, mu for a registered shape).
Every loop runs over the runs of a block without reductions across runs, and a run that
has reached the end of the period waits with step 0 and gets back the copy of its state
taken then, so a run's numbers do not depend on its block, its neighbours or the thread
count.
"""

# ruff: noqa: F821
import math

import numba
import numpy as np

# --- template starts
RUNNING, DRIFT, NONFINITE, STALLED = 0, 1, 2, 3


@numba.njit(cache=True, error_model="numpy")
def _approach(w, wx, wy, hxx, hxy, hyy, vx, vy, ax, ay, ell, b):
    """(v . grad phi)^2 / d(w)^2 and its time derivative for a wall ratio w >= 0 with
    gradient (wx, wy) and Hessian (hxx, hxy, hyy); phi = w^3 / 3, and d = ell at the wall,
    b (1 - w) deep inside (the smooth maximum of the two)."""
    ww = w * w
    gv = wx * vx + wy * vy
    u = ww * gv
    vHv = vx * (hxx * vx + hxy * vy) + vy * (hxy * vx + hyy * vy)
    udot = ww * (wx * ax + wy * ay + vHv) + 2.0 * w * gv * gv
    z = b * (1.0 - w)
    root = math.sqrt(z * z + 4.0 * ell * ell)
    d = 0.5 * (z + root)
    ddot = -0.5 * b * (1.0 + z / root) * gv
    return u * u / (d * d), 2.0 * u * udot / (d * d) - 2.0 * u * u * ddot / (d * d * d)


@numba.njit(cache=True, error_model="numpy")
def _rate(q, v, a, h, P, om, G, ctl):
    """The rate Omega(q, v) of every run and G = (dOmega/dt) / Omega; ``a`` must hold
    a(q).  ctl = (eps, ell, b, p, c0).  Per particle: the wall's local frequency^2
    |grad V|^2 / (m V), the approach to each wall and the crossing c0^2 |v|^2 |grad r|^2;
    plus 1 for the container's spring."""
    _, ell, bw, c0 = ctl
    D, B = q.shape
    K = members_of(D)
    hessian(q, h, P)
    for r in range(B):
        om[r] = 1.0
        G[r] = 0.0
    for j in range(K):
        for r in range(B):
            m = P[MU_ROW, r]
            x = q[1 + j, r] - q[0, r]
            y = q[1 + K + j, r]
            f = walls(x, y, P, r)
            V = f[0]
            gx = -m * a[1 + j, r]
            gy = -m * a[1 + K + j, r]
            hxx = h[SHARED_HESSIAN + j, r]
            hxy = h[SHARED_HESSIAN + K + j, r]
            hyy = h[SHARED_HESSIAN + 2 * K + j, r]
            vx = v[1 + j, r] - v[0, r]
            vy = v[1 + K + j, r]
            ax = a[1 + j, r] - a[0, r]
            ay = a[1 + K + j, r]
            gg = gx * gx + gy * gy
            gv = gx * vx + gy * vy
            gHv = gx * (hxx * vx + hxy * vy) + gy * (hxy * vx + hyy * vy)
            w2 = 0.0
            w2dot = 0.0
            if V > 1e-300:
                w2 = gg / (m * V)
                w2dot = (2.0 * gHv * V - gg * gv) / (m * V * V)
            vv = vx * vx + vy * vy
            vvdot = 2.0 * (vx * ax + vy * ay)
            for i in range((len(f) - 1) // 6):
                k6 = 1 + 6 * i
                ri, rx, ry = f[k6], f[k6 + 1], f[k6 + 2]
                rxx, rxy, ryy = f[k6 + 3], f[k6 + 4], f[k6 + 5]
                sg = 1.0 if ri >= 0.0 else -1.0
                Bi, Bidot = _approach(sg * ri, sg * rx, sg * ry, sg * rxx, sg * rxy, sg * ryy,
                                      vx, vy, ax, ay, ell, bw)  # fmt: skip
                gr = rx * rx + ry * ry
                grdot = 2.0 * (rx * (rxx * vx + rxy * vy) + ry * (rxy * vx + ryy * vy))
                Ci = c0 * c0 * vv * gr
                Cidot = c0 * c0 * (vvdot * gr + vv * grdot)
                if math.isfinite(Bi + Bidot + Ci + Cidot):  # a radial ratio at its centre
                    w2 += Bi + Ci
                    w2dot += Bidot + Cidot
            om[r] += w2
            G[r] += w2dot
    for r in range(B):
        om[r] = math.sqrt(om[r])
        G[r] = G[r] / (2.0 * om[r] * om[r])


@numba.njit(cache=True, error_model="numpy")
def _step(q, v, a, P, A, Bk, hstep):
    """One step of the splitting (kick first) of size hstep[r] of every run (0: held, up
    to the sign of a zero).  ``a`` holds a(q) on entry and on exit."""
    D, B = q.shape
    S = A.shape[0]
    for i in range(S + 1):
        if i > 0:
            accelerations(q, a, P)
        for d in range(D):
            for r in range(B):
                v[d, r] += Bk[i] * hstep[r] * a[d, r]
        if i < S:
            for d in range(D):
                for r in range(B):
                    q[d, r] += A[i] * hstep[r] * v[d, r]


@numba.njit(cache=True, error_model="numpy")
def _control(rho, om, G, eps, active, resets):
    """rho+ - rho- = dOmega/dt (h+ + h-) / 2 with h = eps / rho, solved for rho+ (the
    equation is symmetric under rho+ <-> rho-, dOmega/dt -> -dOmega/dt); rho is reset to
    Omega (counted in resets, not reversible) if it would drop below Omega / 2."""
    for r in range(rho.shape[0]):
        if active[r]:
            c = 0.5 * eps * G[r] * om[r]
            s = rho[r] + c / rho[r]
            disc = s * s + 4.0 * c
            rho[r] = 0.5 * (s + math.sqrt(disc)) if disc > 0.0 else 0.0
            if rho[r] < 0.5 * om[r]:
                rho[r] = om[r]
                resets[r] += 1


@numba.njit(cache=True, error_model="numpy")
def steps(q, v, P, A, Bk, ctl, rho, count, resets):
    """``count`` controller steps of every run from step rates ``rho`` (advanced in place);
    returns the rates the last step used; resets[r] += the controller's resets."""
    D, B = q.shape
    a = np.empty((D, B))
    h = np.empty((hessian_rows(D), B))
    om = np.empty(B)
    G = np.empty(B)
    hstep = np.empty(B)
    used = rho.copy()
    active = np.ones(B, dtype=np.bool_)
    accelerations(q, a, P)
    for _ in range(count):
        for r in range(B):
            used[r] = rho[r]
            hstep[r] = ctl[0] / rho[r]
        _step(q, v, a, P, A, Bk, hstep)
        _rate(q, v, a, h, P, om, G, ctl)
        _control(rho, om, G, ctl[0], active, resets)
    return used


@numba.njit(cache=True, error_model="numpy")
def _period(q, v, P, A, Bk, ctl, period, max_steps, taken, resets, rho, rem):
    """Advance every run of the block by ``period`` time units with the controller's
    steps, carried across period ends: rho[r] is the rate of the run's next step and
    rem[r] > 0 the part of a step that a period end split, still to take (both updated).
    A step that crosses the period end is split there into two parts and the controller
    is updated once, after the second, so the sequence of full steps is the one
    :func:`steps` takes.  taken[r] = the (part-)steps taken, or -1 if it needed more than
    ``max_steps``."""
    D, B = q.shape
    eps = ctl[0]
    a = np.empty((D, B))
    h = np.empty((hessian_rows(D), B))
    om = np.empty(B)
    G = np.empty(B)
    qf = q.copy()  # a stalled run (taken -1) goes back to its start
    vf = v.copy()
    rho0 = rho.copy()
    rem0 = rem.copy()
    t = np.zeros(B)
    hstep = np.zeros(B)
    left = np.zeros(B)
    active = np.zeros(B, dtype=np.bool_)
    whole = np.zeros(B, dtype=np.bool_)
    accelerations(q, a, P)
    for r in range(B):
        taken[r] = 0
    while True:
        moving = 0
        for r in range(B):
            active[r] = t[r] < period and taken[r] >= 0
            hstep[r] = 0.0
            if active[r]:
                if taken[r] == max_steps:
                    taken[r] = -1
                    active[r] = False
                else:
                    left[r] = rem[r] if rem[r] > 0.0 else eps / rho[r]
                    hstep[r] = min(left[r], period - t[r])
                    taken[r] += 1
                    moving += 1
        if moving == 0:
            for r in range(B):
                if taken[r] < 0:
                    rho[r] = rho0[r]
                    rem[r] = rem0[r]
            q[:, :] = qf
            v[:, :] = vf
            return
        _step(q, v, a, P, A, Bk, hstep)
        for r in range(B):
            whole[r] = False
            if active[r]:
                if left[r] < period - t[r]:
                    t[r] = t[r] + left[r]
                    rem[r] = 0.0
                    whole[r] = True
                else:  # the period ends within (or at the end of) this step; NaN too
                    rem[r] = left[r] - hstep[r]
                    whole[r] = not rem[r] > 0.0
                    t[r] = period
                    for d in range(D):
                        qf[d, r] = q[d, r]
                        vf[d, r] = v[d, r]
        _rate(q, v, a, h, P, om, G, ctl)
        _control(rho, om, G, eps, whole, resets)


@numba.njit(cache=True, parallel=True, error_model="numpy")
def advance(Q, V, P, scheme, p0, p1, block, audit, rec):
    """Periods [p0, p1) of every run, in blocks of ``block`` runs spread over threads (a
    block goes through all the periods in one task: one launch of the threads per call,
    not per period).

    scheme = (A, Bk, ctl, period, max_steps).  audit = (h0, bound, status, fail_period,
    fail_energy, worst).  rec = (container (R, P + 1), particles (R, P + 1, K) or empty,
    steps (R,), controller resets (R,), rates rho (R,), split remainders (R,)).  A block
    stops after the first period in which one of its runs failed."""
    A, Bk, ctl, period, max_steps = scheme
    h0, bound, status, fail_period, fail_energy, worst = audit
    rec_shared, rec_members, steps_taken, resets, RHO, REM = rec
    D, R = Q.shape
    K = members_of(D)
    blocks = (R + block - 1) // block
    for ib in numba.prange(blocks):
        r0 = ib * block
        r1 = min(R, r0 + block)
        B = r1 - r0
        q = np.ascontiguousarray(Q[:, r0:r1])
        v = np.ascontiguousarray(V[:, r0:r1])
        Pb = np.ascontiguousarray(P[:, r0:r1])
        rho = RHO[r0:r1].copy()
        rem = REM[r0:r1].copy()
        taken = np.empty(B, dtype=np.int64)
        reset = np.zeros(B, dtype=np.int64)
        total = np.empty(B)
        shared = np.empty(B)
        members = np.empty((K, B))
        for p in range(p0, p1):
            reset[:] = 0
            _period(q, v, Pb, A, Bk, ctl, period, max_steps, taken, reset, rho, rem)
            energies(q, v, Pb, total, shared, members)
            failed = False
            for b in range(B):
                r = r0 + b
                H = total[b]
                if rec_shared.shape[1]:
                    rec_shared[r, p + 1] = shared[b]
                if rec_members.shape[1]:
                    for j in range(K):
                        rec_members[r, p + 1, j] = members[j, b]
                scale = abs(h0[r]) if h0[r] != 0.0 else 1.0
                if taken[b] < 0:
                    status[r] = STALLED
                elif not math.isfinite(H):
                    status[r] = NONFINITE
                else:
                    steps_taken[r] += taken[b]
                    resets[r] += reset[b]
                    err = abs(H - h0[r]) / scale
                    worst[r] = max(worst[r], err)
                    if err > bound:
                        status[r] = DRIFT
                if status[r] != RUNNING:
                    fail_period[r] = p + 1
                    fail_energy[r] = H
                    failed = True
            if failed:
                break
        Q[:, r0:r1] = q
        V[:, r0:r1] = v
        RHO[r0:r1] = rho
        REM[r0:r1] = rem


@numba.njit(cache=True, error_model="numpy")
def rate_of(q, v, P, ctl):
    """Omega(q, v) of every run."""
    D, B = q.shape
    a = np.empty((D, B))
    h = np.empty((hessian_rows(D), B))
    om = np.empty(B)
    G = np.empty(B)
    accelerations(q, a, P)
    _rate(q, v, a, h, P, om, G, ctl)
    return om


@numba.njit(cache=True, error_model="numpy")
def start_rate(q, v, P, ctl):
    """The controller's first rate of every run: Omega, with each particle's crossing of
    the well by its acceleration relative to the container, |a| |grad r| per wall ratio
    r, added to Omega^2.  Omega follows the velocities alone, so a particle at rest in an
    accelerating container (the start of every run from given positions) would otherwise
    begin with a step the wall reaches before it ends."""
    D, B = q.shape
    K = members_of(D)
    a = np.empty((D, B))
    h = np.empty((hessian_rows(D), B))
    om = np.empty(B)
    G = np.empty(B)
    accelerations(q, a, P)
    _rate(q, v, a, h, P, om, G, ctl)
    for r in range(B):
        w2 = om[r] * om[r]
        for j in range(K):
            x = q[1 + j, r] - q[0, r]
            y = q[1 + K + j, r]
            f = walls(x, y, P, r)
            ax = a[1 + j, r] - a[0, r]
            ay = a[1 + K + j, r]
            acc = math.sqrt(ax * ax + ay * ay)
            for i in range((len(f) - 1) // 6):
                rx, ry = f[2 + 6 * i], f[3 + 6 * i]
                term = acc * math.sqrt(rx * rx + ry * ry)
                if math.isfinite(term):
                    w2 += term
        om[r] = math.sqrt(w2)
    return om
