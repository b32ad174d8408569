"""Issue 34, third hardening pass: the adaptive controller's and the step choice's inputs.

Each case the issue lists is refused naming its parameter, or computed without a warning.
"""

import math
import warnings

import numpy as np
import pytest

from sinktheory import ParameterError, Sink, Well
from sinktheory.adaptive import controller_steps
from sinktheory.ensemble import start_state
from sinktheory.stepsize import stiffness_frequency

SINK = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)


def _start():
    return start_state(SINK, 0.5, np.array([[[0.003, -0.004]]]))


def _nan_state():
    y = _start()
    y[0, 0] = math.nan
    return y


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(values=_nan_state, count=2), "values"),  # returned NaN
        (dict(values="x", count=2), "values"),  # ValueError
        (dict(values=lambda: _start()[:, :5], count=2), "values"),
        (dict(values=lambda: np.zeros((0, 6)), count=2), "values"),
        (dict(values=_start, count=2, rho=[-1.0]), "rho"),  # returned NaN
        (dict(values=_start, count=2, rho=[math.nan]), "rho"),
        (dict(values=_start, count=2, rho=[1.0, 2.0]), "rho"),  # one rate per run
        (dict(values=_start, count=2, rho="x"), "rho"),
        (dict(values=_start, count=0), "count"),
    ],
)
def test_controller_steps_refuses_what_it_cannot_step(kwargs, name):
    kwargs = {k: (v() if callable(v) else v) for k, v in kwargs.items()}
    with pytest.raises(ParameterError, match=rf"^{name} = "):
        controller_steps(SINK, **kwargs)
    with pytest.raises(ParameterError, match=r"^sink = "):
        controller_steps("x", _start(), 2)


def test_controller_steps_estimates_its_count_before_stepping():
    """count = 1e12 hung.  By hand: 1e12 steps x 2 (the rate) x (1 run x 1 particle + 8
    for its block) is 1.8e13 particle steps, over the hour's 3e10."""
    with pytest.raises(ParameterError, match=r"^count = 1000000000000 .*is 1.8e\+13 particle"):
        controller_steps(SINK, _start(), 10**12)


def test_stiffness_frequency_of_a_huge_well_warns_nothing():
    """compare --alpha 1e308 warned "invalid value in multiply": the bisection's midpoint
    (lo + hi) / 2 overflowed.  With the walls that far out the basin's curvature vanishes
    and the fastest frequency is the container's own, 1."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert stiffness_frequency(Sink(Well(1e308, 0.3, 4)), 0.5) == 1.0
