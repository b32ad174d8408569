r"""Transverse stability of the coupled normal mode against beta, scored on the chaos map.

The paper predicts the chaotic beta intervals from the normal mode y = 0 of one particle
in a *fixed* container (:mod:`sinktheory.floquet`).  Here the same prediction is made
from the normal mode of the *coupled* container-particle system at the chaos map's total
energy, and both are scored against the chaos map's verdicts.

Which normal mode.  The chaos map starts the container at X = sqrt(2 E) with the
particles at rest, so the mode is followed from the container's side: the linear
container mode at low energy (:func:`reach_energy`, the particles at absolute rest) is
continued up in energy by pseudo-arclength through its folds to E.  At the 1:1 resonance
with the particles' mode (frequency ~ amplitude^(n-1), hardening) the branch folds twice
and comes out as the particles' mode with the container recoiling: for k = 1,
alpha = 1/2, n = 4, m = 0.2 the folds lie below E = 0.2 at every beta tried, and at
E = 0.5 the orbit coincides (up to the half-period shift) with the one shot from the
particle guess of :func:`~sinktheory.nnm.modes.mode_guess`.  That orbit is continued in
beta at fixed E (:func:`transverse_chart`) and corrected by shooting at each beta of the
grid; its transverse (y) multipliers decide stability: |phi_T/2| <= 1 is stable.

Agreement (:func:`agreement_report`).  On one beta grid, the chaos map is judged run by
run (:func:`sinktheory.chaos.verdicts.map_calls`: a run is regular when its lambda_1 <=
3 ln t / t) and each theory's prediction is compared with it (stable <-> every run
regular, unstable <-> every run chaotic): the share of those betas where they coincide,
by :func:`sinktheory.chaos.verdicts.agreement` for both.  A beta whose runs split is
reported as mixed, with its fraction of regular runs, and not scored: a mean over its
runs would be set by how many start in an island.

Examples
--------
>>> from sinktheory import Sink, Well
>>> sink = Sink(Well(0.5, -0.2, 4), particles=1, mass=0.2)
>>> orbit = reach_energy(sink, 0.5)
>>> round(orbit.total_energy, 12), round(orbit.frequency, 4)
(0.5, 3.9667)
>>> chart = transverse_chart(sink, 0.5, [-0.6, -0.2, 0.2], start=orbit)
>>> chart.stable.tolist(), bool(abs(chart.phi_half[1, 0]) < 1)
([False, True, False], True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..glossary import renamed
from ..model import Sink
from .continuation import continue_orbits, merge
from .modes import mode_guess, sink_flow
from .shooting import MAX_SHOOT_STEPS, Orbit, ShootingError, shoot

__all__ = [
    "agreement_report",
    "LOW_ENERGY",
    "reach_energy",
    "transverse_chart",
    "TransverseChart",
]

#: Energy at which the container's linear mode starts (the particles barely touch the walls).
LOW_ENERGY = 1e-4


@renamed(energy="total_energy")
def reach_energy(
    sink: Sink, total_energy: float, *, steps: int = 400, ds: float = 0.2, max_points: int = 400
) -> Orbit:
    """The normal mode that is the container's linear mode at low energy, followed by
    pseudo-arclength continuation in energy (through its folds) up to ``total_energy``
    and corrected there exactly.

    Raises
    ------
    ParameterError
        Unless LOW_ENERGY < total_energy.
    ShootingError
        If the branch ends before reaching ``total_energy``.
    """
    energy = total_energy
    if not v.positive("total_energy", energy) > LOW_ENERGY:
        raise ParameterError("total_energy", energy, f"a finite energy > {LOW_ENERGY:g}")
    system = sink_flow(sink)
    z0, T = mode_guess(sink, "container", LOW_ENERGY)
    branch = continue_orbits(system, z0, T, steps=steps, total_energy=LOW_ENERGY,
                             interval=(0.1 * LOW_ENERGY, energy), ds=ds,
                             max_points=max_points, subspace="plane")  # fmt: skip
    last = branch.orbits[-1]
    if last.total_energy < energy:
        raise ShootingError(f"energy continuation ended at H = {last.total_energy:.6g} before "
                            f"{energy:g} ({branch.stop_reason})")  # fmt: skip
    # the last two points bracket the target: start Newton from the nearer one
    near = min(branch.orbits[-2:], key=lambda o: abs(o.total_energy - energy))
    return shoot(system, near.z0, near.period, steps=steps, total_energy=energy, subspace="plane")


@dataclass(frozen=True)
class TransverseChart:
    """Transverse stability of the coupled normal mode on a beta grid.

    Attributes
    ----------
    beta : (B,) the grid; phi_half : (B, k) transverse half-period half-traces per
    particle; stable : (B,) bool, every |phi_half| <= 1 (to the tolerance of
    :data:`sinktheory.nnm.stability.STABILITY_TOL`); frequency : (B,) of the orbit;
    branch : the continued branch (:class:`~sinktheory.nnm.result.BranchResult`).
    """

    beta: np.ndarray
    phi_half: np.ndarray
    stable: np.ndarray
    frequency: np.ndarray
    branch: object = field(repr=False)

    def stable_intervals(self) -> list[tuple[float, float]]:
        """Grid-resolution intervals [first, last stable beta] of consecutive stable points."""
        out, start = [], None
        for b, ok in zip(self.beta, self.stable, strict=True):
            if ok and start is None:
                start = b
            if ok:
                end = b
            elif start is not None:
                out.append((float(start), float(end)))
                start = None
        if start is not None:
            out.append((float(start), float(end)))
        return out


@renamed(energy="total_energy")
def transverse_chart(
    sink: Sink,
    total_energy: float,
    betas,
    *,
    start: Orbit | None = None,
    steps: int = 400,
    ds: float = 0.05,
    points: int = 400,
) -> TransverseChart:
    """The coupled normal mode at ``total_energy`` on the grid ``betas``.

    Parameters
    ----------
    sink : Sink
        Its well's beta is where the branch starts (inside the grid's range).
    total_energy : float
        Total energy H, fixed along the branch.
    betas : sequence of float, increasing
    start : Orbit, optional
        The mode at (sink, energy); default :func:`reach_energy` (the container's mode
        continued up in energy).
    steps, ds, points : per period, first arclength step, most points per direction.
    """
    _check_sink(sink)
    betas = _check_betas(betas)
    steps = v.positive_int("steps", steps, minimum=2, maximum=MAX_SHOOT_STEPS)
    if start is not None and not isinstance(start, Orbit):
        raise ParameterError("start", type(start).__name__,
                             "None or the Orbit of the mode at (sink, total_energy)")  # fmt: skip
    lo, hi = float(betas[0]), float(betas[-1])
    if not lo <= sink.well.beta <= hi:
        raise ParameterError("beta", sink.well.beta, f"inside the grid [{lo:g}, {hi:g}]")
    energy = total_energy
    orbit = reach_energy(sink, energy, steps=steps) if start is None else start
    system = orbit.system
    kw = dict(steps=orbit.steps, continue_in="beta", total_energy=energy, interval=(lo, hi),
              ds=ds, max_points=points, subspace="plane")  # fmt: skip
    back = continue_orbits(system, orbit.z0, orbit.period, direction=-1, **kw)
    fwd = continue_orbits(system, orbit.z0, orbit.period, direction=1, **kw)
    branch = merge(back, fwd)
    values = branch.values
    phi, stable, freq = [], [], []
    for b in betas:
        i = _bracket(values, b)
        w = (b - values[i]) / (values[i + 1] - values[i]) if values[i + 1] != values[i] else 0.0
        o0, o1 = branch.orbits[i], branch.orbits[i + 1]
        z = (1 - w) * o0.z0 + w * o1.z0
        T = (1 - w) * o0.period + w * o1.period
        o = shoot(system.with_param("beta", b), z, T, steps=orbit.steps, total_energy=energy,
                  subspace="plane")  # fmt: skip
        phi.append(o.transverse_half_traces())
        stable.append(o.floquet.stable_transverse)
        freq.append(o.frequency)
    w = sink.well
    result = branch.result(half_traces=True, shape=w.shape, alpha=w.alpha, beta=w.beta, n=w.n,
                           gamma=w.gamma, particles=sink.particles, mass=sink.mass,
                           mode="coupled", label="coupled normal mode")  # fmt: skip
    return TransverseChart(betas, np.array(phi), np.array(stable), np.array(freq), result)


def _check_sink(sink) -> None:
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")


def _check_betas(betas) -> np.ndarray:
    """The beta grid: finite numbers, increasing."""
    allowed = "an increasing sequence of finite betas"
    grid = v.finite_array("betas", betas, allowed, ndim=1)
    if grid.size < 1 or np.any(np.diff(grid) <= 0):
        raise ParameterError("betas", grid.tolist(), allowed)
    return grid


def _bracket(values: np.ndarray, b: float) -> int:
    """First branch segment [i, i + 1] whose continuation values enclose b."""
    inside = (values[:-1] - b) * (values[1:] - b) <= 0
    if not inside.any():
        raise ShootingError(f"the beta branch [{values.min():.6g}, {values.max():.6g}] "
                            f"does not reach beta = {b:g}")  # fmt: skip
    return int(np.argmax(inside))


@renamed(energy="total_energy")
def agreement_report(
    sink: Sink,
    total_energy: float,
    betas,
    *,
    chaos=None,
    chart: TransverseChart | None = None,
    runs: int = 8,
    periods: int = 200,
    dt: float | None = None,
    seed: int = 0,
    workers: int | None = None,
    steps: int = 400,
) -> dict:
    """Shares of grid betas where each theory's stability agrees with the chaos map.

    Parameters
    ----------
    sink, total_energy, betas : as for :func:`transverse_chart` (the chaos map uses the
        same well, particles and mass, and container energy E0 = ``total_energy``: its
        particles start at rest in a small box at the centre, so E exceeds E0 only by their
        potential energy there).
    chaos : xarray.Dataset, optional
        A chaos map over exactly ``betas`` (:func:`sinktheory.sweep.chaosmap.chaos_map`);
        computed with ``runs``, ``periods``, ``dt``, ``seed``, ``workers`` otherwise.
    chart : TransverseChart, optional
        :func:`transverse_chart` over exactly ``betas`` (computed otherwise).

    Returns
    -------
    dict
        ``nnm`` and ``floquet``: the shares (0..1) of the ``scored`` betas (those whose
        runs are all regular or all chaotic) where the coupled mode's transverse
        stability, respectively the fixed-container Floquet stability of
        :func:`sinktheory.floquet.model_problem` (amplitude A0 = 1), predicts the chaos
        map (stable <-> regular); ``betas``; the counts ``chaotic``, ``regular`` and
        ``mixed``; ``mixed_beta`` with each one's ``regular_fraction``; ``threshold``;
        the charts' stable intervals; ``statement`` (one sentence); and the arrays
        ``beta``, ``phi_half_nnm``, ``phi_half_floquet``, ``lambda1``, ``lambda1_se``
        and ``calls`` (+1 every run chaotic, -1 every run regular, 0 mixed) for plotting.
    """
    from ..chaos.verdicts import agreement, check_map, map_calls
    from ..floquet import model_problem
    from ..runstats import check_runs
    from ..sweep.chaosmap import chaos_map

    _check_sink(sink)
    total_energy = v.positive("total_energy", total_energy)
    betas = _check_betas(betas)
    # the chaos map's and the chart's settings, checked even where chaos or chart is given
    check_runs("runs", runs)
    v.positive_int("periods", periods)
    dt = None if dt is None else v.positive("dt", dt)
    v.positive_int("seed", seed, minimum=0)
    workers = None if workers is None else v.positive_int("workers", workers)
    v.positive_int("steps", steps, minimum=2, maximum=MAX_SHOOT_STEPS)
    if chaos is not None:
        check_map(chaos, "beta", "lambda1", "lambda1_se", "lambda1_runs", "lambda1_periods",
                  attrs=("periods",), name="chaos")  # fmt: skip
    if chart is not None and not isinstance(chart, TransverseChart):
        raise ParameterError("chart", type(chart).__name__, "None or a TransverseChart")
    w = sink.well
    if chaos is None:
        chaos = chaos_map(w.alpha, w.n, betas, shape=w.shape, particles=sink.particles,
                          mass=sink.mass, container_energy=total_energy, runs=runs,
                          periods=periods, dt=dt,
                          seed=seed, workers=workers)  # fmt: skip
    grid = np.asarray(chaos.beta.values, dtype=float)
    if grid.shape != betas.shape or not np.allclose(grid, betas, rtol=0, atol=1e-12):
        raise ParameterError("chaos", grid.tolist(), f"a chaos map over the betas {betas.tolist()}")
    if chart is None:
        chart = transverse_chart(sink, total_energy, betas, steps=steps)
    elif chart.beta.shape != betas.shape or not np.allclose(chart.beta, betas, rtol=0, atol=0):
        raise ParameterError("chart", chart.beta.tolist(), f"a chart over {betas.tolist()}")
    fixed = model_problem(w.alpha, w.n, gamma=w.gamma, shape=w.shape).evaluate(betas)
    a_nnm = agreement(chaos, chart.stable)
    a_fix = agreement(chaos, fixed.stable)
    report = {
        "betas": int(betas.size),
        **{key: a_nnm[key] for key in ("chaotic", "regular", "mixed", "scored", "mixed_beta",
                                       "regular_fraction", "threshold")},
        "nnm": a_nnm["floquet"],
        "floquet": a_fix["floquet"],
        "periods": int(chaos.attrs["periods"]),
        "runs": int(chaos.sizes.get("run", 0)),
        "nnm_stable": chart.stable_intervals(),
        "statement": statement(a_nnm, a_fix["floquet"], float(betas[0]), float(betas[-1])),
        "beta": betas.tolist(),
        "phi_half_nnm": chart.phi_half[:, 0].tolist(),
        "phi_half_floquet": np.asarray(fixed.phi_half, float).tolist(),
        "lambda1": chaos.lambda1.values.tolist(),
        "lambda1_se": chaos.lambda1_se.values.tolist(),
        "calls": map_calls(chaos)["calls"].tolist(),
    }  # fmt: skip
    return report


def statement(scores: dict, fixed: float, lo: float, hi: float) -> str:
    """The agreement sentence of the report: ``scores`` is the coupled mode's
    :func:`sinktheory.chaos.verdicts.agreement`, ``fixed`` the fixed-container share.

    Examples
    --------
    >>> a = {"floquet": 0.6, "scored": 45, "betas": 48, "mixed": 3, "chaotic": 40,
    ...      "regular": 5, "mixed_beta": [-0.3, -0.2, -0.1],
    ...      "regular_fraction": [0.25, 0.5, 0.125]}
    >>> print(statement(a, 0.55, -0.7, 0.45))  # doctest: +NORMALIZE_WHITESPACE
    NNM transverse stability predicts the chaos map at 60 % of the 45 betas whose runs are
    all regular or all chaotic, the fixed-container Floquet theory at 55 % (48 betas in
    [-0.7, 0.45]: 40 all chaotic, 5 all regular, 3 mixed; a run is regular when its
    lambda_1 <= 3 ln t / t; stable counts as right where every run is regular, unstable
    where every run is chaotic); not scored, the runs split at beta = -0.3 (25 % regular),
    -0.2 (50 %), -0.1 (12 %)
    """

    def pct(x):
        return "no" if math.isnan(x) else f"{100 * x:.0f} %"

    a = scores
    text = (
        f"NNM transverse stability predicts the chaos map at {pct(a['floquet'])} of the "
        f"{a['scored']} betas whose runs are all regular or all chaotic, the fixed-container "
        f"Floquet theory at {pct(fixed)} ({a['betas']} betas in [{lo:g}, {hi:g}]: "
        f"{a['chaotic']} all chaotic, {a['regular']} all regular, {a['mixed']} mixed; a run "
        "is regular when its lambda_1 <= 3 ln t / t; stable counts as right where every run "
        "is regular, unstable where every run is chaotic)"
    )
    if a["mixed"]:
        parts = [f"{b:g} ({100 * f:.0f} %{' regular' if i == 0 else ''})"
                 for i, (b, f) in enumerate(zip(a["mixed_beta"], a["regular_fraction"],
                                                strict=True))]  # fmt: skip
        text += "; not scored, the runs split at beta = " + ", ".join(parts)
    return text
