"""Run time of ``sinktheory reproduce`` per figure, quick and paper fidelity (measured).

Each fidelity runs ``python -m sinktheory reproduce --json`` in a fresh process (after one
untimed run that warms the compilation cache, unless ``--cold``) and prints the wall time
and CPU time (all threads) of every figure as the command measured them, the totals, the
machine (cores, load average) and the table to paste into
:data:`sinktheory.scenes.SECONDS`, whose values ``reproduce`` announces as each figure's
estimate.  On a loaded machine the wall time says more about the other jobs than about
``reproduce``; the CPU time does not depend on them, and bounds the wall time on an idle
machine (equal to it for serial work, twice it for work spread over 2 cores).

    python benchmarks/bench_reproduce.py [--figure N ...] [--fidelity quick|paper|both]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time


def run(figures: list[int], quick: bool) -> dict[int, tuple[float, float]]:
    """(wall, CPU) seconds of each figure (as reported by ``reproduce --json``) in a fresh
    process."""
    with tempfile.TemporaryDirectory() as out:
        cmd = [sys.executable, "-m", "sinktheory", "reproduce", "--out", out, "--json"]
        cmd += ["--figure", *map(str, figures)] if figures else []
        cmd += ["--quick"] if quick else []
        proc = subprocess.run(
            cmd, capture_output=True, text=True, env={**os.environ, "MPLBACKEND": "Agg"}
        )
    if not proc.stdout.strip():
        sys.exit(f"reproduce failed:\n{proc.stderr[-2000:]}")
    data = json.loads(proc.stdout)
    return {f["figure"]: (f["seconds"], f["cpu_seconds"]) for f in data["figures"]}


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--figure", type=int, nargs="+", default=[], metavar="N")
    parser.add_argument("--fidelity", choices=("quick", "paper", "both"), default="both")
    parser.add_argument("--cold", action="store_true", help="no warm-up run")
    args = parser.parse_args()
    print(
        f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, python "
        f"{platform.python_version()}; load average before: "
        + " ".join(f"{x:.2f}" for x in os.getloadavg())
    )
    seconds: dict[str, dict[int, tuple[float, float]]] = {}
    for fidelity in ("quick", "paper"):
        if args.fidelity not in (fidelity, "both"):
            continue
        if not args.cold:
            run(args.figure, fidelity == "quick")
        start = time.perf_counter()
        seconds[fidelity] = run(args.figure, fidelity == "quick")
        wall = time.perf_counter() - start
        print(f"\n{fidelity} fidelity: {wall:.1f} s wall for the process; load average now "
              + " ".join(f"{x:.2f}" for x in os.getloadavg()))  # fmt: skip
        print("  figure      wall s     CPU s")
        for number, (w, c) in seconds[fidelity].items():
            print(f"  Fig. {number:>2}  {w:8.1f}  {c:8.1f}")
        walls, cpus = zip(*seconds[fidelity].values(), strict=True)
        print(f"  total    {sum(walls):8.1f}  {sum(cpus):8.1f}")
    print("\nload average after: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    figures = sorted({n for s in seconds.values() for n in s})
    for column, name in ((0, "wall"), (1, "CPU")):
        print(f"\nSECONDS = {{  # (quick, paper), {name} seconds")
        for n in figures:
            q, p = (seconds.get(f, {}).get(n, (math.nan,) * 2)[column] for f in ("quick", "paper"))
            print(f"    {n}: ({q:.1f}, {p:.1f}),")
        print("}")


if __name__ == "__main__":
    main()
