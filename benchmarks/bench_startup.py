"""Start-up time of the ``sinktheory`` command (issue 13), measured, not asserted.

Each command runs as a fresh process (``python -m sinktheory ...``, and the installed
console script when found), ``REPEAT`` times; the table shows the best and the median
wall time next to the target, the best CPU time (user + sys of the process: the honest
figure on a machine shared with other work, where wall times stretch), the load
average, and the heavy modules the command imported (a module listed there is one a
lazy import should have kept out; ``numba.np.arraymath`` and ``scipy.linalg`` mean numba
loaded its compiler target, about 0.5 s).  Targets (issue 25): ``--version``, ``--help``,
every subcommand's ``--help`` and one refused input of each (exit status 2, listed in the
``exit`` column) under 0.3 s; light commands (well, period, floquet at one point, a cached
``derive``) under 1 s.

The numba cache is warmed by one untimed run of each command first, so the figures are
those a user sees from the second call on (the first call after installing compiles the
kernels).

    python benchmarks/bench_startup.py [--repeat N]
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import shutil
import statistics
import subprocess
import sys
import time

#: One refused input per command (exit status 2, one line on stderr); a command missing
#: here is timed with an unknown option, refused by argparse.
REFUSALS = {
    "well": ["--alpha", "-1", "--beta", "0", "--n", "4"],
    "sink": ["--alpha", "0.5", "--beta", "0.3", "--n", "4", "--particles", "0"],
    "derive": ["--digits", "3"],
    "simulate": ["--alpha", "0.5", "--beta", "0.6", "--n", "4"],
    "period": ["--n", "4", "--amplitude", "1", "--digits", "0"],
    "series": ["--n", "0", "--order", "2"],
    "reproduce": ["--figure", "6", "--out", "never-written"],
    "floquet": ["--beta", "0.1", "--n", "4"],
    "nnm": ["--alpha", "0.5", "--beta", "0.3", "--n", "4"],
    "chaos": ["--alpha", "-1", "--beta", "0", "--n", "4"],
    "design": ["--beta", "0.3", "--n", "4"],
    "sweep": ["floquet"],
}


def cases() -> list[tuple[list[str], float | None]]:
    """Every command: ``--help`` and one refusal (target 0.3 s), then the light runs."""
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
    from sinktheory.commands import HELP

    out: list[tuple[list[str], float | None]] = [(["--version"], 0.3), (["--help"], 0.3)]
    for name in HELP:
        out.append(([name, "--help"], 0.3))
        out.append(([name, *REFUSALS.get(name, ["--no-such-option"])], 0.3))
    return out + [
        (["well", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--json"], 1.0),
        (["well", "--alpha", "0.5", "--beta", "-0.3", "--n", "10", "--shape", "symmetric"], 1.0),
        (["period", "--n", "4", "--amplitude", "1", "--json"], 1.0),
        (["floquet", "--alpha", "0.5", "--beta", "0.1", "--n", "4", "--json"], 1.0),
        (["sink", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--particles", "5"], 1.0),
        (["derive", "--json"], 1.0),
    ]


HEAVY = (
    "numpy",
    "numba",
    "matplotlib",
    "xarray",
    "zarr",
    "dask",
    "sympy",
    "sinktheory.scenes.base",
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


def wall(cmd: list[str], env: dict) -> tuple[float, float, int]:
    """Wall time, CPU time (user + sys) and exit status of one run of ``cmd``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    elapsed = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return elapsed, cpu, proc.returncode


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
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=REPEAT)
    repeat = parser.parse_args().repeat
    env = {**os.environ, "MPLBACKEND": "Agg"}
    script = shutil.which("sinktheory", path=os.path.dirname(sys.executable))
    baseline = min(wall([sys.executable, "-c", "pass"], env)[0] for _ in range(repeat))
    print(
        f"{platform.processor() or platform.machine()}, {platform.system()} "
        f"{platform.release()}; python {sys.version.split()[0]}, {os.cpu_count()} cores; "
        f"bare interpreter start "
        f"{baseline:.3f} s; best and median wall, best CPU of {repeat} runs; load average "
        + " ".join(f"{x:.2f}" for x in os.getloadavg())
    )
    launchers = [("python -m sinktheory", [sys.executable, "-m", "sinktheory"])]
    if script:
        launchers.append((f"{script}", [script]))
    for label, launcher in launchers:
        print(f"\n{label}")
        print(
            f"  {'command':<58} {'exit':>4} {'best':>7} {'median':>7} {'cpu':>7} {'target':>7}"
            "  ok  heavy imports"
        )
        for args, target in cases():
            cmd = [*launcher, *args]
            wall(cmd, env)  # warm the numba cache and the OS file cache
            runs = [wall(cmd, env) for _ in range(repeat)]
            times = [t for t, _, _ in runs]
            best, median = min(times), statistics.median(times)
            cpu = min(c for _, c, _ in runs)
            status = runs[-1][2]
            ok = "-" if target is None else ("yes" if median < target else "NO")
            tgt = "-" if target is None else f"{target:.1f}"
            heavy = heavy_modules(args, env) if launcher[0] == sys.executable else ""
            text = " ".join(args)
            text = text if len(text) <= 58 else text[:55] + "..."
            print(
                f"  {text:<58} {status:>4} {best:7.3f} {median:7.3f} {cpu:7.3f} {tgt:>7}  "
                f"{ok:<3} {heavy}"
            )


if __name__ == "__main__":
    main()
