"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules plot.

Its tables (``overrides``, ``fixed_leaks``, ``HEAVY``, ``RECORDS``,
``PENDING_BY_REASON``) are laid out as tests/_fuzz.py describes.
"""

import numpy as np

SMALL = {"runs": 2, "periods": 3}


def _sink():
    from sinktheory import Sink
    from sinktheory.canonical import FIG8_WELL

    return Sink(FIG8_WELL, particles=1, mass=0.2)


def _simulation():
    from sinktheory import RunSettings
    from sinktheory.simulate import simulate

    return simulate(_sink(), RunSettings(**SMALL))


def _billiard():
    from sinktheory import RunSettings
    from sinktheory.billiard import billiard

    return billiard("flat", 0.5, 0.3, settings=RunSettings(runs=2, periods=4), lyapunov=True)


def _indicators():
    from sinktheory.chaos import indicators

    q, v = np.array([[0.0], [-0.25]]), np.array([[0.42081], [0.0]])
    return indicators("henon_heiles", q, v, [], dt=0.05, steps=20, segments=40, gali=2)


def _lyapunov_chart():
    from sinktheory import RunSettings
    from sinktheory.billiard.convergence import lyapunov_chart

    return lyapunov_chart(0.5, [-0.3, 0.3], ns=(4,), settings=RunSettings(**SMALL))


def _convergence():
    from sinktheory import RunSettings
    from sinktheory.billiard.convergence import convergence

    return convergence("flat", 0.5, 0.3, ns=(4,), settings=RunSettings(**SMALL))


def _diagram():
    from sinktheory.bifurcation import BifurcationDiagram

    return BifurcationDiagram(np.array([0.1, 0.2]), np.zeros((2, 3)), "y", 0.5, 4, 1.0, "flat",
                              0.2, 0.5, 10, 3)  # fmt: skip


def _comparison():
    from sinktheory.compare.efficiency import Comparison

    e = np.array([0.01, 0.1, 1.0])
    return Comparison(("NES n = 2", "well flat k = 1"), e,
                      np.array([[0.1, 0.5, 0.6], [0.4, 0.5, 0.5]]), np.full((2, 3), 0.02),
                      np.array([[np.nan, 30, 20], [40, 35, np.nan]]), np.full((2, 3), 1.0),
                      np.array([[0, 4, 4], [4, 4, 0]]), np.zeros((2, 3)), [], 0.01, 4, 50, 0,
                      16, 1.0)  # fmt: skip


def _transfer_map():
    from sinktheory.attachments import Attachment
    from sinktheory.compare.transfer import transfer_map

    return transfer_map(Attachment("nes", n=2), 0.05, damping=0.01, periods=30,
                        omega=(0.5, 2.0, 40))  # fmt: skip


def _branch():
    from sinktheory.nnm.continuation import continue_orbits
    from sinktheory.nnm.system import FlowSystem

    b = continue_orbits(FlowSystem("duffing2", []), np.array([0.1, 0.1, 0, 0]), 2 * np.pi,
                        steps=64, total_energy=0.01, interval=(1e-3, 1.0), ds=0.5)  # fmt: skip
    return b.result(label="NNM1")


def _beta_branch():
    from sinktheory.nnm.continuation import continue_both

    return continue_both(
        _sink(),
        mode="container",
        continue_in="beta",
        total_energy=1e-3,
        interval=(0.2, 0.3),
        steps=200,
        points=3,
        ds=0.1,
        half_traces=True,
    )


def _beta_scan():
    from sinktheory.floquet import model_problem, scan

    return scan(model_problem(0.5, 4), 0.2, 0.3, 20)


def _scan():
    from sinktheory.floquet import pure_problem, scan

    return scan(pure_problem(2), -0.5, 3.0, 20)


def _summary():
    from sinktheory.equilibrium import equilibrium_law

    return equilibrium_law(_sink(), 0.5).summary(points=21)


def _ergodicity():
    from sinktheory.equilibrium.ergodicity import ergodicity_map

    return ergodicity_map([0.2, 0.3], alpha=0.5, n=4, runs=2, periods=40, transient=10,
                          lyapunov_runs=0, progress=False)  # fmt: skip


def _prediction():
    from sinktheory.equilibrium.prediction import predict_relaxation

    return predict_relaxation(_sink(), 0.5, shell_energies=4, shell_runs=16, lag=64,
                              resamples=20, seed=1)  # fmt: skip


def _relaxation():
    from sinktheory.equilibrium.relaxation import measure_relaxation

    runs = 0.3 + 0.2 * np.exp(-np.arange(400.0) / 50)[None, :] * np.array([[1.0], [0.9], [0.8]])
    return measure_relaxation(runs, 0.3, window=5, resamples=20)


def _user_well():
    from sinktheory.model import user_well_summary
    from sinktheory.userwell import UserWell, check_well

    hh = UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})
    return user_well_summary(hh, 0.1), check_well(hh).basin.well.f


def overrides() -> dict:
    """Valid keyword arguments of the entry points of this area, by key."""
    from _fuzz import Lazy

    s = "sinktheory.plot."
    scan, beta_branch, beta_scan = Lazy(_scan), Lazy(_beta_branch), Lazy(_beta_scan)
    comparison = Lazy(_comparison)
    return {
        s + "bifurcation.plot_bifurcation": dict(diagram=Lazy(_diagram), unstable=[(0.1, 0.15)]),
        s + "billiard.billiard_figure": dict(result=Lazy(_billiard)),
        s + "chaos.convergence_figure": dict(result=Lazy(_indicators), window=10),
        s + "chaos.plot_convergence": dict(result=Lazy(_indicators), path="convergence.png"),
        s + "compare.plot_comparison": dict(comparison=comparison),
        s + "compare.plot_efficiency": dict(comparison=comparison),
        s + "compare.plot_t90": dict(comparison=comparison),
        s + "compare.plot_transfer": dict(maps=Lazy(lambda: [_transfer_map()]),
                                          backbones=Lazy(lambda: [[_branch()]])),
        s + "convergence.convergence_figure": dict(result=Lazy(_convergence)),
        s + "convergence.lyapunov_figure": dict(chart=Lazy(_lyapunov_chart)),
        s + "equilibrium.plot_ergodicity": dict(result=Lazy(_ergodicity)),
        s + "equilibrium.plot_law": dict(summary=Lazy(_summary)),
        s + "equilibrium.plot_lifetimes": dict(fractions=[0.2, 0.5], particles=[1, 2],
                                               predicted=[[2.0, 5.0], [4.0, 30.0]],
                                               measured=[(1, 0.5, 5.2, 0.3)]),
        s + "equilibrium.plot_relaxation": dict(prediction=Lazy(_prediction),
                                                measured=Lazy(_relaxation)),
        s + "floquet.plot_scan": dict(result=scan),
        s + "floquet.plot_tongues": dict(ns=[1, 2], lo=-0.5, hi=3.0, count=20),
        s + "nnm.plot_frequency_energy": dict(results=Lazy(lambda: [_branch()])),
        s + "nnm.plot_nnm": dict(results=Lazy(lambda: [_branch()]), beta_result=beta_branch,
                                 scan=beta_scan),
        s + "nnm.plot_transverse": dict(result=beta_branch, scan=beta_scan,
                                        chaos=([0.2, 0.3], [0.01, 0.02], "lambda_1")),
        s + "simulate.plot_ensemble_energy": dict(result=Lazy(_simulation), sink=_sink()),
        s + "well.plot_user_well": dict(summary=Lazy(lambda: _user_well()[0]),
                                        potential=Lazy(lambda: _user_well()[1]), points=41),
    }  # fmt: skip


def fixed_leaks() -> list:
    """(call, parameter it must name) of each leak fixed in this area."""
    from sinktheory.plot.bifurcation import plot_bifurcation
    from sinktheory.plot.compare import plot_comparison
    from sinktheory.plot.equilibrium import plot_lifetimes
    from sinktheory.plot.floquet import plot_tongues
    from sinktheory.plot.nnm import plot_frequency_energy
    from sinktheory.plot.simulate import plot_ensemble_energy

    lifetimes = dict(fractions=[0.2, 0.5], particles=[1, 2])
    return [
        (lambda: plot_ensemble_energy(None, _sink()), "result"),  # AttributeError
        (lambda: plot_comparison(None), "comparison"),  # AttributeError
        (lambda: plot_bifurcation(_diagram(), unstable=5), "unstable"),  # TypeError
        (lambda: plot_tongues(5, -0.5, 3.0), "ns"),  # TypeError
        (lambda: plot_lifetimes(**lifetimes, predicted=[[2.0]]), "predicted"),  # IndexError
        (lambda: plot_frequency_energy([_branch()], stability="x"), "stability"),  # AttributeError
    ]


#: Entry points of this area whose calls take seconds: fewer examples.
HEAVY = {"sinktheory.plot.chaos.plot_convergence"}  # saves a PNG: about 1 s

#: Records the package returns, by key: what returns each.
RECORDS: dict[str, str] = {}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {}
