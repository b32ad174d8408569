"""``sinktheory compare``: the 1-D absorbers and the 2-D sink side by side after an impulse.

For each attachment (``--attachments nes,impact,well``; the well once per ``--shapes`` and
``--particles`` value, or a user's well file ``--well FILE`` once per ``--particles``: the
1-D absorbers stay the line of a registered shape) at the same total mass ``--mass`` and
dashpot ``--damping`` and for ``--energies LO HI COUNT`` log-spaced initial container
energies, ``--runs`` seeded impulsive starts run for ``--periods`` periods
(:func:`sinktheory.compare.compare`).
Reported: the fraction of the initial energy dissipated in the window (mean +- standard
error) and the time to dissipate 90 % (over the runs that reached it).  ``--plot`` draws
both against the energy; ``--wavelet-plot`` the Morlet wavelet map of the container of run 0
of every attachment at ``--wavelet-energy`` with its ridge over the normal modes'
frequency-energy curves.  Bad input: one line on stderr, exit status 2, nothing written.
"""

from __future__ import annotations

import argparse
import math

from ..errors import ParameterError
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_well_file,
    add_work_limit,
    number,
    parameters_text,
    png_path,
    user_well_from_args,
)

__all__ = ["HELP", "KINDS", "NAME"]

NAME = "compare"
HELP = HELPS[NAME]
KINDS = ("nes", "impact", "well")  # sinktheory.attachments.KINDS (kept light here)


def _words(text: str) -> list[str]:
    return [w.strip() for w in str(text).split(",")]


def _ints(name: str, text: str) -> list:
    out = []
    for w in _words(text):
        try:
            out.append(int(w))
        except ValueError:
            raise ParameterError(name, text, "comma-separated integers >= 1") from None
    return out


def add_arguments(parser: argparse.ArgumentParser) -> None:
    g = parser.add_argument_group("attachments (equal total mass and dashpot)")
    g.add_argument(
        "--attachments",
        default=",".join(KINDS),
        help=f"comma-separated, any of {', '.join(KINDS)} (default all)",
    )
    g.add_argument("--mass", type=number, default=0.2, help="total particle mass m > 0 (0.2)")
    g.add_argument(
        "--damping",
        type=number,
        required=True,
        help="total dashpot coefficient c >= 0 on the particles' relative velocity (c/k each)",
    )
    g.add_argument(
        "--alpha", type=number, default=0.5,
        help="alpha > 0 (default 0.5; with --well, of the NES and vibro-impact line)",
    )  # fmt: skip
    g.add_argument(
        "--beta", type=number, default=0.3, help="beta < alpha; alpha - beta is the clearance (0.3)"
    )
    g.add_argument(
        "--n", type=number, default=None, help="wall stiffness of the well (default 4; not with "
        "--well)",
    )  # fmt: skip
    g.add_argument(
        "--nes-n", type=number, default=2, help="wall exponent of the NES (default 2: cubic)"
    )
    g.add_argument(
        "--shapes", default=None,
        help="shapes of the well, comma-separated (default flat; not with --well)",
    )  # fmt: skip
    add_well_file(g)
    g.add_argument(
        "--particles", default="1,5", help="particle counts k of the well, comma-separated (1,5)"
    )
    r = parser.add_argument_group("impulses and runs")
    r.add_argument(
        "--energies",
        type=number,
        nargs=3,
        default=[0.005, 0.5, 7],
        metavar=("LO", "HI", "COUNT"),
        help="COUNT log-spaced initial container energies from LO to HI (0.005 0.5 7)",
    )
    r.add_argument("--runs", type=number, default=8, help="seeded runs per point, >= 2 (8)")
    r.add_argument("--periods", type=number, default=200, help="window in periods T (200)")
    r.add_argument("--seed", type=number, default=0, help="random seed >= 0 (default 0)")
    r.add_argument(
        "--samples-per-period",
        type=number,
        default=16,
        help="samples per period of the records (16)",
    )
    r.add_argument("--tol", type=number, default=None, help="energy tolerance (default 1e-8)")
    o = parser.add_argument_group("output")
    o.add_argument("--plot", default=None, metavar="FILE", help="efficiency and 90 %% time (PNG)")
    o.add_argument(
        "--wavelet-plot", default=None, metavar="FILE", help="wavelet maps over the NNMs (PNG)"
    )
    o.add_argument(
        "--wavelet-energy",
        type=number,
        default=None,
        help="impulse energy of the wavelet maps (default the highest of --energies)",
    )
    o.add_argument("--quiet", action="store_true", help="no progress bar")
    add_json(parser)
    add_work_limit(parser)


