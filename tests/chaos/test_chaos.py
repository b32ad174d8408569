"""Issue 12: chaos indicators through the engine's symplectic tangent map.

Every check compares with something independent: the symplectic identity and a
finite-difference Jacobian (tangent map), published Henon-Heiles orbits (GALI), the Floquet
theory of y = 0 (transverse exponent), a two-trajectory estimate (lambda_1) and the linear
growth of deviations on an integrable orbit.  A few engine systems are reused so that
compilation stays cheap: sink_flat_n4_k1/k2, sink_symmetric_n6_k1/k2, henon_heiles.
"""

import math

import numba
import numpy as np
import pytest

from sinktheory import RunSettings, Sink, Well
from sinktheory._generated import oscillator as _osc
from sinktheory.canonical import FIG8_WELL, HENON_HEILES, SYMMETRIC_WELL
from sinktheory.chaos import (
    chaos,
    finite_difference_jacobian,
    indicators,
    monodromy,
    symplectic_defect,
    two_orbit_exponent,
)
from sinktheory.chaos.sink import transverse_mask
from sinktheory.ensemble import (
    engine_name,
    engine_params,
    random_positions,
    split_values,
    start_state,
)
from sinktheory.errors import ParameterError
from sinktheory.floquet import model_hill

T = 2 * math.pi
STEPS = 800  # steps per container period in these tests (energy error ~1e-12 here)
DT = T / STEPS
FLAT1 = Sink(FIG8_WELL, particles=1, mass=0.2)  # Fig. 8 well, chaotic
SINKS = [
    FLAT1,
    Sink(FIG8_WELL, particles=2, mass=0.2),
    Sink(SYMMETRIC_WELL, particles=1, mass=0.2),
    Sink(SYMMETRIC_WELL, particles=2, mass=0.2),
]
HH_CHAOTIC = (0.0, -0.25, 0.42081, 0.0)  # Skokos et al., Physica D 231 (2007) 30, Fig. 1
HH_REGULAR = [(0.0, 0.295456, 0.407308431, 0.0), (0.0, 0.483, 0.278980390, 0.0)]


def _sink_state(sink, runs=1, seed=4):
    values = start_state(
        sink, 0.5, random_positions(RunSettings(runs=runs, seed=seed), 1 * sink.particles)
    )
    return split_values(values)


def _hh(ic):
    x, y, px, py = ic
    return np.array([[x], [y]]), np.array([[px], [py]])  # unit masses: v = p


def _masses(sink):
    return np.r_[1.0, np.full(2 * sink.particles, sink.mu)]


# --------------------------------------------------------------------------- tangent map
@pytest.mark.parametrize("sink", SINKS, ids=lambda s: f"{s.well.shape}-k{s.particles}")
def test_monodromy_is_symplectic_and_is_the_jacobian(sink):
    """M^T J M = J in canonical (q, p = m v) coordinates over one container period, to
    1e-13 relative to |M|^2 (round-off of the product is eps |M|^2); and M equals the
    central-difference Jacobian of the same discrete map: error O(h^2) + O(eps/h), measured
    2e-8 to 2e-7 |M| at h = 1e-6 (tolerance 1e-6), falling 9-fold when h falls 3-fold."""
    q, v = _sink_state(sink, runs=2)
    args = (engine_name(sink), q, v, engine_params(sink))
    M = monodromy(*args, dt=DT, steps=STEPS)
    assert np.abs(M).max() > 10  # a stretching period: the check is not on a near-identity
    assert symplectic_defect(M, _masses(sink)).max() < 1e-13
    F = finite_difference_jacobian(*args, dt=DT, steps=STEPS, h=1e-6)
    assert np.abs(F - M).max() < 1e-6 * np.abs(M).max()
    if sink is FLAT1:  # second order: the difference is the truncation error, not a bug
        e1, e2 = (
            np.abs(finite_difference_jacobian(*args, dt=DT, steps=STEPS, h=h) - M).max()
            for h in (9e-5, 3e-5)
        )
        assert 7 < e1 / e2 < 11


