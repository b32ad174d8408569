"""Running a sweep: in this process, on local processes, or on a Dask cluster.

Where the points run:

* ``scheduler=None``: the Dask scheduler named by the Dask configuration
  (``DASK_SCHEDULER_ADDRESS`` or the ``scheduler-address`` key) if there is one, else
  local processes;
* ``scheduler="processes"``: local processes (``workers`` of them, default all cores).
  ``workers=1``, a single task, or (with ``workers`` not given) less estimated work
  than :data:`POOL_THRESHOLD` seconds (``kind.cost(point)``: e.g. a floquet chart
  under 20000 points) runs in this process, with no start-up cost (about 1-3 s for the
  processes to start and load the compiled kernels);
* ``scheduler="tcp://host:port"`` (any Dask address) or a ``distributed.Client``: that
  Dask cluster.

Points are grouped into tasks of up to ``kind.batch`` consecutive points (C order); each
point is still computed on its own from (parameters, point seed), so the numbers are
bitwise the same whatever the scheduler, the number of workers or the order in which
tasks finish.  The driver (this process) alone writes the store, task by task, as results
come in.

Examples
--------
>>> ds = run_sweep("floquet", {"alpha": 0.5, "beta": [-0.2, 0.3], "n": 10},
...                workers=1, progress=False)
>>> ds.lam.values.round(12).tolist(), ds.stable.values.tolist()  # lam = -2 beta (alpha - beta)
([0.28, -0.12], [True, False])
>>> ds.attrs["alpha"], ds.attrs["sweep_kind"]
(0.5, 'floquet')
"""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import shutil
import signal
import sys
import threading
import time
import warnings
from collections.abc import Callable, Iterator, Mapping
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from .. import validation as v
from ..errors import NumericalError, ParameterError, SweepPointError
from ..progress import HeldSignals, ProgressBar
from ..worklimit import resumable
from .kinds import KINDS, Kind
from .plan import Sweep
from .store import MemoryStore, SweepStore, _checked_path

__all__ = ["DamagedStoreWarning", "execute", "POOL_THRESHOLD", "run_sweep", "SweepRun"]

#: Below this many seconds of estimated work, local processes are not worth starting.
POOL_THRESHOLD = 2.0


class DamagedStoreWarning(UserWarning):
    """Points of a resumed store were damaged (their results no longer matched their
    checksums, or their flags were lost) and have been computed again."""


@dataclass(frozen=True)
class SweepRun:
    """A finished sweep: the labelled results and what this call did."""

    dataset: xr.Dataset
    store: Path | None
    computed: int
    skipped: int
    seconds: float
    where: str
    #: points found damaged when the store was opened, computed again (in ``computed``)
    repaired: int = 0


