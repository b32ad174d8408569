"""The system-independent stepper that every generated engine module ends with.

This file is not imported: :mod:`sinktheory.engine.printer` copies the text below the
``template starts`` marker after the system's kernels (``accelerations``, ``hessian``,
``tangent_kick``, ``energies``, ``shared_energy``, ``damping_factors``, ``dissipate``,
``members_of``, ``hessian_rows``, ``parameter_table`` and the constants ``SHARED``,
``MEMBER_COORDS``, ``NPARAMS``, ``POWERS`` and ``MAX_POWER``), so
that numba compiles and caches one module per system with every call inlinable.  Keeping
it a real Python file lets linters and readers see it whole.

Data layout (structure of arrays, runs last and contiguous): ``q[i, r]``, ``v[i, r]`` are
coordinate / velocity i of run r; ``dq[i, m, r]``, ``dv[i, m, r]`` deviation vector m;
``P[p, r]`` the per-run parameter table (``parameter_table``: every run may carry its own
parameters).  A *segment* is ``steps`` steps of size ``dt`` (one container period for the
sink); the energy audit, the renormalisation of deviation vectors and all per-segment
records happen at segment ends.  Runs are processed in blocks (their size and the threads
are chosen by :mod:`sinktheory.engine.blocks`); a block is copied into contiguous local
arrays, advanced, and copied back.  Each block has its own step and steps per segment
(runs of one ensemble may need different steps for the same segment, e.g. a chaos map
over beta), so the runs of a block share their step count.  A block of a single run has
nothing to vectorise across runs, so it takes the kernels ``accelerations_one``, ``hessian_one`` and
``tangent_kick_one``, which vectorise across the members (particles) of the run instead and
sum their pull on the shared coordinates in the block kernel's order.  The arithmetic of a
run does not depend on which block or thread it is in (no reductions across runs, no
fast-math reassociation), so the numbers are bitwise the same for any block size and
thread count.
"""

# ruff: noqa: F821
import math

import numba
import numpy as np

# --- template starts
RUNNING, DRIFT, NONFINITE = 0, 1, 2
NO_TANGENT, ORTHONORMALISE, NORMALISE = 0, 1, 2


@numba.njit(cache=True, error_model="numpy")
def _renormalise(dq, dv, logs, orthogonalise):
    """Modified Gram-Schmidt (or plain normalisation) of the deviation vectors of each
    run; the log of each norm is added to logs[m, run]."""
    D, M, B = dq.shape
    acc = np.empty(B)
    for m in range(M):
        if orthogonalise:
            for l in range(m):
                for b in range(B):
                    acc[b] = 0.0
                for i in range(D):
                    for b in range(B):
                        acc[b] += dq[i, l, b] * dq[i, m, b] + dv[i, l, b] * dv[i, m, b]
                for i in range(D):
                    for b in range(B):
                        dq[i, m, b] -= acc[b] * dq[i, l, b]
                        dv[i, m, b] -= acc[b] * dv[i, l, b]
        for b in range(B):
            acc[b] = 0.0
        for i in range(D):
            for b in range(B):
                acc[b] += dq[i, m, b] * dq[i, m, b] + dv[i, m, b] * dv[i, m, b]
        for b in range(B):
            norm = math.sqrt(acc[b])
            logs[m, b] += math.log(norm)
            acc[b] = 1.0 / norm
        for i in range(D):
            for b in range(B):
                dq[i, m, b] *= acc[b]
                dv[i, m, b] *= acc[b]


@numba.njit(cache=True, error_model="numpy")
def _log_norm_first(dq, dv, logs, out):
    """ln |deviation vector 0| of each run, renormalisations included."""
    D, _, B = dq.shape
    for b in range(B):
        out[b] = 0.0
    for i in range(D):
        for b in range(B):
            out[b] += dq[i, 0, b] * dq[i, 0, b] + dv[i, 0, b] * dv[i, 0, b]
    for b in range(B):
        out[b] = logs[0, b] + 0.5 * math.log(out[b])


