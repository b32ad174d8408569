"""Pseudo-arclength continuation of periodic orbits in energy or a system parameter.

A branch is a curve u(s) of solutions of the shooting equations G(u) = 0 of
:class:`~sinktheory.nnm.shooting.ShootingProblem`, u = (z0[free], ln T, sigma, lam),
with lam = ln h (energy h) or a well parameter (alpha, beta, gamma, mu) at fixed energy.
Each step predicts u + ds t along the unit tangent t (the null vector of the Jacobian
dG/du, oriented to continue the previous one) and corrects with Newton on G = 0 plus
Keller's arclength equation t . (u - u_pred) = 0, so folds (lam turning back) are passed
without trouble.  ds adapts to the number of Newton iterations.

Along the branch every point carries its period, frequency, energy, all Floquet
multipliers (full monodromy, in-plane nontrivial and transverse sets), the distance of
the trivial pair from 1, and the stability.  Events are detected from sign changes of
the test functions of :mod:`sinktheory.nnm.stability` between consecutive points and
located by the Illinois (regula falsi) method on the arclength from the earlier point:

* ``fold``: d lam / ds changes sign;
* ``period-doubling``: a nontrivial in-plane multiplier crosses -1;
* ``transverse-period-doubling``: a transverse multiplier crosses -1;
* ``symmetry-breaking``: a transverse multiplier crosses +1 (orbits leaving the
  invariant plane branch off);
* ``branch-point``: an in-plane multiplier crosses +1 away from a fold.

Pairs that reach -1 or +1 and turn back within one step leave the test functions with
the same sign at both ends.  Steps are therefore rejected and halved while a multiplier
turns by more than MAX_TURN (rotation angle, :func:`~sinktheory.nnm.stability.angles`),
and each interior point where a multiplier set's margin
(:meth:`~sinktheory.nnm.stability.Floquet.margins`, the signed distance of the nearest
pair from -1 or +1) is a local minimum of its absolute value, with the parabola through
it and its neighbours heading at least half-way to 0, is refined: Brent's method
minimises the margin along the arclength (each trial point corrected onto the branch).
A minimum within TOUCH_TOL of 0 is reported as ``<kind>-touch`` (e.g.
``transverse-period-doubling-touch``: a transverse pair touching -1); a minimum below
-TOUCH_TOL means a window off the unit circle inside the step, reported as its two
crossings (two ``<kind>`` events located by Brent's root finder).

:func:`switch_branch` starts the period-2T branch at a period doubling (or the
symmetry-broken branch at a symmetry-breaking point) from the critical eigenvector.

Examples
--------
>>> import numpy as np
>>> from sinktheory.nnm.system import FlowSystem
>>> s = FlowSystem("duffing2", [])
>>> b = continue_orbits(s, np.array([0.1, 0.1, 0, 0]), 2 * np.pi, steps=64,
...                     total_energy=0.01, interval=(1e-3, 0.1), ds=0.3, max_points=30)
>>> b.stop_reason, bool(b.frequency[-1] > b.frequency[0])  # hardening spring
('parameter left [0.001, 0.1]', True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from .. import validation as v
from ..errors import ParameterError
from ..glossary import old_attribute, refusals_named, renamed
from ..worklimit import check_particle_steps, ensemble_steps
from .shooting import (
    Orbit,
    ShootingError,
    ShootingProblem,
    checked_start,
    checked_steps,
    subspace_indices,
)
from .stability import angles, classify
from .system import FlowSystem

__all__ = [
    "POINT_STEPS",
    "Branch",
    "check_ds",
    "continue_both",
    "continue_orbits",
    "DS_MIN_FACTOR",
    "DS_RANGE",
    "Event",
    "LOCATE_ITER",
    "MAX_POINTS",
    "MAX_TURN",
    "switch_branch",
    "TOUCH_TOL",
]

#: Arclength-step limits relative to the initial step.
DS_MIN_FACTOR = 1e-4
#: First arclength steps accepted: below 1e-6 the smallest step (x DS_MIN_FACTOR) nears
#: the corrector's tolerance (XTOL = 1e-11) and a branch would not move; above 10 one
#: step spans e^10 in energy, more than any continuation range.
DS_RANGE = (1e-6, 10.0)
#: Most points of one branch.
MAX_POINTS = 100_000


def check_ds(ds, name: str = "ds") -> float:
    """An arclength step inside :data:`DS_RANGE`.

    Examples
    --------
    >>> check_ds(0.1)
    0.1
    >>> check_ds(1e-300)
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: ds = 1e-300 is not allowed: must be a number in [1e-06, 10]
    """
    lo, hi = DS_RANGE
    x = v.positive(name, ds)
    if not lo <= x <= hi:
        raise ParameterError(name, ds, f"a number in [{lo:g}, {hi:g}]")
    return x


def check_stop(stop, name: str = "stop") -> tuple[float, float]:
    """(lo, hi) of a continuation: two numbers, not NaN, lo < hi (hi may be inf); refused
    naming ``name``."""
    allowed = "two numbers (lo, hi) with lo < hi, not NaN"
    try:
        lo, hi = (float(x) for x in stop)
    except (TypeError, ValueError):
        raise ParameterError(name, stop, allowed) from None
    if any(v._is_bool(x) for x in stop) or not lo < hi:  # NaN compares False
        raise ParameterError(name, stop, allowed)
    return lo, hi


#: Iterations of the event location.
LOCATE_ITER = 30
#: Largest change of a multiplier's rotation angle over one step (radians).
MAX_TURN = 0.5
#: A margin (half-trace units) within this of 0 at its minimum is a touch of -1 or +1.
TOUCH_TOL = 1e-7


@dataclass
class Event:
    """A bifurcation or fold located on a branch.

    kind : see the module docstring; index : the branch point before it;
    value : the continuation parameter there (energy, not ln energy); orbit : the
    orbit at the event; multiplier : the critical multiplier (nan for a fold).
    """

    kind: str
    index: int
    value: float
    orbit: Orbit = field(repr=False)
    multiplier: complex = complex("nan")


@dataclass
class Branch:
    """A continued family of periodic orbits (labelled arrays: :mod:`sinktheory.nnm.result`)."""

    problem: ShootingProblem = field(repr=False)
    orbits: list[Orbit] = field(default_factory=list, repr=False)
    tangents: list[np.ndarray] = field(default_factory=list, repr=False)
    events: list[Event] = field(default_factory=list)
    stop_reason: str = ""

    @property
    def continue_in(self) -> str:
        return self.problem.continue_in

    parameter = old_attribute("continue_in")

    @property
    def values(self) -> np.ndarray:
        """The continuation parameter at each point (energy, or the well parameter)."""
        lam = np.array([o.u[-1] for o in self.orbits])
        return np.exp(lam) if self.continue_in == "energy" else lam

    @property
    def total_energy(self) -> np.ndarray:
        """The total energy H of each orbit."""
        return np.array([o.total_energy for o in self.orbits])

    energy = old_attribute("total_energy")

    @property
    def period(self) -> np.ndarray:
        return np.array([o.period for o in self.orbits])

    @property
    def frequency(self) -> np.ndarray:
        return 2 * math.pi / self.period

    @property
    def stable(self) -> np.ndarray:
        return np.array([o.floquet.stable for o in self.orbits])

    def result(self, **meta):
        """Labelled arrays of this branch (:class:`~sinktheory.nnm.result.BranchResult`)."""
        from .result import BranchResult

        return BranchResult._from_branch(self, **meta)


def tangent(J: np.ndarray, previous: np.ndarray | None = None) -> np.ndarray:
    """Unit null vector of the (n, n + 1) Jacobian, oriented along ``previous``."""
    _, _, vt = np.linalg.svd(J)
    t = vt[-1]
    if previous is not None and t @ previous < 0:
        t = -t
    return t / np.linalg.norm(t)


def _scaled_jacobian(problem: ShootingProblem, u: np.ndarray, J: np.ndarray):
    usc, gsc = problem.scales(u)
    return (J * usc) / gsc[:, None], usc


def _dot(a: np.ndarray, b: np.ndarray, usc: np.ndarray) -> float:
    """Inner product of two tangents in scaled unknowns (the arclength metric)."""
    return float((a / usc) @ (b / usc))


def _orient(t: np.ndarray, usc: np.ndarray) -> np.ndarray:
    """A tangent in scaled unknowns back to plain ones (unit length in scaled units)."""
    return t * usc


#: Particle steps a continuation point costs beyond its integrations (the predictor,
#: the corrector's Newton iterations and the event tests, in Python).  On duffing2 (2-core
#: AVX-512 Xeon, load 1-2, 2026-11-26, ``python benchmarks/bench_estimates.py --only
#: continue_orbits``) a point took 3.4e-3-6.8e-3 s at 64-1024 steps a period (later points
#: of a branch cost more), while ensemble_steps alone priced it at 2.8e-4 s at 64 steps:
#: 13-17x optimistic.  80000 (9.6e-3 s at SECONDS_PER_PARTICLE_STEP) is above the dearest:
#: the work took 0.39-0.69 of it (load 1).
POINT_STEPS = 80000.0


@renamed(parameter="continue_in", energy="total_energy", stop="interval")
def continue_orbits(
    system: FlowSystem,
    z0,
    T: float,
    *,
    steps: int,
    continue_in: str = "energy",
    total_energy: float | None = None,
    interval: tuple[float, float] = (0.0, math.inf),
    ds: float = 0.1,
    ds_max: float | None = None,
    max_points: int = 200,
    direction: int = 1,
    subspace: str | None = None,
    phase: str = "velocity",
    phase_index: int = 0,
    locate: bool = True,
) -> Branch:
    """Find the orbit near (z0, T) and continue it in ``continue_in``.

    Parameters
    ----------
    system : FlowSystem
    z0, T : start guess (state (2D,), period)
    steps : int
        Steps per period N (fixed along the branch).
    continue_in : "energy" (the total energy) or a system parameter name ("alpha", "beta",
        "gamma", "mu")
    total_energy : float, optional
        Total energy of the first orbit (and of the whole branch when continuing in a
        parameter); default H(z0).
    interval : (lo, hi)
        The branch ends when the parameter (energy itself, not its logarithm) leaves
        [lo, hi].
    ds, ds_max : float
        First and largest arclength step, in scaled unknowns (ln h for the energy).
    max_points : int
    direction : +1 or -1
        Initial direction of the parameter.
    subspace, phase, phase_index : see :func:`sinktheory.nnm.shooting.shoot`.
    locate : bool
        Locate events by root finding (else the first point past the event is used).

    Returns
    -------
    Branch
    """
    z0, h = checked_start(system, z0, total_energy)
    steps, T = checked_steps(steps, T)
    if isinstance(direction, bool) or direction not in (1, -1):
        raise ParameterError("direction", direction, "+1 or -1")
    lo, hi = check_stop(interval, "interval")
    ds = check_ds(ds)
    ds_max = None if ds_max is None else check_ds(ds_max, "ds_max")
    if ds_max is not None and not ds_max >= ds:
        raise ParameterError("ds_max", ds_max, f">= ds = {ds:g} (the largest step)")
    max_points = v.positive_int("max_points", max_points, maximum=MAX_POINTS)
    _check_work("steps", steps, system, steps, max_points)
    free = subspace_indices(system, subspace)
    with refusals_named(parameter="continue_in"):
        problem = ShootingProblem(
            system, steps, free, z0, continue_in, h, phase, phase_index, phase_ref=z0.copy()
        )
    start = h if continue_in == "energy" else problem.lam(system, h)
    if not lo <= start <= hi:  # the branch would end at its first point (with NaN phi)
        raise ParameterError("interval", interval, f"an interval containing the start's "
                             f"{continue_in} = {start:.6g}")  # fmt: skip
    u = problem.pack(z0, T, 0.0, problem.lam(system, h))
    u, J, data, it = problem.newton(u)
    first = problem.orbit(u, data, it)
    return _continue(problem, first, J, ds, ds_max, max_points, direction, lo, hi, locate)


def _check_work(name: str, value, system: FlowSystem, steps: int, max_points: int) -> None:
    """Refuse (naming ``name`` = ``value``) a branch of ``max_points`` points at ``steps``
    steps a period that could not finish within the work limit."""
    work = ensemble_steps(1, 2 * max_points * steps, system.members or 1, 2 * system.dim)
    check_particle_steps(
        name, value, work + max_points * POINT_STEPS, f"{max_points} point(s) x {steps} "
        f"step(s) per period, each shooting at least twice with {2 * system.dim} tangent "
        f"vectors, plus {POINT_STEPS:.0f} particle steps a point for its Newton iterations"
    )  # fmt: skip


def _continue(problem, first, J, ds, ds_max, max_points, direction, lo, hi, locate, t0=None):
    """Continue from a converged orbit ``first`` (Jacobian J) with step ``ds``."""
    ds_max = 10 * ds if ds_max is None else float(ds_max)
    ds_min = ds * DS_MIN_FACTOR
    branch = Branch(problem)
    A, usc = _scaled_jacobian(problem, first.u, J)
    ts = tangent(A)
    t = _orient(ts, usc)
    if t0 is not None:
        if _dot(t, t0, usc) < 0:
            t = -t
    elif t[-1] * direction < 0:
        t = -t
    branch.orbits.append(first)
    branch.tangents.append(t)
    u = first.u
    tests = first.floquet.tests()
    while len(branch.orbits) < max_points:
        value = _value(problem, u[-1])
        if not lo <= value <= hi:
            branch.stop_reason = f"parameter left [{lo:g}, {hi:g}]"
            break
        try:
            un, Jn, data, it = _corrector(problem, u, t, ds)
        except ShootingError:
            ds *= 0.5
            if ds < ds_min:
                branch.stop_reason = "step size below its minimum (corrector failed)"
                break
            continue
        orbit = problem.orbit(un, data, it)
        if _turn(branch.orbits[-1].floquet, orbit.floquet) > MAX_TURN and ds / 2 >= ds_min:
            ds *= 0.5  # a pair could swing through -1 or +1 and back unseen
            continue
        A, usc = _scaled_jacobian(problem, un, Jn)
        tn = _orient(tangent(A), usc)
        if _dot(tn, t, usc) < 0:
            tn = -tn
        new_tests = orbit.floquet.tests()
        fold = np.sign(tn[-1]) != np.sign(t[-1]) and t[-1] != 0
        for kind in classify(tests, new_tests, fold):
            if kind == "fold":
                f0, f1 = float(t[-1]), float(tn[-1])
            else:
                f0, f1 = tests[_TEST_KEY[kind]], new_tests[_TEST_KEY[kind]]
            index = len(branch.orbits) - 1
            branch.events.append(_locate(problem, index, u, t, f0, un, f1, orbit, kind, locate))
        branch.orbits.append(orbit)
        branch.tangents.append(tn)
        if len(branch.orbits) >= 3:
            branch.events.extend(_touches(problem, branch, len(branch.orbits) - 2))
        u, t, tests = un, tn, new_tests
        ds = min(ds_max, ds * (1.6 if it <= 3 else 1.0 if it <= 5 else 0.6))
    else:
        branch.stop_reason = f"{max_points} points"
    branch.events.sort(key=lambda e: e.index)
    return branch


def _turn(a, b) -> float:
    """Largest change of the multipliers' rotation angles between two Floquet sets."""
    turns = [0.0]
    for x, y in ((a.nontrivial, b.nontrivial), (a.transverse, b.transverse)):
        if x.size and x.size == y.size:
            turns.append(float(np.max(np.abs(angles(x) - angles(y)))))
    return max(turns)


