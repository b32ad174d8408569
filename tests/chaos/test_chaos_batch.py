"""Chaos indicators of many set-ups as one ensemble whose runs carry their own parameters:
each set-up's numbers equal its own run of ``chaos`` bit for bit (the reference is the
unbatched computation, which the rest of tests/test_chaos*.py checks against independent
oracles), and the chaos sweep gives the same store whether its points run together or
one by one."""

import json
import math

import numpy as np
import pytest

from sinktheory import RunSettings, Sink, Well
from sinktheory.canonical import HENON_HEILES
from sinktheory.chaos import chaos, chaos_batch
from sinktheory.errors import ParameterError
from sinktheory.stepsize import ladder_step
from sinktheory.sweep.kinds import get_kind

FIELDS = ("log_growth", "spectrum_logs", "gali", "megno", "transverse_logs", "run_errors")


def test_batch_equals_each_setup_alone():
    sinks = [Sink(Well(a, b, 4), particles=2, mass=m) for a, b, m in
             [(0.5, 0.1, 0.2), (0.5, 0.3, 0.1), (0.6, -0.2, 0.2)]]  # fmt: skip
    settings = [RunSettings(runs=r, periods=4, seed=s) for r, s in [(3, 1), (1, 2), (2, 7)]]
    options = {"dt": 0.01, "gali": 3, "megno": True, "transverse": True, "spectrum": "half"}
    together = chaos_batch(sinks, settings, **options)
    for sink, s, res in zip(sinks, settings, together, strict=True):
        alone = chaos(sink, s, **options)
        assert res.parameters == alone.parameters
        for name in FIELDS:
            assert np.array_equal(getattr(res, name), getattr(alone, name)), name


def test_batch_with_a_step_per_setup_equals_each_setup_alone():
    """Set-ups needing different steps still run as one ensemble, each bitwise its own
    ``chaos`` run with its own step, times and exponents included."""
    sinks = [Sink(Well(0.5, b, 4), particles=2, mass=0.2) for b in (0.1, 0.3, -0.2)]
    settings = [RunSettings(runs=r, periods=3, seed=s) for r, s in [(3, 1), (2, 2), (1, 7)]]
    options = {"gali": 2, "megno": True, "transverse": True}
    # 484 and 300 steps per period: (2 pi / 300) x 300 is not 2 pi in floating point, so
    # each set-up needs its own times
    steps = [2 * math.pi / 484, 2 * math.pi / 300, 2 * math.pi / 484]
    together = chaos_batch(sinks, settings, dt=steps, **options)
    for sink, s, dt, res in zip(sinks, settings, steps, together, strict=True):
        alone = chaos(sink, s, dt=dt, **options)
        assert res.parameters == alone.parameters
        for name in (*FIELDS, "times", "lambda1", "transverse"):
            assert np.array_equal(getattr(res, name), getattr(alone, name)), name
    with pytest.raises(ParameterError, match="dt"):
        chaos_batch(sinks, settings, dt=[0.01, 0.02])


def test_batch_refuses_mixed_engines_and_takes_mixed_n():
    """Wells of two shapes need two engines and are refused; two exponents n share one
    engine, and each result is bitwise the result alone."""
    sinks = [Sink(Well(0.5, 0.1, 4), 1, 0.2), Sink(Well(0.5, 0.1, 2, shape="circular"), 1, 0.2)]
    with pytest.raises(ParameterError, match="sinks"):
        chaos_batch(sinks, [RunSettings(runs=1, periods=2)] * 2, dt=0.01)
    sinks = [Sink(Well(0.5, 0.1, 4), 1, 0.2), Sink(Well(0.5, 0.1, 2), 1, 0.2)]
    runs = [RunSettings(runs=2, periods=3, seed=s) for s in (1, 2)]
    both = chaos_batch(sinks, runs, dt=0.01)
    for sink, settings, result in zip(sinks, runs, both, strict=True):
        alone = chaos(sink, settings, dt=0.01)
        assert np.array_equal(result.lambda1, alone.lambda1)
    with pytest.raises(ParameterError, match="sinks, settings"):
        chaos_batch(sinks[:1], [], dt=0.01)


def test_ladder_step_is_never_larger_and_at_most_nine_percent_smaller():
    for s in range(1, 3000, 7):
        dt, steps = ladder_step(2 * math.pi / s)
        assert s <= steps <= math.ceil(s * 2 ** (1 / 8))
        assert dt == pytest.approx(2 * math.pi / steps, rel=1e-15)


