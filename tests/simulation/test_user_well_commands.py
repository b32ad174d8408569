"""``sink``, ``chaos``, ``lifetime`` and ``compare`` on a user's well
(:class:`sinktheory.wellat.WellAt`, ``--well FILE``).

Two wells, so that only two engines are compiled (the engine cache is keyed by the
definition, so the paper's flat well is shared with test_user_well_simulate.py):

* the paper's flat well typed as a user's expression: each command gives the registry's
  numbers, same seed (a second derivation of the same model);
* a Hénon–Heiles well lifted by 1 (V(0, 0) = 1, energies measured from the centre): its
  escape energy 1/6 (exact), the volume preservation of the flow (the Lyapunov exponents
  sum to 0), the energy balance of the damped runs, and the equilibrium law of the
  unlifted well at the energy the runs start with (closed form of V on the start box);
  the transverse exponent and the 1-D attachments, which need an invariant line y = 0,
  are refused with the reason.
"""

import numpy as np
import pytest
from _cli import BUILT_IN, HH, LIFTED_HH, PAPER, cli_json, refused_well, write_well_file
from scipy import optimize

from sinktheory import RunSettings, Sink, Well
from sinktheory.attachments import Attachment
from sinktheory.chaos import chaos
from sinktheory.compare.efficiency import attachments_of, compare
from sinktheory.equilibrium import well_law
from sinktheory.equilibrium.prediction import measure_settling, predict_relaxation
from sinktheory.errors import ParameterError
from sinktheory.userwell import UserWell
from sinktheory.wellat import WellAt

#: Hénon–Heiles lifted by 1: every energy of the commands is measured from V(0, 0) = 1
LIFTED = LIFTED_HH
REGISTRY = ["--shape", "flat", "--alpha", "0.5", "--beta", "0.3", "--n", "4"]


@pytest.fixture
def files(tmp_path):
    return {
        "flat": str(write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], PAPER)),
        "hh": str(write_well_file(tmp_path, "hh", LIFTED)),
    }


@pytest.fixture(scope="module")
def hh():
    return WellAt(UserWell("hh", LIFTED, {}))


def hh_box_energy(box: float) -> float:
    """The largest V - V(0, 0) of Hénon–Heiles on the start box |x|, |y| <= box < 1/2:
    V grows with |x| there (dV/dx = x (1 + 2y)), and along |x| = box its largest value is
    at y = box: box^2 + 2 box^3 / 3."""
    return box**2 + 2 * box**3 / 3


# --- sink -----------------------------------------------------------------------------------
def test_sink_of_the_flat_file_is_the_registry(files, capsys):
    user = cli_json(["sink", "--well", files["flat"], "--particles", "3"], capsys)
    registry = cli_json(["sink", *REGISTRY, "--particles", "3"], capsys)
    assert user["total_energy_bound"] == pytest.approx(registry["total_energy_bound"], rel=1e-12)
    for axis in ("x", "y"):
        assert user["reach"][axis] == pytest.approx(registry["reach"][axis], rel=1e-12)
    assert user["well"] == {
        "name": "paperflat",
        "parameters": {"alpha": 0.5, "beta": 0.3, "gamma": 1.0, "n": 4.0},
    }


def test_sink_of_henon_heiles_reaches_the_axis_roots_and_refuses_its_saddle(
    files, capsys, tmp_path, monkeypatch
):
    data = cli_json(["sink", "--well", files["hh"], "--particles", "2", "--container-energy",
                     "0.02"], capsys)  # fmt: skip
    e = data["total_energy_bound"]  # E0 + k max(V - V(0, 0)) over the start box
    assert e == pytest.approx(0.02 + 2 * hh_box_energy(0.01), rel=1e-12)
    # the basin's extent in y: the roots of y^2/2 - y^3/3 = e on the axis x = 0
    roots = [optimize.brentq(lambda y: y * y / 2 - y**3 / 3 - e, a, b, xtol=1e-15)
             for a, b in ((-1, 0), (0, 1))]  # fmt: skip
    assert data["reach"]["y"] == pytest.approx(max(map(abs, roots)), rel=1e-12)
    refused_well(["sink", "--well", files["hh"]], capsys, tmp_path, monkeypatch, "0.166666667")


