"""Sweeps of a user's well (``well`` in Python, ``--well FILE`` on the command line): the
paper's flat well typed as a user's expression gives the registry's sections, a
Hénon–Heiles ensemble sweep gives simulate's numbers, the store keeps the well's text (a
resumed sweep equals a fresh one bit for bit; a changed file is refused on resume) and a
point rebuilds its well from that text alone.

References: the registry's flat well (its hand-declared wall ratios against SymPy's
derivatives of the user's text) and ``simulate`` of a WellAt, each computed here.
"""

import json
import pickle
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import zarr
from _cli import BUILT_IN, HH, LIFTED_HH, PAPER, refused_well, run_cli, write_well_file

from sinktheory import RunSettings, Sink
from sinktheory.errors import ParameterError
from sinktheory.simulate import simulate
from sinktheory.sweep import Sweep, bifurcation_diagram, run_sweep
from sinktheory.userwell import UserWell, load_well
from sinktheory.wellat import WellAt

SECTIONS = {"transient": 2, "count": 3}
FLAT = UserWell("paperflat", BUILT_IN["flat"], PAPER)


def test_a_bifurcation_sweep_of_the_flat_well_typed_by_a_user_is_the_registry():
    """Sections over the well's own beta, to 1e-12 (measured: identical)."""
    betas = [0.1, 0.3]
    user = run_sweep("bifurcation", {"beta": betas, **SECTIONS}, well=FLAT, workers=1,
                     progress=False)  # fmt: skip
    registry = run_sweep("bifurcation", {"alpha": 0.5, "beta": betas, "n": 4, **SECTIONS},
                         workers=1, progress=False)  # fmt: skip
    np.testing.assert_allclose(user.section.values, registry.section.values, rtol=1e-12, atol=0)
    assert user.attrs["n"] == 4.0  # the well's own parameters label the store
    assert "shape" not in user.attrs and user.attrs["well"].startswith('name = "paperflat"')
    diagram = bifurcation_diagram(user)  # read back as the well's diagram
    assert (diagram.name, diagram.parameter, diagram.value.tolist()) == ("paperflat", "beta",
                                                                          betas)  # fmt: skip
    assert diagram.parameters == {"alpha": 0.5, "gamma": 1.0, "n": 4.0}
    assert np.array_equal(diagram.section, user.section.values)


def test_an_ensemble_sweep_of_henon_heiles_is_simulate_of_its_well():
    """Each point's ensemble is simulate's, seeded with the point's seed (bit for bit)."""
    hh = UserWell("hh", HH, {})
    params = {"well": hh, "container_energy": [0.01, 0.02], "runs": 2, "periods": 2}
    sweep = Sweep.make("ensemble", params)
    ds = run_sweep("ensemble", params, workers=1, progress=False)
    for i, e0 in enumerate((0.01, 0.02)):
        seed = sweep._task(i)[2]
        res = simulate(Sink(WellAt(hh), 1, 0.2), RunSettings(container_energy=e0, runs=2,
                       periods=2, seed=seed), progress=False)  # fmt: skip
        assert np.array_equal(ds.mean_energy.values[i], res.ensemble_energy()[0])


def test_a_point_rebuilds_its_well_from_the_stored_text(tmp_path):
    """What a worker receives (a pickled task) holds the well's text, not the file: the
    point computes after the file is gone, in a process that never read it."""
    path = write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], PAPER)
    sweep = Sweep.make("bifurcation", {"well": load_well(path), "beta": 0.3, **SECTIONS})
    task = pickle.dumps(sweep._task(0))
    path.unlink()
    from sinktheory import ensemble

    ensemble.well_of_text.cache_clear(), ensemble._well_at.cache_clear()
    _, point, seed = pickle.loads(task)
    assert str(path) not in point["well"]
    section = sweep.kind.compute(point, seed)["section"]
    registry = run_sweep("bifurcation", {"alpha": 0.5, "beta": 0.3, "n": 4, **SECTIONS},
                         workers=1, progress=False)  # fmt: skip
    np.testing.assert_allclose(section, registry.section.values, rtol=1e-12, atol=0)


