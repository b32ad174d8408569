"""``sinktheory relaxation``: how fast the container's energy settles at the law, predicted
(and measured when asked)."""

from __future__ import annotations

import argparse

from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_particle_arguments,
    add_well_arguments,
    number,
    png_path,
    rigid_limit,
    well_from_args,
)

__all__ = ["NO_WELL", "HELP", "NAME", "TABLE_ROWS"]

NAME = "relaxation"
HELP = HELPS[NAME]
#: Why ``--well FILE`` is refused (see :func:`sinktheory.cli.main`).
NO_WELL = "the relaxation model reads a registered shape's alpha, beta and n"
#: Rows of the printed curve.
TABLE_ROWS = 10


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser, rigid=True)
    g = add_particle_arguments(parser, "sink and start")
    g.add_argument(
        "--fraction",
        type=number,
        default=0.05,
        help="settled when <E_c> is within this fraction of the law's mean, in (0, 1) "
        "(default 0.05)",
    )
    g.add_argument(
        "--periods",
        type=number,
        default=None,
        help="length of the printed curve, periods (default: 1.5 x the settling interval's end)",
    )
    g.add_argument("--seed", type=number, default=0, help="random seed, integer >= 0 (default 0)")
    g.add_argument(
        "--tol",
        type=number,
        default=None,
        help="relative total-energy error of the simulator (default 1e-6; not with --n inf, "
        "whose billiards are exact)",
    )
    m = parser.add_argument_group("the model's slow mode (short runs started on the shell)")
    m.add_argument(
        "--shell-energies", type=number, default=12, help="starting energies >= 3 (default 12)"
    )
    m.add_argument(
        "--shell-runs", type=number, default=100, help="runs per starting energy >= 4 (default 100)"
    )
    m.add_argument(
        "--lag",
        type=number,
        default=128,
        help="largest lag in periods >= 8, best near the relaxation time (default 128)",
    )
    parser.add_argument(
        "--measure",
        type=number,
        nargs=2,
        metavar=("RUNS", "PERIODS"),
        help="also simulate RUNS runs x PERIODS periods from the start and measure the settling",
    )
    parser.add_argument(
        "--resamples",
        type=number,
        default=199,
        help="bootstrap resamples of the drift and of the measured runs, >= 20 (default 199)",
    )
    parser.add_argument("--plot", metavar="FILE.png", help="draw predicted (and measured) <E_c>(t)")
    add_json(parser)


def _interval(low: float, high: float) -> str:
    import math

    return f"{low:.0f}-" + (f"{high:.0f}" if math.isfinite(high) else "inf")


def _measure_check(args: argparse.Namespace, sink, rigid: bool = False) -> None:
    """--measure RUNS PERIODS checked before the prediction's runs (for ``rigid`` walls
    only the start box, the rigid billiard's one requirement of the well)."""
    from .. import validation as v
    from ..model import RunSettings

    v.positive_int("measure", args.measure[0], minimum=3)
    v.positive_int("measure", args.measure[1], minimum=24)
    settings = RunSettings(container_energy=args.container_energy, runs=args.measure[0],
                           periods=args.measure[1], seed=args.seed)  # fmt: skip
    if rigid:
        settings.check_box(sink.well)
    else:
        settings.check(sink)