@pytest.mark.parametrize("command", ["sink", "chaos", "lifetime"])
def test_a_shape_option_beside_a_well_file_is_refused(command, files, capsys, tmp_path,
                                                      monkeypatch):  # fmt: skip
    refused_well([command, "--well", files["flat"], "--alpha", "0.5"], capsys, tmp_path,
                 monkeypatch, "must be given without --alpha")  # fmt: skip


# --- chaos ----------------------------------------------------------------------------------
def test_chaos_of_the_flat_file_is_the_registry(files, capsys, tmp_path):
    common = ["--particles", "2", "--runs", "2", "--periods", "4", "--gali", "2",
              "--transverse", "--quiet"]  # fmt: skip
    plot = tmp_path / "c.png"
    user = cli_json(["chaos", "--well", files["flat"], *common, "--plot", str(plot)], capsys)
    registry = chaos(Sink(Well(0.5, 0.3, 4), 2, 0.2), RunSettings(runs=2, periods=4),
                     gali=2, transverse=True).as_dict()  # fmt: skip
    for name in ("lambda1", "transverse"):  # measured: identical
        np.testing.assert_allclose(user[name]["runs"], registry[name]["runs"], rtol=1e-12)
    assert user["parameters"]["shape"] == "paperflat" and user["parameters"]["n"] == 4.0
    assert plot.read_bytes().startswith(b"\x89PNG")


def test_chaos_of_henon_heiles_preserves_volume_and_refuses_the_transverse_exponent(hh):
    sink = Sink(hh, particles=2, mass=0.2)
    settings = RunSettings(container_energy=0.02, runs=2, periods=5, seed=1)
    res = chaos(sink, settings, spectrum="full")
    # a symplectic map keeps volume: the 10 exponents sum to 0 (measured 2e-16)
    assert np.abs(res.spectrum.sum(axis=1)).max() < 1e-12
    assert res.run_errors.max() < 1e-8
    with pytest.raises(ParameterError, match=r"^transverse = True .*dV/dy\(x, 0\) = x\*\*2"):
        chaos(sink, settings, transverse=True)
    with pytest.raises(ParameterError, match="^container_energy = 0.5 .*0.166666667"):
        chaos(sink, RunSettings(container_energy=0.5, runs=2, periods=5))


def test_chaos_transverse_of_a_henon_heiles_file_is_refused(files, capsys, tmp_path,
                                                            monkeypatch):  # fmt: skip
    refused_well(["chaos", "--well", files["hh"], "--container-energy", "0.02",
                  "--transverse", "--plot", "c.png"], capsys, tmp_path, monkeypatch,
                 "y = 0 is not invariant")  # fmt: skip


# --- lifetime -------------------------------------------------------------------------------
def test_lifetime_of_the_flat_file_is_the_registry(files, capsys):
    # beta = -0.2: the user's area quadrature converges at E = 0.5 (at beta = 0.3 the
    # basin's corner is singular there, see docs/guide/user_wells.rst, Limits)
    common = ["--particles", "2", "--runs", "2", "--periods", "30"]
    user = cli_json(["lifetime", "--well", files["flat"], "--well-param", "beta=-0.2",
                     *common], capsys)  # fmt: skip
    registry = cli_json(["lifetime", *REGISTRY[:-3], "-0.2", "--n", "4", *common], capsys)
    for name in ("mean", "ks_distance", "occupation", "return_time"):
        np.testing.assert_allclose(user[name], registry[name], rtol=1e-12)
    for name in ("mean", "total_energy", "exponent"):
        assert user["law"][name] == pytest.approx(registry["law"][name], rel=1e-12)
    assert user["tails"] == pytest.approx(registry["tails"], rel=1e-12)


