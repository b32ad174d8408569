"""Entry points refuse what they cannot compute with the package's errors, and compute
correctly what is valid: each case one row (a ParameterError names the parameter)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from _cli import run_cli

from sinktheory.canonical import FIG8_WELL, HENON_HEILES
from sinktheory.errors import NumericalError, ParameterError
from sinktheory.model import RunSettings

SHORT = RunSettings(runs=2, periods=2)


def _billiard(alpha=0.5, beta=0.3, **kw):
    from sinktheory.billiard import billiard

    return billiard("flat", alpha, beta, **{"settings": SHORT, **kw})


# --------------------------------------------------------------------------- the API
API = {
    # the rigid table's bounds overflow beyond 1e20 (an OverflowError at 1e308 before)
    "billiard alpha 1e308": (lambda: _billiard(alpha=1e308), "alpha"),
    "billiard beta -1e200": (lambda: _billiard(beta=-1e200), "beta"),
    "billiard settings str": (lambda: _billiard(settings="x"), "settings"),
    "billiard fixed yes": (lambda: _billiard(fixed="yes"), "fixed"),
    # a shadow trajectory 1e-9 away from a container of amplitude 1e-150 measured nothing
    "billiard shadow energy": (
        lambda: _billiard(
            settings=RunSettings(container_energy=1e-300, runs=2, periods=2), lyapunov=True
        ),
        "container_energy",
    ),
}


def _law(particles=1, beta=0.3):
    from sinktheory.equilibrium import equilibrium_law
    from sinktheory.model import Sink, Well

    return equilibrium_law(Sink(Well(0.5, beta, 4), particles=particles), 0.5)


def _area(function, value):
    from sinktheory.equilibrium import area

    return getattr(area, function)(FIG8_WELL, value)


def _symmetric_law(energy):
    from sinktheory.equilibrium import equilibrium_law
    from sinktheory.model import Sink, Well

    return equilibrium_law(Sink(Well(0.5, 0.3, 4, shape="symmetric")), energy)


def _lifetimes(sink):
    from sinktheory.equilibrium.lifetime import measure_lifetimes

    return measure_lifetimes(sink, SHORT, transient=0, progress=False)


def _compare_with_law(**kw):
    from sinktheory.equilibrium.lifetime import compare_with_law

    return compare_with_law(np.full((2, 50), 0.2), _law(), transient=0, **kw)


def _ergodicity(**kw):
    from sinktheory.equilibrium.ergodicity import ergodicity_point

    return ergodicity_point({"alpha": 0.5, "beta": 0.3, "n": 4, **kw}, 0)


def _compare(damping, attachments=None):
    from sinktheory.attachments import Attachment
    from sinktheory.compare.efficiency import compare

    attachments = [Attachment("impact")] if attachments is None else attachments
    return compare(attachments, [0.1], damping=damping, periods=2, runs=2)


API.update(
    {
        # NaN and None were a density of 0.0
        "law.pdf nan": (lambda: _law().pdf(math.nan), "s"),
        "law.pdf None": (lambda: _law().pdf(None), "s"),
        "law.kac_periods 1": (lambda: _law().kac_periods(1.0), "f"),  # 1 / 0
        "law.summary points": (lambda: _law().summary(points=10**9), "points"),  # 16 GB
        "law.summary no fractions": (lambda: _law().summary(fractions=[]), "fractions"),
        "scaled_energy -1": (lambda: _area("scaled_energy", -1), "particle_energy"),  # complex
        "area_ratio nan": (lambda: _area("area_ratio", math.nan), "t"),  # NaN
        # 0.0027 % below the corner saddle the area's series cannot converge
        "law near the saddle": (lambda: _symmetric_law(75.35), "total_energy"),
        "compare damping 1e308": (lambda: _compare(1e308), "damping"),  # LinAlgError
        "compare attachments None": (lambda: _compare(0.1, [None]), "attachments"),  # raw
        "compare attachments str": (lambda: _compare(0.1, "nes"), "attachments"),
        "measure_lifetimes sink str": (lambda: _lifetimes("x"), "sink"),  # AttributeError
        # empty fraction lists: no tail to give
        "compare_with_law no fractions": (lambda: _compare_with_law(fractions=[]), "fractions"),
        "ergodicity_point no fractions": (lambda: _ergodicity(fractions=[]), "fractions"),
    }
)  # fmt: skip


def _two_orbit(direction):
    from sinktheory.chaos.twoorbit import two_orbit_exponent

    q, v = np.array([[0.0], [-0.25]]), np.array([[0.42081], [0.0]])  # Henon-Heiles
    return two_orbit_exponent(HENON_HEILES, q, v, [], dt=0.05, steps=20, segments=2,
                              direction=direction)  # fmt: skip


def _floquet(f=(1.0, 0, 0, 0), g=(0, 1.0, 0, 0), free=None):
    from sinktheory.nnm.stability import floquet

    return floquet(np.eye(4), np.array(f), np.array(g), free)


def _sink_mode():
    from sinktheory.model import Sink

    return Sink(FIG8_WELL, particles=1)


def _continue_orbits(**kw):
    from sinktheory.nnm.continuation import continue_orbits
    from sinktheory.nnm.modes import mode_guess, sink_flow

    z0, T = mode_guess(_sink_mode(), "container", 0.5)
    return continue_orbits(sink_flow(_sink_mode()), z0, T, steps=100, **kw)


def _continue_both(**kw):
    from sinktheory.nnm.continuation import continue_both

    return continue_both(_sink_mode(), "container", total_energy=0.5, points=3, steps=100, **kw)


API.update(
    {
        "two_orbit zero direction": (lambda: _two_orbit((np.zeros((2, 1, 1)),) * 2), "direction"),
        "floquet f = 0": (lambda: _floquet(f=np.zeros(4)), "f"),  # NaN multipliers
        "floquet g = 0": (lambda: _floquet(g=np.zeros(4)), "g"),
        "floquet free out of range": (lambda: _floquet(free=[0, 7]), "free"),  # IndexError
        "floquet free 0.5": (lambda: _floquet(free=[0.5]), "free"),  # cast to 0
        "continue_orbits ds_max < ds": (lambda: _continue_orbits(ds=0.1, ds_max=0.01), "ds_max"),
        "continue_both interval excludes start": (
            lambda: _continue_both(interval=(1, 2)),
            "interval",
        ),
        # issue 34, left from before: multipliers 0 with trivial_error 1 were returned
        "floquet singular M": (lambda: floquet_of(np.zeros((4, 4))), "M"),
        "floquet det 2": (lambda: floquet_of(np.diag([2.0, 1, 1, 1])), "M"),
        "two_orbit direction not a pair": (
            lambda: _two_orbit((1, 2, 3)),
            "direction",
        ),  # ValueError
        "two_orbit direction number": (lambda: _two_orbit(5), "direction"),  # TypeError
        "two_orbit direction ragged": (lambda: _two_orbit([[1, 2], [3]]), "direction"),
    }
)


def floquet_of(M):
    from sinktheory.nnm.stability import floquet

    return floquet(M, np.array([1.0, 0, 0, 0]), np.array([0, 1.0, 0, 0]))


@pytest.mark.parametrize("case", list(API))
def test_api_refuses_with_the_parameter_named(case):
    call, name = API[case]
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name


@pytest.mark.parametrize("value", [None, [0.5, None]])
def test_none_is_refused_as_none(value):
    """law.pdf(None) returned 0.0, then was refused as "s = nan" (numpy reads None as NaN):
    the message shows what was given."""
    with pytest.raises(ParameterError, match=r"^s = (None|'list') is not allowed"):
        _law().pdf(value)


def _no_warning_run(call):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return call()


@pytest.mark.parametrize("fixed", [False, True])
def test_billiard_without_impacts_says_so(fixed):
    """A table far larger than the motion or an E0 too small to reach a wall: no impact
    in the run, so no mean free time (inf per run, null in the ensemble summary) where a
    division by zero warned and the text crashed formatting None."""
    tiny = RunSettings(container_energy=1e-300, runs=2, periods=2)
    r = _no_warning_run(
        lambda: _billiard(settings=tiny, fixed=True, lyapunov=True) if fixed else _billiard(1e18)
    )
    assert r.collisions.sum() == 0
    assert np.all(np.isinf(r.mean_free_time))
    d = r.as_dict()
    assert d["mean_mean_free_time"] == {"mean": None, "stderr": None}
    if fixed:  # free flights: the deviation (dq, dv) -> (dq + t dv, dv) exactly
        tan = np.random.default_rng(SHORT.seed).normal(size=(2, 1, 4))  # as the engine draws
        tan /= np.sqrt((tan**2).sum(axis=(1, 2)))[:, None, None]
        dq, dv, t = tan[:, 0, :2], tan[:, 0, 2:], r.duration
        grown = np.sqrt(((dq + t * dv) ** 2).sum(axis=1) + (dv**2).sum(axis=1))
        np.testing.assert_allclose(r.lambda1, np.log(grown) / t, rtol=1e-12)
        assert np.all(np.isnan(r.lambda1_per_collision))


# --------------------------------------------------------------------------- the CLI
SIMULATE = ["simulate", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--runs", "2"]
CLI = {
    "billiard alpha 1e308": (["billiard", "--alpha", "1e308", "--beta", "0.3"], "alpha"),
    # an overflow at 1e-320; 1e-300 was refused naming --runs (now by the API, as eps)
    "adaptive eps 1e-320": ([*SIMULATE, "--stepper", "adaptive", "--eps", "1e-320"], "eps"),
    "adaptive eps 1e-300": ([*SIMULATE, "--stepper", "adaptive", "--eps", "1e-300"], "eps"),
    # documented as allowed, failed in period 1: the range is now (0, 0.25]
    "adaptive eps 0.5": ([*SIMULATE, "--stepper", "adaptive", "--eps", "0.5"], "eps"),
    "compare damping 1e308": (["compare", "--damping", "1e308"], "damping"),  # LinAlgError
    # ran past 60 s (a first compilation, ~70 s cold, which the estimate does not count):
    # its steps are estimated, so a lowered limit refuses it
    "simulate n 1000": (
        [*SIMULATE[:-3], "1000", *SIMULATE[-2:], "--periods", "3", "--max-hours", "1e-6"],
        "periods",
    ),  # fmt: skip
}


@pytest.mark.parametrize("case", list(CLI))
def test_cli_refuses_in_one_line(case, capsys):
    argv, name = CLI[case]
    code, out, err = run_cli(argv, capsys)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and f"error: {name} = " in err, err


@pytest.mark.parametrize(
    "argv",
    [
        ["--alpha", "1e18", "--beta", "0.3"],
        ["--alpha", "0.5", "--beta", "0.3", "--container-energy", "1e-300"],
        [
            "--alpha",
            "0.5",
            "--beta",
            "0.3",
            "--container-energy",
            "1e-320",
            "--fixed",
            "--lyapunov",
        ],
    ],
)
def test_billiard_cli_without_impacts(argv, capsys):
    code, out, err = run_cli(["billiard", *argv, "--runs", "2", "--periods", "2"], capsys)
    assert code == 0 and err == "", err
    assert "0 impacts" in out and "mean free time undefined (a run had no impact)" in out


def test_kac_times_beyond_float_range():
    """k = 1000: P(E_c >= E / 2) ~ 10^-383 underflowed, the Kac time printed inf with
    RuntimeWarnings.  For beta = 0 the law is Beta(1, k (1 + 1/n)) exactly."""
    law = _law(particles=1000, beta=0.0)
    b = 1000 * 1.25
    s = _no_warning_run(lambda: law.summary(fractions=[0.1, 0.5]))
    np.testing.assert_allclose(s.log10_kac_periods, -b * np.log10([0.9, 0.5]), rtol=1e-12)
    assert s.kac_periods[0] == pytest.approx(0.9**-b, rel=1e-10) and np.isinf(s.kac_periods[1])
    with pytest.raises(NumericalError, match=r"10\^376\.3 periods"):
        law.kac_periods(0.5)


def test_equilibrium_command_prints_kac_times_beyond_float_range(capsys):
    """``equilibrium --particles 1000`` printed a Kac time "inf" with RuntimeWarnings.  For
    beta = 0 the law is Beta(1, k (1 + 1/n)) exactly: P(E_c >= f E) = (1 - f)^1250."""
    import re
    import warnings

    argv = ["equilibrium", "--alpha", "0.5", "--beta", "0", "--n", "4", "--particles", "1000"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        code, out, err = run_cli(argv, capsys)
    assert code == 0 and err == "" and "inf" not in out, (err, out)
    rows = dict(re.findall(r"^  (0\.\d)\s+(\S+)\s+\S+$", out, flags=re.M))
    assert float(rows["0.1"]) == pytest.approx(0.9**1250, rel=1e-5)
    for f in ("0.5", "0.8"):  # below the smallest double: printed as a power of ten
        exponent = float(rows[f].removeprefix("10^"))
        assert exponent == pytest.approx(1250 * math.log10(1 - float(f)), abs=1e-4)
