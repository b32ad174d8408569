"""Validated, immutable parameters of the stochastic energy sink.

This is the one place where the model's inputs are checked.  Every object validates
itself on construction and raises :class:`~sinktheory.errors.ParameterError` (a
``ValueError``) with a one-line message naming the parameter, the value and what is
allowed.

Units are the paper's dimensionless ones: container mass 1 on a spring of stiffness 1
(period T = 2 pi); energies in the same units.

Examples
--------
>>> well = Well(alpha=0.5, beta=0.3, n=10)
>>> round(well.wall_distance, 12), well.curvature_at_centre
(0.2, 0.6)
>>> sink = Sink(well, particles=5, mass=0.2)
>>> sink.mu
0.04
>>> Well(alpha=0.5, beta=0.5, n=2)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: beta = 0.5 is not allowed: must be < alpha = 0.5 (...)
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from . import validation as v
from ._generated import shapes as _shapes
from .errors import NumericalError, ParameterError
from .glossary import old_attribute, renamed
from .limits import MAX_N, MAX_PERIODS, MAX_RUNS, MAX_SECONDS, SECONDS_PER_PARTICLE_STEP
from .results import Result
from .twins import python_kernel

__all__ = [
    "confining_betas",
    "DAMPING_KINDS",
    "MAX_N",
    "MAX_PERIODS",
    "MAX_REACH",
    "MAX_RUNS",
    "MAX_SCALED_ENERGY",
    "MAX_SECONDS",
    "MIN_MU",
    "MIN_RELATIVE_WALL_DISTANCE",
    "Reach",
    "RunSettings",
    "SECONDS_PER_PARTICLE_STEP",
    "SHAPES",
    "Sink",
    "SinkSummary",
    "user_well_summary",
    "UserWellSummary",
    "Well",
    "WellSummary",
]

#: Names of the registered well shapes (:data:`sinktheory.symbolic.SHAPES`), with one
#: kernel bundle each in :mod:`sinktheory._generated.shapes`.
SHAPES = _shapes.NAMES
#: How the particles of a damped absorber lose energy: a contact weight, or a dashpot to
#: the container (:func:`sinktheory.damped.simulate_inelastic`).
DAMPING_KINDS = ("contact", "viscous")
#: Largest 2 n E / gamma accepted: the wall ratios' powers s^(2n) = 2 n V / gamma of a
#: particle of energy E stay far inside float64 range (1.8e308).
MAX_SCALED_ENERGY = 1e300
#: Largest reach c = (2 n E / gamma)^(1/(2n)) accepted, in units of the height |y| = 1 where
#: the wall term y^(2n) reaches 1: the basin's bounds are searched on [0, c] to 1e-12,
#: which float spacing cannot resolve much beyond it (Well.reach took minutes, c = 1e4).
MAX_REACH = 1e3
#: Smallest relative wall distance (alpha - beta) / max(alpha, |beta|): below it
#: D(s) = alpha + beta (s^2 - 1) loses more than half its digits to cancellation.
MIN_RELATIVE_WALL_DISTANCE = 1e-8
#: Smallest mass mu = m / k of one particle: its inverse (in every acceleration) and the
#: stiffness omega^2 ~ V'' / mu must stay finite and resolvable by a time step.
MIN_MU = 1e-12


# scalar geometry by Python (see sinktheory.twins): light commands never start numba's
# compiler, and the generated module (which imports numba) is loaded on first use only, so
# refusing bad parameters stays fast
@functools.cache
def _geometry(name: str):
    from ._generated import oscillator

    return python_kernel(getattr(oscillator, name))


def _denominator(s, alpha, beta):
    return _geometry("denominator")(s, alpha, beta)


def _axis_reach_factor(energy, gamma, n):
    return _geometry("axis_reach_factor")(energy, gamma, n)


def _on_points(kernel, x, y, alpha, beta, gamma, n, out):
    """out[i] = kernel(x[i], y[i], alpha, beta, gamma, n) (compiled by :func:`_points_loop`)."""
    for i in range(x.shape[0]):
        out[i] = kernel(x[i], y[i], alpha, beta, gamma, n)


def _box_ratio(well: Well, b: float) -> tuple[float, tuple[float, float]]:
    """The largest wall ratio over the start box [-b, b]^2 and where it is (see
    :meth:`RunSettings.check_box`); inf where the ratios overflow."""
    try:
        return max((well.wall_ratio(*p), p) for p in ((b, b), (b, 0.0), (0.0, b)))
    except OverflowError:
        return math.inf, (b, b)


@functools.lru_cache(maxsize=1024)
def _shape_reach(shape: str, c: float, alpha: float, beta: float, gamma: float, n: int):
    """The shape's generated ``reach`` (a golden-section search in Python, about 1 ms),
    remembered: every ``simulate`` call asks for the same few energies."""
    return _shapes.bundle(shape).reach(c, alpha, beta, gamma, n)


@functools.cache
def _points_loop():
    """:func:`_on_points` compiled by numba, the kernel a first-class function argument so
    one machine code serves every shape (cached on disk)."""
    import numba
    from numba import types

    f64, i64 = types.float64, types.int64
    kernel = types.FunctionType(f64(f64, f64, f64, f64, f64, i64))
    signature = types.void(kernel, f64[::1], f64[::1], f64, f64, f64, i64, f64[::1])
    return numba.njit(signature, cache=True)(_on_points)


@dataclass(frozen=True)
class Well:
    """The soft-wall potential well V(x, y) (paper eqs. V definition / V definition2).

    Parameters
    ----------
    alpha : float > 0
        Sets the wall distance alpha - beta on the x axis.
    beta : float, < alpha
        Half the wall curvature at y = 0: beta > 0 bulges inward (Sinai-like),
        beta < 0 focuses (stadium-like).
    n : int in [1, 1000]
        Wall stiffness; rigid walls as n -> oo.
    gamma : float > 0
        Strength of the well.
    shape : one of :data:`SHAPES`
        ``"flat"``: gamma/(2n) [(x/D(y))^2n + y^2n]; ``"symmetric"``:
        gamma/(2n) [(x/D(y))^2n + (y/D(x))^2n], with D(s) = alpha + beta (s^2 - 1);
        ``"circular"``: gamma/(2n) (r / (alpha - beta))^2n, a round well of radius
        alpha - beta (alpha and beta enter only through it).  Each shape is defined
        once in :mod:`sinktheory.symbolic`; :attr:`kernels` is its generated bundle.

    Examples
    --------
    >>> well = Well(0.5, 0.3, 4, shape="circular")
    >>> well.kernels.NAME, round(well.reach(0.125)[0], 12)  # c = 1: the radius 0.2
    ('circular', 0.2)
    """

    alpha: float
    beta: float
    n: int
    gamma: float = 1.0
    shape: str = "flat"

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        set_(self, "alpha", v.positive("alpha", self.alpha))
        set_(self, "beta", v.finite("beta", self.beta))
        set_(self, "n", v.positive_int("n", self.n, maximum=MAX_N))
        set_(self, "gamma", v.positive("gamma", self.gamma))
        set_(self, "shape", v.choice("shape", self.shape, SHAPES))
        if self.alpha - self.beta <= 0:
            raise ParameterError(
                "beta",
                self.beta,
                f"< alpha = {self.alpha!r}",
                why="the wall distance alpha - beta must be > 0",
            )
        scale = max(self.alpha, abs(self.beta))
        if self.alpha - self.beta < MIN_RELATIVE_WALL_DISTANCE * scale:
            limit = self.alpha - MIN_RELATIVE_WALL_DISTANCE * scale
            raise ParameterError(
                "beta",
                self.beta,
                f"<= {limit!r} (alpha - beta >= {MIN_RELATIVE_WALL_DISTANCE:g} x "
                f"max(alpha, |beta|))",
                why=f"the wall distance alpha - beta = {self.alpha - self.beta:.3g} would be "
                "lost to rounding in D(s) = alpha + beta (s^2 - 1)",
            )

    # --- geometry -------------------------------------------------------------------
    @property
    def wall_distance(self) -> float:
        """alpha - beta: distance from the centre to the wall along x (rigid limit)."""
        return float(_denominator(0.0, self.alpha, self.beta))

    @property
    def kernels(self):
        """The shape's kernel bundle (module of :mod:`sinktheory._generated.shapes`):
        ``potential``, ``gradient``, ``hessian``, ``hill_coefficient``, geometry."""
        return _shapes.bundle(self.shape)

    @property
    def curvature_at_centre(self) -> float:
        """Curvature of the rigid wall at y = 0 (paper eq. kappa: 2 beta for the flat and
        symmetric wells; -1/(alpha - beta) for the circular one)."""
        return self.curvature(0.0)

    def curvature(self, y: float) -> float:
        """Curvature of the rigid-wall contour (n -> oo) at height y (generated kernel)."""
        try:
            return self.kernels.wall_curvature(v.finite("y", y), self.alpha, self.beta)
        except OverflowError:
            raise NumericalError(f"Well.curvature: overflow at y = {y!r}") from None

    def denominator(self, s):
        """D(s) = alpha + beta (s^2 - 1); accepts scalars or arrays of finite numbers."""
        with np.errstate(over="ignore"):
            d = _denominator(v.finite_array("s", s), self.alpha, self.beta)
        if not np.all(np.isfinite(d)):
            raise NumericalError("Well.denominator: D(s) overflows float range (|s| > 1e150)")
        return d

    def potential(self, x, y) -> np.ndarray:
        """V(x, y) at arrays of finite points (relative to the container), broadcast
        together; +inf where V overflows float range, far beyond the walls (the answer
        :meth:`sinktheory.model.RunSettings.check_box` reads as outside).

        The shape's compiled kernel in a compiled loop over the points (calling it once per
        point from Python cost 20 ms of every ``simulate`` call in the step search)."""
        x, y = v.points(x, y)
        out = np.empty(x.size)
        _points_loop()(
            self.kernels.potential, np.ascontiguousarray(x).ravel(),
            np.ascontiguousarray(y).ravel(), float(self.alpha), float(self.beta),
            float(self.gamma), int(self.n), out,
        )  # fmt: skip
        return out.reshape(x.shape)

    # --- what a particle of energy E can reach -----------------------------------------
    @renamed(energy="particle_energy")
    def reach(
        self, particle_energy: float, *, name: str = "particle_energy"
    ) -> tuple[float, float]:
        """Bounds (x_max, y_max) on |x| and |y| over the basin V <= E around the centre of
        a particle of energy E = ``particle_energy``.

        Checks that the well confines that energy (below the shape's escape energy, such
        as the corner saddle of the symmetric well) with positive wall denominators
        everywhere in the basin (see :meth:`check_energy`); a refusal names ``name``, the
        parameter the energy came from.  The bounds are the shape's generated ``reach``.

        Examples
        --------
        >>> Well(alpha=0.5, beta=0.3, n=2).reach(0.5)  # doctest: +ELLIPSIS
        (0.5..., 1.189...)
        """
        energy = particle_energy
        e = v.positive(name, energy)
        # 2 n E / gamma = c^(2n): bounded by float range and by the reach c (log10 scale)
        exponents = (math.log10(MAX_SCALED_ENERGY), 2 * self.n * math.log10(MAX_REACH))
        if math.log10(2 * self.n) + math.log10(e) - math.log10(self.gamma) > min(exponents):
            top = 10 ** min(exponents)
            why = (
                "above it the wall terms (x/D)^(2n) of the potential overflow float range"
                if exponents[0] <= exponents[1]
                else f"above it the reach c = (2 n E / gamma)^(1/(2n)) exceeds {MAX_REACH:g}, "
                "far beyond the wall y^(2n) = 1, where the reach is not resolved"
            )
            raise ParameterError(
                name,
                energy,
                f"a finite number in (0, {top * self.gamma / (2 * self.n):.6g}] "
                f"(2 n E / gamma <= {top:.6g})",
                why=why,
            )
        k = self.kernels
        args = (self.alpha, self.beta, self.gamma, self.n)
        if k.ESCAPE_NAME:
            v_escape = float(python_kernel(k.escape_energy)(*args))
            if e >= v_escape:
                raise ParameterError(
                    name,
                    e,
                    f"< {v_escape:.6g}, the height of {k.ESCAPE_NAME} of this {self.shape} well",
                    why="above it a particle escapes through it",
                )
        c = float(_axis_reach_factor(e, self.gamma, self.n))
        x_max, y_max = _shape_reach(self.shape, c, *args)
        for corner in ((x_max, y_max), (x_max, 0.0), (0.0, y_max)):
            if not k.smallest_denominator(*corner, self.alpha, self.beta) > 0:
                self._refuse_denominator(e, corner)
        return x_max, y_max

    def check_position(self, name: str, x: float, y: float) -> None:
        """Raise ParameterError naming ``name`` unless (x, y) is a finite point inside the
        walls: every wall ratio of the shape below 1 (flat: |x| / D(y) and |y|;
        symmetric: |x| / D(y) and |y| / D(x); circular: r / (alpha - beta)).

        Examples
        --------
        >>> Well(0.5, 0.3, 4).check_position("initial", 0.3, 0.0)  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        sinktheory.errors.ParameterError: initial = (0.3, 0.0) is not allowed: must be a \
