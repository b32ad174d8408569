"""``sinktheory nnm``: normal modes of the container and its particles (issue 15).

Continues the synchronous normal mode of the container + k particles on the plane
y_j = 0 (both shapes) by shooting on the engine's exact tangent map, with all Floquet
multipliers (in-plane and transverse) and located folds, period doublings and
symmetry-breaking points.

* ``--continue-in energy``: the branch through ``--total-energy`` in both directions over
  ``--interval LO HI`` (energies); ``--plot`` draws the frequency-energy plot with stability.
* ``--continue-in beta``: at fixed total energy (default gamma/(2n) per particle, the
  amplitude A0 = 1 of the paper's fixed-container mode), from ``--beta`` over
  ``--interval LO HI`` (betas); each point carries the transverse half-period half-trace
  phi_T/2; ``--plot`` draws it beside the paper's fixed-container phi_T/2(beta) (Fig. 7).
* ``--continue-in beta --betas COUNT``: the chaos map's setting instead (total energy
  default 0.5, the container started at X = 1): the mode reached from the container's
  low-energy mode (:mod:`sinktheory.nnm.agreement`), corrected on COUNT betas of
  ``--interval``, a chaos map (``--runs``, ``--periods``) on the same betas, and the share of
  betas where the coupled mode's transverse stability and the fixed-container Floquet
  theory each predict the chaos map's verdict; ``--plot`` adds lambda_1(beta) below.
"""

from __future__ import annotations

import argparse
import math

from ..errors import ParameterError
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_well_arguments,
    add_work_limit,
    number,
    parameters_text,
    png_path,
    user_well_from_args,
    well_from_args,
)

__all__ = ["HELP", "NAME"]

NAME = "nnm"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser, well_file=True)
    g = parser.add_argument_group("normal mode")
    g.add_argument("--particles", type=number, default=1, help="k, integer >= 1 (default 1)")
    g.add_argument(
        "--mass", type=number, default=0.2, help="total particle mass m > 0 (default 0.2)"
    )
    g.add_argument(
        "--mode",
        default=None,
        help="container or particle: the start guess (default: container for energy, "
        "particle for beta)",
    )
    g.add_argument(
        "--continue-in",
        required=True,
        help="energy (the total energy) or beta (or alpha, gamma: any well parameter at "
        "fixed total energy; with --well, any of the well's own parameters)",
    )
    g.add_argument("--total-energy", type=number, help="total energy H of the start orbit")
    g.add_argument(
        "--interval",
        nargs=2,
        type=number,
        metavar=("LO", "HI"),
        help="the continuation stays in [LO, HI]",
    )
    g.add_argument("--steps", type=number, default=400, help="steps per period, even (400)")
    g.add_argument("--points", type=number, default=120, help="points per direction (120)")
    g.add_argument("--ds", type=number, default=0.1, help="first arclength step (0.1)")
    g.add_argument("--plot", metavar="FILE.png", help="frequency-energy / transverse chart")
    g.add_argument(
        "--betas",
        type=number,
        metavar="COUNT",
        help="with --continue-in beta: score the transverse stability on COUNT betas of "
        "--interval against a chaos map (total energy default 0.5)",
    )
    g.add_argument("--runs", type=number, default=8, help="chaos map runs per beta (8)")
    g.add_argument("--periods", type=number, default=200, help="chaos map periods (200)")
    add_json(parser)
    add_work_limit(parser)