def test_henon_heiles_monodromy_is_symplectic():
    q, v = _hh(HH_CHAOTIC)
    M = monodromy(HENON_HEILES, q, v, [], dt=0.01, steps=100, segments=50)
    assert symplectic_defect(M, np.ones(2))[0] < 1e-13
    F = finite_difference_jacobian(HENON_HEILES, q, v, [], dt=0.01, steps=100, segments=50)
    assert np.abs(F - M).max() < 1e-7 * np.abs(M).max()


def test_a_wrong_tangent_map_would_be_caught():
    """The checks have teeth: dropping the coupling of the tangent map (block-diagonal M)
    gives a defect of order one."""
    q, v = _hh(HH_CHAOTIC)
    M = monodromy(HENON_HEILES, q, v, [], dt=0.01, steps=100, segments=5)
    damaged = M.copy()
    damaged[:, 0, 1] = damaged[:, 1, 0] = 0.0
    assert symplectic_defect(damaged, np.ones(2))[0] > 1e-3


# --------------------------------------------------------------------------- spectrum
def test_spectrum_pairs_and_zero_exponents():
    """A symplectic flow has lambda_i + lambda_{2N+1-i} = 0 and two zero exponents (energy
    and the flow direction).  Finite-time QR exponents reach them like 1/t (the norm of
    (q, v) differs from a canonical one by the mass ratio 25: ln 25 / t): tolerance 10 / t,
    against lambda_1 ~ 0.8."""
    res = chaos(FLAT1, RunSettings(runs=2, periods=300, seed=0), spectrum=True, dt=DT)
    t = res.duration
    s = res.spectrum
    assert s.shape == (2, 6)
    assert np.all(np.diff(s, axis=1) < 0)
    assert s[:, 0].min() > 100 / t  # chaotic: lambda_1 well above the tolerance
    assert np.abs(res.pair_sums).max() < 10 / t
    assert np.abs(s[:, 2:4]).max() < 10 / t  # the two zero exponents
    np.testing.assert_array_equal(res.lambda1, s[:, 0])  # vector 0 of the QR = lambda_1


def test_half_spectrum_is_the_top_of_the_full_one_and_pairs_the_rest():
    """spectrum="half" carries D of the 2D vectors: modified Gram-Schmidt treats vector i
    independently of the vectors after it, so its D exponents are bitwise the full
    computation's first D (same seeded vectors); the lower half is their pairing, which
    the full computation reaches to within its pair sums (10 / t, as above)."""
    settings = RunSettings(runs=2, periods=150, seed=4)
    full = chaos(FLAT1, settings, spectrum=True, dt=DT)
    half = chaos(FLAT1, settings, spectrum="half", dt=DT)
    D = full.spectrum.shape[1] // 2
    assert half.spectrum_logs.shape[-1] == D and half.spectrum_paired
    np.testing.assert_array_equal(half.spectrum[:, :D], full.spectrum[:, :D])
    np.testing.assert_allclose(half.spectrum, full.spectrum, atol=10 / full.duration, rtol=0)
    assert half.pair_sums is None and "pair_sums" not in half.as_dict()
    assert half.to_dataset().spectrum.shape == (2, 2 * D)


@pytest.mark.parametrize("bad", ["quarter", 2, "True"])
def test_bad_spectrum_option_is_refused_naming_it(bad):
    with pytest.raises(ParameterError, match="^spectrum = "):
        chaos(FLAT1, RunSettings(runs=1, periods=1), spectrum=bad, dt=DT)


# --------------------------------------------------------------------------- Henon-Heiles
def test_henon_heiles_gali2_chaotic_and_regular():
    """Skokos et al. (2007): at E = 1/8 the chaotic orbit's GALI_2 falls below 1e-12 before
    t = 1000, the regular orbits' stays above 0.01 (it fluctuates about a level set by the
    start vectors; here the unit position deviations dx, dy: measured minima 0.39 and
    0.78).  With seeded random vectors the chaotic orbit falls just the same."""
    xy = (np.eye(2)[:, :, None], np.zeros((2, 2, 1)))  # deviation vectors dx and dy
    kw = {"dt": 0.01, "steps": 100, "segments": 1000, "gali": 2}
    q, v = _hh(HH_CHAOTIC)
    res = indicators(HENON_HEILES, q, v, [], vectors=xy, **kw)
    assert abs(res.parameters["dt"] * 100 * 1000 - 1000) < 1e-9
    assert res.gali[0].min() < 1e-12
    assert res.sali[0].min() < 1e-12  # SALI ~ GALI_2 for nearly parallel vectors
    random = indicators(HENON_HEILES, q, v, [], seed=5, **kw)
    assert random.gali[0].min() < 1e-12
    for ic in HH_REGULAR:
        q, v = _hh(ic)
        res = indicators(HENON_HEILES, q, v, [], vectors=xy, **kw)
        assert res.gali[0].min() > 0.01, ic
        assert res.run_errors[0] < 1e-10


