"""Validated parameters: good input accepted, every bad input refused by name."""

import math

import numpy as np
import pytest

from sinktheory import ParameterError, RunSettings, Sink, Well
from sinktheory import symbolic as S
from sinktheory.canonical import FIG8_SINK, FIG8_WELL, SYMMETRIC_WELL

BAD_WELLS = [
    (dict(alpha=0.5, beta=0.1, n=0), "n"),
    (dict(alpha=0.5, beta=0.1, n=-3), "n"),
    (dict(alpha=0.5, beta=0.1, n=2.5), "n"),
    (dict(alpha=0.5, beta=0.1, n=math.nan), "n"),
    (dict(alpha=0.5, beta=0.1, n=2, gamma=0.0), "gamma"),
    (dict(alpha=0.5, beta=0.1, n=2, gamma=-1.0), "gamma"),
    (dict(alpha=0.5, beta=0.1, n=2, gamma=math.inf), "gamma"),
    (dict(alpha=0.0, beta=-0.1, n=2), "alpha"),
    (dict(alpha=-1.0, beta=-2.0, n=2), "alpha"),
    (dict(alpha=math.nan, beta=0.1, n=2), "alpha"),
    (dict(alpha=0.5, beta=math.inf, n=2), "beta"),
    (dict(alpha=0.5, beta=0.5, n=2), "beta"),  # flat: alpha - beta <= 0
    (dict(alpha=0.5, beta=0.7, n=2), "beta"),
    (dict(alpha=1.0, beta=1.0, n=6, shape="symmetric"), "beta"),  # Fig. 12 caption
    (dict(alpha=0.5, beta=0.1, n=2, shape="round"), "shape"),
]


@pytest.mark.parametrize("kwargs,name", BAD_WELLS)
def test_bad_well_is_refused_by_name(kwargs, name):
    with pytest.raises(ParameterError) as info:
        Well(**kwargs)
    message = str(info.value)
    assert message.startswith(f"{name} = ")
    assert "\n" not in message
    assert info.value.name == name


@pytest.mark.parametrize(
    "kwargs,name",
    [
        (dict(particles=0), "particles"),
        (dict(particles=1.5), "particles"),
        (dict(particles=math.nan), "particles"),
        (dict(mass=0.0), "mass"),
        (dict(mass=-0.2), "mass"),
        (dict(mass=math.inf), "mass"),
    ],
)
def test_bad_sink_is_refused(kwargs, name):
    with pytest.raises(ParameterError, match=f"^{name} = "):
        Sink(FIG8_WELL, **kwargs)


@pytest.mark.parametrize(
    "kwargs,name",
    [
        (dict(runs=0), "runs"),
        (dict(runs=2.5), "runs"),
        (dict(periods=0), "periods"),
        (dict(periods=-10), "periods"),
        (dict(container_energy=0.0), "container_energy"),
        (dict(container_energy=math.nan), "container_energy"),
        (dict(seed=-1), "seed"),
        (dict(box=0.0), "box"),
    ],
)
def test_bad_run_settings_are_refused(kwargs, name):
    with pytest.raises(ParameterError, match=f"^{name} = "):
        RunSettings(**kwargs)


def test_parameter_error_is_a_value_error():
    assert issubclass(ParameterError, ValueError)


def test_focusing_flat_well_refused_where_denominator_reaches_zero():
    """beta < 0: D(y) = alpha - beta + beta y^2 must stay > 0 up to the reach |y| <= c."""
    well = Well(alpha=0.5, beta=-2.0, n=2)  # valid as a shape ...
    c = (2 * 2 * 0.5) ** (1 / 4)  # ... but y reaches (2 n E / gamma)^(1/2n)
    assert 0.5 + 2.0 - 2.0 * c**2 < 0  # where D < 0
    with pytest.raises(ParameterError, match="^beta = "):
        well.reach(0.5)
    # a low energy keeps the particle where D > 0
    assert well.reach(0.01)[1] < math.sqrt(2.5 / 2.0)


def test_symmetric_well_refused_above_corner_saddle():
    well = Well(alpha=1.0, beta=0.5, n=6, shape="symmetric")
    # independent: V on the diagonal peaks at s = sqrt((alpha-beta)/beta) = 1
    s = np.linspace(0.01, 3, 3001)
    v_diag = well.potential(s, s)
    assert abs(v_diag.max() - 1 / 6) < 1e-6
    with pytest.raises(ParameterError, match="^particle_energy = "):
        well.reach(0.5)
    well.reach(0.1)