def _check(args, user=None) -> None:
    if user is not None:  # a user's well: energy or one of its own parameters
        names = ("energy", *user.parameter_names)
        if args.continue_in not in names:
            raise ParameterError("continue_in", args.continue_in, f"one of {', '.join(names)}")
        if args.continue_in != "energy" and (args.interval is None or args.total_energy is None):
            raise ParameterError("interval" if args.interval is None else "total_energy", None,
                                 f"given with --well and --continue-in {args.continue_in} (a "
                                 "well's own parameter has no default range)")  # fmt: skip
        if args.betas is not None:
            raise ParameterError("betas", args.betas, "left out with --well (the chart is "
                                 "scored against a chaos map of a registered shape)")  # fmt: skip
    elif args.continue_in not in ("energy", "alpha", "beta", "gamma"):
        raise ParameterError("continue_in", args.continue_in, "energy, beta, alpha or gamma")
    if args.mode not in (None, "container", "particle"):
        raise ParameterError("mode", args.mode, "container or particle")
    from ..nnm.continuation import check_ds
    from ..nnm.shooting import MAX_SHOOT_STEPS

    allowed = f"an even integer in [8, {MAX_SHOOT_STEPS}]"
    if not isinstance(args.steps, int) or not 8 <= args.steps <= MAX_SHOOT_STEPS or args.steps % 2:
        raise ParameterError("steps", args.steps, allowed)
    if not isinstance(args.points, int) or not 2 <= args.points <= 10_000:
        raise ParameterError("points", args.points, "an integer in [2, 10000]")
    check_ds(args.ds)
    if args.betas is not None:
        if args.continue_in != "beta":
            raise ParameterError("betas", args.betas, "only with --continue-in beta")
        if not isinstance(args.betas, int) or not 2 <= args.betas <= 1000:
            raise ParameterError("betas", args.betas, "an integer in [2, 1000]")
    for name in ("runs", "periods"):
        v = getattr(args, name)
        if not isinstance(v, int) or not 2 <= v <= 100_000:
            raise ParameterError(name, v, "an integer in [2, 100000]")
    if args.total_energy is not None and not (
        math.isfinite(args.total_energy) and args.total_energy > 0
    ):
        raise ParameterError("total_energy", args.total_energy, "a finite positive energy")
    if args.interval is not None:
        lo, hi = args.interval
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ParameterError("interval", args.interval, "two finite numbers LO < HI")
        if args.continue_in == "energy" and lo <= 0:
            raise ParameterError("interval", args.interval, "positive energies")


def run(args: argparse.Namespace) -> Output:
    from ..model import Sink

    user = user_well_from_args(args)
    _check(args, None if user is None else user[0])
    if user is not None:  # refused when y = 0 is not invariant, with the reason
        from ..nnm.modes import check_user_well
        from ..wellat import WellAt

        well = WellAt(user[0], **user[1])
        check_user_well(well)
    else:
        well = well_from_args(args)
    sink = Sink(well, particles=args.particles, mass=args.mass)
    plot = png_path("plot", args.plot)
    param = args.continue_in
    mode = args.mode or ("container" if param == "energy" else "particle")
    if param == "energy":
        energy = args.total_energy if args.total_energy is not None else 1e-3
        lo, hi = args.interval if args.interval is not None else (1e-4, 10.0)
        if not lo <= energy <= hi:
            raise ParameterError("total_energy", energy, f"inside --interval [{lo:g}, {hi:g}]")
    else:
        energy = args.total_energy  # given with --well (see _check)
        if energy is None:
            energy = 0.5 if args.betas else sink.particles * well.gamma / (2 * well.n)
        if user is not None:  # --interval is given (see _check)
            start, (lo, hi) = well.parameters[param], args.interval
        else:
            start = getattr(well, param)
            default = {"beta": (-1.0, well.alpha - 0.02), "alpha": (well.beta + 0.02, 2.0)}
            lo, hi = args.interval if args.interval is not None else default.get(param, (0.1, 10.0))
        if not lo <= start <= hi:
            raise ParameterError(param, start, f"inside --interval [{lo:g}, {hi:g}]")
    if args.betas:
        return _agreement(args, sink, energy, lo, hi, plot)
    from ..nnm.continuation import continue_both

    result = continue_both(
        sink,
        mode,
        continue_in=param,
        total_energy=energy,
        interval=(lo, hi),
        steps=args.steps,
        points=args.points,
        ds=args.ds,
        half_traces=param != "energy",
    )
    out = _report(result, sink, mode, param)
    if plot is not None:
        from ..plot import nnm as nplot

        if param == "energy":
            fig = nplot.plot_frequency_energy([result])
        else:
            scan = _fixed_scan(well, result) if param == "beta" and user is None else None
            fig = nplot.plot_transverse(result, scan)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        out.data["plot"] = str(plot)
    return out