def _value(problem: ShootingProblem, lam: float) -> float:
    return math.exp(lam) if problem.continue_in == "energy" else lam


def _normal(problem: ShootingProblem, u: np.ndarray, t: np.ndarray) -> np.ndarray:
    """The arclength hyperplane's normal in plain unknowns: t / scales^2 (scaled metric)."""
    usc, _ = problem.scales(u)
    with np.errstate(over="ignore"):  # a scale beyond 1e154: that component's weight is 0
        return t / usc**2


def _corrector(problem: ShootingProblem, u: np.ndarray, t: np.ndarray, ds: float, max_iter=12):
    """Newton from the predictor u + ds t with t . (u' - u_pred) = 0 in scaled units.

    Near a branch point the augmented Jacobian is nearly singular and Newton slows down
    to linear convergence; the location of events allows more iterations.
    """
    up = u + ds * t
    return problem.newton(up, extra=(_normal(problem, u, t), up), max_iter=max_iter)


_TEST_KEY = {
    "period-doubling": "inplane_minus",
    "transverse-period-doubling": "transverse_minus",
    "symmetry-breaking": "transverse_plus",
    "branch-point": "inplane_plus",
}


_KIND = {key: kind for kind, key in _TEST_KEY.items()}


def _touches(problem: ShootingProblem, branch: Branch, i: int) -> list[Event]:
    """Touches of -1 / +1 (and windows off the unit circle) inside the steps around point
    ``i`` that the sign tests cannot see (see the module docstring)."""
    orbits, tangents = branch.orbits[i - 1 : i + 2], branch.tangents[i - 1]
    u0 = orbits[0].u
    normal = _normal(problem, u0, tangents)
    s = np.array([float(normal @ (o.u - u0)) / float(normal @ tangents) for o in orbits])
    found = [(e.kind, e.index) for e in branch.events]
    out = []
    for key, kind in _KIND.items():
        g = np.array([o.floquet.margins()[key] for o in orbits])
        sign = np.sign(g[1])
        if not (np.all(np.isfinite(g)) and sign != 0 and np.all(np.sign(g) == sign)):
            continue
        if not (abs(g[1]) < abs(g[0]) and abs(g[1]) < abs(g[2])):
            continue
        near = {(k, j) for k in (kind, "fold") for j in (i - 1, i)}
        if near & set(found) or not s[0] < s[1] < s[2]:
            continue  # a sign test already saw this step, or the parameterisation folds
        if sign * _vertex(s, g) >= 0.5 * abs(g[1]):
            continue  # the parabola does not head towards 0

        def margin(x, key=key, sign=sign):
            un, Jn, data, it = _corrector(problem, u0, tangents, x, max_iter=40)
            o = problem.orbit(un, data, it)
            return sign * o.floquet.margins()[key], o

        try:
            res = minimize_scalar(lambda x: margin(x)[0], bracket=tuple(s), tol=1e-10)
            gmin, omin = margin(res.x)
            if gmin > TOUCH_TOL:
                continue
            if gmin >= -TOUCH_TOL:
                hits = [(res.x, omin, f"{kind}-touch")]
            else:
                hits = []
                for a, b in ((s[0], res.x), (res.x, s[2])):
                    root = brentq(lambda x: margin(x)[0], a, b, xtol=1e-12)
                    hits.append((root, margin(root)[1], kind))
        except (ShootingError, ValueError):
            continue  # a trial point off the branch: keep the sign tests' verdict
        for x, o, name in hits:
            out.append(
                Event(
                    kind=name,
                    index=i - 1 if x < s[1] else i,
                    value=_value(problem, o.u[-1]),
                    orbit=o,
                    multiplier=_critical(kind, o),
                )
            )
    return out


