"""How the work estimates compare with the work: actual seconds over estimated seconds.

Every command checks its estimated work against the limit before it starts
(:mod:`sinktheory.worklimit`).  This script runs a handful of small cases of each
long-running command in this process (``sinktheory.cli.main``, output discarded), collects
the estimates the command made (:func:`sinktheory.worklimit.tally`) and times the command
after a first run of the same case has compiled or loaded its kernels.  A ratio above 1
means the estimate was optimistic (the work took longer than estimated); the goal
(issue 34) is a ratio in [1/3, 1] for every case: never optimistic, at most 3x pessimistic.
The estimate prices the work, not a command's fixed cost (set-up, statistics, output:
a second or less), which only matters for jobs far below any limit.
Wall-clock times include the machine's load, printed with the machine.

Usage::

    python benchmarks/bench_estimates.py [--only simulate,chaos,design] [--repeats 2]

Prints one row per case: its two lengths, the estimates and the seconds (best of
``--repeats``) of both, the fixed cost (the straight line through both, at no work) and
the ratio of the work's seconds to the estimate's (its slope); then the range of that
ratio per command and the machine.  A few minutes with warm caches.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import sys
import time
from pathlib import Path

WELL = ["--alpha", "0.5", "--beta", "0.3"]
#: A small design grid (Fig. 8's well at two beta and two k, lambda_1 of 2 runs each).
DESIGN = {
    "shape": "flat",
    "alpha": 0.5,
    "beta": [0.2, 0.3],
    "n": 4,
    "particles": [1, 5],
    "runs": 4,
    "lyapunov_runs": 2,
    "lyapunov_periods": 50,
    "bootstrap": 50,
}
#: (command, case, argv without --periods, periods of the small and the large run): each
#: case runs at both lengths, so the fixed cost of a command (its set-up, statistics and
#: output) and the cost of its work (what the estimate prices) are told apart.
CASES = [
    ("simulate", "n=4 k=1 2 runs", ["simulate", *WELL, "--n", "4", "--particles", "1",
                                    "--runs", "2"], 2000, 8000),
    ("simulate", "n=4 k=1 64 runs", ["simulate", *WELL, "--n", "4", "--particles", "1",
                                     "--runs", "64"], 500, 2000),
    ("simulate", "n=4 k=1 8 runs", ["simulate", *WELL, "--n", "4", "--runs", "8"], 1000, 4000),
    ("simulate", "n=4 k=5 2 runs", ["simulate", *WELL, "--n", "4", "--particles", "5",
                                    "--runs", "2"], 500, 2000),
    ("simulate", "n=4 k=100 2 runs", ["simulate", *WELL, "--n", "4", "--particles", "100",
                                      "--runs", "2"], 20, 80),
    ("simulate", "n=10 k=20 2 runs", ["simulate", *WELL, "--n", "10", "--particles", "20",
                                      "--runs", "2"], 20, 80),
    ("simulate", "n=4 k=1 tol 1e-11", ["simulate", *WELL, "--n", "4", "--runs", "4", "--tol",
                                   "1e-11"], 400, 1600),
    ("simulate adaptive", "n=4 2 runs", ["simulate", *WELL, "--n", "4", "--runs", "2",
                                         "--stepper", "adaptive"], 500, 2000),
    ("simulate adaptive", "n=10 2 runs", ["simulate", *WELL, "--n", "10", "--runs", "2",
                                          "--stepper", "adaptive"], 500, 2000),
    ("simulate --n inf", "k=1 2 runs", ["simulate", *WELL, "--n", "inf", "--runs", "2"],
     10000, 40000),
    ("billiard", "fixed 2 runs", ["billiard", *WELL, "--runs", "2", "--fixed"], 5000, 20000),
    ("billiard", "moving 2 runs", ["billiard", *WELL, "--runs", "2"], 5000, 20000),
    ("chaos", "lambda1 n=4 4 runs", ["chaos", *WELL, "--n", "4", "--runs", "4"], 1000, 4000),
    ("chaos", "spectrum n=4 2 runs", ["chaos", *WELL, "--n", "4", "--runs", "2", "--spectrum"],
     300, 1200),
    ("chaos", "spectrum k=20 2 runs", ["chaos", *WELL, "--n", "4", "--particles", "20",
                                       "--runs", "2", "--spectrum"], 2, 8),
    ("lifetime", "n=4 2 runs", ["lifetime", *WELL, "--n", "4", "--runs", "2"], 2000, 8000),
    ("compare", "2 runs", ["compare", "--damping", "0.05", "--runs", "2"], 50, 200),
    ("compare", "well k=5 4 runs", ["compare", "--damping", "0.05", "--runs", "4",
                                    "--attachments", "well", "--particles", "5"], 50, 200),
    # a design sweep (one worker, in this process): the work limit's estimate of its points
    # (what ``sweep`` prints) and the design estimator's (design.cost.estimate, which times
    # a short run of the heaviest point and scales it)
    ("design limit", "2x2 designs", DESIGN, 200, 800),
    ("design estimator", "2x2 designs", DESIGN, 200, 800),
    # entry points of the Python API without a command (called by :func:`run_api`; the
    # lengths are periods, lags or continuation points)
    ("solve_fokker_planck", "10 cells", 10, 100, 400),
    ("solve_fokker_planck", "1000 cells", 1000, 100, 400),
    ("jacobi_increments", "5 points 100 runs", 100, 5, 20),
    ("jacobi_increments", "5 points 1000 runs", 1000, 5, 20),
    ("continue_orbits", "duffing2 64 steps", 64, 10, 40),
    ("continue_orbits", "duffing2 1024 steps", 1024, 5, 20),
]  # fmt: skip
#: The entry points of the API cases: (size, length) -> the call.
API = {
    "solve_fokker_planck": lambda cells, periods: _fokker_planck(cells, periods),
    "jacobi_increments": lambda runs, lag: _jacobi(runs, lag),
    "continue_orbits": lambda steps, points: _continuation(steps, points),
}


def _fokker_planck(cells: int, periods: int) -> None:
    from numpy import linspace

    from sinktheory.equilibrium.kramers import solve_fokker_planck

    s = linspace(0, 1, 101)
    solve_fokker_planck(1.0, s, 0.01 * (1 - 2.25 * s), 0.01 * s * (1 - s), 0.5, periods,
                        cells=cells)  # fmt: skip


def _jacobi(runs: int, lag: int) -> None:
    from numpy import linspace, random

    from sinktheory.equilibrium.kramers import jacobi_increments

    jacobi_increments(linspace(0.1, 0.9, 5), (1, lag), runs, random.default_rng(0), a=1, b=1,
                      c=0.1)  # fmt: skip


def _continuation(steps: int, points: int) -> None:
    """Duffing2's branch from the module's example, run to ``points`` points (its
    interval wide enough that none stops it sooner)."""
    from numpy import array, pi

    from sinktheory.nnm.continuation import continue_orbits
    from sinktheory.nnm.system import FlowSystem

    branch = continue_orbits(FlowSystem("duffing2", []), array([0.1, 0.1, 0, 0]), 2 * pi,
                             steps=steps, total_energy=0.01, interval=(1e-3, 1e3), ds=0.3,
                             max_points=points)  # fmt: skip
    if len(branch.frequency) != points:
        raise SystemExit(f"continue_orbits stopped at {len(branch.frequency)} of {points} points")


def run_api(name: str, size: int, length: int) -> tuple[float, float]:
    """(seconds, estimated seconds) of the API entry point ``name`` in this process."""
    from sinktheory.worklimit import tally

    start = time.perf_counter()
    with tally() as estimates:
        API[name](size, length)
    return time.perf_counter() - start, sum(estimates)


def run_case(argv: list[str]) -> tuple[float, float]:
    """(seconds, estimated seconds) of ``sinktheory ARGV`` in this process."""
    from sinktheory.cli import main
    from sinktheory.worklimit import tally

    sink = io.StringIO()
    start = time.perf_counter()
    with tally() as estimates, contextlib.redirect_stdout(sink), contextlib.redirect_stderr(sink):
        status = main([*argv, "--json"])
    seconds = time.perf_counter() - start
    if status != 0:
        raise SystemExit(f"{' '.join(argv)}: status {status}: {sink.getvalue()[-500:]}")
    return seconds, sum(estimates)


def run_design(command: str, params: dict) -> tuple[float, float]:
    """(seconds, estimated seconds) of the design sweep of ``params`` on one worker:
    the estimate of the work limit (``command`` "design limit") or of the design
    estimator ("design estimator")."""
    from sinktheory.design import explore
    from sinktheory.design.cost import estimate
    from sinktheory.design.explorer import plan

    sweep = plan(params)
    if command == "design limit":
        estimated = sweep.estimate
    else:
        estimated = estimate(sweep, workers=1, seconds=1.0).total_seconds
    start = time.perf_counter()
    explore(params, workers=1, progress=False, estimate_first=False)
    return time.perf_counter() - start, estimated


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default=None, help="commands to run, comma-separated")
    parser.add_argument("--repeats", type=int, default=2)
    args = parser.parse_args()
    sys.path.insert(0, str(Path(__file__).parent))
    from machine import describe

    only = None if args.only is None else set(args.only.split(","))
    ratios: dict[str, list[float]] = {}
    print(f"{'command':18s} {'case':22s} {'periods':>11s} {'estimates':>17s} "
          f"{'seconds':>13s} {'fixed':>6s} {'work/estimate':>13s}")  # fmt: skip
    for command, label, argv, small, large in CASES:
        if only is not None and command.split()[0] not in only:
            continue
        runs = {}
        for periods in (small, large):
            if command in API:
                API[command](argv, periods)  # compile or load the kernels, fill caches
                runs[periods] = min(run_api(command, argv, periods) for _ in range(args.repeats))
                continue
            if command.startswith("design"):
                case = {**argv, "periods": periods}
                run_design(command, case)  # compile or load the kernels, fill caches
                runs[periods] = min(run_design(command, case) for _ in range(args.repeats))
                continue
            case = [*argv, "--periods", str(periods)]
            run_case(case)  # compile or load the kernels, fill caches
            runs[periods] = min(run_case(case) for _ in range(args.repeats))
        (t1, e1), (t2, e2) = runs[small], runs[large]
        ratio = (t2 - t1) / (e2 - e1)  # the work's seconds per estimated second
        fixed = t1 - ratio * e1
        ratios.setdefault(command, []).append(ratio)
        print(f"{command:18s} {label:22s} {small:5d}/{large:<5d} {e1:7.3g}/{e2:<7.3g}s "
              f"{t1:6.3g}/{t2:<6.3g}s {fixed:5.2f}s {ratio:13.2f}", flush=True)  # fmt: skip
    print("the work's seconds per estimated second, per command (goal: within [0.33, 1]):")
    for command, values in ratios.items():
        print(f"  {command:18s} {min(values):6.2f} .. {max(values):6.2f}")
    print(describe())


if __name__ == "__main__":
    main()
