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
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sinktheory.canonical import FIG8_WELL, HENON_HEILES
from sinktheory.errors import ParameterError


def _sink():
    from sinktheory import Sink

    return Sink(FIG8_WELL, particles=1, mass=0.2)


def _flow():
    from sinktheory.nnm.system import FlowSystem

    return FlowSystem("duffing2", [])


HH_Q, HH_V = np.array([[0.0], [-0.25]]), np.array([[0.42081], [0.0]])  # Henon-Heiles


def entries():
    """(name, function, valid keyword arguments) of each public entry point."""
    from sinktheory import RunSettings
    from sinktheory.chaos import chaos, indicators, monodromy, random_vectors
    from sinktheory.chaos import two_orbit_exponent as two_orbit
    from sinktheory.nnm.agreement import reach_energy
    from sinktheory.nnm.continuation import continue_both, continue_orbits
    from sinktheory.nnm.modes import mode_guess, sink_flow
    from sinktheory.nnm.shooting import shoot
    from sinktheory.nnm.stability import floquet
    from sinktheory.nnm.system import FlowSystem
    from sinktheory.sweep.chaosmap import beta_grid

    small = RunSettings(runs=2, periods=2, seed=1)
    engine = {"q": HH_Q, "v": HH_V, "params": [], "dt": 0.05, "steps": 4, "segments": 2}
    duffing = {"z0": np.array([0.1, 0.1, 0.0, 0.0]), "T": 2 * math.pi}
    M = np.array([[1.0, 1.0, 0, 0], [0, 1.0, 0, 0], [0, 0, 0.0, 1.0], [0, 0, -1.0, 0]])
    return [
        (
            "chaos",
            chaos,
            dict(
                sink=_sink(),
                settings=small,
                spectrum=False,
                gali=0,
                megno=False,
                transverse=False,
                scheme="blanes-moan6",
                dt=0.05,
                renorm=0,
                initial=None,
                energy_bound=1e-4,
                block=None,
                progress=False,
            ),
        ),  # fmt: skip
        (
            "indicators",
            indicators,
            dict(
                system=HENON_HEILES,
                **engine,
                spectrum=False,
                gali=0,
                megno=False,
                transverse=None,
                vectors=None,
                renorm=0,
                seed=0,
                bound=math.inf,
                block=None,
                progress=False,
            ),
        ),  # fmt: skip
        ("monodromy", monodromy, dict(system=HENON_HEILES, **engine, block=None)),
        ("two_orbit_exponent", two_orbit, dict(system=HENON_HEILES, **engine, d0=1e-9, seed=0)),
        ("random_vectors", random_vectors, dict(dim=2, count=1, runs=2, seed=0, mask=None)),
        ("beta_grid", beta_grid, dict(ranges=[(0.0, 0.2)], points=4)),
        ("FlowSystem", FlowSystem, dict(system="duffing2", params=[], members=0)),
        ("shoot", shoot, dict(system=_flow(), **duffing, steps=64, total_energy=0.01)),
        (
            "continue_orbits",
            continue_orbits,
            dict(
                system=_flow(),
                **duffing,
                steps=64,
                total_energy=0.01,
                interval=(1e-3, 0.1),
                ds=0.3,
                max_points=2,
                direction=1,
            ),
        ),  # fmt: skip
        ("mode_guess", mode_guess, dict(sink=_sink(), mode="container", total_energy=0.5)),
        (
            "continue_both",
            continue_both,
            dict(
                sink=_sink(),
                mode="container",
                continue_in="energy",
                total_energy=1e-3,
                interval=(5e-4, 2e-3),
                steps=200,
                points=2,
                ds=0.1,
                half_traces=False,
            ),
        ),  # fmt: skip
        (
            "reach_energy",
            reach_energy,
            dict(sink=_sink(), total_energy=2e-4, steps=200, max_points=20),
        ),
        ("sink_flow", sink_flow, dict(sink=_sink())),
        ("floquet", floquet, dict(M=M, f=np.array([1.0, 0, 0, 0]), g=np.array([0, 1.0, 0, 0]))),
        *_rigid_and_equilibrium_entries(small),
    ]


def _rigid_and_equilibrium_entries(small):
    """The billiard, equilibrium-law and ergodicity entry points (issue 34)."""
    from sinktheory.billiard import billiard, simulate_billiard
    from sinktheory.billiard.table import rigid_table
    from sinktheory.equilibrium import equilibrium_law
    from sinktheory.equilibrium.area import area_ratio, basin_area, scaled_energy
    from sinktheory.equilibrium.ergodicity import ergodicity_point
    from sinktheory.equilibrium.law import check_fractions

    well = _sink().well
    law = equilibrium_law(_sink(), 0.5)
    point = {"alpha": 0.5, "beta": 0.3, "n": 4, "runs": 2, "periods": 20, "transient": 10,
             "lyapunov_runs": 0}  # fmt: skip
    start = {"positions": np.array([[[0.01, 0.02]]]), "velocities": np.array([[[1.0, 0.5]]])}
    return [
        ("billiard", billiard, dict(shape="flat", alpha=0.5, beta=0.3, particles=1, mass=0.2,
                                    settings=small, fixed=False, lyapunov=True)),
        ("simulate_billiard", simulate_billiard,
         dict(table=rigid_table("flat", 0.5, 0.3), **start, mu=0.1, container=None,
              periods=2, lyapunov=True, seed=0, discard=0)),
        ("ergodicity_point", ergodicity_point, dict(p=point, seed=0)),
        ("law.pdf", law.pdf, dict(s=[0.0, 0.5])),
        ("law.tail", law.tail, dict(f=0.5)),
        ("law.kac_periods", law.kac_periods, dict(f=0.5)),
        ("law.summary", law.summary, dict(fractions=[0.5], levels=[0.5], points=5)),
        ("scaled_energy", scaled_energy, dict(well=well, particle_energy=0.5)),
        ("area_ratio", area_ratio, dict(well=well, t=[0.5, 1.0])),
        ("basin_area", basin_area, dict(well=well, particle_energy=0.5)),
        ("check_fractions", check_fractions, dict(fractions=[0.5])),
    ]  # fmt: skip


