"""Predicted relaxation with rigid walls (n = oo): the slow-mode model on billiard runs.

The soft-wall prediction (:mod:`sinktheory.equilibrium.prediction`) reads the slow mode
of E_c off short runs started on the energy shell.  Here the runs are exact rigid
billiards (:func:`~sinktheory.billiard.run.simulate_billiard`, moving container) and the
shell is that of H = (X'^2 + X^2) / 2 + sum mu |v_j|^2 / 2 with the particles' positions
relative to the container confined to the table: given s = E_c / E, the container's
phase is uniform on its circle, the positions are uniform over the table and the k
velocities are uniform on the sphere sum mu |v_j|^2 / 2 = (1 - s) E
(:func:`rigid_shell_states`).  The law of s is then Beta(1, k) (the n -> oo limit of
:mod:`sinktheory.equilibrium.law`), with mean 1 / (k + 1).  The starting fractions are
Gauss-Legendre nodes of [0, 1] (no wall exponent to map them by), the lags and the fit
those of the soft-wall model.  The paper's start has the particles at rest, so E = E0.

Examples
--------
>>> from sinktheory.billiard.table import rigid_table
>>> t = rigid_table("flat", 0.5, 0.3)
>>> pos, vel, box = rigid_shell_states(t, 3, 0.2, 0.5, 0.25, 4, np.random.default_rng(1))
>>> e_c = 0.5 * (box**2).sum(axis=1)
>>> e_p = 0.5 * (0.2 / 3) * (vel**2).sum(axis=(1, 2))
>>> np.allclose(e_c, 0.125), np.allclose(e_c + e_p, 0.5)
(True, True)
"""

from __future__ import annotations

import math

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..glossary import renamed
from ..limits import MAX_RESAMPLES
from ..model import MAX_PERIODS
from .table import Table

__all__ = [
    "measure_rigid_settling",
    "predict_rigid_relaxation",
    "rigid_shell_increments",
    "rigid_shell_states",
]


@renamed(energy="total_energy")
def rigid_shell_states(table: Table, particles: int, mass: float, total_energy: float,
                       s: float, runs: int, rng: np.random.Generator):  # fmt: skip
    """(positions (R, k, 2) relative to the container, absolute velocities (R, k, 2),
    container (R, 2) as (X, X')) of ``runs`` states drawn from the rigid shell at total
    energy E = ``total_energy`` given E_c = s E (module docstring); k = ``particles`` of
    total mass ``mass``."""
    k = v.positive_int("particles", particles)
    e = v.positive("total_energy", total_energy)
    mu = v.positive("mass", mass) / k
    if not math.isfinite(2 * e / mu):  # the particles' speeds squared
        raise ParameterError("total_energy", total_energy, "a number > 0 whose speeds are finite")
    runs = v.positive_int("runs", runs)
    if not 0 <= v.finite("s", s) < 1:
        raise ParameterError("s", s, "a fraction in [0, 1)")
    if not isinstance(table, Table):
        raise ParameterError("table", table, "a sinktheory.billiard.table.Table")
    if not isinstance(rng, np.random.Generator):
        raise ParameterError("rng", rng, "a numpy.random.Generator")
    larger = ("runs", runs) if runs >= k else ("particles", particles)
    v.fits_memory(*larger, 112.0 * runs * k, f"{runs} run(s) x {k} particle(s)",
                  "fewer runs x particles")  # fmt: skip
    bx, by = table.box
    pos = np.empty((runs * k, 2))
    filled = 0
    while filled < pos.shape[0]:  # uniform over the table by rejection from its box
        trial = rng.uniform((-bx, -by), (bx, by), size=(2 * (pos.shape[0] - filled) + 8, 2))
        inside = trial[np.all(table.wall_values(trial[:, 0], trial[:, 1]) > 0, axis=0)]
        take = min(inside.shape[0], pos.shape[0] - filled)
        pos[filled : filled + take] = inside[:take]
        filled += take
    g = rng.standard_normal((runs, k, 2))
    speed = math.sqrt(2 * (1 - s) * e / mu)  # finite: checked above
    vel = g * (speed / np.sqrt((g**2).sum(axis=(1, 2))))[:, None, None]
    phase = rng.uniform(0, 2 * math.pi, runs)
    amplitude = math.sqrt(2 * s * e)
    container = amplitude * np.column_stack([np.cos(phase), np.sin(phase)])
    return pos.reshape(runs, k, 2), vel, container