def run(args: argparse.Namespace) -> Output:
    plot = png_path("plot", args.plot)
    wavelet = png_path("wavelet_plot", args.wavelet_plot)
    from .. import validation as v
    from ..compare.efficiency import attachments_of, compare, energies_of
    from ..wellat import WellAt

    if args.well is not None:
        for name in ("shapes", "n"):
            if getattr(args, name) is not None:
                raise ParameterError("well", args.well, f"given without --{name} (the well file "
                                     "defines the well)")  # fmt: skip
        if wavelet is not None:
            raise ParameterError("wavelet_plot", args.wavelet_plot, "left out with --well",
                                 why="the backbones are normal modes of a registered shape's "
                                 "well")  # fmt: skip
    # --alpha and --beta stay: the 1-D attachments' line (--well-param alone is refused)
    user = user_well_from_args(argparse.Namespace(well=args.well, well_param=args.well_param))
    well = None if user is None else WellAt(user[0], **user[1])
    atts = attachments_of(
        _words(args.attachments),
        shapes=None if args.shapes is None else _words(args.shapes),
        particles=_ints("particles", args.particles),
        alpha=args.alpha,
        beta=args.beta,
        n=args.n,
        nes_n=args.nes_n,
        mass=args.mass,
        well=well,
    )
    energies = energies_of(*args.energies)
    if wavelet is not None and not (
        isinstance(args.samples_per_period, int) and args.samples_per_period >= 6
    ):
        # the map reaches omega = 3: the Nyquist frequency samples / 2 must too
        raise ParameterError(
            "samples_per_period", args.samples_per_period, "an integer >= 6 with --wavelet-plot"
        )
    if wavelet is None and args.wavelet_energy is not None:
        raise ParameterError(
            "wavelet_energy", args.wavelet_energy, "given with --wavelet-plot only"
        )
    if args.wavelet_energy is not None:  # refused before the comparison runs
        v.positive("wavelet_energy", args.wavelet_energy)
    result = compare(
        atts,
        energies,
        damping=args.damping,
        periods=args.periods,
        runs=args.runs,
        seed=args.seed,
        samples_per_period=args.samples_per_period,
        tol=args.tol,
        progress=not args.quiet,
    )
    data = result.as_dict()
    data["half_dissipated"] = {name: result.span(i) for i, name in enumerate(result.attachment)}
    writers = {}
    if plot is not None:
        from ..plot.compare import plot_comparison

        fig = plot_comparison(result)
        writers[plot] = lambda path: fig.savefig(path, dpi=110)
    if wavelet is not None:
        fig_w, notes = _transfer_figure(atts, args, energies)
        data["wavelet_notes"] = notes
        writers[wavelet] = lambda path: fig_w.savefig(path, dpi=90)
    return Output(data, _text(result, data["half_dissipated"]), writers)


def _transfer_figure(atts, args, energies):
    """The wavelet maps of run 0 of each attachment over their backbones
    (:func:`sinktheory.compare.transfer.transfer_maps`)."""
    from ..compare.transfer import transfer_maps
    from ..plot.compare import plot_transfer

    maps, bones, notes = transfer_maps(atts, args.wavelet_energy, energies=energies,
                                       damping=args.damping, periods=args.periods,
                                       seed=args.seed, samples_per_period=args.samples_per_period,
                                       tol=args.tol)  # fmt: skip
    energy = maps[0].impulse_energy
    title = f"container wavelet maps after an impulse E0 = {energy:g}, dashpot c = {args.damping:g}"
    return plot_transfer(maps, bones, title=title), notes


def _text(c, spans: dict) -> str:
    lines = [
        f"impulse responses: {len(c.attachment)} attachment(s) x {c.container_energy.size} "
        f"energies, {c.runs} runs x {c.periods} periods, dashpot c = {c.damping:g}, seed {c.seed} "
        f"({c.seconds:.1f} s)",
        "fraction of the initial energy dissipated (mean +- s.e.; 90 % time in periods, "
        "runs reaching it):",
    ]
    head = "  E0        " + "".join(f"{name:>26}" for name in c.attachment)
    lines.append(head)
    for j, e in enumerate(c.container_energy):
        cells = []
        for i in range(len(c.attachment)):
            t = c.t90[i, j]
            t90 = "never" if not math.isfinite(t) else f"{t:.0f}T"
            cell = f"{c.efficiency[i, j]:.3f}+-{c.efficiency_se[i, j]:.3f} {t90}/{c.reached[i, j]}"
            cells.append(f"{cell:>26}")
        lines.append(f"  {e:<10.4g}" + "".join(cells))
    lines.append(
        "energies E0 of the grid where at least half is dissipated: "
        + "; ".join(
            f"{name} {'none' if x is None else f'{x[0]:.3g} to {x[1]:.3g}'}"
            for name, x in spans.items()
        )
    )
    lines.append(f"largest audit error |H + W - H0|/H0: {float(c.max_audit_error.max()):.2g}")
    users = {(a["shape"], parameters_text(a["well_parameters"])) for a in c.attachments
             if "well_parameters" in a}  # fmt: skip
    lines += [f"{name} well (a user's well file): {values}" for name, values in sorted(users)]
    return "\n".join(lines)