def _fixed_scan(well, result):
    """The paper's fixed-container chart over the branch's betas."""
    from ..floquet import model_problem, scan

    problem = model_problem(well.alpha, well.n, gamma=well.gamma, shape=well.shape)
    return scan(problem, float(result.value.min()), float(result.value.max()), 200)


def _agreement(args, sink, energy, lo, hi, plot) -> Output:
    """--betas: the chart on a beta grid scored against a chaos map."""
    from ..nnm.agreement import agreement_report, transverse_chart
    from ..sweep.chaosmap import beta_grid, chaos_map

    well = sink.well
    betas = beta_grid([(lo, hi)], args.betas)
    chart = transverse_chart(sink, energy, betas, steps=args.steps, ds=args.ds)
    chaos = chaos_map(well.alpha, well.n, betas, shape=well.shape, particles=sink.particles,
                      mass=sink.mass, container_energy=energy, runs=args.runs,
                      periods=args.periods)  # fmt: skip
    report = agreement_report(sink, energy, betas, chaos=chaos, chart=chart)
    out = _report(chart.branch, sink, "coupled", "beta")
    out.data["agreement"] = report
    out.text += "\n  " + report["statement"]
    if plot is not None:
        from ..plot import nnm as nplot

        fig = nplot.plot_transverse(
            chart.branch,
            _fixed_scan(well, chart.branch),
            chaos=(
                betas,
                chaos.lambda1.values,
                r"mean $\lambda_1$ of the chaos map; runs split into regular ($\lambda_1 \leq$ "
                f"{report['threshold']:.3g}) and chaotic at {report['mixed']} of "
                f"{report['betas']} betas",
            ),  # fmt: skip
        )
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        out.data["plot"] = str(plot)
    return out


def _report(result, sink, mode, param) -> Output:
    """JSON data and the text summary of one branch."""
    well = sink.well
    data = result.as_dict()
    ev = ", ".join(f"{e['kind']} at {e['value']:.6g}" for e in result.events) or "none"
    described = (
        parameters_text(well.parameters)
        if hasattr(well, "definition")
        else f"alpha = {well.alpha:g}, beta = {well.beta:g}, n = {well.n}"
    )
    text = (
        f"{mode} mode of {sink.particles} particle(s), {well.shape} well {described}, "
        f"m = {sink.mass:g}; continued in {param} over "
        f"[{result.value.min():.6g}, {result.value.max():.6g}] ({result.points} orbits)\n"
        f"  frequency {result.frequency.min():.6g} .. {result.frequency.max():.6g}; "
        f"stable at {int(result.stable.sum())} of {result.points} points\n"
        f"  events: {ev}\n"
        f"  checks: max trivial-multiplier error {data['max_trivial_error']:.2e}, "
        f"{_sigma_text(data['max_abs_sigma'])}"
    )
    return Output(data, text)


def _sigma_text(largest: float) -> str:
    """The unfolding parameter sigma at the precision it is computed with.

    sigma vanishes exactly for a conservative system; Newton solves it only to its step
    tolerance :data:`~sinktheory.nnm.shooting.XTOL`, so a value below that is printed as
    0 (its digits are round-off), a larger one as it is (a sign of trouble).

    Examples
    --------
    >>> _sigma_text(3.7e-16), _sigma_text(2e-9)
    ('sigma = 0 (to the Newton tolerance 1e-11)', 'max |sigma| 2.00e-09')
    """
    from ..nnm.shooting import XTOL

    if largest < XTOL:
        return f"sigma = 0 (to the Newton tolerance {XTOL:g})"
    return f"max |sigma| {largest:.2e}"
