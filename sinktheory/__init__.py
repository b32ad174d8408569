"""sinktheory: the stochastic energy sink of Pilipchuk (arXiv:1610.02939).

A massive container on a spring drains its energy into a few light particles bouncing in
a soft-wall potential well, with no damping at all.  The package derives the model
symbolically (:mod:`sinktheory.symbolic`), prints numerical kernels from it and builds
analyses on top of validated parameters (:mod:`sinktheory.model`).

``import sinktheory as st`` gives the main verbs, their result types and every error;
each loads its module on first use, so the import itself stays light (no numba, no
SymPy).

Examples
--------
>>> import sinktheory as st
>>> st.Well(alpha=0.5, beta=0.3, n=10).curvature_at_centre
0.6
>>> sink = st.Sink(st.Well(0.5, 0.3, 4), particles=1, mass=0.2)
>>> res = st.simulate(sink, st.RunSettings(runs=2, periods=2, seed=1))
>>> res.container_energy.shape
(2, 3)
>>> round(float(st.period(2, amplitude=1)), 6)  # 4 K(1/2) for x'' + x^3 = 0, amplitude 1
7.416299
"""

from importlib import import_module

from .errors import (
    BracketError,
    EnergyDriftError,
    HillIntegrationError,
    NonFiniteStateError,
    NumericalError,
    ParameterError,
    PeriodOutOfRangeError,
    ShootingError,
    StepControlError,
    SweepPointError,
    WellDefinitionError,
)

#: Verbs that are modules too: calling the module calls its function (:mod:`._verbs`).
_VERBS = ("simulate", "chaos", "bifurcation", "billiard")
#: Public name -> the module that defines it, loaded on first use.
_LAZY = {
    # the model
    "Well": "model",
    "Sink": "model",
    "RunSettings": "model",
    # the full dynamics
    "SimulationResult": "ensemble",
    "SimulationState": "ensemble",
    # chaos indicators and chaos maps
    "ChaosResult": "chaos.result",
    "chaos_map": "sweep.chaosmap",
    # the power-law oscillator, Hill's equation and the Floquet stability of y = 0
    "period": "oscillator",
    "model_problem": "floquet",
    "scan": "floquet",
    "StabilityScan": "floquet",
    # statistical mechanics
    "equilibrium_law": "equilibrium.law",
    "EquilibriumLaw": "equilibrium.law",
    "measure_relaxation": "equilibrium.relaxation",
    "Relaxation": "equilibrium.relaxation",
    "predict_relaxation": "equilibrium.prediction",
    "RelaxationPrediction": "equilibrium.prediction",
    "settling_periods": "equilibrium.prediction",
    "Settling": "equilibrium.prediction",
    # the rigid limit, sections, recurrence
    "BilliardResult": "billiard.run",
    "BifurcationDiagram": "bifurcation",
    "rqa": "recurrence",
    "RQA": "recurrence",
    # sweeps
    "run_sweep": "sweep.runner",
}

__all__ = [
    "BifurcationDiagram",
    "BilliardResult",
    "BracketError",
    "ChaosResult",
    "EnergyDriftError",
    "EquilibriumLaw",
    "HillIntegrationError",
    "NonFiniteStateError",
    "NumericalError",
    "ParameterError",
    "PeriodOutOfRangeError",
    "RQA",
    "Relaxation",
    "RelaxationPrediction",
    "RunSettings",
    "ShootingError",
    "SimulationResult",
    "Settling",
    "SimulationState",
    "Sink",
    "StabilityScan",
    "StepControlError",
    "SweepPointError",
    "Well",
    "WellDefinitionError",
    "bifurcation",
    "billiard",
    "chaos",
    "chaos_map",
    "equilibrium_law",
    "measure_relaxation",
    "model_problem",
    "period",
    "predict_relaxation",
    "rqa",
    "run_sweep",
    "scan",
    "settling_periods",
    "simulate",
]


def __getattr__(name: str):
    if name in _VERBS:
        return import_module(f".{name}", __name__)  # binds itself on the package
    if name in _LAZY:
        value = getattr(import_module(f".{_LAZY[name]}", __name__), name)
        globals()[name] = value  # later look-ups skip this function
        return value
    if name == "__version__":
        from importlib.metadata import PackageNotFoundError, version

        try:
            return version("sinktheory")
        except PackageNotFoundError:  # running from a source tree that is not installed
            return "0.1.0"
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *_LAZY, *_VERBS, "__version__"})