def test_lifetime_of_henon_heiles_takes_the_law_from_the_centre(files, tmp_path, capsys):
    plot = tmp_path / "l.png"
    data = cli_json(["lifetime", "--well", files["hh"], "--container-energy", "0.02",
                     "--particles", "2", "--runs", "2", "--periods", "30", "--seed", "3",
                     "--plot", str(plot)], capsys)  # fmt: skip
    law = data["law"]
    e = law["total_energy"]  # E0 + the particles' start energies, V(0, 0) = 1 left out
    assert 0.02 < e <= 0.02 + 2 * hh_box_energy(0.01)
    # the unlifted well's law at that energy: a different definition, the same law
    plain = well_law(UserWell("hh0", HH, {}), 2, e)
    assert law["mean"] == pytest.approx(plain.mean, rel=1e-12)
    assert data["tails"][1] == pytest.approx(plain.tail(0.5), rel=1e-12)  # f = 0.5
    assert plot.read_bytes().startswith(b"\x89PNG")


# --- compare --------------------------------------------------------------------------------
def test_compare_of_the_flat_file_is_the_registry(files, capsys):
    common = [
        "--attachments",
        "well",
        "--particles",
        "3",
        "--damping",
        "0.05",
        "--energies",
        "0.05",
        "0.5",
        "2",
        "--runs",
        "2",
        "--periods",
        "4",
        "--quiet",
    ]
    user = cli_json(["compare", "--well", files["flat"], *common], capsys)
    registry = cli_json(["compare", "--shapes", "flat", *common], capsys)
    for name in ("efficiency", "efficiency_se", "max_audit_error"):  # measured: identical
        np.testing.assert_allclose(user[name], registry[name], rtol=1e-12, atol=1e-15)
    assert user["attachment"] == ["well paperflat k = 3"]
    assert user["attachments"][0]["well_parameters"]["beta"] == 0.3


def test_compare_of_henon_heiles_balances_energy_and_refuses_the_line(
    hh, files, capsys, tmp_path, monkeypatch
):
    c = compare([Attachment("well", particles=2, user_well=hh)], [0.02], damping=0.05,
                periods=4, runs=2, progress=False)  # fmt: skip
    # H + W = H0, the dashpot's work audited against the engine's energy
    assert c.max_audit_error.max() < 1e-6
    assert 0 < c.efficiency.min() and c.efficiency.max() < 1
    with pytest.raises(ParameterError, match="^user_well = .*'nes'.*line y = 0"):
        Attachment("nes", user_well=hh)
    with pytest.raises(ParameterError, match="^well = 'hh.toml' .*WellAt"):
        attachments_of(["well"], well="hh.toml")
    with pytest.raises(ParameterError, match="^n = 4 .*left out with well"):
        attachments_of(["well"], well=hh, n=4)
    base = ["compare", "--well", files["hh"], "--damping", "0.05"]
    refused_well([*base, "--shapes", "flat"], capsys, tmp_path, monkeypatch, "without --shapes")
    refused_well([*base, "--wavelet-plot", "w.png"], capsys, tmp_path, monkeypatch,
                 "normal modes of a registered shape")  # fmt: skip


def test_a_well_param_without_a_well_file_is_refused(capsys, tmp_path, monkeypatch):
    refused_well(["compare", "--damping", "0.05", "--well-param", "n=3"], capsys, tmp_path,
                 monkeypatch, "given with --well FILE")  # fmt: skip


# --- the relaxation's law (equilibrium_law of a WellAt) ---------------------------------------
def test_settling_targets_the_law_from_the_centre_and_the_prediction_refuses(hh):
    sink = Sink(hh, particles=2, mass=0.2)
    r, sim = measure_settling(sink, 0.02, (3, 24))
    e = float(np.mean(sim.initial_energy))  # the engine counts from V(0, 0) = 1
    assert 0.02 < e <= 0.02 + 2 * hh_box_energy(0.01)
    assert r.target == pytest.approx(well_law(UserWell("hh0", HH, {}), 2, e).mean, rel=1e-12)
    with pytest.raises(ParameterError, match="^sink = .*not made for a user's well"):
        predict_relaxation(sink, 0.02)
