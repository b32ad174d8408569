"""Ctrl-C (SIGINT) and SIGTERM end a long command at once and cleanly.

Each command runs in a subprocess on a job that is long only because of its many periods
(or, for a floquet sweep, its many points); the signal comes once it is computing (a
sweep: once its store exists).  It must exit with 130 (SIGINT) or 143 (SIGTERM) within
2 s, with exactly one line on stderr (no traceback, no warning after it), nothing on
stdout and no output file; a sweep's line names --resume, and its store opens for
resuming.  Every sweep kind is interrupted computing in the driver (``--workers 1``: the
kind's own loops must act on the signal), and sweeps on two worker processes by a signal
to the driver alone and to the whole process group, at work and while the pool starts.
Before the fixes the billiard kernels crashed with a segmentation fault some seconds
after the signal (numba boxing their results while the interrupt was raised), and
simulate and chaos ended with a traceback and status -2.

The commands start as a terminal starts them (:func:`_cli.launch`: SIGINT and SIGTERM at
their usual actions), whatever this test process inherited.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from _cli import alive, cpu_ticks, descendants, launch, run_cli

ROOT = Path(__file__).resolve().parents[2]
WELL = ["--alpha", "0.5", "--beta", "0.3"]
LONG = ["--runs", "2", "--periods", "1000000"]


def _sweep(kind: str, *params: str, workers: int = 1) -> list[str]:
    """``sweep KIND --param P ...`` into s.zarr, quiet."""
    words = ["sweep", kind]
    for param in params:
        words += ["--param", param]
    return [*words, "--workers", str(workers), "--quiet", "--out", "s.zarr"]


def _params(argv: list[str]) -> list[str]:
    """The ``--param`` values of ARGV."""
    return [argv[i + 1] for i, word in enumerate(argv) if word == "--param"]


#: A well of every sweep kind but floquet and design (which take no alpha, or sweep it)
SWEPT_WELL = ("alpha=0.5", "beta=0.3", "n=4")


#: The commands' environment: this tree, and numba's machine code in a folder of this
#: module's own (set by :func:`compiled`), which no other test rewrites while a command
#: loads it.
ENV: dict[str, str] = {}

#: What :func:`compiled` runs once, in one process: every kernel path the signalled
#: commands take, so that none compiles in them (a signal that comes while numba compiles
#: is swallowed by LLVM's callbacks, not the command's).
WARM = [
    ["billiard", *WELL, "--runs", "1", "--periods", "1"],
    ["billiard", *WELL, "--runs", "1", "--periods", "1", "--fixed", "--lyapunov"],
    ["simulate", *WELL, "--n", "4", "--runs", "1", "--periods", "1"],
    ["simulate", *WELL, "--n", "inf", "--runs", "1", "--periods", "1"],
    ["chaos", *WELL, "--n", "4", "--runs", "1", "--periods", "1"],
    ["simulate", *WELL, "--n", "4", "--runs", "1", "--periods", "1", "--stepper", "adaptive"],
    ["lifetime", *WELL, "--n", "4", "--runs", "2", "--periods", "5", "--transient", "1"],
    ["compare", "--damping", "0.05", "--runs", "2", "--periods", "1"],
    _sweep("ensemble", *SWEPT_WELL, "runs=1", "periods=1"),
    _sweep("floquet", "alpha=0.5", "beta=0.1,0.2", "n=4"),
    _sweep("bifurcation", *SWEPT_WELL, "transient=1", "count=1"),
    _sweep("chaos", *SWEPT_WELL, "runs=2", "periods=1"),
    _sweep("ergodicity", *SWEPT_WELL, "runs=2", "periods=10", "transient=2",
           "lyapunov_runs=2", "lyapunov_periods=1"),
    _sweep("design", "beta=0.3", "n=4", "runs=2", "periods=2", "lyapunov_runs=2",
           "lyapunov_periods=1"),
]  # fmt: skip
WARM_SCRIPT = """
import shutil, sys
from sinktheory.cli import main
for argv in {warm!r}:
    status = main(argv)
    assert status == 0, (argv, status)
    shutil.rmtree("s.zarr", ignore_errors=True)
