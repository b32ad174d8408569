"""The analyses' entry points validate like the command line (issue 34, item 5).

The property-based test of test_api_fuzz.py extended to Kramers-Moyal estimation, the
bifurcation sections, Hill's equation, the oscillator and its series, the design
explorer, the Python sweep API (every parameter of every sweep kind) and user wells
(constructor, well files with hostile contents, degenerate potentials).  One argument at a
time is replaced by a hostile value; the call must succeed with finite numbers or raise a
ParameterError naming the parameter (one line), or a NumericalError.  Example counts are
small; SINKTHEORY_FUZZ_SCALE=10 runs ten times as many.
"""

import math

import pytest
from _cli import ELLIPTIC, FUZZ_SCALE, HOSTILE, call_hostile, fuzz_one, non_finite
from _fuzz import (
    DESIGN,
    bifurcation_entries,
    design_entries,
    kramers_entries,
    oscillator_entries,
    sweep_and_well_entries,
)
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sinktheory.errors import ParameterError, WellDefinitionError

#: Fixed examples (derandomize): CI sees the same cases every run.
FUZZ = settings(max_examples=25 * FUZZ_SCALE, deadline=None, derandomize=True,
                suppress_health_check=[HealthCheck.too_slow])  # fmt: skip


ENTRIES = (kramers_entries() + bifurcation_entries() + oscillator_entries() + design_entries()
           + sweep_and_well_entries())  # fmt: skip
_BASELINE: dict = {}  # entry -> where its valid call's result is not finite (or None)


@pytest.fixture(autouse=True, scope="module")
def _in_a_scratch_directory(tmp_path_factory):
    """Hostile paths ("x", "") are tried as stores and report directories: in a scratch
    directory."""
    with pytest.MonkeyPatch.context() as mp:
        mp.chdir(tmp_path_factory.mktemp("fuzz"))
        yield


@pytest.mark.parametrize(("name", "function", "valid"), ENTRIES, ids=[e[0] for e in ENTRIES])
@FUZZ
@given(data=st.data())
def test_analyses_raise_only_documented_errors(name, function, valid, data):
    if name not in _BASELINE:
        _BASELINE[name] = non_finite(function(**valid))
    fuzz_one(function, valid, data, baseline=_BASELINE[name])


# --- the sweep API: every parameter of every kind -----------------------------------------
#: A small valid point of each kind (other parameters take their defaults).
KIND_BASE = {
    "floquet": {"alpha": 0.5, "beta": 0.1, "n": 4},
    "bifurcation": {"alpha": 0.5, "beta": 0.3, "n": 4, "transient": 2, "count": 3},
    "ensemble": {"alpha": 0.5, "beta": 0.3, "n": 4, "runs": 2, "periods": 3},
    "chaos": {"alpha": 0.5, "beta": 0.3, "n": 4, "runs": 2, "periods": 3},
    "ergodicity": {"alpha": 0.5, "beta": 0.3, "n": 4, "runs": 2, "periods": 30,
                   "transient": 10, "lyapunov_runs": 0},
    "design": DESIGN,
}  # fmt: skip
#: Hostile values of a sweep parameter: the API's, and lists holding one.
SWEPT = [*HOSTILE, [0.1, math.nan], [1, "x"], [[1, 2]], (), [None], [True, 2], range(3)]


@pytest.mark.parametrize("kind", sorted(KIND_BASE))
@FUZZ
@given(data=st.data())
def test_every_sweep_parameter_is_checked(kind, data):
    """Sweep.make checks a hostile value of any of the kind's parameters."""
    from sinktheory.sweep import Sweep, get_kind

    name = data.draw(st.sampled_from(sorted(get_kind(kind).params)), label="parameter")
    value = data.draw(st.sampled_from(SWEPT), label="value")
    call_hostile(Sweep.make, {"kind": kind, "params": {**KIND_BASE[kind], name: value}},
                 "seed", 0)  # fmt: skip


def test_sweep_bases_are_valid():
    from sinktheory.sweep import Sweep

    for kind, params in KIND_BASE.items():
        Sweep.make(kind, params)


