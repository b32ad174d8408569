"""How long a sweep checks its grid before it creates its store (:meth:`Sweep.make`).

Every point of a grid is validated and its work estimated before anything is written
(:mod:`sinktheory.sweep.plan`); this times that check alone, per kind at a few grid sizes
over beta, and prints the seconds per point.  Each size gets betas of its own (a shifted
grid), so no point is remembered from an earlier size.  The rows "(user's well)" sweep
the semi-axis a of docs/guide/elliptic.toml instead: a user's well is checked at each
point's parameter values.  Run:
``python benchmarks/bench_sweep_check.py [--kinds floquet,chaos] [--sizes 16,64,256]``
(about two minutes at the default sizes on 2 shared cores).
"""

import argparse
import os
import time
from pathlib import Path

import numpy as np

from sinktheory.sweep.kinds import KINDS
from sinktheory.sweep.plan import Sweep
from sinktheory.userwell import load_well

#: Each kind's fixed parameters (small runs: the check's cost does not grow with them,
#: only the estimate does).
FIXED = {
    "floquet": {"alpha": 0.5, "n": 4},
    "bifurcation": {"alpha": 0.5, "n": 4, "transient": 1000, "count": 3},
    "ensemble": {"alpha": 0.5, "n": 4, "runs": 2, "periods": 1000},
    "design": {"alpha": 0.5, "n": 4, "runs": 2, "periods": 1000, "lyapunov_runs": 2},
    "chaos": {"alpha": 0.5, "n": 4, "runs": 2, "periods": 1000},
    "ergodicity": {
        "alpha": 0.5,
        "n": 4,
        "runs": 2,
        "periods": 1000,
        "transient": 500,
        "lyapunov_runs": 2,
    },
}
#: Grid sizes per kind when --sizes is not given (floquet's points are ~100x cheaper).
SIZES = {"floquet": (100, 1000, 10000)}
DEFAULT_SIZES = (16, 64, 256)
#: The user's well of the "(user's well)" rows, its kinds and sizes.
ELLIPTIC = Path(__file__).resolve().parent.parent / "docs" / "guide" / "elliptic.toml"
WELL_KINDS = ("bifurcation", "chaos")
WELL_SIZES = (4, 16)


def betas(size: int, shift: int) -> list[float]:
    """``size`` betas in [-0.3, 0.4], moved by a tiny amount per ``shift``."""
    return (np.linspace(-0.3, 0.4, size) + 1e-7 * shift).tolist()


def timed(kind: str, label: str, params: dict) -> None:
    """Time Sweep.make of ``params`` and print a row."""
    size = len(next(v for v in params.values() if isinstance(v, list)))
    start = time.perf_counter()
    Sweep.make(kind, params)
    seconds = time.perf_counter() - start
    load = os.getloadavg()[0]
    print(f"{label:24s}  {size:6d}  {seconds:8.2f}  {seconds / size:12.2e}  {load:5.2f}")


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--kinds", default=",".join(KINDS))
    parser.add_argument("--sizes", default=None, help="comma-separated grid sizes")
    args = parser.parse_args()
    print(describe())
    print("kind                      points   seconds   s per point   load")
    shift = 0
    for kind in args.kinds.split(","):
        shift += 1
        Sweep.make(kind, {**FIXED[kind], "beta": betas(2, shift)})  # imports, compiled code
        sizes = args.sizes.split(",") if args.sizes else SIZES.get(kind, DEFAULT_SIZES)
        for size in map(int, sizes):
            shift += 1
            timed(kind, kind, {**FIXED[kind], "beta": betas(size, shift)})
    well = load_well(ELLIPTIC)
    for kind in (k for k in WELL_KINDS if k in args.kinds.split(",")):
        fixed = {key: x for key, x in FIXED[kind].items() if key not in ("alpha", "n")}
        for size in WELL_SIZES:
            shift += 1
            a = (np.linspace(0.25, 0.35, size) + 1e-7 * shift).tolist()
            timed(kind, f"{kind} (user's well)", {**fixed, "well": well, "a": a})


if __name__ == "__main__":
    main()