def test_the_command_line_resumes_a_well_sweep_and_refuses_a_changed_file(
    tmp_path, capsys, monkeypatch
):
    path = write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], PAPER)
    store = tmp_path / "s.zarr"
    args = ["sweep", "bifurcation", "--well", str(path), "--param", "beta=0.1,0.2,0.3",
            "--well-param", "n=4", "--param", "transient=2", "--param", "count=3", "--out",
            str(store), "--workers", "1", "--quiet", "--json"]  # fmt: skip
    code, out, err = run_cli(args, capsys)
    assert code == 0, err
    fresh = xr.open_zarr(store).load()
    assert json.loads(out)["dims"] == {"beta": 3}
    # two points lost (flag cleared, data spoiled): --resume computes them again
    group = zarr.open_group(store, mode="r+")
    done, section = group["done"][...], group["section"][...]
    done[[0, 2]], section[[0, 2]] = False, 12345.0
    group["done"][...], group["section"][...] = done, section
    code, out, err = run_cli([*args, "--resume"], capsys)
    assert code == 0, err
    assert (json.loads(out)["computed"], json.loads(out)["skipped"]) == (2, 1)
    resumed = xr.open_zarr(store)
    for name in ("section", "done", "point_seed"):
        assert np.array_equal(resumed[name].values, fresh[name].values), name
    # the file changed (another range of beta): the store's well is not this one
    changed = write_well_file(tmp_path, "paperflat", BUILT_IN["flat"],
                              {**PAPER, "beta": (0.3, (-5.0, 0.4))})  # fmt: skip
    assert changed == path
    line = refused_well(
        [*args, "--resume"],
        capsys,
        tmp_path,
        monkeypatch,
        "the well differs: beta = { default = 0.3, range = [-5.0, 0.45] } there",
    )
    assert "range = [-5.0, 0.4] } here" in line


@pytest.mark.parametrize(
    "extra,reason",
    [
        (
            ["--param", "shape=flat"],
            "shape = ['flat'] is not allowed: must be left out beside "
            "a well (it defines the shape; its parameters: alpha, beta,",
        ),
        (["--param", "beta=0.1,0.5"], "0.5"),
        (["--well-param", "beta=0.2"], "beta = 'beta=0.2' is not allowed: must be given once"),
    ],
)
def test_the_command_line_refuses_a_shape_beside_a_well(extra, reason, tmp_path, capsys,
                                                          monkeypatch):  # fmt: skip
    path = write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], PAPER)
    args = ["sweep", "bifurcation", "--well", str(path), "--param", "beta=0.1",
            "--out", str(tmp_path / "s.zarr"), "--quiet", *extra]  # fmt: skip
    refused_well(args, capsys, tmp_path, monkeypatch, reason)


def test_a_design_sweep_takes_a_well_on_its_shape_axis():
    """As ``well`` it is refused, saying where it goes; ``sweep design --well FILE`` puts it
    there, beside the shapes of --param shape=..."""
    import argparse

    from sinktheory.commands.sweep import params_with_well

    with pytest.raises(ParameterError, match=r"^well = 'hh' .* on the shape axis of a design"):
        Sweep.make("design", {"well": UserWell("hh", HH, {})})
    path = str(Path(__file__).parents[2] / "docs" / "guide" / "elliptic.toml")
    args = argparse.Namespace(kind="design", param=["shape=flat"], well=path, well_param=[])
    shapes = params_with_well(args)["shape"]
    assert shapes[0] == "flat" and shapes[1].name == "elliptic" and len(shapes) == 2


def test_a_floquet_sweep_of_the_elliptic_well_is_its_closed_form():
    """Over the semi-axis b at n = 1 the motion on y = 0 is harmonic and phi_half =
    cos(pi a / b) exactly (held to 1e-10); the rotation number is arccos of it over pi.
    Hénon–Heiles, whose y = 0 is not invariant, is refused with the reason."""
    from _cli import ELLIPTIC

    well = UserWell("elliptic", ELLIPTIC, {"a": 0.5, "b": 0.3, "gamma": 1.0, "n": (4, (1, 100))})
    bs = [0.4, 0.7, 1.2]
    ds = run_sweep("floquet", {"b": bs, "n": 1, "amplitude": 0.2}, well=well, workers=1,
                   progress=False)  # fmt: skip
    exact = np.cos(np.pi * 0.5 / np.array(bs))
    np.testing.assert_allclose(ds.phi_half.values, exact, rtol=0, atol=1e-10)
    np.testing.assert_allclose(ds.rotation_number.values, np.arccos(exact) / np.pi, atol=1e-9)
    assert ds.stable.values.tolist() == [True, True, True] and np.isnan(ds.lam.values).all()
    with pytest.raises(ParameterError, match=r"dV/dy\(x, 0\) = x\*\*2"):
        run_sweep("floquet", {"amplitude": 0.2}, well=UserWell("hh", HH, {}), workers=1,
                  progress=False)  # fmt: skip


