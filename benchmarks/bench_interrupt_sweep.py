"""Ctrl-C to the whole process group of a 2-worker sweep of every kind: exit status,
lines, latency.

A terminal's Ctrl-C sends SIGINT to every process of the foreground group: the sweep's
driver, its forkserver and its worker processes at once.  For each sweep kind (floquet,
bifurcation, ensemble, design, chaos, ergodicity: a job long enough to be running when the
signal comes) this script starts ``sinktheory sweep KIND ... --workers 2`` in a process
group of its own, sends SIGINT to the group after a delay (spread over the tries), and
records the exit status, the lines on stderr and the seconds from the signal to the exit.
The delays count from the moment the sweep's store appears (checking a grid of a few
hundred bifurcation or chaos points takes 10-30 s before it), so that the pool's start
(the forkserver imports the package: 2-5 s) and the computation are hit; ``--from-start``
counts them from the command's start instead, to hit its start-up and planning.  The goal
(issue 34): status 130, the one line "sinktheory sweep: interrupted[; --resume
continues]", within 2 s, every time.  ``--again S`` sends a second SIGINT S seconds after
the first, as an impatient user pressing Ctrl-C twice (it must change nothing: before the
fix it ended the driver with status -2 while Python tore itself down).  ``--driver`` sends
the signal to the driver alone (``kill -INT PID``) instead of the group.

The commands start with SIGINT at its default action, as a terminal starts them: a script
run as a shell's background job inherits an ignored SIGINT, and so would the sweeps.

Usage::

    python benchmarks/bench_interrupt_sweep.py [--tries 11] [--first 0] [--last 6]
        [--kinds floquet,ensemble,...] [--again S] [--driver] [--from-start] [--root TREE]

Prints one row per try, then per kind the counts and the latencies, and the machine (with
its load average) at the start and at the end.
"""

from __future__ import annotations

import argparse
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
WELL = "--param alpha=0.5 --param n=4 "
#: A long job of each kind on two workers (at least two tasks: bifurcation and chaos put
#: up to 256 consecutive points in one task).
SWEEPS = {
    "floquet": "--param alpha=0.5 --param beta=-0.3:0.3:8000 --param n=4",
    "bifurcation": WELL + "--param beta=0.05:0.45:300 --param transient=1000000 --param count=3",
    "ensemble": WELL + "--param beta=0.1,0.2,0.3,0.4 --param runs=2 --param periods=1000000",
    "design": "--param beta=0.1,0.2,0.3,0.4 --param n=4 --param runs=2 "
    "--param periods=1000000 --param lyapunov_runs=2",
    "chaos": WELL + "--param beta=0.05:0.45:300 --param runs=2 --param periods=100000",
    "ergodicity": WELL + "--param beta=0.1,0.2,0.3,0.4 --param runs=2 "
    "--param periods=1000000 --param lyapunov_runs=2",
}
TAIL = " --workers 2 --quiet --out s.zarr"
#: Python started as a terminal starts a foreground command (SIGINT at its default).
LAUNCH = (
    "import signal, sys; signal.signal(signal.SIGINT, signal.default_int_handler); "
    "signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT}); "
    "from sinktheory.cli import main; sys.exit(main())"
)
GOAL_SECONDS = 2.0


def one_try(
    kind: str,
    delay: float,
    cwd: Path,
    root: Path = ROOT,
    again: float | None = None,
    driver_only: bool = False,
    from_store: bool = True,
) -> tuple[int, float, list[str], float] | None:
    """(exit status, seconds from the signal until the group's last process closed stderr,
    stderr lines, seconds until the driver itself exited) of one sweep of ``kind`` sent
    SIGINT (its group, or with ``driver_only`` its driver) ``delay`` seconds after its
    store appeared (the grid checked, the pool starting) or, without ``from_store``, after
    its start (a shell returns at the driver's exit; the forkserver, busy with its imports,
    may hold the terminal a little longer), and once more ``again`` seconds after that if
    the driver still runs; None if the sweep ended before the signal."""
    env = dict(os.environ, PYTHONPATH=str(root))
    argv = ["sweep", kind, *SWEEPS[kind].split(), *TAIL.split()]
    proc = subprocess.Popen(
        [sys.executable, "-c", LAUNCH, *argv], cwd=cwd, env=env,
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
    )  # fmt: skip

    def send() -> None:
        os.kill(proc.pid, signal.SIGINT) if driver_only else os.killpg(proc.pid, signal.SIGINT)

    try:
        deadline = time.monotonic() + 600
        while from_store and not (cwd / "s.zarr").exists() and time.monotonic() < deadline:
            if proc.poll() is not None:
                break
            time.sleep(0.02)
        time.sleep(delay)
        if proc.poll() is not None:
            print(f"  the sweep ended before the signal: {proc.communicate()}")
            return None
        sent = time.monotonic()
        send()
        if again is not None:
            try:
                proc.wait(timeout=again)
            except subprocess.TimeoutExpired:
                send()
        proc.wait(timeout=60)
        driver = time.monotonic() - sent
        _, err = proc.communicate(timeout=60)  # EOF once every process of the group left
        took = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
    _reap_group(proc.pid)
    return proc.returncode, took, err.splitlines(), driver


