"""The classic absorbers as configurations of the sink, with a dashpot: impulse responses.

Three attachments of the same container (mass 1, spring 1), all built from the existing
model, none with a formula of its own:

* ``"nes"`` -- one particle on the invariant line y = 0 of a well (started there with
  ydot = 0; the line's invariance is checked on the shape's symbolic potential,
  :func:`sinktheory.symbolic.normal_mode_refusal`).  On the line the well is
  V(x, 0) = gamma/(2n) (x / (alpha - beta))^(2n), a force ~ x^(2n - 1): n = 2 is the
  cubic nonlinear energy sink (NES), n = 1 a linear absorber.  Integrated by the full
  engine (:func:`sinktheory.damped.simulate_inelastic`), so whether the
  particle stays on the line is the dynamics' verdict, not an assumption
  (:attr:`ImpulseResponse.transverse`).
* ``"impact"`` -- the rigid limit n -> oo on the line: the vibro-impact NES, a particle
  in the clearance |x| <= alpha - beta, integrated exactly by
  :mod:`sinktheory.vibroimpact` (n is ignored).
* ``"well"`` -- the 2-D stochastic sink with k particles (flat or symmetric well, ...,
  or a user's well: ``user_well``, a :class:`~sinktheory.wellat.WellAt`).

Equal attachment mass: ``mass`` is the *total* particle mass m of every attachment
(k particles of m / k).  Equal damping: a linear dashpot on each particle's velocity
relative to the container (weight 1 everywhere, ``damping_kind="viscous"``), the total
coefficient c shared equally, c / k per particle, so every particle relaxes at the same
rate c / m as the single particle of a 1-D attachment and k particles moving together
feel the one dashpot c.

Impulsive start (the standard test of an absorber): the container at X = 0 with velocity
sqrt(2 E), E = ``energy``, every particle at rest (absolute velocity 0: the impulse acts
on the container alone, so H(0) = E up to the particles' tiny potential energy).  The
particles start at seeded random positions of a start box, as
:func:`sinktheory.ensemble.random_positions` draws them for ``simulate`` (run r from the
r-th child of the seed), in (-b, b)^2 with b = box sqrt(2 E): the box is relative to the
container's amplitude sqrt(2 E), so the particles' start potential energy stays a
negligible share of E at every energy (an absolute box of 0.01 holds about 1e-7 in the
cubic NES, the whole impulse at E = 1e-7).  For the 1-D attachments the same x with
y = 0, so their runs differ only by that small seeded offset along the line (they
coincide as box -> 0).

Examples
--------
>>> res = impulse_response(Attachment("nes", n=2), 0.05, damping=0.02, periods=4, runs=2,
...                        tol=1e-6)
>>> res.container_x.shape, bool(res.max_audit_error < 1e-6)
((2, 65), True)
>>> bool(((0 < res.fraction_dissipated()) & (res.fraction_dissipated() < 1)).all())
True
>>> Attachment("nes", particles=2)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
sinktheory.errors.ParameterError: particles = 2 is not allowed: must be 1 for a 1-D ...
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from . import validation as v
from .ensemble import random_positions
from .errors import ParameterError
from .glossary import old_attribute, renamed
from .layout import StateLayout
from .model import SHAPES, RunSettings, Sink, Well
from .results import Result

#: The attachments (module docstring).
KINDS = ("nes", "impact", "well")
#: Attachments confined to the line y = 0.
LINE_KINDS = ("nes", "impact")


@functools.cache
def _line_refusal(shape: str) -> str:
    from .symbolic import normal_mode_refusal

    return normal_mode_refusal(shape)


@dataclass(frozen=True)
class Attachment:
    """One attachment of the container (module docstring); validated on construction.

    Parameters
    ----------
    kind : {"nes", "impact", "well"}
    shape, alpha, beta, n
        The well (:class:`sinktheory.model.Well`); for ``"impact"`` only the clearance
        alpha - beta matters (n is ignored).
    particles : int
        k: 1 for the 1-D attachments, 1..1000 for ``"well"``.
    mass : float > 0
        Total particle mass m (each particle m / k).
    user_well : WellAt, optional
        A user's well at its values (:class:`sinktheory.wellat.WellAt`) in place of
        shape, alpha, beta and n: ``"well"`` only (the 1-D attachments are the line y = 0
        of a registered shape).
    """

    kind: str
    shape: str = "flat"
    alpha: float = 0.5
    beta: float = 0.3
    n: int = 2
    particles: int = 1
    mass: float = 0.2
    user_well: object = None

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        set_(self, "kind", v.choice("kind", self.kind, KINDS))
        if self.user_well is not None:
            self._check_user_well()
            return
        well = Well(self.alpha, self.beta, self.n, shape=v.choice("shape", self.shape, SHAPES))
        set_(self, "alpha", well.alpha)
        set_(self, "beta", well.beta)
        set_(self, "n", well.n)
        sink = Sink(well, self.particles, self.mass)
        set_(self, "particles", sink.particles)
        set_(self, "mass", sink.mass)
        if self.kind in LINE_KINDS:
            if self.particles != 1:
                raise ParameterError("particles", self.particles, "1 for a 1-D attachment")
            why = _line_refusal(self.shape)
            if why:
                raise ParameterError("shape", self.shape, "a shape with an invariant line "
                                     "y = 0 for a 1-D attachment", why=why)  # fmt: skip

    def _check_user_well(self) -> None:
        from .wellat import WellAt

        if not isinstance(self.user_well, WellAt):
            raise ParameterError("user_well", self.user_well, "None or a user's well at its "
                                 "values, a sinktheory.wellat.WellAt")  # fmt: skip
        if self.kind != "well":
            raise ParameterError("user_well", self.user_well, f"None for the 1-D attachment "
                                 f"{self.kind!r}", why="it is the line y = 0 of a registered "
                                 "shape (alpha, beta and n)")  # fmt: skip
        sink = Sink(self.user_well, self.particles, self.mass)
        object.__setattr__(self, "particles", sink.particles)
        object.__setattr__(self, "mass", sink.mass)

    @property
    def well(self):
        """The well: a :class:`~sinktheory.model.Well` of the shape, or ``user_well``."""
        if self.user_well is not None:
            return self.user_well
        return Well(self.alpha, self.beta, self.n, shape=self.shape)

    @property
    def parameters(self) -> dict:
        """What the attachment is, as plain values: kind, shape (a user's well: its name
        and ``well_parameters``), alpha, beta, n, particles, mass."""
        if self.user_well is None:
            well = {"shape": self.shape, "alpha": self.alpha, "beta": self.beta, "n": self.n}
        else:
            w = self.user_well
            well = {"shape": w.shape, "well_parameters": dict(w.parameters)}
        return {"kind": self.kind, **well, "particles": self.particles, "mass": self.mass}

    @property
    def sink(self) -> Sink:
        """The sink the engine integrates (the well with k particles of m / k)."""
        return Sink(self.well, self.particles, self.mass)

    @property
    def clearance(self) -> float:
        """alpha - beta: the wall distance on the line (the vibro-impact clearance)."""
        if self.user_well is not None:
            raise ParameterError("user_well", self.user_well, "None for a clearance",
                                 why="a user's well has no wall distance alpha - beta")  # fmt: skip
        return self.well.wall_distance

    @property
    def label(self) -> str:
        """A short name for legends, e.g. ``"NES n = 2"``, ``"well flat k = 5"``."""
        if self.kind == "nes":
            return f"NES n = {self.n}"
        if self.kind == "impact":
            return "vibro-impact"
        return f"well {self.well.shape} k = {self.particles}"


@renamed(energy="impulse_energy")
@dataclass(frozen=True)
class ImpulseResponse(Result):
    """The response of the container to an impulse, R runs sampled at S instants.

    Attributes
    ----------
    t : ndarray (S,)
        Sample times i T / s (s = samples per period).
    container_x, container_v, container_energy : ndarray (R, S)
        X, Xdot and E = (X^2 + Xdot^2)/2.
    dissipated : ndarray (R, S)
        W, the dashpots' work since t = 0.
    initial_energy : ndarray (R,)
        H(0) of each run.
    max_audit_error : float
        Largest |H + W - H(0)| / H(0) checked (the engine at period ends, the
        vibro-impact integrator at every sample).
    attachment : Attachment
    damping, impulse_energy : float
        Total dashpot coefficient c and the impulse's container energy E0.
    transverse : ndarray (R, S) or None
        max_j |y_j| (None for ``"impact"``): how far the particles are from y = 0.
    impacts : ndarray (R,) or None
        Impacts of each run (``"impact"`` only).
    integrator : str
        What integrated it (scheme and step, or the exact vibro-impact flow).
    dt : float
        The engine's step (NaN for ``"impact"``: its flow is exact, with no step).
    """

    t: np.ndarray
    container_x: np.ndarray
    container_v: np.ndarray
    container_energy: np.ndarray
    dissipated: np.ndarray
    initial_energy: np.ndarray
    max_audit_error: float
    attachment: Attachment
    damping: float
    impulse_energy: float
    transverse: np.ndarray | None = None
    impacts: np.ndarray | None = None
    integrator: str = ""
    dt: float = math.nan

    DIMS = {
        "container_x": ("run", "time"),
        "container_v": ("run", "time"),
        "container_energy": ("run", "time"),
        "dissipated": ("run", "time"),
        "transverse": ("run", "time"),
        "initial_energy": ("run",),
        "impacts": ("run",),
    }
    COORDS = {"t": "time"}

    energy = old_attribute("impulse_energy")

    def fraction_dissipated(self) -> np.ndarray:
        """W / H(0) of each run at the end of the window, (R,)."""
        return self.dissipated[:, -1] / self.initial_energy

    def time_to_fraction(self, q: float = 0.9) -> np.ndarray:
        """First time W reaches q H(0) in each run, (R,): linear interpolation between
        the samples (W never decreases); inf where the window ends first.

        Examples
        --------
        >>> r = ImpulseResponse(np.arange(3.0), *[np.zeros((1, 3))] * 3,
        ...                     np.array([[0.0, 0.5, 1.0]]), np.ones(1), 0.0,
        ...                     Attachment("well"), 0.1, 1.0)
        >>> r.time_to_fraction(0.9).tolist(), r.time_to_fraction(0.25).tolist()
        ([1.8], [0.5])
        """
        if not 0 < (q := v.finite("q", q)) <= 1:
            raise ParameterError("q", q, "a fraction in (0, 1]")
        share = self.dissipated / self.initial_energy[:, None]
        return np.array([_crossing(self.t, row, q) for row in share])

    def time_leaving_line(self, threshold: float = 1e-6) -> np.ndarray:
        """First sample time where some particle is farther than ``threshold`` from
        y = 0, (R,) (inf if never; all inf for ``"impact"``, which has no y)."""
        threshold = v.positive("threshold", threshold)
        if self.transverse is None:
            return np.full(self.initial_energy.shape, math.inf)
        out = np.full(self.transverse.shape[0], math.inf)
        for r, row in enumerate(self.transverse):
            hit = np.flatnonzero(row > threshold)
            if hit.size:
                out[r] = self.t[hit[0]]
        return out


def _crossing(t: np.ndarray, y: np.ndarray, q: float) -> float:
    above = np.flatnonzero(y >= q)
    if not above.size:
        return math.inf
    i = above[0]
    if i == 0:
        return float(t[0])
    return float(t[i - 1] + (q - y[i - 1]) / (y[i] - y[i - 1]) * (t[i] - t[i - 1]))


def start_rows(att: Attachment, settings: RunSettings) -> np.ndarray:
    """State rows (R, 2 + 4k) of the impulsive start (module docstring)."""
    positions = random_positions(settings, att.particles)
    if att.kind in LINE_KINDS:
        positions[:, :, 1] = 0.0
    rows = StateLayout(att.particles).start(0.0, positions)
    rows[:, StateLayout.XDOT] = math.sqrt(2.0 * settings.container_energy)
    return rows


@renamed(energy="container_energy")
def impulse_response(
    att: Attachment,
    container_energy: float,
    *,
    damping: float,
    periods: int,
    runs: int = 8,
    seed: int = 0,
    samples_per_period: int = 16,
    tol: float | None = None,
    dt: float | None = None,
    box: float = 0.01,
    energy_bound: float | None = None,
    line_offset: float = 0.0,
) -> ImpulseResponse:
    """The container's response to an impulse of energy E0 = ``container_energy`` (module
    docstring).

    Parameters
    ----------
    att : Attachment
    container_energy : float > 0
        E0, the container's energy given by the impulse (Xdot(0) = sqrt(2 E0)).
    damping : float >= 0
        c, the total dashpot coefficient (c / k per particle).
    periods, runs, seed
        As :class:`sinktheory.model.RunSettings`.
    box : float > 0
        Half-width of the particles' start box relative to sqrt(2 E0) (module docstring).
    samples_per_period : int >= 1
        Samples per period T = 2 pi of the records.
    tol : float, optional
        The engine's energy tolerance (default 1e-8; ``"impact"`` is exact and ignores
        it).  It sets the conservative stage's step; the dashpot's Strang splitting adds
        its own second-order error to W, which tol does not bound (measured for the
        linear absorber, c = 0.05, at tol 1e-10: 2e-4 H0 over 6 periods).
    dt : float > 0, optional
        The step instead of ``tol`` (a finer step for an accurate W; error ~ dt^2).
    energy_bound : float > 0, optional
        Largest audit error tolerated (default as simulate: max(1e-6, 100 tol)).
    line_offset : float >= 0
        Start the ``"nes"`` particle this far off the line (y(0) = line_offset): whether
        it stays near y = 0 (:meth:`ImpulseResponse.time_leaving_line`) is the line's
        stability.  Only for ``"nes"``.

    Returns
    -------
    ImpulseResponse
    """
    if not isinstance(att, Attachment):
        raise ParameterError("att", att, "a sinktheory.attachments.Attachment")
    damping = v.nonnegative("damping", damping)
    samples = v.positive_int("samples_per_period", samples_per_period, maximum=100_000)
    energy = v.positive("container_energy", container_energy)
    box = v.positive("box", box) * math.sqrt(2.0 * energy)
    settings = RunSettings(container_energy=energy, runs=runs, periods=periods, seed=seed, box=box)
    offset = v.nonnegative("line_offset", line_offset)
    for name, value in (("tol", tol), ("dt", dt)):  # checked even where "impact" ignores them
        if value is not None:
            v.positive(name, value)
    if offset and att.kind != "nes":
        raise ParameterError("line_offset", offset, "0 unless the attachment is an 'nes'")
    rows = start_rows(att, settings)
    rows[:, StateLayout(att.particles).y] += offset
    common = {"attachment": att, "damping": damping, "impulse_energy": settings.container_energy}
    if att.kind == "impact":
        from .vibroimpact import simulate_vibroimpact

        L = StateLayout(1)
        res = simulate_vibroimpact(rows[:, [L.X, L.XDOT, L.u.start, L.udot.start]],
                                   clearance=att.clearance, mass=att.mass, damping=damping,
                                   periods=settings.periods, samples_per_period=samples,
                                   energy_bound=energy_bound)  # fmt: skip
        x, xd = res.container_x, res.container_v
        return ImpulseResponse(res.sample_times, x, xd, 0.5 * (x * x + xd * xd), res.dissipated,
                               res.initial_energy, res.max_audit_error, impacts=res.impacts,
                               integrator="exact flights and impacts (sinktheory.vibroimpact)",
                               **common)  # fmt: skip
    from .damped import simulate_inelastic

    res = simulate_inelastic(att.sink, settings, damping=damping / att.particles,
                             damping_kind="viscous", tol=tol, dt=dt, energy_bound=energy_bound,
                             start=rows, samples_per_period=samples)  # fmt: skip
    x, xd = res.container_x, res.container_v
    return ImpulseResponse(res.sample_times, x, xd, 0.5 * (x * x + xd * xd),
                           res.sample_dissipated, res.initial_energy, res.max_audit_error,
                           transverse=res.transverse, dt=float(res.dt),
                           integrator=f"{res.scheme}, dt = {res.dt:.6g}, with the exact "
                           "dashpot flow (Strang)", **common)  # fmt: skip


__all__ = ["KINDS", "Attachment", "ImpulseResponse", "impulse_response"]
