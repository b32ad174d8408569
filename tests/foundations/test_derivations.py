"""Each derivation script reproduces the paper's equations; `sinktheory derive` is readable."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp

from sinktheory import symbolic as S
from sinktheory.cli import main

DERIVATIONS = Path(__file__).resolve().parents[2] / "derivations"
SCRIPTS = sorted(
    p.name
    for p in DERIVATIONS.glob("*.py")
    if not p.name.startswith("_") and p.name != "generate_kernels.py"
)


def test_there_is_a_script_per_derivation():
    assert {"potential.py", "hamiltonian.py", "rescaled.py", "curvature.py", "period.py"} <= set(
        SCRIPTS
    )


@pytest.mark.parametrize("script", SCRIPTS)
def test_derivation_script_succeeds(script):
    # the scripts import this work tree's sinktheory, not an installed copy
    env = {**os.environ, "PYTHONPATH": str(DERIVATIONS.parent)}
    r = subprocess.run(
        [sys.executable, str(DERIVATIONS / script)],
        capture_output=True,
        text=True,
        timeout=600,
        env=env,
    )
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    assert "all checks passed" in r.stdout
    assert "MISMATCH" not in r.stdout


def test_checker_fails_on_a_wrong_form(capsys):
    """The scripts' comparison is not vacuous: a misprinted lambda is caught."""
    sys.path.insert(0, str(DERIVATIONS))
    try:
        import _report
    finally:
        sys.path.remove(str(DERIVATIONS))
    assert not _report.check(
        "wrong lambda", S.lambda_coefficient(), 2 * S.beta * (S.alpha - S.beta)
    )
    _report._failures.clear()
    with pytest.raises(SystemExit) as info:
        _report.check("wrong", S.alpha, S.beta)
        _report.finish()
    assert info.value.code == 1
    _report._failures.clear()


def test_derive_json_is_sympifiable(capsys):
    assert main(["derive", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    required = {"hamiltonian", "x_equation", "y_equation", "lambda", "period", "curvature"}
    assert required <= set(data)
    names = {
        "hamiltonian": {"X", "x", "y", "P", "p_x", "p_y", "alpha", "beta", "gamma", "n", "mu"},
        "x_equation": {"x", "X", "xdd", "n", "mu", "alpha", "beta", "gamma"},
        "y_equation": {"x", "y", "ydd", "n", "alpha", "beta"},
        "lambda": {"alpha", "beta"},
        "period": {"n", "A0"},
        "curvature": {"beta", "y"},
    }
    for key, allowed in names.items():
        expr = sp.sympify(data[key])
        assert {s.name for s in expr.free_symbols} <= allowed, key
    # the paper's forms, typed independently with plain sympify symbols
    a, b, g, n, mu, x, X, y, xdd, ydd, A0 = sp.symbols("alpha beta gamma n mu x X y xdd ydd A0")
    lam = -2 * b * (a - b)
    assert sp.simplify(sp.sympify(data["lambda"]) - lam) == 0
    assert sp.simplify(sp.sympify(data["y_equation"]) - (ydd + lam * x ** (2 * n) * y)) == 0
    paper_x = xdd + x ** (2 * n - 1) - mu / (1 + mu) * (xdd + (a - b) ** 2 / g * X)
    ratio = sp.simplify(sp.sympify(data["x_equation"]) / paper_x)
    assert ratio.free_symbols <= {mu} and sp.simplify(ratio - (1 + mu)) == 0
    paper_T = (
        2 / A0 ** (n - 1) * sp.sqrt(sp.pi / n) * sp.gamma(1 / (2 * n)) / sp.gamma((1 + n) / (2 * n))
    )
    for k in (1, 2, 7):
        at = {n: k, A0: sp.Rational(13, 10)}
        got, want = sp.sympify(data["period"]).subs(at), paper_T.subs(at)
        assert abs(sp.N(got / want - 1, 40)) < 1e-35
    kappa = sp.sympify(data["curvature"])
    assert sp.simplify(kappa - 2 * b / (1 + 4 * b**2 * y**2) ** sp.Rational(3, 2)) == 0


def test_derive_text_and_latex(capsys):
    assert main(["derive"]) == 0
    assert "hamiltonian" in capsys.readouterr().out
    assert main(["derive", "--latex"]) == 0
    assert "\\frac" in capsys.readouterr().out