# --- user wells: well files with hostile contents, degenerate potentials ---------------------
GOOD_FILE = {
    "name": '"ellipse"',
    "potential": f'"{ELLIPTIC}"',
    "wall_ratios": '["(x/a)**2 + (y/b)**2"]',
}
GOOD_PARAMETERS = {
    "a": "{ default = 0.3, range = [0.01, 10] }",
    "b": "{ default = 0.2 }",
    "gamma": "{ default = 1 }",
    "n": "{ default = 2, range = [1, 20] }",
}
#: Degenerate potentials: open, inverted, constant, singular, complex near the centre,
#: flat-bottomed, huge or tiny, with a saddle, periodic.
POTENTIALS = [
    "x**2 + y**2", "-x**2 - y**2", "0", "x**2", "1/(x**2 + y**2)", "log(x**2 + y**2)",
    "sqrt(x) + y**2", "exp(x) + y**2", "x**4 + y**4", "(x**2 + y**2)**1000",
    "1e308*(x**2 + y**2)", "1e-300*(x**2 + y**2)", "x**2 + y**2 - (x**2 + y**2)**2",
    "Abs(x) + Abs(y)", "tan(x)**2 + y**2", "exp(-1/(x**2 + y**2))", "x**2*y**2",
    "cosh(x) + cosh(y)", "sin(x)**2 + y**2", "x**3 + y**2",
]  # fmt: skip
#: TOML values a key of a well file might hold.
TOML_VALUES = [
    '""', '"x"', "0", "-1", "1e308", "nan", "inf", "-inf", "true", "9223372036854775807",
    "1979-05-27T07:32:00Z", "[]", "[1, 2]", "[1, 2, 3]", '["x"]', "[nan, 1]", "[1, inf]",
    "[10, 1]", "{}", "{ default = nan }", '{ default = "x" }', "{ default = [1] }",
    "{ default = 1, range = [nan, 2] }", "{ default = 1, range = [2, 1] }",
    "{ default = 1, range = 5 }", "{ range = [0, 1] }", "{ default = 1, extra = 2 }",
    *(f'"{p}"' for p in POTENTIALS),
]  # fmt: skip


def _toml(top: dict, parameters: dict) -> str:
    lines = [f"{k} = {v}" for k, v in top.items()]
    if parameters is not None:
        lines.append("[parameters]")
        lines += [f"{k} = {v}" for k, v in parameters.items()]
    return "\n".join(lines) + "\n"


@FUZZ
@given(data=st.data())
def test_hostile_well_files_are_refused_in_one_line(data, tmp_path_factory):
    """A well file with one key (top-level or a parameter) set to a hostile TOML value
    loads, and checks, or is refused with a WellDefinitionError naming the file's key."""
    from sinktheory.userwell import check_well, load_well

    top, parameters = dict(GOOD_FILE), dict(GOOD_PARAMETERS)
    key = data.draw(st.sampled_from([*top, "parameters", "extra", *parameters]), label="key")
    value = data.draw(st.sampled_from(TOML_VALUES), label="value")
    if key in parameters:
        parameters[key] = value
    else:
        top[key] = value
    if key == "parameters":
        parameters = None  # the key itself holds the value
    path = tmp_path_factory.mktemp("well") / "hostile.toml"
    path.write_text(_toml(top, parameters))
    well = call_hostile(load_well, {"path": path}, "path", path)
    if well is not None:
        call_hostile(check_well, {"well": well, "radius": 0.5}, "radius", 0.5)


@pytest.mark.parametrize("potential", POTENTIALS)
def test_degenerate_potentials_are_checked_or_refused(potential):
    """Constant, open, singular, complex, flat-bottomed and huge wells: check_well
    passes or refuses them in one line (never a raw exception or a hang)."""
    from sinktheory.userwell import UserWell, check_well

    try:
        well = UserWell("degenerate", potential, {})
    except WellDefinitionError:
        return
    call_hostile(check_well, {"well": well, "radius": 0.5}, "radius", 0.5)


