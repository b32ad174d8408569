"""The design explorer's attachment dimension (issue 23): well, nes and impact side by side."""

import math

import numpy as np
import pytest
from _cli import run_cli

from sinktheory.attachments import Attachment, impulse_response
from sinktheory.design.explorer import explore
from sinktheory.design.point import SAMPLES
from sinktheory.errors import ParameterError
from sinktheory.sinkstats import equipartition_container_energy
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
    point = {"shape": "flat", "alpha": 0.5, "gamma": 1.0, "mass": 0.2, "container_energy": 0.5,
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


# --------------------------------------------------------------------------- equipartition
def _shell_share(energy, mu, potential, bounds, samples=2_000_000, width=0.01, seed=0):
    """<E_c> / E on the energy shell |H - E| < width E of the container and one particle
    on a line, by uniform sampling of (X, P, x, p) (the volume-preserving coordinates
    x = u - X, p = mu du/dt): an estimate of the microcanonical average independent of the
    formula, with its standard error."""
    rng = np.random.default_rng(seed)
    a, c, b = bounds
    X, P = rng.uniform(-a, a, (2, samples))
    x, p = rng.uniform(-c, c, samples), rng.uniform(-b, b, samples)
    ec = 0.5 * (X * X + P * P)
    H = ec + 0.5 * p * p / mu + potential(x)
    keep = np.abs(H - energy) < width * energy
    share = ec[keep] / H[keep]
    return share.mean(), share.std(ddof=1) / np.sqrt(share.size)


@pytest.mark.parametrize("n", [2, math.inf], ids=["cubic", "rigid"])
def test_line_equipartition_against_the_shell_average(n):
    """The 1-D equipartition share E / (1 + (1 + 1/n) / 2) (4/7 for the cubic NES, 2/3
    for rigid walls) against the shell average of the container's energy, within 4
    standard errors (about 0.003)."""
    E, mu, L = 0.05, 0.2, 0.2
    if n == math.inf:
        potential = lambda x: np.where(np.abs(x) <= L, 0.0, np.inf)  # noqa: E731
        reach = L
    else:
        potential = lambda x: 0.5 / n * (x / L) ** (2 * n)  # noqa: E731
        reach = L * (2 * n * E * 1.02) ** (1 / (2 * n))
    r = math.sqrt(2.04 * E)
    mean, se = _shell_share(E, mu, potential, (r, reach, r * math.sqrt(mu)))
    assert se < 0.002
    assert abs(mean - equipartition_container_energy(1.0, 1, n, dimension=1)) < 4 * se


def test_1d_points_use_the_line_equipartition_and_report_their_step():
    """The design explorer's 1-D points: equipartition E_total / (1 + (1 + 1/n) / 2) (the
    2-D formula 1 / (1 + 1 + 1/n) before), dt_used the response's step (NaN for the exact
    vibro-impact flow), and the damper they used (always the dashpot)."""
    run = _explore({**BASE, "attachment": ["nes", "impact"], "damping": 0.02}, seed=4)
    ds = run.dataset
    nes, impact = ds.sel(attachment="nes"), ds.sel(attachment="impact")
    assert float(nes.equipartition) == pytest.approx(float(nes.total_energy) / 1.75, rel=1e-14)
    assert float(impact.equipartition) == pytest.approx(float(impact.total_energy) / 1.5,
                                                        rel=1e-14)  # fmt: skip
    r = impulse_response(Attachment("nes", n=2), 0.5, damping=0.02, periods=1, runs=1,
                         tol=1e-6)  # fmt: skip
    assert float(nes.dt_used) == r.dt and 0 < r.dt < 0.1
    assert np.isnan(float(impact.dt_used))
    assert float(nes.dashpot) == 1.0 and float(impact.dashpot) == 1.0


def test_damping_kind_viscous_gives_the_well_the_same_dashpot():
    """damping_kind = viscous: the well's particles get the 1-D attachments' dashpot, c
    shared by the k particles (c/k each): the point equals simulate_inelastic with that
    dashpot to round-off; contact stays the wall contact; the NES does not change."""
    from sinktheory.damped import simulate_inelastic
    from sinktheory.design.point import compute, settings_of, sink_of

    params = {**BASE, "particles": 2, "damping": 0.05, "damping_kind": ["contact", "viscous"]}
    ds = _explore(params, seed=3).dataset
    viscous, contact = ds.sel(damping_kind="viscous"), ds.sel(damping_kind="contact")
    assert float(viscous.dashpot) == 1.0 and float(contact.dashpot) == 0.0
    p = {"shape": "flat", "alpha": 0.5, "gamma": 1.0, "mass": 0.2, "container_energy": 0.5,
         "box": 0.01, **BASE, "particles": 2}  # fmt: skip
    res = simulate_inelastic(sink_of(p), settings_of(p, point_seed(3, 1)), damping=0.025,
                             damping_kind="viscous", tol=1e-6)  # fmt: skip
    share = (res.dissipated[:, -1] / res.initial_energy).mean()
    assert float(viscous.dissipated) == pytest.approx(share, rel=1e-12)
    assert float(viscous.dissipated) != pytest.approx(float(contact.dissipated), rel=1e-3)
    nes = {**p, "particles": 1, "attachment": "nes", "damping": 0.02, "tol": 1e-6,
           "energy_bound": None, "transient": None, "sigmas": 3.0, "risk_level": 0.5,
           "rqa_eps": 0.01, "lyapunov_periods": 100, "replica": 0}  # fmt: skip
    a, b = (compute({**nes, "damping_kind": kind}, 7) for kind in ("contact", "viscous"))
    for name in a:
        np.testing.assert_array_equal(a[name], b[name], err_msg=name)


def test_cli_damping_kind_refused_in_one_line(capsys, tmp_path):
    store = tmp_path / "s.zarr"
    argv = ["design", "--beta", "0.3", "--n", "2", "--damping-kind", "sticky",
            "--out", str(store)]  # fmt: skip
    code, out, err = run_cli(argv, capsys)
    assert code == 2 and out == "" and "error: damping_kind = 'sticky'" in err
    assert len(err.strip().splitlines()) == 1 and not store.exists()