def test_chaos_sweep_points_together_equal_points_alone(monkeypatch):
    import sinktheory.chaos

    kind = get_kind("chaos")
    base = {"alpha": 0.5, "n": 2, "runs": 2, "periods": 6, "transverse": 1}
    points = [(kind.complete(base | {"beta": b}), seed) for b, seed in
              [(-0.3, 11), (-0.295, 12), (0.1, 13), (0.102, 14)]]  # fmt: skip
    calls = []
    batch = sinktheory.chaos.chaos_batch
    monkeypatch.setattr(sinktheory.chaos, "chaos_batch", lambda *a, **k: calls.append(1) or
                        batch(*a, **k))  # fmt: skip
    together = kind.compute_many(points)
    steps = {float(o["dt_used"]) for o in together}
    assert 1 < len(steps) < len(points)  # the ladder let neighbours share a step
    assert len(calls) == 1  # and every step ran in one ensemble
    for (p, seed), out in zip(points, together, strict=True):
        alone = kind.compute(p, seed)
        assert set(out) == set(alone)
        for name in out:
            assert np.array_equal(out[name], alone[name], equal_nan=True), name


def test_sections_together_equal_sections_alone():
    from sinktheory.bifurcation import section, section_step, sections

    wells = [Sink(Well(0.5, b, 2), 1, 0.2) for b in (0.1, 0.101, 0.102, -0.6)]
    steps = [section_step(w)[1] for w in wells]
    assert steps[0] == steps[1] == steps[2] != steps[3]  # one ladder rung, and another
    for quantity in ("y", "energy"):
        rows = sections(wells, transient=3, count=4, quantity=quantity)
        for w, row in zip(wells, rows, strict=True):
            alone = section(w, transient=3, count=4, quantity=quantity)
            assert np.array_equal(row, alone)
    with pytest.raises(ParameterError, match="sinks"):
        sections([wells[0], Sink(Well(0.5, 0.1, 4, shape="circular"), 1, 0.2)], transient=1,
                 count=1)  # fmt: skip
    mixed = [wells[0], Sink(Well(0.5, 0.1, 4), 1, 0.2)]  # n = 2 and 4: one engine
    for w, row in zip(mixed, sections(mixed, transient=2, count=3), strict=True):
        assert np.array_equal(row, section(w, transient=2, count=3))


def test_staged_exponents_stop_settled_betas_and_keep_the_rest_bitwise():
    """A settled beta's runs stop at a look with the exponent an unstopped run has at that
    time; an unsettled one runs to the end with chaos_batch's numbers, bit for bit."""
    from sinktheory.chaos.staged import looks, staged_chaos
    from sinktheory.chaos.verdicts import threshold
    from sinktheory.runstats import ensemble_mean

    sinks = [Sink(Well(0.5, b, 2), 1, 0.2) for b in (0.3, -0.3)]
    settings = [RunSettings(runs=4, periods=80, seed=s) for s in (1, 2)]
    steps = [0.05, 0.04]  # one step per beta: still one ensemble
    staged = staged_chaos(sinks, settings, dt=steps, transverse=True, scheme="blanes-moan6")
    full = chaos_batch(sinks, settings, dt=steps, transverse=True)
    assert looks(80) == [(20, 4.0), (40, 3.0)]
    chaotic, other = staged[0]["lambda1"], staged[1]["lambda1"]
    assert set(chaotic.periods) == {40} and set(other.periods) == {80}
    assert np.array_equal(other.exponent, full[1].lambda1)
    # the stopped runs' exponents are those of the same runs integrated for 40 periods
    short = chaos(sinks[0], RunSettings(runs=4, periods=40, seed=1), dt=0.05)
    assert np.array_equal(chaotic.exponent, short.lambda1)
    # and the look's rule (4 s.e. at 20 T not met, 3 s.e. at 40 T met) was applied
    mean, se = ensemble_mean(short.lambda1[:, None])
    assert mean[0] - 3 * se[0] > threshold(40)
    # stopping early never turns a verdict: settled at a look => chaotic by the final rule
    assert mean[0] - 2 * se[0] > threshold(80)


def test_chaos_sweep_stop_early_points_together_equal_points_alone():
    kind = get_kind("chaos")
    base = {"alpha": 0.5, "n": 2, "runs": 3, "periods": 40, "transverse": 1, "stop_early": 1}
    points = [(kind.complete(base | {"beta": b}), seed) for b, seed in
              [(0.3, 11), (0.302, 12), (-0.3, 13)]]  # fmt: skip
    together = kind.compute_many(points)
    for (p, seed), out in zip(points, together, strict=True):
        alone = kind.compute(p, seed)
        for name in out:
            assert np.array_equal(out[name], alone[name], equal_nan=True), name
    with pytest.raises(ParameterError, match="stop_early"):
        kind.check(kind.complete(base | {"beta": 0.3, "gali": 2}))


