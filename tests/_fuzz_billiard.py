"""The API fuzz's tables (issue 34, item 5; see tests/_fuzz.py) for the modules billiard,
vibroimpact, attachments, damped, compare.

Its tables (``overrides``, ``fixed_leaks``, ``HEAVY``, ``RECORDS``,
``PENDING_BY_REASON``) are laid out as tests/_fuzz.py describes.
"""


def overrides() -> dict:
    """Valid keyword arguments of the entry points of this area, by key."""
    import math

    import sympy as sp

    from sinktheory import RunSettings
    from sinktheory.billiard.table import Piece, rigid_table

    small = RunSettings(runs=2, periods=2, seed=1)
    s = sp.Symbol("s")
    square = [Piece(a, g, sp.Integer(1) + 0 * s, -1, 1) for a in "xy" for g in (1, -1)]
    x, y = sp.symbols("x y", real=True)
    b = "sinktheory.billiard."
    return {
        b + "table.Piece": dict(axis="x", sign=1, expr=sp.sqrt(1 - s**2), lo=-1.0, hi=1.0,
                                hole=False),
        b + "table.polynomial_table": dict(name="square", walls=[1 - x**2, 1 - y**2],
                                           pieces=square, parameters=None, symbol=s),
        b + "impact.velocities_after": dict(impulse=sp.Symbol("J", real=True)),
        b + "run.start_directions": dict(settings=small, particles=2),
        b + "convergence.measure": dict(shape="flat", alpha=0.5, beta=0.3, n=math.inf,
                                        settings=small, transient=1),
        b + "convergence.convergence": dict(shape="flat", alpha=0.5, beta=0.3, ns=(4,),
                                            settings=small, transient=1),
        b + "convergence.lyapunov_chart": dict(alpha=0.5, betas=[0.3], ns=(4,),
                                               settings=small, transient=1),
        b + "convergence.power_rate": dict(ns=[10, 20, 40], means=[1.1, 1.05, 1.025],
                                           ses=[1e-3, 1e-3, 0.1], limit=1.0, limit_se=1e-3,
                                           n_min=1),
        b + "kinetic.kinetic_coefficients": dict(table=rigid_table("flat", 0.5, 0.3),
                                                 particles=2, mass=0.2, total_energy=0.5,
                                                 container_energies=[0.1, 0.25]),
        b + "relaxation.measure_rigid_settling": dict(shape="flat", alpha=0.5, beta=0.3,
                                                      measure=(4, 40), resamples=20),
        b + "relaxation.predict_rigid_relaxation": dict(
            shape="flat", alpha=0.5, beta=0.3, shell_energies=3, shell_runs=4, lag=8,
            resamples=20),
        b + "relaxation.rigid_shell_increments": dict(
            table=rigid_table("flat", 0.5, 0.3), particles=1, mass=0.2, total_energy=0.5,
            points=3, runs=4, lags=(1, 2), seed=0),
    }  # fmt: skip


