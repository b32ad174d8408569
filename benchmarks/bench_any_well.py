"""One engine per well, n a run-time value (issue 36): what it costs and what it saves.

Usage::

    python benchmarks/bench_any_well.py [--baseline REV] [--repeats 3] [--quick]

Prints, on the machine it runs on (its description first):

1. **A new n on a warm cache**: a fresh process runs ``simulate`` (2 runs x 1 period,
   Fig. 8's well) for exponents it has never run; the time to the first result, and the
   machine code files numba wrote meanwhile (0: nothing compiled).  Goal: < 1 s.
2. **First use of a well**: the same in a fresh process with an empty engine cache, for a
   built-in shape, so the engine is printed and compiled; and a user's elliptic well
   through the engine directly (``Ensemble``, the engine's own interface).
   Goal: < 30 s.
3. **Fig. 8 at tol 1e-8** (flat, alpha = 0.5, beta = 0.3, n = 4, k = 5, m = 0.2, 25 runs x
   1500 periods, E0 = 0.5) with this checkout's engine and with the engine of ``REV``
   (default: the last commit whose engine fixed n in its text), each in its own process,
   alternating, best of ``--repeats``; the largest relative energy error of each, which
   differ at round-off only.  Goal: within 10 %.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import textwrap
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from baseline import run_at  # noqa: E402
from machine import describe  # noqa: E402

#: The last commit whose engine was printed per (shape, n) with n in its text.
FIXED_N = "de40031"

FIRST = """
import time
t = time.perf_counter()
from pathlib import Path
from sinktheory import RunSettings, Sink, Well, simulate
from sinktheory.engine.cache import cache_dir
before = set((cache_dir() / "__pycache__").glob("*"))
simulate(Sink(Well(0.5, 0.3, {n}, shape={shape!r}), particles=5, mass=0.2),
         RunSettings(runs=2, periods=1), progress=False)
wall = time.perf_counter() - t
after = set((cache_dir() / "__pycache__").glob("*"))  # glob of a missing folder: empty
print(wall, len(after - before))
"""

USER_WELL = """
import time
t = time.perf_counter()
import numpy as np
from sinktheory.engine.cache import well_name
from sinktheory.engine.core import Ensemble
from sinktheory.integrators import get_scheme
from sinktheory.userwell import UserWell
well = UserWell("ellipse", "gamma/(2*n) * ((x/a)**2 + (y/b)**2)**n",
                {{"a": 0.4, "b": 0.25, "gamma": 1.0, "n": ({n}, (1, 1000))}})
rng = np.random.default_rng(0)
q, v = np.zeros((11, 8)), np.zeros((11, 8))
q[0], q[1:] = 1.0, rng.uniform(-0.1, 0.1, (10, 8))
q[1:6] += 1.0  # particles near the container's centre
ens = Ensemble(well_name(well), q, v, [0.4, 0.25, 1.0, {n}, 0.04])
ens.run(get_scheme("blanes-moan6"), dt=2 * np.pi / 2000, steps=2000, segments=1)
print(time.perf_counter() - t, 0)
"""

FIG8 = """
import time
from sinktheory import RunSettings, Sink, Well, simulate
sink = Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2)
simulate(sink, RunSettings(runs=2, periods=1), progress=False)
t = time.perf_counter()
r = simulate(sink, RunSettings(runs={runs}, periods={periods}, seed=0), tol=1e-8, progress=False)
print(time.perf_counter() - t, float(r.run_errors.max()))
"""


def first_result(n: int, shape: str = "flat", env: dict | None = None) -> tuple[float, int]:
    """(seconds to the first result in a fresh process, machine code files written)."""
    wall, written = run_at(None, textwrap.dedent(FIRST.format(n=n, shape=shape)), env).split()
    return float(wall), int(written)


def first_user_well(n: int, env: dict) -> float:
    """Seconds to one period of 8 runs of an elliptic user well in a fresh process."""
    return float(run_at(None, textwrap.dedent(USER_WELL.format(n=n)), env).split()[0])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--baseline", default=FIXED_N, help="git revision to compare with")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--quick", action="store_true", help="a short Fig. 8 (smoke test)")
    args = parser.parse_args(argv)
    print(describe())

    print("\n== 1. a new n on a warm cache (fresh process, Fig. 8's well, 2 runs x 1 period)")
    first_result(4)  # the engine itself compiled once, if it was not yet
    for n in (5, 7, 13, 57, 333):
        wall, written = first_result(n)
        print(f"  n = {n:4d}: first result in {wall:5.2f} s, {written} machine code files written")

    print("\n== 2. first use of a well (fresh process, empty engine cache)")
    with tempfile.TemporaryDirectory() as empty:
        wall, written = first_result(4, "symmetric", {"SINKTHEORY_CACHE": empty})
        print(f"  symmetric, n = 4: first result in {wall:5.1f} s ({written} files written)")
        wall, written = first_result(9, "symmetric", {"SINKTHEORY_CACHE": empty})
        print(f"  then n = 9 in a new process: {wall:5.2f} s ({written} files written)")
        env = {"SINKTHEORY_CACHE": empty}
        print(
            f"  a user's elliptic well, n = 3 (engine level, 8 runs x 1 period): "
            f"{first_user_well(3, env):5.1f} s; then n = 7: {first_user_well(7, env):5.2f} s"
        )

    runs, periods = (25, 100) if args.quick else (25, 1500)
    print(f"\n== 3. Fig. 8 at tol 1e-8, {runs} runs x {periods} periods, best of {args.repeats}")
    script = textwrap.dedent(FIG8.format(runs=runs, periods=periods))
    best = {"this checkout (n at run time)": [], f"{args.baseline} (n in the text)": []}
    for _ in range(args.repeats):
        for label, rev in zip(best, (None, args.baseline), strict=True):
            best[label].append(tuple(map(float, run_at(rev, script).split())))
    (ours, ours_err), (theirs, theirs_err) = (min(v) for v in best.values())
    for (label, _), (wall, err) in zip(best.items(), [(ours, ours_err), (theirs, theirs_err)],
                                       strict=True):  # fmt: skip
        print(f"  {label:34s} {wall:6.3f} s   max energy error {err:.2e}")
    print(f"  ratio {ours / theirs:.3f} (goal <= 1.10)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
