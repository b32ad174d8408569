"""Chaos indicators of any engine system: one call, the ensembles it needs, one result.

The engine (:class:`sinktheory.engine.core.Ensemble`) renormalises deviation vectors at
every segment end (and every ``renorm`` steps inside a segment, if asked) in one of two
ways, so an analysis may need two ensembles over the same orbits:

* ``orthonormalise`` (modified Gram-Schmidt of 2D vectors: Benettin et al. 1980, the QR
  method): the accumulated ln R_ii give the whole Lyapunov spectrum;
* ``normalise`` (each vector on its own): the first vector gives lambda_1 and MEGNO, and
  the volume of the first k unit vectors is GALI_k (Skokos, Bountis & Antonopoulos 2007).

Vector 0 is normalised identically in both modes, so lambda_1 and MEGNO are bitwise the
same whichever ensemble carries them; when both are needed the orbits are integrated
twice (the cost of an orbit is small next to that of 2D tangent vectors).

Norms are Euclidean in the engine's (q, v) coordinates; the exponents do not depend on the
norm, finite-time values do by O(ln cond(mass matrix) / t).

Examples
--------
>>> import numpy as np
>>> q, v = np.array([[0.0], [-0.25]]), np.array([[0.42081], [0.0]])  # Henon-Heiles, E = 1/8
>>> res = indicators("henon_heiles", q, v, [], dt=0.05, steps=20, segments=50,
...                  spectrum=True, megno=True)
>>> res.spectrum.shape, bool(abs(res.pair_sums).max() < 0.05)
((1, 4), True)
"""

from __future__ import annotations

import math

import numpy as np

from .. import validation as val
from ..errors import ParameterError
from ..glossary import renamed
from ..integrators import DEFAULT_SCHEME, get_scheme
from .result import ChaosResult
from .vectors import random_vectors

__all__ = [
    "check_block",
    "check_renorm",
    "check_run",
    "check_spectrum",
    "indicators",
]


def check_gali(gali: int, dim: int) -> int:
    """k of GALI_k: 0 (none) or an integer in [2, 2D]."""
    k = val.positive_int("gali", gali, minimum=0, maximum=2 * dim)
    if k == 1:
        raise ParameterError("gali", gali, f"0 (none) or an integer in [2, {2 * dim}]")
    return k


def check_renorm(renorm) -> int:
    """Steps between renormalisations inside a segment: 0 (none) or up to
    :data:`~sinktheory.validation.MAX_STEPS_PER_PERIOD` (more steps than a period has
    would never renormalise, and the engine counts steps in 64-bit integers).

    Examples
    --------
    >>> check_renorm(0), check_renorm(50.0)
    (0, 50)
    >>> check_renorm(1e308)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: renorm = 1e+308 is not allowed: must be an integer in \
[0, 1000000000]
    """
    return val.positive_int("renorm", renorm, minimum=0, maximum=val.MAX_STEPS_PER_PERIOD)


def check_block(block) -> int | None:
    """Runs per engine block: None (the engine's choice) or an integer in [1, MAX_RUNS]."""
    from ..model import MAX_RUNS

    return None if block is None else val.positive_int("block", block, maximum=MAX_RUNS)


def check_params(system: str, params, runs: int | None = None) -> np.ndarray:
    """The runtime parameters of engine ``system``: as many finite numbers as it has
    (:func:`sinktheory.nnm.system.parameter_names`), shared by every run or, given the
    number of ``runs``, one column of them per run (shape (count, runs))."""
    from ..nnm.system import parameter_names

    names = parameter_names(system)
    p = val.real_array("params", params) if np.ndim(params) <= 2 else None
    shapes = {(len(names),)} | ({(len(names), runs)} if runs is not None else set())
    if p is None or p.shape not in shapes or not np.isfinite(p).all():
        shown = params if isinstance(params, str | list | tuple) else type(params).__name__
        per_run = f", or a column of them for each of {runs} runs" if runs is not None else ""
        raise ParameterError("params", shown, f"{len(names)} finite values {names} for "
                             f"{system}{per_run}")  # fmt: skip
    return p


