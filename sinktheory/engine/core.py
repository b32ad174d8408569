"""One engine for ensembles, tangent vectors and monodromy matrices.

:class:`Ensemble` owns the state of R runs of one generated system (positions and
velocities, structure of arrays, runs last), optionally M deviation vectors per run, and
advances them with a symmetric splitting scheme in segments of ``steps`` steps.  At each
segment end it audits the total energy of every run and records what was asked for.  The
deviation vectors follow the exact derivative of the same splitting step (the kick's
derivative uses the Hessian, the drift is linear), so the tangent map of a step is its
Jacobian and is symplectic; this is what the chaos indicators and the periodic-orbit
monodromy use.

Examples
--------
>>> import numpy as np
>>> from sinktheory.integrators import get_scheme
>>> ens = Ensemble("henon_heiles", np.array([[0.0], [0.1]]), np.array([[0.3], [0.0]]), [])
>>> out = ens.run(get_scheme("blanes-moan6"), dt=0.01, steps=100, segments=3)
>>> bool(out.worst.max() < 1e-12), out.shared.shape
(True, (1, 4))
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numba
import numpy as np

from ..errors import EnergyDriftError, NonFiniteStateError, ParameterError
from ..integrators import SplittingScheme
from ..limits import SECONDS_PER_PARTICLE_STEP, max_seconds
from ..model import DAMPING_KINDS
from ..progress import ProgressBar, chunks
from ..validation import choice, flag, nonnegative, positive, positive_int, real_array
from . import blocks
from .cache import cost_table_path, load

__all__ = ["Ensemble", "Records", "TANGENT_MODES"]

#: Tangent modes: none (raw deviation vectors, e.g. a monodromy matrix), Gram-Schmidt
#: orthonormalisation at every renormalisation (Lyapunov spectrum), or independent
#: normalisation (GALI/SALI, maximal exponent).
TANGENT_MODES = {"none": 0, "orthonormalise": 1, "normalise": 2}
_RUNNING, _DRIFT, _NONFINITE = 0, 1, 2


@dataclass(frozen=True)
class Records:
    """What :meth:`Ensemble.run` recorded at the segment ends 0..S (index 0 = start).

    shared : (R, S + 1) energy of the shared coordinates (the container), or None
    members : (R, S + 1, K) energy of each member (particle), or None
    trajectory : (R, samples, 2D) states every ``stride`` steps (sample 0 = start), or None
    logs : (R, S + 1, M) accumulated log growth of each deviation vector, or None
    gali : (R, S + 1) GALI_k of the first k deviation vectors, or None
    megno : (R, S + 1) MEGNO Y(t) of deviation vector 0, or None
    worst : (R,) largest relative energy error of each run over the segments (of H + W with damping)
    work : (R, S + 1) work the damping has taken from each run since the ensemble started, or None
    work_samples : (R, samples) the same work at the trajectory's samples, or None
    integral : (R,) the shared energy integrated over time since the ensemble started, or None
    """

    shared: np.ndarray | None
    members: np.ndarray | None
    trajectory: np.ndarray | None
    logs: np.ndarray | None
    gali: np.ndarray | None
    megno: np.ndarray | None
    worst: np.ndarray
    work: np.ndarray | None = None
    work_samples: np.ndarray | None = None
    integral: np.ndarray | None = None


class Ensemble:
    """R runs of a generated system, with optional deviation vectors.

    Parameters
    ----------
    system : str
        Engine name (see :func:`sinktheory.engine.cache.load`), e.g. ``sink_flat``.
    q, v : array (D, R)
        Positions and velocities (masses as in the system; for the sink, absolute ones).
    params : array (NPARAMS,) or (NPARAMS, R)
        The system's runtime parameters (sink: alpha, beta, gamma, mu), shared by every
        run or one column per run (so one ensemble can cover a grid of parameter values).
    dq, dv : array (D, M, R), optional
        Deviation vectors (M of them per run).
    tangent : {"none", "orthonormalise", "normalise"}
        What happens to the deviation vectors at each renormalisation.
    reference_energy : array (R,), optional
        H0 of the energy audit (default: the energy of the start state).
    damping : float >= 0
        c0 of the system's damping (:class:`~sinktheory.engine.systems.Damping`); 0, the
        default, is the conservative system, bitwise.
    damping_kind : {"contact", "viscous"}
        The damping's weight: the members' potential terms (contact) or 1.
    """

    def __init__(
        self,
        system: str,
        q,
        v,
        params,
        *,
        dq=None,
        dv=None,
        tangent: str = "none",
        reference_energy=None,
        damping: float = 0.0,
        damping_kind: str = "contact",
    ):
        if not isinstance(system, str):
            raise ParameterError("system", system, "the name of an engine system")
        try:
            self.module = load(system)
        except KeyError as e:
            raise ParameterError("system", system, "the name of an engine system",
                                 why=e.args[0]) from None  # fmt: skip
        self.system = system
        # copies: the engine advances its state in place and must not touch the caller's
        self.q = np.array(real_array("q", q), order="C")
        self.v = np.array(real_array("v", v), order="C")
        if self.q.ndim != 2:
            raise ParameterError("q", f"shape {self.q.shape}", "an array (D, R)")
        D, R = self.q.shape
        mod = self.module
        C = mod.MEMBER_COORDS
        if self.v.shape != self.q.shape or D < mod.SHARED or (C and (D - mod.SHARED) % C):
            raise ParameterError(
                "q, v",
                f"shapes {self.q.shape}, {self.v.shape}",
                f"(D, R) each with D = {mod.SHARED} + {C} x members",
            )
        if np.shape(params) not in ((mod.NPARAMS,), (mod.NPARAMS, R)):
            raise ParameterError("params", np.shape(params), f"({mod.NPARAMS},) or "
                                 f"({mod.NPARAMS}, {R}) values")  # fmt: skip
        try:
            self.table = mod.table_of(params, R)
        except ValueError as e:  # a run-time exponent that is not a whole number
            raise ParameterError("params", "these values", "parameters whose powers the "
                                 "kernels can raise", why=str(e)) from None  # fmt: skip
        if dq is None:
            dq = np.zeros((D, 0, R))
            dv = np.zeros((D, 0, R))
        self.dq = np.array(real_array("dq", dq), order="C")
        self.dv = np.array(real_array("dv", dv), order="C")
        if self.dq.shape != self.dv.shape or self.dq.shape[::2] != (D, R):
            raise ParameterError("dq, dv", f"shapes {self.dq.shape}", f"({D}, M, {R}) each")
        self.tangent = tangent = choice("tangent", tangent, tuple(TANGENT_MODES))
        damping = nonnegative("damping", damping)
        if damping and not mod.DAMPED:
            raise ParameterError("damping", damping, f"0 (system {system} has no damping)")
        damping_kind = choice("damping_kind", damping_kind, tuple(DAMPING_KINDS))
        self.damping = damping
        self.weighted = damping_kind == "contact"
        self.diss = np.zeros((2, R))  # work taken by the damping, integral of E_shared
        M = self.dq.shape[1]
        self.logs = np.zeros((M, R))
        self.meg = np.zeros((2, R))
        self.status = np.zeros(R, dtype=np.int64)
        self.time = 0.0
        self.tangent_start = 0.0
        self.segments_done = 0
        self._seconds: dict = {}  # plan -> seconds per segment, as last timed (_Chooser)
        self._warm = False  # the compiled code has run once in this ensemble
        total = self.energies()[0]
        self.h0 = total if reference_energy is None else real_array("reference_energy",
                                                                    reference_energy)  # fmt: skip
        if M and tangent != "none":
            # start from unit vectors so that the logs measure growth from |delta(0)| = 1
            norms = np.sqrt((self.dq**2).sum(0) + (self.dv**2).sum(0))
            if np.any(norms == 0) or not np.all(np.isfinite(norms)):
                raise ParameterError(
                    "dq, dv", "a zero or non-finite deviation vector", "non-zero finite vectors"
                )
            self.dq /= norms
            self.dv /= norms

    @property
    def runs(self) -> int:
        return self.q.shape[1]

    def _take(self, runs) -> Ensemble:
        """A new ensemble of the runs ``runs`` (indices or a boolean mask), continuing
        exactly where these are: state, deviation vectors and their logs, audit reference,
        time.  Advancing it gives each run bitwise what advancing this one would."""
        new = object.__new__(Ensemble)
        new.__dict__.update(self.__dict__)
        for name in ("q", "v", "dq", "dv", "logs", "meg", "table", "status", "h0", "diss"):
            setattr(new, name, np.ascontiguousarray(getattr(self, name)[..., runs]))
        new._seconds = {}  # other runs, other plans
        return new

    @property
    def vectors(self) -> int:
        return self.dq.shape[1]

    def energies(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(total (R,), shared (R,), members (K, R)) energies of the current state."""
        return self.module.block_energies(self.q, self.v, self.table)

    def run(
        self,
        scheme,
        *,
        dt: float,
        steps: int,
        segments: int,
        record: tuple[str, ...] = ("shared",),
        stride: int = 0,
        renorm: int = 0,
        gali: int = 0,
        megno: bool = False,
        bound: float = math.inf,
        block: int | None = None,
        progress: bool | None = False,
        label: str = "engine ",
        unit: str = "segment",
    ) -> Records:
        """Advance ``segments`` segments of ``steps`` steps of size ``dt``.

        ``dt`` and ``steps`` may also be given per run (arrays (R,)), when the runs need
        different steps for the same segment (say, a chaos map over beta): ``dt * steps``
        must then be the same segment time for every run, ``renorm`` (counted in steps)
        must be 0, and ``stride`` (in steps too) may be one per run, giving every run the
        same number of samples (``stride = steps`` samples each segment end).  The runs
        are grouped by their steps; each group is cut into blocks of its own, and a run's
        numbers are bitwise those it gets in an ensemble of its group alone (MEGNO after a
        continued run only to the rounding of the segment time, which the ensemble counts
        with run 0's dt x steps).

        ``record`` is a subset of {"shared", "members", "trajectory", "logs", "work",
        "integral"} ("work": the damping's work at segment ends, and at the trajectory's
        samples; "integral": the shared energy integrated over time); ``stride``
        steps between trajectory samples; ``renorm`` steps between renormalisations of the
        deviation vectors inside a segment (0: only at segment ends); ``gali`` = k records
        GALI_k; ``megno`` records MEGNO of vector 0.  A run whose relative energy error
        exceeds ``bound`` or whose state becomes non-finite stops the engine with
        :class:`~sinktheory.errors.EnergyDriftError` / :class:`NonFiniteStateError` naming
        the run and the time (the earliest failure, whatever the threads); ``unit`` is
        what the messages call a segment.
        """
        if not isinstance(scheme, SplittingScheme):
            raise ParameterError("scheme", scheme, "a SplittingScheme (sinktheory.integrators."
                                 "get_scheme)")  # fmt: skip
        R, M, D = self.runs, self.vectors, self.q.shape[0]
        K = self.module.members_of(D)
        S = positive_int("segments", segments, minimum=0)
        record, renorm, gali, megno, bound = _checked_options(record, renorm, gali, megno, bound)
        if block is not None:
            block = positive_int("block", block, maximum=np.iinfo(np.int64).max)
        if progress is not None:
            progress = flag("progress", progress)
        for name, text in (("label", label), ("unit", unit)):
            if not isinstance(text, str):
                raise ParameterError(name, text, "a string")
        if gali > M or (megno and M == 0):
            raise ParameterError("gali", gali, f"at most the number of deviation vectors ({M})")
        dt, steps, segment_time = _per_run_steps(dt, steps, R, renorm)
        _check_work(steps, S, K, scheme)
        stride, samples = _strides(stride if "trajectory" in record else 0, steps, S)
        groups = blocks.groups_of(steps)
        threads = numba.get_num_threads()
        if block is None:  # the plans _Chooser times against each other
            plans = blocks.candidates(groups, self.block_costs(), threads)
        else:
            plans = [blocks.fixed(groups, block, threads)]
        layouts = {p: _Layout.of(p, steps, dt, stride) for p in plans}
        # rows of the audit and the records: the runs, then the inert copies (discarded)
        Rp = max(p.padded for p in plans)
        top = int(steps.max())  # the slowest group's steps
        rec = {
            "shared": np.zeros((Rp, S + 1 if "shared" in record else 0)),
            "members": np.zeros((Rp, S + 1 if "members" in record else 0, K)),
            "logs": np.zeros((Rp, S + 1 if "logs" in record else 0, M)),
            "gali": np.zeros((Rp, S + 1 if gali else 0)),
            "megno": np.zeros((Rp, S + 1 if megno else 0)),
            "work": np.zeros((Rp, S + 1 if "work" in record else 0)),
        }
        wsamples = np.zeros((Rp, samples if "work" in record else 0))
        total, shared, members = self.energies()
        if "shared" in record:
            rec["shared"][:R, 0] = shared
        if "members" in record:
            rec["members"][:R, 0] = members.T
        if "logs" in record:
            rec["logs"][:R, 0] = self.logs.T
        if "work" in record:
            rec["work"][:R, 0] = self.diss[0]
            if samples:
                wsamples[:R, 0] = self.diss[0]
        traj = np.zeros((Rp, samples, 2 * D))
        if samples:
            Sh = self.module.SHARED
            traj[:R, 0] = np.concatenate(
                [self.q[:Sh].T, self.v[:Sh].T, self.q[Sh:].T, self.v[Sh:].T], axis=1
            )
        if gali:
            rec["gali"][:, 0] = 1.0
        if megno:
            rec["megno"][:, 0] = 2.0  # the limit of Y(t) as t -> 0 (ln|delta| ~ linear)
        fixed = (
            scheme.arrays(),
            (TANGENT_MODES[self.tangent], int(renorm), int(gali), bool(megno),
             self.time - self.tangent_start),
            float(bound),
            (rec["shared"], rec["members"], traj, rec["logs"], rec["gali"], rec["megno"],
             rec["work"], wsamples),
            (self.damping > 0.0, self.damping, self.weighted, "integral" in record),
        )  # fmt: skip
        fails = (np.zeros(Rp, dtype=np.int64), np.zeros(Rp), np.zeros(Rp))  # segment, H, worst
        chunk = max(1, math.ceil(S / 100))
        # the cost table is per run and Verlet step (one force evaluation); a step of the
        # scheme evaluates the forces once per stage
        chooser = _Chooser(plans, self._seconds, top * len(fixed[0][0]))
        bar = ProgressBar(S, enabled=progress is not False, label=label, unit=unit)
        seg_base = self.segments_done
        try:  # chunks of ~0.1 s (at most 1 % of the work), interrupts acted on between
            for start, stop in chunks(S, most=chunk):
                policy = chooser.next()
                numba.set_num_threads(policy.threads)
                t0 = time.perf_counter()
                self._advance(layouts[policy], start, stop, fixed, fails)
                chooser.record(policy, (time.perf_counter() - t0) / (stop - start), self._warm)
                self._warm = True
                self._raise_on_failure(
                    fails[0][:R], fails[1][:R], segment_time, seg_base, bound, unit
                )
                bar.update(stop - start)
        finally:
            numba.set_num_threads(threads)
            bar.close()
        self.segments_done += S
        self.time += S * segment_time
        rec = {name: a[:R] for name, a in rec.items()}
        traj, worst, wsamples = traj[:R], fails[2][:R], wsamples[:R]
        return Records(
            shared=rec["shared"] if "shared" in record else None,
            members=rec["members"] if "members" in record else None,
            trajectory=traj if samples else None,
            logs=rec["logs"] if "logs" in record else None,
            gali=rec["gali"] if gali else None,
            megno=rec["megno"] if megno else None,
            worst=worst,
            work=rec["work"] if "work" in record else None,
            work_samples=wsamples if samples and "work" in record else None,
            integral=self.diss[1].copy() if "integral" in record else None,
        )

    def _advance(self, layout: _Layout, start, stop, fixed, fails) -> None:
        """Segments [start, stop) of every run laid out by ``layout`` (blocks, threads):
        the runs' own arrays, or copies in the layout's columns that are written back."""
        weights, tangent, bound, rec, damp = fixed
        own = (self.q, self.v, self.dq, self.dv, self.logs, self.meg, self.diss, self.table)
        state = [layout.gather(a) for a in own]
        h0, status = (layout.by_row(a) for a in (self.h0, self.status))
        rows = layout.rows
        fail_segment, fail_energy, worst = (a[:rows] for a in fails)
        Q, V, DQ, DV, logs, meg, diss, table = state
        try:
            self.module.advance(
                Q, V, DQ, DV, table, weights, start, stop, layout.compiled, tangent, logs, meg,
                (h0, bound, status, fail_segment, fail_energy, worst),
                tuple(a[:rows] if isinstance(a, np.ndarray) else a for a in rec), damp, diss,
            )  # fmt: skip
        finally:
            for mine, advanced in zip(own[:-1], state[:-1], strict=True):
                layout.scatter(advanced, mine)
            self.status[:] = status[: self.runs]

    def plan(self, threads: int | None = None) -> blocks.BlockPlan:
        """The plan the cost table predicts fastest for these runs (see
        :mod:`sinktheory.engine.blocks`): at most ``threads`` threads (default: numba's
        current number; at most numba's ``NUMBA_NUM_THREADS``).  :meth:`run` times it against
        the other candidates while running (:func:`blocks.candidates`) and keeps the fastest."""
        if threads is None:
            threads = numba.get_num_threads()
        threads = positive_int("threads", threads, maximum=numba.config.NUMBA_NUM_THREADS)
        return blocks.plan(self.runs, self.block_costs(), threads)

    def timings(self) -> dict[blocks.BlockPlan, float]:
        """The plans this ensemble has timed while running, with the best of their recent
        seconds per segment (the fastest is the one it runs)."""
        return {p: min(t) for p, t in self._seconds.items()}

    def block_costs(self) -> dict[int, float]:
        """This machine's cost per run and Verlet step of the engine for each block size
        (measured once, then read from the cache; :func:`blocks.block_costs`)."""
        D = self.q.shape[0]
        one = (self.q[:, :1], self.v[:, :1], self.table[:, :1])
        return blocks.block_costs(
            self.module, cost_table_path(self.system, D), self.module.members_of(D), one
        )

    def _raise_on_failure(self, fail_segment, fail_energy, segment_time, seg_base, bound, unit):
        """Raise for the earliest failure (segment, then run): the same whatever the
        block size or thread count (inert copies are not looked at)."""
        r = earliest_failure(self.status, fail_segment)
        if r is None:
            return
        seg = int(fail_segment[r])
        t = self.time + seg * segment_time
        where = f"run {r} at t = {t:.6g} ({unit} {seg_base + seg})"
        raise audit_error(where, self.status[r] == _NONFINITE, float(fail_energy[r]),
                          float(self.h0[r]), bound, ("the step is too large for this "
                          "stiffness", "use a smaller dt or tolerance"),
                          "H + W" if self.damping else "H")  # fmt: skip


