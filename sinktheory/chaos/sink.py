"""Chaos indicators of the container + particles ensemble, set up like :func:`simulate`.

:func:`chaos` starts the same runs as :func:`sinktheory.simulate.simulate` for the same
:class:`~sinktheory.model.RunSettings` (container at X = sqrt(2 E0) at rest, particles at
rest at :func:`~sinktheory.ensemble.random_positions`), with the same step, scheme and
energy audit, and records the indicators once per container period T = 2 pi.

The transverse exponent is that of the invariant subspace y = 0 (every y_j = ydot_j = 0,
which the flow keeps because V is even in y): the runs start from the same positions with
y_j = 0, and one deviation vector lies in the y_j-directions only.  Linearised about
y = 0 each particle's y obeys a Hill equation driven by its x-motion; with the container
fixed (mass ratio -> 0) this is the paper's Floquet problem (:mod:`sinktheory.floquet`),
whose ln|rho| / T it then equals (tests/chaos/test_chaos.py).

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> sink = Sink(Well(alpha=0.5, beta=0.3, n=4), particles=1, mass=0.2)
>>> res = chaos(sink, RunSettings(runs=2, periods=20, seed=1), gali=2, transverse=True,
...             dt=0.01)
>>> res.lambda1.shape, res.gali.shape, res.transverse.shape
((2,), (2, 21), (2,))
>>> bool(res.run_errors.max() < 1e-6)
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .. import validation as val
from ..ensemble import (
    ENERGY_BOUND,
    check_sink,
    engine_name,
    engine_params,
    run_parameters,
    split_values,
    start_positions,
    start_state,
    total_energy,
)
from ..errors import ParameterError
from ..glossary import renamed
from ..integrators import DEFAULT_SCHEME, get_scheme
from ..model import SECONDS_PER_PARTICLE_STEP, RunSettings, Sink
from ..stepsize import aligned_step, step_of
from ..worklimit import check_particle_steps, ensemble_steps
from .general import (
    check_block,
    check_gali,
    check_renorm,
    check_spectrum,
    indicators,
    vector_count,
)
from .result import ChaosResult
from .vectors import ORTHONORMALISE_SECONDS, random_vectors

__all__ = [
    "chaos",
    "chaos_batch",
    "start_energy",
]


def transverse_mask(particles: int) -> np.ndarray:
    """Phase-space directions (q, v of the engine) of the particles' y: the y_j."""
    D = 1 + 2 * particles
    mask = np.zeros(2 * D, bool)
    mask[1 + particles : D] = True
    return mask


def tangent_runs(dim: int, spectrum: str | None, gali: int, transverse: bool) -> list[int]:
    """Deviation vectors of each ensemble :func:`chaos` integrates (see
    :func:`~sinktheory.chaos.general.indicators`): the spectrum's (2D, or D for "half"),
    the normalised ones (k of GALI_k, or 1 for lambda_1) unless the spectrum carries
    lambda_1 alone, and 1 for the transverse runs.

    Examples
    --------
    >>> tangent_runs(3, "full", 0, True), tangent_runs(3, None, 4, False)
    ([6, 1], [4])
    """
    runs = []
    if spectrum:
        runs.append(2 * dim if spectrum == "full" else dim)
    if gali or not spectrum:
        runs.append(max(gali, 1))
    if transverse:
        runs.append(1)
    return runs


def check_tangent_work(
    sink: Sink,
    settings: RunSettings,
    steps: int,
    spectrum: str | None,
    gali: int,
    transverse,
    scheme: str | None = None,
) -> None:
    """Refuse, before any integration, an analysis whose deviation vectors would not fit in
    memory or could not finish within the work limit (:mod:`sinktheory.worklimit`).

    The spectrum's 2D vectors of dimension 2D make its cost grow with the square of the
    number of particles, and their set-up (drawing and orthonormalising them, 2D x (2D)^2
    per run at :data:`~sinktheory.chaos.vectors.ORTHONORMALISE_SECONDS`) with its cube;
    it is named when the analysis without it would fit, else the larger of ``runs`` and
    ``periods``.  ``steps`` are steps of ``scheme`` (:func:`sinktheory.worklimit.scheme_factor`).
    """
    dim = 1 + 2 * sink.particles
    R, P = settings.runs, settings.periods
    vectors = tangent_runs(dim, spectrum, gali, transverse)

    def work(vecs):
        setup = R * 2 * dim * max(vecs) ** 2 * ORTHONORMALISE_SECONDS / SECONDS_PER_PARTICLE_STEP
        return setup + sum(
            ensemble_steps(R, float(P) * steps, sink.particles, m, scheme) for m in vecs
        )

    def check(name, vecs):
        value = {"spectrum": spectrum, "periods": P, "runs": R}[name]
        what = f"{R} run(s) x {P} period(s) x {steps} step(s) with "
        what += f"{'+'.join(map(str, vecs))} deviation vector(s) of {sink.particles} particle(s)"
        what += " (set-up included)"
        val.fits_memory(name, value, 16.0 * dim * max(vecs) * R, what, "smaller")
        check_particle_steps(name, value, work(vecs), what)

    name = "periods" if P > R else "runs"
    if spectrum:
        try:
            check(name, tangent_runs(dim, None, gali, transverse))
        except ParameterError:
            pass
        else:  # the spectrum alone makes it too large
            name = "spectrum"
    check(name, vectors)


