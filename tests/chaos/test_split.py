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


@pytest.fixture(scope="module")
def table_map():
    """A chaos map over three betas made of the rigid fixed tables' runs (their lambda_1
    per run), with each run's wall-1 impacts: the focusing table (-0.3) mixed, the
    rectangle (0) all regular, the dispersing table (+0.3) all chaotic."""
    import xarray as xr

    betas = [-0.3, 0.0, 0.3]
    results = [_fixed(b, 24) for b in betas]
    runs = np.array([r.lambda1 for r in results])
    se = runs.std(axis=1, ddof=1) / np.sqrt(runs.shape[1])
    ds = xr.Dataset(
        {
            "lambda1": ("beta", runs.mean(axis=1)),
            "lambda1_se": ("beta", se),
            "lambda1_runs": (("beta", "run"), runs),
            "lambda1_periods": ("beta", [float(PERIODS)] * 3),
        },
        coords={"beta": betas, "run": np.arange(runs.shape[1])},
        attrs={"periods": PERIODS, "transient": 0, "box": 0.1, "runs": runs.shape[1]},
    )
    return ds, np.array([r.collisions[:, 1] == 0 for r in results])


def test_agreement_scores_only_unmixed_betas(table_map):
    """A theory is scored run by run: the island table is reported as mixed with the
    fraction of runs that never reach the flat walls (the independent count), not
    averaged into a verdict."""
    from sinktheory.chaos.verdicts import agreement, map_calls

    ds, island = table_map
    c = map_calls(ds)
    assert c["calls"].tolist() == [0, -1, 1]
    assert c["regular_fraction"][0] == island[0].mean() and 0 < island[0].mean() < 1
    # the old mean rule called the focusing table chaotic: its mean is far above the cut
    assert ds.lambda1.values[0] - 2 * ds.lambda1_se.values[0] > threshold(PERIODS)
    a = agreement(ds, stable=np.array([True, True, False]))
    assert (a["chaotic"], a["regular"], a["mixed"], a["scored"]) == (1, 1, 1, 2)
    assert a["mixed_beta"] == [-0.3] and a["regular_fraction"] == [island[0].mean()]
    assert a["floquet"] == 1.0  # right at both scored betas; the mean rule would give 2/3
    assert agreement(ds, stable=np.array([False, False, False]))["floquet"] == 0.5


def test_orbit_and_nnm_reports_name_the_mixed_beta(table_map):
    """Fig. 3/11's generic-start text and the NNM agreement statement give the mixed beta
    with its regular fraction (the island runs' share) instead of a mean verdict."""
    from sinktheory import Sink, Well
    from sinktheory.nnm.agreement import TransverseChart, agreement_report
    from sinktheory.scenes.orbits import generic_runs

    ds, island = table_map
    pct = f"{100 * island[0].mean():.0f} %"
    assert generic_runs(ds) == (
        "have every run chaotic at 1, their runs split into regular and chaotic at 1 and "
        f"every run regular at 1 of 3 betas (regular fraction {pct} at -0.300)"
    )
    betas = np.array([-0.3, 0.0, 0.3])
    chart = TransverseChart(betas, np.zeros((3, 1)), np.array([True, True, False]),
                            np.ones(3), branch=None)  # fmt: skip
    sink = Sink(Well(0.5, 0.0, 4), particles=1, mass=0.2)
    r = agreement_report(sink, 0.5, betas, chaos=ds, chart=chart)
    assert r["calls"] == [0, -1, 1] and r["mixed_beta"] == [-0.3] and r["nnm"] == 1.0
    assert f"the runs split at beta = -0.3 ({pct} regular)" in r["statement"]
    assert "at 100 % of the 2 betas whose runs are all regular or all chaotic" in r["statement"]