def run_sweep(
    kind: str,
    params: Mapping[str, Any],
    seed: int = 0,
    store: str | Path | None = None,
    scheduler: Any = None,
    workers: int | None = None,
    resume: bool = False,
    progress: bool = True,
    repair: bool = False,
    well: Any = None,
) -> xr.Dataset:
    """Compute ``kind`` at every point of the grid ``params``; return labelled results.

    Parameters
    ----------
    kind : "floquet", "bifurcation" or "ensemble"
        See :mod:`sinktheory.sweep.kinds` for each kind's parameters and results.
    params : dict
        name -> value (fixed) or list of values (swept; becomes a coordinate).  Parameters
        left out take their defaults; alpha, beta and n are required.
    seed : int >= 0
        Sweep seed; point i gets ``SeedSequence(seed, spawn_key=(i,))``.
    store : path, optional
        Zarr store to write the results to, point by point.  None keeps them in memory.
    scheduler : None, "processes", a Dask address or a distributed.Client
        Where to compute (see the module docstring).
    workers : int >= 1, optional
        Local processes (default: all cores).  Ignored on a Dask cluster.
    resume : bool
        Continue the sweep in ``store``, computing only the points not yet done; a store
        made by a different sweep is refused.  Without it an existing store is refused.
    progress : bool
        Progress bar on stderr (points done, rate, time left; only on a terminal), and
        of the check of the grid's points when it lasts over a second.
    repair : bool
        On resuming, remove chunks that no longer decode and recompute their points
        instead of refusing the store.  (Points whose stored results no longer match
        their checksum are always recomputed; damaged coordinates always refuse.)
    well : UserWell, optional
        A user's well (:class:`~sinktheory.userwell.UserWell`) in place of the shape and
        alpha, beta, n, gamma (kinds bifurcation, ensemble, chaos, ergodicity): its own
        parameters are then those of ``params``.  The same as ``params["well"]``; its
        text (:func:`~sinktheory.userwell.well_text`) is stored with the results and sent
        to the workers, so a resumed sweep and a remote worker rebuild the same well.

    Returns
    -------
    xarray.Dataset
        Results over the swept parameters (opened lazily from ``store`` if given).

    Warns
    -----
    DamagedStoreWarning
        Resuming found damaged points (see :mod:`sinktheory.sweep.store`) and recomputed
        them; the message says how many.

    Raises
    ------
    ParameterError
        Unknown kind or parameter, a value the model refuses (at any point), a store
        that exists (without resume) or belongs to another sweep.
    SweepPointError
        A point failed numerically; the points finished before it stay stored.
    """
    if well is not None:
        if isinstance(params, Mapping) and "well" in params:
            raise ParameterError("well", getattr(well, "name", well), "given once (params "
                                 "has a well too)")  # fmt: skip
        params = {**params, "well": well} if isinstance(params, Mapping) else params
    done = execute(
        Sweep.make(kind, params, seed, progress=progress),
        store=store,
        scheduler=scheduler,
        workers=workers,
        resume=resume,
        progress=progress,
        repair=repair,
    )
    if done.repaired:  # the command line says it in its report; here a warning says it
        warnings.warn(
            f"{done.repaired} damaged point(s) found in the store {done.store} and recomputed",
            DamagedStoreWarning,
            stacklevel=2,
        )
    return done.dataset


def execute(
    sweep: Sweep,
    *,
    store: str | Path | None = None,
    scheduler: Any = None,
    workers: int | None = None,
    resume: bool = False,
    progress: bool = True,
    repair: bool = False,
    announce: Callable[[], None] | None = None,
) -> SweepRun:
    """Run a checked :class:`~sinktheory.sweep.plan.Sweep` (see :func:`run_sweep`);
    ``announce`` is called once every argument is checked and the scheduler reached, just
    before the store is opened (the command prints the estimate there, so a refused
    argument stays one line)."""
    start = time.perf_counter()
    if not isinstance(sweep, Sweep):
        raise ParameterError("sweep", sweep, "a Sweep (from Sweep.make)")
    workers = None if workers is None else v.positive_int("workers", workers)
    for name, flag in (("resume", resume), ("repair", repair), ("progress", progress)):
        v.flag(name, flag)
    if announce is not None and not callable(announce):
        raise ParameterError("announce", announce, "a function of no arguments or None")
    if store is not None:
        store = _checked_path(store)  # before reaching a scheduler or computing anything
    # reach the scheduler first: a bad address must not leave a new store behind
    created = False
    with _Engine(scheduler, workers) as engine:
        if announce is not None:
            announce()
        if store is None:
            target = MemoryStore(sweep)
        elif resume and Path(store).exists():
            target = SweepStore.open(store, sweep, repair=repair)
        else:
            target = SweepStore.create(store, sweep)
            created = True
        tasks = _tasks(sweep, target.done())
        pending = sum(len(t) for t in tasks)
        bar = ProgressBar(pending, enabled=progress, label="sweep ", unit="point")
        refused = False
        try:  # closing: a pool's run holds the signals until it ends (HeldSignals)
            with contextlib.closing(engine.run(sweep.kind, tasks)) as results:
                for task, outputs in results:
                    indices = np.array([index for index, _, _ in task])
                    values = {
                        name: np.stack([o[name] for o in outputs]) for name in sweep.kind.results
                    }
                    target.write(indices, values)
                    bar.update(len(task))
        except ParameterError:  # a point refused its input: the sweep was never valid
            refused = True
            raise
        finally:
            bar.close()
            target.close()
            if refused and created:  # a refusal leaves no store behind
                shutil.rmtree(target.path, ignore_errors=True)
    return SweepRun(
        target.dataset(),
        target.path,
        computed=pending,
        skipped=sweep.grid.size - pending,
        seconds=time.perf_counter() - start,
        where=engine.where,
        repaired=getattr(target, "repaired", 0),
    )