def _predicted(args: argparse.Namespace):
    """(prediction, measured relaxation or None, one line on the measured runs or None,
    the header's description of the well) for soft or rigid (--n inf) walls."""
    from ..model import Sink, Well

    reading = dict(fraction=args.fraction, periods=args.periods,
                   shell_energies=args.shell_energies, shell_runs=args.shell_runs, lag=args.lag,
                   seed=args.seed, resamples=args.resamples)  # fmt: skip
    if rigid_limit(args, {"--tol": args.tol}):
        from ..billiard.relaxation import measure_rigid_settling, predict_rigid_relaxation
        from ..validation import positive

        positive("gamma", args.gamma)  # plays no part with rigid walls
        sink = Sink(Well(args.alpha, args.beta, 1, shape=args.shape), particles=args.particles,
                    mass=args.mass)  # fmt: skip
        if args.measure is not None:
            _measure_check(args, sink, rigid=True)
        table = (args.shape, args.alpha, args.beta)
        p = predict_rigid_relaxation(
            *table,
            particles=args.particles,
            mass=args.mass,
            container_energy=args.container_energy,
            **reading,
        )
        described = (f"{args.shape} well alpha={sink.well.alpha:g} beta={sink.well.beta:g} "
                     "n=inf (rigid walls, exact billiards)")  # fmt: skip
        if args.measure is None:
            return p, None, None, described
        r, runs = measure_rigid_settling(*table, args.measure, particles=args.particles,
                                         mass=args.mass, container_energy=args.container_energy,
                                         fraction=args.fraction, seed=args.seed,
                                         resamples=args.resamples)  # fmt: skip
        note = (f"{runs.container_energy.shape[0]} rigid billiards x {args.measure[1]} periods "
                f"from the paper's start (seed {args.seed}), exact flights: max relative energy "
                f"error {runs.max_relative_energy_error:.2g}")  # fmt: skip
        return p, r, note, described
    from ..equilibrium.prediction import measure_settling, predict_relaxation

    tol = 1e-6 if args.tol is None else args.tol
    sink = Sink(well_from_args(args), particles=args.particles, mass=args.mass)
    if args.measure is not None:
        _measure_check(args, sink)
    p = predict_relaxation(sink, args.container_energy, tol=tol, **reading)
    w = sink.well
    described = f"{w.shape} well alpha={w.alpha:g} beta={w.beta:g} n={w.n} gamma={w.gamma:g}"
    if args.measure is None:
        return p, None, None, described
    r, sim = measure_settling(sink, args.container_energy, args.measure, fraction=args.fraction,
                              seed=args.seed, tol=tol, resamples=args.resamples)  # fmt: skip
    return p, r, sim.message, described


def run(args: argparse.Namespace) -> Output:
    import numpy as np

    plot = png_path("plot", args.plot)
    p, measured, note, described = _predicted(args)
    level = f"{100 * p.level:g} %"
    lines = [
        f"relaxation of E_c: {described}, k={p.particles}, m={p.mass:g}, "
        f"E0={p.container_energy:g} (total E={p.total_energy:.6g}), particles at rest",
        f"  law's mean <E_c> {p.target:.6g}; settled when within {100 * p.fraction:g} % of it",
        f"  predicted: settles at {p.settle_time:.0f} periods ({level} interval "
        f"{_interval(p.settle_low, p.settle_high)}, statistical), relaxation time "
        f"{p.rate_time:.0f} ({_interval(p.rate_low, p.rate_high)}), fraction seen by E_c "
        f"{p.visible:.2f} ± {p.visible_stderr:.2f}",
        f"    model: {p.model}",
        "    ln lambda at lags "
        + ", ".join(
            f"{t}: {x:.3f} ± {e:.3f}"
            for t, x, e in zip(p.lags, p.log_lambda, p.log_lambda_stderr, strict=True)
        )  # fmt: skip
        + f"; from {p.coefficients}",
    ]
    if p.extrapolated:
        lines.append("    the relaxation time exceeds 4 times the largest lag: such slow "
                     "relaxations have come out short by up to a factor 2; measure with --measure "
                     "RUNS PERIODS")  # fmt: skip
    data = {"well": described, "prediction": p.as_dict(), "measured": None}
    if measured is not None:
        flag = " (beyond the record: extrapolated, run longer)" if measured.extrapolated else ""
        lines += [
            f"  measured: settles at {measured.settle_time:.0f} periods ({level} interval "
            f"{_interval(measured.settle_low, measured.settle_high)}){flag}, tail time "
            f"{measured.rate_time:.0f} ± {measured.rate_stderr:.0f}, late mean - law "
            f"{measured.late_z:+.1f} standard errors",
            f"    {note}",
        ]
        data["measured"] = measured.as_dict()
        data["simulation"] = note
    lines.append("  t (periods)  predicted <E_c> (band)      spread"
                 + ("   measured <E_c> ± se" if measured is not None else ""))  # fmt: skip
    for t in np.linspace(0, p.times[-1], TABLE_ROWS + 1):
        i = int(np.argmin(np.abs(p.times - t)))
        row = (f"  {p.times[i]:<11.0f}  {p.means[i]:.4f} ({p.low[i]:.4f}-{p.high[i]:.4f})"
               f"  {p.spread[i]:.4f}")  # fmt: skip
        if measured is not None and measured.times[0] <= p.times[i] <= measured.times[-1]:
            w = int(np.argmin(np.abs(measured.times - p.times[i])))
            row += f"   {measured.means[w]:.4f} ± {measured.stderr[w]:.4f}"
        lines.append(row)
    out = Output(data, "\n".join(lines))
    if plot is not None:
        from ..plot.equilibrium import plot_relaxation

        fig = plot_relaxation(p, measured)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        data["plot"] = str(plot)
    return out
