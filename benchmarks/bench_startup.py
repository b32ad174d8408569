"""Start-up time of the ``sinktheory`` command (issue 13), measured, not asserted.

Each command runs as a fresh process (``python -m sinktheory ...``, and the installed
console script when found), ``REPEAT`` times; the table shows the best and the median
wall time next to the target, the best CPU time (user + sys of the process: the honest
figure on a machine shared with other work, where wall times stretch), the load
average, and the heavy modules the command imported (a module listed there is one a
lazy import should have kept out; ``numba.np.arraymath`` and ``scipy.linalg`` mean numba
loaded its compiler target, about 0.5 s).  Targets: ``--version`` and ``--help`` under
0.3 s; light commands (well, period, floquet at one point) under 1 s.

The numba cache is warmed by one untimed run of each command first, so the figures are
those a user sees from the second call on (the first call after installing compiles the
kernels).

    python benchmarks/bench_startup.py [--repeat N]
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import time

CASES = [
    (["--version"], 0.3),
    (["--help"], 0.3),
    (["well", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--json"], 1.0),
    (["well", "--alpha", "0.5", "--beta", "-0.3", "--n", "10", "--shape", "symmetric"], 1.0),
    (["period", "--n", "4", "--amplitude", "1", "--json"], 1.0),
    (["floquet", "--alpha", "0.5", "--beta", "0.1", "--n", "4", "--json"], 1.0),
    (["sink", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--particles", "5"], 1.0),
    (["derive", "--json"], None),
]
HEAVY = (
    "matplotlib",
    "xarray",
    "zarr",
    "dask",
    "sympy",
    "sinktheory.scenes",
    "scipy.optimize",
    "scipy.linalg",
    "numba.np.arraymath",
)
REPEAT = 7

PROBE = (
    "import sys, runpy\n"
    "sys.argv = ['sinktheory', *sys.argv[1:]]\n"
    "try:\n"
    "    runpy.run_module('sinktheory', run_name='__main__')\n"
    "except SystemExit:\n"
    "    pass\n"
    "heavy = [m for m in {heavy!r} if m in sys.modules]\n"
    "print('HEAVY:' + ','.join(heavy), file=sys.stderr)\n"
)


def wall(cmd: list[str], env: dict) -> tuple[float, float]:
    """Wall time and CPU time (user + sys) of one run of ``cmd``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    elapsed = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return elapsed, cpu


def heavy_modules(args: list[str], env: dict) -> str:
    proc = subprocess.run(
        [sys.executable, "-c", PROBE.format(heavy=HEAVY), *args],
        capture_output=True,
        text=True,
        env=env,
    )
    for line in proc.stderr.splitlines():
        if line.startswith("HEAVY:"):
            return line[6:] or "-"
    return "?"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=REPEAT)
    repeat = parser.parse_args().repeat
    env = {**os.environ, "MPLBACKEND": "Agg"}
    script = shutil.which("sinktheory", path=os.path.dirname(sys.executable))
    baseline = min(wall([sys.executable, "-c", "pass"], env)[0] for _ in range(repeat))
    print(
        f"python {sys.version.split()[0]}, {os.cpu_count()} cores; bare interpreter start "
        f"{baseline:.3f} s; best and median wall, best CPU of {repeat} runs; load average "
        + " ".join(f"{x:.2f}" for x in os.getloadavg())
    )
    launchers = [("python -m sinktheory", [sys.executable, "-m", "sinktheory"])]
    if script:
        launchers.append((f"{script}", [script]))
    for label, launcher in launchers:
        print(f"\n{label}")
        print(
            f"  {'command':<58} {'best':>7} {'median':>7} {'cpu':>7} {'target':>7}  ok  "
            "heavy imports"
        )
        for args, target in CASES:
            cmd = [*launcher, *args]
            wall(cmd, env)  # warm the numba cache and the OS file cache
            runs = [wall(cmd, env) for _ in range(repeat)]
            times = [t for t, _ in runs]
            best, median = min(times), statistics.median(times)
            cpu = min(c for _, c in runs)
            ok = "-" if target is None else ("yes" if median < target else "NO")
            tgt = "-" if target is None else f"{target:.1f}"
            heavy = heavy_modules(args, env) if launcher[0] == sys.executable else ""
            text = " ".join(args)
            text = text if len(text) <= 58 else text[:55] + "..."
            print(f"  {text:<58} {best:7.3f} {median:7.3f} {cpu:7.3f} {tgt:>7}  {ok:<3} {heavy}")


if __name__ == "__main__":
    main()