def earliest_failure(status: np.ndarray, fail_segment: np.ndarray) -> int | None:
    """The run that failed first (earliest segment, then lowest run index) among runs
    whose ``status`` is not 0, or None: the same whatever the blocks and threads."""
    failed = np.flatnonzero(status)
    if failed.size == 0:
        return None
    return int(failed[np.lexsort((failed, fail_segment[failed]))[0]])


def audit_error(where: str, nonfinite: bool, H: float, H0: float, bound: float,
                advice: tuple[str, str], audited: str = "H") -> Exception:  # fmt: skip
    """The error of a run that failed the energy audit at ``where``: a non-finite state,
    or a relative total-energy error over ``bound``; ``advice`` = (what to say for each).
    ``audited`` names what is conserved: the energy H, or with damping H + W (the energy
    plus the work dissipated), whose value ``H`` is then."""
    what = "total energy" if audited == "H" else "energy plus dissipated work"
    if nonfinite:
        return NonFiniteStateError(f"{where}: the state became non-finite ({what} "
                                   f"{H!r}, started at {H0!r}); {advice[0]}")  # fmt: skip
    err = abs(H - H0) / (abs(H0) or 1.0)
    error = "total-energy error" if audited == "H" else f"error of {what}"
    return EnergyDriftError(f"{where}: relative {error} {err:.3g} > bound {bound:.3g} "
                            f"({audited} = {H!r}, H0 = {H0!r}); {advice[1]}")  # fmt: skip


