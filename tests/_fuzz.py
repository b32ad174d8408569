"""The API fuzz's tables (issue 34, item 5), shared by tests/interface/test_api_fuzz*.py.

* :func:`public_entry_points` walks the package: every callable named in the ``__all__`` of
  a public module (no part of its name starts with ``_``), exceptions and the generated
  kernels aside, keyed by where it is defined.
* The hand-written tables (:func:`entries`, :func:`newer_entries`, :func:`kramers_entries`
  ...) give valid, small keyword arguments of the heavy entry points.
* :func:`built_entries` gives those of every other entry point from :data:`VALID` (a
  valid value per parameter name) and :func:`_overrides` (per entry point, where a name
  means something else there), the parameters with defaults taking their defaults.
* Each area has a file of tables, tests/_fuzz_AREA.py (:data:`AREAS`): ``overrides()``
  (valid keyword arguments by key, a costly one wrapped in :class:`Lazy`),
  ``fixed_leaks()`` (each leak found and fixed, as a call and the parameter its
  ParameterError must name), ``HEAVY`` (entry points taking seconds), ``RECORDS`` (classes
  the package builds and returns, with what returns each) and ``PENDING_BY_REASON``.
* :data:`EXEMPT` lists the entry points with no user input, each with its reason;
  :data:`RECORDS` the classes the package builds and returns (their constructors are not
  entry points); :data:`PENDING` those not fuzzed yet (test_api_fuzz_coverage.py fails on any entry
  point in none of these, and reports the pending ones).
"""

import importlib
import inspect
import math
import pkgutil
import types

import numpy as np
from _cli import ELLIPTIC, HH

from sinktheory.canonical import FIG8_WELL, HENON_HEILES


def key_of(function) -> str:
    """Where ``function`` is defined, ``module.qualname``: a bound method counts for its
    class (calling it is the way users reach the class), a numba function for its Python
    function, a module that is also a verb (``sinktheory.simulate``) for its function."""
    self = getattr(function, "__self__", None)
    if self is not None and not isinstance(self, types.ModuleType):
        cls = self if inspect.isclass(self) else type(self)
        return f"{cls.__module__}.{cls.__qualname__}"
    function = getattr(function, "py_func", function)
    return f"{function.__module__}.{function.__qualname__}"


def public_entry_points() -> dict[str, object]:
    """``key_of(f) -> f`` for every callable named in the ``__all__`` of a public module of
    sinktheory, the classes of :func:`_never_called_with_values` and the generated kernels
    (``sinktheory._generated``) aside."""
    import sinktheory

    names = ["sinktheory"] + [
        m.name
        for m in pkgutil.walk_packages(sinktheory.__path__, "sinktheory.")
        if not any(part.startswith("_") for part in m.name.split(".")[1:])
    ]
    found = {}
    for name in names:
        module = importlib.import_module(name)
        for attr in module.__all__:
            obj = getattr(module, attr)
            if isinstance(obj, types.ModuleType) and callable(obj):  # a verb (sinktheory)
                obj = getattr(obj, attr)
            if isinstance(obj, types.ModuleType) or not callable(obj):
                continue
            if inspect.isclass(obj) and _never_called_with_values(obj):
                continue
            key = key_of(obj)
            if key.startswith("sinktheory.") and not key.startswith("sinktheory._generated"):
                found.setdefault(key, obj)
    return found


def public_methods() -> dict[str, tuple]:
    """``"module.Class.method" -> (class, method name)`` for every public method with user
    input (a parameter besides ``self``/``cls``; properties aside) of every class among
    :func:`public_entry_points`, defined in the class itself."""
    found = {}
    for key, cls in public_entry_points().items():
        if not inspect.isclass(cls):
            continue
        for name, attr in vars(cls).items():
            if name.startswith("_") or isinstance(attr, property):
                continue
            function = attr.__func__ if isinstance(attr, classmethod | staticmethod) else attr
            if not inspect.isfunction(function):
                continue
            bound = 0 if isinstance(attr, staticmethod) else 1
            if len(inspect.signature(function).parameters) > bound:
                found[f"{key}.{name}"] = (cls, name)
    return found


