"""One engine per well, n a run-time value: a user's well compiles through the path of the
registered shapes, a new n compiles nothing, and the runs of one ensemble may carry
different n.

References: the registry's engine for the paper's flat well typed as a user would (a
second derivation: SymPy differentiates the user's expression through lifted powers, the
registry's through its hand-declared wall ratios), exact SymPy gradients of the elliptic
well, and a run of each n on its own (bitwise).
"""

import numpy as np
import pytest
import sympy as sp
from _cli import BUILT_IN, ELLIPTIC, PAPER

from sinktheory import RunSettings, Sink, Well
from sinktheory import symbolic as S
from sinktheory.engine.cache import load, sink_name, well_name
from sinktheory.engine.core import Ensemble
from sinktheory.ensemble import engine_params, random_positions, split_values, start_state
from sinktheory.errors import ParameterError
from sinktheory.integrators import get_scheme
from sinktheory.simulate import simulate
from sinktheory.userwell import UserWell

K, R = 3, 6


def _states(seed, spread=0.15):
    rng = np.random.default_rng(seed)
    return rng.uniform(-spread, spread, (1 + 2 * K, R)), rng.uniform(-0.3, 0.3, (1 + 2 * K, R))


def test_flat_well_typed_by_a_user_runs_as_the_registry_to_1e_12():
    """Kernels at random states for n = 1..40 (one n per run), and a period of an ensemble
    of Fig. 8's well: the user's engine against the registry's."""
    user = load(well_name(UserWell("paperflat", BUILT_IN["flat"], PAPER)))
    registry = load(sink_name("flat"))
    q, v = _states(1)
    params = np.array([[0.5, 0.3, 1.0, n, 0.07] for n in (1, 2, 4, 10, 17, 40)]).T
    ta, tb = user.table_of(params, R), registry.table_of(params, R)
    a, b = user.block_accelerations(q, ta), registry.block_accelerations(q, tb)
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12 * np.abs(b).max())
    ea, eb = user.block_energies(q, v, ta)[0], registry.block_energies(q, v, tb)[0]
    np.testing.assert_allclose(ea, eb, rtol=1e-12)
    sink = Sink(Well(0.5, 0.3, 4), particles=K, mass=0.2)
    z = start_state(sink, 0.5, random_positions(RunSettings(runs=R, seed=2), K))
    q, v = split_values(z)
    histories = []
    for name in (well_name(UserWell("paperflat", BUILT_IN["flat"], PAPER)), sink_name("flat")):
        ens = Ensemble(name, q, v, engine_params(sink))
        rec = ens.run(get_scheme("blanes-moan6"), dt=2 * np.pi / 600, steps=60, segments=10)
        histories.append(rec.shared)
    np.testing.assert_allclose(histories[0], histories[1], rtol=1e-12)


def test_elliptic_well_forces_against_exact_sympy():
    """a = -grad U / m of the elliptic well at an exact point, n = 1, 3, 8 (n a run-time
    value: one engine), against SymPy's exact gradient of the user's expression."""
    well = UserWell("ellipse", ELLIPTIC, {"a": 0.4, "b": 0.25, "gamma": 1.0, "n": (3, (1, 50))})
    mod = load(well_name(well))
    X, x, y = sp.Rational(1, 10), sp.Rational(-1, 7), sp.Rational(1, 9)
    q = np.array([[float(X)], [float(X + x)], [float(y)]])
    for n in (1, 3, 8):
        V = well.potential.subs(well.values(n=n))
        gx, gy = (float(sp.diff(V, c).subs({S.x: x, S.y: y})) for c in (S.x, S.y))
        mu = 0.1
        a = mod.block_accelerations(q, mod.table_of([0.4, 0.25, 1.0, n, mu], 1))[:, 0]
        expected = [-float(X) + gx, -gx / mu, -gy / mu]
        np.testing.assert_allclose(a, expected, rtol=1e-13, atol=1e-15)


def test_a_new_n_compiles_nothing_and_mixed_n_runs_equal_runs_alone():
    """After one run, other exponents add no machine code (the dispatcher's signatures do
    not grow); an ensemble whose runs carry n = 2, 4, 10 equals each run alone, bitwise."""
    simulate(Sink(Well(0.5, 0.3, 4), particles=2, mass=0.2), RunSettings(runs=2, periods=1))
    mod = load(sink_name("flat"))
    before = {f: len(getattr(mod, f).signatures) for f in ("advance", "parameter_table")}
    for n in (2, 7, 31, 400):
        simulate(Sink(Well(0.5, 0.3, n), particles=2, mass=0.2), RunSettings(runs=2, periods=1))
    assert {f: len(getattr(mod, f).signatures) for f in before} == before
    sinks = [Sink(Well(0.5, 0.3, n), particles=2, mass=0.2) for n in (2, 4, 10)]
    z = start_state(sinks[0], 0.5, random_positions(RunSettings(runs=3, seed=5), 2))
    q, v = split_values(z)
    params = np.stack([engine_params(s) for s in sinks], axis=1)
    scheme = get_scheme("blanes-moan6")
    together = Ensemble(sink_name("flat"), q, v, params)
    rec = together.run(scheme, dt=2 * np.pi / 2000, steps=200, segments=3, block=3)
    for r, sink in enumerate(sinks):
        alone = Ensemble(sink_name("flat"), q[:, r : r + 1], v[:, r : r + 1], engine_params(sink))
        one = alone.run(scheme, dt=2 * np.pi / 2000, steps=200, segments=3)
        assert np.array_equal(rec.shared[r], one.shared[0])
        assert np.array_equal(together.q[:, r], alone.q[:, 0])


@pytest.mark.parametrize("n", [2.25, 1024.5, float("nan")])
def test_an_exponent_the_kernels_cannot_raise_is_refused(n):
    """2n - 1 not whole, or of 2048 and more (past the last bit class), or NaN."""
    q, v = _states(3)
    with pytest.raises(ParameterError, match="whole numbers"):
        Ensemble(sink_name("flat"), q, v, [0.5, 0.3, 1.0, n, 0.1])