#: What :meth:`Ensemble.run` can record.
RECORDABLE = ("shared", "members", "trajectory", "logs", "work", "integral")


def _checked_options(record, renorm, gali, megno, bound) -> tuple:
    """(record, renorm, gali, megno, bound) of :meth:`Ensemble.run`, checked: ``record`` a
    collection of names among :data:`RECORDABLE`, ``renorm`` and ``gali`` integers >= 0,
    ``megno`` a bool, ``bound`` a number > 0 (inf: none); else ParameterError naming it."""
    allowed = "a tuple of names among " + ", ".join(RECORDABLE)
    if isinstance(record, str) or not isinstance(record, tuple | list | set | frozenset):
        raise ParameterError("record", record, allowed)
    if any(not isinstance(r, str) or r not in RECORDABLE for r in record):
        raise ParameterError("record", tuple(record), allowed)
    renorm = positive_int("renorm", renorm, minimum=0, maximum=np.iinfo(np.int64).max)
    gali = positive_int("gali", gali, minimum=0)
    megno = flag("megno", megno)
    if bound != math.inf:
        bound = positive("bound", bound)
    return tuple(record), renorm, gali, megno, bound


def _per_run_steps(dt, steps, runs: int, renorm: int):
    """(dt (R,), steps (R,), segment time) from one step or one per run; refuses steps per
    run whose segments differ, or that vary together with renorm (in steps)."""
    if np.ndim(dt) == 0 and np.ndim(steps) == 0:  # one step for all (the common case)
        steps = positive_int("steps", steps)
        dt = positive("dt", dt)
        if not dt * steps < math.inf:
            raise ParameterError("dt, steps", (dt, steps), "a positive finite step and a "
                                 "positive integer number of steps")  # fmt: skip
        return np.full(runs, dt), np.full(runs, steps), dt * steps
    dt_r = _per_run("dt", real_array("dt", dt), runs)
    steps_r = _per_run("steps", np.asarray(steps), runs)
    if steps_r.dtype.kind not in "iuf" or np.any(steps_r < 1) or np.any(steps_r % 1):
        raise ParameterError("steps", steps, "a positive integer, or one per run")
    segment = dt_r * steps_r
    if not np.all(np.isfinite(segment)) or np.any(dt_r <= 0):
        raise ParameterError("dt", dt, "a positive finite step, or one per run")
    spread = float(np.ptp(segment) / segment[0])
    if spread > 1e-12:
        raise ParameterError("dt, steps", f"segments dt x steps differing by {spread:.2g}",
                             "one segment time for every run (to 1e-12)")  # fmt: skip
    if np.unique(steps_r).size > 1 and renorm:
        raise ParameterError("renorm", renorm,
                             "0 when the runs take different steps (it counts steps)")  # fmt: skip
    return dt_r, steps_r.astype(np.int64), float(segment[0])


