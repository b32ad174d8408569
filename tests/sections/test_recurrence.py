"""Recurrence plots and RQA against hand-counted matrices and brute force."""

import math

import numpy as np
import pytest

from sinktheory import ParameterError
from sinktheory.plot.recurrence import plot_recurrence
from sinktheory.recurrence import (
    epsilon_for_rate,
    recurrence_image,
    recurrence_rate,
    rqa,
    rqa_matrix,
)

# A 5 x 5 symmetric matrix whose lines were counted by hand (see the comments).
HAND = np.array(
    [
        [1, 1, 0, 0, 0],
        [1, 1, 1, 0, 0],
        [0, 1, 1, 0, 1],
        [0, 0, 0, 1, 1],
        [0, 0, 1, 1, 1],
    ],
    bool,
)


def test_hand_counted_matrix_main_diagonal_excluded():
    r = rqa_matrix(HAND, theiler=1)
    # off-diagonal ones: (0,1) (1,2) (2,4) (3,4) and mirrors -> 8 of 20 pairs
    assert r.recurrence_rate == 8 / 20
    # upper diagonals: offset 1 has runs [2, 1], offset 2 has [1]; mirrored below
    assert list(r.diagonal_lines[:3]) == [0, 4, 2]
    assert r.determinism == 4 / 8
    # columns (window cuts at i = j): lengths 1 | 1,1 | 1,1 | 1 | 2
    assert list(r.vertical_lines[:3]) == [0, 6, 1]
    assert r.laminarity == 2 / 8
    assert r.trapping_time == 2.0
    assert math.isnan(r.mean_recurrence_time)  # no gap bounded on both sides


def test_hand_counted_matrix_main_diagonal_included():
    r = rqa_matrix(HAND, theiler=0)
    assert r.recurrence_rate == 13 / 25
    assert r.determinism == 9 / 13  # lines of length 2 (x2) and the diagonal of length 5
    # columns: 2 | 3 | 2,1 | 2 | 3
    assert list(r.vertical_lines[:4]) == [0, 1, 3, 2]
    assert r.laminarity == 12 / 13
    assert r.trapping_time == 12 / 5
    assert r.mean_recurrence_time == 2.0  # column 2: recurrence at i=2, gap, again at i=4


def test_wider_theiler_window_removes_near_diagonal_points():
    r = rqa_matrix(HAND, theiler=2)
    # left: (2,4) and (4,2) at offset 2, out of 25 - 5 - 8 = 12 pairs
    assert r.recurrence_rate == 2 / 12
    assert r.determinism == 0.0


@pytest.mark.parametrize("theiler", [0, 1, 3])
def test_series_path_equals_explicit_matrix(theiler):
    rng = np.random.default_rng(7)
    e = np.cumsum(rng.normal(size=80))  # a random walk: long lines and gaps
    eps = 0.8
    R = np.abs(e[:, None] - e[None, :]) <= eps
    a, b = rqa(e, eps, theiler=theiler), rqa_matrix(R, theiler=theiler)
    for key in (
        "recurrence_rate",
        "determinism",
        "laminarity",
        "trapping_time",
        "mean_recurrence_time",
    ):
        assert getattr(a, key) == pytest.approx(getattr(b, key), nan_ok=True), key
    np.testing.assert_array_equal(a.diagonal_lines, b.diagonal_lines)
    np.testing.assert_array_equal(a.vertical_lines, b.vertical_lines)
    brute = R.sum() - (np.abs(np.subtract.outer(range(80), range(80))) < theiler)[R].sum()
    assert a.recurrence_rate == pytest.approx(
        brute / (80 * 80 - (np.abs(np.subtract.outer(range(80), range(80))) < theiler).sum())
    )


def test_fast_rate_and_epsilon_rule():
    rng = np.random.default_rng(3)
    e = rng.random(500)
    eps = 0.05
    R = np.abs(e[:, None] - e[None, :]) <= eps
    assert recurrence_rate(e, eps) == pytest.approx((R.sum() - 500) / (500 * 499))
    eps5 = epsilon_for_rate(e, 0.05)
    assert recurrence_rate(e, eps5) >= 0.05
    assert recurrence_rate(e, np.nextafter(eps5, 0)) < 0.05
    assert rqa(e).eps == eps5  # default rule


def test_ten_thousand_points_without_a_dense_matrix():
    e = np.sin(0.05 * np.arange(10_000)) + 0.01 * np.random.default_rng(0).random(10_000)
    r = rqa(e, 0.05)
    assert r.recurrence_rate == pytest.approx(recurrence_rate(e, 0.05), rel=1e-12)
    # period 7 with well-separated values: exact answers at N = 10^4
    n = 10_000
    periodic = rqa(np.arange(n) % 7, 0.1)
    pairs = sum(2 * (n - k) for k in range(7, n, 7))
    assert periodic.recurrence_rate == pairs / (n * (n - 1))
    assert periodic.determinism == 1.0 and periodic.laminarity == 0.0
    assert periodic.mean_recurrence_time == 7.0
    img = recurrence_image(e, 0.05, max_pixels=500)
    assert img.shape == (500, 500) and img.dtype == np.float32
    assert abs(img.mean() - r.recurrence_rate) < 2e-3  # block means average to RR (+diag)


def test_small_image_is_exact():
    e = np.array([0.0, 1.0, 0.05, 2.0])
    img = recurrence_image(e, 0.1)
    np.testing.assert_array_equal(img, np.abs(e[:, None] - e[None, :]) <= 0.1)


def test_plot_recurrence_labels():
    fig = plot_recurrence(np.sin(np.arange(200) * 0.3))
    assert fig.axes[0].get_xlabel().startswith("$i$")


@pytest.mark.parametrize(
    "call,name",
    [
        (lambda: rqa(np.ones((3, 3)), 0.1), "series"),
        (lambda: rqa([1.0, np.nan, 2.0], 0.1), "series"),
        (lambda: rqa([1.0], 0.1), "series"),
        (lambda: rqa([1.0, 2.0], -0.1), "eps"),
        (lambda: rqa([1.0, 2.0, 3.0], 0.1, theiler=5), "theiler"),
        (lambda: rqa_matrix(np.triu(np.ones((3, 3)))), "matrix"),
        (lambda: epsilon_for_rate([1.0, 2.0], 0.0), "rate"),
    ],
)
def test_bad_input(call, name):
    with pytest.raises(ParameterError, match=f"^{name} = "):
        call()