@renamed(method="scheme")
def chaos(
    sink: Sink,
    settings: RunSettings | None = None,
    *,
    spectrum: bool | str = False,
    gali: int = 0,
    megno: bool = False,
    transverse: bool = False,
    scheme: str = DEFAULT_SCHEME,
    dt: float | None = None,
    tol: float | None = None,
    renorm: int = 0,
    initial=None,
    energy_bound: float = ENERGY_BOUND,
    block: int | None = None,
    progress: bool | None = None,
    transient: int = 0,
) -> ChaosResult:
    """Lyapunov exponent(s), GALI/SALI, MEGNO and the transverse exponent of an ensemble.

    Parameters
    ----------
    sink : Sink
    settings : RunSettings, default RunSettings()
        E0, runs R, periods P, seed, box -- as for :func:`~sinktheory.simulate.simulate`;
        the seed also draws the deviation vectors (:mod:`~sinktheory.chaos.vectors`).
    spectrum : bool or "full" or "half"
        The spectrum of 2(1 + 2k) exponents (QR method, renormalised every period): all
        computed (True / "full"), or the 1 + 2k largest with the rest from the symplectic
        pairing ("half", about half the cost; no pair sums to check it by).
    gali : int
        k of GALI_k, 0 or 2..2(1 + 2k); 2 also gives SALI.
    megno : bool
        MEGNO Y(t) and its time average.
    transverse : bool
        Transverse exponent of y = 0 (runs restarted with y_j = 0, see module docstring).
    scheme, dt, energy_bound
        Splitting scheme, step and energy audit, as for ``simulate`` (dt aligned to
        T / steps; the stepper is the fixed one).
    tol : float, optional
        Relative energy error the step of ``scheme`` is chosen for (default 1e-8, see
        :mod:`sinktheory.stepsize`); ``dt`` overrides it.
    renorm : int >= 0
        Steps between extra renormalisations inside a period (0: once per period).
    initial : array (k, 2) or (R, k, 2), optional
        Particle positions instead of random ones.
    block : int, optional
        Engine runs per block (the numbers do not depend on it).
    progress : bool, optional
        Progress bar on stderr (on a terminal only).
    transient : int >= 0
        Periods left out of lambda_1 and the transverse exponent (their growth rates from
        then on; :attr:`ChaosResult.transient`), fewer than ``periods``.

    Returns
    -------
    ChaosResult
        ``times`` are t_j = j T, exponents per unit time.
    """
    settings = RunSettings() if settings is None else settings
    scheme = get_scheme(scheme)
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    options = _options(sink, spectrum, gali, megno, transverse, renorm, energy_bound, progress)
    block = check_block(block)
    if initial is None and isinstance(settings, RunSettings):
        settings.check(sink)  # a start box overflowing the wall ratio names box
    point = _Point.of(sink, settings, options["transverse"], initial)
    transient = val.positive_int("transient", transient, minimum=0,
                                 maximum=max(0, settings.periods - 1))  # fmt: skip
    _, dt, steps, _ = step_of(
        sink, point.top, scheme=scheme.name, dt=dt, tol=tol, settings=settings
    )
    check_tangent_work(
        sink,
        settings,
        steps,
        options["spectrum"],
        options["gali"],
        options["transverse"],
        scheme.name,
    )
    result = _together([point], scheme.name, [dt], [steps], block, options)[0]
    return replace(result, transient=transient)


