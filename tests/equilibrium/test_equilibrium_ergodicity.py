"""The ergodicity map: the verdict rule, the point function, the sweep kind and the chart."""

import math
import re

import numpy as np
import pytest

from sinktheory.equilibrium.ergodicity import (
    check_point,
    ergodicity_map,
    ergodicity_point,
    fractions_of,
    verdict,
)
from sinktheory.errors import ParameterError
from sinktheory.sweep import point_seed, run_sweep

SMALL = {
    "alpha": 0.5,
    "n": 4,
    "runs": 3,
    "periods": 120,
    "transient": 20,
    "lyapunov_runs": 2,
    "lyapunov_periods": 30,
}


def test_verdict_rule():
    """Chaotic as the chaos map says: lambda_1 - 2 se above 3 ln t / t (0.0093 over 400
    periods), so a regular orbit's small positive finite-time exponent is regular."""
    t = 400 * 2 * math.pi
    assert 3 * math.log(t) / t == pytest.approx(0.009346, abs=1e-6)
    assert verdict(math.nan, math.nan, 400, 0.5, 0.0) == -1
    assert verdict(0.01, 0.01, 400, 0.5, 0.0) == 0  # lambda_1 within 2 se of zero: regular
    assert verdict(0.0036, 0.0003, 400, 0.5, 0.0) == 0  # all-regular runs (n = 2, beta -0.074)
    assert verdict(0.02, 0.003, 400, 0.5, 0.0) == 2  # 0.014 above the threshold 0.0093
    assert verdict(0.3, 0.01, 400, 0.5, 0.5) == 2
    assert verdict(0.3, 0.01, 400, 0.001, 0.5) == 1  # the KS test rejects the law
    assert verdict(0.3, 0.01, 400, 0.5, 4.0) == 1  # the mean misses the law's


def test_sweep_points_equal_the_point_function():
    ds = run_sweep("ergodicity", {**SMALL, "beta": [0.2, 0.3]}, seed=5, workers=1, progress=False)
    assert ds.tail_ratio.dims == ("beta", "fraction")
    assert ds.fraction.values.tolist() == [0.2, 0.5, 0.8]
    for i, beta in enumerate((0.2, 0.3)):
        direct = ergodicity_point({**SMALL, "beta": beta}, point_seed(5, i))
        for name in ("ks_distance", "ks_pvalue", "lambda1", "verdict", "mean_z"):
            assert ds[name].sel(beta=beta).item() == pytest.approx(direct[name], rel=1e-15)
        assert np.array_equal(ds.tail_ratio.sel(beta=beta).values, direct["tail_ratio"])


def test_map_and_chart():
    from sinktheory.plot.equilibrium import plot_ergodicity

    m = ergodicity_map([0.2, 0.3], seed=2, progress=False, **SMALL)
    assert m.verdict.shape == (2,) and set(m.verdict.tolist()) <= {0, 1, 2}
    assert np.all(m.lambda1 > 0)  # the Fig. 8 well is chaotic at these beta
    ds = m.to_dataset()
    assert ds.tail_ratio.dims == ("beta", "fraction")
    fig = plot_ergodicity(m)
    assert len(fig.axes) == 2
    # no regular Lyapunov run here: the chaotic group is the whole ensemble
    assert m.regular_runs.tolist() == [0, 0]
    np.testing.assert_allclose(m.lambda1_chaotic, m.lambda1, rtol=1e-12)
    assert np.isnan(m.lambda1_regular).all()


def test_chart_shows_both_groups_of_a_mixed_point():
    from dataclasses import replace

    from sinktheory.plot.equilibrium import plot_ergodicity

    m = ergodicity_map([0.2], seed=2, progress=False, **{**SMALL, "runs": 2, "periods": 40})
    mixed = replace(m, regular_runs=np.array([1.0]), lambda1_regular=np.array([0.01]),
                    lambda1_chaotic=np.array([0.4]))  # fmt: skip
    texts = [t.get_text() for t in plot_ergodicity(mixed).axes[1].texts]
    assert texts == ["1/2 reg."]
    regular = replace(m, regular_runs=np.array([2.0]))
    legend = plot_ergodicity(regular).axes[1].get_legend().get_texts()
    assert [t.get_text() for t in legend] == [r"every run regular ($\lambda_1 \leq 3 \ln t / t$)"]


def test_bad_points_are_refused_before_running():
    with pytest.raises(ParameterError, match="fractions"):
        fractions_of("0.2,x")
    with pytest.raises(ParameterError, match="fraction"):
        fractions_of("0.2,1.5")
    with pytest.raises(ParameterError, match="transient"):
        run_sweep("ergodicity", {**SMALL, "beta": 0.3, "transient": 200}, progress=False)
    with pytest.raises(ParameterError, match="runs"):
        run_sweep("ergodicity", {**SMALL, "beta": 0.3, "runs": 1}, progress=False)


def test_a_box_that_spreads_the_runs_over_shells_is_refused_naming_box():
    """Near the symmetric well's corner saddle (alpha = 1, beta = 0.99, n = 6) the default
    start box reaches high up the well: the runs' total energies, measured by the engine's
    energy kernel, spread by more than ENERGY_SLACK, so no one law fits them.  The point is
    refused before it runs, naming box, with a bound (k V at the box's corner) no smaller
    than that measured spread; the largest box it states holds V = ENERGY_SLACK E0 at its
    corner (by hand), and a point started there computes."""
    from sinktheory.equilibrium.lifetime import ENERGY_SLACK
    from sinktheory.model import RunSettings, Sink, Well
    from sinktheory.simulate import simulate

    point = {"shape": "symmetric", "alpha": 1.0, "beta": 0.99, "n": 6, "runs": 8,
             "periods": 40, "transient": 10, "lyapunov_runs": 0}  # fmt: skip
    sink = Sink(Well(1.0, 0.99, 6, shape="symmetric"))
    h0 = simulate(sink, RunSettings(runs=64, periods=1, seed=1), progress=False).initial_energy
    assert h0.max() - h0.min() > ENERGY_SLACK * 0.5  # measured: the runs sit on other shells
    with pytest.raises(
        ParameterError,
        match=r"box = 0.01 is not allowed: must be a start box "
        r"whose runs share one energy shell \(<= (0\.\d+) here\)",
    ) as refusal:
        check_point(point)  # nothing has run
    largest = float(re.search(r"<= (0\.\d+) here", str(refusal.value)).group(1))

    def corner(b):  # V of the symmetric well at (b, b), by hand: 2/(2n) (b / D(b))^2n
        return 2 / 12 * (b / (1.0 + 0.99 * (b * b - 1))) ** 12

    assert h0.max() - 0.5 <= corner(0.01) and f"add up to {corner(0.01):.4g}" in str(refusal.value)
    assert corner(largest) == pytest.approx(ENERGY_SLACK * 0.5, rel=0.1)  # 2 digits of the box
    out = ergodicity_point({**point, "box": largest}, seed=1)
    assert 0 < out["ks_distance"] < 1 and math.isfinite(out["mean_z"])
