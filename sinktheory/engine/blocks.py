"""How the engine cuts an ensemble into blocks and threads: measured, not assumed.

The engine's loops run over the runs of a block, and what a block of B runs costs depends
on how the compiler vectorised those loops on this machine.  LLVM's main vector body takes
16 runs at a time and an epilogue 4 (see :mod:`sinktheory.engine.cache`), so on a 2-core
AVX2 machine a block of 4 runs costs about 2x a block of 64 per run, a block of 1 about 7x,
and a block of 13 pays a scalar remainder of one run; other CPUs differ.  No constant
block size is right everywhere, so the policy is:

1. **Measure** (:func:`block_costs`): the cost per run and step of the compiled engine for
   the block sizes :data:`SIZES`, timed on the engine itself (one thread, a synthetic state
   of the same system and number of members).  The table is cached on disk beside the
   compiled kernels, keyed by the engine, the number of members and the machine (CPU name
   and features, numba version), so each machine measures once (about 0.2-0.5 s).
2. **Plan** (:func:`plan`): for R runs and up to T threads pick the block size b from
   :data:`SIZES` and the thread count t that minimise the predicted wall time
   ceil(ceil(R / b) / t) b c(b).  The last block is filled up to b with *inert copies* of
   the last run (their results are discarded), which is cheaper than a remainder loop
   whenever the table says so.  A second thread is used only for blocks of at least the
   :func:`efficient_width` (each thread gets an efficient block; an ensemble smaller than
   two such blocks stays on one thread, so it never waits for a busy second core) and
   only when the prediction gains at least :data:`THREAD_GAIN` from it.
3. **Check while running** (:func:`candidates`, ``sinktheory.engine.core``): the table is
   measured on one thread, and two threads that share a core's vector units or caches do
   not run twice as fast, so the chosen plan, the best one-thread plan and the plans
   predicted nearly as fast are each timed on a few chunks of the run, and the fastest
   carries on (re-timed now and then); a plan predicted slower than the fastest time seen
   is not tried (a second thread never beats the one-thread table's prediction).

Results do not depend on the plan: a run's arithmetic is the same in every block and
thread, and inert copies never touch real runs (``tests/simulation/test_engine.py``
checks the numbers bitwise for several block sizes, thread counts and paddings).

Examples
--------
>>> import numpy as np
>>> costs = {1: 1.0, 4: 0.5, 16: 0.1}          # seconds per run-step for b = 1, 4, 16
>>> p = plan(13, costs, threads=1)
>>> p.block, p.padded, p.threads                # 13 runs as one padded block of 16
(16, 16, 1)
>>> plan(1, costs, threads=2).block             # one run: no padding pays
1
>>> plan(32, costs, threads=2).threads          # two efficient blocks: two threads
2
"""

from __future__ import annotations

import functools
import hashlib
import json
import math
import os
import tempfile
import time
from dataclasses import dataclass

import numpy as np

__all__ = [
    "BlockPlan",
    "CALIBRATION",
    "machine_key",
    "SIZES",
    "THREAD_GAIN",
]

#: Block sizes the policy measures and chooses from (a last block is padded up to one).
SIZES = (1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 28, 32, 40, 48, 56, 64)
#: A second thread must cut the predicted wall time by this factor to be used (a thread
#: start and a shared core cost something the per-block table does not see).
THREAD_GAIN = 1.15
#: Runs and steps of each calibration measurement (about 0.2-2 ms each).
_CALIBRATION_WORK = 8192
#: Version of :func:`measure`; a cached table measured by another version is measured again
#: (4: a disturbed, implausibly small difference is timed again, never kept as near zero;
#: 3: the short and long timings alternate, five of each; 2: one Verlet step per step;
#: version 1 ran a two-stage scheme that read one kick weight past its array).
CALIBRATION = 4
#: Timings of each length per block size (alternating short and long, best kept).
_REPEATS = 5
#: Rounds of :data:`_REPEATS` timings before :func:`measure` settles for an upper bound.
_ROUNDS = 3