def test_megno_separates_regular_from_chaotic():
    """<Y> -> 2 on a quasi-periodic orbit; <Y> ~ lambda_1 t / 2 on a chaotic one
    (Cincotta & Simo 2000).  Tolerances: 0.05 (regular, t = 5000; <Y> - 2 = O(1/t) with
    oscillations, measured 0.006-0.03 over seeds) and 15 %."""
    q, v = _hh(HH_REGULAR[1])
    res = indicators(HENON_HEILES, q, v, [], dt=0.01, steps=100, segments=5000, megno=True)
    assert abs(res.mean_megno[0, -1] - 2) < 0.05
    q, v = _hh(HH_CHAOTIC)
    res = indicators(HENON_HEILES, q, v, [], dt=0.01, steps=100, segments=1000, megno=True)
    expected = res.lambda1[0] * res.duration / 2
    assert abs(res.mean_megno[0, -1] / expected - 1) < 0.15


# --------------------------------------------------------------------------- references
@pytest.mark.parametrize("beta", [0.2, 0.4])
def test_transverse_exponent_equals_floquet(beta):
    """A particle of mass 1e-6 on y = 0 at rest at x0 = alpha - beta (rescaled amplitude 1),
    container almost at rest: its y-deviation grows at ln|rho| / T_n per rescaled time,
    i.e. at floquet_exponent * sqrt(gamma / mu) / (alpha - beta) per unit time
    (tests/oscillator/test_floquet_vs_simulation.py).  Segments are whole periods T_n of the
    x-motion, so the growth between two segment ends is exactly a power of the monodromy
    (up to the decaying Floquet mode, dropped with the first 20 periods).  Tolerance 1e-3;
    measured 2e-6 (the container's recoil, O(mu))."""
    alpha, n, gamma, mu = 0.5, 4, 1.0, 1e-6
    L = alpha - beta
    chart = model_hill(alpha, [beta], n)
    assert not chart.stable[0]
    rate = chart.floquet_exponent[0] * math.sqrt(gamma / mu) / L
    period = _osc.period(n, 1.0) * L * math.sqrt(mu / gamma)
    sink = Sink(Well(alpha, beta, n, gamma=gamma), particles=1, mass=mu)
    q, v = split_values(start_state(sink, 1e-12, np.array([[[L, 0.0]]])))
    res = indicators(
        engine_name(sink),
        q,
        v,
        engine_params(sink),
        dt=period / 200,
        steps=200,
        segments=200,
        transverse=(q, v, transverse_mask(1)),
    )
    logs = res.transverse_logs[0]
    measured = (logs[-1] - logs[20]) / (res.times[-1] - res.times[20])
    assert abs(measured / rate - 1) < 1e-3
    assert res.run_errors[0] < 1e-10


def test_lambda1_agrees_with_two_trajectories():
    """Tangent map versus a shadow orbit at d0 = 1e-9 renormalised every period, along the
    same reference orbits from the same direction: the two differ by the nonlinearity
    d0 e^(lambda T) and round-off eps / d0; tolerance 1e-3 relative (measured 3e-5)."""
    q, v = _sink_state(FLAT1, runs=2, seed=2)
    args = (engine_name(FLAT1), q, v, engine_params(FLAT1))
    res = indicators(*args, dt=DT, steps=STEPS, segments=150, seed=2)
    logs = two_orbit_exponent(*args, dt=DT, steps=STEPS, segments=150, seed=2)
    two = logs[:, -1] / res.duration
    assert res.lambda1.min() > 0.1
    np.testing.assert_allclose(res.lambda1, two, rtol=1e-3)


