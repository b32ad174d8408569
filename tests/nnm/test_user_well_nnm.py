"""Normal modes of a user's well: the flow system is the engine derived from the user's
potential, the start guesses use the well's own numbers (its wall along -x from its wall
ratios, the turning point and period on y = 0 by quadrature), and a well in which y = 0
is not invariant is refused with the reason, on the command line too.

Reference: the registry's flat well (hand-declared wall ratios against SymPy's
derivatives of the user's text; its guesses from the power-law oscillator's exact
period), computed here.
"""

import json

import numpy as np
import pytest
from _cli import BUILT_IN, HH, PAPER, refused_well, run_cli, write_well_file

from sinktheory import Sink, Well
from sinktheory.errors import ParameterError
from sinktheory.nnm import shoot
from sinktheory.nnm.continuation import continue_both
from sinktheory.nnm.modes import mode_guess, sink_flow
from sinktheory.userwell import UserWell
from sinktheory.wellat import WellAt

WALLS = ["x/(alpha + beta*(y**2 - 1))", "y"]
FLAT = UserWell("paperflat", BUILT_IN["flat"], PAPER, WALLS)
REGISTRY = Sink(Well(0.5, 0.3, 4), 1, 0.2)


def test_the_flat_well_typed_by_a_user_flows_as_the_registry():
    """The time-T map and its Jacobian to 1e-12; the particle mode's guess (quadrature
    against the oscillator's exact period: measured 8e-14 to 3e-13 apart for E = 1e-3 to
    2) and the container mode's (the wall from the wall ratios: identical)."""
    user = sink_flow(Sink(WellAt(FLAT), 1, 0.2))
    assert user.parameter_names == ("alpha", "beta", "gamma", "n", "mu")
    z0, T = mode_guess(REGISTRY, "particle", 0.1)
    zu, mu = user._propagate(z0, T, steps=200)
    zr, mr = sink_flow(REGISTRY)._propagate(z0, T, steps=200)
    np.testing.assert_allclose(zu, zr, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(mu, mr, rtol=1e-12, atol=1e-13)
    for mode, energy in (("particle", 1e-3), ("particle", 2.0), ("container", 0.5)):
        zu, Tu = mode_guess(Sink(WellAt(FLAT), 1, 0.2), mode, energy)
        zr, Tr = mode_guess(REGISTRY, mode, energy)
        np.testing.assert_allclose(zu, zr, rtol=1e-12, atol=1e-15)
        assert abs(Tu - Tr) <= 1e-12 * Tr


def test_the_continuation_of_the_flat_well_typed_by_a_user_is_the_registry_branch():
    """In energy (container mode): identical; in the well's own beta (particle mode) to
    Newton's tolerance 1e-11 (measured 5e-13)."""
    for mode, param, energy, interval, tol in (
        ("container", "energy", 1e-3, (5e-4, 2e-3), 1e-12),
        ("particle", "beta", 0.0625, (0.25, 0.35), 1e-11),
    ):
        kw = dict(continue_in=param, total_energy=energy, interval=interval, points=3, steps=200)
        user = continue_both(Sink(WellAt(FLAT), 1, 0.2), mode, **kw)
        registry = continue_both(REGISTRY, mode, **kw)
        assert user.points == registry.points
        np.testing.assert_allclose(user.value, registry.value, rtol=tol)
        np.testing.assert_allclose(user.period, registry.period, rtol=tol)
        assert user.meta["parameters"] == {"alpha": 0.5, "beta": 0.3, "gamma": 1.0, "n": 4.0}


def test_henon_heiles_is_refused_with_the_reason():
    hh = Sink(WellAt(UserWell("hh", HH, {})), 1, 0.2)
    reason = r"y = 0 is invariant .*\(dV/dy\(x, 0\) = x\*\*2, not identically 0\)"
    with pytest.raises(ParameterError, match=r"^well = 'hh' .*" + reason):
        continue_both(hh, "container", total_energy=0.01, interval=(0.005, 0.02))
    with pytest.raises(ParameterError, match=r"^subspace = 'plane' .*y = 0 is not invariant"):
        shoot(sink_flow(hh), np.zeros(6) + 0.01, 6.28, steps=100, subspace="plane")


def test_nnm_on_the_command_line_takes_a_well_file(tmp_path, capsys, monkeypatch):
    """The frequencies of the registry's branch; Hénon–Heiles and a shape option beside
    the file refused (exit 2, one line, nothing written)."""
    path = write_well_file(tmp_path, "paperflat", BUILT_IN["flat"], PAPER, WALLS)
    args = ["--continue-in", "energy", "--total-energy", "1e-3", "--interval", "5e-4", "2e-3",
            "--points", "3", "--steps", "200", "--json"]  # fmt: skip
    code, out, err = run_cli(["nnm", "--well", str(path), *args], capsys)
    assert code == 0, err
    user = json.loads(out)
    code, out, err = run_cli(["nnm", "--alpha", "0.5", "--beta", "0.3", "--n", "4", *args], capsys)
    registry = json.loads(out)
    np.testing.assert_allclose(user["frequency"], registry["frequency"], rtol=1e-12)
    hh = write_well_file(tmp_path, "hh", HH)
    refused_well(["nnm", "--well", str(hh), "--continue-in", "energy"], capsys, tmp_path,
                 monkeypatch, "dV/dy(x, 0) = x**2, not identically 0")  # fmt: skip
    refused_well(["nnm", "--well", str(path), "--continue-in", "beta"], capsys, tmp_path,
                 monkeypatch, "interval = None is not allowed: must be given with")  # fmt: skip
    refused_well(["nnm", "--well", str(path), "--n", "4", "--continue-in", "energy"], capsys,
                 tmp_path, monkeypatch, "must be given without --n")  # fmt: skip