def fixed_leaks() -> list:
    """(call, parameter its ParameterError must name) of each leak fixed in this area."""
    import sympy as sp

    from sinktheory import RunSettings
    from sinktheory.billiard.convergence import convergence, lyapunov_chart, measure, power_rate
    from sinktheory.billiard.impact import velocities_after
    from sinktheory.billiard.kinetic import kinetic_coefficients
    from sinktheory.billiard.relaxation import (
        measure_rigid_settling,
        predict_rigid_relaxation,
        rigid_shell_increments,
    )
    from sinktheory.billiard.run import start_directions
    from sinktheory.billiard.table import Piece, polynomial_table, rigid_table, stadium_table

    s, flat = sp.Symbol("s"), rigid_table("flat", 0.5, 0.3)
    square = [Piece(a, g, sp.Integer(1) + 0 * s, -1, 1) for a in "xy" for g in (1, -1)]
    x, y = sp.symbols("x y", real=True)
    disk = [Piece("x", g, sp.sqrt(1 - s**2), -1, 1) for g in (1, -1)]
    rate = ([10, 20, 40], [1.1, 1.05, 1.025], [1e-3] * 3)
    small = RunSettings(runs=2, periods=2)
    return [
        (lambda: Piece("x", 1, sp.Integer(1), -1.0, float("nan")), "hi"),  # NaN kept
        (lambda: Piece("x", 1, float("inf"), -1.0, 1.0), "expr"),  # inf kept
        (lambda: polynomial_table("sq", [1 - x**2, 4 - y**2], square, symbol=s), "walls"),
        (lambda: polynomial_table("sq", [[5.0, 5.0]], square, symbol=s), "walls"),  # Attribute
        (lambda: polynomial_table("disk", [1 - x**2 - y**2], disk, symbol=x), "symbol"),  # Name
        (lambda: velocities_after(None), "impulse"),  # TypeError
        (lambda: stadium_table(1e308, 1.0), "half_length"),  # overflow warnings, quad error
        (lambda: start_directions(None, 2), "settings"),  # AttributeError
        (lambda: start_directions(small, 10**12), "particles"),  # MemoryError
        (lambda: power_rate(*rate, None, 1e-3), "limit"),  # TypeError
        (lambda: power_rate([10, 20], *[r[:3] for r in rate[1:]], 1.0, 0.0), "means"),
        (lambda: kinetic_coefficients(flat, 1, 0.2, 0.5, "x"), "container_energies"),
        (lambda: kinetic_coefficients(flat, 1e308, 0.2, 0.5, [0.1]), "particles"),  # Overflow
        (lambda: kinetic_coefficients(flat, 1, 0.2, 1e308, [0.1]), "total_energy"),  # inf
        (lambda: rigid_shell_increments(flat, 1, 0.2, 0.5, 3, 4, 2, 0), "lags"),  # TypeError
        (lambda: rigid_shell_increments(flat, 1, 0.2, 0.5, 3, 4, (1, 2), -1), "seed"),
        (lambda: measure("flat", 0.5, 0.3, 4, settings=1), "settings"),  # AttributeError
        (lambda: lyapunov_chart(0.5, [0.3], ns=(4, 4), settings=small), "ns"),  # LinAlgError
        (lambda: convergence("flat", 2.5, 0.3, ns=(4,), settings=small), "settings"),  # inf
        (lambda: predict_rigid_relaxation("flat", 0.5, 0.3, resamples=10**12), "resamples"),
        (lambda: predict_rigid_relaxation("flat", 0.5, 0.3, periods=1e308), "periods"),  # Ufunc
        (
            lambda: measure_rigid_settling("flat", 0.5, 0.3, (3, 24), container_energy=1e-300),
            "measure",
        ),  # NaN z-score (no impact in any run)
    ]


#: Entry points of this area whose calls take seconds: fewer examples.
HEAVY: set[str] = {
    "sinktheory.billiard.convergence.convergence",
    "sinktheory.billiard.convergence.lyapunov_chart",
    "sinktheory.billiard.relaxation.measure_rigid_settling",
    "sinktheory.billiard.relaxation.rigid_shell_increments",
}

_R = "sinktheory."
#: Records the package returns, by key: what returns each.
RECORDS: dict[str, str] = {
    _R + "attachments.ImpulseResponse": "returned by attachments.impulse_response",
    _R + "billiard.convergence.Convergence": "returned by billiard.convergence.convergence",
    _R + "billiard.convergence.LyapunovChart": "returned by billiard.convergence.lyapunov_chart",
    _R + "billiard.convergence.Measurement": "returned by billiard.convergence.measure",
    _R + "billiard.run.BilliardResult": "returned by billiard.billiard, simulate_billiard",
    _R + "billiard.run.RigidLimit": "returned by billiard.rigid_limit",
    _R + "billiard.table.Table": "returned by billiard.rigid_table, well_table, sinai_table, "
    "stadium_table, polynomial_table (users build tables with these)",
    _R + "compare.efficiency.Comparison": "returned by compare.efficiency.compare",
    _R + "compare.transfer.TransferMap": "returned by compare.transfer.transfer_map",
    _R + "compare.wavelet.WaveletMap": "returned by compare.wavelet.wavelet_map",
    _R + "damped.InelasticResult": "returned by damped.simulate_inelastic",
    _R + "vibroimpact.VibroImpactResult": "returned by vibroimpact.simulate_vibroimpact",
}

#: Entry points not fuzzed yet, by why.
PENDING_BY_REASON: dict[str, tuple] = {}