def test_transient_is_left_out_of_the_exponents():
    """With a transient t0 the stored exponent is (ln|delta(t)| - ln|delta(t0)|)/(t - t0):
    checked against the log growth chaos() records, for the staged and the plain path."""
    kind = get_kind("chaos")
    base = {"alpha": 0.5, "n": 2, "runs": 3, "periods": 60, "transverse": 1, "beta": -0.3}
    sink = Sink(Well(0.5, -0.3, 2), 1, 0.2)
    for stop_early in (0, 1):
        p = kind.complete(base | {"transient": 6, "stop_early": stop_early})
        out = kind.compute(p, 21)
        ref = chaos(sink, RunSettings(runs=3, periods=60, seed=21), dt=float(out["dt_used"]),
                    transverse=True)  # fmt: skip
        t = ref.times[-1] - ref.times[6]
        rate = (ref.log_growth[:, -1] - ref.log_growth[:, 6]) / t
        if out["lambda1_periods"] == 60:  # not stopped at a look
            assert np.array_equal(out["lambda1_runs"], rate)
        assert not np.array_equal(rate, ref.lambda1)  # the transient made a difference
    with pytest.raises(ParameterError, match="transient"):
        kind.check(kind.complete(base | {"transient": 60}))


def test_chaos_transient_is_the_growth_rate_from_its_end(capsys):
    from sinktheory.cli import main

    sink = Sink(Well(0.5, 0.3, 2), 1, 0.2)
    s = RunSettings(runs=2, periods=30, seed=5)
    plain = chaos(sink, s, dt=0.02, transverse=True)
    later = chaos(sink, s, dt=0.02, transverse=True, transient=10)
    t = plain.times[-1] - plain.times[10]
    pairs = ((plain.log_growth, later.lambda1), (plain.transverse_logs, later.transverse))
    for logs, rate in pairs:
        assert np.array_equal(rate, (logs[:, -1] - logs[:, 10]) / t)
    assert np.array_equal(later.log_growth, plain.log_growth)  # the runs are the same
    with pytest.raises(ParameterError, match="transient"):
        chaos(sink, s, dt=0.02, transient=30)
    args = "chaos --alpha 0.5 --beta 0.3 --n 2 --runs 2 --periods 30 --seed 5 --dt 0.02"
    args = [*args.split(), "--transient", "10", "--json"]
    assert main(args) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["lambda1"]["mean"] == pytest.approx(float(later.lambda1.mean()), rel=1e-12)
    assert out["transient_time"] == pytest.approx(10 * 2 * np.pi, rel=1e-12)


def test_steps_per_run_only_where_the_runs_are_the_callers():
    """indicators() takes a step per run; monodromy() and two_orbit_exponent() run copies
    of the runs (displaced or shadow states), so they refuse one, naming dt."""
    from sinktheory.chaos import monodromy, two_orbit_exponent

    q, v = np.full((2, 2), 0.1), np.zeros((2, 2))
    for f in (monodromy, two_orbit_exponent):
        with pytest.raises(ParameterError, match="dt"):
            f(HENON_HEILES, q, v, [], dt=np.array([0.1, 0.1]), steps=10, segments=1)


def test_one_run_gives_no_chaos_verdict():
    """Issue 34: a NaN standard error (one run) made ``chaotic`` return False (regular),
    and the chaos sweep kind allowed runs = 1.  Now the kind refuses it before any work
    and the verdict refuses a NaN standard error, as ergodicity's is undecided."""
    from sinktheory.chaos.verdicts import chaotic
    from sinktheory.sweep.chaosmap import chaos_map
    from sinktheory.sweep.plan import Sweep

    with pytest.raises(ParameterError, match=r"^se = nan .*one run has none"):
        chaotic([0.5, 0.1], [0.01, math.nan], 300)
    with pytest.raises(ParameterError, match=r"^se = -0.1 "):
        chaotic(0.5, -0.1, 300)
    with pytest.raises(ParameterError, match=r"^runs = 1 .*standard error"):
        Sweep.make("chaos", {"alpha": 0.5, "beta": [0.1, 0.3], "n": 4, "runs": 1})
    with pytest.raises(ParameterError, match=r"^runs = 1 "):
        chaos_map(0.5, 4, [0.1], runs=1, periods=10, dt=0.01, workers=1)
    # by hand at 300 periods: threshold 3 ln(600 pi) / (600 pi) = 0.01200
    assert chaotic([0.03, 0.03], [0.008, 0.0095], 300).tolist() == [True, False]
