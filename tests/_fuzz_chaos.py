"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules chaos, nnm.

Its tables (``overrides``, ``fixed_leaks``, ``HEAVY``, ``RECORDS``,
``PENDING_BY_REASON``) are laid out as tests/_fuzz.py describes.
"""

import functools


def overrides() -> dict:
    """Valid keyword arguments of the entry points of this area, by key."""
    from _fuzz import Lazy, fig8_sink

    from sinktheory import RunSettings, Sink, Well
    from sinktheory.nnm.system import FlowSystem

    sink = Sink(Well(0.5, -0.2, 4), particles=1, mass=0.2)
    betas = [-0.25, -0.2]
    chaos_map, orbit = Lazy(lambda: _chaos_map(betas)), Lazy(lambda: _coupled_mode(sink))
    chart = Lazy(lambda: _chart(sink, betas, orbit.value()))
    s = "sinktheory."
    return {
        s + "chaos.sink.chaos_batch": dict(
            sinks=[fig8_sink(), Sink(Well(0.5, 0.1, 4), particles=1, mass=0.2)],
            settings=[RunSettings(runs=2, periods=2, seed=s) for s in (1, 2)],
            dt=0.05,
            progress=False,
        ),
        s + "chaos.verdicts.verdicts": dict(ds=chaos_map),
        s + "chaos.verdicts.map_calls": dict(ds=chaos_map),
        s + "chaos.verdicts.agreement": dict(ds=chaos_map, stable=[True, False]),
        s + "nnm.agreement.transverse_chart": dict(
            sink=sink, total_energy=0.5, betas=betas, start=orbit, steps=100
        ),
        s + "nnm.agreement.agreement_report": dict(
            sink=sink,
            total_energy=0.5,
            betas=betas,
            chaos=chaos_map,
            chart=chart,
            runs=2,
            periods=20,
            dt=0.05,
            seed=0,
            workers=1,
            steps=100,
        ),  # fmt: skip
        s + "nnm.backbone.localisation_energy": dict(backbone=Lazy(_backbone)),
        s + "nnm.continuation.switch_branch": dict(
            branch=Lazy(_y_axis_branch),
            event=Lazy(lambda: _y_axis_branch().events[0]),
            max_points=2,
            interval=(0.1, 0.16),
            amplitude=1e-2,
            ds=0.05,
        ),  # fmt: skip
        s + "nnm.modes.linear_modes": dict(system=FlowSystem("duffing2", [])),
    }


def _chaos_map(betas):
    """A small chaos map (two betas, two runs of 20 periods)."""
    from sinktheory.sweep.chaosmap import chaos_map

    return chaos_map(0.5, 4, betas, runs=2, periods=20, dt=0.05, workers=1)


def _coupled_mode(sink):
    from sinktheory.nnm.agreement import reach_energy

    return reach_energy(sink, 0.5)


def _chart(sink, betas, orbit):
    from sinktheory.nnm.agreement import transverse_chart

    return transverse_chart(sink, 0.5, betas, start=orbit, steps=100)


@functools.cache
def _backbone():
    """A short piece of the cubic NES's in-phase backbone (7 points)."""
    from sinktheory import Sink, Well
    from sinktheory.nnm.backbone import inphase_backbone

    sink = Sink(Well(0.5, 0.3, 2), particles=1, mass=0.2)
    return inphase_backbone(sink, 2e-5, 1e-4, steps=100, points=40)


@functools.cache
def _y_axis_branch():
    """The Henon-Heiles y-axis orbits up to their period doubling (one event)."""
    import math

    import numpy as np

    from sinktheory.canonical import HENON_HEILES
    from sinktheory.nnm.continuation import continue_orbits
    from sinktheory.nnm.system import FlowSystem

    return continue_orbits(FlowSystem(HENON_HEILES, []), np.array([0, 0.1, 0, 0]), 2 * math.pi,
                           steps=64, interval=(1e-3, 0.15), ds=0.1, phase_index=1)  # fmt: skip


