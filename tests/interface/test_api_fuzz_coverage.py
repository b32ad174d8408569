"""Every public entry point is fuzzed (issue 34, item 5).

The property-based test of test_api_fuzz.py for every public entry point the hand-written
tables leave out, its valid arguments built from the parameters' names (tests/_fuzz.py):
one argument at a time is replaced by a hostile value; the call must succeed with finite
numbers or raise a ParameterError naming the parameter (one line), or a NumericalError.
And the guard that keeps "every": an entry point added to a public module's ``__all__``
fails here until it is fuzzed, or listed with its reason as having no user input.
Example counts are small; SINKTHEORY_FUZZ_SCALE=10 runs ten times as many.
"""

import dataclasses
import inspect

import pytest
from _cli import FUZZ_SCALE, fuzz_one, non_finite
from _fuzz import (
    ALSO_FUZZED,
    AREA_HEAVY,
    EXEMPT,
    PENDING,
    RECORDS,
    _overrides,
    area_fixed_leaks,
    built_entries,
    hand_entries,
    key_of,
    public_entry_points,
    resolved,
)
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

HAND = {key_of(function) for _, function, _ in hand_entries()}
#: Entry points whose calls take seconds (simulations, continuations): fewer examples.
HEAVY = {
    "sinktheory." + name
    for name in (
        "adaptive.simulate_adaptive", "billiard.run.well_billiard",
        "chaos.tangent.finite_difference_jacobian", "damped.simulate_inelastic",
        "equilibrium.law.well_law", "equilibrium.prediction.predict_relaxation",
        "equilibrium.prediction.settling_periods", "model.user_well_summary",
        "sweep.chaosmap.chaos_map", "symbolic.normal_mode",
    )
} | AREA_HEAVY  # fmt: skip
_ALL_BUILT = built_entries(skip=HAND)
BUILT = [e for e in _ALL_BUILT if e[0] not in HEAVY]
BUILT_HEAVY = [e for e in _ALL_BUILT if e[0] in HEAVY]
_BASELINE: dict = {}  # entry -> where its valid call's result is not finite (or None)


@pytest.fixture(autouse=True, scope="module")
def _in_a_scratch_directory(tmp_path_factory):
    """Hostile paths ("x", "") may be written to: in a scratch directory."""
    with pytest.MonkeyPatch.context() as mp:
        mp.chdir(tmp_path_factory.mktemp("fuzz"))
        yield


@pytest.mark.parametrize(("key", "function", "valid"), BUILT, ids=[e[0] for e in BUILT])
@settings(max_examples=12 * FUZZ_SCALE, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])  # fmt: skip
@given(data=st.data())
def test_every_other_entry_point_raises_only_documented_errors(key, function, valid, data):
    _fuzz(key, function, valid, data)


@pytest.mark.parametrize(("key", "function", "valid"), BUILT_HEAVY,
                         ids=[e[0] for e in BUILT_HEAVY])  # fmt: skip
@settings(max_examples=3 * FUZZ_SCALE, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])  # fmt: skip
@given(data=st.data())
def test_heavy_entry_points_raise_only_documented_errors(key, function, valid, data):
    _fuzz(key, function, valid, data)


def _fuzz(key, function, valid, data):
    valid = resolved(valid)
    if key not in _BASELINE:
        _BASELINE[key] = non_finite(function(**valid))
    fuzz_one(function, valid, data, baseline=_BASELINE[key])


def test_every_public_entry_point_is_fuzzed_or_exempt():
    """Each callable of a public ``__all__`` is fuzzed, exempt (no parameters at all), a
    record the package returns, or pending (listed with why); the lists name only public
    entry points, once."""
    public = public_entry_points()
    fuzzed = HAND | {key for key, _, _ in BUILT + BUILT_HEAVY} | set(ALSO_FUZZED)
    listed = set(EXEMPT) | set(RECORDS) | set(PENDING)
    unlisted = sorted(set(public) - fuzzed - listed)
    assert not unlisted, f"public entry points neither fuzzed nor exempt: {unlisted}"
    stale = sorted((listed | set(ALSO_FUZZED)) - set(public))
    assert not stale, f"listed but not public entry points: {stale}"
    twice = sorted((HAND | set(ALSO_FUZZED)) & listed)
    assert not twice, f"fuzzed and also listed as exempt, a record or pending: {twice}"
    stale_arguments = sorted(set(_overrides()) - set(public))
    assert not stale_arguments, f"valid arguments of no public entry point: {stale_arguments}"
    with_input = [k for k in EXEMPT if inspect.signature(public[k]).parameters]
    assert not with_input, f"exempt, but they take arguments: {with_input}"