@numba.njit(cache=True, error_model="numpy")
def _gali(dq, dv, k, out):
    """GALI_k: the volume spanned by the first k unit deviation vectors of each run (the
    product of the Gram-Schmidt norms)."""
    D, _, B = dq.shape
    w = np.empty((2 * D, k, B))
    for m in range(k):
        for i in range(D):
            for b in range(B):
                w[i, m, b] = dq[i, m, b]
                w[D + i, m, b] = dv[i, m, b]
    acc = np.empty(B)
    for b in range(B):
        out[b] = 1.0
    for m in range(k):
        for l in range(m):
            for b in range(B):
                acc[b] = 0.0
            for i in range(2 * D):
                for b in range(B):
                    acc[b] += w[i, l, b] * w[i, m, b]
            for i in range(2 * D):
                for b in range(B):
                    w[i, m, b] -= acc[b] * w[i, l, b]
        for b in range(B):
            acc[b] = 0.0
        for i in range(2 * D):
            for b in range(B):
                acc[b] += w[i, m, b] * w[i, m, b]
        for b in range(B):
            norm = math.sqrt(acc[b])
            out[b] *= norm
            acc[b] = 1.0 / norm if norm > 0.0 else 0.0
        for i in range(2 * D):
            for b in range(B):
                w[i, m, b] *= acc[b]


