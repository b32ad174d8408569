"""Normal modes of a user's well: the flow system is the engine derived from the user's
potential (the paper's flat well typed by a user propagates as the registry's, and a
periodic orbit shot in it is the registry's orbit); the start guesses of the continuation
refuse a user's well with the reason (Hénon–Heiles: y = 0 not invariant), on the command
line too.

Reference: the registry's flat well (hand-declared wall ratios against SymPy's
derivatives of the user's text).
"""

import numpy as np
import pytest
from _cli import BUILT_IN, HH, PAPER, refused_well, write_well_file

from sinktheory import Sink, Well
from sinktheory.errors import ParameterError
from sinktheory.nnm import shoot
from sinktheory.nnm.continuation import continue_both
from sinktheory.nnm.modes import mode_guess, sink_flow
from sinktheory.userwell import UserWell
from sinktheory.wellat import WellAt

FLAT = UserWell("paperflat", BUILT_IN["flat"], PAPER)


def test_the_flat_well_typed_by_a_user_flows_and_shoots_as_the_registry():
    user = sink_flow(Sink(WellAt(FLAT), 1, 0.2))
    registry = sink_flow(Sink(Well(0.5, 0.3, 4), 1, 0.2))
    assert user.parameter_names == ("alpha", "beta", "gamma", "n", "mu")
    z0, T = mode_guess(Sink(Well(0.5, 0.3, 4), 1, 0.2), "particle", 0.1)
    zu, mu = user.propagate(z0, T, steps=200)
    zr, mr = registry.propagate(z0, T, steps=200)
    np.testing.assert_allclose(zu, zr, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(mu, mr, rtol=1e-12, atol=1e-13)
    a = shoot(user, z0, T, steps=200, subspace="plane")
    b = shoot(registry, z0, T, steps=200, subspace="plane")
    assert abs(a.period - b.period) <= 1e-12 * b.period
    np.testing.assert_allclose(a.z0, b.z0, rtol=0, atol=1e-12)


def test_the_continuation_refuses_a_user_s_well_with_the_reason():
    hh = Sink(WellAt(UserWell("hh", HH, {})), 1, 0.2)
    with pytest.raises(ParameterError, match=r"^well = 'hh' .* y = 0 is invariant .*\("
                       r"dV/dy\(x, 0\) = x\*\*2, not identically 0"):
        continue_both(hh, "container", total_energy=0.01, interval=(0.005, 0.02))
    with pytest.raises(ParameterError, match=r"^subspace = 'plane' .*y = 0 is not invariant"):
        shoot(sink_flow(hh), np.zeros(6) + 0.01, 6.28, steps=100, subspace="plane")
    flat = Sink(WellAt(FLAT), 1, 0.2)
    with pytest.raises(ParameterError, match=r"^well = 'paperflat' .* a registered shape .*"
                       r"nnm\.shoot"):
        mode_guess(flat, "particle", 0.1)


@pytest.mark.parametrize("name,reason", [("hh", "dV/dy(x, 0) = x**2, not identically 0"),
                                         ("paperflat", "a registered shape for the start")])
def test_nnm_on_the_command_line_refuses_a_well_file_with_the_reason(name, reason, tmp_path,
                                                                    capsys, monkeypatch):  # fmt: skip
    path = write_well_file(tmp_path, name, HH if name == "hh" else BUILT_IN["flat"],
                           {} if name == "hh" else PAPER)  # fmt: skip
    refused_well(["nnm", "--well", str(path), "--continue-in", "energy"], capsys, tmp_path,
                 monkeypatch, reason)  # fmt: skip