point inside the walls (wall ratios < 1) (wall ratio 1.5 there)
        """
        allowed = "a point inside the walls (wall ratios < 1)"
        try:
            x, y = float(x), float(y)
        except (TypeError, ValueError):
            raise ParameterError(name, (x, y), allowed) from None
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ParameterError(name, (x, y), allowed)
        try:
            ratio = self.wall_ratio(x, y)
        except OverflowError:
            ratio = math.inf
        if not ratio < 1:
            raise ParameterError(name, (x, y), allowed, why=f"wall ratio {ratio:.3g} there")

    def wall_ratio(self, x: float, y: float) -> float:
        """Largest wall ratio of the shape at the finite point (x, y): < 1 strictly inside
        the walls; it grows beyond them, to +inf where it overflows float range."""
        x, y = v.finite("x", x), v.finite("y", y)
        return self.kernels.wall_ratio(x, y, self.alpha, self.beta)

    @renamed(energy="particle_energy")
    def check_energy(self, particle_energy: float, *, name: str = "particle_energy") -> None:
        """Raise ParameterError naming ``name`` unless a particle holding all of
        ``particle_energy`` stays in a regular well."""
        self.reach(particle_energy, name=name)

    @renamed(energy="particle_energy")
    def summary(self, particle_energy: float = 0.5) -> WellSummary:
        """The well's parameters, walls and the reach of a particle of ``particle_energy``.

        Examples
        --------
        >>> s = Well(0.5, 0.3, 10).summary()
        >>> s.walls, round(s.wall_distance, 12), s.curvature_at_centre
        ('scattering (Sinai-like)', 0.2, 0.6)
        """
        x_max, y_max = self.reach(particle_energy)
        curvature = self.curvature_at_centre
        walls = "straight"
        if curvature != 0:
            walls = "scattering (Sinai-like)" if curvature > 0 else "focusing (stadium-like)"
        return WellSummary(
            self.shape,
            self.alpha,
            self.beta,
            self.n,
            self.gamma,
            self.wall_distance,
            curvature,
            walls,
            float(particle_energy),
            Reach(x_max, y_max),
        )

    def _refuse_denominator(self, energy: float, point: tuple[float, float]) -> None:
        x, y = point
        d = self.kernels.smallest_denominator(x, y, self.alpha, self.beta)
        raise ParameterError(
            "beta",
            self.beta,
            "a value keeping D(s) = alpha + beta (s^2 - 1) > 0 wherever a particle can go",
            why=f"with energy {energy:.6g} a particle reaches (|x|, |y|) = ({x:.6g}, {y:.6g}), "
            f"where D = {d:.6g}",
        )


@renamed(energy="particle_energy")
def confining_betas(
    alpha: float,
    n: int,
    particle_energy: float,
    *,
    gamma: float = 1.0,
    shape: str = "flat",
    lo: float = -5.0,
    hi: float | None = None,
    points: int = 2001,
) -> list[tuple[float, float]]:
    """Intervals of beta in [lo, hi] for which the well holds a particle of
    ``particle_energy``.

    A beta is valid when :class:`Well` accepts it and :meth:`Well.check_energy` passes
    (positive denominator within reach; below the corner saddle for the symmetric
    shape).  The grid is refined at each change of validity by bisection to 1e-12.

    Examples
    --------
    >>> [(round(float(a), 4), round(float(b), 4))
    ...  for a, b in confining_betas(1.0, 6, 0.5, shape="symmetric")]
    [(-0.4959, 0.2955), (0.7045, 1.0)]
    """
    Well(alpha, 0.0, n, gamma=gamma, shape=shape)  # checks alpha, n, gamma and shape
    particle_energy = v.positive("particle_energy", particle_energy)
    lo = v.finite("lo", lo)
    hi = alpha if hi is None else v.finite("hi", hi)
    if not lo < hi:
        raise ParameterError("hi", hi, f"a number > lo = {lo:g}")
    points = v.positive_int("points", points, minimum=2, maximum=10**6)

    def ok(beta: float) -> bool:
        try:
            Well(alpha, beta, n, gamma=gamma, shape=shape).check_energy(particle_energy)
        except ParameterError:
            return False
        return True

    grid = np.linspace(lo, hi, points)
    flags = [ok(b) for b in grid]
    intervals: list[tuple[float, float]] = []
    start = float(grid[0]) if flags[0] else None
    for i in range(1, grid.size):
        if flags[i] == flags[i - 1]:
            continue
        a, b = grid[i - 1], grid[i]  # validity changes in (a, b): bisect
        while b - a > 1e-12:
            mid = 0.5 * (a + b)
            if not a < mid < b:  # float resolution reached (a large alpha)
                break
            if ok(mid) == flags[i - 1]:
                a = mid
            else:
                b = mid
        if flags[i]:
            start = float(b)
        else:
            intervals.append((start, float(a)))
            start = None
    if start is not None:
        intervals.append((start, float(grid[-1])))
    return intervals


@dataclass(frozen=True)
class Sink:
    """The container (mass 1, spring 1) holding k particles of total mass m.

    Parameters
    ----------
    well : Well
    particles : int in [1, 1000]
        Number k of non-interacting particles.
    mass : float > 0
        Their total mass m; each particle has mass mu = m / k.
    """

    well: Well
    particles: int = 1
    mass: float = 0.2

    def __post_init__(self) -> None:
        from .wellat import WellAt

        if not isinstance(self.well, Well | WellAt):
            raise ParameterError(
                "well", self.well, "a sinktheory.model.Well or a user's sinktheory.wellat.WellAt"
            )
        particles, mass = self.check_particles(self.particles, self.mass)
        object.__setattr__(self, "particles", particles)
        object.__setattr__(self, "mass", mass)

    @staticmethod
    def check_particles(particles: int, mass: float) -> tuple[int, float]:
        """(k, m) validated: k in [1, 1000], m > 0 and m / k >= :data:`MIN_MU` (also for
        the particles of a user's well, which is not a :class:`Well`).

        Examples
        --------
        >>> Sink.check_particles(4, 0.2)
        (4, 0.2)
        """
        particles = v.positive_int("particles", particles, maximum=1000)
        mass = v.positive("mass", mass)
        if mass / particles < MIN_MU:
            raise ParameterError(
                "mass",
                mass,
                f">= {MIN_MU:g} x particles = {MIN_MU * particles:g}",
                why=f"each particle's mass m / k must be >= {MIN_MU:g}: lighter ones make "
                "the accelerations and the stiffness of the walls overflow",
            )
        return particles, mass

    @property
    def mu(self) -> float:
        """Mass of one particle, m / k."""
        return self.mass / self.particles

    def summary(self, settings: RunSettings) -> SinkSummary:
        """The set-up of an ensemble run: masses, energies, run size and the reach of a
        particle at the total energy bound (``settings`` checked against this sink first).

        Examples
        --------
        >>> Sink(Well(0.5, 0.3, 4), particles=5).summary(RunSettings()).mu
        0.04
        """
        if not isinstance(settings, RunSettings):
            raise ParameterError("settings", type(settings).__name__, "a RunSettings")
        settings.check(self)
        e_total = settings.total_energy_bound(self)
        return SinkSummary(
            self.particles,
            self.mass,
            self.mu,
            settings.container_energy,
            e_total,
            settings.runs,
            settings.periods,
            settings.seed,
            Reach(*self.well.reach(e_total)),
        )


@renamed(energy="container_energy")
@dataclass(frozen=True)
class RunSettings:
    """How an ensemble is started and how long it runs.

    Parameters
    ----------
    container_energy : float > 0
        Initial energy E0 of the container (0.5: displaced to X = 1 and released).
    runs : int >= 1
        Ensemble size R.
    periods : int >= 1
        Number of container periods T = 2 pi to integrate.
    seed : int >= 0
        Seed of the random initial positions; the same seed gives the same runs.
    box : float > 0
        Half-width of the square (-box, box)^2 around the centre where particles start.
    """

    container_energy: float = 0.5
    runs: int = 25
    periods: int = 1500
    seed: int = 0
    box: float = 0.01

    energy = old_attribute("container_energy")

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        set_(self, "container_energy", v.positive("container_energy", self.container_energy))
        set_(
            self,
            "runs",
            v.positive_int("runs", self.runs, maximum=MAX_RUNS, why=_runs_cost),
        )
        set_(
            self,
            "periods",
            v.positive_int("periods", self.periods, maximum=MAX_PERIODS, why=_periods_cost),
        )
        set_(self, "seed", v.positive_int("seed", self.seed, minimum=0))
        set_(self, "box", v.positive("box", self.box))

    def total_energy_bound(self, sink: Sink) -> float:
        """Upper bound of the total energy: E0 plus k times V at the box's corner (for a
        user's well, the largest V - V(0, 0) on a grid of the box)."""
        self._sink(sink)
        if isinstance(sink.well, Well):
            corner = float(sink.well.potential(self.box, self.box))
        else:
            corner = sink.well.box_potential(self.box)
        return self.container_energy + sink.particles * corner

    def check(self, sink: Sink) -> None:
        """Raise ParameterError unless the particles start inside the walls, every
        particle stays in a regular part of the well, and the ensemble fits in memory."""
        self.check_box(self._sink(sink).well)
        bound = self.total_energy_bound(sink)
        try:
            sink.well.check_energy(bound)
        except ParameterError as e:  # name what the user gave: E0, not the bound
            raise ParameterError(
                "container_energy",
                self.container_energy,
                "an energy the well holds",
                why=f"the total energy bound E0 + k V(box corner) = {bound:.6g} is refused: {e}",
            ) from None
        self.check_memory(sink)

    def check_box(self, well: Well) -> None:
        """Raise ParameterError unless the start box (-box, box)^2 lies inside the walls.

        Each wall ratio of a shape is a coordinate's modulus over a denominator
        alpha + beta (s^2 - 1) of the other coordinate s (or over alpha - beta), so over the
        box it is largest where the modulus is ``box`` and s is 0 or ``box``: the box lies
        inside when the ratios at (box, box), (box, 0) and (0, box) are all below 1.  (The
        corner alone is not enough: in the symmetric well with beta > 0 the corner of
        box = 10 lies inside, the wall ratio is 50 at (10, 0).)  A box so large that its
        ratios overflow float range is refused too.

        Examples
        --------
        >>> RunSettings(box=10).check_box(Well(0.5, 0.3, 4, shape="symmetric"))
        Traceback (most recent call last):
        ...
        sinktheory.errors.ParameterError: box = 10.0 is not allowed: must be < 0.2, inside the \
walls of the well (the start box reaches wall ratio 50 >= 1 at (10, 0) (wall distance \
alpha - beta = 0.2))
        """
        if not isinstance(well, Well):  # a user's well: V on the box's edge
            if not callable(getattr(well, "check_box", None)):
                raise ParameterError("well", type(well).__name__, "a Well or a user's WellAt")
            return well.check_box(self.box)
        ratio, where = _box_ratio(well, self.box)
        if not ratio < 1:
            wall = well.wall_distance
            # the largest box inside: the box's ratio grows with its size, so bisect on it
            lo, hi = 0.0, min(wall, 1.0)
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if _box_ratio(well, mid)[0] < 1 else (lo, mid)
            raise ParameterError(
                "box",
                self.box,
                f"< {hi:.6g}, inside the walls of the well",
                why=f"the start box reaches wall ratio {ratio:.3g} >= 1 at "
                f"({where[0]:g}, {where[1]:g}) (wall distance alpha - beta = {wall:.3g})",
            )

    @staticmethod
    def _sink(sink: object, needs: tuple[str, ...] = ("well", "particles")) -> Sink:
        """``sink`` if it has the attributes ``needs`` of a :class:`Sink` (the package
        passes stand-ins holding ``particles`` alone), else a ParameterError naming it."""
        if not all(hasattr(sink, name) for name in needs):
            raise ParameterError("sink", type(sink).__name__, "a Sink")
        return sink

    @staticmethod
    def _record(record: object) -> None:
        """A ParameterError unless ``record`` is a tuple or list of record names."""
        if not isinstance(record, tuple | list) or not all(isinstance(r, str) for r in record):
            raise ParameterError("record", record, "a tuple of names ('container', 'particles')")

    def memory_bytes(self, sink: Sink, record: tuple[str, ...] = ("container",)) -> int:
        """Bytes the ensemble's state and ``record`` take (estimate: the state three
        times, one float per run and period for ``container``, k for ``particles``)."""
        self._sink(sink, ("particles",)), self._record(record)
        state = 3 * self.runs * (2 + 4 * sink.particles) * 8
        per_period = {"container": 1, "particles": sink.particles}
        records = sum(per_period.get(r, 0) for r in record)
        return state + self.runs * (self.periods + 1) * records * 8

    def check_memory(self, sink: Sink, record: tuple[str, ...] = ("container",)) -> None:
        """Raise ParameterError (naming runs or periods, whichever is larger) when the
        ensemble would need more than half of this machine's memory."""
        self._sink(sink, ("particles",)), self._record(record)
        name = "periods" if self.periods > self.runs else "runs"
        per_period = {"container": 1, "particles": sink.particles}
        records = max(1, sum(per_period.get(r, 0) for r in record))
        other = self.runs if name == "periods" else self.periods + 1
        largest = max(1, v.memory_limit() // (8 * records * other) - (name == "periods"))
        v.fits_memory(
            name,
            getattr(self, name),
            self.memory_bytes(sink, record),
            f"{self.runs} run(s) x {self.periods} period(s) of {sink.particles} particle(s)",
            f"<= {largest} with {'runs' if name == 'periods' else 'periods'} = "
            f"{getattr(self, 'runs' if name == 'periods' else 'periods')}",
        )


def _runs_cost(runs: int) -> str:
    r = _float(runs)
    return (
        f"seeding {r:.3g} runs alone takes about {r * 2e-6:.3g} s and their states "
        f"at least {v.nbytes_text(r * 48.0)}"
    )


def _periods_cost(periods: int) -> str:
    p = _float(periods)
    return (
        f"one run's energy record of {p:.3g} periods takes {v.nbytes_text(p * 8.0)}, and "
        f"at >= 100 steps per period its integration about {p * 100 * 1e-7:.3g} s"
    )


def _float(i: int) -> float:
    try:
        return float(i)
    except OverflowError:
        return math.inf


# --- summaries (results of ``sinktheory well`` and ``sinktheory sink``) ------------------
@dataclass(frozen=True)
class Reach(Result):
    """Bounds on |x| and |y| of a particle of given energy (:meth:`Well.reach`)."""

    x: float
    y: float


@dataclass(frozen=True)
class WellSummary(Result):
    """What :meth:`Well.summary` reports: the parameters, the wall distance alpha - beta,
    the rigid wall's curvature at y = 0 and its kind (``walls``: scattering, focusing or
    straight, from the curvature's sign) and the reach of a particle of ``particle_energy``."""

    shape: str
    alpha: float
    beta: float
    n: int
    gamma: float
    wall_distance: float
    curvature_at_centre: float
    walls: str
    particle_energy: float
    reach: Reach


@dataclass(frozen=True)
class SinkSummary(Result):
    """What :meth:`Sink.summary` reports: k, m, mu = m / k, the container energy E0, the
    bound on the total energy, runs, periods, seed, and the reach at that bound."""

    particles: int
    mass: float
    mu: float
    container_energy: float
    total_energy_bound: float
    runs: int
    periods: int
    seed: int
    reach: Reach


@dataclass(frozen=True)
class UserWellSummary(Result):
    """What :func:`user_well_summary` reports of a user's well at its parameter values:
    the potential, how its minimum at the centre and its escape energy (measured from
    V(0, 0)) were found, whether y = 0 is a normal mode (and why), its wall ratios, and the
    reach of a particle of ``particle_energy`` (measured from V(0, 0))."""

    name: str
    potential: str
    parameters: dict
    minimum: str
    escape_energy: float
    escape: str
    y_invariant: bool
    normal_mode: str
    wall_ratios: list
    particle_energy: float
    reach: Reach


def user_well_summary(
    well, particle_energy: float = 0.5, values=None, *, well_check=None
) -> UserWellSummary:
    """The :class:`UserWellSummary` of a user's well (a
    :class:`~sinktheory.userwell.UserWell`) at its parameter ``values`` by name (its
    defaults for the others); ``well_check``: its
    :func:`~sinktheory.userwell.check_well` at those values, if already run.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> s = user_well_summary(UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {}), 0.1)
    >>> round(s.escape_energy * 6, 12), s.y_invariant, round(s.reach.y, 9)  # y^2/2 - y^3/3 = 0.1
    (1.0, False, 0.567068923)
    """
    from .userwell import UserWell, well_report

    if not isinstance(well, UserWell):
        raise ParameterError("well", well, "a sinktheory.userwell.UserWell")
    given, report = well_report(well, values, well_check)
    basin = report.basin
    e = basin.check_energy(particle_energy)
    r = basin.reach(basin.well.v0 + e)
    return UserWellSummary(
        name=well.name,
        potential=str(well.potential),
        parameters={name: float(value) for name, value in report.values.items()},
        minimum=report.minimum,
        escape_energy=basin.escape_energy,
        escape=report.confinement,
        y_invariant=report.y_invariant,
        normal_mode=report.y_invariant_reason,
        wall_ratios=[str(ratio) for ratio in well.wall_ratios],
        particle_energy=e,
        reach=Reach(float(r.x_max), float(r.y_max)),
    )
