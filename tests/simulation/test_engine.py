"""The generated ensemble engine: kernels against the exact model, the tangent map, and
bitwise reproducibility whatever the block size or thread count.

References: the separable Hamiltonian of :func:`sinktheory.symbolic.separable_hamiltonian`
differentiated by SymPy and evaluated exactly (rationals) -- not the atom-form expressions
the engine is printed from -- and a central finite difference of the engine's own step map
(an independent numerical derivative) for the tangent map.
"""

import numba
import numpy as np
import pytest
import sympy as sp

from sinktheory import RunSettings, Sink
from sinktheory import symbolic as S
from sinktheory.canonical import FIG8_WELL, HENON_HEILES
from sinktheory.engine.cache import load, sink_name
from sinktheory.engine.core import Ensemble
from sinktheory.ensemble import engine_params, random_positions, split_values, start_state
from sinktheory.errors import ParameterError
from sinktheory.integrators import get_scheme

RTOL = 1e-12
STATE = [sp.Rational(3, 10), sp.Rational(4, 10), sp.Rational(1, 10)]
STATE += [sp.Rational(-1, 5), sp.Rational(1, 3)]
PARAMS = {S.alpha: sp.Rational(1, 2), S.beta: sp.Rational(1, 5), S.gamma: 1}
PARAMS[S.mu] = sp.Rational(1, 10)


def _state(k):
    """STATE (X, u_1, u_2, y_1, y_2) for k = 2, (X, u_1, y_1) for k = 1."""
    return STATE if k == 2 else [STATE[0], STATE[1], STATE[3]]


def _exact(shape, n, k=2):
    sh = S.separable_hamiltonian(k, shape)
    U = sh.potential.subs(S.n, n).subs(PARAMS)
    point = dict(zip(sh.coordinates, _state(k), strict=True))
    masses = [m.subs(PARAMS) for m in sh.masses]
    grad = [sp.diff(U, q).subs(point) for q in sh.coordinates]
    hess = [[sp.diff(U, a, b).subs(point) for b in sh.coordinates] for a in sh.coordinates]
    return sh, U.subs(point), masses, grad, hess


# the symmetric well with one particle: SymPy's separation of its k = 2 Hamiltonian takes
# about 50 s (the member loop is checked on the flat well with two particles)
@pytest.mark.parametrize("shape, n, k", [("flat", 3, 2), ("symmetric", 6, 1), ("flat", 37, 2)])
def test_kernels_match_the_separable_hamiltonian(shape, n, k):
    """a = -grad U / m, the tangent kick = -c Hess U dq / m and H, against exact SymPy."""
    sh, U, masses, grad, hess = _exact(shape, n, k)
    mod = load(sink_name(shape))
    D = 1 + 2 * k
    q = np.array([[float(s)] for s in _state(k)])
    P = mod.table_of([*(float(PARAMS[s]) for s in (S.alpha, S.beta, S.gamma)), n, PARAMS[S.mu]], 1)
    a = mod.block_accelerations(q, P)[:, 0]
    expected = [-float(g / m) for g, m in zip(grad, masses, strict=True)]
    np.testing.assert_allclose(a, expected, rtol=RTOL, atol=RTOL * np.max(np.abs(expected)))

    h = np.empty((mod.hessian_rows(D), 1))
    mod.hessian(q, h, P)
    rng = np.random.default_rng(1)
    dq = rng.normal(size=(D, 3, 1))
    dv = np.zeros_like(dq)
    mod.tangent_kick(h, dq, dv, 0.5, P)
    H = np.array([[float(e) for e in row] for row in hess])
    im = np.array([1 / float(m) for m in masses])
    expected = -0.5 * im[:, None] * (H @ dq[:, :, 0])
    np.testing.assert_allclose(dv[:, :, 0], expected, rtol=1e-11, atol=1e-11 * abs(expected).max())

    v = rng.normal(size=(D, 1))
    total, shared, members = mod.block_energies(q, v, P)
    kinetic = sum(0.5 * float(m) * v[i, 0] ** 2 for i, m in enumerate(masses))
    assert total[0] == pytest.approx(kinetic + float(U), rel=RTOL)
    assert total[0] == pytest.approx(shared[0] + members[:, 0].sum(), rel=1e-15)
    assert shared[0] == pytest.approx(0.5 * v[0, 0] ** 2 + 0.5 * float(STATE[0]) ** 2, rel=1e-15)