"""


@pytest.fixture(scope="module", autouse=True)
def compiled(tmp_path_factory):
    """Compile the kernels the commands use (:data:`WARM`), into this module's own numba
    cache: a cache another test process is rewriting while a command loads it would be
    compiled anew."""
    out = tmp_path_factory.mktemp("warm")
    ENV.update(os.environ, PYTHONPATH=str(ROOT), NUMBA_CACHE_DIR=str(out / "numba"))
    done = subprocess.run([sys.executable, "-c", WARM_SCRIPT.format(warm=WARM)], env=ENV,
                          cwd=out, capture_output=True, text=True, timeout=900)  # fmt: skip
    assert done.returncode == 0, done.stderr


def _interrupt(argv, signum, cwd, wait=2.5, until=None):
    """(status, seconds from the signal to the exit, stdout, stderr) of ``sinktheory
    ARGV`` sent ``signum`` ``wait`` seconds after it started or, with ``until``, after
    that path exists (a loaded machine may take longer to get there).  The command runs
    in :data:`ENV`, where :func:`compiled` left its kernels compiled."""
    proc = launch(argv, cwd, env=ENV)
    try:
        deadline = time.monotonic() + 60
        while until is not None and not until.exists() and time.monotonic() < deadline:
            assert proc.poll() is None, proc.communicate()
            time.sleep(0.05)
        time.sleep(wait)
        assert proc.poll() is None, proc.communicate()  # still computing
        sent = time.monotonic()
        proc.send_signal(signum)
        out, err = proc.communicate(timeout=30)
        return proc.returncode, time.monotonic() - sent, out, err
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()


def _resumable(argv: list[str], store: Path) -> None:
    """The store of the sweep ARGV opens for resuming (as --resume opens it: coordinates,
    checksums and flags checked) with none of its points, or only whole ones, done."""
    from sinktheory.commands.sweep import params_of
    from sinktheory.sweep.plan import Sweep
    from sinktheory.sweep.store import SweepStore

    sweep = Sweep.make(argv[1], params_of(_params(argv)))
    opened = SweepStore.open(store, sweep)
    try:
        assert opened.done().shape == sweep.grid.shape
        assert not opened.done().all()
    finally:
        opened.close()


SWEEP = _sweep("ensemble", *SWEPT_WELL, "runs=2", "periods=1000000")
CASES = {
    "billiard-fixed": (["billiard", *WELL, *LONG, "--fixed", "--lyapunov"], signal.SIGTERM),
    "simulate-rigid": (["simulate", *WELL, "--n", "inf", *LONG, "--plot", "out.png"],
                       signal.SIGINT),
    "simulate": (["simulate", *WELL, "--n", "4", *LONG, "--plot", "out.png"], signal.SIGTERM),
    # its tangent vectors are priced above the one-hour limit at LONG's length
    "chaos": (["chaos", *WELL, "--n", "4", *LONG, "--max-hours", "100"], signal.SIGINT),
    "simulate-adaptive": (["simulate", *WELL, "--n", "4", *LONG, "--stepper", "adaptive"],
                          signal.SIGINT),
    "lifetime": (["lifetime", *WELL, "--n", "4", *LONG], signal.SIGTERM),
    "compare": (["compare", "--damping", "0.05", "--runs", "2", "--periods", "100000",
                 "--max-hours", "100"], signal.SIGINT),
    # one period of ~1e10 impacts: the compiled call does not return for minutes, so the
    # signal's watcher ends the process (SIGTERM could not stop it, not even timeout's);
    # estimated at 21.6 h, so the one-hour limit is raised
    "billiard-one-long-period": (["billiard", *WELL, "--runs", "1", "--periods", "1",
                                  "--fixed", "--container-energy", "1e18", "--max-hours", "100"],
                                 signal.SIGTERM),
    # every sweep kind, computing in the driver: its own loops act on the signal
    "sweep-ensemble": (SWEEP, signal.SIGTERM),
    # many cheap points (a task of 64 a few hundredths of a second): stored as they come
    "sweep-floquet": (_sweep("floquet", "alpha=0.5", "beta=-0.3:0.3:4000", "n=4"),
                      signal.SIGINT),
    "sweep-bifurcation": (_sweep("bifurcation", *SWEPT_WELL, "transient=1000000", "count=3"),
                          signal.SIGTERM),
    "sweep-chaos": (_sweep("chaos", *SWEPT_WELL, "runs=2", "periods=1000000"), signal.SIGINT),
    "sweep-ergodicity": (_sweep("ergodicity", *SWEPT_WELL, "runs=2", "periods=1000000",
                                "lyapunov_runs=2"), signal.SIGTERM),
    "sweep-design": (_sweep("design", "beta=0.3", "n=4", "runs=2", "periods=1000000",
                            "lyapunov_runs=2"), signal.SIGINT),
}  # fmt: skip


@pytest.mark.parametrize("case", list(CASES))
def test_signal_ends_a_long_command_with_one_line(case, tmp_path):
    argv, signum = CASES[case]
    store = tmp_path / "s.zarr" if argv[0] == "sweep" else None
    wait = 0.5 if store else 2.5  # a sweep: once it computes, past its store's creation
    status, took, out, err = _interrupt(argv, signum, tmp_path, wait=wait, until=store)
    assert status == 128 + signum, err
    assert took < 2.0, (took, err)
    line = f"sinktheory {argv[0]}: interrupted" + ("; --resume continues" if store else "")
    assert err.splitlines() == [line], err
    assert out == ""
    assert not (tmp_path / "out.png").exists()
    assert [p.name for p in tmp_path.iterdir()] == (["s.zarr"] if store else [])
    if store:
        _resumable(argv, store)


@pytest.mark.parametrize(
    "error",
    [
        # a signal acted on while numba boxes a compiled call's results
        SystemError("returned a result with an exception set"),
        # Ctrl-C while a C extension module initialises (SciPy's, on a command's first
        # import of it): a rigid simulate exited 1 with a traceback (full suite, 2026-11-26)
        ImportError("initialization failed"),
    ],
    ids=["boxing", "import"],
)
def test_interrupt_behind_another_error_is_an_interrupt(error, capsys, monkeypatch):
    """An error caused by KeyboardInterrupt ends the command as an interrupt."""
    from sinktheory.commands import period

    def interrupted(args):
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as e:
            raise error from e

    monkeypatch.setattr(period, "run", interrupted)
    with pytest.raises(SystemExit) as info:
        run_cli(["period", "--n", "2", "--amplitude", "1"], capsys)
    assert info.value.code == 130
    assert capsys.readouterr().err == "sinktheory period: interrupted\n"


def test_interrupt_swallowed_by_a_callback_is_raised_again(capsys, monkeypatch):
    """Ctrl-C while numba compiles can land in llvmlite's ctypes callback, where Python
    only prints "Exception ignored" and goes on: a floquet sweep ran to its end with status
    0 (full suite, 2026-11-26).  The command still ends as an interrupt, at the next line
    of Python after the callback, printing nothing else."""
    import ctypes

    from sinktheory.commands import period

    @ctypes.CFUNCTYPE(None)
    def callback():
        raise KeyboardInterrupt

    after = []

    def compiling(args):
        callback()  # swallowed here, as in llvmlite's object-cache notification
        after.append("reached")  # the signal is raised again before or at this line
        for _ in range(100):
            time.sleep(0.01)
        after.append("ran on")

    monkeypatch.setattr(period, "run", compiling)
    with pytest.raises(SystemExit) as info:
        run_cli(["period", "--n", "2", "--amplitude", "1"], capsys)
    assert info.value.code == 130
    assert "ran on" not in after
    assert capsys.readouterr().err == "sinktheory period: interrupted\n"


def test_interrupt_lets_zarr_finish_the_io_in_flight():
    """An interrupt during a store write left zarr's tasks pending; exiting then closed
    zarr's event loop under them ("Task was destroyed but it is pending!" after the
    command's line); so did a refusal while reads were in flight.  The command now waits
    for them (briefly) before it exits."""
    import asyncio

    import zarr.core.sync as zsync

    from sinktheory.commands._common import settle_zarr

    done = []

    async def write():
        await asyncio.sleep(0.2)
        done.append(True)

    zsync.sync(asyncio.sleep(0))  # zarr's loop is running
    asyncio.run_coroutine_threadsafe(write(), zsync.loop[0])  # in flight, not awaited
    settle_zarr()
    assert done == [True]


@pytest.mark.parametrize("exists", [False, True])
def test_sweep_names_resume_only_when_there_is_a_store(exists, tmp_path, capsys, monkeypatch):
    """An interrupt before the store exists (checking a large grid, say) has nothing to
    resume: the line does not say --resume then."""
    from sinktheory.commands import sweep

    store = tmp_path / "s.zarr"
    if exists:
        store.mkdir()

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(sweep, "_run", interrupted)
    with pytest.raises(SystemExit) as info:
        run_cli(["sweep", "floquet", "--param", "alpha=0.5", "--out", str(store)], capsys)
    assert info.value.code == 130
    hint = "; --resume continues" if exists else ""
    assert capsys.readouterr().err == f"sinktheory sweep: interrupted{hint}\n"


FORKSERVER_RACE = """
import os, signal, time
signal.signal(signal.SIGINT, signal.default_int_handler)  # whatever the test inherited
from multiprocessing import forkserver
from sinktheory.sweep import runner
runner._context()
runner._start_forkserver()
os.kill(forkserver._forkserver._forkserver_pid, signal.SIGINT)  # still starting up
time.sleep(3)
with open(f"/proc/{forkserver._forkserver._forkserver_pid}/status") as f:
    state = [line.split()[1] for line in f if line.startswith("State:")][0]