def test_records_are_records():
    """A class listed as a record is a dataclass or a NamedTuple that checks nothing on
    construction (no ``__post_init__``, no ``__init__`` of its own): one that checks its
    fields is an entry point, and fuzzed."""
    public = public_entry_points()
    for key in RECORDS:
        cls = public[key]
        assert inspect.isclass(cls), f"{key} is not a class"
        if dataclasses.is_dataclass(cls):
            assert not hasattr(cls, "__post_init__"), f"{key} checks its fields: fuzz it"
        else:
            assert issubclass(cls, tuple) and hasattr(cls, "_fields"), f"{key}: not a record"


def test_no_entry_point_is_pending():
    assert not PENDING, sorted(PENDING)


def _fixed_leaks():
    """(call, parameter it must name) of each leak this fuzz found and that is fixed: before,
    each escaped as a TypeError, ValueError, AttributeError, ZeroDivisionError,
    OverflowError or MemoryError, ran on in compiled code, or returned NaN or inf."""
    import math

    import numpy as np
    from _fuzz import _overrides, fig8_sink, newer_entries

    from sinktheory.adaptive import estimated_steps
    from sinktheory.billiard import well_billiard
    from sinktheory.chaos import canonical, sali_from_gali2, symplectic_defect
    from sinktheory.compare import attachments_of, backbone
    from sinktheory.compare.efficiency import steps_per_period
    from sinktheory.compare.threshold import (
        averaged_share,
        fold_energy,
        full_exchange_energy,
        half_share_energy,
    )
    from sinktheory.equilibrium import well_law
    from sinktheory.equilibrium.microcanonical import particle_energies, shell_states
    from sinktheory.equilibrium.relaxation import measure_relaxation
    from sinktheory.floquet import rigid_limit_phi_half, well_floquet, well_hill
    from sinktheory.model import confining_betas, user_well_summary
    from sinktheory.nnm.backbone import harmonic_balance, harmonic_balance_frequency
    from sinktheory.stepsize import cost_table, step_for
    from sinktheory.sweep import point_seed
    from sinktheory.sweep.grid import parse_range
    from sinktheory.symbolic import potential, wall_ratios
    from sinktheory.worklimit import check_work

    ellipse = _overrides()["sinktheory.floquet.well_hill"]["well"]
    relaxation = next(e[2] for e in newer_entries() if e[0] == "measure_relaxation")
    sink, rng, fig8 = fig8_sink(), np.random.default_rng(0), fig8_sink().well
    return [
        (lambda: averaged_share(0.2, 625.0, 1e-5, horizon=1e308), "horizon"),  # Overflow
        (lambda: averaged_share(0.2, 625.0, 1e-5, horizon=1e12), "horizon"),  # ran on
        (lambda: fold_energy(1e308, 625.0, 0.0), "mu"),  # NaN returned
        (lambda: half_share_energy(1e308, 625.0), "mu"),  # blamed container_energy
        (lambda: half_share_energy(0.2, 1e308), "k3"),  # ValueError
        (lambda: full_exchange_energy(1e308, 625.0), "mu"),
        (lambda: full_exchange_energy(0.2, 1e308), "k3"),  # ValueError
        (lambda: estimated_steps(sink, 0.5, 0), "eps"),  # ZeroDivisionError
        (lambda: estimated_steps(None, 0.5, 0.25), "sink"),  # AttributeError
        (lambda: estimated_steps(sink, [], 0.25), "total_energy"),  # TypeError (unhashable)
        (lambda: well_billiard(ellipse, True), "values"),  # TypeError
        (lambda: user_well_summary(ellipse, 0.5, True), "values"),
        (lambda: user_well_summary(ellipse, 0.5, well_check=True), "well_check"),  # Attribute
        (lambda: well_hill(ellipse, [0.3]), "values"),
        (lambda: well_hill(ellipse, well_check="x"), "well_check"),
        (lambda: well_floquet(ellipse, 0.1, True), "values"),
        (lambda: well_floquet(ellipse, 0.1, well_check=1), "well_check"),
        (lambda: well_law(ellipse, 1, 0.5, True), "values"),
        (lambda: well_law(ellipse, 1, 0.5, well_check=True), "well_check"),
        (lambda: attachments_of(["well"], shapes=[[5.0, 5.0]]), "shapes"),  # TypeError
        (lambda: steps_per_period(None, 0.5, runs=2, periods=2), "att"),  # AttributeError
        (lambda: backbone(None, 0.01, 0.1), "att"),  # AttributeError
        (lambda: confining_betas(None, 4, 0.5), "alpha"),  # TypeError
        (lambda: confining_betas(0.5, 4, 0.5, lo="x"), "lo"),  # DTypePromotionError
        (lambda: confining_betas(0.5, 4, 0.5, hi=None, lo=1.0), "hi"),
        (lambda: harmonic_balance(sink, 1e-300), "omega"),  # ZeroDivisionError
        (lambda: harmonic_balance_frequency(sink, 1e-300), "total_energy"),  # Overflow
        (lambda: harmonic_balance_frequency(sink, 1e308), "total_energy"),  # ValueError
        (lambda: particle_energies(fig8, 2, 0.4, 10**12, rng), "size"),  # MemoryError
        (lambda: particle_energies(fig8, 10**12, 0.4, 5, rng), "particles"),  # MemoryError
        (lambda: shell_states(sink, 0.5, 0.25, 10**12, rng), "runs"),  # MemoryError
        (lambda: rigid_limit_phi_half(None), "lam"),  # NaN returned
        (lambda: rigid_limit_phi_half(0.5, 1e308), "amplitude"),  # -inf returned
        (lambda: rigid_limit_phi_half([0.5, math.nan]), "lam"),
        (lambda: canonical(None, [1.0]), "M"),  # TypeError
        (lambda: canonical(np.eye(2), None), "masses"),  # TypeError
        (lambda: symplectic_defect(None, [1.0]), "M"),  # ValueError (einsum)
        (lambda: symplectic_defect(np.eye(2)[None], "x"), "masses"),
        (lambda: sali_from_gali2(None), "g"),  # NaN returned
        (lambda: point_seed(0, None), "index"),  # TypeError
        (lambda: parse_range("beta", None), "beta"),  # AttributeError
        (lambda: step_for("verlet", None, 1e-6), "omega"),  # TypeError
        (lambda: step_for("verlet", 1e308, 1e-6), "omega"),  # OverflowError
        (lambda: cost_table(sink, 0.5, 1e-6, schemes=True), "schemes"),  # TypeError
        (lambda: check_work(None, sink, 100), "settings"),  # AttributeError
        (lambda: particle_energies(fig8, 2, 0.4, 1e308, rng), "size"),  # OverflowError
        (lambda: wall_ratios(None), "shape"),  # ValueError (in 11 symbolic functions)
        (lambda: potential([1]), "shape"),  # TypeError (unhashable)
        (lambda: measure_relaxation(**{**relaxation, "target": 1e308}), "target"),  # NaN z
        *_fixed_leaks_leaksb(),
    ]


