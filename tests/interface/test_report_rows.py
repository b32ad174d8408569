"""The report's rules for long-time rows, fine-grid windows and the closing section, on
synthetic inputs whose answers are known (the full figures run in test_reproduce.py)."""

import functools
import math

import numpy as np

from sinktheory.equilibrium import measure_relaxation
from sinktheory.report import SceneOutcome, render
from sinktheory.scenes.base import BEYOND, Claim, Scene, SceneResult
from sinktheory.scenes.ensembles import LongTime, _level_verdict
from sinktheory.scenes.horizons import FACTOR, SETTLING, describe, horizon, settling_time
from sinktheory.scenes.orbits import _window

LAW, TAU, AMPLITUDE = 0.2, 100.0, 3.0
#: The synthetic approach's exact 5 % crossing: TAU ln(AMPLITUDE / 0.05) = 409 periods.
EXACT = TAU * math.log(AMPLITUDE / 0.05)


@functools.lru_cache
def _settle(periods: int):
    rng = np.random.default_rng(1)
    t = np.arange(periods + 1)
    runs = LAW * (1 + AMPLITUDE * np.exp(-t / TAU)) + 0.01 * rng.standard_normal((16, t.size))
    return measure_relaxation(runs, LAW, resamples=49)


def _long(mean, se, horizon_periods, settle):
    stored = SETTLING[("flat", 0.5, 0.3, 4, 1)]
    return LongTime("k = 1", LAW, LAW, horizon_periods, 16, stored, mean, se, settle)


def test_horizon_spans_three_measured_settling_times():
    for key, s in SETTLING.items():
        h = horizon(*key)
        assert h % 50 == 0 and FACTOR * s.periods <= h < FACTOR * s.periods + 50


def test_a_setup_without_a_stored_measurement_is_predicted_and_says_so():
    """Fig. 8's well with two particles is not stored: its settling time is predicted, and
    the prediction's interval covers the one measured in docs/guide/relaxation.inc (1380,
    684-2739, 32 runs x 3970 periods, seed 1)."""
    key = ("flat", 0.5, 0.3, 4, 2)
    assert key not in SETTLING
    s = settling_time(*key)
    assert s.source == "predicted" and describe(s).startswith("predicted ")
    assert s.low <= 684 and 2739 <= s.high
    h = horizon(*key)
    assert h % 50 == 0 and max(FACTOR * s.periods, s.high) <= h
    assert describe(SETTLING[("flat", 0.5, 0.3, 4, 5)]).startswith("measured 5241 ")


def test_far_from_the_law_is_a_failure_only_on_a_run_long_enough():
    long_run = _settle(2000)  # 2000 periods > 3 x 409: the run spans three settling times
    assert abs(long_run.settle_time - EXACT) < 0.15 * EXACT
    far = 10 * 0.002
    assert _level_verdict(_long(LAW + far, 0.002, 2000, long_run), LAW, "law")[0] == "does not hold"
    short = _long(LAW + far, 0.002, 1000, long_run)  # the same settling, a 1000-period horizon
    verdict, why = _level_verdict(short, LAW, "law")
    assert verdict == "cannot be decided" and "more periods" in why


def test_agreement_holds_only_at_the_stated_resolution():
    run = _settle(2000)
    assert _level_verdict(_long(LAW + 0.002, 0.005, 2000, run), LAW, "law")[0] == "holds"
    verdict, why = _level_verdict(_long(LAW, 0.02, 2000, run), LAW, "law")  # 3 s.e. = 30 %
    assert verdict == "cannot be decided" and "more runs" in why


def test_window_needs_unstable_calls_at_the_touching_between_stable_ones():
    assert _window(np.array([-1, -1, 1, 1, -1]), 2) == "window"
    assert _window(np.array([-1, -1, -1, -1, -1]), 2) == "stable"
    assert _window(np.array([1, 1, 1, 1, 0]), 2) == "unstable"
    assert _window(np.array([-1, 0, 0, 0, -1]), 2) == "unresolved"
    assert _window(np.array([1, -1, -1, -1, -1]), 2) == "unresolved"  # unstable far away


def test_closing_section_sorts_the_papers_claims_and_links_their_rows():
    claims = [
        Claim("a right claim", "1.0", "holds", "because of x = 1.0"),
        Claim("a wrong claim", "2.0", "does not hold", "because of y = 2.0"),
        Claim(f"{BEYOND} our own row", "3.0", "holds"),
    ]
    scene = Scene(99, "synthetic", "nothing", lambda quick: None)
    outcome = SceneOutcome(scene, SceneResult(None, {}, claims), "fig99.png", 0.0)
    text = render([outcome], quick=False, version="test")
    closing = text.split("## What the paper gets right and wrong")[1]
    right, rest = closing.split("### Wrong")
    assert "[99.1](#r99-1) a right claim. because of x = 1.0" in right
    assert "[99.2](#r99-2) a wrong claim. because of y = 2.0" in rest
    assert "### Beyond the paper" in rest and "holds: [99.3](#r99-3)" in rest
    for i in (1, 2, 3):
        assert f'<a id="r99-{i}"></a>99.{i}' in text