def check_run(system, q, v, dt, steps, segments, *, per_run: bool = False) -> tuple:
    """(system, q, v, dt, steps, segments) of an engine run, each validated: a known engine
    system, finite start states q and v of one shape (D, R), dt > 0, and steps and
    segments integers in [1, :data:`~sinktheory.validation.MAX_STEPS_PER_PERIOD`]; with
    ``per_run``, dt and steps may be one per run (arrays (R,), checked entry by entry)."""
    from ..engine.cache import engine_system  # numba loads with the first run

    system = engine_system("system", system)
    q = val.real_array("q", q)
    v = val.real_array("v", v)
    if q.ndim != 2 or q.shape != v.shape or 0 in q.shape:
        raise ParameterError("q", f"arrays of shapes {q.shape}, {v.shape}",
                             "positions q and velocities v of one shape (D, R)")  # fmt: skip
    if not (np.isfinite(q).all() and np.isfinite(v).all()):
        raise ParameterError("q", "non-finite start states", "finite q and v")
    if per_run and (np.ndim(dt) or np.ndim(steps)):
        runs = q.shape[1]
        if np.shape(dt) not in ((), (runs,)) or np.shape(steps) not in ((), (runs,)):
            raise ParameterError("dt, steps", f"shapes {np.shape(dt)}, {np.shape(steps)}",
                                 f"one value or one per run ({runs},)")  # fmt: skip
        dt = np.array([val.positive("dt", x) for x in np.broadcast_to(dt, (runs,))])
        steps = np.array([val.positive_int("steps", x, maximum=val.MAX_STEPS_PER_PERIOD)
                          for x in np.broadcast_to(steps, (runs,))])  # fmt: skip
    else:
        dt = val.positive("dt", dt)
        steps = val.positive_int("steps", steps, maximum=val.MAX_STEPS_PER_PERIOD)
    segments = val.positive_int("segments", segments, maximum=val.MAX_STEPS_PER_PERIOD)
    if not np.all(np.isfinite(dt * steps * segments)):
        raise ParameterError("dt", dt, "a step whose run (dt x steps x segments) is finite")
    return system, q, v, dt, steps, segments


def check_transverse(transverse, dim: int, runs: int) -> tuple:
    """(q, v, mask) or (q, v, mask, (dq, dv)) of the transverse runs: finite start states of
    shape (D, R), a boolean mask of the 2D phase-space directions and, optionally, the
    deviation vectors (D, 1, R) to start from."""
    allowed = (f"(q, v, mask[, (dq, dv)]): states of shape ({dim}, {runs}), {2 * dim} "
               f"booleans and optionally vectors of shape ({dim}, 1, {runs})")  # fmt: skip
    if not isinstance(transverse, tuple | list) or len(transverse) not in (3, 4):
        raise ParameterError("transverse", type(transverse).__name__, allowed)
    q, v, mask = (val.real_array("transverse", a, allowed) for a in transverse[:3])
    if q.shape != (dim, runs) or v.shape != (dim, runs) or mask.shape != (2 * dim,):
        raise ParameterError("transverse", f"shapes {q.shape}, {v.shape}, {mask.shape}", allowed)
    if not (np.isfinite(q).all() and np.isfinite(v).all() and np.isin(mask, (0, 1)).all()):
        raise ParameterError("transverse", "non-finite states or a non-boolean mask", allowed)
    if len(transverse) == 3:
        return q, v, mask.astype(bool)
    given = transverse[3]
    if not isinstance(given, tuple | list) or len(given) != 2:
        raise ParameterError("transverse", "vectors that are not a pair (dq, dv)", allowed)
    dq, dv = (val.real_array("transverse", a, allowed) for a in given)
    if dq.shape != (dim, 1, runs) or dv.shape != dq.shape or not np.isfinite(dq).all():
        raise ParameterError("transverse", f"vectors of shapes {dq.shape}, {dv.shape}", allowed)
    return q, v, mask.astype(bool), (dq, dv)


def check_bound(bound) -> float:
    """Largest relative energy error tolerated: a number > 0, or inf (no audit)."""
    if not val._is_bool(bound) and isinstance(bound, int | float) and bound == math.inf:
        return math.inf
    return val.positive("bound", bound)