def _fixed_leaks_leaksb():
    """The leaks fixed on branch leaksb (glossary ... worklimit of the pending list)."""
    import math

    from sinktheory.canonical import FIG8_WELL
    from sinktheory.layout import StateLayout
    from sinktheory.plot.floquet import plot_fig7
    from sinktheory.plot.well import plot_well
    from sinktheory.runstats import mean_stderr, plus_minus, spread
    from sinktheory.simulate import first_order_rhs
    from sinktheory.sweep.runner import execute
    from sinktheory.symbolic import lagrangian, rescaled_equations

    return [
        (lambda: mean_stderr(None), "values"),  # NaN returned
        (lambda: spread([1.0, math.inf]), "values"),  # NaN returned
        (lambda: plus_minus(1.0, 0.1, digits=None), "digits"),  # ValueError
        (lambda: lagrangian(None), "k"),  # TypeError
        (lambda: rescaled_equations("flat", -1), "n_value"),  # AssertionError
        (lambda: rescaled_equations("flat", [2]), "n_value"),  # TypeError (unhashable)
        (lambda: execute(None), "sweep"),  # AttributeError
        (lambda: plot_fig7(beta_range=None), "beta_range"),  # TypeError
        (lambda: plot_well(FIG8_WELL, ax=True), "ax"),  # AttributeError
        (lambda: first_order_rhs(None), "sink"),  # AttributeError
        (lambda: StateLayout(math.nan), "particles"),  # NaN kept
    ]


def test_named_leaks_of_the_fuzz():
    """The leaks this fuzz found, each refused naming its parameter."""
    from sinktheory.errors import ParameterError

    for make, name in _fixed_leaks() + area_fixed_leaks():
        with pytest.raises(ParameterError) as info:
            make()
        assert info.value.name == name, (name, str(info.value))