def _vertex(s: np.ndarray, g: np.ndarray) -> float:
    """The extreme value of the parabola through (s_k, g_k), k = 0, 1, 2 (g[1] if flat)."""
    a = np.polyfit(s - s[1], g, 2)
    return float(a[2] - a[1] ** 2 / (4 * a[0])) if a[0] != 0 else float(g[1])


def _test_value(problem, kind, orbit, J, t_ref):
    if kind == "fold":
        A, usc = _scaled_jacobian(problem, orbit.u, J)
        tn = _orient(tangent(A), usc)
        return float(tn[-1] if _dot(tn, t_ref, usc) >= 0 else -tn[-1])
    return orbit.floquet.tests()[_TEST_KEY[kind]]


def _critical(kind: str, orbit: Orbit) -> complex:
    fl = orbit.floquet
    if kind == "fold":
        return complex("nan")
    target = -1.0 if kind.endswith("period-doubling") else 1.0
    pool = fl.transverse if kind.startswith(("transverse", "symmetry")) else fl.nontrivial
    return complex(pool[np.argmin(np.abs(pool - target))])


def _locate(problem, index, u0, t0, f0, u1, f1, orbit1, kind, locate) -> Event:
    """Event between u0 (tangent t0, test value f0) and u1 (f1, ``orbit1``): the Illinois
    method on s, the arclength along t0 from u0."""
    normal = _normal(problem, u0, t0)
    s1 = float(normal @ (u1 - u0)) / float(normal @ t0)
    best = orbit1

    def evaluate(s):
        un, Jn, data, it = _corrector(problem, u0, t0, s, max_iter=40)
        o = problem.orbit(un, data, it)
        return _test_value(problem, kind, o, Jn, t0), o

    if locate:
        a, b, fa, fb = 0.0, s1, f0, f1
        side = 0
        try:
            for _ in range(LOCATE_ITER):
                if fa == fb or abs(b - a) < 1e-9 * abs(s1):
                    break
                s = b - fb * (b - a) / (fb - fa)
                fs, best = evaluate(s)
                if fs == 0:
                    break
                if np.sign(fs) == np.sign(fb):
                    if side == -1:
                        fa *= 0.5
                    b, fb, side = s, fs, -1
                else:
                    a, fa = b, fb
                    b, fb = s, fs
                    if side == 1:
                        fa *= 0.5
                    side = 1
        except ShootingError:
            pass  # keep the last converged estimate
    return Event(
        kind=kind,
        index=index,
        value=_value(problem, best.u[-1]),
        orbit=best,
        multiplier=_critical(kind, best),
    )


