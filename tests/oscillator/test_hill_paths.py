"""The two ways to run Hill's quarter-period loop: compiled (numba) and interpreted.

``sinktheory.hill`` writes the adaptive DOP853 loop once and runs it compiled for charts
and interpreted (with pure-Python twins of the generated kernels) for the first
single-value integrations of a process, so a one-point ``sinktheory floquet`` starts
without loading numba's compiler.  Checked here:

- the interpreted run against the compiled one: the same floating-point operations, so
  the same step sequence and values to 1e-14 relative (bitwise on x86-64, where numba
  does not contract multiply-adds; the tolerance leaves room for a platform that does);
- the interpreted run against independent references: mpmath's Taylor solver at 30
  digits (1e-10, the accuracy the chart promises), scipy's solve_ivp over whole half
  periods (1e-9), and the exact phi_half = -1 of the circular well;
- the choice ``implementation="auto"`` makes in a fresh process: one value interpreted without
  importing numba's array support or scipy.linalg, a chart compiled, a long single
  integration handed to the compiled loop, with the same numbers.
"""

import json
import subprocess
import sys

import numpy as np
import pytest

from sinktheory._generated import oscillator as osc
from sinktheory._generated.shapes import NAMES, bundle
from sinktheory.errors import ParameterError
from sinktheory.floquet import model_problem, pure_problem
from sinktheory.hill import (
    PYTHON_STEPS,
    HillIntegrationError,
    integrate_quarter_period,
    monodromy_solve_ivp,
    quarter_period_mpmath,
)
from sinktheory.twins import python_kernel

CASES = [  # (shape or "pure", n, parameter, amplitude): every regime the loop meets
    ("pure", 1, 9.0, 1.0),
    ("pure", 2, -4500.0, 1.0),  # |phi_half| > 1e30
    ("pure", 1, -1e5, 1.0),  # renormalised past 2^400
    ("pure", 200, 2.0, 1.0),  # stiff walls: short impacts
    ("flat", 4, 0.1, 1.0),
    ("flat", 1, -0.3, 1.7),
    ("symmetric", 3, 0.2, 0.8),
    ("circular", 6, 0.1, 1.0),
]


def problem_of(kind, n, amplitude):
    if kind == "pure":
        return pure_problem(n, amplitude)
    return model_problem(0.5, n, shape=kind, amplitude=amplitude)


def quarter(problem, value, method):
    pure = problem.kind == "pure"
    return integrate_quarter_period(
        problem.n,
        np.array([value * problem.amplitude**2 if pure else value]),
        coefficient=problem.coefficient,
        amplitude=1.0 if pure else problem.amplitude,
        alpha=problem.alpha,
        implementation=method,
    )


def test_python_kernels_equal_the_compiled_ones():
    """Each shape's Hill coefficient and the oscillator's kernels, twin vs compiled."""
    xs = np.linspace(-1.3, 1.3, 27)
    for name in NAMES:
        q = bundle(name).hill_coefficient
        twin = python_kernel(q)
        assert not hasattr(twin, "py_func")
        for n in (1, 2, 7, 40):
            for x in xs:
                assert twin(x, 0.5, 0.2, n) == pytest.approx(q(x, 0.5, 0.2, n), rel=1e-15)
    for n in (1, 3, 100):
        assert python_kernel(osc.period)(n, 1.3) == pytest.approx(osc.period(n, 1.3), rel=1e-14)
        for x in xs:
            got = python_kernel(osc.oscillator_acceleration)(x, n)
            assert got == pytest.approx(osc.oscillator_acceleration(x, n), rel=1e-15)


@pytest.mark.parametrize(("kind", "n", "value", "amplitude"), CASES)
def test_interpreted_run_is_the_compiled_run(kind, n, value, amplitude):
    problem = problem_of(kind, n, amplitude)
    compiled = quarter(problem, value, "compiled")
    python = quarter(problem, value, "python")
    assert (python.steps, python.rejected) == (compiled.steps, compiled.rejected)
    np.testing.assert_array_equal(python.scale1, compiled.scale1)
    np.testing.assert_array_equal(python.scale2, compiled.scale2)
    for name in ("y1", "dy1", "y2", "dy2"):
        np.testing.assert_allclose(getattr(python, name), getattr(compiled, name), rtol=1e-14)