def test_a_floquet_sweep_s_rotation_number_near_the_edges_of_stability():
    """The elliptic well at n = 1 has rotation number a/b exactly (phi_half = cos(pi a/b)):
    at a/b = 1e-6, phi_half = 1 - 4.9e-12, it is held to 1e-12 relative (measured 1.3e-15),
    and at a/b = 1 - 1e-6 its distance from 1 to 1e-7 relative (measured 4.9e-9).  Plain
    arccos of phi_half was off by 3e-5 and 1.5e-4 there."""
    from _cli import ELLIPTIC

    well = UserWell("elliptic", ELLIPTIC, {"a": 0.5, "b": 1.0, "gamma": 1.0, "n": 1})
    bs = [5e5, 0.5 / (1 - 1e-6)]
    ds = run_sweep("floquet", {"b": bs, "amplitude": 0.2}, well=well, workers=1,
                   progress=False)  # fmt: skip
    near_plus, near_minus = ds.rotation_number.values
    assert abs(near_plus - 0.5 / bs[0]) <= 1e-12 * (0.5 / bs[0])
    assert abs((1 - near_minus) - (1 - 0.5 / bs[1])) <= 1e-7 * (1 - 0.5 / bs[1])


def test_well_bifurcation_over_the_flat_well_s_own_beta_is_the_registry_diagram():
    from sinktheory.bifurcation import bifurcation, well_bifurcation

    user = well_bifurcation(WellAt(FLAT, n=4), "beta", [0.1, 0.3], **SECTIONS)
    registry = bifurcation([0.1, 0.3], alpha=0.5, n=4, **SECTIONS)
    np.testing.assert_allclose(user.section, registry.section, rtol=1e-12, atol=0)
    assert user.parameters == {"alpha": 0.5, "gamma": 1.0, "n": 4.0}
    with pytest.raises(ParameterError, match=r"^beta: 0.5 is refused: outside the range"):
        well_bifurcation(WellAt(FLAT), "beta", [0.1, 0.5], **SECTIONS)  # its range ends at 0.45
    with pytest.raises(ParameterError, match=r"^parameter = 'b' .* one of 'alpha', 'beta'"):
        well_bifurcation(WellAt(FLAT), "b", [0.1], **SECTIONS)


def test_a_well_parameter_named_like_a_setting_of_the_kind_is_refused():
    runs = UserWell("runny", "runs*(x**2 + y**2)/2", {"runs": 1.0})
    with pytest.raises(
        ParameterError,
        match=r"^well = 'runny' .* not named like the ensemble "
        r"sweep's settings \(runs is one\)",
    ):
        Sweep.make("ensemble", {"well": runs})


def test_a_chaos_sweep_of_the_flat_well_typed_by_a_user_is_the_registry():
    """lambda_1 of every run over the well's own beta, same seeds, to 1e-12; the lifted
    Hénon–Heiles well's transverse exponent is refused with the reason."""
    small = {"beta": [0.1, 0.3], "particles": 2, "runs": 2, "periods": 5}
    user = run_sweep("chaos", small, well=FLAT, workers=1, progress=False)
    registry = run_sweep("chaos", {"alpha": 0.5, "n": 4, **small}, workers=1, progress=False)
    assert np.isfinite(registry.lambda1.values).all()
    np.testing.assert_allclose(user.lambda1.values, registry.lambda1.values, rtol=1e-12, atol=0)
    with pytest.raises(ParameterError, match=r"dV/dy\(x, 0\) = x\*\*2"):
        run_sweep("chaos", {"well": UserWell("hh", LIFTED_HH, {}), "container_energy": 0.02,
                            "transverse": 1, "runs": 2, "periods": 2}, workers=1,
                  progress=False)  # fmt: skip


def test_an_ergodicity_sweep_of_the_flat_well_typed_by_a_user_is_the_registry():
    """The law (well_law's quadrature against the registry's closed form), the runs'
    statistics and lambda_1 with the same seeds: every result to 1e-12 (measured 6e-15).
    (At beta = 0.3, n = 4 the law's ray quadrature does not converge near the wall's
    corners and the point stops with that reason: the limit in user_wells.rst.)"""
    small = {"beta": [-0.2, 0.1], "particles": 2, "runs": 2, "periods": 12, "transient": 4,
             "lyapunov_runs": 2, "lyapunov_periods": 4}  # fmt: skip
    user = run_sweep("ergodicity", small, well=FLAT, workers=1, progress=False)
    registry = run_sweep("ergodicity", {"alpha": 0.5, "n": 4, **small}, workers=1,
                         progress=False)  # fmt: skip
    assert np.isfinite(registry.law_mean.values).all() and np.isfinite(registry.lambda1).all()
    for name in registry.data_vars:
        if registry[name].dtype.kind == "f":
            np.testing.assert_allclose(user[name].values, registry[name].values, rtol=1e-12,
                                       atol=1e-300, err_msg=name)  # fmt: skip
