"""``sinktheory lifetime``: measured return times of the container energy against Kac's
prediction from the equilibrium law, and the runs' distribution against the law."""

from __future__ import annotations

import argparse

from . import HELP as HELPS
from ._common import (
    Output,
    add_fractions_argument,
    add_json,
    add_sink_arguments,
    add_well_arguments,
    add_work_limit,
    number,
    png_path,
    sink_well_from_args,
    well_text,
)

__all__ = ["CHART_PARTICLES", "FRACTIONS", "HELP", "NAME"]

NAME = "lifetime"
HELP = HELPS[NAME]
#: Default fractions f for the sets {E_c >= f E}.
FRACTIONS = (0.2, 0.5, 0.8)
#: Particle numbers of the lifetime chart's predicted lines.
CHART_PARTICLES = (1, 2, 3, 4, 5)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser, well_file=True)
    g = add_sink_arguments(parser, runs_default=8, runs_help="independent runs >= 2 (default 8)")
    g.add_argument(
        "--transient",
        type=number,
        default=None,
        help="periods skipped before sampling (default: a third of --periods)",
    )
    add_fractions_argument(g, FRACTIONS, "of the sets {E_c >= f E}")
    g.add_argument(
        "--tol",
        type=number,
        default=None,
        help="relative total-energy error wanted (default 1e-8; see 'simulate')",
    )
    parser.add_argument(
        "--plot",
        metavar="FILE.png",
        help="lifetime chart: Kac's return time against f for k = 1..5, measured points",
    )
    add_json(parser)
    add_work_limit(parser)


def _pm(value: float, stderr: float) -> str:
    """'value +- error' in 17 characters; says 'not seen' or 'no error' instead of NaN."""
    import math

    if not math.isfinite(value):
        return f"{'not seen':<17s}"
    if not math.isfinite(stderr):
        return f"{value:<8.4g} no error"
    return f"{value:.4g} +- {stderr:.2g}".ljust(17)


def _autocorrelation(c) -> str:
    """The autocorrelation time with its error and the effective samples of a
    :class:`~sinktheory.equilibrium.lifetime.LawComparison` ``c``: never more effective
    samples than samples (a time below 1 gives a lower bound)."""
    import math

    tau = c.autocorrelation_time
    if not math.isfinite(tau):
        return "autocorrelation time not measurable (runs shorter than ~12 of it)"
    text = f"autocorrelation time {_pm(tau, c.autocorrelation_time_stderr).rstrip()} periods"
    if tau < 1:
        return f"{text} (below 1: at least the {c.runs * c.samples} samples taken are effective)"
    return f"{text} (about {c.effective_samples:.3g} effective samples)"


def run(args: argparse.Namespace) -> Output:
    import numpy as np

    from .. import validation as v
    from ..equilibrium import equilibrium_law
    from ..equilibrium.law import check_fractions
    from ..equilibrium.lifetime import measure_lifetimes
    from ..model import RunSettings, Sink
    from ..runstats import check_runs

    sink = Sink(sink_well_from_args(args), particles=args.particles, mass=args.mass)
    settings = RunSettings(
        container_energy=args.container_energy, runs=args.runs, periods=args.periods,
        seed=args.seed,
    )  # fmt: skip
    check_runs("runs", settings.runs)
    # 4 periods after the transient; the default one, periods // 3, leaves them from 5 on
    periods = v.positive_int("periods", settings.periods, minimum=4 + (args.transient is None))
    transient = periods // 3 if args.transient is None else args.transient
    v.positive_int("transient", transient, minimum=0, maximum=periods - 4)
    fractions = check_fractions(args.fractions)
    plot = png_path("plot", args.plot)
    settings.check(sink)
    c, sim = measure_lifetimes(
        sink, settings, transient=transient, fractions=fractions, tol=args.tol
    )
    law = c.law
    data = c.as_dict()
    del data["law"]["log_density"]
    data["simulation"] = sim.message
    lines = [
        f"{sink.well.shape} well {well_text(sink.well)}, k={law.particles}, m={sink.mass:g}, "
        f"E0={settings.container_energy:g} "
        f"(total E={law.total_energy:.6g})",
        f"  {sim.message}",
        f"  kept {c.runs} runs x {c.samples} periods after {c.transient}; " + _autocorrelation(c),
        f"  <E_c>  measured {c.mean:.6g} +- {c.mean_stderr:.2g}, law {law.mean:.6g}, "
        f"homogeneous estimate {law.homogeneous_mean:.6g}",
        f"  KS distance to the law {c.ks_distance:.3g}, run-bootstrap p-value {c.ks_pvalue:.3g}",
        "  f      P law       occupation        return time: Kac   measured          "
        "(seen whole)       entry interval: measured  (sojourn / P)",
    ]
    for i, f in enumerate(c.fractions):
        row = (
            f"  {f:<5g}  {c.tails[i]:<10.4g}"
            f"  {_pm(c.occupation[i], c.occupation_stderr[i])}"
            f"  {c.kac_periods[i]:<9.4g}  {_pm(c.return_time[i], c.return_time_stderr[i])}"
            f"  {_pm(c.observed_return[i], c.observed_return_stderr[i])}"
            f"  {_pm(c.entry_interval[i], c.entry_interval_stderr[i])}"
            + ("" if np.isnan(c.sojourn[i]) else f"  ({c.entry_interval_predicted[i]:.4g})")
        )
        lines.append(row.rstrip())
    out = Output(data, "\n".join(lines))
    if plot is not None:
        from ..plot.equilibrium import plot_lifetimes

        grid = np.linspace(0.05, 0.95, 19)
        ks = sorted({*CHART_PARTICLES, sink.particles})
        energy = law.total_energy
        predicted = [
            equilibrium_law(Sink(sink.well, particles=k, mass=sink.mass), energy).kac_periods(grid)
            for k in ks
        ]
        measured = [
            (sink.particles, f, c.return_time[i], c.return_time_stderr[i])
            for i, f in enumerate(c.fractions)
            if np.isfinite(c.return_time[i])
        ]
        fig = plot_lifetimes(grid, ks, predicted, measured)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        data["plot"] = str(plot)
    return out
