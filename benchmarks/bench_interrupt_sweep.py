"""Ctrl-C to the whole process group of a 2-worker sweep: exit status, lines, latency.

A terminal's Ctrl-C sends SIGINT to every process of the foreground group: the sweep's
driver, its forkserver and its worker processes at once.  This script starts
``sinktheory sweep ensemble ... --workers 2`` in a process group of its own, sends SIGINT
to the group after a delay (spread over the tries, so start-up, planning, the pool's
start and the computation are all hit), and records the exit status, the lines on stderr
and the seconds from the signal to the exit.  The goal (issue 34): status 130, the one
line "sinktheory sweep: interrupted[; --resume continues]", within 2 s, every time.
``--again S`` sends a second SIGINT S seconds after the first, as an impatient user
pressing Ctrl-C twice (it must change nothing: before the fix it ended the driver with
status -2 while Python tore itself down).

Usage::

    python benchmarks/bench_interrupt_sweep.py [--tries 11] [--first 1.0] [--last 8.0]
        [--again S] [--root TREE]

Prints one row per try, then the counts, the latencies and the machine.
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
SWEEP = (
    "sweep ensemble --param alpha=0.5 --param beta=0.1,0.2,0.3,0.4 --param n=4 "
    "--param runs=2 --param periods=1000000 --workers 2 --quiet --out s.zarr"
).split()
GOAL_SECONDS = 2.0


def one_try(
    delay: float, cwd: Path, root: Path = ROOT, again: float | None = None
) -> tuple[int, float, list[str], float]:
    """(exit status, seconds from the signal until the group's last process closed stderr,
    stderr lines, seconds until the driver itself exited) of one sweep sent SIGINT to its
    group ``delay`` seconds after its start (a shell returns at the driver's exit; the
    forkserver, busy with its imports, may hold the terminal a little longer), and once
    more ``again`` seconds after that if the driver still runs."""
    env = dict(os.environ, PYTHONPATH=str(root))
    proc = subprocess.Popen(
        [sys.executable, "-m", "sinktheory", *SWEEP], cwd=cwd, env=env,
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
    )  # fmt: skip
    try:
        time.sleep(delay)
        if proc.poll() is not None:
            raise SystemExit(f"the sweep ended before the signal: {proc.communicate()}")
        sent = time.monotonic()
        os.killpg(proc.pid, signal.SIGINT)
        if again is not None:
            try:
                proc.wait(timeout=again)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGINT)
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
    parser.add_argument("--tries", type=int, default=11)
    parser.add_argument("--first", type=float, default=1.0, help="delay of the first try (s)")
    parser.add_argument("--last", type=float, default=8.0, help="delay of the last try (s)")
    parser.add_argument(
        "--again",
        type=float,
        default=None,
        metavar="S",
        help="a second SIGINT S seconds after the first",
    )
    parser.add_argument("--root", type=Path, default=ROOT, help="the sinktheory tree to run")
    args = parser.parse_args()
    sys.path.insert(0, str(Path(__file__).parent))
    from machine import describe

    n = args.tries
    delays = [args.first + (args.last - args.first) * i / max(1, n - 1) for i in range(n)]
    rows = []
    for delay in delays:
        with tempfile.TemporaryDirectory() as tmp:
            status, took, lines, driver = one_try(delay, Path(tmp), args.root, args.again)
        rows.append((status, took, lines, driver))
        first = lines[0] if lines else ""
        print(f"delay {delay:5.2f} s: status {status}, {len(lines)} line(s), driver exit "
              f"{driver:.2f} s, all exits {took:.2f} s after the signal: {first}",
              flush=True)  # fmt: skip
        if len(lines) > 1:
            print("    " + "\n    ".join(lines))
    clean = [r for r in rows if r[0] == 130 and len(r[2]) == 1 and "interrupted" in r[2][0]]
    fast = [r for r in rows if r[1] < GOAL_SECONDS]
    took = sorted(r[1] for r in rows)
    driver = sorted(r[3] for r in rows)
    print(f"clean (130, one line): {len(clean)} of {n}; within {GOAL_SECONDS:g} s: "
          f"{len(fast)} of {n}")  # fmt: skip
    print(
        f"exit latency, driver: median {statistics.median(driver):.2f} s, max {driver[-1]:.2f} s;"
        f" every process: median {statistics.median(took):.2f} s, max {took[-1]:.2f} s"
    )
    print(describe())


if __name__ == "__main__":
    main()