@pytest.mark.parametrize("d0", [1e-300, 1e-15, 0.01])
def test_two_orbit_separation_outside_its_range_is_refused(d0):
    # 1e-300 vanished after one step (log 0 = -inf reached the caller as an exponent)
    q, v = _sink_state(FLAT1, runs=1, seed=2)
    with pytest.raises(ParameterError, match=r"d0 = .* in \["):
        two_orbit_exponent(engine_name(FLAT1), q, v, engine_params(FLAT1), dt=DT,
                           steps=STEPS, segments=1, d0=d0)  # fmt: skip


def test_integrable_case_decays_like_log_t_over_t():
    """beta = 0 separates the well (x and y independent) and a particle of mass 1e-6 barely
    moves the container: the orbit is regular, deviations grow linearly (shear of the
    nonlinear oscillators), ln|delta| ~ ln t, so lambda_1(t) ~ ln t / t.  Slope of
    ln|delta| against ln t over the last decade: 1 within 0.1 (measured 0.97); a chaotic
    orbit would grow linearly in t, a periodic one not at all."""
    sink = Sink(Well(0.5, 0.0, 4), particles=1, mass=1e-6)
    q, v = split_values(start_state(sink, 1e-12, np.array([[[0.4, 0.3]]])))
    unit = 4 * math.sqrt(sink.mu)  # a few periods of the particle (time scale sqrt(mu))
    res = indicators(
        engine_name(sink),
        q,
        v,
        engine_params(sink),
        dt=unit / 100,
        steps=100,
        segments=2000,
        seed=1,
    )
    t, logs = res.times[1:], res.log_growth[0, 1:]
    slope = np.polyfit(np.log(t[200:]), logs[200:], 1)[0]
    assert abs(slope - 1) < 0.1
    lam = res.finite_time_lambda1[0]
    assert lam[-1] < lam[199] / 5  # decays ...
    assert lam[-1] * t[-1] / math.log(t[-1] / t[0]) < 3  # ... like ln t / t


# --------------------------------------------------------------------------- ensembles
def test_bitwise_reproducible_for_any_threads_and_blocks():
    sink = SINKS[1]
    settings = RunSettings(runs=5, periods=15, seed=7)

    def run(threads, block):
        old = numba.get_num_threads()
        numba.set_num_threads(threads)
        try:
            return chaos(
                sink,
                settings,
                spectrum=True,
                gali=3,
                megno=True,
                transverse=True,
                dt=DT,
                block=block,
            )
        finally:
            numba.set_num_threads(old)

    a = run(1, 1)
    b = run(numba.config.NUMBA_NUM_THREADS, 2)
    c = run(numba.config.NUMBA_NUM_THREADS, None)
    for other in (b, c):
        for name in ("log_growth", "spectrum_logs", "gali", "megno", "transverse_logs"):
            np.testing.assert_array_equal(getattr(a, name), getattr(other, name), err_msg=name)


def test_ensemble_mean_and_outputs():
    res = chaos(FLAT1, RunSettings(runs=3, periods=30, seed=1), gali=2, megno=True, dt=DT)
    m, se = res.mean("lambda1")
    assert m == pytest.approx(res.lambda1.mean(), rel=1e-15)
    assert se == pytest.approx(res.lambda1.std(ddof=1) / math.sqrt(3), rel=1e-12)
    d = res.as_dict(series=True)
    assert d["lambda1"]["runs"] == pytest.approx(res.lambda1.tolist())
    assert len(d["series"]["times"]) == 31
    ds = res.to_dataset()
    np.testing.assert_array_equal(ds.gali.values, res.gali)
    ends, w = res.window_exponents(10)
    assert w.shape == (3, 3)
    # windows tile the run: their time-weighted mean is the whole-run exponent
    np.testing.assert_allclose(w.mean(axis=1), res.lambda1, rtol=1e-12)
    # same seed, same runs as simulate: the orbit's energy is audited the same way
    assert res.run_errors.max() < 1e-8


