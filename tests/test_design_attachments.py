"""The design explorer's attachment dimension (issue 23): well, nes and impact side by side."""

import numpy as np
import pytest
from _cli import run_cli

from sinktheory.attachments import Attachment, impulse_response
from sinktheory.design.explorer import explore
from sinktheory.design.point import SAMPLES
from sinktheory.errors import ParameterError
from sinktheory.sweep.grid import point_seed

BASE = {"beta": 0.3, "n": 2, "runs": 3, "periods": 12, "horizons": "6+12",
        "lyapunov_runs": 0, "bootstrap": 10}  # fmt: skip


def _explore(params, seed=0):
    return explore(params, seed, workers=1, progress=False, estimate_first=False)


def test_the_three_attachments_rank_side_by_side():
    """A sweep over the attachment ranks all three; each 1-D point's absorbed fraction is
    recomputed from impulse_response with the point's seed (1 - <E(hT)>/E0, the record
    taken every SAMPLES samples), its dissipated share from the same runs, to round-off."""
    run = _explore({**BASE, "attachment": ["well", "nes", "impact"], "damping": 0.02}, seed=4)
    assert sorted(r["attachment"] for r in run.ranked) == ["impact", "nes", "well"]
    ds = run.dataset
    for i, kind in enumerate(("well", "nes", "impact")):
        point = ds.sel(attachment=kind)
        if kind == "well":
            continue
        r = impulse_response(Attachment(kind, n=2), 0.5, damping=0.02, periods=12, runs=3,
                             seed=point_seed(4, i), samples_per_period=SAMPLES,
                             tol=1e-6)  # fmt: skip
        e = r.container_energy[:, ::SAMPLES]
        absorbed = 1 - e.mean(axis=0)[[6, 12]] / 0.5
        np.testing.assert_allclose(point.absorbed.values, absorbed, rtol=1e-12)
        share = r.fraction_dissipated().mean()
        assert float(point.dissipated) == pytest.approx(share, rel=1e-12)
        assert float(point.zeta_eq) > 0 and np.isnan(float(point.lambda1))


def test_default_is_the_well_bitwise():
    """Leaving the attachment out, or naming the default, gives the same results, and a
    point dict without the key (a caller from before the dimension) computes the same."""
    from sinktheory.design.point import compute

    a = _explore({**BASE, "particles": [1, 2]}, seed=2).dataset
    b = _explore({**BASE, "particles": [1, 2], "attachment": "well"}, seed=2).dataset
    for name in a.data_vars:
        np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)
    point = {"shape": "flat", "alpha": 0.5, "gamma": 1.0, "mass": 0.2, "energy": 0.5,
             "box": 0.01, "tol": 1e-6, "energy_bound": None, "transient": None,
             "sigmas": 3.0, "risk_level": 0.5, "rqa_eps": 0.01, "lyapunov_periods": 100,
             "damping": 0.0, "replica": 0, **BASE, "particles": 1}  # fmt: skip
    out = compute(point, point_seed(2, 0))
    np.testing.assert_array_equal(out["mean_energy"], a.mean_energy.isel(particles=0).values)


@pytest.mark.parametrize(
    "extra, name",
    [
        ({"particles": 2}, "particles"),
        ({"gamma": 2.0}, "gamma"),
        ({"attachment": "spring"}, "attachment"),
    ],
)
def test_1d_attachments_refuse_what_they_cannot_take(extra, name):
    params = {**BASE, "attachment": "nes", **extra}
    with pytest.raises(ParameterError, match=f"^{name} ="):
        _explore(params)


def test_cli_attachment_refused_in_one_line(capsys, tmp_path):
    store = tmp_path / "s.zarr"
    argv = ["design", "--beta", "0.3", "--n", "2", "--attachment", "nes", "--particles", "3",
            "--out", str(store)]  # fmt: skip
    code, out, err = run_cli(argv, capsys)
    assert code == 2 and out == "" and "error: particles = 3" in err
    assert len(err.strip().splitlines()) == 1 and not store.exists()