def predict_rigid_relaxation(
    shape: str,
    alpha: float,
    beta: float,
    *,
    particles: int = 1,
    mass: float = 0.2,
    container_energy: float = 0.5,
    fraction: float = 0.05,
    periods: int | None = None,
    shell_energies: int = 12,
    shell_runs: int = 100,
    lag: int = 128,
    seed: int = 0,
    level: float = 0.95,
    resamples: int = 199,
):
    """The slow-mode prediction of <E_c>(t) from the paper's start (container at E0 =
    ``container_energy``, particles at rest) with rigid walls: ``shell_energies`` x
    ``shell_runs`` billiards from the rigid shell (module docstring; one child of
    ``SeedSequence(seed)`` per energy) over ``lag`` periods, read as
    :func:`~sinktheory.equilibrium.prediction.predict_relaxation` reads the soft-wall runs
    (``periods``, ``level`` and ``resamples`` as there).

    Examples
    --------
    >>> p = predict_rigid_relaxation("flat", 0.5, 0.3, shell_energies=4, shell_runs=8,
    ...                              lag=32, seed=3)
    >>> round(p.target, 12), bool(p.settle_low <= p.settle_time <= p.settle_high)
    (0.25, True)
    """
    from scipy import stats

    from ..equilibrium.prediction import (
        check_fraction,
        check_reading,
        shell_lags,
        shell_prediction,
    )
    from .table import rigid_table

    fraction = check_fraction(fraction)
    mass = v.positive("mass", mass)
    k = v.positive_int("particles", particles)
    e = v.positive("container_energy", container_energy)
    points = v.positive_int("shell_energies", shell_energies, minimum=3)
    runs = v.positive_int("shell_runs", shell_runs, minimum=4)
    lag = v.positive_int("lag", lag, minimum=8)
    seed = v.positive_int("seed", seed, minimum=0)
    if periods is not None:
        periods = v.positive_int("periods", periods, maximum=MAX_PERIODS)
    resamples = v.positive_int("resamples", resamples, minimum=20, maximum=MAX_RESAMPLES)
    periods, level, resamples = check_reading(periods, level, resamples)
    s, inc, message = rigid_shell_increments(rigid_table(shape, alpha, beta), k, mass, e,
                                             points, runs, shell_lags(lag), seed)  # fmt: skip
    return shell_prediction(s, inc, shell_lags(lag), stats.beta(1, k).pdf, 1 / (k + 1),
                            start=e, total=e, particles=k, mass=mass, lag=lag,
                            coefficients=message, fraction=fraction, periods=periods,
                            seed=seed, level=level, resamples=resamples)  # fmt: skip


def measure_rigid_settling(shape: str, alpha: float, beta: float, measure, *,
                           particles: int = 1, mass: float = 0.2,
                           container_energy: float = 0.5, fraction: float = 0.05,
                           seed: int = 0, resamples: int = 199):  # fmt: skip
    """(:class:`~sinktheory.equilibrium.relaxation.Relaxation`, the
    :class:`~sinktheory.billiard.run.BilliardResult`) of ``measure = (runs, periods)``
    rigid billiards from the paper's start (container at E0 = ``container_energy``,
    particles at rest at the seeded start positions), read by
    :func:`~sinktheory.equilibrium.prediction.read_settling` against the rigid law's mean
    <E_c> = E / (k + 1): the measured counterpart of :func:`predict_rigid_relaxation`.
    Runs in which no particle meets a wall do not settle and are refused (ParameterError
    naming ``measure``).

    Examples
    --------
    >>> r, runs = measure_rigid_settling("flat", 0.5, 0.3, (8, 600), seed=2, resamples=20)
    >>> round(r.target, 12), runs.container_energy.shape
    (0.25, (8, 601))
    """
    from ..equilibrium.prediction import check_fraction, measure_settings, read_settling
    from .run import billiard

    fraction = check_fraction(fraction)
    settings = measure_settings(measure, container_energy, seed)
    result = billiard(shape, alpha, beta, particles=particles, mass=mass, settings=settings)
    if not result.collisions.any():
        raise ParameterError(
            "measure", measure, "runs in which the particles reach the walls",
            why=f"no particle met a wall of the rigid {shape} table in {settings.periods} "
            "periods of any run: the container's energy never changed",
        )  # fmt: skip
    total = float(np.mean(result.total_energy[:, 0]))
    r = read_settling(result.container_energy, total / (result.particles + 1),
                      fraction=fraction, seed=seed, resamples=resamples)  # fmt: skip
    return r, result


@renamed(energy="total_energy")
def rigid_shell_increments(table: Table, particles: int, mass: float, total_energy: float,
                           points: int, runs: int, lags, seed: int):  # fmt: skip
    """(s (points,), increments of s (point, lag, run), one line on the runs): ``runs``
    billiards from the rigid shell at total energy E = ``total_energy`` at each of
    ``points`` Gauss-Legendre fractions s of [0, 1] (one child of ``SeedSequence(seed)``
    per point), at ``lags`` (periods, ascending)."""
    from ..equilibrium.kramers import gauss_grid
    from .run import simulate_billiard

    allowed = f"an ascending sequence of integers in [1, {MAX_PERIODS}] (periods)"
    steps = v.finite_array("lags", lags, allowed, ndim=1)
    lags = [v.positive_int("lags", j, maximum=MAX_PERIODS) for j in steps.tolist()]
    if not lags or any(b <= a for a, b in zip(lags, lags[1:], strict=False)):
        raise ParameterError("lags", lags, allowed)
    seed = v.positive_int("seed", seed, minimum=0)
    s = gauss_grid(points, 1)[0]
    children = np.random.SeedSequence(seed).spawn(points)
    states = [rigid_shell_states(table, particles, mass, total_energy, si, runs,
                                 np.random.default_rng(c))
              for si, c in zip(s, children, strict=True)]  # fmt: skip
    pos, vel, box = (np.concatenate(part) for part in zip(*states, strict=True))
    res = simulate_billiard(table, pos, vel, mu=mass / particles, container=box,
                            periods=int(max(lags)), seed=seed)  # fmt: skip
    ec = res.container_energy.reshape(points, runs, -1)
    inc = np.stack([ec[:, :, j] - ec[:, :, 0] for j in lags], axis=1) / total_energy
    message = (f"{points} points x {runs} rigid billiards from the shell, lags "
               f"{list(lags)} periods (seed {seed}); max relative energy error "
               f"{res.max_relative_energy_error:.2g}")  # fmt: skip
    return s, inc, message