# --------------------------------------------------------------------------- tasks
def _tasks(sweep: Sweep, done: np.ndarray) -> list[list[tuple[int, dict, int]]]:
    """Points not done, in runs of up to ``kind.batch`` consecutive points (C order)."""
    batch = sweep.kind.batch
    tasks, current = [], []
    for index in np.flatnonzero(~done.reshape(-1)).tolist():
        if current and (index != current[-1][0] + 1 or len(current) == batch):
            tasks.append(current)
            current = []
        current.append(sweep._task(index))
    if current:
        tasks.append(current)
    return tasks


# --------------------------------------------------------------------------- engines
class _Engine:
    """Where tasks run.  ``run(kind, tasks)`` yields (task, outputs) as tasks finish;
    ``where`` says where they ran.  A Dask scheduler is reached on entering."""

    def __init__(self, scheduler: Any, workers: int | None) -> None:
        if scheduler is None:
            import dask.config

            scheduler = dask.config.get("scheduler-address", None) or "processes"
        self.scheduler = scheduler
        self.workers = workers
        self.where = "this process"
        self._close = None
        self._abort = None
        self._client = None

    def __enter__(self) -> _Engine:
        if isinstance(self.scheduler, str) and self.scheduler == "processes":
            return self
        from distributed import Client

        if isinstance(self.scheduler, Client):
            self._client = self.scheduler
        elif isinstance(self.scheduler, str):
            try:
                self._client = Client(self.scheduler)  # waits distributed.comm.timeouts.connect
            except (OSError, TimeoutError, ValueError) as e:
                raise ParameterError(
                    "scheduler",
                    self.scheduler,
                    "the address of a running Dask scheduler",
                    why=str(e),
                ) from None
            self._close = self._client.close
        else:
            raise ParameterError(
                "scheduler", self.scheduler, "None, 'processes', a Dask address or a Client"
            )
        return self

    def run(self, kind: Kind, tasks: list) -> Iterator[tuple[list, list]]:
        if self._client is not None:
            self.where = f"Dask cluster at {self._client.scheduler.address}"
            return _run_dask(self._client, kind.name, tasks)
        workers = min(self.workers or os.cpu_count() or 1, len(tasks))
        work = sum(kind.cost(params) for task in tasks for _, params, _ in task)
        cheap = self.workers is None and work < POOL_THRESHOLD
        if workers <= 1 or cheap:
            return _run_here(kind.name, tasks)
        context = _context()
        _start_forkserver()
        pool = ProcessPoolExecutor(
            workers, mp_context=context, initializer=_start_worker, initargs=(os.getpid(),)
        )
        starter: list[threading.Thread] = []  # the thread that submits (see _run_pool)
        failed: list[BaseException] = []  # and what it raised
        self._close = lambda: pool.shutdown(wait=True, cancel_futures=True)
        self._abort = lambda: _end_workers(pool, starter, failed)
        self.where = f"{workers} local processes"
        return _run_pool(pool, kind.name, tasks, starter, failed)

    def __exit__(self, kind, error, traceback) -> None:
        if kind is not None and self._abort is not None:
            self._abort()  # interrupted or failed: running tasks are not waited for
        elif self._close is not None:
            self._close()
        self._close = self._abort = None  # the pool and its queues can be freed now


