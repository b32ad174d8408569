"""Regular and chaotic runs of a mixed ensemble (sinktheory.chaos.verdicts.split) against
cases whose answer is known without the rule.

* Islands: the rigid flat table at beta = -0.3 (fixed container) has an island around
  the horizontal two-bounce orbit between its focusing side walls.  A run in that island
  never reaches the flat walls y = +-1 (wall function 1), a chaotic run does: the impact
  counts decide each run independently of its exponent, and the split must agree run by
  run.  The chaotic runs' exponent was 0.435 in an earlier independent check (issue 33).
* No islands: the rectangle (beta = 0) is integrable, every run regular; the dispersing
  table (beta = +0.3, a Sinai-like billiard) is chaotic everywhere, no run regular.
* The single-run rule of sinktheory.runstats.
"""

import math

import numpy as np
import pytest

from sinktheory.billiard import billiard
from sinktheory.chaos.verdicts import split, threshold
from sinktheory.errors import ParameterError
from sinktheory.model import RunSettings

PERIODS = 200


def _fixed(beta, runs):
    return billiard("flat", 0.5, beta, particles=1, lyapunov=True, fixed=True,
                    settings=RunSettings(runs=runs, periods=PERIODS, box=0.1))  # fmt: skip


def test_island_runs_are_the_regular_ones():
    r = _fixed(-0.3, 40)
    s = split(r.lambda1, PERIODS, starts="box 0.1")
    in_island = r.collisions[:, 1] == 0  # never reached y = +-1
    assert np.array_equal(r.lambda1 <= s.threshold, in_island)
    assert s.mixed and s.regular == in_island.sum()
    assert 0.4 < s.fraction < 0.9  # 61-68 % from the centre in the earlier check
    assert abs(s.chaotic_mean - 0.435) < 4 * s.chaotic_se + 0.02
    # the rule sits in a wide gap of the per-run distribution
    assert s.gap[0] < 0.5 * s.threshold and s.gap[1] > 20 * s.threshold
    assert s.regular_mean < s.threshold and np.isfinite(s.regular_se)
    assert 0 < s.fraction_se < 0.1


@pytest.mark.parametrize("beta, regular", [(0.0, 40), (0.3, 0)])
def test_no_islands_one_group(beta, regular):
    s = split(_fixed(beta, 40).lambda1, PERIODS)
    assert s.regular == regular and not s.mixed
    assert s.fraction_se == 0.0


def test_single_run_and_empty_groups():
    s = split([0.8], 300)
    assert s.runs == 1 and math.isnan(s.chaotic_se) and math.isnan(s.fraction_se)
    assert math.isnan(s.regular_mean) and math.isnan(s.gap[0])
    assert "(no standard error from one run)" in s.text() and "regular none" in s.text()
    d = s.as_dict()
    assert d["chaotic_lambda1"]["stderr"] is None and d["regular_lambda1"]["mean"] is None


def test_rule_is_the_envelope_of_the_span():
    t = 100 * 2 * math.pi
    assert threshold(100) == pytest.approx(3 * math.log(t) / t, rel=1e-15)
    cut = threshold(100)
    assert split([cut], 100).regular == 1 and split([cut * (1 + 1e-12)], 100).regular == 0


@pytest.mark.parametrize("bad", [[], [0.1, math.nan], [[math.inf]]])
def test_bad_exponents_refused(bad):
    with pytest.raises(ParameterError, match="lambda1"):
        split(bad, 100)


def test_plots_draw_each_group_of_a_mixed_ensemble():
    from sinktheory.chaos import ChaosResult
    from sinktheory.plot.chaos import convergence_figure

    times = 2 * np.pi * np.arange(201.0)
    regular = np.log1p(times)  # linear growth of a deviation: lambda_1(t) ~ ln t / t
    logs = np.stack([regular, regular, 0.4 * times, 0.45 * times])
    res = ChaosResult(times, logs, parameters={"period": 2 * np.pi, "box": 0.1})
    s = res.split()
    assert (s.regular, s.runs) == (2, 4) and s.chaotic_mean == pytest.approx(0.425)
    labels = [t.get_text() for t in convergence_figure(res).axes[0].get_legend().get_texts()]
    assert any("2 regular runs of 4" in t for t in labels)
    assert any("2 chaotic runs of 4" in t for t in labels)


def test_chaos_map_splits_each_beta():
    """A synthetic map: per-run exponents of a mixed, a regular and a chaotic beta; the
    span is the periods each beta ran less the transient."""
    import xarray as xr
    from matplotlib.figure import Figure

    from sinktheory.chaos.verdicts import map_split, verdicts
    from sinktheory.plot.chaos import draw_map

    cut = threshold(90)  # 100 periods, transient 10
    runs = [[0.5 * cut, 0.9 * cut, 0.4, 0.5], [0.5 * cut] * 4, [0.3, 0.4, 0.5, 0.6]]
    ds = xr.Dataset(
        {
            "lambda1": ("beta", np.mean(runs, axis=1)),
            "lambda1_se": ("beta", np.std(runs, axis=1, ddof=1) / 2),
            "lambda1_runs": (("beta", "run"), runs),
            "lambda1_periods": ("beta", [100.0] * 3),
        },
        coords={"beta": [-0.3, 0.0, 0.3], "run": np.arange(4)},
        attrs={"periods": 100, "transient": 10, "box": 0.01},
    )
    groups = map_split(ds)
    assert [g.regular for g in groups] == [2, 4, 0] and groups[0].threshold == cut
    assert groups[0].chaotic_mean == pytest.approx(0.45) and "(-0.01, 0.01)^2" in groups[0].starts
    v = verdicts(ds)
    assert v["regular_runs"].tolist() == [2, 4, 0] and v["mixed"].tolist() == [True, False, False]
    ax = Figure().subplots()
    draw_map(ds, [], ax)
    assert [t.get_text() for t in ax.texts] == ["2/4 reg."]
