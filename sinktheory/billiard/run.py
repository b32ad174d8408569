"""Ensembles of rigid billiards: the n -> oo limit of the sink, fixed or moving container.

Units as everywhere in the package: container mass 1 on a spring of stiffness 1, period
T = 2 pi; particles of mass mu = m / k.  Positions are relative to the container,
velocities absolute (as in :mod:`sinktheory.layout`).

* Moving container (the sink): the container starts at X = sqrt(2 E0) at rest and the
  particles at rest at the seeded random positions of
  :func:`sinktheory.ensemble.random_positions`, exactly as ``sinktheory simulate`` starts
  its runs, but with rigid walls.  lambda_1 by two nearby trajectories (distance
  :data:`SHADOW_DISTANCE` in the full phase space, pulled back :data:`RENORMALISATIONS`
  times a period).
* Fixed container: the table does not move; each particle starts at the same positions
  with energy E0 / k in a seeded random direction.  lambda_1 by the billiard tangent map
  (exact linearisation of flights and reflections, renormalised every period).

Exponents are per unit time; the per-collision exponent is also given.  Tables with
islands (the flat table with focusing walls, beta < 0, fixed container) give regular and
chaotic runs side by side: :meth:`BilliardResult.split` reports the two groups (the rule
of :func:`sinktheory.chaos.verdicts.split`) and the start distribution that set their
proportion.

Examples
--------
>>> from sinktheory.model import RunSettings
>>> r = billiard("flat", 0.5, 0.3, particles=2, settings=RunSettings(runs=2, periods=3))
>>> r.max_relative_energy_error < 1e-13, r.container_energy.shape
(True, (2, 4))
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any, ClassVar

import numpy as np

from ..chaos.verdicts import Split, split
from ..ensemble import random_positions
from ..errors import BracketError, EnergyDriftError, ParameterError
from ..model import MAX_PERIODS, SECONDS_PER_PARTICLE_STEP, RunSettings, Sink, Well
from ..progress import chunks
from ..results import Result
from ..runstats import mean_stderr
from ..userwell import parameter_values
from ..validation import fits_memory, flag, positive, positive_int, real_array
from ..worklimit import check_particle_steps
from . import kernels as K
from .table import Table, rigid_table, well_table

__all__ = [
    "billiard",
    "BILLIARD_SECONDS",
    "BilliardResult",
    "ENERGY_BOUND",
    "PERIOD",
    "RENORMALISATIONS",
    "rigid_limit",
    "RigidLimit",
    "SHADOW_DISTANCE",
    "simulate_billiard",
    "start_directions",
    "well_billiard",
]

#: Relative total-energy error above which a run is reported as broken (the engine is
#: exact up to rounding: flights in closed form, impacts conserving energy exactly).
ENERGY_BOUND = 1e-10
#: Initial distance of the shadow trajectory (two-trajectory lambda_1, moving container).
SHADOW_DISTANCE = 1e-9
#: Renormalisations of the shadow trajectory per period: with lambda_1 up to ~5 per unit
#: time the pair separates by at most e^(5 T / 32) ~ 3 between them, so the two
#: trajectories' impacts stay within ~1e-8 time units of each other.
RENORMALISATIONS = 32
#: Smallest E0 of the moving container's lambda_1: the shadow trajectory must start close
#: next to the motion, SHADOW_DISTANCE <= 1e-3 x the container's amplitude sqrt(2 E0).
MIN_SHADOW_ENERGY = 0.5 * (1e3 * SHADOW_DISTANCE) ** 2
PERIOD = 2 * math.pi
#: Seconds of the engine's work in the estimate (:func:`flight_seconds`): per particle and
#: period, per expected collision (:func:`expected_collisions`) of a fixed container's
#: particle, and of a moving one's: ("moving" + "per_particle" x k, as an impact ends the
#: flight of every particle) x (1 + 3 / (1 + A / mean free path)), A = sqrt(2 E) the
#: largest amplitude of the container: when A dwarfs the table the particles ride with it
#: and collide far less often than their speed says (75 collisions a period at E0 = 5e3
#: against 2300 expected), while the search still steps through the container's motion.
#: benchmarks/bench_billiard_estimate.py (flat table 0.5, 0.3; E0 = 1e-6 .. 5e9; k = 1 and
#: 5; 2 runs; 2-core AVX-512 Xeon, load 4.5-6.2, 2026-11-26; two runs of it) measured per
#: expected collision: fixed 1.9-4.2e-6 s at every E0 from 1e-3 up; moving 1.9-2.4e-6 s
#: (k = 1) and 4.2e-6 s (k = 5) at E0 = 0.5, 0.8-1.3e-6 and 2.1-2.2e-6 s at E0 = 50,
#: 0.64-0.86e-6 and 1.0-1.6e-6 s from E0 = 5e3 up; and 0.6-1.4e-6 s per particle and
#: period at E0 = 1e-6 (almost no collision).  With these prices a run of the script at
#: load 8.9 (same day) timed the work at 0.48-0.71 of the estimate for a fixed container,
#: 0.30-0.83 for a moving one (0.18 at k = 5, E0 = 1e-3, where the expected collisions do
#: not happen and a period takes 1e-5 s); ``billiard --runs 2`` at the default E0 0.57
#: (fixed) and 0.81 (moving) in benchmarks/bench_estimates.py at load 9.4.
BILLIARD_SECONDS = {"period": 1.5e-6, "collision": 5e-6, "moving": 1e-6, "per_particle": 0.4e-6}


def _stats(values: np.ndarray) -> dict[str, float]:
    """Mean and standard error over the runs (:func:`sinktheory.runstats.mean_stderr`);
    NaN (JSON null) when a run's value is not finite (a run without impacts has no mean
    free time)."""
    v = np.asarray(values, dtype=float)
    if not np.all(np.isfinite(v)):
        return {"mean": math.nan, "stderr": math.nan}
    mean, se = mean_stderr(v)
    return {"mean": mean, "stderr": se}


@dataclass(frozen=True)
class BilliardResult(Result):
    """An ensemble of rigid-billiard runs (module docstring).

    Attributes
    ----------
    table : the :class:`~sinktheory.billiard.table.Table`
    fixed : True for a fixed container
    particles, mu : k and the mass of one particle
    times : (P + 1,) t = j T
    container_energy : (R, P + 1) (X'^2 + X^2)/2 at t = j T (zeros if fixed)
    total_energy : (R, P + 1) container plus particles
    collisions : (R, walls) impacts on each wall function
    logs : (R, P + 1) accumulated log growth of the separation (None without Lyapunov)
    lyapunov_method : "tangent map", "two trajectories" or ""
    """

    DIMS: ClassVar = {
        "container_energy": ("run", "time"),
        "total_energy": ("run", "time"),
        "collisions": ("run", "wall"),
        "logs": ("run", "time"),
        "lambda1": ("run",),
        "lambda1_per_collision": ("run",),
        "mean_free_time": ("run",),
    }
    COORDS: ClassVar = {"times": "time"}

    table: Table
    fixed: bool
    particles: int
    mu: float
    times: np.ndarray
    container_energy: np.ndarray
    total_energy: np.ndarray
    collisions: np.ndarray
    logs: np.ndarray | None
    lyapunov_method: str
    parameters: dict

    @property
    def duration(self) -> float:
        return float(self.times[-1])

    @property
    def max_relative_energy_error(self) -> float:
        e0 = self.total_energy[:, :1]
        return float(np.max(np.abs(self.total_energy - e0) / e0))

    @property
    def mean_free_time(self) -> np.ndarray:
        """(R,) time between a particle's impacts: k t / (impacts of all particles); inf
        for a run without impacts (a table far larger than the motion, or E0 so small that
        nothing reaches a wall within the run)."""
        hits = self.collisions.sum(axis=1).astype(float)
        out = np.full(hits.shape, math.inf)
        np.divide(self.particles * self.duration, hits, out=out, where=hits > 0)
        return out

    @property
    def lambda1(self) -> np.ndarray | None:
        """(R,) largest Lyapunov exponent per unit time."""
        return None if self.logs is None else self.logs[:, -1] / self.duration

    @property
    def lambda1_per_collision(self) -> np.ndarray | None:
        """(R,) the same per impact of a particle: lambda_1 x mean free time (NaN for a run
        without impacts)."""
        if self.logs is None:
            return None
        mft = self.mean_free_time
        out = np.full(mft.shape, math.nan)
        np.multiply(self.lambda1, mft, out=out, where=np.isfinite(mft))
        return out

    @property
    def starts(self) -> str:
        """The start distribution, in words (from :func:`billiard`'s parameters)."""
        p = self.parameters
        if "box" not in p:
            return "start states given to simulate_billiard"
        where = f"uniform in (-{p['box']:g}, {p['box']:g})^2 around the centre"
        if self.fixed:
            return f"particles {where}, energy E0/k each in seeded random directions"
        return f"particles at rest {where}; container at X = sqrt(2 E0) at rest"

    def split(self) -> Split | None:
        """lambda_1 split into regular and chaotic runs (None without lambda_1)."""
        if self.logs is None:
            return None
        return split(self.lambda1, self.duration / PERIOD, self.starts)

    def items(self) -> dict[str, Any]:
        out = super().items()
        out["max_relative_energy_error"] = self.max_relative_energy_error
        out["mean_free_time"] = self.mean_free_time
        out["mean_mean_free_time"] = _stats(self.mean_free_time)
        if self.logs is not None:
            out["lambda1"] = self.lambda1
            out["lambda1_per_collision"] = self.lambda1_per_collision
            out["mean_lambda1"] = _stats(self.lambda1)
            out["mean_lambda1_per_collision"] = _stats(self.lambda1_per_collision)
            out["split_lambda1"] = self.split().as_dict()
        return out


def _table_arrays(table: Table) -> tuple:
    return (table.kinds, table.coef, table.cap, table.hneg, table.gx, table.eps, table.reach)


def _raise_status(status, where, what: str) -> None:
    bad = np.nonzero(status)[0]
    if len(bad):
        r = int(bad[0])
        raise BracketError(
            f"{what}: run {r}, particle {int(where[r, 0])}, t = {where[r, 1]:.17g}: a flight "
            f"took over {K.MAX_ITERATIONS} safe steps without reaching a wall, or over "
            f"{K.MAX_REPEATS} impacts came at one instant"
        )


def _outputs(R: int, walls: int, periods: int, records: int) -> tuple:
    """The arrays a kernel fills (:func:`kernels.run_fixed`, :func:`kernels.run_moving`):
    ``records`` records (R, periods + 1), hits (R, walls), status (R,), where (R, 2)."""
    rec = (np.zeros((R, periods + 1)) for _ in range(records))
    return (*rec, np.zeros((R, walls), dtype=np.int64), np.zeros(R, dtype=np.int64),
            np.zeros((R, 2)))  # fmt: skip


def _collisions_per_period(table: Table, vel: np.ndarray, mu: float, cont) -> np.ndarray:
    """Each run's expected collisions per period (:func:`expected_collisions`)."""
    if cont is None:
        speed = np.sqrt((vel**2).sum(axis=-1)).sum(axis=-1)
    else:
        k = vel.shape[1]
        speed = k * np.sqrt(2.0 * _energies(vel, mu, cont) / (k * mu))
    return PERIOD * speed / table.mean_free_path


def _energies(vel: np.ndarray, mu: float, cont: np.ndarray) -> np.ndarray:
    return 0.5 * (cont**2).sum(axis=-1) + 0.5 * mu * (vel**2).sum(axis=(1, 2))


def expected_collisions(table: Table, velocities, mu: float, container, periods: int) -> float:
    """The collisions ``periods`` periods of the runs are expected to have, for the work
    estimate: a particle of speed v crosses the table's mean free path (Santalo's
    pi A / perimeter) every mean_free_path / v.  Fixed container: each particle keeps its
    speed |v|.  Moving container: the energy E = (X^2 + X'^2) / 2 + mu sum |v|^2 / 2 is
    conserved, and each of the k particles is counted at the speed sqrt(2 E / (k mu)) it
    has when they share E evenly.

    Examples
    --------
    >>> from sinktheory.billiard.table import stadium_table
    >>> t = stadium_table(1, 1)
    >>> expected_collisions(t, [[[3.0, 4.0]]], 1.0, None, 2) == 2 * PERIOD * 5 / t.mean_free_path
    True
    """
    vel = np.asarray(velocities, dtype=float)
    cont = None if container is None else np.asarray(container, dtype=float)
    return periods * float(_collisions_per_period(table, vel, mu, cont).sum())


def flight_seconds(table: Table, velocities, mu: float, container, periods: int) -> float:
    """Estimated seconds of ``periods`` periods of the runs: every particle's periods and
    the :func:`expected_collisions` at :data:`BILLIARD_SECONDS`.

    Examples
    --------
    >>> from sinktheory.billiard.table import stadium_table
    >>> t, cost = stadium_table(1, 1), BILLIARD_SECONDS
    >>> seconds = 2 * cost["period"] + 10 * PERIOD / t.mean_free_path * cost["collision"]
    >>> bool(np.isclose(flight_seconds(t, [[[3.0, 4.0]]], 1.0, None, 2), seconds, rtol=1e-14))
    True
    """
    vel = np.asarray(velocities, dtype=float)
    R, k = vel.shape[:2]
    cost = BILLIARD_SECONDS
    if container is None:
        price = cost["collision"]
        cont = None
    else:  # each run at its own energy
        cont = np.asarray(container, dtype=float)
        amplitude = np.sqrt(2.0 * _energies(vel, mu, cont))
        slow = 1.0 + 3.0 / (1.0 + amplitude / table.mean_free_path)
        price = (cost["moving"] + k * cost["per_particle"]) * slow
    collisions = _collisions_per_period(table, vel, mu, cont)
    return periods * (float(R) * k * cost["period"] + float((collisions * price).sum()))


def check_flights(table: Table, velocities, mu, container, periods: int, name, value) -> None:
    """Refuse, naming ``name``, billiard runs whose flights would exceed the work limit
    (:func:`sinktheory.worklimit.check_particle_steps`; :func:`flight_seconds`)."""
    seconds = flight_seconds(table, velocities, mu, container, periods)
    collisions = expected_collisions(table, velocities, mu, container, periods)
    R = np.shape(velocities)[0]
    check_particle_steps(
        name, value, seconds / SECONDS_PER_PARTICLE_STEP, f"{R} run(s) x {periods} period(s) "
        f"of billiard flights with about {collisions:.3g} collisions",
    )  # fmt: skip


def simulate_billiard(
    table: Table,
    positions,
    velocities,
    *,
    mu: float = 1.0,
    container=None,
    periods: int = 100,
    lyapunov: bool = False,
    seed: int = 0,
    discard: int = 0,
    parameters: dict | None = None,
) -> BilliardResult:
    """Run R rigid billiards of k particles from given states.

    Parameters
    ----------
    table : Table
    positions, velocities : (R, k, 2) relative positions (inside the table) and absolute
        velocities
    mu : mass of one particle (moving container only)
    container : (R, 2) container (X, X') to let the container move, None for a fixed one
    periods : int, the runs last periods x 2 pi; records at every t = j 2 pi
    lyapunov : compute lambda_1 (tangent map if fixed, two trajectories if moving)
    seed : seeds the initial deviation vectors
    discard : periods run first and not recorded (the deviation vector aligns with the
        unstable direction; without this the exponent carries a transient of order
        1 / (impacts per run))

    Examples
    --------
    >>> from sinktheory.billiard.table import stadium_table
    >>> r = simulate_billiard(stadium_table(1, 1), [[[0.1, 0.2]]], [[[1.0, 0.3]]], periods=2)
    >>> int(r.collisions.sum()) > 0, r.max_relative_energy_error < 1e-14
    (True, True)
    """
    if not isinstance(table, Table):
        raise ParameterError("table", table, "a sinktheory.billiard.table.Table")
    pos = np.array(real_array("positions", positions), dtype=float)
    vel = np.array(real_array("velocities", velocities), dtype=float)
    if pos.ndim != 3 or pos.shape[2] != 2 or vel.shape != pos.shape:
        raise ParameterError(
            "positions", f"shape {pos.shape} (velocities {vel.shape})", "two (R, k, 2) arrays"
        )
    if not (np.all(np.isfinite(pos)) and np.all(np.isfinite(vel))):
        raise ParameterError("positions", "non-finite values", "finite positions and velocities")
    table.check_positions("positions", pos)
    mu = positive("mu", mu)
    periods = positive_int("periods", periods, maximum=MAX_PERIODS)
    discard = positive_int("discard", discard, minimum=0, maximum=MAX_PERIODS)
    lyapunov = flag("lyapunov", lyapunov)
    seed = positive_int("seed", seed, minimum=0)
    R, k, _ = pos.shape
    for name, count in (("periods", periods), ("discard", discard)):  # 4 records each
        fits_memory(name, count, 32.0 * R * (count + 1), f"{R} run(s) x {count} period(s)",
                    "smaller: the records must fit in memory")  # fmt: skip
    cont = None
    if container is not None:
        cont = np.array(real_array("container", container), dtype=float)
        if cont.shape != (R, 2) or not np.all(np.isfinite(cont)):
            raise ParameterError("container", f"shape {cont.shape}", f"finite, shape ({R}, 2)")
    check_flights(table, vel, mu, cont, periods + discard, "periods", periods)
    return _fly(table, pos, vel, mu, cont, periods, lyapunov, seed, discard, parameters)


def _fly(table, pos, vel, mu, cont, periods, lyapunov, seed, discard, parameters):
    """The runs of :func:`simulate_billiard` from checked inputs (their work checked too)."""
    R, k, _ = pos.shape
    arrays = _table_arrays(table)
    rng = np.random.default_rng(seed)
    times = PERIOD * np.arange(periods + 1)
    if cont is None:
        tan = rng.normal(size=(R, k, 4)) if lyapunov else np.zeros((R, 0, 4))
        if lyapunov:
            tan /= np.sqrt((tan**2).sum(axis=(1, 2)))[:, None, None]
        for count, what in ((discard, "fixed billiard (discarded periods)"),
                            (periods, "fixed billiard")):  # fmt: skip
            logs, v2, hits, status, where = out = _outputs(R, len(arrays[0]), count, 2)
            for first, last in chunks(count):
                K.run_fixed(pos, vel, tan, first, last, PERIOD, *arrays, out)
            _raise_status(status, where, what)
        cont_e = np.zeros((R, periods + 1))
        total = 0.5 * mu * v2
        method = "tangent map"
    else:
        if lyapunov:
            d = rng.normal(size=(R, 2 + 4 * k))
            d *= SHADOW_DISTANCE / np.sqrt((d**2).sum(axis=1))[:, None]
            shadow = (
                cont + d[:, :2],
                pos + d[:, 2 : 2 + 2 * k].reshape(R, k, 2),
                vel + d[:, 2 + 2 * k :].reshape(R, k, 2),
            )
            table.check_positions("positions", shadow[1])
        else:
            shadow = (np.zeros((0, 2)), np.zeros((0, k, 2)), np.zeros((0, k, 2)))
        for count, what in ((discard, "moving billiard (discarded periods)"),
                            (periods, "moving billiard")):  # fmt: skip
            out = _outputs(R, len(arrays[0]), count, 3)
            cont_e, total, logs, hits, status, where = out
            for first, last in chunks(count):
                K.run_moving(
                    cont, pos, vel, mu, first, last, PERIOD, *arrays, shadow, SHADOW_DISTANCE,
                    RENORMALISATIONS, out,
                )  # fmt: skip
            _raise_status(status, where, what)
        method = "two trajectories"
    result = BilliardResult(
        table, cont is None, k, mu, times, cont_e, total, hits,
        logs if lyapunov else None, method if lyapunov else "", parameters or {},
    )  # fmt: skip
    err = result.max_relative_energy_error
    if not err <= ENERGY_BOUND:
        raise EnergyDriftError(
            f"rigid billiard: relative energy error {err:.3g} > {ENERGY_BOUND:g}"
        )
    return result


def start_directions(settings: RunSettings, particles: int) -> np.ndarray:
    """(R, k, 2) unit vectors in seeded random directions, one child seed per run (a
    stream apart from the positions' of :func:`sinktheory.ensemble.random_positions`).

    Examples
    --------
    >>> d = start_directions(RunSettings(runs=2, seed=3), 4)
    >>> d.shape, bool(np.allclose(np.hypot(d[..., 0], d[..., 1]), 1))
    ((2, 4, 2), True)
    """
    if not isinstance(settings, RunSettings):
        raise ParameterError("settings", settings, "a RunSettings")
    particles = positive_int("particles", particles)
    fits_memory("particles", particles, 48.0 * settings.runs * particles,
                f"{settings.runs} run(s) x {particles} particle(s)", "fewer")  # fmt: skip
    children = np.random.SeedSequence([settings.seed, 22]).spawn(settings.runs)
    angles = np.stack([np.random.default_rng(c).uniform(0, 2 * np.pi, particles) for c in children])
    return np.stack([np.cos(angles), np.sin(angles)], axis=-1)


def billiard(
    shape: str,
    alpha: float,
    beta: float,
    *,
    particles: int = 1,
    mass: float = 0.2,
    settings: RunSettings | None = None,
    fixed: bool = False,
    lyapunov: bool = False,
) -> BilliardResult:
    """The rigid limit n -> oo of the sink (module docstring), started like ``simulate``.

    Parameters
    ----------
    shape, alpha, beta : the well (:class:`sinktheory.model.Well`; n plays no part)
    particles, mass : k particles of total mass m (:class:`sinktheory.model.Sink`)
    settings : energy E0, runs, periods, seed, start box (:class:`RunSettings`)
    fixed : keep the container fixed; the particles share E0 (E0 / k each)
    lyapunov : also compute lambda_1
    """
    settings = _settings(settings)
    sink = Sink(Well(alpha, beta, 1, shape=shape), particles=particles, mass=mass)
    settings.check_box(sink.well)
    params = {"shape": shape, "alpha": sink.well.alpha, "beta": sink.well.beta}
    return _table_runs(
        lambda: rigid_table(shape, alpha, beta), sink.particles, sink.mass, settings, fixed,
        lyapunov, params,
    )  # fmt: skip


def well_billiard(
    well,
    values=None,
    *,
    particles: int = 1,
    mass: float = 0.2,
    settings: RunSettings | None = None,
    fixed: bool = False,
    lyapunov: bool = False,
) -> BilliardResult:
    """:func:`billiard` in the rigid table of a user's well (a
    :class:`~sinktheory.userwell.UserWell` with wall ratios, at its parameter ``values`` by
    name, defaults for the others; :func:`sinktheory.billiard.table.well_table`), the start
    box checked inside it.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> ellipse = UserWell("ellipse", "((x/a)**2 + (y/b)**2)**4", {"a": 1.0, "b": 0.5},
    ...                    wall_ratios=["sqrt((x/a)**2 + (y/b)**2)"])
    >>> r = well_billiard(ellipse, fixed=True, settings=RunSettings(runs=2, periods=2))
    >>> r.table.name, r.max_relative_energy_error < 1e-13
    ('ellipse', True)
    """
    settings = _settings(settings)
    k, m = Sink.check_particles(particles, mass)
    table = well_table(well, **parameter_values(values))
    b = settings.box
    try:
        table.check_positions("box", np.array([[b, b], [b, -b], [-b, b], [-b, -b]]))
    except ParameterError:
        raise ParameterError(
            "box", b, f"a start box (-box, box)^2 inside the rigid {table.name} table"
        ) from None
    params = {"well": well.name, **table.parameters}
    return _table_runs(lambda: table, k, m, settings, fixed, lyapunov, params)


def _settings(settings: RunSettings | None) -> RunSettings:
    settings = RunSettings() if settings is None else settings
    if not isinstance(settings, RunSettings):
        raise ParameterError("settings", settings, "a RunSettings")
    return settings


def _table_runs(make_table, k, mass, settings, fixed, lyapunov, params) -> BilliardResult:
    """The runs of :func:`billiard` and :func:`well_billiard` in the table ``make_table()``
    (made after the cheap checks), k particles of total mass ``mass``; ``params`` name the
    well in the result."""
    fixed, lyapunov = flag("fixed", fixed), flag("lyapunov", lyapunov)
    if lyapunov and not fixed and not settings.container_energy >= MIN_SHADOW_ENERGY:
        raise ParameterError(
            "container_energy", settings.container_energy,
            f">= {MIN_SHADOW_ENERGY:g} for lambda_1 of a moving container",
            why=f"its shadow trajectory starts {SHADOW_DISTANCE:g} away, which must be small "
            "next to the container's amplitude sqrt(2 E0)",
        )  # fmt: skip
    # the memory estimate reads only the number of particles of the sink
    settings.check_memory(SimpleNamespace(particles=k), ("container",) * 3)  # E_c, E, logs
    table = make_table()
    mu = mass / k
    pos = random_positions(settings, k)
    params = {
        **params, "particles": k, "mass": mass, "container_energy": settings.container_energy,
        "runs": settings.runs, "periods": settings.periods, "seed": settings.seed,
        "box": settings.box, "fixed": fixed,
    }  # fmt: skip
    if fixed:
        speed = math.sqrt(2.0 * settings.container_energy / mass)  # E0 / k per particle
        vel = speed * start_directions(settings, k)
        container = None
    else:
        vel = np.zeros_like(pos)
        container = np.zeros((settings.runs, 2))
        container[:, 0] = math.sqrt(2.0 * settings.container_energy)
    name = "periods" if settings.periods >= settings.runs else "runs"
    table.check_positions("positions", pos)
    check_flights(table, vel, mu, container, settings.periods, name, getattr(settings, name))
    return _fly(table, pos, vel, mu, container, settings.periods, lyapunov, settings.seed, 0,
                params)  # fmt: skip


@dataclass(frozen=True)
class RigidLimit(Result):
    """The rigid-limit figures of a sink beside which soft-wall runs are plotted:
    the moving-container (sink) and fixed-container billiards of the same table."""

    moving: BilliardResult
    fixed: BilliardResult

    def items(self) -> dict[str, Any]:
        return {
            "table": self.moving.table,
            "mean_free_path_santalo": self.moving.table.mean_free_path,
            "moving_lambda1": _stats(self.moving.lambda1),
            "moving_mean_free_time": _stats(self.moving.mean_free_time),
            "moving_final_container_energy": _stats(self.moving.container_energy[:, -1]),
            "moving_split_lambda1": self.moving.split().as_dict(),
            "fixed_lambda1": _stats(self.fixed.lambda1),
            "fixed_split_lambda1": self.fixed.split().as_dict(),
            "fixed_lambda1_per_collision": _stats(self.fixed.lambda1_per_collision),
            "fixed_mean_free_time": _stats(self.fixed.mean_free_time),
        }


def rigid_limit(
    shape: str,
    alpha: float,
    beta: float,
    *,
    particles: int = 1,
    mass: float = 0.2,
    settings: RunSettings | None = None,
) -> RigidLimit:
    """lambda_1 and mean free time of the rigid limit, moving and fixed container, as
    functions of (shape, alpha, beta): the n = oo points of the soft-wall charts.

    Examples
    --------
    >>> r = rigid_limit("flat", 0.5, 0.3, settings=RunSettings(runs=2, periods=5))
    >>> sorted(r.as_dict())[:3]
    ['fixed_lambda1', 'fixed_lambda1_per_collision', 'fixed_mean_free_time']
    """
    kw = {"particles": particles, "mass": mass, "settings": settings, "lyapunov": True}
    return RigidLimit(
        billiard(shape, alpha, beta, **kw), billiard(shape, alpha, beta, fixed=True, **kw)
    )
