r"""The attachments side by side: energy dissipated from an impulse, against its energy.

For each attachment (:class:`sinktheory.attachments.Attachment`: the 1-D cubic NES on
the line y = 0, the 1-D vibro-impact NES, the 2-D well with k particles) at the same
total mass m and the same damping coefficient, and for each initial container energy E0
of a log-spaced list, :func:`sinktheory.attachments.impulse_response` runs ``runs``
seeded impulsive starts for ``periods`` container periods T = 2 pi; then

* the efficiency is the fraction of the initial energy dissipated by the end of the
  window (mean over the runs and its standard error, ``ImpulseResponse.fraction_dissipated``);
* the 90 % time is the first time the dissipated energy reaches 90 % of it (mean and
  standard error over the runs that got there, and how many did:
  ``ImpulseResponse.time_to_fraction``), in periods T.

Every cell uses the same ``seed``, so the start states of the runs are the same at every
energy (common random numbers: the curves against E0 are smoother than independent draws
would give them).  The work of the whole grid is checked against the work limit
(:mod:`sinktheory.worklimit`) before anything runs, and a progress bar counts the cells.

Units: the paper's (container mass 1, spring 1, period T = 2 pi).
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from .. import validation as v
from ..attachments import KINDS, Attachment
from ..errors import ParameterError
from ..glossary import old_attribute, renamed
from ..results import Result
from ..runstats import check_runs, mean_stderr

__all__ = [
    "attachments_of",
    "compare",
    "Comparison",
    "energies_of",
    "FRACTION",
    "MAX_ENERGIES",
    "steps_per_period",
]

#: The share of the initial energy whose dissipation time is reported.
FRACTION = 0.9
#: Most initial energies of one comparison.
MAX_ENERGIES = 1000


def attachments_of(
    kinds: Sequence[str],
    *,
    shapes: Sequence[str] | None = None,
    particles: Sequence[int] = (1,),
    alpha: float = 0.5,
    beta: float = 0.3,
    n: int | None = None,
    nes_n: int = 2,
    mass: float = 0.2,
    well=None,
) -> list:
    """The attachments of ``kinds`` at one total mass: ``nes`` (wall exponent ``nes_n``,
    2: the cubic NES) and ``impact`` once each (on the line y = 0 every registered shape
    has the same wall, so the first shape is used), ``well`` (wall exponent ``n``,
    default 4) once per shape (default flat) and particle count.

    ``well``, a user's well at its values (:class:`sinktheory.wellat.WellAt`), is the 2-D
    attachment instead of ``shapes`` and ``n`` (then left out); the 1-D attachments stay
    the line of a registered shape (``alpha``, ``beta``, ``nes_n``).

    Examples
    --------
    >>> [a.label for a in attachments_of(["nes", "well"], particles=[1, 5])]
    ['NES n = 2', 'well flat k = 1', 'well flat k = 5']

    Raises ParameterError for an unknown kind, an empty list or repeated entries.
    """
    kinds = _names("attachments", kinds, KINDS)
    if well is not None:
        from ..wellat import WellAt

        if not isinstance(well, WellAt):
            raise ParameterError("well", well, "None or a user's well at its values, a "
                                 "sinktheory.wellat.WellAt")  # fmt: skip
        for name, value in (("shapes", shapes), ("n", n)):
            if value is not None:
                raise ParameterError(name, value, "left out with well (the user's well is "
                                     "the 2-D attachment)")  # fmt: skip
    shapes = _names("shapes", ("flat",) if shapes is None else shapes, None)
    n = 4 if n is None else n
    counts = [v.positive_int("particles", k) for k in _listed("particles", particles)]
    if len(set(counts)) != len(counts):
        raise ParameterError("particles", list(particles), "distinct particle counts")
    out = []
    for kind in kinds:
        if kind == "well" and well is not None:
            out += [Attachment("well", particles=k, mass=mass, user_well=well) for k in counts]
        elif kind == "well":
            for shape in shapes:
                for k in counts:
                    out.append(_made({"shape": "shapes"}, "well", shape, alpha, beta, n, k, mass))
        else:
            out.append(_made({"shape": "shapes", "n": "nes_n"}, kind, shapes[0], alpha, beta,
                             nes_n, 1, mass))  # fmt: skip
    return out


def _made(keywords: dict[str, str], *fields) -> Attachment:
    """``Attachment(*fields)``; its refusal of a field is named by the keyword of
    :func:`attachments_of` the value came from (``keywords``: field -> keyword).

    Examples
    --------
    >>> _made({"n": "nes_n"}, "nes", "flat", 0.5, 0.3, 0, 1, 0.2)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: nes_n = 0 is not allowed: must be an integer ...
    """
    try:
        return Attachment(*fields)
    except ParameterError as e:
        if e.name not in keywords:
            raise
        text = keywords[e.name] + str(e)[len(e.name) :]
        e.name, e.args = keywords[e.name], (text,)
        raise


def _listed(name: str, values) -> list:
    if isinstance(values, str) or not isinstance(values, Sequence) or not len(values):
        raise ParameterError(name, values, "a non-empty list")
    return list(values)


def _names(name: str, values, options) -> list[str]:
    values = _listed(name, values)
    if options is not None:
        values = [v.choice(name, x, options) for x in values]
    elif not all(isinstance(x, str) for x in values):
        raise ParameterError(name, values, "a list of names")
    if len(set(values)) != len(values):
        raise ParameterError(name, values, "a list without repeated entries")
    return values


def energies_of(lo: float, hi: float, count: int) -> np.ndarray:
    """``count`` log-spaced initial energies from ``lo`` to ``hi`` (both included).

    Examples
    --------
    >>> energies_of(0.01, 1.0, 3).tolist()
    [0.01, 0.1, 1.0]
    >>> energies_of(1.0, 0.1, 3)
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: energies = (1.0, 0.1, 3) is not allowed: must be \
LO HI COUNT with 0 < LO <= HI (LO = HI only with COUNT = 1)
    """
    allowed = "LO HI COUNT with 0 < LO <= HI (LO = HI only with COUNT = 1)"
    lo, hi = v.positive("energies", lo), v.positive("energies", hi)
    count = v.positive_int("energies", count, maximum=MAX_ENERGIES)
    if lo > hi or (lo == hi) != (count == 1):
        raise ParameterError("energies", (lo, hi, count), allowed)
    return np.geomspace(lo, hi, count)


@renamed(energy="container_energy")
@dataclass(frozen=True)
class Comparison(Result):
    """Efficiency and 90 % time of each attachment at each initial container energy.

    Attributes
    ----------
    attachment : (A,) labels (``Attachment.label``)
    container_energy : (E,) initial container energies E0 (the ``energies`` compared)
    efficiency, efficiency_se : (A, E) fraction of the initial energy dissipated by the
        end of the window: mean over the runs and its standard error
    t90, t90_se : (A, E) periods until 90 % is dissipated: mean and standard error over
        the runs that reached it (NaN where none did; the s.e. also where one did)
    reached : (A, E) runs that reached 90 %
    max_audit_error : (A, E) largest |H + W - H0| / H0 of the cell's runs
    attachments : list of dict
        Each attachment's parameters (:attr:`Attachment.parameters
        <sinktheory.attachments.Attachment.parameters>`).
    damping, runs, periods, seed, samples_per_period, seconds
    """

    attachment: tuple
    container_energy: np.ndarray
    efficiency: np.ndarray
    efficiency_se: np.ndarray
    t90: np.ndarray
    t90_se: np.ndarray
    reached: np.ndarray
    max_audit_error: np.ndarray
    attachments: list
    damping: float
    runs: int
    periods: int
    seed: int
    samples_per_period: int
    seconds: float

    DIMS = {
        "attachment": ("attachment",),
        "container_energy": ("container_energy",),
        **dict.fromkeys(
            ("efficiency", "efficiency_se", "t90", "t90_se", "reached", "max_audit_error"),
            ("attachment", "container_energy"),
        ),
    }

    energy = old_attribute("container_energy")

    def span(self, index: int, level: float = 0.5) -> tuple[float, float] | None:
        """(lowest, highest) energy of the grid at which attachment ``index`` dissipates
        at least ``level`` of the initial energy on average (None if at none).

        Examples
        --------
        >>> c = Comparison(("a",), np.array([0.1, 1.0, 10.0]), np.array([[0.2, 0.6, 0.7]]),
        ...                *[np.zeros((1, 3))] * 5, [], 0.0, 2, 10, 0, 16, 0.0)
        >>> c.span(0), c.span(0, 0.9)
        ((1.0, 10.0), None)
        """
        index = v.positive_int("index", index, minimum=0, maximum=len(self.efficiency) - 1)
        above = np.flatnonzero(self.efficiency[index] >= v.finite("level", level))
        if not above.size:
            return None
        return float(self.container_energy[above[0]]), float(self.container_energy[above[-1]])


def _mean_se(x: np.ndarray) -> tuple[float, float]:
    """Mean and standard error over the runs that reached the level (finite values)."""
    return mean_stderr(x[np.isfinite(x)])


@renamed(energy="container_energy")
def steps_per_period(att, container_energy: float, *, runs: int, periods: int, tol=None) -> int:
    """Integration steps per period of ``att`` after an impulse of E0 =
    ``container_energy``: the step :func:`sinktheory.stepsize.step_of` picks for the
    start's total energy bound (a well too stiff to integrate is refused naming its
    parameter); the vibro-impact flow is exact between impacts and is counted as one step
    per recorded sample."""
    from ..model import RunSettings
    from ..stepsize import step_of

    if not isinstance(att, Attachment):
        raise ParameterError("att", att, "a sinktheory.attachments.Attachment")
    if att.kind == "impact":
        return 0
    settings = RunSettings(container_energy=container_energy, runs=runs, periods=periods)
    settings.check(att.sink)
    return step_of(att.sink, settings.total_energy_bound(att.sink), tol=tol, settings=settings)[2]


def work(
    attachments,
    energies,
    *,
    runs: int,
    periods: int,
    samples_per_period: int,
    tol: float | None = None,
) -> float:
    """Particle steps of the whole comparison, checked against the work limit before
    anything runs (:func:`sinktheory.worklimit.check_particle_steps`, naming ``periods``):
    the damped engine's steps at :data:`~sinktheory.worklimit.DISSIPATIVE` plain ones, the
    vibro-impact attachment's periods and samples at
    :data:`~sinktheory.vibroimpact.FLIGHT_SECONDS` (its impacts are checked when it runs)."""
    from ..limits import SECONDS_PER_PARTICLE_STEP
    from ..vibroimpact import FLIGHT_SECONDS
    from ..worklimit import DISSIPATIVE, check_particle_steps, ensemble_steps

    periods = v.positive_int("periods", periods)
    total = 0.0
    for att in attachments:
        for e in energies:
            if att.kind == "impact":
                seconds = FLIGHT_SECONDS["period"] + samples_per_period * FLIGHT_SECONDS["sample"]
                total += float(runs) * periods * seconds / SECONDS_PER_PARTICLE_STEP
                continue
            steps = steps_per_period(att, float(e), runs=runs, periods=periods, tol=tol)
            steps = max(steps, samples_per_period)  # steps are a multiple of the samples
            total += DISSIPATIVE * ensemble_steps(runs, float(periods) * steps, att.particles)
    check_particle_steps(
        "periods",
        periods,
        total,
        f"{len(attachments)} attachment(s) x {len(energies)} energies x {runs} run(s) x "
        f"{periods} period(s)",
    )
    return total


def check_attachments(attachments) -> list:
    """``attachments`` as a non-empty list of :class:`~sinktheory.attachments.Attachment`."""
    from ..attachments import Attachment

    allowed = "a non-empty list of sinktheory.attachments.Attachment"
    try:
        items = list(attachments)
    except TypeError:
        raise ParameterError("attachments", attachments, allowed) from None
    if not items or not all(isinstance(a, Attachment) for a in items):
        raise ParameterError("attachments", [type(a).__name__ for a in items], allowed)
    return items


def check_damping(damping, attachments) -> float:
    """``damping`` >= 0 whose rate on every attachment's particles, c (1 + m) / m (the
    relative velocity's decay rate), is a finite number (at 1e308 it overflowed into a
    LinAlgError of the vibro-impact flow).

    Examples
    --------
    >>> from sinktheory.attachments import Attachment
    >>> check_damping(1e308, [Attachment("impact")])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: damping = 1e+308 is not allowed: must be <= 2.99...e+307 \
(the rate c (1 + m) / m on the particles of mass m = 0.2 must be finite)
    """
    c = v.nonnegative("damping", damping)
    mass = min(float(att.mass) for att in attachments)
    largest = np.finfo(float).max / ((1.0 + mass) / mass)
    if not c <= largest:
        raise ParameterError(
            "damping", damping, f"<= {largest:.17g}",
            why=f"the rate c (1 + m) / m on the particles of mass m = {mass:g} must be finite",
        )  # fmt: skip
    return c


def compare(
    attachments,
    energies,
    *,
    damping: float,
    periods: int,
    runs: int = 8,
    seed: int = 0,
    samples_per_period: int = 16,
    tol: float | None = None,
    progress: bool = True,
) -> Comparison:
    """Efficiency and 90 % time of each attachment at each initial container energy.

    Parameters
    ----------
    attachments : sequence of Attachment
        E.g. :func:`attachments_of`; compared at their own (usually equal) mass.
    energies : sequence of float > 0
        Initial container energies E0 (e.g. :func:`energies_of`).
    damping : float >= 0
        The damping coefficient every attachment gets
        (:func:`sinktheory.attachments.impulse_response`).
    periods : int
        The window, in container periods T = 2 pi.
    runs : int >= 2
        Seeded runs per cell (standard errors need two).
    seed : int >= 0
        The same for every cell.
    samples_per_period : int
        Recording resolution of the 90 % time.
    tol : float, optional
        Energy tolerance of the integration (the engine's default if None).
    progress : bool
        A progress bar on stderr for work longer than two seconds.

    Returns
    -------
    Comparison
    """
    from ..attachments import impulse_response
    from ..progress import ProgressBar

    attachments = check_attachments(attachments)
    energies = v.real_array("energies", energies)
    if energies.ndim != 1 or not energies.size or not np.all(energies > 0):
        raise ParameterError("energies", energies.tolist(), "a non-empty list of numbers > 0")
    check_damping(damping, attachments)
    runs = check_runs("runs", runs)
    samples_per_period = v.positive_int("samples_per_period", samples_per_period,
                                        maximum=100_000)  # fmt: skip
    work(attachments, energies, runs=runs, periods=periods,
         samples_per_period=samples_per_period, tol=tol)  # fmt: skip
    shape = (len(attachments), energies.size)
    eff, eff_se, t90, t90_se, audit = (np.full(shape, math.nan) for _ in range(5))
    reached = np.zeros(shape, dtype=int)
    start = time.perf_counter()
    bar = ProgressBar(eff.size, enabled=progress, label="compare", unit="cell")
    try:
        for i, att in enumerate(attachments):
            for j, e in enumerate(energies):
                res = impulse_response(
                    att,
                    float(e),
                    damping=damping,
                    periods=periods,
                    runs=runs,
                    seed=seed,
                    samples_per_period=samples_per_period,
                    tol=tol,
                )
                eff[i, j], eff_se[i, j] = _mean_se(res.fraction_dissipated())
                times = res.time_to_fraction(FRACTION) / (2 * math.pi)
                reached[i, j] = int(np.isfinite(times).sum())
                t90[i, j], t90_se[i, j] = _mean_se(times)
                audit[i, j] = res.max_audit_error
                bar.update(1)
    finally:
        bar.close()
    return Comparison(
        tuple(a.label for a in attachments),
        energies,
        eff,
        eff_se,
        t90,
        t90_se,
        reached,
        audit,
        [a.parameters for a in attachments],
        float(damping),
        runs,
        int(periods),
        int(seed),
        int(samples_per_period),
        time.perf_counter() - start,
    )