def _end_workers(
    pool: ProcessPoolExecutor,
    starter: list[threading.Thread],
    failed: list[BaseException],
    grace: float = 0.5,
) -> None:
    """End a pool at once, its running tasks too (an interrupt, a failed point), in order:
    the forkserver first (:func:`_end_forkserver`; the thread still starting workers,
    ``starter``, waits for it, then fails and ends), then the worker processes (SIGTERM,
    then SIGKILL after ``grace`` seconds), then the pool's own thread, queued tasks
    cancelled.  Neither the driver nor its workers wait for tasks in flight.

    What the starting thread raised (``failed``) is let go: its frames hold the process
    it was starting, whose arguments hold the pool's queues, in a reference cycle through
    ``failed``; their named semaphores were then unlinked only by a garbage collection or
    multiprocessing's exit handlers, and an interrupted command, which ends without either
    (:func:`sinktheory.cli.main`), left them to the resource tracker, whose warning about
    "leaked semaphore objects" followed the command's one line.

    A worker holds SIGTERM while a compiled call runs (:func:`sinktheory.progress.chunks`,
    a tenth of a second), but its first task also loads the compiled kernels inside that
    call (a second or more); the workers hold nothing the driver needs (it alone writes
    the store), so the grace is short: a 2 s grace made Ctrl-C take 2.5-2.7 s."""
    _end_forkserver()
    for thread in starter:
        thread.join(2.0)  # it fails at once now; the pool's lock is free when it is done
    processes = list((getattr(pool, "_processes", None) or {}).values())
    for process in processes:
        if process.is_alive():
            process.terminate()
    deadline = time.monotonic() + grace
    for process in processes:
        process.join(max(0.0, deadline - time.monotonic()))
        if process.is_alive():
            process.kill()
            process.join(1.0)
    # the workers are gone: the pool's manager thread sees it at once and cleans up
    pool.shutdown(wait=True, cancel_futures=True)
    failed.clear()


def _run_here(kind: str, tasks: list) -> Iterator[tuple[list, list]]:
    for task in tasks:
        yield task, _checked(kind, task)


def _run_pool(
    pool: ProcessPoolExecutor,
    kind: str,
    tasks: list,
    starter: list[threading.Thread],
    failed: list[BaseException],
) -> Iterator[tuple[list, list]]:
    """Submit the tasks and yield their results as they finish, a signal held while the
    pool's code runs and acted on every 0.2 s.

    The first submits start the worker processes, and each start waits until the
    forkserver has imported the package (2-5 s on a loaded machine).  They run in a thread
    of their own (appended to ``starter``), so that the main thread can answer Ctrl-C
    meanwhile (before, it waited with the signal held: the driver exited up to 2.4 s
    after it, benchmarks/bench_interrupt_sweep.py); what it raises goes to ``failed``."""
    futures: dict = {}

    def submit() -> None:
        try:
            for task in tasks:
                futures[pool.submit(_checked, kind, task)] = task
        except BaseException as e:  # raised in the main thread below
            failed.append(e)

    with HeldSignals() as signals:
        with _main_file_hidden():  # while the workers start
            starter.append(threading.Thread(target=submit, name="pool-start", daemon=True))
            starter[0].start()
            while starter[0].is_alive():
                starter[0].join(0.1)
                signals.release()  # an interrupt raises here
        if failed:
            signals.release()  # an interrupt that ended the forkserver is raised instead
            raise failed[0]
        remaining = set(futures)
        while remaining:
            finished, remaining = wait(remaining, timeout=0.2, return_when=FIRST_COMPLETED)
            signals.release()  # an interrupt raises here, between the pool's calls
            for future in finished:
                yield futures[future], future.result()


def _run_dask(client, kind: str, tasks: list) -> Iterator[tuple[list, list]]:
    from distributed import as_completed

    futures = {client.submit(_checked, kind, task, pure=False): i for i, task in enumerate(tasks)}
    try:
        for future in as_completed(futures):
            yield tasks[futures[future]], future.result()
    finally:
        client.cancel(list(futures))


def _checked(kind: str, task: list) -> list[dict[str, Any]]:
    """Compute the points of a task (together, if the kind can: see ``Kind.compute_many``);
    a numerical failure names the point (the points are then computed one by one).  The
    work checks the point functions repeat are those of a resumable sweep, as in
    :meth:`~sinktheory.sweep.plan.Sweep.make`."""
    with resumable():
        return _compute(kind, task)