def test_bad_input():
    with pytest.raises(ParameterError, match="gali"):
        chaos(FLAT1, RunSettings(runs=1, periods=1), gali=1)
    with pytest.raises(ParameterError, match="gali"):
        chaos(FLAT1, RunSettings(runs=1, periods=1), gali=7)
    with pytest.raises(ParameterError, match="renorm"):
        chaos(FLAT1, RunSettings(runs=1, periods=1), renorm=-1)
    with pytest.raises(ParameterError, match="initial"):
        chaos(FLAT1, RunSettings(runs=2, periods=1), initial=[(0.0, 0.0)])


# --------------------------------------------------------------------------- sweep kind
def test_chaos_sweep_kind_is_the_api_at_the_point_seed():
    from sinktheory.sweep import run_sweep

    ds = run_sweep(
        "chaos",
        {"alpha": 0.5, "beta": [0.1, 0.3], "n": 4, "runs": 3, "periods": 10, "dt": DT,
         "transverse": 1},
        workers=1,
        progress=False,
    )  # fmt: skip
    for i, beta in enumerate((0.1, 0.3)):
        seed = int(ds.point_seed.values[i])
        res = chaos(Sink(Well(0.5, beta, 4), 1, 0.2), RunSettings(runs=3, periods=10, seed=seed),
                    transverse=True, dt=DT)  # fmt: skip
        np.testing.assert_array_equal(ds.lambda1_runs.values[i], res.lambda1)
        assert ds.lambda1.values[i] == pytest.approx(res.lambda1.mean(), rel=1e-15)
        assert ds.transverse.values[i] == pytest.approx(res.transverse.mean(), rel=1e-15)
    assert np.isnan(ds.gali.values).all()


def test_chaos_map_verdicts_and_agreement():
    """The mean verdict rule on a synthetic map: chaotic iff mean - 2 s.e. > 3 ln t / t;
    the agreement with a theory judged run by run (each run regular iff its lambda_1 <=
    3 ln t / t), its mixed beta left unscored."""
    import xarray as xr

    from sinktheory.chaos.verdicts import agreement, threshold, verdicts

    thr = threshold(100)
    assert thr == pytest.approx(3 * math.log(200 * math.pi) / (200 * math.pi))
    runs = [[0.49, 0.51], [0.0, 4 * thr], [0.5 * thr, 0.5 * thr], [0.39, 0.41]]
    ds = xr.Dataset(
        {
            "lambda1": ("beta", [0.5, 2 * thr, 0.5 * thr, 0.4]),
            "lambda1_se": ("beta", [0.01, 2 * thr, 0.0, 0.01]),
            "lambda1_runs": (("beta", "run"), runs),
            "lambda1_periods": ("beta", [100.0] * 4),
            "transverse": ("beta", [0.5, 0.0, 0.0, 0.0]),
            "transverse_se": ("beta", [0.01, 0.0, 0.0, 0.0]),
        },
        coords={"beta": [0.0, 0.1, 0.2, 0.3], "run": [0, 1]},
        attrs={"periods": 100},
    )
    # mean rule: chaotic at betas 0 and 3 (beta 1 is within 2 s.e. of the threshold)
    assert verdicts(ds)["chaotic"].tolist() == [True, False, False, True]
    a = agreement(ds, stable=np.array([False, True, True, True]))
    assert (a["chaotic"], a["regular"], a["mixed"], a["scored"]) == (2, 1, 1, 3)
    assert a["mixed_beta"] == [0.1] and a["regular_fraction"] == [0.5]
    assert a["floquet"] == pytest.approx(2 / 3)  # beta 3 chaotic although Floquet-stable
    assert a["transverse"] == pytest.approx(2 / 3)  # beta 3 chaotic, transverse regular


def test_tol_sets_the_step_and_is_refused_with_dt():
    from sinktheory.simulate import simulate

    sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    settings = RunSettings(runs=1, periods=2, seed=3)
    for tol in (1e-6, 1e-10):
        res = chaos(sink, settings, tol=tol, scheme="blanes-moan6")
        plain = simulate(sink, settings, tol=tol, scheme="blanes-moan6", progress=False)
        assert res.parameters["steps_per_segment"] == plain.steps_per_period
    with pytest.raises(ParameterError, match="^tol = "):
        chaos(sink, settings, tol=1e-6, dt=0.01)