def _reap_group(pgid: int, wait: float = 5.0) -> None:
    """Wait until no process of the group is left (a leftover worker is reported)."""
    deadline = time.monotonic() + wait
    while time.monotonic() < deadline:
        try:
            os.killpg(pgid, 0)
        except ProcessLookupError:
            return
        time.sleep(0.05)
    print(f"  processes of group {pgid} still alive {wait:g} s after the exit: killed")
    os.killpg(pgid, signal.SIGKILL)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tries", type=int, default=11, help="tries per kind")
    parser.add_argument("--first", type=float, default=0.0, help="delay of the first try (s)")
    parser.add_argument("--last", type=float, default=6.0, help="delay of the last try (s)")
    parser.add_argument(
        "--from-start",
        action="store_true",
        help="delays from the command's start, not from its store's creation",
    )
    parser.add_argument("--kinds", default=",".join(SWEEPS), help="comma-separated kinds")
    parser.add_argument(
        "--again",
        type=float,
        default=None,
        metavar="S",
        help="a second SIGINT S seconds after the first",
    )
    parser.add_argument("--driver", action="store_true", help="signal the driver alone")
    parser.add_argument("--root", type=Path, default=ROOT, help="the sinktheory tree to run")
    args = parser.parse_args()
    sys.path.insert(0, str(Path(__file__).parent))
    from machine import describe

    kinds = args.kinds.split(",")
    unknown = sorted(set(kinds) - set(SWEEPS))
    if unknown:
        parser.error(f"unknown kinds {unknown}: choose from {', '.join(SWEEPS)}")
    print("start:", describe(), flush=True)
    n = args.tries
    delays = [args.first + (args.last - args.first) * i / max(1, n - 1) for i in range(n)]
    summary = []
    for kind in kinds:
        rows = []
        for delay in delays:
            with tempfile.TemporaryDirectory() as tmp:
                row = one_try(kind, delay, Path(tmp), args.root, args.again, args.driver,
                              not args.from_start)  # fmt: skip
            if row is None:
                continue
            status, took, lines, driver = row
            rows.append(row)
            first = lines[0] if lines else ""
            print(f"{kind:11s} delay {delay:5.2f} s: status {status}, {len(lines)} line(s), "
                  f"driver exit {driver:.2f} s, all exits {took:.2f} s after the signal: "
                  f"{first}", flush=True)  # fmt: skip
            if len(lines) > 1:
                print("    " + "\n    ".join(lines))
        if not rows:
            summary.append(f"{kind}: every sweep ended before its signal")
            continue
        clean = [r for r in rows if r[0] == 130 and len(r[2]) == 1 and "interrupted" in r[2][0]]
        fast = [r for r in rows if r[1] < GOAL_SECONDS]
        took = sorted(r[1] for r in rows)
        driver = sorted(r[3] for r in rows)
        summary.append(
            f"{kind}: clean (130, one line) {len(clean)} of {len(rows)}, within "
            f"{GOAL_SECONDS:g} s {len(fast)} of {len(rows)}; exit latency, driver: median "
            f"{statistics.median(driver):.2f} s, max {driver[-1]:.2f} s; every process: "
            f"median {statistics.median(took):.2f} s, max {took[-1]:.2f} s"
        )
    print("\n".join(summary))
    print("end:", describe())


if __name__ == "__main__":
    main()
