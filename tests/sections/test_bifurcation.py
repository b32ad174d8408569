"""Bifurcation sections: decoupled and chaotic limits, determinism, bad input."""

import numpy as np
import pytest

from sinktheory import ParameterError, Sink, Well
from sinktheory.bifurcation import bifurcation, section
from sinktheory.canonical import FIG8_WELL
from sinktheory.plot.bifurcation import plot_bifurcation


def test_straight_walls_decouple_y():
    """beta = 0: V = gamma/2n [(x/alpha)^2n + y^2n] separates, so y obeys y'' = -(gamma/mu)
    y^(2n-1) alone.  From y = 0.01 at rest with n = 10 the force is ~1e-37: over 60
    periods y moves by < 1e-30, so every section value is 0.01 to rounding."""
    s = section(Sink(Well(0.5, 0.0, 10), 1, 0.2), transient=10, count=50)
    np.testing.assert_allclose(s, 0.01, rtol=1e-12, atol=0)


def test_scattering_walls_spread_the_particle_over_the_well():
    """beta = 0.3, n = 10 (Fig. 4f): the normal mode is Floquet-unstable and the particle
    leaves it: within 150 periods its y covers most of the well (|y| <= 1.12)."""
    s = section(Sink(Well(0.5, 0.3, 10), 1, 0.2), transient=50, count=100)
    assert np.ptp(s) > 1.0
    assert np.abs(s).max() <= Well(0.5, 0.3, 10).reach(0.5 + 1e-9)[1]


def test_diagram_is_deterministic_and_energy_section_works():
    kw = dict(alpha=0.5, n=4, transient=5, count=10)
    a = bifurcation([-0.2, 0.2], **kw)
    b = bifurcation([-0.2, 0.2], **kw)
    np.testing.assert_array_equal(a.section, b.section)
    e = bifurcation([0.2], quantity="energy", **kw)
    assert e.section.shape == (1, 10) and np.all((e.section >= 0) & (e.section <= 0.5 + 1e-6))
    fig = plot_bifurcation(a, unstable=[(0.0, 0.3)])
    assert fig.axes[0].get_xlabel() == "$\\beta$"


@pytest.mark.parametrize(
    "call,name",
    [
        (lambda: section(Sink(FIG8_WELL, 2, 0.2)), "particles"),
        (lambda: bifurcation([0.6], alpha=0.5, n=4), "beta"),
        (lambda: bifurcation([0.1], alpha=0.5, n=4, quantity="x"), "quantity"),
        (lambda: bifurcation([], alpha=0.5, n=4), "betas"),
    ],
)
def test_bad_input(call, name):
    with pytest.raises(ParameterError, match=f"^{name} = "):
        call()


def test_section_refuses_work_and_memory_beyond_the_limits_at_once(monkeypatch):
    import time

    from sinktheory import validation

    stiff = Sink(Well(0.5, 0.3, 100), 1, 0.2)  # about 17,900 steps per period
    t0 = time.perf_counter()
    # by hand: 1e8 periods x 6 numbers x 8 bytes x (1 run + 3 padding) = 19 GB of record
    with pytest.raises(ParameterError, match=r"count = 100000000 .*memory"):
        section(stiff, transient=10, count=10**8)
    # with memory to spare, 1e8 periods x 17,900 steps = 1.8e12 particle steps > 1 hour
    monkeypatch.setattr(validation, "memory_limit", lambda: 10**15)
    with pytest.raises(ParameterError, match=r"count = 100000000 .*particle steps"):
        section(stiff, transient=10, count=10**8)
    with pytest.raises(ParameterError, match=r"count = 100000000"):
        bifurcation([0.3, 0.31], alpha=0.5, n=100, count=10**8)
    assert time.perf_counter() - t0 < 5