@numba.njit(cache=True, error_model="numpy")
def _run_block(q, v, dq, dv, P, scheme, seg0, seg1, rows, tangent, logs, meg, audit, rec,
               damp, diss):  # fmt: skip
    """Advance one block of runs over segments [seg0, seg1); see the module docstring.

    scheme = (a, b, dt, steps): drift and kick weights of the splitting method, step,
    steps per segment.  rows[b]: the row of the block's run b in the audit and record
    arrays.  tangent = (mode, renorm, gali_k, megno, t0), t0 the time at which
    the deviation vectors started (for MEGNO).  audit = (h0, bound,
    status, fail_segment, fail_energy, worst).  rec = (shared, members, trajectory, stride,
    logs, gali, megno, work, work_samples), per-segment records indexed [run, segment]
    (empty when unused; work_samples at the trajectory's samples).  damp = (on, c0,
    weighted, integrate): the damping (see below) and whether to integrate the shared
    energy over time; diss[0, b] is the work the damping has taken from run b, diss[1, b]
    the integral of the shared energy (both carried between calls).

    With damping on, a step is D(dt/2) S(dt) D(dt/2): S the splitting step, D the damping
    flow with the positions frozen (``dissipate``), whose factors depend on the positions
    only and so serve the end of one step and the start of the next.  The energy audit is
    then of H + W: each exact pair flow removes exactly the kinetic energy it adds to W.
    """
    ah, bh, dt, steps = scheme
    mode, renorm, gali_k, megno, t0 = tangent
    h0, bound, status, fail_segment, fail_energy, worst = audit
    rec_shared, rec_members, traj, stride, rec_logs, rec_gali, rec_megno, rec_work, wsamp = rec
    on, c0, weighted, integrate = damp
    D, B = q.shape
    M = dq.shape[1]
    s = ah.shape[0]
    a = np.empty((D, B))
    h = np.empty((hessian_rows(D), B))
    total = np.empty(B)
    shared = np.empty(B)
    K = members_of(D)
    members = np.empty((K, B))
    work = np.empty(B)
    f = np.empty((MEMBER_COORDS * K, B))
    lost = np.empty(B)
    ec = np.empty(B)
    ec_prev = np.empty(B)
    tau = 0.25 * dt  # D(dt/2): the pair flows over dt/4 each way
    if on:
        damping_factors(q, P, c0, weighted, tau, f)
    if integrate:
        shared_energy(q, v, P, ec_prev)
    # a block of one run takes the kernels *_one, vectorised across the members (the same
    # numbers; pull is their work space).  The branches are written out at every call: behind
    # a helper function, the copy numba caches ran the single run 2x slower (measured).
    pull = np.empty((SHARED, K))
    # flat views: the kick and the drift treat every entry alike, and one long loop
    # vectorises better than D short ones over a small block
    q_, v_, a_ = q.reshape(D * B), v.reshape(D * B), a.reshape(D * B)
    dq_, dv_ = dq.reshape(D * M * B), dv.reshape(D * M * B)
    if B == 1:
        accelerations_one(q, a, P, pull)
    else:
        accelerations(q, a, P)
    if M > 0:
        if B == 1:
            hessian_one(q, h, P)
        else:
            hessian(q, h, P)
    for seg in range(seg0, seg1):
        for step in range(steps):
            if on:  # the factors of the positions at the end of the previous step
                dissipate(v, f, P, lost)
                for b in range(B):
                    diss[0, b] += lost[b]
            for stage in range(s):
                # kick then drift, fused into one pass over the block
                ck = bh[stage] * dt
                cd = ah[stage] * dt
                for e in range(D * B):
                    v_[e] += ck * a_[e]
                    q_[e] += cd * v_[e]
                if M > 0:
                    if B == 1:
                        tangent_kick_one(h, dq, dv, ck, P, pull)
                    else:
                        tangent_kick(h, dq, dv, ck, P)
                    for e in range(D * M * B):
                        dq_[e] += cd * dv_[e]
                if B == 1:
                    accelerations_one(q, a, P, pull)
                else:
                    accelerations(q, a, P)
                if M > 0:
                    if B == 1:
                        hessian_one(q, h, P)
                    else:
                        hessian(q, h, P)
            ck = bh[s] * dt
            for e in range(D * B):
                v_[e] += ck * a_[e]
            if M > 0:
                if B == 1:
                    tangent_kick_one(h, dq, dv, ck, P, pull)
                else:
                    tangent_kick(h, dq, dv, ck, P)
            if on:
                if weighted:
                    damping_factors(q, P, c0, weighted, tau, f)
                dissipate(v, f, P, lost)
                for b in range(B):
                    diss[0, b] += lost[b]
            if integrate:  # the trapezoid rule over the steps
                shared_energy(q, v, P, ec)
                for b in range(B):
                    diss[1, b] += 0.5 * dt * (ec[b] + ec_prev[b])
                    ec_prev[b] = ec[b]
            g = seg * steps + step + 1
            if mode != NO_TANGENT and renorm > 0 and g % renorm == 0 and step + 1 < steps:
                _renormalise(dq, dv, logs, mode == ORTHONORMALISE)
            if megno:
                _log_norm_first(dq, dv, logs, work)
                for b in range(B):
                    meg[0, b] += 0.5 * dt * (meg[1, b] + work[b])
                    meg[1, b] = work[b]
            if stride > 0 and g % stride == 0:
                for b in range(B):
                    row = traj[rows[b], g // stride]
                    for i in range(SHARED):
                        row[i] = q[i, b]
                        row[SHARED + i] = v[i, b]
                    for i in range(SHARED, D):
                        row[SHARED + i] = q[i, b]
                        row[D + i] = v[i, b]
                    if wsamp.shape[1] > 0:
                        wsamp[rows[b], g // stride] = diss[0, b]
        if mode != NO_TANGENT:
            _renormalise(dq, dv, logs, mode == ORTHONORMALISE)
        energies(q, v, P, total, shared, members)
        failed = False
        for b in range(B):
            r = rows[b]
            H = total[b]
            scale = abs(h0[r]) if h0[r] != 0.0 else 1.0
            if not math.isfinite(H):
                status[r] = NONFINITE
            else:
                err = abs(H + diss[0, b] - h0[r]) / scale
                worst[r] = max(worst[r], err)
                if err > bound:
                    status[r] = DRIFT
            if status[r] != RUNNING:
                fail_segment[r] = seg + 1
                fail_energy[r] = H + diss[0, b]  # H + W with damping
                failed = True
        if rec_shared.shape[1] > 0:
            for b in range(B):
                rec_shared[rows[b], seg + 1] = shared[b]
        if rec_work.shape[1] > 0:
            for b in range(B):
                rec_work[rows[b], seg + 1] = diss[0, b]
        if rec_members.shape[1] > 0:
            for b in range(B):
                for j in range(K):
                    rec_members[rows[b], seg + 1, j] = members[j, b]
        if rec_logs.shape[1] > 0:
            for b in range(B):
                for m in range(M):
                    rec_logs[rows[b], seg + 1, m] = logs[m, b]
        if gali_k > 0:
            _gali(dq, dv, gali_k, work)
            for b in range(B):
                rec_gali[rows[b], seg + 1] = work[b]
        if megno:
            t = t0 + (seg + 1) * steps * dt
            for b in range(B):
                rec_megno[rows[b], seg + 1] = 2.0 * meg[1, b] - 2.0 * meg[0, b] / t
        if failed:
            return seg + 1
    return seg1


@numba.njit(cache=True, parallel=True, error_model="numpy")
def advance(Q, V, DQ, DV, P, weights, seg0, seg1, layout, tangent, logs, meg, audit, rec,
            damp, diss):  # fmt: skip
    """Advance every run (columns of Q, V; P its parameter table, see
    ``parameter_table``) over segments [seg0, seg1); blocks holding a stopped run are
    skipped.

    weights = (a, b): drift and kick weights of the splitting method.  layout = (parts,
    bounds, rows, dt, steps, stride): block i holds the columns bounds[i]:bounds[i + 1] and
    advances with step dt[i], steps[i] steps per segment, a trajectory sample every
    stride[i] steps; thread part j takes the blocks
    parts[j]:parts[j + 1] (:func:`sinktheory.engine.blocks.layout`); rows[c] is the row of
    column c in the audit and record arrays; rec = (shared, members, trajectory, logs,
    gali, megno, work, work_samples) as for ``_run_block`` without the stride; damp and
    diss (2, runs) as for ``_run_block``.
    """
    ah, bh = weights
    parts, bounds, rows, dts, nsteps, strides = layout
    rec_shared, rec_members, traj, rec_logs, rec_gali, rec_megno, rec_work, wsamp = rec
    status = audit[2]
    for j in numba.prange(parts.shape[0] - 1):
        for ib in range(parts[j], parts[j + 1]):
            r0 = bounds[ib]
            r1 = bounds[ib + 1]
            skip = False
            for c in range(r0, r1):
                if status[rows[c]] != RUNNING:
                    skip = True
            if skip:
                continue
            q = Q[:, r0:r1].copy()
            v = V[:, r0:r1].copy()
            dq = DQ[:, :, r0:r1].copy()
            dv = DV[:, :, r0:r1].copy()
            lg = logs[:, r0:r1].copy()
            mg = meg[:, r0:r1].copy()
            p = P[:, r0:r1].copy()
            ds = diss[:, r0:r1].copy()
            scheme = (ah, bh, dts[ib], nsteps[ib])
            records = (rec_shared, rec_members, traj, strides[ib], rec_logs, rec_gali, rec_megno,
                       rec_work, wsamp)  # fmt: skip
            _run_block(q, v, dq, dv, p, scheme, seg0, seg1, rows[r0:r1], tangent, lg, mg,
                       audit, records, damp, ds)  # fmt: skip
            Q[:, r0:r1] = q
            V[:, r0:r1] = v
            DQ[:, :, r0:r1] = dq
            DV[:, :, r0:r1] = dv
            logs[:, r0:r1] = lg
            meg[:, r0:r1] = mg
            diss[:, r0:r1] = ds


def table_of(params, runs):
    """The kernels' parameter table (NTABLE, runs) from parameters shared by every run
    (NPARAMS,) or given per run (NPARAMS, runs); what every kernel and ``block_*`` takes."""
    p = np.asarray(params, dtype=np.float64)
    if p.ndim == 1:
        p = np.repeat(p.reshape(-1, 1), runs, axis=1)
    if p.shape != (NPARAMS, runs):
        raise ValueError(f"params: shape {p.shape}, expected ({NPARAMS},) or ({NPARAMS}, {runs})")
    table = parameter_table(np.ascontiguousarray(p))
    powers = table[POWERS:]
    good = (powers == np.round(powers)) & (np.abs(powers) < MAX_POWER)
    if not np.all(good):
        run = int(np.nonzero(~np.all(good, axis=0))[0][0])
        raise ValueError(
            f"params: run {run} raises a base to the power {powers[:, run].tolist()}: the "
            f"kernels' run-time exponents must be whole numbers of size below {MAX_POWER}"
        )
    return table


@numba.njit(cache=True, error_model="numpy")
def block_energies(Q, V, P):
    """(total, shared, members) energies of every run: (R,), (R,), (K, R); P is the
    parameter table (NTABLE, R)."""
    R = Q.shape[1]
    total = np.empty(R)
    shared = np.empty(R)
    members = np.empty((members_of(Q.shape[0]), R))
    energies(np.ascontiguousarray(Q), np.ascontiguousarray(V), P, total, shared, members)
    return total, shared, members


@numba.njit(cache=True, error_model="numpy")
def block_accelerations(Q, P):
    """Accelerations of every run (D, R); P is the parameter table (NTABLE, R)."""
    a = np.empty(Q.shape)
    accelerations(np.ascontiguousarray(Q), a, P)
    return a