@pytest.mark.parametrize(
    "well",
    [
        Well(0.5, 0.3, 2),
        Well(0.5, 0.3, 10),
        Well(0.5, -0.3, 2),
        Well(0.5, -0.5, 10),
        SYMMETRIC_WELL,
        Well(1.0, -0.1, 6, shape="symmetric"),
    ],
)
def test_reach_bounds_the_basin(well):
    """Grid check: every grid point of the central basin V <= E lies inside the reach."""
    E = 0.5
    x_max, y_max = well.reach(E)
    g = np.linspace(-2.0, 2.0, 801)
    X, Y = np.meshgrid(g, g)
    inside = well.potential(X, Y) <= E
    # keep the connected part around the centre: scan outward along rows and columns
    from scipy import ndimage

    labels, _ = ndimage.label(inside)
    basin = labels == labels[400, 400]
    assert np.abs(X[basin]).max() <= x_max + 1e-12
    assert np.abs(Y[basin]).max() <= y_max + 1e-12
    if well.shape == "flat":  # the flat reach is exact: tight to a grid step
        assert np.abs(X[basin]).max() >= x_max - 0.006
        assert np.abs(Y[basin]).max() >= y_max - 0.006


def test_geometry_against_symbolic_model():
    well = Well(alpha=0.5, beta=0.3, n=10)
    assert well.wall_distance == pytest.approx(0.2, abs=1e-15)
    kappa = S.rigid_wall_curvature()
    for y in (0.0, 0.3, -0.7):
        exact = float(kappa.subs({S.beta: 0.3, S.y: y}))
        assert well.curvature(y) == pytest.approx(exact, rel=1e-14)
    assert well.curvature_at_centre == pytest.approx(0.6, rel=1e-15)


def test_models_are_immutable():
    well = Well(0.5, 0.3, 2)
    with pytest.raises(AttributeError):
        well.beta = 0.1


def test_sink_mu_and_energy_bound():
    sink = FIG8_SINK
    assert sink.mu == pytest.approx(0.04)
    settings = RunSettings(container_energy=0.5, box=0.01)
    bound = settings.total_energy_bound(sink)
    # V(0.01, 0.01) = (1/8) [(0.01/0.2)^8 + 0.01^8]: independent hand evaluation
    assert bound == pytest.approx(0.5 + 5 * ((0.01 / 0.2) ** 8 + 0.01**8) / 8, rel=1e-14)


@pytest.mark.parametrize("shape", ["flat", "symmetric", "circular"])
def test_potential_on_arrays_is_the_kernel_at_each_point(shape):
    # the compiled loop over points against the shape's kernel called point by point
    w = Well(0.5, 0.1, 3, shape=shape)
    x = np.linspace(-0.45, 0.45, 7)[None, :]
    y = np.linspace(-0.35, 0.35, 4)[:, None]
    got = w.potential(x, y)
    assert got.shape == (4, 7)
    for (i, j), value in np.ndenumerate(got):
        expected = w.kernels.potential(x[0, j], y[i, 0], w.alpha, w.beta, w.gamma, w.n)
        assert value == expected
    assert np.shape(w.potential(0.1, 0.2)) == ()


@pytest.mark.parametrize(
    "shape, beta, bound",
    [
        ("circular", 0.1, 0.4 / math.sqrt(2)),  # the corner (b, b) on the circle r = alpha - beta
        # flat, beta < 0: the corner on the wall, b = D(b) = alpha + beta (b^2 - 1)
        ("flat", -0.3, (-1 + math.sqrt(1 + 4 * 0.3 * 0.8)) / (2 * 0.3)),
        ("flat", 0.3, 0.2),  # the wall at y = 0: b = alpha - beta
    ],
)
def test_box_refusal_names_the_largest_box_inside(shape, beta, bound):
    with pytest.raises(ParameterError) as info:
        RunSettings(box=0.99).check_box(Well(0.5, beta, 4, shape=shape))
    stated = float(str(info.value).split("must be < ")[1].split(",")[0])
    assert stated == pytest.approx(bound, rel=1e-5)
    RunSettings(box=0.999 * bound).check_box(Well(0.5, beta, 4, shape=shape))  # just inside