@renamed(method="scheme")
def chaos_batch(
    sinks,
    settings,
    *,
    dt,
    spectrum: bool | str = False,
    gali: int = 0,
    megno: bool = False,
    transverse: bool = False,
    scheme: str = DEFAULT_SCHEME,
    renorm: int = 0,
    energy_bound: float = ENERGY_BOUND,
    progress: bool | None = None,
) -> list[ChaosResult]:
    """:func:`chaos` of several set-ups at once, as one ensemble whose runs carry their own
    parameters: a chaos map's betas (or alphas, gammas, masses, seeds) vectorised together.

    ``sinks`` and ``settings`` are sequences of equal length; the set-ups must share the
    engine (the well's shape; n is a run-time value), the particles and the number of
    periods.  ``dt`` (required: the step
    :func:`chaos` would pick depends on the well) is one step for all, or one per set-up
    (a chaos map's stiff and soft betas need different steps; the engine groups the runs by
    their steps).  Each result is bitwise the result of ``chaos(sink, settings, dt=dt,
    ...)`` on its own with its step (tested).

    Examples
    --------
    >>> from sinktheory import RunSettings, Sink, Well
    >>> sinks = [Sink(Well(0.5, b, 4), particles=1, mass=0.2) for b in (0.1, 0.3)]
    >>> runs = [RunSettings(runs=2, periods=5, seed=s) for s in (1, 2)]
    >>> both = chaos_batch(sinks, runs, dt=0.01)
    >>> alone = chaos(sinks[1], runs[1], dt=0.01)
    >>> bool((both[1].lambda1 == alone.lambda1).all())
    True
    """
    sinks = _sequence("sinks", sinks, "a sequence of sinktheory.model.Sink")
    settings = _sequence("settings", settings, "a sequence of sinktheory.model.RunSettings")
    for sink in sinks:
        if not isinstance(sink, Sink):
            raise ParameterError("sinks", type(sink).__name__,
                                 "a sequence of sinktheory.model.Sink")  # fmt: skip
    if not sinks or len(sinks) != len(settings):
        raise ParameterError(
            "sinks, settings", f"{len(sinks)} and {len(settings)} items", "equal, non-zero"
        )
    points = [_Point.of(k, s, transverse, None) for k, s in zip(sinks, settings, strict=True)]
    engines = {(engine_name(p.sink), p.sink.particles, p.settings.periods) for p in points}
    if len(engines) > 1:
        raise ParameterError(
            "sinks", f"{len(engines)} engines or period counts", "one shape, k and periods"
        )
    scheme = get_scheme(scheme)
    dts, steps = point_steps(points, dt)
    options = _options(sinks[0], spectrum, gali, megno, transverse, renorm, energy_bound, progress)
    for p, n in zip(points, steps, strict=True):
        check_tangent_work(p.sink, p.settings, n, options["spectrum"], options["gali"],
                           options["transverse"], scheme.name)  # fmt: skip
    return _together(points, scheme.name, dts, steps, None, options)


def _sequence(name: str, value, allowed: str) -> list:
    """``value`` as a list: a list, tuple or other sequence of items (not text, not a
    mapping), else refused naming ``name``."""
    from collections.abc import Sequence

    if isinstance(value, str | bytes) or not isinstance(value, Sequence | np.ndarray):
        raise ParameterError(name, type(value).__name__, allowed)
    return list(value)


def point_steps(points, dt) -> tuple[tuple[float, ...], tuple[int, ...]]:
    """(step, steps per period) of each set-up from ``dt``: one step for all or one per
    set-up, each aligned to the period (:func:`~sinktheory.stepsize.aligned_step`)."""
    given = [dt] * len(points) if np.ndim(dt) == 0 else list(np.ravel(dt))
    if len(given) != len(points):
        raise ParameterError("dt", f"{len(given)} steps",
                             f"one step, or one per set-up ({len(points)})")  # fmt: skip
    dts, steps = zip(*(aligned_step(d) for d in given), strict=True)
    return dts, steps


def start_energy(sink: Sink, settings: RunSettings, transverse: bool = False) -> float:
    """The largest total energy the runs of :func:`chaos` start with (what its step is
    chosen for)."""
    return _Point.of(sink, settings, transverse, None).top


def _options(sink, spectrum, gali, megno, transverse, renorm, energy_bound, progress) -> dict:
    """The analysis options, each checked (``sink`` gives the dimension for ``gali``, and
    whether y = 0 is invariant for ``transverse``)."""
    return {
        "spectrum": check_spectrum(spectrum),
        "gali": check_gali(gali, 1 + 2 * sink.particles),
        "megno": val.flag("megno", megno),
        "transverse": _check_transverse(sink, val.flag("transverse", transverse)),
        "renorm": check_renorm(renorm),
        "bound": val.positive("energy_bound", energy_bound),
        "progress": progress,
    }


def _check_transverse(sink: Sink, transverse: bool) -> bool:
    """``transverse``, refused for a user's well whose line y = 0 is not invariant (the
    registered shapes are even in y: :func:`sinktheory.userwell.y_invariant` decides a
    user's well symbolically)."""
    report = getattr(sink.well, "report", None)  # a user's well (sinktheory.wellat.WellAt)
    if transverse and report is not None and not report.y_invariant:
        raise ParameterError(
            "transverse", transverse, f"False for the {sink.well.shape} well (the exponent "
            "transverse to the invariant line y = 0)", why=f"y = 0 is not invariant: "
            f"{report.y_invariant_reason}",
        )  # fmt: skip
    return transverse


