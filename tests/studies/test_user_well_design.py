"""``design`` with users' wells on its shape axis (Python: a UserWell among the shapes;
the command line: ``--shape flat,FILE.toml``): the paper's flat well typed as a user's
expression gives the registry's design measures, the estimate counts one engine per
well, and a well the design cannot use is refused with the reason.

Reference: the registry's flat well, computed here with the same point seed.
"""

import json

import numpy as np
import pytest
import xarray as xr
from _cli import BUILT_IN, PAPER, refused_well, run_cli, write_well_file

from sinktheory.design.cost import uncompiled
from sinktheory.design.explorer import explore
from sinktheory.engine.cache import sink_name, well_name
from sinktheory.sweep import Sweep
from sinktheory.userwell import UserWell

BASE = {"beta": 0.3, "n": 4, "runs": 2, "periods": 12, "horizons": "6+12", "bootstrap": 10,
        "lyapunov_runs": 0}  # fmt: skip
FLAT = UserWell("paperflat", BUILT_IN["flat"], PAPER)


def test_the_flat_well_typed_by_a_user_is_the_registry_design():
    """Every stored measure to 1e-12, lambda_1 and its split included (one point each, so
    the same point seed)."""
    chaos = {"lyapunov_runs": 2, "lyapunov_periods": 5}
    user = explore({**BASE, **chaos, "shape": [FLAT]}, workers=1, progress=False,
                   estimate_first=False).dataset  # fmt: skip
    registry = explore({**BASE, **chaos, "shape": "flat"}, workers=1, progress=False,
                       estimate_first=False).dataset  # fmt: skip
    assert np.isfinite(registry.lambda1.values).all()
    assert user.attrs["shape"] == "paperflat"
    assert json.loads(user.attrs["wells"])["paperflat"].startswith('name = "paperflat"')
    for name, values in registry.data_vars.items():
        np.testing.assert_allclose(user[name].values, values.values, rtol=1e-12, atol=0,
                                   err_msg=name)  # fmt: skip


@pytest.mark.parametrize(
    "potential,degree", [("x**n + y**n", 4), ("sqrt(x**2 + y**2)**3 + x**2*y**2", 3)]
)
def test_the_equipartition_share_of_a_user_s_well_is_that_of_its_degree(potential, degree):
    """x^n + y^n is homogeneous of degree n, not 2n: by the virial theorem each particle
    holds Theta of kinetic and 2 Theta/d of potential energy (degree d) against the
    container's Theta, so the share is E/(1 + k (1 + 2/d)): E/(1 + 1.5 k) at n = 4 (it was
    read as E/(1 + 1.25 k), the degree taken for 2n); r^3 + x^2 y^2 has the leading
    degree 3 at the centre.  The design's measure of a point against that closed form, to
    1e-12 (end to end, a whole design of Hénon–Heiles, harmonic at its centre, is
    checked in tests/interface/test_well_file_matrix.py)."""
    from sinktheory.design.measures import design_measures
    from sinktheory.design.point import equipartition_n

    well = UserWell("power", potential, {"n": (4, (2, 8))})
    k, total = 2, 0.3
    point = Sweep.make("design", {**BASE, "shape": [well], "particles": k}).grid.point(0)
    n = equipartition_n(point)
    assert n == degree / 2
    energies = np.full((2, 13), 0.1) + 0.01 * np.arange(13)
    m = design_measures(energies, e0=0.1, total_energy=total, particles=k, n=n,
                        horizons=[6, 12], bootstrap=10)  # fmt: skip
    assert m.equipartition == pytest.approx(total / (1 + k * (1 + 2 / degree)), rel=1e-12)


def test_the_estimate_counts_one_engine_per_well():
    """After the flat engines exist, a new well (never compiled: no test runs it) is one
    engine to compile, whatever its n; the registry's flat and the user's flat none."""
    fresh = UserWell("fresh", "gamma/(2*n)*(x**2 + y**2)**n + x**4*y**2", {"gamma": 1.0,
                     "n": (2, (1, 10)), "alpha": 0.5, "beta": 0.3})  # fmt: skip
    explore({**BASE, "shape": ["flat", FLAT], "runs": 2, "periods": 2, "horizons": "2"},
            workers=1, progress=False, estimate_first=False)  # fmt: skip
    sweep = Sweep.make("design", {**BASE, "shape": ["flat", FLAT, fresh], "n": [2, 3]})
    points = [sweep.grid.point(i) for i in range(sweep.grid.size)]
    assert uncompiled(points) == [well_name(fresh)]
    assert sink_name("flat") not in uncompiled(points)
    # the report's settling prediction gives its reason for a user's well
    from sinktheory.design.settling import predicted_settling

    user = next(p for p in points if p["shape"] == "paperflat")
    assert predicted_settling(user).startswith("n/a: a user's well")


def test_the_command_line_takes_a_well_file_on_the_shape_axis(tmp_path, capsys, monkeypatch):
    path = write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], PAPER)
    store = tmp_path / "d.zarr"
    args = ["design", "--shape", f"flat,{path}", "--beta", "0.3", "--n", "4", "--runs", "2",
            "--periods", "12", "--horizons", "6,12", "--bootstrap", "10", "--lyapunov-runs", "2",
            "--lyapunov-periods", "5", "--out", str(store),
            "--workers", "1", "--no-estimate", "--quiet", "--json"]  # fmt: skip
    code, out, err = run_cli(args, capsys)
    assert code == 0, err
    ds = xr.open_zarr(store)
    assert ds.shape.values.tolist() == ["flat", "paperflat"] and bool(ds.done.all())
    assert np.isfinite(ds.lambda1.values).all()  # the user's on its own engine
    assert {d["shape"] for d in json.loads(out)["designs"]} == {"flat", "paperflat"}
    # resumed with the file changed: refused
    write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], {**PAPER, "gamma": 2.0})
    refused_well([*args, "--resume"], capsys, tmp_path, monkeypatch, "store = ")


@pytest.mark.parametrize(
    "shape,extra,reason",
    [
        (
            "valley",
            [],
            "shape = 'valley' is not allowed: must be a well whose leading term at the centre "
            "is a form positive in every direction (the design's equipartition share",
        ),
        ("nosuch.toml", [], "must be one of flat, symmetric, circular or a TOML well file"),
        (
            "paperflat",
            ["--well-param", "n=3"],
            "well_param = 'n=3' is not allowed: must be a "
            "parameter of a well file other than a design axis",
        ),
        (
            "paperflat",
            ["--attachment", "nes"],
            "attachment = 'nes' is not allowed: must be well with the user's well paperflat",
        ),
    ],
)
def test_a_well_the_design_cannot_use_is_refused(shape, extra, reason, tmp_path, capsys,
                                                 monkeypatch):  # fmt: skip
    write_well_file(tmp_path, "valley", "x**2 + y**4")  # x^2 vanishes along y
    write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], PAPER)
    args = ["design", "--shape", f"{shape}" + (".toml" if "." not in shape else ""),
            "--beta", "0.3", "--n", "4", "--out", str(tmp_path / "d.zarr"), "--quiet",
            *extra]  # fmt: skip
    refused_well(args, capsys, tmp_path, monkeypatch, reason)