@pytest.mark.parametrize("system", ["sink_flat", "sink_symmetric", "sink_circular", HENON_HEILES])
def test_single_run_kernels_are_bitwise_the_block_kernels(system):
    """The one-run kernels (vectorised across the particles, the container's share summed
    afterwards) give each run the bits the block kernels give it, signed zeros included,
    for any number of particles and per-run parameters: with one exponent n for the
    whole block (a scalar power) and with a different n in every run (a power per run)."""
    mod = load(system)
    rng = np.random.default_rng(7)
    for k in (0, 1, 5, 13) if mod.MEMBER_COORDS else (0,):
        D, R, M = mod.SHARED + mod.MEMBER_COORDS * k, 6, 3
        q = rng.uniform(-0.6, 0.6, size=(D, R))
        q[:, 0] = 0.0  # every force term is a signed zero here
        q[:, 1] = -0.0
        params = rng.uniform(0.2, 0.4, size=(mod.NPARAMS, R))
        if mod.MEMBER_COORDS:  # n: the same in every run, then a different one in each
            params[3] = 4 if k < 5 else rng.permutation([1, 2, 4, 9, 17, 40])
        P = mod.table_of(params, R)
        dq, dv = rng.normal(size=(D, M, R)), rng.normal(size=(D, M, R))
        a = mod.block_accelerations(q, P)
        # every term is a signed zero in runs 0 and 1: sums from a zeroed array give +0.0
        assert not np.signbit(a[:, :2]).any()
        h = np.empty((mod.hessian_rows(D), R))
        mod.hessian(q, h, P)
        kicked = dv.copy()
        mod.tangent_kick(h, dq, kicked, 0.3, P)
        w = np.empty((mod.SHARED, k))
        for r in range(R):
            col = slice(r, r + 1)
            Pr = P[:, col].copy()
            a1, h1, dv1 = np.empty((D, 1)), np.empty((h.shape[0], 1)), dv[:, :, col].copy()
            mod.accelerations_one(q[:, col].copy(), a1, Pr, w)
            mod.hessian_one(q[:, col].copy(), h1, Pr)
            mod.tangent_kick_one(h1, dq[:, :, col].copy(), dv1, 0.3, Pr, w)
            assert a1.tobytes() == a[:, col].copy().tobytes(), (k, r)
            assert h1.tobytes() == h[:, col].copy().tobytes(), (k, r)
            assert dv1.tobytes() == kicked[:, :, col].copy().tobytes(), (k, r)


def test_symbol_names_the_kernels_use_are_refused():
    """A system symbol named like a kernel's own variable (the circular well's atom w once
    met the work array w) is refused when the engine is printed, not miscompiled."""
    from sinktheory.engine.printer import render
    from sinktheory.engine.systems import SeparableSystem, Term

    pull, x = sp.symbols("pull x", real=True)
    term = Term._plain((pull, x), (pull, x), pull**2 * x**2)
    system = SeparableSystem("clash", (pull, x), (sp.Integer(1),) * 2, shared_terms=(term,))
    with pytest.raises(ValueError, match=r"\['pull'\]"):
        render(system, "")


def _fig8_like(runs, k=2):
    sink = Sink(FIG8_WELL, particles=k, mass=0.2)
    values = start_state(sink, 0.5, random_positions(RunSettings(runs=runs, seed=4), k))
    return sink, *split_values(values)


