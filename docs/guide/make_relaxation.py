"""Predicted against measured settling times: the chart and table of the equilibrium guide.

    python docs/guide/make_relaxation.py [--quick] [--runs 32] [--out DIR]

For each case (flat and symmetric wells, k = 1..5, m = 0.1..0.5, beta from -0.5 to 0.4,
n = 4, 10, 20 and oo), from the paper's start (E0 = 0.5, particles at rest):

* predicted: :func:`sinktheory.equilibrium.prediction.predict_relaxation` with its
  defaults (12 points x 100 runs on the shell, lags 16 to 128; seed 0), the 5 % settling
  time and its bootstrap interval; for rigid walls (n = oo)
  :func:`sinktheory.billiard.relaxation.predict_rigid_relaxation`, the same model on exact
  billiards started on the rigid shell;
* measured: ``--runs`` runs (seed 1, tol 1e-6) over four times the predicted settling
  time (at least 3000 periods, at most 20000), read by
  :func:`sinktheory.equilibrium.relaxation.measure_relaxation`
  (:func:`~sinktheory.equilibrium.prediction.measure_settling`; for n = oo
  :func:`~sinktheory.billiard.relaxation.measure_rigid_settling`, exact billiards).

"agrees": within 25 %, or ln(predicted / measured) within 2 standard errors (each from its
95 % interval's width); "+" marks a prediction whose t_r exceeds 4 times the largest lag.
``--cache FILE.json`` keeps the measurements (the slow part) between runs: a case is
measured again only when its run length (set by the prediction) changes.

Writes into DIR (default: this folder) ``relaxation.png`` (predicted against measured,
log-log, with the intervals) and ``relaxation.inc`` (the table, included by
equilibrium.rst), with the machine's description.  How each case relates to the choice
of the model: "seen" (Fig. 8, k = 1 and 5: their shell runs shaped it), "earlier" (run
with an earlier model, a drift from base lag 8 to lag 64, before this one was chosen:
their measured settling times were known; for n = oo: run by
benchmarks/bench_rigid_limit.py before this chart had rigid points) and "fresh" (chosen
before the model's predictions for them were seen).  Rigid cases are drawn as triangles.
The full run took 41 minutes on two cores shared at a load average of 4-15; --quick runs
three small cases (one of them rigid) and writes nothing unless --out is given.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path
from types import SimpleNamespace

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "benchmarks"))

from machine import describe  # noqa: E402

from sinktheory.billiard.relaxation import (  # noqa: E402
    measure_rigid_settling,
    predict_rigid_relaxation,
)
from sinktheory.equilibrium.prediction import measure_settling, predict_relaxation  # noqa: E402
from sinktheory.errors import NumericalError  # noqa: E402
from sinktheory.model import Sink, Well  # noqa: E402

FLAT = dict(alpha=0.5, beta=0.3, n=4)
SYMMETRIC = dict(alpha=1.0, beta=0.1, n=6, shape="symmetric")
RIGID = {**FLAT, "n": math.inf}
#: (label, well, k, m, how the case relates to the choice of the model: see above)
CASES = [
    ("Fig. 8, k = 1", FLAT, 1, 0.2, "seen"),
    ("Fig. 8, k = 2", FLAT, 2, 0.2, "earlier"),
    ("Fig. 8, k = 3", FLAT, 3, 0.2, "earlier"),
    ("Fig. 8, k = 4", FLAT, 4, 0.2, "earlier"),
    ("Fig. 8, k = 5", FLAT, 5, 0.2, "seen"),
    ("k = 3, m = 0.1", FLAT, 3, 0.1, "earlier"),
    ("k = 3, m = 0.4", FLAT, 3, 0.4, "earlier"),
    ("k = 2, m = 0.5", FLAT, 2, 0.5, "earlier"),
    ("k = 3, beta = -0.5", {**FLAT, "beta": -0.5}, 3, 0.2, "earlier"),
    ("k = 3, beta = 0.1", {**FLAT, "beta": 0.1}, 3, 0.2, "earlier"),
    ("k = 3, n = 10", {**FLAT, "n": 10}, 3, 0.2, "fresh"),
    ("k = 2, n = 20", {**FLAT, "n": 20}, 2, 0.2, "fresh"),
    ("symmetric, k = 5 (Fig. 12)", SYMMETRIC, 5, 0.2, "fresh"),
    ("symmetric, k = 2", SYMMETRIC, 2, 0.2, "fresh"),
    ("k = 4, m = 0.3", FLAT, 4, 0.3, "fresh"),
    ("k = 1, beta = -0.3", {**FLAT, "beta": -0.3}, 1, 0.2, "fresh"),
    ("k = 5, n = 10", {**FLAT, "n": 10}, 5, 0.2, "fresh"),
    ("k = 2, beta = 0.4", {**FLAT, "beta": 0.4}, 2, 0.2, "fresh"),
    ("symmetric, k = 3, m = 0.3", SYMMETRIC, 3, 0.3, "fresh"),
    ("Fig. 8, k = 1, n = oo", RIGID, 1, 0.2, "earlier"),
    ("Fig. 8, k = 3, n = oo", RIGID, 3, 0.2, "earlier"),
    ("k = 2, m = 0.4, n = oo", RIGID, 2, 0.4, "fresh"),
    ("k = 4, m = 0.3, n = oo", RIGID, 4, 0.3, "fresh"),
    ("k = 1, beta = -0.3, n = oo", {**RIGID, "beta": -0.3}, 1, 0.2, "fresh"),
    ("symmetric, k = 2, n = oo", {**SYMMETRIC, "n": math.inf}, 2, 0.2, "fresh"),
]


def rigid(well: dict) -> bool:
    """Whether ``well`` has rigid walls (n = oo)."""
    return math.isinf(well["n"])


def predicted(well: dict, k: int, m: float):
    """The model's prediction for the case (soft or rigid walls)."""
    if rigid(well):
        return predict_rigid_relaxation(well.get("shape", "flat"), well["alpha"],
                                        well["beta"], particles=k, mass=m, seed=0)  # fmt: skip
    return predict_relaxation(Sink(Well(**well), particles=k, mass=m), 0.5, seed=0)