print("STATE", state, "RESTORED", signal.getsignal(signal.SIGINT) is signal.default_int_handler)
"""


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads /proc")
def test_ctrl_c_while_the_forkserver_starts_is_discarded(tmp_path):
    """Ctrl-C reaches the forkserver too.  While it started up (before it ignored SIGINT)
    it died with a 7-line KeyboardInterrupt traceback after the sweep's one line
    (benchmarks/bench_interrupt_sweep.py: 1 try in 8); sent SIGINT just after its spawn it
    died (a zombie 3 s later).  Started with SIGINT ignored, it runs on, and the driver's
    handler is back."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    done = subprocess.run([sys.executable, "-c", FORKSERVER_RACE], env=env, cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)  # fmt: skip
    assert "Traceback" not in done.stderr and "KeyboardInterrupt" not in done.stderr, done.stderr
    state, restored = done.stdout.split()[1::2]
    assert state in ("R", "S") and restored == "True", (done.stdout, done.stderr)


def test_a_second_ctrl_c_while_exiting_changes_nothing(tmp_path):
    """An impatient user presses Ctrl-C twice.  Once the one line was printed, Python's
    tear-down of the loaded modules took 1-2 s, and a second SIGINT during it ended the
    process with status -2 (benchmarks/bench_interrupt_sweep.py --again 0.3: 4 of 4).
    The command line (``main()`` without arguments, as ``python -m sinktheory`` runs it)
    now ends the process at once and ignores further signals."""
    argv = ["simulate", *WELL, "--n", "4", *LONG]
    proc = launch(argv, tmp_path, env=ENV)
    try:
        time.sleep(2.5)
        assert proc.poll() is None, proc.communicate()  # still computing
        proc.send_signal(signal.SIGINT)
        line = proc.stderr.readline()  # printed before the tear-down
        time.sleep(0.2)
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    assert proc.returncode == 130, (line, err)
    assert (line, err, out) == ("sinktheory simulate: interrupted\n", "", "")