def test_tangent_map_is_the_jacobian_of_the_step_map():
    """Deviation vectors after 40 steps equal a central difference of the flow map."""
    sink, q, v = _fig8_like(1)
    scheme, dt, steps = get_scheme("blanes-moan6"), 2e-3, 40
    D = q.shape[0]
    eye = np.eye(2 * D)
    ens = Ensemble(
        sink_name("flat"),
        q,
        v,
        engine_params(sink),
        dq=eye[:D, :, None].copy(),
        dv=eye[D:, :, None].copy(),
    )
    ens.run(scheme, dt=dt, steps=steps, segments=1, record=())
    jac = np.vstack([ens.dq[:, :, 0], ens.dv[:, :, 0]])
    eps = 1e-6
    fd = np.empty_like(jac)
    for col in range(2 * D):
        ends = []
        for sign in (1, -1):
            z = np.concatenate([q[:, 0], v[:, 0]])
            z[col] += sign * eps
            e = Ensemble(sink_name("flat"), z[:D, None], z[D:, None], engine_params(sink))
            e.run(scheme, dt=dt, steps=steps, segments=1, record=())
            ends.append(np.concatenate([e.q[:, 0], e.v[:, 0]]))
        fd[:, col] = (ends[0] - ends[1]) / (2 * eps)
    # central differences: truncation ~eps^2 |third derivative|, round-off ~1e-16/eps
    np.testing.assert_allclose(jac, fd, atol=1e-7 * np.abs(jac).max())


@pytest.mark.parametrize("tangent", ["none", "orthonormalise"])
def test_bitwise_identical_for_any_block_size_and_thread_count(tangent):
    sink, q, v = _fig8_like(11)
    D = q.shape[0]
    rng = np.random.default_rng(0)
    dq0, dv0 = rng.normal(size=(D, 3, 11)), rng.normal(size=(D, 3, 11))
    results = []
    threads = numba.get_num_threads()
    try:
        for block, nthreads in [(64, 1), (1, 1), (3, threads), (5, threads), (11, threads)]:
            numba.set_num_threads(nthreads)
            ens = Ensemble(
                sink_name("flat"),
                q,
                v,
                engine_params(sink),
                dq=dq0,
                dv=dv0,
                tangent=tangent,
            )
            rec = ens.run(
                get_scheme("blanes-moan6"),
                dt=2 * np.pi / 400,
                steps=400,
                segments=3,
                record=("shared", "members", "logs"),
                block=block,
            )
            results.append((ens.q, ens.v, ens.dq, rec.shared, rec.members, rec.logs))
    finally:
        numba.set_num_threads(threads)
    for other in results[1:]:
        for a, b in zip(results[0], other, strict=True):
            assert np.array_equal(a, b)


def _run(q, v, params, **options):
    """Final state and records of a 3-period ensemble (blanes-moan6, 400 steps)."""
    ens = Ensemble(sink_name("flat"), q, v, params)
    rec = ens.run(get_scheme("blanes-moan6"), dt=2 * np.pi / 400, steps=400, segments=3,
                  record=("shared", "members"), **options)  # fmt: skip
    return ens.q, ens.v, rec.shared, rec.members, rec.worst


@pytest.mark.parametrize("runs", [1, 5, 13, 17])
def test_automatic_plan_with_inert_copies_is_bitwise_the_plain_run(runs):
    """Whatever block, padding and threads the policy picks, each run's numbers equal a
    one-run-per-block computation bit for bit, and no inert copy leaks into the results."""
    sink, q, v = _fig8_like(runs)
    auto = _run(q, v, engine_params(sink))
    plain = _run(q, v, engine_params(sink), block=1)
    assert auto[0].shape == q.shape and auto[2].shape[0] == runs and auto[4].shape == (runs,)
    for a, b in zip(auto, plain, strict=True):
        assert a.shape == b.shape and np.array_equal(a, b)


