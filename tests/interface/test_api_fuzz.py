"""The Python API validates like the command line (issue 26, item 5).

A property-based test over the public signatures of the chaos, normal-mode and start-state
entry points: one argument at a time is replaced by a hostile value (wrong type, bool,
NaN, infinities, huge and tiny numbers, negative counts, wrong shapes, text), the others
kept valid and small; the call must either succeed or raise one of the documented error
types -- ParameterError naming a parameter, or a NumericalError -- never a TypeError,
KeyError, AttributeError, OverflowError, LinAlgError, MemoryError or a numba error, and
never a NaN, inf or complex number the valid call does not return.  Example counts are
kept small (the file runs in well under a minute); SINKTHEORY_FUZZ_SCALE=10 runs ten times
as many.  The analyses' entry points are fuzzed in test_api_fuzz_analyses.py.
"""

import math

import numpy as np
import pytest
from _cli import FUZZ_SCALE, fuzz_one, non_finite
from _fuzz import HH_Q, HH_V, entries, newer_entries
from _fuzz import duffing_flow as _flow
from _fuzz import fig8_sink as _sink
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sinktheory.canonical import FIG8_WELL
from sinktheory.errors import ParameterError

ENTRIES = entries()
NEWER = newer_entries()


_BASELINE: dict = {}  # entry -> where its valid call's result is not finite (or None)
#: Statistics that report "not defined for these data" as NaN (the standard error of a
#: single run, as a 1-d ``inside`` or ``energy_runs`` gives): the documented answer.
UNDEFINED_AS_NAN = {"visit_statistics", "sink_measures"}


def _fuzz(name, function, valid, data):
    if name not in _BASELINE:
        _BASELINE[name] = non_finite(function(**valid)) or (name in UNDEFINED_AS_NAN or None)
    fuzz_one(function, valid, data, baseline=_BASELINE[name])


@pytest.mark.parametrize(("name", "function", "valid"), ENTRIES, ids=[e[0] for e in ENTRIES])
@settings(max_examples=120 * FUZZ_SCALE, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])  # fmt: skip
@given(data=st.data())
def test_only_documented_errors_escape(name, function, valid, data):
    _fuzz(name, function, valid, data)


@pytest.mark.parametrize(("name", "function", "valid"), NEWER, ids=[e[0] for e in NEWER])
@settings(max_examples=60 * FUZZ_SCALE, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])  # fmt: skip
@given(data=st.data())
def test_newer_entry_points_raise_only_documented_errors(name, function, valid, data):
    _fuzz(name, function, valid, data)


def test_valid_arguments_run():
    """The base arguments are valid: each entry point runs with them as they are."""
    for _, function, valid in ENTRIES + NEWER:
        function(**valid)


def test_named_cases_of_the_issue():
    """The cases the issue lists, each refused naming its parameter."""
    from sinktheory import RunSettings, Sink, Well
    from sinktheory.chaos import chaos, indicators, random_vectors
    from sinktheory.equilibrium.area import scaled_energy
    from sinktheory.nnm.continuation import continue_orbits
    from sinktheory.nnm.modes import mode_guess
    from sinktheory.nnm.shooting import shoot
    from sinktheory.nnm.stability import floquet
    from sinktheory.nnm.system import FlowSystem
    from sinktheory.simulate import simulate
    from sinktheory.sweep.chaosmap import beta_grid, chaos_map

    small = RunSettings(runs=2, periods=2)
    duffing = (np.array([0.1, 0.1, 0.0, 0.0]), 2 * math.pi)
    stop = (1e-3, 0.1)
    cases = [
        (lambda: chaos(_sink(), small, megno="yes", dt=0.05), "megno"),
        (lambda: chaos(_sink(), small, transverse=[1], dt=0.05), "transverse"),
        (lambda: chaos(_sink(), small, block=True, dt=0.05), "block"),
        (lambda: chaos(_sink(), small, block=-1, dt=0.05), "block"),
        (lambda: chaos(_sink(), small, block=2.5, dt=0.05), "block"),
        (lambda: chaos(_sink(), small, block=1e12, dt=0.05), "block"),
        (lambda: chaos(_sink(), RunSettings(runs=1), initial=[[5, 5]], dt=0.05), "initial"),
        (lambda: chaos(_sink(), RunSettings(runs=1, box=1e308), dt=0.05), "box"),
        (lambda: simulate(_sink(), RunSettings(runs=1), initial=[[5, 5]]), "initial"),
        (lambda: simulate(Sink(Well(0.5, 0.3, 4, gamma=1e308)), small), "gamma"),
        (lambda: scaled_energy(FIG8_WELL, 1e308), "particle_energy"),  # returned inf
        (lambda: shoot(_flow(), duffing[0], -1.0, steps=400), "T"),
        (lambda: shoot(_flow(), *duffing, steps=10**12), "steps"),
        (lambda: shoot(_flow(), *duffing, steps=64, total_energy=-1.0), "total_energy"),
        (lambda: FlowSystem("nosuch", []), "system"),
        (lambda: FlowSystem(3, []), "system"),
        (lambda: floquet(np.full((4, 4), np.nan), np.ones(4), np.ones(4)), "M"),
        (lambda: mode_guess(_sink(), "container", True), "total_energy"),
        (lambda: mode_guess(_sink(), "container", 1e308), "total_energy"),
        (lambda: continue_orbits(_flow(), *duffing, steps=64, interval=stop, ds=0), "ds"),
        (lambda: continue_orbits(_flow(), *duffing, steps=64, interval=stop, ds=-1), "ds"),
        (
            lambda: continue_orbits(_flow(), *duffing, steps=64, interval=stop, max_points=-1),
            "max_points",
        ),  # fmt: skip
        (lambda: continue_orbits(_flow(), *duffing, steps=64, interval=(math.nan, 1)), "interval"),
        (lambda: indicators(3, HH_Q, HH_V, [], dt=0.05, steps=4, segments=2), "system"),
        (lambda: random_vectors(2, 5, 2, 0), "count"),
        (lambda: random_vectors(2, 1, -1, 0), "runs"),
        (lambda: random_vectors(10**12, 1, 1, 0), "dim"),
        (lambda: beta_grid([(0.0, 0.2)], 0), "points"),
        (lambda: beta_grid([(0.2, 0.0)], 4), "ranges"),
        (lambda: chaos_map(0.5, 4, "x", runs=2, periods=2, workers=1), "betas"),
    ]
    for make, name in cases:
        with pytest.raises(ParameterError) as info:
            make()
        assert info.value.name == name, (name, str(info.value))