def _check_work(steps: np.ndarray, segments: int, members: int, scheme) -> None:
    """Refuse ``segments`` segments of ``steps`` steps (one per run) beyond the work limit
    in force (:func:`sinktheory.worklimit.max_seconds`), priced at a lower bound of
    :func:`sinktheory.worklimit.ensemble_steps` (each run's members, at least one, by the
    scheme's stages; no vectors, no blocks): the callers' own checks, which price the same
    work higher, refuse first; this catches the work they did not check."""
    per_step = max(members, 1) * scheme.relative_cost * SECONDS_PER_PARTICLE_STEP
    seconds = float(np.sum(steps, dtype=float)) * segments * per_step
    limit = max_seconds()
    if seconds > limit:
        name, value = ("segments", segments) if segments > steps.max() else ("steps", steps.max())
        raise ParameterError(
            name, value, f"at most {limit:.3g} s of estimated engine work (the limit in force; "
            "sinktheory.worklimit.interactive_limit raises it)",
            why=f"{segments} segments of {int(steps.max())} steps of {len(steps)} runs: "
            f"about {seconds:.3g} s",
        )  # fmt: skip


def _per_run(name: str, value: np.ndarray, runs: int) -> np.ndarray:
    """``value`` broadcast to one per run, else ParameterError naming ``name``."""
    try:
        return np.broadcast_to(value, (runs,))
    except ValueError:
        shown = f"an array of shape {value.shape}"
        raise ParameterError(name, shown, f"one value, or one per run ({runs})") from None