@renamed(stop="interval")
def switch_branch(
    branch: Branch,
    event: Event,
    *,
    amplitude: float = 1e-3,
    ds: float = 0.05,
    max_points: int = 50,
    interval: tuple[float, float] = (0.0, math.inf),
    locate: bool = True,
) -> Branch:
    """Start the bifurcating branch at a period doubling or symmetry-breaking ``event``.

    The new orbit is sought at amplitude ``amplitude`` (scaled state units) along the
    critical eigenvector w of the monodromy (multiplier -1: period 2T with 2N steps;
    multiplier +1 of a transverse pair: same period, out of the invariant plane), by
    Newton on the shooting equations plus w . (z0 - z0* - amplitude w) = 0, then
    continued by :func:`continue_orbits`' stepper.

    Raises
    ------
    ParameterError
        For events of other kinds.
    ShootingError
        If the new orbit cannot be found.
    """
    if not isinstance(branch, Branch):
        raise ParameterError("branch", branch, "a Branch of continue_orbits")
    if not isinstance(event, Event):
        raise ParameterError("event", event, "an Event of a branch")
    if event.kind not in ("period-doubling", "transverse-period-doubling", "symmetry-breaking"):
        raise ParameterError("event", event.kind, "a period doubling or a symmetry-breaking point")
    amplitude = v.positive("amplitude", amplitude)
    ds = check_ds(ds)
    max_points = v.positive_int("max_points", max_points, maximum=MAX_POINTS)
    interval = check_stop(interval, "interval")
    old = branch.problem
    orbit = event.orbit
    target = 1.0 if event.kind == "symmetry-breaking" else -1.0
    mu, vec = np.linalg.eig(orbit.monodromy)
    k = int(np.argmin(np.abs(mu - target)))
    w = np.real(vec[:, k])
    w /= np.linalg.norm(w)
    D2 = orbit.z0.size
    leaves = np.any(np.abs(w[np.setdiff1d(np.arange(D2), old.free)]) > 1e-8)
    free = np.arange(D2) if leaves or event.kind != "period-doubling" else old.free
    factor = 1 if event.kind == "symmetry-breaking" else 2
    _check_work("max_points", max_points, orbit.system, old.steps * factor, max_points)
    problem = ShootingProblem(
        orbit.system if old.continue_in == "energy" else old.system,
        old.steps * factor,
        free,
        orbit.z0,
        old.continue_in,
        old.total_energy,
        old.phase,
        old.phase_index,
        phase_ref=orbit.z0.copy(),
    )
    if problem.phase == "velocity":
        w[orbit.system.dim + problem.phase_index] = 0.0  # keep the phase condition
        w /= np.linalg.norm(w)
    u_star = problem.pack(orbit.z0, orbit.period * factor, 0.0, orbit.u[-1])
    usc, _ = problem.scales(u_star)
    direction = np.concatenate([w[free], [0.0, 0.0, 0.0]])
    direction /= np.linalg.norm(direction / usc)
    guess = u_star + amplitude * direction
    u, J, data, it = problem.newton(guess, extra=(direction / usc**2, guess))
    first = problem.orbit(u, data, it)
    t0 = direction
    return _continue(problem, first, J, ds, None, max_points, 1, *interval, locate, t0=t0)