def _compute(kind: str, task: list) -> list[dict[str, Any]]:
    if KINDS[kind].compute_many is not None and len(task) > 1:
        try:
            return KINDS[kind].compute_many([(params, seed) for _, params, seed in task])
        except NumericalError:
            pass  # find the failing point below
    compute = KINDS[kind].compute
    outputs = []
    for index, params, seed in task:
        try:
            outputs.append(compute(params, seed))
        except NumericalError as e:
            raise SweepPointError(f"point {index} ({params}): {e}") from None
    return outputs


@contextlib.contextmanager
def _main_file_hidden() -> Iterator[None]:
    """Hide ``__main__.__file__`` while workers start, so they do not run the caller's
    script again (what multiprocessing does for spawn and forkserver; the tasks only need
    :mod:`sinktheory`).  Scripts then need no ``if __name__ == "__main__"`` guard and
    code read from stdin works."""
    main = sys.modules["__main__"]
    missing = object()
    path = getattr(main, "__file__", missing)
    if path is not missing:
        del main.__file__
    try:
        yield
    finally:
        if path is not missing:
            main.__file__ = path


def _context():
    """forkserver: children start from a clean process with the point functions imported
    (fork is unsafe once numba's thread pool runs; spawn re-imports everything per child)."""
    context = multiprocessing.get_context("forkserver")
    # SIGINT ignored before the heavy imports (see sinktheory._forkserver_sigint)
    context.set_forkserver_preload(["sinktheory._forkserver_sigint", "sinktheory.sweep.runner"])
    return context


def _start_forkserver() -> None:
    """Start the forkserver (once per process) with SIGINT ignored from its first
    instruction.

    Ctrl-C reaches the whole process group.  The forkserver ignores SIGINT once it has
    imported :mod:`sinktheory._forkserver_sigint`, but a Ctrl-C during its start-up (the
    interpreter and ``multiprocessing`` imports) ended it with a 7-line traceback after
    the driver's one line (1 try in 8 of benchmarks/bench_interrupt_sweep.py).  An ignored
    signal stays ignored across exec, and Python leaves an ignored SIGINT alone, so the
    driver ignores SIGINT while it spawns the forkserver (blocking it would not do: the
    spawn resets the child's signal mask).  A Ctrl-C within those milliseconds is lost
    to the driver as well (a second one stops it).  Outside the main thread, where
    handlers cannot be set, the forkserver starts as it is."""
    from multiprocessing import forkserver

    if threading.current_thread() is not threading.main_thread():
        forkserver.ensure_running()
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        forkserver.ensure_running()
    finally:
        signal.signal(signal.SIGINT, signal.SIG_DFL if previous is None else previous)


def _end_forkserver() -> None:
    """Kill the forkserver started by :func:`_start_forkserver`, if it runs (an interrupt,
    a failed point).  It holds nothing but imported modules, and left alone it would
    finish its imports and then tear them down after the driver had gone, keeping the
    terminal 1-2 s longer.  The next pool of this process starts a new one
    (``forkserver.ensure_running`` finds it dead and reaps it)."""
    from multiprocessing import forkserver

    pid = getattr(forkserver._forkserver, "_forkserver_pid", None)
    if pid is not None:
        with contextlib.suppress(OSError):
            os.kill(pid, signal.SIGKILL)


def _start_worker(driver: int) -> None:
    """Set up a local worker process.

    One numba thread per process: the processes already use every core (a run's
    arithmetic does not depend on the thread count).  SIGINT is ignored: Ctrl-C reaches
    the whole process group, and the driver alone decides, ending its workers
    (:func:`_end_workers`); a worker interrupted on its own would only print a traceback.
    A watchdog thread ends the worker when the driver is gone (killed with kill -9, a
    pool's workers would otherwise wait for work forever).  The worker starts no processes,
    so its default start method is set to fork: the locks numba's thread pool and tqdm
    create here are then anonymous, not named semaphores registered with the resource
    tracker, which reported them as leaked on stderr when an interrupt ended the worker.
    """
    import numba

    multiprocessing.set_start_method("fork", force=True)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    numba.set_num_threads(1)
    threading.Thread(target=_watch, args=(driver,), daemon=True).start()


def _watch(driver: int) -> None:
    while True:
        time.sleep(0.5)
        try:
            os.kill(driver, 0)
        except ProcessLookupError:
            os._exit(1)