def _strides(stride, steps: np.ndarray, segments: int) -> tuple[np.ndarray, int]:
    """(stride (R,), samples) of the trajectory record: steps between samples, one for all
    runs or one per run (0: no record); every run must give the same number of samples
    S x steps // stride + 1."""
    if np.ndim(stride) == 0 and stride == 0:  # no trajectory (the common case)
        return np.zeros_like(steps), 0
    stride_r = _per_run("stride", np.asarray(stride), len(steps))
    top = np.iinfo(np.int64).max
    if stride_r.dtype.kind not in "iuf" or np.any(
        (stride_r < 0) | (stride_r > top) | (stride_r % 1)
    ):
        raise ParameterError("stride", stride, "a non-negative integer, or one per run")
    stride_r = stride_r.astype(np.int64)
    if not stride_r.any():
        return np.zeros_like(steps), 0
    if not stride_r.all():
        raise ParameterError("stride", stride, "positive for every run, or 0 for all")
    samples = segments * steps // stride_r + 1
    if np.ptp(samples):
        raise ParameterError("stride", stride, "strides giving every run the same number "
                             "of samples (segments x steps // stride): stride = steps")  # fmt: skip
    return stride_r, int(samples[0])


@dataclass(frozen=True)
class _Layout:
    """A plan's columns (:func:`blocks.layout`) and how the ensemble's arrays (runs last)
    map to and from them; ``columns`` is None when they are the runs themselves, and
    ``source`` is the run behind each record row (the runs, then each inert copy's run)."""

    columns: np.ndarray | None
    compiled: tuple
    runs: int
    rows: int
    source: np.ndarray

    @classmethod
    def of(cls, plan: blocks.BlockPlan, steps, dt, stride) -> _Layout:
        columns, compiled = blocks.layout(plan, steps, dt, stride)
        R, rows = steps.size, compiled[2]
        own = columns.size == R and bool(np.all(columns == np.arange(R)))
        source = np.empty(columns.size, dtype=np.int64)
        source[rows] = columns
        return cls(None if own else columns, compiled, R, columns.size, source)

    def gather(self, a: np.ndarray) -> np.ndarray:
        if self.columns is None:
            return a
        return np.ascontiguousarray(a[..., self.columns])

    def by_row(self, a: np.ndarray) -> np.ndarray:
        """``a`` (R,) per record row (a copy)."""
        return a[self.source]

    def scatter(self, advanced: np.ndarray, mine: np.ndarray) -> None:
        """Write the real runs of ``advanced`` (columns) back into ``mine`` (runs)."""
        if advanced is mine:
            return
        real = self.compiled[2] < self.runs
        mine[..., self.columns[real]] = advanced[..., real]