@dataclass(frozen=True)
class _Point:
    """One set-up's start: sink, settings, states (engine layout), energies."""

    sink: Sink
    settings: RunSettings
    q: np.ndarray
    v: np.ndarray
    h0: np.ndarray
    on_plane: tuple | None  # (q, v) started on y = 0, for the transverse exponent
    top: float  # the largest energy any of its runs starts with, from the well's centre

    @classmethod
    def of(cls, sink, settings, transverse: bool, initial) -> _Point:
        settings = check_sink(sink, settings)
        positions = start_positions(sink, settings, initial)
        values = start_state(sink, settings.container_energy, positions)
        h0 = total_energy(sink, values)
        top = float(np.max(h0))
        on_plane = None
        if transverse:
            flat = positions.copy()
            flat[:, :, 1] = 0.0
            tvalues = start_state(sink, settings.container_energy, flat)
            top = max(top, float(np.max(total_energy(sink, tvalues))))
            on_plane = split_values(tvalues)
        sink.well.check_energy(top, name="total_energy")
        return cls(sink, settings, *split_values(values), h0, on_plane, top)

    def parameters(self) -> dict:
        """What the runs were (:func:`~sinktheory.ensemble.run_parameters`: a user's well
        by its own parameters) and the period T."""
        s = self.settings
        return run_parameters(self.sink, s, s.runs) | {"period": 2.0 * math.pi}


def _together(points: list[_Point], scheme, dts, steps, block, o) -> list[ChaosResult]:
    """One engine ensemble over every point's runs (each run with its point's parameters,
    step ``dts[i]`` and ``steps[i]`` per period, start state and seeded deviation vectors);
    the result split back per point."""
    D = points[0].q.shape[0]
    count = vector_count(D, o["spectrum"], o["gali"])
    transverse = None
    if o["transverse"]:
        mask = transverse_mask(points[0].sink.particles)
        transverse = (
            _join(p.on_plane[0] for p in points),
            _join(p.on_plane[1] for p in points),
            mask,
            _vectors(points, 1, mask),
        )
    params = _params(points)
    res = indicators(
        engine_name(points[0].sink),
        _join(p.q for p in points),
        _join(p.v for p in points),
        params,
        dt=_per_run(points, dts),
        steps=_per_run(points, steps),
        segments=points[0].settings.periods,
        spectrum=o["spectrum"],
        gali=o["gali"],
        megno=o["megno"],
        transverse=transverse,
        vectors=_vectors(points, count),
        scheme=scheme,
        renorm=o["renorm"],
        seed=points[0].settings.seed,
        bound=o["bound"],
        block=block,
        progress=o["progress"],
        reference_energy=np.concatenate([p.h0 for p in points]),
    )
    out, start = [], 0
    for p, dt, n in zip(points, dts, steps, strict=True):
        runs = slice(start, start + p.settings.runs)
        start = runs.stop
        info = dict(res.parameters, params=engine_params(p.sink).tolist(), seed=p.settings.seed,
                    dt=float(dt), steps_per_segment=int(n))  # fmt: skip
        part = res._runs_of(runs, info | p.parameters())
        # its own times: dt x steps rounds differently for each step (as in indicators)
        out.append(replace(part, times=dt * n * np.arange(res.times.size)))
    return out


def _per_run(points: list[_Point], values) -> np.ndarray:
    """One value per point repeated over its runs (R,); a scalar when all are equal (so a
    single step stays a single step)."""
    if len(set(values)) == 1:
        return values[0]
    return np.concatenate(
        [np.full(p.settings.runs, x) for p, x in zip(points, values, strict=True)]
    )


def _params(points: list[_Point]) -> np.ndarray:
    """The engine parameters of every run, one column per run (NPARAMS, R)."""
    return _join(np.repeat(engine_params(p.sink)[:, None], p.settings.runs, 1) for p in points)


def _vectors(points: list[_Point], count: int, mask=None) -> tuple[np.ndarray, np.ndarray]:
    """Each point's seeded deviation vectors (as :func:`chaos` draws them for it alone),
    side by side: (dq, dv) of shape (D, count, R)."""
    D = points[0].q.shape[0]
    drawn = [random_vectors(D, count, p.settings.runs, p.settings.seed, mask=mask) for p in points]
    return _join(x[0] for x in drawn), _join(x[1] for x in drawn)


def _join(arrays) -> np.ndarray:
    """Arrays with runs last, side by side."""
    return np.concatenate(list(arrays), axis=-1)
