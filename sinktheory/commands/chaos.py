"""``sinktheory chaos``: Lyapunov exponents, GALI/SALI, MEGNO and the transverse exponent.

The runs are those ``sinktheory simulate`` starts for the same options (same seed, same
positions); exponents are per unit time (the container period is T = 2 pi), each with its
ensemble mean and standard error std(ddof=1)/sqrt(R) (none from a single run: the rule of
:mod:`sinktheory.runstats`).
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from ..integrators import DEFAULT_SCHEME, SCHEMES
from ..model import RunSettings, Sink
from ..runstats import plus_minus
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_sink_arguments,
    add_well_arguments,
    add_work_limit,
    number,
    png_path,
    rigid_limit,
    sink_well_from_args,
    well_text,
)

__all__ = ["HELP", "NAME"]

NAME = "chaos"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser, rigid=True, well_file=True)
    add_sink_arguments(parser)
    c = parser.add_argument_group("indicators (lambda_1 is always computed)")
    c.add_argument(
        "--spectrum",
        nargs="?",
        const="full",
        choices=("full", "half"),
        help="the Lyapunov spectrum (QR): all 2D exponents (full, the default), or the D "
        "largest and the rest by symplectic pairing (half: half the cost)",
    )
    c.add_argument(
        "--gali", type=number, default=0, metavar="K", help="GALI_K (K >= 2; 2 adds SALI)"
    )
    c.add_argument("--megno", action="store_true", help="MEGNO Y(t) and its time average")
    c.add_argument(
        "--transverse", action="store_true", help="transverse exponent of the invariant y = 0"
    )
    c.add_argument(
        "--transient",
        type=number,
        default=0,
        metavar="P",
        help="periods left out of lambda_1 and the transverse exponent (their growth rates "
        "from then on; default 0)",
    )
    i = parser.add_argument_group("integrator")
    i.add_argument(
        "--scheme",
        default=DEFAULT_SCHEME,
        help=f"splitting scheme: one of {', '.join(SCHEMES)} (default {DEFAULT_SCHEME})",
    )
    i.add_argument(
        "--tol",
        type=number,
        default=None,
        help="relative energy error the step is chosen for (default 1e-8)",
    )
    i.add_argument("--dt", type=number, default=None, help="step, overriding --tol")
    i.add_argument(
        "--renorm",
        type=number,
        default=0,
        help="steps between renormalisations inside a period (default 0: once per period)",
    )
    o = parser.add_argument_group("output")
    o.add_argument("--plot", help="draw the convergence of the exponents to FILE.png")
    o.add_argument("--quiet", action="store_true", help="no progress bar")
    add_json(parser)
    add_work_limit(parser)


def _fmt(mean, se) -> str:
    return plus_minus(mean, se)


def run(args: argparse.Namespace) -> Output:
    plot = png_path("plot", args.plot)
    unsupported = {
        "--spectrum": args.spectrum, "--gali": args.gali, "--megno": args.megno,
        "--transverse": args.transverse, "--tol": args.tol, "--dt": args.dt,
        "--renorm": args.renorm, "--scheme": None if args.scheme == DEFAULT_SCHEME else args.scheme,
    }  # fmt: skip
    if args.well is None and rigid_limit(args, unsupported):
        return _rigid(args, plot)
    from ..chaos import chaos

    sink = Sink(sink_well_from_args(args), particles=args.particles, mass=args.mass)
    settings = RunSettings(
        container_energy=args.container_energy, runs=args.runs, periods=args.periods,
        seed=args.seed,
    )  # fmt: skip
    result = chaos(
        sink,
        settings,
        spectrum=args.spectrum or False,
        gali=args.gali,
        megno=args.megno,
        transverse=args.transverse,
        scheme=args.scheme,
        dt=args.dt,
        tol=args.tol,
        renorm=args.renorm,
        progress=not args.quiet,
        transient=args.transient,
    )
    data = result.as_dict()
    w = sink.well
    p = result.parameters
    lines = [
        f"{w.shape} well {well_text(w)}; k={sink.particles}, m={sink.mass:g}; "
        f"{settings.runs} run(s) x {settings.periods} period(s), {p['scheme']}, "
        f"dt = {p['dt']:.6g}; max relative energy error "
        f"{data['max_relative_energy_error']:.3g}",
        "exponents per unit time (x T = 2 pi for per period); mean +- standard error"
        + (
            f"; lambda_1 and the transverse exponent from t = {args.transient:g} T on"
            if args.transient
            else ""
        ),  # fmt: skip
        f"lambda_1 = {_fmt(*result.mean('lambda1'))}",
        "lambda_1 " + result.split().text(),
    ]
    if result.spectrum is not None:
        m, se = result.mean("spectrum")
        lines.append("spectrum: " + ", ".join(_fmt(a, b) for a, b in zip(m, se, strict=True)))
        if result.spectrum_paired:
            lines.append("lower half by the symplectic pairing lambda_(2D+1-i) = -lambda_i")
        else:
            lines.append(
                "pairs lambda_i + lambda_(2D+1-i): largest |sum| "
                f"{np.abs(result.pair_sums).max():.2g} (1/t = {1 / result.duration:.2g})"
            )
    if result.gali is not None:
        g = result.gali[:, -1]
        lines.append(
            f"GALI_{result.gali_order}(t_end): median {np.median(g):.3g}, "
            f"{int(np.sum(g < 1e-8))} of {len(g)} run(s) below 1e-8"
        )
        if result.sali is not None:
            lines.append(f"SALI(t_end): median {np.median(result.sali[:, -1]):.3g}")
    if result.megno is not None:
        m = data["mean_megno"]
        lines.append(
            "<Y>(t_end) (time-averaged MEGNO; 2 = quasi-periodic) = "
            + plus_minus(m["mean"], m["stderr"])
        )
    if result.transverse is not None:
        lines.append(f"transverse exponent of y = 0: {_fmt(*result.mean('transverse'))}")
    writers = {}
    if plot is not None:

        def draw(path):
            from ..plot.chaos import plot_convergence
            from ..plot.simulate import well_title

            plot_convergence(
                result,
                path,
                title=f"{w.shape}, {well_title(w)}, k={sink.particles}, m={sink.mass:g}; "
                f"{settings.runs} run(s)",
            )

        writers[plot] = draw
    data["period"] = 2 * math.pi
    return Output(data, "\n".join(lines), writers)


def _rigid(args: argparse.Namespace, plot) -> Output:
    """--n inf: lambda_1 of the rigid billiard (moving container, two nearby trajectories),
    the runs started as for a finite n; gamma plays no part."""
    from ..billiard import billiard
    from ..billiard.convergence import lambda_after
    from ..chaos.verdicts import split
    from ..runstats import ensemble_mean
    from ..validation import positive

    positive("gamma", 1.0 if args.gamma is None else args.gamma)
    shape = "flat" if args.shape is None else args.shape  # None: the default (--well may stand in)
    settings = RunSettings(
        container_energy=args.container_energy, runs=args.runs, periods=args.periods,
        seed=args.seed,
    )  # fmt: skip
    result = billiard(
        shape, args.alpha, args.beta, particles=args.particles, mass=args.mass,
        settings=settings, lyapunov=True,
    )  # fmt: skip
    lam = lambda_after(result, args.transient)
    data = result.as_dict()
    m, se = ensemble_mean(lam[:, None])
    groups = split(lam, settings.periods - args.transient, result.starts)
    data |= {
        "split_lambda1": groups.as_dict(),
        "n": "inf", "rigid": True, "lambda1": lam.tolist(),
        "transient_time": args.transient * 2 * math.pi,
        "mean_lambda1": {"mean": float(m[0]), "stderr": float(se[0])},
    }  # fmt: skip
    t = result.table
    lines = [
        f"{shape} well alpha={args.alpha:g} beta={args.beta:g} n=inf: the rigid billiard "
        f"(area {t.area:.6g}, perimeter {t.perimeter:.6g}); k={args.particles}, "
        f"m={args.mass:g}; {settings.runs} run(s) x {settings.periods} period(s), "
        f"{int(result.collisions.sum())} impacts; max relative energy error "
        f"{result.max_relative_energy_error:.3g}",
        f"exponent per unit time (x T = 2 pi for per period), {result.lyapunov_method}; mean "
        "+- standard error" + (f"; from t = {args.transient:g} T on" if args.transient else ""),
        f"lambda_1 = {_fmt(m[0], se[0])}",
        "lambda_1 " + groups.text(),
    ]
    writers = {}
    if plot is not None:

        def draw(path):
            from ..plot.billiard import billiard_figure

            billiard_figure(result).savefig(path, dpi=120)

        writers[plot] = draw
    data["period"] = 2 * math.pi
    return Output(data, "\n".join(lines), writers)