def check_spectrum(spectrum) -> str | None:
    """None (no spectrum), "full" (True or "full") or "half" (see :func:`indicators`).

    Examples
    --------
    >>> check_spectrum(True), check_spectrum("half"), check_spectrum(False)
    ('full', 'half', None)
    """
    if spectrum is False or spectrum is None:
        return None
    if spectrum is True or spectrum in ("full", "half"):
        return "full" if spectrum is True else spectrum
    raise ParameterError("spectrum", spectrum, 'False, True, "full" or "half"')


def vector_count(dim: int, spectrum, gali: int) -> int:
    """Deviation vectors per run that :func:`indicators` needs: 2D for the full spectrum, D
    for the half, k for GALI_k, at least one (lambda_1)."""
    gali = check_gali(gali, dim)
    return max({"full": 2 * dim, "half": dim, None: 0}[check_spectrum(spectrum)], gali, 1)


def _run(system, q, v, params, vectors, mode, scheme, dt, steps, segments, opts, **kw):
    """One ensemble with deviation vectors: (Records, Ensemble)."""
    dq, dv = vectors
    from ..engine.core import Ensemble  # numba loads with the first run

    ens = Ensemble(
        system,
        np.array(q, float),  # copies: the engine advances its arrays in place
        np.array(v, float),
        params,
        dq=dq,
        dv=dv,
        tangent=mode,
        reference_energy=opts["reference_energy"],
    )
    rec = ens.run(
        scheme,
        dt=dt,
        steps=steps,
        segments=segments,
        record=("logs",),
        renorm=opts["renorm"],
        bound=opts["bound"],
        block=opts["block"],
        progress=opts["progress"],
        **kw,
    )
    return rec, ens