def _newer_entries():
    """The simulation, attachment, comparison and statistics entry points (issue 34)."""
    from sinktheory import RunSettings
    from sinktheory.adaptive import controller_steps
    from sinktheory.attachments import Attachment, impulse_response
    from sinktheory.compare.efficiency import compare
    from sinktheory.ensemble import start_state
    from sinktheory.equilibrium import equilibrium_law
    from sinktheory.equilibrium.lifetime import (
        autocorrelation_time,
        compare_with_law,
        jackknife_ratio,
        kaplan_meier_mean,
        ks_distance,
        measure_lifetimes,
        visit_statistics,
    )
    from sinktheory.equilibrium.relaxation import measure_relaxation
    from sinktheory.recurrence import epsilon_for_rate, recurrence_rate, rqa
    from sinktheory.simulate import simulate
    from sinktheory.sinkstats import (
        equipartition_container_energy,
        first_fall_below,
        running_mean,
        sink_measures,
    )
    from sinktheory.vibroimpact import modes, simulate_vibroimpact

    small = RunSettings(runs=2, periods=2, seed=1)
    law = equilibrium_law(_sink(), 0.5)
    runs = 0.5 * np.abs(np.sin(np.arange(60.0)))[None, :] * np.array([[1.0], [0.9], [0.8]])
    y0 = start_state(_sink(), 0.5, np.array([[[0.003, -0.004]]]))
    return [
        ("simulate", simulate, dict(sink=_sink(), settings=small, scheme=None, dt=None,
                                    tol=None, record=("container",), progress=False)),
        ("controller_steps", controller_steps, dict(sink=_sink(), values=y0, count=3,
                                                    eps=0.2, rho=None)),
        ("simulate_vibroimpact", simulate_vibroimpact,
         dict(start=np.array([[0.0, 1.0, 0.0, 0.0]]), clearance=0.2, mass=0.2, damping=0.05,
              periods=2, samples_per_period=4, energy_bound=None)),
        ("modes", modes, dict(mass=0.2, damping=0.05)),
        ("impulse_response", impulse_response,
         dict(att=Attachment("impact"), container_energy=0.1, damping=0.05, periods=2, runs=2,
              seed=0, samples_per_period=4, tol=None, dt=None, box=0.01, energy_bound=None,
              line_offset=0.0)),
        ("compare", compare, dict(attachments=[Attachment("impact")], energies=[0.1],
                                  damping=0.05, periods=2, runs=2)),
        ("measure_lifetimes", measure_lifetimes,
         dict(sink=_sink(), settings=RunSettings(runs=2, periods=30, seed=1), transient=10,
              fractions=(0.5,), tol=None, progress=False)),
        ("compare_with_law", compare_with_law,
         dict(energy_runs=runs, law=law, transient=10, fractions=(0.5,), seed=0)),
        ("ks_distance", ks_distance, dict(samples=runs, cdf=law.cdf, resamples=20, seed=0)),
        ("autocorrelation_time", autocorrelation_time, dict(series=runs[0])),
        ("jackknife_ratio", jackknife_ratio, dict(numerators=[1.0, 2.0, 3.0],
                                                   denominators=[2.0, 2.0, 4.0])),
        ("kaplan_meier_mean", kaplan_meier_mean, dict(events=[1, 1, 0], at_risk=[3, 2, 1])),
        ("visit_statistics", visit_statistics, dict(inside=runs > 0.25)),
        ("measure_relaxation", measure_relaxation,
         dict(energy_runs=runs, target=0.3, fraction=0.05, tail=1.0, window=5, level=0.95,
              resamples=20, seed=0)),
        ("sink_measures", sink_measures,
         dict(energy_runs=runs, e0=0.5, total_energy=0.5, particles=1, n=4, transient=None,
              fractions=(0.5,))),
        ("running_mean", running_mean, dict(series=runs[0], window=5)),
        ("first_fall_below", first_fall_below, dict(mean_energy=runs[0], fractions=[0.5],
                                                    e0=0.5)),
        ("equipartition_container_energy", equipartition_container_energy,
         dict(total_energy=0.5, particles=1, n=4, dimension=2)),
        ("rqa", rqa, dict(series=runs[0], eps=None, theiler=1, l_min=2, v_min=2)),
        ("recurrence_rate", recurrence_rate, dict(series=runs[0], eps=0.05)),
        ("epsilon_for_rate", epsilon_for_rate, dict(series=runs[0], rate=0.05)),
    ]  # fmt: skip


ENTRIES = entries()
NEWER = _newer_entries()


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