def _leaks():
    """(call, parameter it must name) of each leak the fuzz found (issue 34): before, each
    escaped as a TypeError, ValueError, AttributeError, OverflowError or MemoryError, ran
    for minutes, or returned NaN."""
    import mpmath

    from sinktheory import hill, oscillator, series
    from sinktheory.bifurcation import bifurcation, sampled_run, section_step
    from sinktheory.design.ranking import pareto_layers
    from sinktheory.equilibrium.kramers import (
        check_fluctuation_dissipation,
        gauss_grid,
        jacobi_increments,
        kramers_moyal,
        measure_kramers_moyal,
        solve_fokker_planck,
    )
    from sinktheory.sweep import parse_param
    from sinktheory.userwell import disc_grid, parse_potential, ring_grid

    kramers, bif, osc, design, wells = (dict((e[0], e[2]) for e in group) for group in (
        kramers_entries(), bifurcation_entries(), oscillator_entries(), design_entries(),
        sweep_and_well_entries()))  # fmt: skip
    km = kramers["check_fluctuation_dissipation"]
    fp, jacobi = kramers["solve_fokker_planck"], kramers["jacobi_increments"]
    moyal, measure = kramers["kramers_moyal"], kramers["measure_kramers_moyal"]
    return [
        (lambda: gauss_grid(10**12, 4), "points"),  # MemoryError
        (lambda: kramers_moyal(**{**moyal, "lags": 1e308}), "lags"),  # OverflowError
        (lambda: kramers_moyal(**{**moyal, "total_energy": math.nan}), "total_energy"),  # NaN
        (lambda: kramers_moyal(**{**moyal, "weights": [math.nan] * 4}), "weights"),
        (lambda: kramers_moyal(**{**moyal, "s": "x"}), "s"),  # ValueError
        (lambda: check_fluctuation_dissipation(**{**km, "tests": 10**12}), "tests"),  # hang
        (lambda: check_fluctuation_dissipation(**{**km, "lag": "x"}), "lag"),  # ValueError
        (lambda: solve_fokker_planck(**{**fp, "substeps": 10**12}), "substeps"),  # hang
        (lambda: solve_fokker_planck(**{**fp, "cells": 10**12}), "cells"),  # MemoryError
        (lambda: solve_fokker_planck(**{**fp, "periods": 10**12}), "periods"),  # MemoryError
        (lambda: solve_fokker_planck(**{**fp, "points": fp["points"][::-1]}), "points"),
        (lambda: solve_fokker_planck(**{**fp, "drift": [1.0, 2.0]}), "drift"),  # ValueError
        (lambda: jacobi_increments(**{**jacobi, "rng": 0}), "rng"),  # AttributeError
        (lambda: jacobi_increments(**{**jacobi, "lags": (10**9,), "runs": 10**3}), "lags"),  # hang
        (lambda: jacobi_increments(**{**jacobi, "s0": [2.0]}), "s0"),
        (lambda: jacobi_increments(**{**jacobi, "c": math.nan}), "c"),  # NaN returned
        (lambda: measure_kramers_moyal(**{**measure, "seed": "x"}), "seed"),  # TypeError
        (lambda: measure_kramers_moyal(**{**measure, "runs": 10**12}), "runs"),  # MemoryError
        (lambda: measure_kramers_moyal(**{**measure, "base_lag": 1e308}), "base_lag"),
        (lambda: section_step("x"), "sink"),  # AttributeError
        (lambda: sampled_run(**{**bif["sampled_run"], "settings": None}), "settings"),
        (lambda: bifurcation(**{**bif["bifurcation"], "betas": "x"}), "betas"),  # ValueError
        (lambda: hill.check_amplitude("x", 2.0), "n"),  # ValueError
        (lambda: hill.quarter_period_length([]), "n"),  # TypeError (unhashable)
        (lambda: hill.quarter_period_length(math.nan), "n"),  # NaN returned
        (
            lambda: hill.integrate_quarter_period(
                **{**osc["integrate_quarter_period"], "coefficient": None}
            ),
            "coefficient",
        ),  # fmt: skip
        (
            lambda: hill.integrate_quarter_period(
                **{**osc["integrate_quarter_period"], "alpha": "x"}
            ),
            "alpha",
        ),  # fmt: skip
        (lambda: oscillator.triangle_wave(None), "phase"),  # NaN returned
        (lambda: oscillator.triangle_wave_derivative("x"), "phase"),  # ValueError
        (lambda: oscillator.significant(mpmath.mpf(1.5), 10**12), "digits"),  # MemoryError
        (lambda: oscillator.significant("x", 5), "x"),
        (lambda: series.bound(1e308, 2, 1), "tau"),  # inf returned
        (lambda: series.bound(0.5, 2, 10**12), "i"),  # hang (2**(i - 1))
        (lambda: series.check_bounds(5, [2]), "n_values"),  # TypeError
        (lambda: pareto_layers([1.0], [1.0, 2.0], [1.0]), "depth"),  # ValueError
        (lambda: pareto_layers("x", [1.0], [1.0]), "speed"),  # ValueError
        (lambda: parse_param(None), "param"),  # AttributeError
        (lambda: parse_potential("x", None), "parameters"),  # TypeError
        (lambda: disc_grid(math.nan), "radius"),  # NaN returned
        (lambda: ring_grid("x"), "radius"),  # UFuncTypeError
    ]


def test_named_leaks_of_the_fuzz():
    """The leaks the fuzz found, each refused naming its parameter."""
    for make, name in _leaks():
        with pytest.raises(ParameterError) as info:
            make()
        assert info.value.name == name, (name, str(info.value))


def test_numerical_trouble_of_the_fuzz_says_where():
    """Valid but extreme input that used to return NaN or warn now raises a NumericalError
    saying where: the Fokker-Planck spread at E = 1e308 overflows, the Jacobi diffusion
    with c = 1e308 leaves float range."""
    from sinktheory.equilibrium.kramers import jacobi_increments, solve_fokker_planck
    from sinktheory.errors import NonFiniteStateError

    fp = dict(kramers_entries()[4][2])
    with pytest.raises(NonFiniteStateError, match="Fokker-Planck solution"):
        solve_fokker_planck(**{**fp, "total_energy": 1e308, "start": 0.5e308})
    jacobi = dict(kramers_entries()[5][2])
    with pytest.raises(NonFiniteStateError, match="Jacobi diffusion"):
        jacobi_increments(**{**jacobi, "c": 1e308})


def test_y_invariant_never_evaluates_a_string(tmp_path):
    """y_invariant handed a string used to pass it to sympify, which evaluates Python: it
    ran the code.  Now only a SymPy expression is taken, and nothing runs."""
    from sinktheory.userwell import y_invariant

    marker = tmp_path / "ran"
    with pytest.raises(WellDefinitionError) as info:
        y_invariant(f"__import__('pathlib').Path({str(marker)!r}).touch()")
    assert info.value.name == "V"
    assert not marker.exists()
