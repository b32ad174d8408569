"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules design,
scenes, report.

Its tables (``overrides``, ``fixed_leaks``, ``HEAVY``, ``RECORDS``,
``PENDING_BY_REASON``) are laid out as tests/_fuzz.py describes.
"""

import functools


@functools.cache
def _design_run():
    """A small design sweep (two designs, a few seconds), run once."""
    from _fuzz import DESIGN

    from sinktheory.design import explore

    return explore(DESIGN, workers=1, progress=False, estimate_first=False)


def overrides() -> dict:
    """Valid keyword arguments of the entry points of this area, by key."""
    import numpy as np
    from _fuzz import Lazy, fig8_sink

    from sinktheory import RunSettings

    one = RunSettings(runs=1, periods=1, seed=1)
    dataset = Lazy(lambda: _design_run().dataset)
    runs = 0.5 * np.abs(np.sin(np.arange(60.0)))[None, :] * np.array([[1.0], [0.9], [0.8]])
    point = {"shape": "flat", "alpha": 0.5, "beta": 0.3, "n": 4, "gamma": 1.0,
             "particles": 1, "mass": 0.2}  # fmt: skip
    s = "sinktheory."
    return {
        s + "design.inelastic_reference.simulate_inelastic_reference": dict(
            sink=fig8_sink(), settings=one, damping=0.5, dt=0.05
        ),
        s + "design.inelastic_reference.solve_damped_ivp": dict(
            sink=fig8_sink(), settings=one, damping=0.5, periods=1
        ),
        s + "design.measures.design_measures": dict(
            energy_runs=runs, horizons=(10, 59), transient=30, bootstrap=10, window=3
        ),
        s + "design.point.equipartition_n": dict(p=point),
        s + "design.ranking.rank": dict(ds=dataset),
        s + "design.report.write_report": dict(
            ds=dataset,
            directory="report",
            ranked=None,
            top=2,
            run=None,
            settling=False,
            predicted=None,
        ),
        s + "scenes.scene": dict(number=7),
        s + "scenes.horizons.horizon": dict(shape="flat", alpha=0.5, beta=0.3, n=4, k=5),
        s + "scenes.base.Claim": dict(
            statement="beta is half the curvature",
            measured="0.6",
            verdict="holds",
            physics="",
        ),
    }


def fixed_leaks() -> list:
    """(call, parameter its ParameterError must name) of each leak fixed in this area."""
    import numpy as np
    from _fuzz import fig8_sink

    from sinktheory import RunSettings
    from sinktheory.design.inelastic_reference import (
        simulate_inelastic_reference,
        solve_damped_ivp,
    )
    from sinktheory.design.measures import design_measures
    from sinktheory.design.point import equipartition_n
    from sinktheory.design.ranking import rank
    from sinktheory.design.report import write_report
    from sinktheory.scenes import estimate, scene
    from sinktheory.scenes.base import Claim
    from sinktheory.scenes.horizons import horizon

    sink, one = fig8_sink(), RunSettings(runs=1, periods=1, seed=1)
    e = 0.5 * np.abs(np.sin(np.arange(60.0)))[None, :] * np.array([[1.0], [0.9], [0.8]])
    measures = dict(e0=0.5, total_energy=0.5, particles=1, n=4, horizons=(10, 59))
    long = RunSettings(runs=2, periods=10**5, seed=1)
    return [
        (lambda: scene("x"), "number"),  # KeyError
        (lambda: estimate(None, True), "number"),  # KeyError
        (lambda: Claim("a claim", "1.0", "maybe"), "verdict"),  # ValueError
        (lambda: horizon("flat", None, 0.3, 4, 5), "alpha"),  # TypeError
        (lambda: equipartition_n(None), "p"),  # TypeError
        (lambda: solve_damped_ivp(sink, one, None, 1), "damping"),  # TypeError
        (lambda: solve_damped_ivp(sink, one, 0.5, 10**4), "periods"),  # ran for hours
        (lambda: simulate_inelastic_reference(sink, long, damping=0.5, dt=0.05), "periods"),
        (lambda: design_measures(e, **measures, seed=None), "seed"),  # TypeError
        (lambda: design_measures(e, **{**measures, "horizons": None}), "horizons"),  # TypeError
        (lambda: design_measures({"a": 1}, **measures), "energy_runs"),  # TypeError
        (lambda: design_measures(e, **measures, bootstrap=10**12), "bootstrap"),
        (lambda: rank(None), "ds"),  # AttributeError
        (lambda: write_report(None, "report"), "ds"),  # AttributeError
    ]


#: Entry points of this area whose calls take seconds: fewer examples.
HEAVY: set[str] = {
    "sinktheory.design.inelastic_reference.solve_damped_ivp",  # 1-1.5 s a period
    "sinktheory.design.report.write_report",
}

#: Records the package returns, by key: what returns each.
RECORDS: dict[str, str] = {
    "sinktheory.design.cost.Estimate": "returned by sinktheory.design.cost.estimate",
    "sinktheory.design.explorer.DesignRun": "returned by sinktheory.design.explorer.explore",
    "sinktheory.design.measures.DesignMeasures": "returned by "
    "sinktheory.design.measures.design_measures",
    "sinktheory.scenes.base.Scene": "returned by sinktheory.scenes.scene",
    "sinktheory.scenes.base.SceneResult": "returned by the build of a Scene "
    "(sinktheory.scenes.scene(number).build)",
}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {}