# --------------------------------------------------------------------------- worker pools
SLOW_SWEEP = ["sweep", "ensemble", "--param", "alpha=0.5", "--param", "beta=-0.3:0.3:40"]
SLOW_SWEEP += ["--param", "n=4", "--param", "runs=8", "--param", "periods=2000"]
SLOW_DESIGN = ["design", "--beta", "-0.3:0.3:20", "--n", "4", "--no-estimate"]


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads /proc")
@pytest.mark.parametrize(
    ("argv", "signame", "group", "status"),
    [
        (SLOW_SWEEP, "SIGINT", False, 130),  # kill -INT to the driver alone: hung before
        (SLOW_SWEEP, "SIGINT", True, 130),  # Ctrl-C: the whole process group
        (SLOW_SWEEP, "SIGTERM", False, 143),
        (SLOW_DESIGN, "SIGINT", False, 130),
        (SLOW_SWEEP, "SIGTERM", None, 143),  # None: as soon as the store exists
    ],
    ids=["sweep-int-main", "sweep-int-group", "sweep-term-main", "design-int-main", "starting"],
)
def test_interrupt_ends_workers_and_exits_promptly(argv, signame, group, status, tmp_path):
    """Two workers busy on long points (or, with group None, the pool still starting: a
    worker forked but not yet recorded by the pool once escaped and printed a traceback);
    the signal ends driver and workers within a few seconds, with exactly one line on
    stderr naming --resume (a resource-tracker warning of the workers' semaphores once
    followed it), and the store stays readable."""
    import xarray as xr

    argv = [*argv, "--workers", "2", "--out", str(tmp_path / "s.zarr"), "--quiet"]
    proc = launch(argv, tmp_path, env=ENV, group=True)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:  # two workers have computed for 1 s or more
            busy = [p for p in descendants(proc.pid) if cpu_ticks(p) >= 100]
            if len(busy) >= 2 or (group is None and (tmp_path / "s.zarr").exists()):
                break
            assert proc.poll() is None, proc.communicate()
            time.sleep(0.2)
        else:
            pytest.fail("the workers did not start within 120 s")
        below = descendants(proc.pid)
        sent = time.monotonic()
        sig = getattr(signal, signame)
        os.killpg(proc.pid, sig) if group else os.kill(proc.pid, sig)
        out, err = proc.communicate(timeout=30)
        took = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
    assert proc.returncode == status, err
    # 10 s: the driver terminates its workers at once (0.5 s grace before SIGKILL); a
    # driver waiting for the tasks in flight would take minutes
    assert took < 10, took
    assert err.splitlines() == [f"sinktheory {argv[0]}: interrupted; --resume continues"], err
    assert "Traceback" not in err and out == ""
    for _ in range(50):  # the resource tracker ends right after the driver
        if not any(alive(p) for p in below):
            break
        time.sleep(0.1)
    assert not any(alive(p) for p in below), [p for p in below if alive(p)]
    ds = xr.open_zarr(tmp_path / "s.zarr")  # whole: created before the points ran
    assert ds.done.shape == ((40,) if argv[0] == "sweep" else (20,))


def test_ctrl_c_reaches_a_command_whatever_the_tests_inherited(tmp_path):
    """A test process that ignores SIGINT (started as a shell's background job, or left so
    by an earlier test) passes that on to every command it starts, and an ignored SIGINT
    stays ignored: the sweep ran on to its end, and the test timed out after 30 s
    (``test_interrupt_ends_workers_and_exits_promptly[sweep-int-main]`` and
    ``[design-int-main]``, one xdist worker of a CI run).  :func:`_cli.launch` starts the
    command as a terminal does, so Ctrl-C reaches it."""
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        status, took, out, err = _interrupt(["simulate", *WELL, "--n", "4", *LONG],
                                            signal.SIGINT, tmp_path)  # fmt: skip
    finally:
        signal.signal(signal.SIGINT, previous)
    assert (status, err, out) == (130, "sinktheory simulate: interrupted\n", ""), (took, err)