def fixed_leaks() -> list:
    """(call, parameter its ParameterError must name) of each leak fixed in this area."""
    from sinktheory import RunSettings, Sink, Well
    from sinktheory.chaos import chaos_batch
    from sinktheory.chaos.verdicts import agreement, map_calls, verdicts
    from sinktheory.nnm.agreement import agreement_report, transverse_chart
    from sinktheory.nnm.backbone import localisation_energy
    from sinktheory.nnm.modes import linear_modes

    sink, ds = Sink(Well(0.5, -0.2, 4), particles=1, mass=0.2), _tiny_map()
    one = [RunSettings(runs=2, periods=2)]
    return [
        (lambda: chaos_batch(None, one, dt=0.05), "sinks"),  # TypeError
        (lambda: chaos_batch([sink], 1.0, dt=0.05), "settings"),  # TypeError
        (lambda: verdicts(None), "ds"),  # AttributeError
        (lambda: map_calls(ds.drop_vars("lambda1_runs")), "ds"),  # AttributeError
        (lambda: agreement(ds, None), "stable"),  # IndexError
        (lambda: agreement(ds, [1.0, 2.0]), "stable"),  # read as True, True
        (lambda: linear_modes("duffing2"), "system"),  # AttributeError
        (lambda: localisation_energy(None), "backbone"),  # AttributeError
        (lambda: localisation_energy(_backbone(), 1e-300), "share"),  # NaN returned
        (lambda: transverse_chart(None, 0.5, [0.1]), "sink"),  # AttributeError
        (lambda: transverse_chart(sink, 0.5, "x"), "betas"),  # ValueError
        (lambda: transverse_chart(sink, 0.5, [-0.2], start=1.0), "start"),  # AttributeError
        (lambda: agreement_report(sink, 0.5, [-0.2], chaos={"a": 1}), "chaos"),  # Attribute
        (lambda: agreement_report(sink, 0.5, [-0.2], chaos=ds, chart=1), "chart"),
        (lambda: agreement_report(sink, 0.5, [-0.2], chaos=ds, runs=None), "runs"),  # unused
    ]


def _tiny_map():
    """A chaos map's variables written out (two betas, two runs; no integration)."""
    import xarray as xr

    runs = [[0.30, 0.32], [0.001, 0.4]]
    return xr.Dataset(
        {"lambda1": ("beta", [0.31, 0.2]), "lambda1_se": ("beta", [0.01, 0.2]),
         "lambda1_runs": (("beta", "run"), runs), "lambda1_periods": ("beta", [200.0, 200.0])},
        coords={"beta": [-0.25, -0.2], "run": [0, 1]}, attrs={"periods": 200},
    )  # fmt: skip


#: Entry points of this area whose calls take seconds: fewer examples.
HEAVY: set[str] = {
    "sinktheory.nnm.agreement.agreement_report",
    "sinktheory.nnm.agreement.transverse_chart",
}

#: Records the package returns, by key: what returns each.
RECORDS: dict[str, str] = {
    "sinktheory.chaos.result.ChaosResult": "returned by chaos.chaos, chaos_batch, indicators",
    "sinktheory.chaos.staged.StagedExponent": "returned by chaos.staged.staged_chaos",
    "sinktheory.chaos.verdicts.Split": "returned by chaos.verdicts.split",
    "sinktheory.nnm.agreement.TransverseChart": "returned by nnm.agreement.transverse_chart",
    "sinktheory.nnm.continuation.Branch": "returned by nnm.continuation.continue_orbits",
    "sinktheory.nnm.continuation.Event": "in the events of nnm.continuation.continue_orbits",
    "sinktheory.nnm.result.BranchResult": "returned by nnm.continuation.continue_both",
    "sinktheory.nnm.shooting.Orbit": "returned by nnm.shooting.shoot",
    "sinktheory.nnm.stability.Floquet": "returned by nnm.stability.floquet",
}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {}