def test_runs_with_their_own_parameters_equal_separate_ensembles():
    """One ensemble over a grid of (beta, n, mu) equals one ensemble per point, bitwise:
    a block whose runs differ in n raises each run to its own power, a run alone raises
    all to one, with the same products."""
    sink, q, v = _fig8_like(6)
    base = engine_params(sink)
    grid = np.repeat(base[:, None], 6, axis=1)
    grid[1] = [0.1, 0.1, 0.2, 0.2, 0.3, 0.3]  # beta
    grid[3] = [4, 2, 10, 4, 3, 40]  # n
    grid[4] = [0.05, 0.1, 0.05, 0.1, 0.05, 0.1]  # mu
    together = _run(q, v, grid)
    for r in range(6):
        alone = _run(q[:, r : r + 1], v[:, r : r + 1], grid[:, r])
        assert np.array_equal(together[0][:, r], alone[0][:, 0])
        assert np.array_equal(together[2][r], alone[2][0])
        assert np.array_equal(together[3][r], alone[3][0])


@pytest.mark.parametrize("kind", ["contact", "viscous"])
def test_damped_runs_are_bitwise_for_any_block_size_and_chunking(kind):
    """With the damping on, each run's numbers (state, work, the shared energy's integral)
    are the same bits in any block or thread and whether the segments run in one call or
    in pieces (the factors and the trapezoid's last value are recomputed, not carried)."""
    sink, q, v = _fig8_like(5)
    results = []
    for block, pieces in [(1, (3,)), (5, (3,)), (2, (1, 2))]:
        ens = Ensemble(sink_name("flat"), q, v, engine_params(sink), damping=0.7,
                       damping_kind=kind)  # fmt: skip
        for segments in pieces:
            rec = ens.run(get_scheme("blanes-moan6"), dt=2 * np.pi / 400, steps=400,
                          segments=segments, record=("shared", "work", "integral"),
                          block=block)  # fmt: skip
        results.append((ens.q, ens.v, rec.work[:, -1], rec.integral))
    assert np.all(results[0][2] > 0)
    for other in results[1:]:
        for a, b in zip(results[0], other, strict=True):
            assert np.array_equal(a, b)


def test_damping_is_refused_where_it_cannot_apply():
    sink, q, v = _fig8_like(2)
    with pytest.raises(ParameterError, match="damping"):
        Ensemble(sink_name("flat"), q, v, engine_params(sink), damping=-1.0)
    with pytest.raises(ParameterError, match="damping_kind"):
        Ensemble(sink_name("flat"), q, v, engine_params(sink), damping=1.0,
                 damping_kind="magnetic")  # fmt: skip
    hh = np.array([[0.0], [0.1]]), np.array([[0.3], [0.0]])
    with pytest.raises(ParameterError, match="has no damping"):
        Ensemble("henon_heiles", *hh, [], damping=1.0)


def test_parameters_of_the_wrong_shape_are_refused():
    sink, q, v = _fig8_like(3)
    with pytest.raises(ValueError, match="params"):
        Ensemble(sink_name("flat"), q, v, np.ones((4, 2)))


def test_take_continues_the_chosen_runs_bitwise():
    sink, q, v = _fig8_like(7)
    D = q.shape[0]
    rng = np.random.default_rng(3)
    vectors = {"dq": rng.normal(size=(D, 1, 7)), "dv": rng.normal(size=(D, 1, 7))}
    scheme, dt = get_scheme("blanes-moan6"), 2 * np.pi / 400

    def fresh():
        return Ensemble(sink_name("flat"), q, v, engine_params(sink), tangent="normalise",
                        **vectors)  # fmt: skip

    whole = fresh()
    whole.run(scheme, dt=dt, steps=400, segments=4, record=())
    part = fresh()
    part.run(scheme, dt=dt, steps=400, segments=2, record=())
    kept = np.array([1, 4, 6])
    part = part._take(kept)
    rec = part.run(scheme, dt=dt, steps=400, segments=2, record=("logs",))
    assert part.runs == 3 and part.time == whole.time
    for name in ("q", "v", "dq", "dv", "logs"):
        assert np.array_equal(getattr(part, name), getattr(whole, name)[..., kept]), name
    assert np.array_equal(rec.logs[:, -1, 0], whole.logs[0, kept])