def measured(well, k, m, runs, periods, cache, key):
    """The measured settling (time, low, high, extrapolated), from ``cache`` when there."""
    if key not in cache:
        if rigid(well):
            r, _ = measure_rigid_settling(well.get("shape", "flat"), well["alpha"],
                                          well["beta"], (runs, periods), particles=k, mass=m,
                                          seed=1)  # fmt: skip
        else:
            r, _ = measure_settling(Sink(Well(**well), particles=k, mass=m), 0.5,
                                    (runs, periods), seed=1)  # fmt: skip
        cache[key] = [r.settle_time, r.settle_low, r.settle_high, bool(r.extrapolated)]
    t, low, high, extrapolated = cache[key]
    return SimpleNamespace(settle_time=t, settle_low=low, settle_high=high,
                           extrapolated=extrapolated)  # fmt: skip


def log_stderr(estimate: float, low: float, high: float) -> float:
    """Standard error of ln(estimate) from a 95 % interval (its width in ln over 2 x 1.96;
    inf when the interval is open)."""
    if low <= 0 or not math.isfinite(high):
        return math.inf
    return (math.log(high) - math.log(low)) / (2 * 1.96)


def verdict(p, r) -> tuple[str, float]:
    """('agrees' within 25 % or within 2 standard errors of ln(predicted / measured), else
    'no'; that number of standard errors z)."""
    ratio = p.settle_time / r.settle_time
    se = math.hypot(log_stderr(p.settle_time, p.settle_low, p.settle_high),
                    log_stderr(r.settle_time, r.settle_low, r.settle_high))  # fmt: skip
    z = abs(math.log(ratio)) / se
    return ("agrees" if abs(ratio - 1) <= 0.25 or z <= 2 else "no"), z


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--runs", type=int, default=32)
    parser.add_argument("--out", default=None)
    parser.add_argument("--cache", default=None, help="JSON file keeping the measurements")
    args = parser.parse_args()
    cases = [CASES[0], CASES[6], CASES[19]] if args.quick else CASES
    runs = 8 if args.quick else args.runs
    out = Path(args.out) if args.out else (None if args.quick else HERE)
    cache_path = Path(args.cache) if args.cache else None
    cache = json.loads(cache_path.read_text()) if cache_path and cache_path.exists() else {}
    machine = describe()
    print(machine, flush=True)
    rows, points = [], []
    for label, well, k, m, seen in cases:
        t0 = time.perf_counter()
        try:
            p = predicted(well, k, m)
        except NumericalError as error:
            p, periods = None, 3000
            failure = str(error).split(": ", 1)[1].split(" (")[0]  # without the numbers
        else:
            periods = int(min(max(4 * p.settle_time, 3000), 20000))
        t1 = time.perf_counter()
        r = measured(well, k, m, runs, periods, cache, f"{label}|{runs}|{periods}")
        if cache_path:
            cache_path.write_text(json.dumps(cache, indent=1))
        t2 = time.perf_counter()
        star = "*" if r.extrapolated else ""
        meas = f"{r.settle_time:.0f}{star} ({r.settle_low:.0f}-{r.settle_high:.0f})"
        if p is None:
            row = (f"{label} ({seen})", "fails: " + failure, meas, "", "fails",
                   f"{runs} x {periods}")  # fmt: skip
        else:
            high = f"{p.settle_high:.0f}" if math.isfinite(p.settle_high) else "inf"
            ratio = p.settle_time / r.settle_time if r.settle_time > 0 else math.inf
            row = (f"{label} ({seen})", f"{p.settle_time:.0f} ({p.settle_low:.0f}-{high})"
                   + ("+" if p.extrapolated else ""), meas, f"{ratio:.2f}",
                   "{} (z = {:.1f})".format(*verdict(p, r)), f"{runs} x {periods}")  # fmt: skip
            points.append((label, seen, rigid(well), p, r))
        rows.append(row)
        print(" | ".join(row) + f"  [{t1 - t0:.0f} s + {t2 - t1:.0f} s]", flush=True)
    if out is None:
        return
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.0, 5.0), layout="constrained")
    ax = fig.subplots()
    for label, seen, hard, p, r in points:
        p_high = p.settle_high if math.isfinite(p.settle_high) else 3e4
        ax.errorbar(r.settle_time, p.settle_time,
                    xerr=[[r.settle_time - r.settle_low], [max(r.settle_high - r.settle_time, 0)]],
                    yerr=[[p.settle_time - p.settle_low], [p_high - p.settle_time]],
                    fmt="^" if hard else {"seen": "s", "earlier": "D", "fresh": "o"}[seen],
                    ms=5, capsize=2,
                    color="C3" if r.extrapolated else {"seen": "0.4", "earlier": "C1",
                                                       "fresh": "C0"}[seen])  # fmt: skip
        ax.annotate(label, (r.settle_time, p.settle_time), fontsize=6, xytext=(3, 3),
                    textcoords="offset points")  # fmt: skip
    lo, hi = 30, 30000
    ax.plot([lo, hi], [lo, hi], "k-", lw=0.8, label="predicted = measured")
    ax.fill_between([lo, hi], [lo / 1.25, hi / 1.25], [lo * 1.25, hi * 1.25], color="0.85",
                    label="within 25 %")  # fmt: skip
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_xlabel("measured 5 % settling time (periods)")
    ax.set_ylabel("predicted (slow mode seen through fast noise)")
    ax.set_title(f"{runs} runs per case; grey squares: seen while choosing the model,\n"
                 "orange diamonds: run with an earlier model, blue: fresh; "
                 "triangles: rigid walls (n = oo)", fontsize=7)  # fmt: skip
    ax.legend(fontsize=7, loc="upper left")
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(out / "relaxation.png", dpi=110)
    widths = [max(len(r[i]) for r in rows + [HEADER]) for i in range(len(HEADER))]
    rule = "  ".join("=" * w for w in widths)
    lines = [f".. Written by docs/guide/make_relaxation.py on {machine.splitlines()[0]}", "",
             rule, "  ".join(h.ljust(w) for h, w in zip(HEADER, widths, strict=True)),
             rule]  # fmt: skip
    lines += ["  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows]
    lines += [rule, ""]
    (out / "relaxation.inc").write_text("\n".join(lines))
    print(f"wrote {out / 'relaxation.png'} and {out / 'relaxation.inc'}")


HEADER = ("case", "predicted (95 %)", "measured (95 %)", "ratio", "verdict", "runs x periods")

if __name__ == "__main__":
    main()
