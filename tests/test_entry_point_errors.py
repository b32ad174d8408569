"""Entry points refuse what they cannot compute with the package's errors, and compute
correctly what is valid: each case one row (a ParameterError names the parameter)."""

from __future__ import annotations

import numpy as np
import pytest

from sinktheory.errors import ParameterError
from sinktheory.model import RunSettings
from tests._cli import run_cli

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
        lambda: _billiard(settings=RunSettings(energy=1e-300, runs=2, periods=2), lyapunov=True),
        "energy",
    ),
}


@pytest.mark.parametrize("case", list(API))
def test_api_refuses_with_the_parameter_named(case):
    call, name = API[case]
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name


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
    tiny = RunSettings(energy=1e-300, runs=2, periods=2)
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
CLI = {
    "billiard alpha 1e308": (["billiard", "--alpha", "1e308", "--beta", "0.3"], "alpha"),
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
        ["--alpha", "0.5", "--beta", "0.3", "--energy", "1e-300"],
        ["--alpha", "0.5", "--beta", "0.3", "--energy", "1e-320", "--fixed", "--lyapunov"],
    ],
)
def test_billiard_cli_without_impacts(argv, capsys):
    code, out, err = run_cli(["billiard", *argv, "--runs", "2", "--periods", "2"], capsys)
    assert code == 0 and err == "", err
    assert "0 impacts" in out and "mean free time undefined (a run had no impact)" in out