@dataclass(frozen=True)
class BlockPlan:
    """How an ensemble of ``runs`` runs is advanced.

    block : runs per block
    padded : runs advanced, ``blocks * block`` >= runs (the extra ones are inert copies)
    threads : threads used
    predicted : predicted seconds per step of the whole ensemble (from the cost table)
    pad : whether the last block of a group is filled up with inert copies
    groups : ((runs, steps relative to the largest), ...) of each step group when the runs
    do not all take the same steps per segment (each group is cut into blocks and padded
    on its own); () for one group
    """

    runs: int
    block: int
    padded: int
    threads: int
    predicted: float
    groups: tuple[tuple[int, float], ...] = ()
    pad: bool = True

    @property
    def blocks(self) -> int:
        return sum(-(-count // self.block) for count, _ in self._groups)

    @property
    def _groups(self) -> tuple[tuple[int, float], ...]:
        return self.groups or ((self.runs, 1.0),)

    def work(self) -> list[float]:
        """Each block's steps relative to the largest, in group order."""
        return [w for count, w in self._groups for _ in range(-(-count // self.block))]

    def parts(self) -> list[int]:
        """Where the blocks (in group order) are cut into the threads' contiguous parts:
        the cut points 0 = p_0 <= ... <= p_threads = blocks, balancing their steps."""
        if self.threads == 1:
            return [0, self.blocks]
        return _partition(self.work(), self.threads)


def _partition(work: list[float], parts: int) -> list[int]:
    """Cut points of ``work`` (in order) into at most ``parts`` contiguous parts of about
    equal sums: each part takes blocks up to its share of what is left, the last one
    only if that brings its sum closer to the share.

    Examples
    --------
    >>> _partition([1.0] * 13, 2), _partition([1.0, 1.0, 4.0], 2)
    ([0, 7, 13], [0, 2, 3])
    """
    cuts, i, left = [0], 0, float(sum(work))
    for j in range(parts - 1, 0, -1):
        share, got = left / (j + 1), 0.0
        while i < len(work) and (got + work[i] <= share or
                                 share - got >= got + work[i] - share):  # fmt: skip
            got += work[i]
            i += 1
        left -= got
        cuts.append(i)
    return [*cuts, len(work)]


def efficient_width(costs: dict[int, float]) -> int:
    """The efficient block width on this machine: the smallest block size whose cost per
    run is within twice the cheapest of the table (the width the compiled loops vectorise
    to; a block narrower than that runs partly as scalar code).

    Examples
    --------
    >>> efficient_width({1: 5.0, 2: 4.0, 4: 1.9, 16: 1.0})
    4
    """
    cheapest = min(costs.values())
    return min(b for b, c in costs.items() if c <= 2 * cheapest)


def _options(runs, costs: dict[int, float], threads: int) -> list[BlockPlan]:
    """Every plan of :data:`SIZES` x threads, a second thread only for blocks of at least
    the :func:`efficient_width` (so each thread gets an efficient block and tiny ensembles
    never wait for a second, possibly busy, core).  ``runs`` is a number of runs or step
    groups ((runs, relative steps), ...) (:func:`groups_of`)."""
    groups, total = _groups_and_total(runs)
    threads, width = max(1, int(threads)), efficient_width(costs)
    out = []
    for b, c in sorted(costs.items()):
        blocks = BlockPlan(total, b, 0, 1, 0.0, groups).blocks
        top = min(threads, blocks) if b >= width else 1
        for t in range(1, top + 1):
            if groups:  # the slowest thread's blocks, weighted by their steps
                shape = BlockPlan(total, b, blocks * b, t, 0.0, groups)
                work, cuts = shape.work(), shape.parts()
                slowest = max(sum(work[i:j]) for i, j in zip(cuts, cuts[1:], strict=False))
            else:  # equal blocks: what _partition gives, without building it
                slowest = -(-blocks // t)
            out.append(BlockPlan(total, b, blocks * b, t, slowest * b * c, groups))
    return out


def _groups_and_total(runs) -> tuple[tuple[tuple[int, float], ...], int]:
    """(step groups, number of runs) from a number of runs or step groups."""
    if isinstance(runs, tuple):
        groups = tuple((int(c), float(w)) for c, w in runs)
        return groups, sum(c for c, _ in groups)
    return (), int(runs)


def groups_of(steps) -> tuple[tuple[int, float], ...] | int:
    """The step groups of runs taking ``steps`` (R,) steps per segment: the number of runs
    itself when all take the same, else ((runs, steps / largest), ...) in increasing
    steps (the ``runs`` of :func:`plan` and :func:`candidates`).

    Examples
    --------
    >>> groups_of([10, 10, 10]), groups_of([10, 20, 10])
    (3, ((2, 0.5), (1, 1.0)))
    """
    steps = np.asarray(steps, dtype=np.int64)
    if steps.min() == steps.max():
        return steps.size
    values, counts = np.unique(steps, return_counts=True)
    return tuple((int(c), float(s / values[-1])) for s, c in zip(values, counts, strict=True))


def plan(runs: int, costs: dict[int, float], threads: int) -> BlockPlan:
    """The block size and thread count with the smallest predicted wall time.

    ``costs`` maps block size to seconds per run and step (:func:`block_costs`); a second
    thread must gain :data:`THREAD_GAIN`; ties go to fewer threads, then to fewer padded
    runs.
    """
    return _best(_options(runs, costs, threads))


def _best(options: list[BlockPlan]) -> BlockPlan:
    return min(
        options,
        key=lambda p: (p.predicted * (THREAD_GAIN if p.threads > 1 else 1.0), p.threads,
                       p.padded, p.block),
    )  # fmt: skip


def candidates(runs: int, costs: dict[int, float], threads: int, *, within: float = 1.1,
               limit: int = 3) -> list[BlockPlan]:  # fmt: skip
    """The plans worth timing while the ensemble runs: :func:`plan`'s choice, the best
    one-thread plan, and the plans predicted within ``within`` of the fastest (at most
    ``limit`` in all).  The table is measured on one thread, so it cannot tell which of
    several near-equal plans two threads that share a core's resources run fastest.

    Examples
    --------
    >>> costs = {16: 16.7e-9, 24: 11.1e-9, 32: 10.7e-9}
    >>> [(p.block, p.threads) for p in candidates(25, costs, 2)]
    [(24, 2), (32, 1), (16, 2)]
    """
    options = _options(runs, costs, threads)
    chosen = _best(options)
    options = sorted(options, key=lambda p: (p.predicted, p.threads, p.padded))
    single = min((p for p in options if p.threads == 1), key=lambda p: p.predicted)
    near = [p for p in options if p.predicted <= within * options[0].predicted]
    out = list(dict.fromkeys([chosen, single, *near]))
    return out[:limit]


def fixed(runs, block: int, threads: int) -> BlockPlan:
    """A plan with a block size the caller chose: no padding, at most one thread per
    block (``runs`` as for :func:`plan`)."""
    block = max(1, int(block))
    groups, total = _groups_and_total(runs)
    blocks = BlockPlan(total, block, total, 1, math.nan, groups).blocks
    return BlockPlan(total, block, total, max(1, min(int(threads), blocks)), math.nan, groups,
                     pad=False)  # fmt: skip


def layout(plan: BlockPlan, steps, dt, stride=0) -> tuple[np.ndarray, tuple]:
    """Where each run of ``plan`` goes: (columns, (parts, bounds, rows, dt, steps, stride)).

    ``steps``, ``dt``, ``stride`` (R,): each run's steps per segment, step, and steps
    between trajectory samples (0: none; runs of one step count share it).  The runs are laid out
    group by group (increasing steps, run order within a group), each group cut into blocks
    of ``plan.block`` runs and, when the plan pads, its last block filled with inert copies
    of the group's last run.  ``columns`` (C,): the run in each column; the second item is
    the compiled ``advance``'s layout: thread parts (cut points into the blocks), block
    bounds (cut points into the columns), the record row of each column (a run's own index
    for a real run, R, R + 1, ... for the inert copies), and each block's step, steps and stride.

    Examples
    --------
    >>> p = fixed(((2, 0.5), (1, 1.0)), 4, 1)
    >>> columns, (parts, bounds, rows, dts, steps, _) = layout(p, [20, 10, 10], [0.1, 0.2, 0.2])
    >>> columns.tolist(), bounds.tolist(), steps.tolist()
    ([1, 2, 0], [0, 2, 3], [10, 20])
    """
    steps = np.asarray(steps, dtype=np.int64)
    dt = np.asarray(dt, dtype=np.float64)
    stride = np.broadcast_to(np.asarray(stride, dtype=np.int64), steps.shape)
    R, b = steps.size, plan.block
    if not plan.groups:  # one step count: the runs in order, then the inert copies
        bounds = np.minimum(np.arange(plan.blocks + 1) * b, plan.padded)
        n = bounds.size - 1
        columns = np.minimum(np.arange(plan.padded), R - 1)
        return columns, (
            np.asarray(plan.parts(), dtype=np.int64), bounds, np.arange(plan.padded),
            np.full(n, dt[0]), np.full(n, steps[0]), np.full(n, stride[0]),
        )  # fmt: skip
    columns, rows, bounds, block_dt, block_steps, block_stride = [], [], [0], [], [], []
    inert = R
    for s in np.unique(steps):
        members = np.flatnonzero(steps == s)
        for i in range(0, members.size, b):
            chunk = members[i : i + b].tolist()
            extra = b - len(chunk) if plan.pad else 0
            columns += chunk + [chunk[-1]] * extra
            rows += chunk + list(range(inert, inert + extra))
            inert += extra
            bounds.append(len(columns))
            block_dt.append(dt[chunk[0]])
            block_steps.append(s)
            block_stride.append(stride[chunk[0]])
    parts = np.asarray(plan.parts(), dtype=np.int64)
    return np.asarray(columns, dtype=np.int64), (
        parts, np.asarray(bounds, dtype=np.int64), np.asarray(rows, dtype=np.int64),
        np.asarray(block_dt, dtype=np.float64), np.asarray(block_steps, dtype=np.int64),
        np.asarray(block_stride, dtype=np.int64),
    )  # fmt: skip


@functools.cache
def machine_key() -> str:
    """What the cost table depends on besides the engine: CPU name and features, numba and
    llvmlite versions (a digest)."""
    import llvmlite
    import llvmlite.binding as llvm
    import numba

    text = "|".join(
        [
            llvm.get_host_cpu_name(),
            llvm.get_host_cpu_features().flatten(),
            numba.__version__,
            llvmlite.__version__,
        ]
    )
    return hashlib.sha256(text.encode()).hexdigest()[:12]


_memory: dict[tuple, dict[int, float]] = {}


def block_costs(module, path, members: int, state) -> dict[int, float]:
    """Seconds per run and step of ``module``'s engine for each block size in :data:`SIZES`.

    Read from ``path`` (a JSON file whose name carries the engine's digest and
    :func:`machine_key`), else measured with :func:`measure` and written there
    (atomically).  ``state`` = (q, v, table) of one
    run, repeated to fill the blocks.
    """
    key = (str(path), members)
    if key in _memory:
        return _memory[key]
    try:
        with open(path) as f:
            data = json.load(f)
        costs = {int(b): float(c) for b, c in data["costs"].items()}
        if data.get("calibration") != CALIBRATION:
            costs = {}
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        costs = {}
    if set(costs) != set(SIZES) or not all(c > 0 for c in costs.values()):
        costs = measure(module, *state)
        _write(path, {"members": members, "calibration": CALIBRATION,
                      "sizes": "seconds per run and Verlet step", "costs": costs})  # fmt: skip
    _memory[key] = costs
    return costs


def _write(path, data) -> None:
    folder = os.path.dirname(path)
    try:
        os.makedirs(folder, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=".blocks-", suffix=".json")
        with os.fdopen(fd, "w") as f:
            json.dump(data, f)
        os.replace(tmp, path)
    except OSError:  # a read-only cache only costs a new measurement next time
        pass


def measure(module, q, v, table) -> dict[int, float]:
    """Time the compiled engine on one thread for every block size of :data:`SIZES`.

    Each size runs a block of copies of the one-run state (q, v, table: columns of one run)
    with the Verlet (leapfrog) scheme for s and 2s steps; the difference removes the fixed
    cost of a call, and the best of :data:`_REPEATS` timings of each is kept (the least
    disturbed by other processes).  The short and long timings alternate, so a stretch of
    disturbance slows both rather than only the short ones, whose inflated best once made
    block 24 look a third cheaper than its neighbours and sent 25 runs to blocks of 24 and
    1.  A difference below a quarter of the long timing (the short call disturbed while the
    long one was not, so that the step looks nearly free) is timed again, up to
    :data:`_ROUNDS` times; then the long call's own time per step, an upper bound that
    includes the fixed cost, is kept.  Returns seconds per run and step (one force
    evaluation a step).
    """
    import numba

    from ..integrators import get_scheme

    a, b = get_scheme("verlet").arrays()  # kick, drift, kick: one force evaluation a step
    threads = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        out = {}
        for size in SIZES:
            steps = max(16, _CALIBRATION_WORK // size)
            out[size] = _step_seconds(module, q, v, table, size, (a, b), steps) / size
        return out
    finally:
        numba.set_num_threads(threads)


def _step_seconds(module, q, v, table, size, weights, steps) -> float:
    """Seconds of one step of a block of ``size``: the best long timing less the best short
    one, timed again while that difference is implausibly small (see :func:`measure`)."""
    short, long = [], []
    for _ in range(_ROUNDS):
        for _ in range(_REPEATS):
            short.append(_time(module, q, v, table, size, weights, steps))
            long.append(_time(module, q, v, table, size, weights, 2 * steps))
        if min(long) - min(short) >= 0.25 * min(long):
            return (min(long) - min(short)) / steps
    return min(long) / (2 * steps)


def _time(module, q, v, table, size, weights, steps) -> float:
    """Seconds of one call of ``advance`` on a block of ``size`` copies, ``steps`` steps."""
    D = q.shape[0]
    Q = np.repeat(q, size, axis=1)
    V = np.repeat(v, size, axis=1)
    P = np.repeat(table, size, axis=1)
    empty3 = np.zeros((D, 0, size))
    _, one_block = layout(fixed(size, size, 1), np.full(size, steps), np.full(size, 1e-3))
    status = np.zeros(size, dtype=np.int64)
    audit = (np.zeros(size), math.inf, status, np.zeros(size, dtype=np.int64),
             np.zeros(size), np.zeros(size))  # fmt: skip
    rec = (np.zeros((size, 0)), np.zeros((size, 0, 0)), np.zeros((size, 0, 2 * D)),
           np.zeros((size, 0, 0)), np.zeros((size, 0)), np.zeros((size, 0)),
           np.zeros((size, 0)), np.zeros((size, 0)))  # fmt: skip
    t0 = time.perf_counter()
    module.advance(Q, V, empty3, empty3.copy(), P, weights, 0, 1, one_block,
                   (0, 0, 0, False, 0.0), np.zeros((0, size)), np.zeros((2, size)),
                   audit, rec, (False, 0.0, False, False), np.zeros((2, size)))  # fmt: skip
    return time.perf_counter() - t0