def _never_called_with_values(cls) -> bool:
    """Whether the class ``cls`` is no entry point by its kind: an exception or warning, a
    typing Protocol (a type to check against, never called) or a SymPy function head (its
    arguments are SymPy expressions, which SymPy checks)."""
    import sympy

    protocol = getattr(cls, "_is_protocol", False)
    return issubclass(cls, (BaseException, sympy.Function)) or protocol


def fig8_sink():
    from sinktheory import Sink

    return Sink(FIG8_WELL, particles=1, mass=0.2)


def duffing_flow():
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
                sink=fig8_sink(),
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
        ("shoot", shoot, dict(system=duffing_flow(), **duffing, steps=64, total_energy=0.01)),
        (
            "continue_orbits",
            continue_orbits,
            dict(
                system=duffing_flow(),
                **duffing,
                steps=64,
                total_energy=0.01,
                interval=(1e-3, 0.1),
                ds=0.3,
                max_points=2,
                direction=1,
            ),
        ),  # fmt: skip
        ("mode_guess", mode_guess, dict(sink=fig8_sink(), mode="container", total_energy=0.5)),
        (
            "continue_both",
            continue_both,
            dict(
                sink=fig8_sink(),
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
            dict(sink=fig8_sink(), total_energy=2e-4, steps=200, max_points=20),
        ),
        ("sink_flow", sink_flow, dict(sink=fig8_sink())),
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

    well = fig8_sink().well
    law = equilibrium_law(fig8_sink(), 0.5)
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


def newer_entries():
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
    law = equilibrium_law(fig8_sink(), 0.5)
    runs = 0.5 * np.abs(np.sin(np.arange(60.0)))[None, :] * np.array([[1.0], [0.9], [0.8]])
    y0 = start_state(fig8_sink(), 0.5, np.array([[[0.003, -0.004]]]))
    return [
        ("simulate", simulate, dict(sink=fig8_sink(), settings=small, scheme=None, dt=None,
                                    tol=None, record=("container",), progress=False)),
        ("controller_steps", controller_steps, dict(sink=fig8_sink(), values=y0, count=3,
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
         dict(sink=fig8_sink(), settings=RunSettings(runs=2, periods=30, seed=1), transient=10,
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


def kramers_entries():
    """The Kramers-Moyal entry points, on the Jacobi diffusion of known law Beta(1, 2)."""
    from sinktheory import Sink, Well
    from sinktheory.equilibrium import equilibrium_law
    from sinktheory.equilibrium.kramers import (
        check_fluctuation_dissipation,
        gauss_grid,
        jacobi_increments,
        kramers_moyal,
        measure_kramers_moyal,
        solve_fokker_planck,
    )

    s = gauss_grid(4, 1)[0]
    inc = jacobi_increments(s, (1, 2), 20, np.random.default_rng(0), a=1.0, b=2.0, c=0.01)
    km = kramers_moyal(s, 1.0, 1, (1, 2), inc)
    law = equilibrium_law(Sink(Well(0.5, 0.0, 1), particles=1), 1.0)
    grid = np.linspace(0, 1, 11)
    return [
        ("gauss_grid", gauss_grid, dict(points=4, n=4)),
        ("kramers_moyal", kramers_moyal,
         dict(s=s, total_energy=1.0, n=1, lags=(1, 2), increments=inc, weights=None, base_lag=0)),
        ("measure_kramers_moyal", measure_kramers_moyal,
         dict(sink=fig8_sink(), total_energy=0.5, points=2, lags=(1,), runs=2, seed=1, tol=1e-6,
              base_lag=0)),
        ("check_fluctuation_dissipation", check_fluctuation_dissipation,
         dict(km=km, law=law, lag=None, tests=2, exact=False)),
        ("solve_fokker_planck", solve_fokker_planck,
         dict(total_energy=1.0, points=grid, drift=0.01 * (1 - 3 * grid),
              diffusion=0.01 * grid * (1 - grid), start=0.5, periods=3, cells=20, substeps=2)),
        ("jacobi_increments", jacobi_increments,
         dict(s0=[0.5], lags=(1, 2), runs=3, rng=np.random.default_rng(1), a=1.0, b=1.0,
              c=0.1, substeps=5)),
    ]  # fmt: skip


def bifurcation_entries():
    from sinktheory import RunSettings
    from sinktheory.bifurcation import bifurcation, sampled_run, section, section_step

    return [
        ("bifurcation", bifurcation,
         dict(betas=[0.3], alpha=0.5, n=4, gamma=1.0, shape="flat", mass=0.2,
              container_energy=0.5, transient=1, count=2, quantity="y")),
        ("section", section, dict(sink=fig8_sink(), transient=1, count=2, quantity="y",
                                  container_energy=0.5)),
        ("section_step", section_step, dict(sink=fig8_sink(), container_energy=0.5)),
        ("sampled_run", sampled_run,
         dict(sink=fig8_sink(), settings=RunSettings(runs=1, periods=2), start=(0.0, 0.01),
              per_period=2)),
    ]  # fmt: skip


def oscillator_entries():
    """Hill's equation, the power-law oscillator and its triangle-wave series."""
    import mpmath

    from sinktheory import hill, oscillator, series

    return [
        ("integrate_quarter_period", hill.integrate_quarter_period,
         dict(n=2, params=np.array([0.5]), coefficient=hill.PURE, amplitude=1.0, alpha=0.0,
              rtol=1e-10, max_steps=1000, implementation="python")),
        ("quarter_period_mpmath", hill.quarter_period_mpmath, dict(n=2, lam=0.5, dps=15)),
        ("monodromy_solve_ivp", hill.monodromy_solve_ivp,
         dict(n=2, param=0.5, coefficient=hill.PURE, amplitude=1.0, alpha=0.0,
              half_periods=1, rtol=1e-8)),
        ("check_amplitude", hill.check_amplitude, dict(n=4, amplitude=2.0)),
        ("quarter_period_length", hill.quarter_period_length, dict(n=2)),
        ("oscillator", oscillator.oscillator, dict(n=2, amplitude=1.0, energy=None, dps=15)),
        ("period", oscillator.period, dict(n=2, amplitude=None, energy=0.5, dps=15)),
        ("triangle_wave", oscillator.triangle_wave, dict(phase=[0.1, 0.3])),
        ("triangle_wave_derivative", oscillator.triangle_wave_derivative, dict(phase=0.3)),
        ("exact_shape", oscillator.exact_shape, dict(tau=[0.1, 0.5], n=2)),
        ("exact_solution", oscillator.exact_solution,
         dict(t=[0.0, 1.0], n=2, amplitude=1.0, start="turning")),
        ("exact_shape_mp", oscillator.exact_shape_mp, dict(tau=0.3, n=2, dps=15)),
        ("exact_solution_mp", oscillator.exact_solution_mp,
         dict(t=1.0, n=2, amplitude=1.0, start="turning", dps=15)),
        ("significant", oscillator.significant, dict(x=mpmath.mpf(1.5), digits=5)),
        ("triangle_series", series.triangle_series, dict(n=2, order=3)),
        ("bound", series.bound, dict(tau=0.5, n=2, i=1)),
        ("check_bounds", series.check_bounds, dict(n_values=[2], orders=[2])),
        ("error_table", series.error_table, dict(n=2, order=3, samples=101)),
        ("accuracy", series.accuracy, dict(n=2, order=3, samples=101)),
    ]  # fmt: skip


#: A small design grid (two designs, a few seconds).
DESIGN = {"beta": 0.3, "n": 4, "particles": [1, 2], "runs": 2, "periods": 12,
          "horizons": "6+12", "lyapunov_runs": 0, "bootstrap": 10}  # fmt: skip


def design_entries():
    from sinktheory.design import cost, explorer, ranking

    sweep = explorer.plan(DESIGN)
    return [
        ("plan", explorer.plan, dict(params=DESIGN, seed=0)),
        ("estimate", cost.estimate, dict(sweep=sweep, workers=1, seconds=0.05, todo=None)),
        ("explore", explorer.explore,
         dict(params=DESIGN, seed=0, store=None, scheduler=None, workers=1, resume=False,
              repair=False, progress=False, estimate_first=False, report=None, top=10)),
        ("pareto_layers", ranking.pareto_layers,
         dict(speed=[1.0, 2.0], depth=[0.5, 0.4], spread=[0.1, 0.2])),
    ]  # fmt: skip


def sweep_and_well_entries():
    from sinktheory.sweep import parse_param, run_sweep
    from sinktheory.userwell import (
        Parameter,
        UserWell,
        check_well,
        disc_grid,
        parse_potential,
        ring_grid,
        y_invariant,
    )

    well = UserWell("hh", HH, {})
    return [
        ("run_sweep", run_sweep,
         dict(kind="floquet", params={"alpha": 0.5, "beta": [-0.2, 0.1], "n": 4}, seed=0,
              store=None, scheduler=None, workers=1, resume=False, progress=False,
              repair=False)),
        ("parse_param", parse_param, dict(text="beta=0:0.3:4")),
        ("UserWell", UserWell,
         dict(name="ellipse", potential=ELLIPTIC,
              parameters={"a": 0.3, "b": 0.2, "gamma": 1, "n": (2, (1, 20))},
              wall_ratios=())),
        ("Parameter", Parameter, dict(name="a", default=0.3, range=(0.01, 10))),
        ("parse_potential", parse_potential, dict(text=HH, parameters=(), where="potential")),
        ("check_well", check_well, dict(well=well, radius=0.5)),
        ("disc_grid", disc_grid, dict(radius=1.0)),
        ("ring_grid", ring_grid, dict(radius=1.0)),
        ("y_invariant", y_invariant, dict(V=well.potential)),
    ]  # fmt: skip


# --- every other entry point: valid arguments from the parameters' names ------------------
def _valid():
    """A valid, small value of each common parameter name (built on each call: fresh
    arrays and objects)."""
    from sinktheory import RunSettings
    from sinktheory.attachments import Attachment
    from sinktheory.billiard.table import rigid_table
    from sinktheory.equilibrium import equilibrium_law

    sink = fig8_sink()
    runs = 0.5 * np.abs(np.sin(np.arange(60.0)))[None, :] * np.array([[1.0], [0.9], [0.8]])
    return {
        "sink": sink, "well": FIG8_WELL, "n": 4, "alpha": 0.5, "beta": 0.3, "gamma": 1.0,
        "shape": "flat", "particles": 1, "mass": 0.2, "mu": 0.1, "total_energy": 0.5,
        "container_energy": 0.5, "particle_energy": 0.5, "energy": 0.5, "e0": 0.5,
        "settings": RunSettings(runs=2, periods=2, seed=1), "runs": 2, "periods": 2,
        "seed": 0, "dt": 0.05, "steps": 4, "damping": 0.05, "eps": 0.2, "ds": 0.1,
        "points": 5, "transient": 1, "amplitude": 1.0, "order": 3, "window": 3, "count": 2,
        "fraction": 0.5, "fractions": [0.5], "t": [0.0, 1.0], "tau": 0.5, "lam": 0.5,
        "radius": 0.5, "x": 0.5, "y": 0.5, "s": 0.5, "period": 1.0, "lo": 0.1, "hi": 0.2,
        "tol": 1e-6, "k3": 1.0, "dim": 2, "values": [1.0, 2.0, 3.0], "series": runs[0],
        "energy_runs": runs, "mean": runs[0], "stderr": 0.1 * runs[0], "se": 0.01,
        "att": Attachment("impact"), "attachments": [Attachment("impact")],
        "table": rigid_table("flat", 0.5, 0.3), "law": equilibrium_law(sink, 0.5),
        "system": HENON_HEILES, "q": HH_Q, "v": HH_V, "params": [], "segments": 2,
        "phase": 0.3, "digits": 5, "i": 1, "total": 10, "hours": 0.001, "seconds": 1.0,
        "rng": np.random.default_rng(0), "betas": [0.3], "omega": 1.0, "lambda1": [0.1, 0.2],
        "kinds": ["impact"], "energies": [0.1], "V": HH, "potential": HH, "expr": HH,
        "text": "beta=0:0.3:4", "name": "alpha", "value": 1.0, "tolerance": 1e-6,
        "sinks": [sink], "spectrum": False, "gali": 0, "transverse": False, "renorm": 0,
        "block": None, "bound": 1e-4, "scheme": "verlet", "stable": [True, False],
        "p": {"alpha": 0.5, "beta": 0.3, "n": 4, "runs": 2, "periods": 2},
    }  # fmt: skip


def _overrides():
    """Where a parameter name means something else (or needs a matching value) at one entry
    point: its valid arguments there, by key."""
    import sympy

    from sinktheory import RunSettings
    from sinktheory.floquet import model_problem
    from sinktheory.sweep import Sweep
    from sinktheory.userwell import UserWell

    ellipse = UserWell("ellipse", ELLIPTIC, {"a": 0.3, "b": 0.2, "gamma": 1, "n": (2, (1, 20))},
                       wall_ratios=("(x/a)**2 + (y/b)**2",))  # fmt: skip
    small = RunSettings(runs=1, periods=2, seed=1)
    ring = np.eye(20, dtype=bool) | np.eye(20, k=1, dtype=bool) | np.eye(20, k=-1, dtype=bool)
    M = np.array([[1.0, 1.0, 0, 0], [0, 1.0, 0, 0], [0, 0, 1.0, 0], [0, 0, -1.0, 1.0]])
    t = np.linspace(0, 20, 64)
    s = "sinktheory."
    return {
        s + "attachments.Attachment": dict(kind="impact"),
        s + "billiard.run.well_billiard": dict(well=ellipse, settings=small),
        s + "billiard.run.rigid_limit": dict(shape="flat", settings=small),
        s + "billiard.table.sinai_table": dict(radius=0.2),
        s + "billiard.table.stadium_table": dict(half_length=0.5, radius=0.5),
        s + "billiard.table.well_table": dict(well=ellipse),
        s + "floquet.well_floquet": dict(well=ellipse, amplitude=0.1),
        s + "floquet.well_hill": dict(well=ellipse),
        s + "floquet.model_scan": dict(beta_range=(0.1, 0.3, 3)),
        s + "floquet.pure_scan": dict(lam_range=(0.1, 0.3, 3), n=2),
        s + "floquet.scan": dict(problem=model_problem(0.5, 4), lo=0.1, hi=0.3, count=3),
        s + "equilibrium.law.well_law": dict(well=ellipse, particles=1, total_energy=0.5),
        s + "model.user_well_summary": dict(well=ellipse),
        s + "wellat.WellAt": dict(well=ellipse),
        s + "integrators.get_scheme": dict(name="verlet"),
        s + "sweep.kinds.get_kind": dict(name="floquet"),
        s + "sweep.grid.parse_range": dict(name="beta", text="0:0.3:4"),
        s + "sweep.grid.point_seed": dict(seed=0, index=3),
        s + "sweep.runner.execute": dict(
            sweep=Sweep.make("floquet", {"alpha": 0.5, "beta": [0.1, 0.2], "n": 4}),
            progress=False),
        s + "design.ranking.pareto_front": dict(speed=[1.0, 2.0], depth=[0.5, 0.4],
                                                spread=[0.1, 0.2]),
        s + "recurrence.rqa_matrix": dict(matrix=ring),
        s + "runstats.plus_minus": dict(mean=1.0, stderr=0.1),
        s + "nnm.backbone.harmonic_balance": dict(omega=0.5),
        s + "nnm.backbone.inphase_backbone": dict(lo=0.05, hi=0.1, points=2, steps=100),
        s + "nnm.backbone.inphase_pieces": dict(lo=0.05, hi=0.1, points=2, steps=100),
        s + "equilibrium.microcanonical.shell_states": dict(container_energy=0.25, runs=2),
        s + "equilibrium.microcanonical.particle_energies": dict(particles=2, total=0.5,
                                                                  size=3),
        s + "ensemble.start_state": dict(positions=np.array([[[0.003, -0.004]]])),
        s + "ensemble.join_values": dict(q=np.zeros((3, 2)), v=np.zeros((3, 2))),
        s + "ensemble.split_values": dict(values=np.zeros((2, 6))),
        s + "compare.wavelet.wavelet_map": dict(t=t, x=np.sin(t), omega=(0.3, 3.0, 8)),
        s + "compare.wavelet.morlet": dict(name="cmor1.5-1.0"),
        s + "design.measures.horizons_of": dict(text="6+12", periods=12),
        s + "equilibrium.ergodicity.fractions_of": dict(text="0.5,0.25"),
        s + "runstats.check_runs": dict(name="runs", value=3),
        s + "userwell.expression_text": dict(expr=sympy.sympify("x**2 + y**2")),
        s + "validation.flag": dict(name="x", value=True),
        s + "userwell.parameter_values": dict(values={"a": 0.3}),
        s + "chaos.tangent.canonical": dict(M=M, masses=[1.0, 1.0]),
        s + "chaos.tangent.symplectic_defect": dict(M=M[None], masses=[1.0, 1.0]),
        s + "chaos.result.sali_from_gali2": dict(g=np.array([[0.5, 0.1]])),
        s + "worklimit.check_work": dict(steps_per_period=100),
        s + "scenes.estimate": dict(number=2, quick=True),
        s + "userwell.well_report": dict(well=ellipse),
        s + "damped.simulate_inelastic": dict(settings=small),
        # leaksb: one run, whose standard error is NaN by the package's rule (runstats.py),
        # so a hostile value read as one run (a number, [1.0, 2.0]) may give NaN too
        s + "runstats.ensemble_mean": dict(energy_runs=[[0.5, 0.4]]),
        s + "runstats.mean_stderr": dict(values=[0.5]),
        s + "runstats.spread": dict(values=[0.5]),
        s + "plot.floquet.plot_fig7": dict(ns=(2,), count=20),
    } | {key: given for m in _AREA_MODULES for key, given in m.overrides().items()}  # fmt: skip


#: Entry points fuzzed by a test of their own rather than from a table: the test.
ALSO_FUZZED = {
    "sinktheory.sweep.plan.Sweep": "test_every_sweep_parameter_is_checked (Sweep.make)",
    "sinktheory.userwell.load_well": "test_hostile_well_files_are_refused_in_one_line",
}

#: Entry points with no user input (no parameters at all: the guard checks), each with why.
EXEMPT = {
    "sinktheory.billiard.impact.impulse_expression": "no parameters",
    "sinktheory.codegen.render": "no parameters",
    "sinktheory.engine.blocks.machine_key": "no parameters",
    "sinktheory.engine.cache.cache_dir": "no parameters",
    "sinktheory.engine.cache.compilation_notes": "no parameters",
    "sinktheory.engine.systems.henon_heiles": "no parameters",
    "sinktheory.engine.systems.two_dof_duffing": "no parameters",
    "sinktheory.progress.HeldSignals": "no parameters",
    "sinktheory.results.Result": "no parameters",
    "sinktheory.symbolic.amplitude_of_energy": "no parameters",
    "sinktheory.symbolic.axis_reach_factor": "no parameters",
    "sinktheory.symbolic.energy_of_amplitude": "no parameters",
    "sinktheory.symbolic.flat_level_half_width": "no parameters",
    "sinktheory.symbolic.hill_shape": "no parameters",
    "sinktheory.symbolic.lambda_coefficient": "no parameters",
    "sinktheory.symbolic.oscillator_acceleration": "no parameters",
    "sinktheory.symbolic.oscillator_energy": "no parameters",
    "sinktheory.symbolic.period_closed_form": "no parameters",
    "sinktheory.symbolic.period_integral": "no parameters",
    "sinktheory.symbolic.rigid_wall_contour": "no parameters",
    "sinktheory.symbolic.symmetric_corner_bound": "no parameters",
    "sinktheory.symbolic.symmetric_corner_saddle": "no parameters",
    "sinktheory.validation.memory_limit": "no parameters",
    "sinktheory.limits.max_seconds": "no parameters",
    "sinktheory.worklimit.resumable": "no parameters",
    "sinktheory.worklimit.tally": "no parameters",
}

#: The areas whose tables live in files of their own (tests/_fuzz_AREA.py: valid arguments,
#: records and pending entry points), so that work on one area does not touch another's.
AREAS = ("billiard", "chaos", "design", "engine", "equilibrium", "plot", "sweep")
_AREA_MODULES = [importlib.import_module(f"_fuzz_{area}") for area in AREAS]

#: Classes the package builds and returns (dataclasses or NamedTuples that do not check
#: their fields): their constructors are not entry points.  Key -> what returns it.
RECORDS = {key: what for m in _AREA_MODULES for key, what in m.RECORDS.items()}

#: Entry points whose calls take seconds, by area: fewer examples.
AREA_HEAVY = set().union(*(m.HEAVY for m in _AREA_MODULES))


def area_fixed_leaks() -> list:
    """(call, parameter it must name) of each leak fixed in an area: see its file."""
    return [leak for m in _AREA_MODULES for leak in m.fixed_leaks()]


class Lazy:
    """A valid argument built on first use, not when the tests are collected (a result to
    plot, say): ``Lazy(make)``; :func:`resolved` builds it, once."""

    def __init__(self, make):
        self.make = make

    def value(self):
        if not hasattr(self, "_value"):
            self._value = self.make()
        return self._value


def resolved(valid: dict) -> dict:
    """``valid`` with each :class:`Lazy` argument built."""
    return {k: v.value() if isinstance(v, Lazy) else v for k, v in valid.items()}


#: Entry points the fuzz does not call yet (issue 34), by why: the coverage test reports
#: them (strict xfail) until none is left.
PENDING_BY_REASON: dict[str, tuple] = {}
for _m in _AREA_MODULES:
    for _why, _keys in _m.PENDING_BY_REASON.items():
        PENDING_BY_REASON[_why] = PENDING_BY_REASON.get(_why, ()) + tuple(_keys)
PENDING = {key: why for why, keys in PENDING_BY_REASON.items() for key in keys}


def _arguments(function, given: dict) -> dict:
    """Valid keyword arguments of ``function``: ``given`` first, then :data:`VALID` by
    name for the parameters without a default, then the defaults."""
    valid = _valid()
    out = {}
    for p in inspect.signature(function).parameters.values():
        if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD) or p.kind is p.POSITIONAL_ONLY:
            continue
        if p.name in ("self", "cls"):  # a method's own object (test_api_fuzz_methods.py)
            continue
        if p.name in given:
            out[p.name] = given[p.name]
        elif p.default is not p.empty:
            out[p.name] = p.default
        elif p.name in valid:
            out[p.name] = valid[p.name]
        else:
            where = key_of(function)
            raise KeyError(f"no valid {p.name!r} for {where}: give it in _overrides")
    return out


def built_entries(skip=()) -> list:
    """(key, function, valid keyword arguments) of each public entry point not in ``skip``
    (the keys of the hand-written tables), :data:`EXEMPT`, :data:`RECORDS` or
    :data:`PENDING`."""
    out, overrides = [], _overrides()
    for key, function in sorted(public_entry_points().items()):
        if key in skip or key in ALSO_FUZZED or key in EXEMPT or key in RECORDS or key in PENDING:
            continue
        out.append((key, function, _arguments(function, overrides.get(key, {}))))
    return out


def hand_entries() -> list:
    """The hand-written tables, all of them."""
    return (entries() + newer_entries() + kramers_entries() + bifurcation_entries()
            + oscillator_entries() + design_entries() + sweep_and_well_entries())  # fmt: skip
