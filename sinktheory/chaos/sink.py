"""Chaos indicators of the container + particles ensemble, set up like :func:`simulate`.

:func:`chaos` starts the same runs as :func:`sinktheory.simulate.simulate` for the same
:class:`~sinktheory.model.RunSettings` (container at X = sqrt(2 E0) at rest, particles at
rest at :func:`~sinktheory.simulate.random_positions`), with the same step, scheme and
energy audit, and records the indicators once per container period T = 2 pi.

The transverse exponent is that of the invariant subspace y = 0 (every y_j = ydot_j = 0,
which the flow keeps because V is even in y): the runs start from the same positions with
y_j = 0, and one deviation vector lies in the y_j-directions only.  Linearised about
y = 0 each particle's y obeys a Hill equation driven by its x-motion; with the container
fixed (mass ratio -> 0) this is the paper's Floquet problem (:mod:`sinktheory.floquet`),
whose ln|rho| / T it then equals (tests/test_chaos.py).

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

import numpy as np

from .. import validation as val
from ..errors import ParameterError
from ..integrators import DEFAULT_SCHEME, get_scheme
from ..model import RunSettings, Sink
from ..simulate import (
    ENERGY_BOUND,
    engine_name,
    engine_params,
    split_values,
    start_positions,
    start_state,
    total_energy,
)
from ..worklimit import check_particle_steps, step_of, tangent_steps
from .general import check_block, check_gali, check_renorm, check_spectrum, indicators
from .result import ChaosResult


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
    sink: Sink, settings: RunSettings, steps: int, spectrum: str | None, gali: int, transverse
) -> None:
    """Refuse, before any integration, an analysis whose deviation vectors would not fit in
    memory or could not finish within the work limit (:mod:`sinktheory.worklimit`).

    The spectrum's 2D vectors of dimension 2D make its cost grow with the square of the
    number of particles; it is named when the analysis without it would fit, else the
    larger of ``runs`` and ``periods``.
    """
    dim = 1 + 2 * sink.particles
    R, P = settings.runs, settings.periods
    vectors = tangent_runs(dim, spectrum, gali, transverse)
    base = R * P * steps

    def work(vecs):
        return base * sum(tangent_steps(sink.particles, m) for m in vecs)

    def check(name, vecs):
        value = {"spectrum": spectrum, "periods": P, "runs": R}[name]
        what = f"{R} run(s) x {P} period(s) x {steps} step(s) with "
        what += f"{'+'.join(map(str, vecs))} deviation vector(s) of {sink.particles} particle(s)"
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


def chaos(
    sink: Sink,
    settings: RunSettings | None = None,
    *,
    spectrum: bool | str = False,
    gali: int = 0,
    megno: bool = False,
    transverse: bool = False,
    method: str = DEFAULT_SCHEME,
    dt: float | None = None,
    tol: float | None = None,
    renorm: int = 0,
    initial=None,
    energy_bound: float = ENERGY_BOUND,
    block: int | None = None,
    progress: bool | None = None,
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
    method, dt, energy_bound
        Integrator and energy audit, as for ``simulate`` (dt aligned to T / steps).
    tol : float, optional
        Relative energy error the step of ``method`` is chosen for (default 1e-8, see
        :mod:`sinktheory.stepsize`); ``dt`` overrides it.
    renorm : int >= 0
        Steps between extra renormalisations inside a period (0: once per period).
    initial : array (k, 2) or (R, k, 2), optional
        Particle positions instead of random ones.
    block : int, optional
        Engine runs per block (the numbers do not depend on it).
    progress : bool, optional
        Progress bar on stderr (on a terminal only).

    Returns
    -------
    ChaosResult
        ``times`` are t_j = j T, exponents per unit time.
    """
    settings = RunSettings() if settings is None else settings
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    if not isinstance(settings, RunSettings):
        raise ParameterError("settings", settings, "a sinktheory.model.RunSettings")
    scheme = get_scheme(method)
    bound = val.positive("energy_bound", energy_bound)
    megno = val.flag("megno", megno)
    transverse = val.flag("transverse", transverse)
    spectrum = check_spectrum(spectrum)
    gali = check_gali(gali, 1 + 2 * sink.particles)
    check_renorm(renorm)
    block = check_block(block)
    positions = start_positions(sink, settings, initial)
    values = start_state(sink, settings.energy, positions)
    h0 = total_energy(sink, values)
    top = float(np.max(h0))
    trans = None
    if transverse:
        on_plane = positions.copy()
        on_plane[:, :, 1] = 0.0
        tvalues = start_state(sink, settings.energy, on_plane)
        top = max(top, float(np.max(total_energy(sink, tvalues))))
        qt, vt = split_values(tvalues)
        trans = (qt, vt, transverse_mask(sink.particles))
    sink.well.check_energy(top)
    _, dt, steps, _ = step_of(sink, top, method=scheme.name, dt=dt, tol=tol, settings=settings)
    check_tangent_work(sink, settings, steps, spectrum, gali, transverse)
    q, v = split_values(values)
    w = sink.well
    return indicators(
        engine_name(sink),
        q,
        v,
        engine_params(sink),
        dt=dt,
        steps=steps,
        segments=settings.periods,
        spectrum=spectrum,
        gali=gali,
        megno=megno,
        transverse=trans,
        method=scheme.name,
        renorm=renorm,
        seed=settings.seed,
        bound=bound,
        block=block,
        progress=progress,
        reference_energy=h0,
        parameters={
            "shape": w.shape,
            "alpha": w.alpha,
            "beta": w.beta,
            "n": w.n,
            "gamma": w.gamma,
            "particles": sink.particles,
            "mass": sink.mass,
            "energy": settings.energy,
            "runs": settings.runs,
            "periods": settings.periods,
            "period": 2.0 * math.pi,
        },
    )