def merge(backward: Branch, forward: Branch) -> Branch:
    """One branch from two continuations that start at the same orbit (``backward`` is
    reversed; the shared first orbit is kept once; event indices follow)."""
    nb = len(backward.orbits)
    out = Branch(forward.problem)
    out.orbits = backward.orbits[::-1] + forward.orbits[1:]
    out.tangents = [-t for t in backward.tangents[::-1]] + forward.tangents[1:]
    for e in backward.events:
        e.index = nb - 2 - e.index
    for e in forward.events:
        e.index = nb - 1 + e.index
    out.events = backward.events[::-1] + forward.events
    out.stop_reason = f"backward: {backward.stop_reason}; forward: {forward.stop_reason}"
    return out


@renamed(parameter="continue_in", energy="total_energy", stop="interval")
def continue_both(
    sink,
    mode: str,
    *,
    continue_in: str = "energy",
    total_energy: float,
    interval: tuple[float, float],
    steps: int = 400,
    points: int = 120,
    ds: float = 0.1,
    half_traces: bool = False,
    subspace: str = "plane",
):
    """The sink's normal mode ``mode`` at ``total_energy`` continued both ways in
    ``continue_in`` inside ``interval`` (see :func:`continue_orbits`), as a
    :class:`~sinktheory.nnm.result.BranchResult`.

    Parameters
    ----------
    sink : Sink
        Container, particles and well (the start value of a well parameter).
    mode : "container" or "particle"
        Start guess (:func:`sinktheory.nnm.modes.mode_guess`).
    continue_in : "energy" (the total energy) or a well parameter ("alpha", "beta", ...)
    total_energy : float > 0
        The total energy H of the start orbit (kept along a branch in a well parameter).
    interval : (LO, HI)
        The continuation stops where ``continue_in`` leaves it.
    half_traces : bool
        Also compute the transverse half-period half-traces phi_T/2 at every point.
    """
    from .modes import mode_guess, sink_flow

    kw = dict(steps=steps, continue_in=continue_in, total_energy=total_energy,
              interval=interval, ds=ds)  # fmt: skip
    with refusals_named(energy="total_energy"):  # mode_guess's energy
        system = sink_flow(sink)
        z0, T = mode_guess(sink, mode, total_energy)
        back = continue_orbits(system, z0, T, direction=-1, max_points=points,
                               subspace=subspace, **kw)  # fmt: skip
        fwd = continue_orbits(system, z0, T, direction=1, max_points=points,
                              subspace=subspace, **kw)  # fmt: skip
    branch = merge(back, fwd)
    w = sink.well
    if hasattr(w, "definition"):  # a user's well: its own parameters
        well = {"shape": w.shape, "parameters": dict(w.parameters)}
    else:
        well = {"shape": w.shape, "alpha": w.alpha, "beta": w.beta, "n": w.n, "gamma": w.gamma}
    return branch.result(
        half_traces=half_traces,
        mode=mode,
        **well,
        particles=sink.particles,
        mass=sink.mass,
        label=f"{mode} mode",
    )