def _mixed_steps_run(q, v, params, steps, *, block=None, threads=None, dq=None, dv=None):
    """State, records and audit of 3 periods with ``steps`` (R,) steps per period."""
    saved = numba.get_num_threads()
    numba.set_num_threads(threads or saved)
    try:
        ens = Ensemble(sink_name("flat"), q, v, params, dq=dq, dv=dv,
                       tangent="none" if dq is None else "normalise")  # fmt: skip
        steps = np.asarray(steps)
        rec = ens.run(get_scheme("blanes-moan6"), dt=2 * np.pi / steps, steps=steps, segments=3,
                      record=("shared", "members", "trajectory") + (("logs",) if dq is not None
                                                                    else ()),
                      stride=steps, megno=dq is not None, block=block)  # fmt: skip
    finally:
        numba.set_num_threads(saved)
    return ens, rec


@pytest.mark.parametrize("block, threads", [(None, None), (1, 1), (2, 2), (4, 2), (64, 1)])
def test_runs_with_their_own_steps_equal_each_step_group_alone(block, threads):
    """Runs taking 300, 400 or 520 steps per period in one ensemble (any block size,
    padding and threads) are bitwise the runs of each step count in an ensemble of their
    own, state, records (the trajectory sampled at period ends: stride = steps per run),
    deviation vectors, MEGNO and audit; the time is the common segment time."""
    sink, q, v = _fig8_like(9)
    D = q.shape[0]
    rng = np.random.default_rng(5)
    dq, dv = rng.normal(size=(D, 1, 9)), rng.normal(size=(D, 1, 9))
    steps = np.array([400, 300, 520, 400, 300, 400, 520, 400, 400])
    params = engine_params(sink)
    mixed, rec = _mixed_steps_run(q, v, params, steps, block=block, threads=threads, dq=dq, dv=dv)
    assert mixed.time == pytest.approx(3 * 2 * np.pi, rel=1e-14)
    for s in np.unique(steps):
        runs = np.flatnonzero(steps == s)
        alone, arec = _mixed_steps_run(q[:, runs], v[:, runs], params, np.full(runs.size, s),
                                       dq=dq[..., runs], dv=dv[..., runs])  # fmt: skip
        for name in ("q", "v", "dq", "dv", "logs", "meg"):
            assert np.array_equal(getattr(mixed, name)[..., runs], getattr(alone, name)), name
        for name in ("shared", "members", "trajectory", "logs", "megno", "worst"):
            assert np.array_equal(getattr(rec, name)[runs], getattr(arec, name)), name


def test_steps_per_run_are_checked():
    sink, q, v = _fig8_like(3)
    ens = Ensemble(sink_name("flat"), q, v, engine_params(sink))
    scheme = get_scheme("verlet")
    with pytest.raises(ParameterError, match="dt, steps"):  # unequal segments
        ens.run(scheme, dt=np.array([0.01, 0.01, 0.02]), steps=np.array([10, 10, 10]), segments=1)
    steps = np.array([10, 20, 10])
    with pytest.raises(ParameterError, match="stride"):  # 3, 5 and 3 samples
        ens.run(scheme, dt=1.0 / steps, steps=steps, segments=1, stride=5,
                record=("trajectory",))  # fmt: skip
    with pytest.raises(ParameterError, match="renorm"):  # it counts steps
        ens.run(scheme, dt=1.0 / steps, steps=steps, segments=1, renorm=5)
    with pytest.raises(ParameterError, match="steps"):
        ens.run(scheme, dt=0.1, steps=np.array([10, 0, 10]), segments=1)
    assert ens.time == 0.0 and ens.segments_done == 0  # nothing ran