@pytest.mark.parametrize(("n", "lam"), [(2, 1.7), (10, 25.0), (1, 12.0)])
def test_interpreted_run_certified_by_mpmath(n, lam):
    """phi_half = y1 y2' + y2 y1' at Q to 1e-10 relative to max(1, |phi_half|)."""
    y1, dy1, y2, dy2, _ = quarter_period_mpmath(n, lam, dps=30)
    ref = float(y1 * dy2 + y2 * dy1)
    qp = integrate_quarter_period(n, np.array([lam]), implementation="python")
    got = qp.y1[0] * qp.dy2[0] + qp.y2[0] * qp.dy1[0]
    assert abs(got - ref) <= 1e-10 * max(1.0, abs(ref))


def test_interpreted_model_run_agrees_with_solve_ivp():
    """Flat well, n = 4, beta = 0.1: M(T/2) from the quarter-period formulas vs solve_ivp
    over a whole half period (rtol 1e-13 gives ~1e-11; 1e-9 has margin)."""
    q = bundle("flat").hill_coefficient
    qp = integrate_quarter_period(4, [0.1], coefficient=q, alpha=0.5, implementation="python")
    y1, dy1, y2, dy2 = qp.y1[0], qp.dy1[0], qp.y2[0], qp.dy2[0]
    predicted = np.array([[y1 * dy2 + y2 * dy1, 2 * y2 * dy2], [2 * y1 * dy1, y1 * dy2 + y2 * dy1]])
    half = monodromy_solve_ivp(4, 0.1, coefficient=q, alpha=0.5)
    np.testing.assert_allclose(half, predicted, atol=1e-9, rtol=0)


def test_interpreted_circular_well_is_neutral():
    """The circular well's normal mode is the turned orbit: phi_half = -1 exactly (1e-11)."""
    problem = model_problem(0.5, 5, shape="circular")
    qp = quarter(problem, 0.2, "python")
    assert qp.y1[0] * qp.dy2[0] + qp.y2[0] * qp.dy1[0] == pytest.approx(-1.0, abs=1e-11)


def test_interpreted_run_raises_like_the_compiled_one():
    with pytest.raises(HillIntegrationError, match="quarter period"):
        integrate_quarter_period(10, np.array([1e6]), max_steps=50, implementation="python")


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [({"implementation": "numba"}, "implementation"), ({"max_steps": 0}, "max_steps")],
)
def test_bad_options_name_the_parameter(kwargs, name):
    with pytest.raises(ParameterError) as info:
        integrate_quarter_period(2, np.array([1.0]), **kwargs)
    assert info.value.name == name


AUTO_SCRIPT = """
import json, sys
import numpy as np
from sinktheory import hill
from sinktheory.floquet import model_hill, pure_hill

out = {}
one = model_hill(0.5, [0.1], 4)
out["one"] = [float(one.phi_half[0]), one.quarter.steps]
out["one_loaded"] = hill._compiled_loop.cache_info().currsize
out["one_heavy"] = [m for m in ("numba.np.arraymath", "scipy.linalg") if m in sys.modules]
long = pure_hill([-1e5], 1)  # more than PYTHON_STEPS steps: redone compiled
out["long"] = [float(long.log_abs_phi_half[0]), long.quarter.steps]
out["long_loaded"] = hill._compiled_loop.cache_info().currsize
chart = pure_hill([0.5, 2.0], 3)
out["chart"] = chart.phi_half.tolist()
print(json.dumps(out))
"""


def test_auto_interprets_one_value_in_a_fresh_process():
    """A fresh interpreter: one value runs interpreted (compiled loop not loaded, numba's
    array support and scipy.linalg not imported); a long one-value integration and a
    chart run compiled; all equal the compiled run here to 1e-14."""
    proc = subprocess.run(
        [sys.executable, "-c", AUTO_SCRIPT], capture_output=True, text=True, check=True
    )
    out = json.loads(proc.stdout)
    assert out["one_loaded"] == 0 and out["one_heavy"] == []
    one = model_problem(0.5, 4).evaluate([0.1])
    phi, steps = out["one"]
    assert steps == one.quarter.steps and phi == pytest.approx(one.phi_half[0], rel=1e-14)
    assert out["long_loaded"] == 1
    long = pure_problem(1).evaluate([-1e5])
    assert long.quarter.steps > PYTHON_STEPS
    assert out["long"] == [pytest.approx(long.log_abs_phi_half[0], rel=1e-14), long.quarter.steps]
    chart = pure_problem(3).evaluate([0.5, 2.0])
    np.testing.assert_allclose(out["chart"], chart.phi_half, rtol=1e-14)