class _Chooser:
    """Which plan each chunk of segments runs with.  One plan: always it.  Several (see
    :func:`blocks.candidates`): the first chunk of an ensemble only warms up (it may include
    compilation) and runs the predicted plan; then each plan *worth timing* is timed
    :data:`TRIES` times, the least timed first, and the one whose best of its last TRIES
    timings is fastest per segment carries on (a best-of is robust to the pauses of a shared
    machine), with every 16th chunk re-timing one of the others in turn, so that a core
    that becomes busy (or free) is noticed.  A plan is worth timing when it is the
    predicted one, has been timed, or its predicted time per segment (``predicted`` per
    Verlet step times ``evaluations`` per segment) is below the fastest time seen: the
    one-thread table never overrates a plan much (threads do not beat it), so a plan
    predicted slower than what runs already is not tried (a short ensemble of a few runs
    spent 2 of its 5 periods on a one-thread plan predicted twice as slow).  ``seconds``
    (plan -> recent seconds per segment) is the ensemble's, kept across its runs.  The
    numbers do not depend on the choice."""

    REFRESH = 16
    TRIES = 2

    def __init__(self, plans, seconds: dict, evaluations: float = 1.0):
        self.plans = plans
        self.seconds = seconds
        self.evaluations = evaluations
        self.count = 0

    def _worth_timing(self) -> list:
        seen = [min(self.seconds[p]) for p in self.plans if self.seconds.get(p)]
        fastest = min(seen, default=math.inf)
        return [
            p
            for p in self.plans
            if p == self.plans[0]
            or self.seconds.get(p)
            or not p.predicted * self.evaluations >= fastest
        ]

    def next(self) -> blocks.BlockPlan:
        i, self.count = self.count, self.count + 1
        if len(self.plans) == 1 or not self.seconds:
            return self.plans[0]
        plans = self._worth_timing()
        timed = {p: len(self.seconds.get(p, ())) for p in plans}
        if min(timed.values()) < self.TRIES:
            return min(plans, key=timed.__getitem__)
        best = min(plans, key=lambda p: min(self.seconds[p]))
        others = [p for p in plans if p != best]
        if others and i % self.REFRESH == self.REFRESH - 1:
            return others[(i // self.REFRESH) % len(others)]
        return best

    def record(self, plan, seconds_per_segment: float, warm: bool) -> None:
        if warm:
            recent = self.seconds.setdefault(plan, [])
            recent.append(seconds_per_segment)
            del recent[: -self.TRIES]
