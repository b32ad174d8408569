"""What machine a benchmark ran on: printed beside every figure, since a speed measured on
one machine (vector width, real or shared cores, load) need not hold on another.

Usage: ``from machine import describe; print(describe())`` in a benchmark script (the
scripts run from this folder), or ``python benchmarks/machine.py``.
"""

from __future__ import annotations

import math
import os
import platform
import time


def _cpu_model() -> str:
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def _vector_extensions() -> str:
    """The widest SIMD extensions the compiler may use here (from LLVM's view of the
    host)."""
    import llvmlite.binding as llvm

    flags = llvm.get_host_cpu_features().flatten().split(",")
    features = {f[1:] for f in flags if f.startswith("+")}
    wanted = ("avx512f", "avx2", "fma", "avx", "sse4.2", "neon", "sve")
    have = [f for f in wanted if f in features]
    return ", ".join(have) or "none of " + "/".join(wanted)


def describe() -> str:
    """One line: CPU, cores, SIMD, LLVM's CPU name, numba/numpy versions, load average."""
    import llvmlite.binding as llvm
    import numba
    import numpy

    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    return (
        f"machine: {_cpu_model()} ({llvm.get_host_cpu_name()}), {os.cpu_count()} cores, "
        f"SIMD {_vector_extensions()}; numba {numba.__version__} with "
        f"{numba.get_num_threads()} threads, numpy {numpy.__version__}, "
        f"Python {platform.python_version()}; load average {load:.2f}"
    )


if __name__ == "__main__":
    print(describe())


def best_of(fn, repeats: int = 3) -> tuple[float, object]:
    """(fewest seconds, last result) of ``repeats`` calls of ``fn``: the best of several
    is the timing least disturbed by other work on a shared machine."""
    best, out = math.inf, None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out
