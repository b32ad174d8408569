"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules equilibrium,
ensemble, basin, model, results, layout, recurrence, sinkstats, simulate.

Its tables (``overrides``, ``fixed_leaks``, ``HEAVY``, ``RECORDS``,
``PENDING_BY_REASON``) are laid out as tests/_fuzz.py describes.
"""


def overrides() -> dict:
    """Valid keyword arguments of the entry points of this area, by key."""
    import numpy as np
    from _fuzz import Lazy
    from scipy import stats

    s = "sinktheory."
    rows = np.array([[0.5**0.5 * 2, 0.0, 0.003, -0.004, 0.0, 0.0]])  # Fig. 8, k = 1: E0 = 1
    lags = np.array([32.0, 64.0, 128.0])
    grid = np.array([0.1, 0.5, 0.9])
    # increments (point, lag, run) of s, relaxing to mu = 0.3 as 0.75 exp(-tau / 120)
    relaxing = np.stack([(0.75 * np.exp(-t / 120) - 1) * (grid - 0.3) for t in lags], axis=1)
    increments = relaxing[..., None] + 0.01 * np.sin(np.arange(8.0))  # 8 runs, a spread
    noisy = relaxing[..., None] + 0.01 * np.random.default_rng(0).standard_normal((3, 3, 20))

    def hh():  # the Henon-Heiles potential, as a user's well parses it
        from _cli import HH

        from sinktheory.userwell import UserWell

        return UserWell("hh", HH, {}).potential

    def hh_well():
        from sinktheory.basin import NumericWell

        return NumericWell(hh())

    return {
        s + "basin.NumericWell": dict(V=Lazy(hh)),
        s + "basin.escape": dict(well=Lazy(hh_well)),
        s + "basin.leading_order": dict(V=Lazy(hh)),
        s + "ensemble.prepare": dict(record=("container",)),
        s + "equilibrium.ergodicity.ergodicity_map": dict(
            betas=[0.3], runs=2, periods=20, transient=10, lyapunov_runs=0, progress=False
        ),
        s + "equilibrium.prediction.read_settling": dict(target=0.3, resamples=20),
        s + "equilibrium.prediction.measure_settling": dict(measure=(3, 24), resamples=20),
        s + "equilibrium.prediction.shell_prediction": dict(
            s=grid,
            increments=noisy,
            lags=lags,
            pdf=stats.beta(1, 2).pdf,
            mu=1 / 3,
            start=0.5,
            total=0.6,
            particles=2,
            mass=0.2,
            lag=128,
            coefficients="synthetic",
            resamples=20,
            cells=20,
        ),  # fmt: skip
        s + "ensemble.total_energy": dict(values=rows),
        s + "ensemble.SimulationState": dict(
            values=rows, time=0.0, reference_energy=[1.0], dt=0.05, scheme="verlet"
        ),
        s + "equilibrium.prediction.shell_lags": dict(lag=128),
        s + "equilibrium.prediction.slow_mode": dict(
            lags=lags, log_lambda=np.log(0.75) - lags / 120, stderr=np.ones(3)
        ),
        s + "equilibrium.prediction.log_lambdas": dict(
            s=grid, increments=increments, weights=np.ones((3, 3))
        ),
        s + "equilibrium.prediction.law_chain": dict(
            pdf=stats.beta(1, 2).pdf, s_points=[0.0, 1.0], drift=[0.01, -0.02], cells=50
        ),
    }


def fixed_leaks() -> list:
    """(call, parameter its ParameterError must name) of each leak fixed in this area."""
    import math

    import numpy as np

    from sinktheory import RunSettings
    from sinktheory.basin import NumericWell, escape, leading_order
    from sinktheory.canonical import FIG8_SINK
    from sinktheory.ensemble import (
        SimulationState,
        engine_name,
        join_values,
        prepare,
        random_positions,
        run_parameters,
        start_state,
        total_energy,
    )
    from sinktheory.equilibrium.ergodicity import ergodicity_map
    from sinktheory.equilibrium.prediction import (
        law_chain,
        log_lambdas,
        measure_settling,
        read_settling,
        shell_lags,
        shell_prediction,
        slow_mode,
    )
    from sinktheory.layout import pack_params
    from sinktheory.symbolic import x, y

    at = np.array([[[0.003, -0.004]]])
    shells = overrides()["sinktheory.equilibrium.prediction.shell_prediction"]
    rows = np.zeros((1, 6))
    settings = RunSettings(runs=2, seed=1)
    ones = np.ones(3)
    return [
        (lambda: engine_name(None), "sink"),  # AttributeError
        (lambda: pack_params(None), "sink"),  # AttributeError
        (lambda: join_values(None, np.zeros((3, 2))), "q"),  # AttributeError
        (lambda: join_values(np.zeros((3, 2)), None), "v"),  # AttributeError
        (lambda: random_positions(settings, 10**12), "particles"),  # MemoryError
        (lambda: random_positions(None, 1), "settings"),  # AttributeError
        (lambda: run_parameters(FIG8_SINK, settings, math.nan), "runs"),  # NaN returned
        (lambda: start_state(FIG8_SINK, -1, at), "container_energy"),  # ValueError
        (lambda: start_state(FIG8_SINK, 1e308, at), "container_energy"),  # inf returned
        (lambda: start_state(FIG8_SINK, 0.5, None), "positions"),  # AttributeError
        (lambda: total_energy(FIG8_SINK, "x"), "values"),  # ValueError
        (lambda: law_chain(None, [0.0, 1.0], [0.1, 0.1]), "pdf"),  # TypeError
        (lambda: law_chain(np.ones_like, None, [0.1]), "s_points"),  # ValueError
        (lambda: log_lambdas(None, np.zeros((3, 1, 2)), np.ones((3, 1))), "s"),  # LinAlgError
        (lambda: log_lambdas([0.1, 0.5, 0.9], None, np.ones((3, 1))), "increments"),
        (lambda: slow_mode([1.0, 2.0, 3.0], ones, 0 * ones), "stderr"),  # inf returned
        (lambda: slow_mode(None, ones, ones), "lags"),  # LinAlgError
        (lambda: slow_mode([1.0, 2.0, 3.0], 1e12, ones), "log_lambda"),  # OverflowError
        (lambda: shell_lags(math.inf), "lag"),  # OverflowError
        (lambda: prepare(FIG8_SINK, settings, "container", tol="x"), "tol"),  # TypeError
        (lambda: prepare(FIG8_SINK, settings, "container", allowed=None), "allowed"),
        (lambda: read_settling(None, 0.3), "energy_runs"),  # IndexError
        (lambda: measure_settling(None, 0.5, (3, 24)), "sink"),  # AttributeError
        (lambda: shell_prediction(**{**shells, "mu": 0}), "mu"),  # ZeroDivisionError
        (lambda: shell_prediction(**{**shells, "start": -1}), "start"),  # IndexError
        (lambda: shell_prediction(**{**shells, "total": math.inf}), "total"),  # inf returned
        (lambda: shell_prediction(**{**shells, "particles": math.nan}), "particles"),  # NaN
        (lambda: shell_prediction(**{**shells, "periods": 1e308}), "periods"),  # UFuncTypeError
        (lambda: shell_prediction(**{**shells, "increments": None}), "increments"),
        (lambda: SimulationState([[1.0]], 0.0, [1.0], 0.05, "verlet"), "values"),  # unchecked
        (lambda: SimulationState(rows, 0.0, [1.0], 0.05, "x"), "scheme"),  # unchecked
        (lambda: SimulationState(rows, math.nan, [1.0], 0.05, "verlet"), "time"),  # unchecked
        (lambda: NumericWell(None), "V"),  # AttributeError
        (lambda: NumericWell(x**2 + y**2, name=None), "name"),  # unchecked
        (lambda: NumericWell(x**2 + y**2, values=[]), "values"),  # unchecked
        (lambda: leading_order("x**2"), "V"),  # AttributeError
        (lambda: escape(None), "well"),  # AttributeError
        (lambda: escape(NumericWell(x**2 + y**2), 1e-300), "radius"),  # seconds of doubling
        (lambda: ergodicity_map([0.3], alpha=0.5, n=4, shape=[]), "shape"),  # TypeError
    ]


#: Entry points of this area whose calls take seconds: fewer examples.
HEAVY: set[str] = {
    "sinktheory.equilibrium.ergodicity.ergodicity_map",
    "sinktheory.equilibrium.prediction.measure_settling",
}

#: Records the package returns, by key: what returns each.
RECORDS: dict[str, str] = {
    "sinktheory.basin.Basin": "returned by Basin.of (userwell.check_well(...).basin)",
    "sinktheory.basin.Escape": "returned by basin.escape",
    "sinktheory.basin.LeadingOrder": "returned by basin.leading_order",
    "sinktheory.basin.Reach": "returned by Basin.reach",
    "sinktheory.ensemble.SimulationResult": "returned by simulate and simulate_adaptive",
    "sinktheory.ensemble.Start": "returned by ensemble.prepare",
    "sinktheory.equilibrium.area.WellArea": "returned by WellArea.of",
    "sinktheory.equilibrium.ergodicity.ErgodicityMap": "returned by ergodicity_map",
    "sinktheory.equilibrium.kramers.FluctuationDissipation": "returned by "
    "check_fluctuation_dissipation",
    "sinktheory.equilibrium.kramers.KramersMoyal": "returned by kramers_moyal and "
    "measure_kramers_moyal",
    "sinktheory.equilibrium.law.EquilibriumSummary": "returned by EquilibriumLaw.summary",
    "sinktheory.equilibrium.lifetime.LawComparison": "returned by compare_with_law",
    "sinktheory.equilibrium.lifetime.VisitStatistics": "returned by visit_statistics",
    "sinktheory.equilibrium.prediction.LawChain": "returned by law_chain",
    "sinktheory.equilibrium.prediction.RelaxationPrediction": "returned by "
    "predict_relaxation and shell_prediction",
    "sinktheory.equilibrium.prediction.Settling": "returned by settling_periods",
    "sinktheory.equilibrium.relaxation.Relaxation": "returned by measure_relaxation",
    "sinktheory.model.Reach": "returned by Well.reach",
    "sinktheory.model.SinkSummary": "returned by Sink.summary",
    "sinktheory.model.UserWellSummary": "returned by user_well_summary",
    "sinktheory.model.WellSummary": "returned by Well.summary",
    "sinktheory.recurrence.RQA": "returned by rqa and rqa_matrix",
    "sinktheory.simulate.Stepper": "the entries of simulate.STEPPERS (built by the package)",
    "sinktheory.sinkstats.SinkMeasures": "returned by sink_measures",
}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {}