@renamed(method="scheme")
def indicators(
    system: str,
    q,
    v,
    params,
    *,
    dt: float,
    steps: int,
    segments: int,
    spectrum: bool = False,
    gali: int = 0,
    megno: bool = False,
    transverse: tuple | None = None,
    vectors: tuple | None = None,
    scheme: str = DEFAULT_SCHEME,
    renorm: int = 0,
    seed: int = 0,
    bound: float = math.inf,
    block: int | None = None,
    progress: bool | None = False,
    reference_energy=None,
    parameters: dict | None = None,
) -> ChaosResult:
    """Lyapunov exponents, GALI/SALI, MEGNO and transverse exponents of R orbits.

    Parameters
    ----------
    system : str
        Engine system (``sink_<shape>_n<N>_k<K>``, ``henon_heiles``, ``duffing2``).
    q, v : arrays (D, R)
        Start states (positions, velocities); not modified.
    params : array (NPARAMS,) or (NPARAMS, R)
        The system's runtime parameters, shared or one column per run.
    dt, steps, segments : float, int, int
        Step, steps per segment (records and renormalisation at every segment end), and
        number of segments; dt and steps may be one per run (arrays (R,)) with the same
        segment time dt x steps (see :meth:`sinktheory.engine.core.Ensemble.run`); the
        result's times are then run 0's (dt x steps rounds differently for each step).
    spectrum : bool or "full" or "half"
        Lyapunov spectrum by the QR method: all 2D exponents from 2D vectors (True or
        "full"), or the D largest from D vectors with the rest by the symplectic pairing
        lambda_{2D+1-i} = -lambda_i ("half": half the tangent work; exact for a
        Hamiltonian flow, but nothing is left to check the pairing with).
    gali : int
        k of GALI_k (0: none; 2 also gives SALI).
    megno : bool
        MEGNO Y(t) of the first vector.
    transverse : (q, v, mask) or (q, v, mask, (dq, dv)), optional
        Start states (D, R) on an invariant subspace and the phase-space directions
        (bool, 2D) transverse to it: the growth of one vector confined to them (seeded
        random, or the given (D, 1, R) vectors).
    vectors : (dq, dv) arrays (D, M, R), optional
        Start deviation vectors instead of the seeded random orthonormal ones (M at least
        the number needed: 2D for the spectrum, k for GALI_k, 1 else).
    scheme : str
        Splitting scheme (:data:`sinktheory.integrators.SCHEMES`).
    renorm : int >= 0
        Steps between renormalisations inside a segment (0: at segment ends only); needed
        when the growth over one segment could overflow (ln growth > ~700).
    seed : int
        Seed of the random orthonormal start vectors (:mod:`~sinktheory.chaos.vectors`).
    bound : float
        Largest relative total-energy error tolerated (engine audit at segment ends).
    block : int, optional
        Runs per block of the engine (results are bitwise the same for any value).
    reference_energy : array (R,), optional
        H0 of the energy audit (default: energy of the start state).

    Returns
    -------
    ChaosResult
    """
    system, q, v, dt, steps, segments = check_run(system, q, v, dt, steps, segments, per_run=True)
    D, R = q.shape
    params = check_params(system, params, R)
    scheme = get_scheme(scheme)
    if transverse is not None:
        transverse = check_transverse(transverse, D, R)
    gali = check_gali(gali, D)
    renorm = check_renorm(renorm)
    megno = val.flag("megno", megno)
    seed = val.positive_int("seed", seed, minimum=0)
    block = check_block(block)
    bound = check_bound(bound)
    opts = {
        "renorm": renorm,
        "bound": bound,
        "block": block,
        "progress": progress,
        "reference_energy": reference_energy,
    }
    spectrum = check_spectrum(spectrum)
    count = vector_count(D, spectrum, gali)
    if vectors is None:
        dq, dv = random_vectors(D, count, R, seed)
    else:
        allowed = f"(dq, dv) of shape ({D}, >= {count}, {R}), finite"
        if not isinstance(vectors, tuple | list) or len(vectors) != 2:
            raise ParameterError("vectors", type(vectors).__name__, allowed)
        dq, dv = (val.real_array("vectors", a, allowed) for a in vectors)
        if dq.shape != dv.shape or dq.ndim != 3 or dq.shape[::2] != (D, R) or dq.shape[1] < count:
            raise ParameterError("vectors", f"arrays of shapes {dq.shape}, {dv.shape}", allowed)
        if not (np.isfinite(dq).all() and np.isfinite(dv).all()):
            raise ParameterError("vectors", "non-finite vectors", allowed)
    times = float(np.ravel(dt * steps)[0]) * np.arange(segments + 1)
    worst = np.zeros(R)
    out: dict = {}
    need_normalise = gali > 0 or not spectrum
    if spectrum:
        rec, _ = _run(
            system,
            q,
            v,
            params,
            (dq[:, :D].copy(), dv[:, :D].copy()) if spectrum == "half" else (dq, dv),
            "orthonormalise",
            scheme,
            dt,
            steps,
            segments,
            opts,
            megno=megno and not need_normalise,
            label="spectrum ",
        )
        out["spectrum_logs"] = rec.logs
        out["spectrum_paired"] = spectrum == "half"
        out["log_growth"] = rec.logs[:, :, 0]
        if megno and not need_normalise:
            out["megno"] = rec.megno
        worst = np.maximum(worst, rec.worst)
    if need_normalise:
        m = max(gali, 1)
        rec, _ = _run(
            system,
            q,
            v,
            params,
            (dq[:, :m].copy(), dv[:, :m].copy()),
            "normalise",
            scheme,
            dt,
            steps,
            segments,
            opts,
            gali=gali,
            megno=megno,
            label="lambda1 ",
        )
        out["log_growth"] = rec.logs[:, :, 0]
        if gali:
            out["gali"] = rec.gali
        if megno:
            out["megno"] = rec.megno
        worst = np.maximum(worst, rec.worst)
    if transverse is not None:
        qt, vt, mask, *given = transverse
        vecs = given[0] if given else random_vectors(D, 1, R, seed, mask=mask)
        topts = dict(opts, reference_energy=None)
        rec, _ = _run(
            system,
            qt,
            vt,
            params,
            vecs,
            "normalise",
            scheme,
            dt,
            steps,
            segments,
            topts,
            label="transverse ",
        )
        out["transverse_logs"] = rec.logs[:, :, 0]
        worst = np.maximum(worst, rec.worst)
    info = {
        "system": system,
        "params": np.asarray(params, float).tolist(),
        "scheme": scheme.name,
        "dt": dt.tolist() if np.ndim(dt) else float(dt),
        "steps_per_segment": steps.tolist() if np.ndim(steps) else int(steps),
        "segments": int(segments),
        "renorm": int(renorm),
        "seed": int(seed),
    }
    info.update(parameters or {})
    return ChaosResult(
        times=times,
        gali_order=gali,
        run_errors=worst,
        parameters=info,
        **out,
    )
