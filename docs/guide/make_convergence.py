"""Soft walls against the rigid billiard: the chart and tables of the billiard guide.

    python docs/guide/make_convergence.py [--quick] [--part chart|table|all] [--out DIR]

Writes into DIR (default: this folder) the chart part, ``convergence.png`` (lambda_1(beta)
for n = 4, 10, 20 and the rigid limit over the beta range of the paper's Fig. 3) and
``convergence.inc`` (its tables), and the table part, ``convergence_n.png`` (lambda_1,
mean free time and time-averaged container energy against n at beta = 0.3) and
``convergence_n.inc`` (soft walls against the rigid limit for three wells, with lambda_1
split into regular and chaotic runs); billiard.rst includes both.  Fig. 3's set-up: flat
well, alpha = 1/2, gamma = 1, one particle of mass 0.2, E0 = 0.5, particles at rest near
the centre.  The machine's description is printed and written with the tables.

The table's runs per well (:data:`WELLS`) are what resolves the gaps it states: at
beta = 0.3 the soft and rigid lambda_1 differ by 0.05-0.1 with a per-run spread of about
0.35, so 256 runs (standard error about 0.02).  The chart takes about four minutes on two
cores, the table about 40 (plus about 15 s of compilation per new n the first time);
--quick takes seconds and writes nothing unless --out is given; --cache DIR keeps the
ensembles, so a rerun only rewrites the tables.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "benchmarks"))

from machine import describe  # noqa: E402

from sinktheory.billiard.convergence import (  # noqa: E402
    NS,
    QUANTITIES,
    Convergence,
    convergence,
    lyapunov_chart,
)
from sinktheory.chaos.verdicts import chaotic, threshold  # noqa: E402
from sinktheory.floquet import model_problem, scan  # noqa: E402
from sinktheory.model import RunSettings  # noqa: E402
from sinktheory.plot.convergence import convergence_figure, lyapunov_figure  # noqa: E402
from sinktheory.sweep.chaosmap import beta_grid  # noqa: E402

ALPHA, RANGE, CHART_NS = 0.5, (-0.7, 0.45), (4, 10, 20)
#: The tail of the stiffnesses fitted on their own (past the peak of the focusing wells).
TAIL = 50
#: The wells of the convergence table and their runs: dispersing, focusing with a stable
#: bouncing orbit in the fixed rigid table (|beta| < 1/2 for alpha = 1/2), focusing beyond
#: it.  The focusing wells' gaps are 5-9 standard errors at 32 runs; beta = 0.3 needs 256.
WELLS = {0.3: 256, -0.2: 32, -0.6: 32}
FULL = {"points": 24, "chart": (12, 200), "periods": 200, "ns": NS, "scale": 1}
QUICK = {"points": 5, "chart": (2, 6), "periods": 4, "ns": (4, 10), "scale": 0}


def _pm(mean: float, se: float) -> str:
    return f"{mean:.3f} +- {se:.3f}"


def _verdict(mean: float, se: float, periods: int) -> str:
    """C (chaotic) or R, as the chaos maps decide (:func:`sinktheory.chaos.verdicts.chaotic`)."""
    return "C" if chaotic(mean, se, periods) else "R"


def _rate(r: dict) -> str:
    """p +- its standard error and the n it was fitted over, or why there is none."""
    used = ", ".join(map(str, r["fit_ns"]))
    if r.get("below") and r.get("above"):
        below, above = (", ".join(map(str, r[k])) for k in ("below", "above"))
        return f"-- (crosses the limit: below at n = {below}, above at n = {above})"
    if not np.isfinite(r["p"]):
        return f"-- (beyond two s.e.: n = {used or 'none'})"
    se = f" +- {r['p_stderr']:.2f}" if np.isfinite(r["p_stderr"]) else ""
    return f"{r['p']:.2f}{se} (n = {used})"


def _table(title: str, header: list[str], rows: list[list[str]]) -> list[str]:
    out = [f".. list-table:: {title}", "   :header-rows: 1", ""]
    for row in [header, *rows]:
        out += [f"   * - {row[0]}"] + [f"     - {c}" for c in row[1:]]
    return out + [""]


def _diff(m: float, se: float, rm: float, rse: float) -> str:
    """soft minus rigid, and how many combined standard errors that is."""
    z = (m - rm) / np.hypot(se, rse) if np.hypot(se, rse) > 0 else np.nan
    return f"{m - rm:+.3f} ({z:+.1f} s.e.)"


def chart_part(f: dict, out: Path | None, machine: str) -> None:
    """lambda_1(beta) for n = 4, 10, 20 and the rigid billiard: convergence.png/.inc."""
    start = time.perf_counter()
    runs, periods = f["chart"]
    transient = periods // 10
    betas = beta_grid([RANGE], f["points"])
    settings = RunSettings(runs=runs, periods=periods)
    chart = lyapunov_chart(ALPHA, betas, ns=CHART_NS, settings=settings, transient=transient)
    stable = scan(model_problem(ALPHA, 10), *RANGE, 400).stable_intervals
    print(f"chart: {time.perf_counter() - start:.0f} s", flush=True)
    chart_rows = []

    def mark(count):  # regular runs of a point, where there are any
        return f" ({count} of {runs} regular)" if count else ""

    for j, b in enumerate(betas):
        cells = [f"{b:+.3f}"]
        for i in range(len(CHART_NS)):
            m, se = chart.lambda1[i, j], chart.lambda1_se[i, j]
            cells.append(f"{_pm(m, se)} {_verdict(m, se, periods)}{mark(chart.regular[i, j])}")
        m, se = chart.rigid_lambda1[j], chart.rigid_lambda1_se[j]
        cells.append(f"{_pm(m, se)} {_verdict(m, se, periods)}{mark(chart.rigid_regular[j])}")
        chart_rows.append(cells)
        print("  ".join(cells), flush=True)
    pooled_rows = []
    for lo, hi, what in ((0.1, RANGE[1], "dispersing"), (RANGE[0], -0.1, "focusing")):
        r = chart.pooled_rate(lo, hi)
        m = chart.lambda1[:, (betas >= lo) & (betas <= hi)].mean(axis=1)
        pooled_rows.append(
            [f"{what}, {r['betas'][2]} betas in [{r['betas'][0]:+.2f}, {r['betas'][1]:+.2f}]"]
            + [f"{v:.3f}" for v in m]
            + [f"{r['limit']:.3f} +- {r['limit_stderr']:.3f}", _rate(r)]
        )
        print(*pooled_rows[-1], flush=True)
    total = time.perf_counter() - start
    if out is None:
        return
    out.mkdir(parents=True, exist_ok=True)
    fig = lyapunov_figure(chart)
    ax = fig.axes[0]
    for a, b in stable:
        ax.axvspan(a, b, color="tab:green", alpha=0.08, lw=0)
    ax.text(0.01, 0.97, "green: Floquet-stable y = 0 at n = 10", transform=ax.transAxes,
            fontsize=7, va="top")  # fmt: skip
    fig.savefig(out / "convergence.png", dpi=90)
    lines = [
        f"Measured {time.strftime('%Y-%m-%d')} by ``python docs/guide/make_convergence.py "
        f"--part chart`` ({total / 60:.0f} min):",
        "",
        f"``{machine}``",
        "",
        f"Chart: {runs} runs x {periods} periods per point, lambda_1 after a transient of "
        f"{transient} T; C: chaotic (mean - 2 s.e. > 3 ln t / t = {threshold(periods):.3f}), "
        "R: regular; a point some of whose runs are regular (lambda_1 <= 3 ln t / t over "
        f"the {periods - transient} periods after the transient) says how many: "
        f"{int(chart.regular.sum() + chart.rigid_regular.sum())} of "
        f"{runs * (chart.regular.size + chart.rigid_regular.size)} runs are.  "
        "Floquet-stable y = 0 at n = 10: "
        + (", ".join(f"({a:.3f}, {b:.3f})" for a, b in stable) or "none")
        + ".",
        "",
    ]
    lines += _table(
        "lambda_1 per unit time (mean +- standard error)",
        ["beta"] + [f"n = {n}" for n in CHART_NS] + ["rigid"],
        chart_rows,
    )
    lines += _table(
        "lambda_1 of the chart averaged over betas, and the rate of the averages",
        ["betas"] + [f"n = {n}" for n in CHART_NS] + ["rigid", "p (fit range)"],
        pooled_rows,
    )
    (out / "convergence.inc").write_text("\n".join(lines))
    print(f"wrote {out / 'convergence.png'}, {out / 'convergence.inc'}")


def _split_rows(beta: float, c) -> list[list[str]]:
    """The rows of lambda_1 split into regular and chaotic runs (group means only where a
    stiffness's ensemble is mixed)."""
    soft, rigid = c.split()
    groups = [*soft, rigid]
    rows = [[f"{beta:+g}", "regular runs (lambda1 <= 3 ln t/t)"]
            + [f"{s.regular} of {s.runs}" for s in groups]]  # fmt: skip
    if any(s.mixed for s in groups):
        for what, mean, se in (("regular", "regular_mean", "regular_se"),
                               ("chaotic", "chaotic_mean", "chaotic_se")):  # fmt: skip
            rows.append([f"{beta:+g}", f"lambda1 of the {what} runs"]
                        + [_pm(getattr(s, mean), getattr(s, se)) for s in groups])  # fmt: skip
    return rows


def _convergence(beta: float, runs: int, periods: int, ns, cache: Path | None):
    """One well's :func:`convergence`, kept in (and taken from) ``cache`` when given: an
    .npz per set-up, so that rewriting the tables does not rerun the ensembles."""
    fields = [f.name for f in dataclasses.fields(Convergence)]
    key = f"flat_{ALPHA:g}_{beta:+g}_{runs}x{periods}_n{'-'.join(map(str, ns))}.npz"
    if cache is not None and (cache / key).exists():
        with np.load(cache / key) as z:
            print(f"beta = {beta:+g}: taken from {cache / key}", flush=True)
            data = {k: z[k] for k in fields if k != "parameters"}
            return Convergence(**data, parameters=json.loads(str(z["parameters"])))
    settings = RunSettings(runs=runs, periods=periods)
    c = convergence("flat", ALPHA, beta, ns=ns, transient=periods // 10, settings=settings,
                    progress=True)  # fmt: skip
    if cache is not None:
        cache.mkdir(parents=True, exist_ok=True)
        arrays = {k: getattr(c, k) for k in fields if k != "parameters"}
        np.savez(cache / key, **arrays, parameters=json.dumps(c.parameters))
    return c


def table_part(f: dict, out: Path | None, machine: str, cache: Path | None = None) -> None:
    """Soft walls against the rigid limit at three wells: convergence_n.png/.inc."""
    start = time.perf_counter()
    periods = f["periods"]
    conv_rows, rate_rows, results, counts = [], [], [], []
    for beta, runs in WELLS.items():
        runs = max(2, runs * f["scale"])
        counts.append(f"{runs} runs at beta = {beta:+g}")
        t0 = time.perf_counter()
        c = _convergence(beta, runs, periods, f["ns"], cache)
        results.append(c)
        print(f"beta = {beta:+g}: {runs} runs, {time.perf_counter() - t0:.0f} s", flush=True)
        for q in QUANTITIES:
            shown = len(conv_rows)
            m, se, rm, rse = c.summary(q)
            row = [f"{beta:+g}", q.replace("_", " ")]
            conv_rows.append(row + [_pm(a, b) for a, b in zip(m, se, strict=True)]
                             + [_pm(rm, rse)])  # fmt: skip
            if q == "lambda1":
                conv_rows.append([f"{beta:+g}", "lambda1 minus rigid"]
                                 + [_diff(a, b, rm, rse) for a, b in zip(m, se, strict=True)]
                                 + ["--"])  # fmt: skip
                conv_rows += _split_rows(beta, c)
            fit, tail = _rate(c.rate(q)), _rate(c.rate(q, n_min=TAIL))
            rate_rows.append([f"{beta:+g}", q.replace("_", " "), fit, tail])
            print("\n".join("  ".join(r) for r in conv_rows[shown:]), "| p:", fit, "| tail:",
                  tail, flush=True)  # fmt: skip
    total = time.perf_counter() - start
    print(f"table: {total:.0f} s", flush=True)
    if out is None:
        return
    out.mkdir(parents=True, exist_ok=True)
    first_runs = results[0].parameters["runs"]
    conv = convergence_figure(results[0], title=(
        rf"flat, $\alpha$ = 0.5, $\beta$ = {next(iter(WELLS)):g}, k = 1, m = 0.2: "
        f"{first_runs} runs x {periods} T per point"))  # fmt: skip
    conv.savefig(out / "convergence_n.png", dpi=80)
    lines = [
        f"Measured {time.strftime('%Y-%m-%d')} by ``python docs/guide/make_convergence.py "
        f"--part table`` ({total / 60:.0f} min):",
        "",
        f"``{machine}``",
        "",
        f"Convergence in n: {', '.join(counts)}, {periods} periods each "
        f"(lambda_1 after {periods // 10} T), the same seeded starts at every n ("
        + results[0].split()[1].starts
        + ").  Regular runs: lambda_1 <= 3 ln t / t over the "
        f"{periods - periods // 10} periods after the transient "
        f"({threshold(periods - periods // 10):.3f}).",
        "",
    ]
    lines += _table(
        "soft walls against the rigid limit (mean +- standard error)",
        ["beta", "quantity"] + [f"n = {n}" for n in f["ns"]] + ["rigid"],
        conv_rows,
    )
    lines += _table(
        "observed rate: abs(q(n) - q(oo)) ~ C n^-p, fitted over the n whose difference exceeds "
        "two standard errors",
        ["beta", "quantity", "p (fit range)", f"p from n >= {TAIL}"],
        rate_rows,
    )
    (out / "convergence_n.inc").write_text("\n".join(lines))
    print(f"wrote {out / 'convergence_n.png'}, {out / 'convergence_n.inc'}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="tiny ensembles (seconds)")
    ap.add_argument("--part", choices=("chart", "table", "all"), default="all",
                    help="the lambda_1(beta) chart, the table in n, or both")  # fmt: skip
    ap.add_argument("--out", help="directory for the PNGs and the .inc (default: this folder)")
    ap.add_argument("--cache", help="keep each well's ensembles in DIR (rerun: taken from it)")
    args = ap.parse_args()
    f = QUICK if args.quick else FULL
    out = Path(args.out) if args.out else (None if args.quick else HERE)
    machine = describe()
    print(machine, flush=True)
    if args.part in ("chart", "all"):
        chart_part(f, out, machine)
    if args.part in ("table", "all"):
        table_part(f, out, machine, Path(args.cache) if args.cache else None)


if __name__ == "__main__":
    main()
