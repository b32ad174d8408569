"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules engine,
codegen, symbolic, twins, integrators, adaptive, stepsize, hill, series, oscillator.

Its tables (``overrides``, ``fixed_leaks``, ``HEAVY``, ``RECORDS``,
``PENDING_BY_REASON``) are laid out as tests/_fuzz.py describes.
"""


def overrides() -> dict:
    """Valid keyword arguments of the entry points of this area, by key."""
    from sinktheory import symbolic as S
    from sinktheory.userwell import UserWell

    bowl = UserWell("bowl", "k*(x**2 + y**2)/2", {"k": 2})
    s = "sinktheory."
    return {
        s + "engine.cache.well_name": dict(well=bowl),
        s + "integrators.SplittingScheme": dict(
            name="leapfrog", order=2, a=(1.0,), b=(0.5, 0.5), reference="by hand"
        ),
        s + "symbolic.ladder": dict(well=bowl, values=bowl.values()),
        s + "symbolic.mechanics": dict(k=1),
        s + "symbolic.substitute_ratios": dict(expr=S.s1**2 + S.s2, shape="flat"),
    }


def fixed_leaks() -> list:
    """(call, parameter its ParameterError must name) of each leak fixed in this area."""
    import numpy as np

    from sinktheory import symbolic as S
    from sinktheory.engine.cache import well_name
    from sinktheory.engine.core import Ensemble
    from sinktheory.integrators import SplittingScheme

    def hh():
        return Ensemble("henon_heiles", np.array([[0.0], [0.1]]), np.array([[0.3], [0.0]]), [])

    return [
        (lambda: S.denominator(None), "s"),  # TypeError
        (lambda: S.denominator(3 + 1j), "s"),  # a complex D(s) returned
        (lambda: S.ladder(None), "well"),  # its ParameterError named shape
        (lambda: S.ladder("flat", True), "values"),  # TypeError
        (lambda: S.normal_mode("flat", {"a": 1}), "values"),  # unknown parameter ignored
        (lambda: S.substitute_ratios(None, "flat"), "expr"),  # AttributeError
        (lambda: well_name(None), "well"),  # AttributeError
        # accepted: Ensemble.run read past b (energy error 0.72 in 200 steps, no error)
        (lambda: SplittingScheme("leapfrog", 2, (1.0,), (0.5,), "by hand"), "b"),
        (lambda: hh().run("verlet", dt=0.01, steps=1, segments=1), "scheme"),  # AttributeError
    ]


#: Entry points of this area whose calls take seconds: fewer examples.
HEAVY: set[str] = set()

#: Records the package returns, by key: what returns each.
RECORDS: dict[str, str] = {
    "sinktheory.engine.blocks.BlockPlan": "returned by engine.core.Ensemble.plan",
    "sinktheory.engine.core.Records": "returned by engine.core.Ensemble.run",
    "sinktheory.engine.systems.Damping": "part of the system engine.systems.sink_system "
    "builds for a sink's engine (not user input: engines are named, engine.cache)",
    "sinktheory.engine.systems.SeparableSystem": "returned by engine.systems.henon_heiles, "
    "two_dof_duffing (not user input: the chaos tools take engine names)",
    "sinktheory.engine.systems.Term": "part of the SeparableSystem engine.systems."
    "henon_heiles returns (its shared_terms)",
    "sinktheory.hill.QuarterPeriod": "returned by hill.integrate_quarter_period",
    "sinktheory.oscillator.Oscillator": "returned by oscillator.oscillator",
    "sinktheory.series.BoundCheck": "returned by series.check_bounds",
    "sinktheory.series.SeriesAccuracy": "returned by series.accuracy",
    "sinktheory.series.SeriesError": "returned by series.error_table",
    "sinktheory.series.TriangleSeries": "returned by series.triangle_series",
    "sinktheory.stepsize.StepChoice": "returned by stepsize.choose",
    "sinktheory.symbolic.AtomForm": "returned by symbolic.kernel_form",
    "sinktheory.symbolic.Mechanics": "returned by symbolic.mechanics",
    "sinktheory.symbolic.NormalMode": "returned by symbolic.normal_mode",
    "sinktheory.symbolic.RescaledSystem": "returned by symbolic.rescaled_equations",
    "sinktheory.symbolic.SeparableHamiltonian": "returned by symbolic.separable_hamiltonian",
    "sinktheory.symbolic.Shape": "returned by symbolic.shape_definition (the SHAPES registry)",
    "sinktheory.symbolic.WellLadder": "returned by symbolic.ladder",
}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {}
