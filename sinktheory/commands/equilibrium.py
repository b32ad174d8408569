"""``sinktheory equilibrium``: the exact law of the container energy at equilibrium.

With ``--well FILE`` the well is a user's well file (:func:`sinktheory.equilibrium.well_law`:
energies measured from V(0, 0), below the well's certified escape energy)."""

from __future__ import annotations

import argparse

from . import HELP as HELPS
from ._common import (
    Output,
    add_fractions_argument,
    add_json,
    add_well_arguments,
    number,
    parameters_text,
    png_path,
    user_well_from_args,
    well_from_args,
)

__all__ = ["FRACTIONS", "HELP", "NAME"]

NAME = "equilibrium"
HELP = HELPS[NAME]
#: Default tail fractions f (as in :data:`sinktheory.equilibrium.law.FRACTIONS`, kept
#: here so --help does not import the package).
FRACTIONS = (0.1, 0.2, 0.3, 0.5, 0.8)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser, well_file=True)
    g = parser.add_argument_group("particles and energy")
    g.add_argument("--particles", type=number, default=1, help="k, integer >= 1 (default 1)")
    g.add_argument(
        "--mass",
        type=number,
        default=0.2,
        help="total particle mass m > 0 (default 0.2; validated, but the law does not depend "
        "on it)",
    )
    g.add_argument(
        "--total-energy",
        type=number,
        default=0.5,
        help="total energy E > 0 (default 0.5; a run's E0 plus the particles' initial "
        "potential energy)",
    )
    add_fractions_argument(g, FRACTIONS, "for the tails P(E_c >= f E) and Kac's return times")
    parser.add_argument("--plot", metavar="FILE.png", help="draw the density of E_c / E")
    add_json(parser)


def run(args: argparse.Namespace) -> Output:
    from ..equilibrium import equilibrium_law, well_law
    from ..equilibrium.law import check_fractions
    from ..model import Sink

    user = user_well_from_args(args)
    if user is None:
        sink = Sink(well_from_args(args), particles=args.particles, mass=args.mass)
    else:  # k and m validated as for a Sink, though the law does not depend on m
        Sink.check_particles(args.particles, args.mass)
    fractions = check_fractions(args.fractions)
    plot = png_path("plot", args.plot)
    if user is None:
        law = equilibrium_law(sink, args.total_energy)
        well = f"alpha={law.alpha:g} beta={law.beta:g} n={law.n} gamma={law.gamma:g}"
    else:
        well_file, given, check = user
        law = well_law(well_file, args.particles, args.total_energy, given, well_check=check)
        well = f"{parameters_text(law.parameters)}, leading degree 2n = {2 * law.n:g} at the centre"
    s = law.summary(fractions=fractions)
    data = s.as_dict()
    del data["s"], data["pdf"], data["cdf"], data["law"]["log_density"]
    lines = [
        f"equilibrium law of E_c: {law.shape} well {well}, k={law.particles}, total energy "
        f"E={law.total_energy:g}",
        f"  <E_c>                 {law.mean:.10g}  ({law.mean_fraction:.6g} of E)",
        f"  homogeneous estimate  {law.homogeneous_mean:.10g}  (E / (1 + k (1 + 1/n)))",
        "  quantiles of E_c      "
        + ", ".join(f"{p:g}: {q:.6g}" for p, q in zip(s.levels, s.quantiles, strict=True)),
        "  f       P(E_c >= f E)    Kac mean return time (periods T)",
    ]
    for f, p, kac, log10 in zip(s.fractions, s.tails, s.kac_periods, s.log10_kac_periods,
                                strict=True):  # fmt: skip
        tail, time = (
            (f"{p:.6g}", f"{kac:.6g}") if p > 0 else (f"10^{-log10:.4f}", f"10^{log10:.4f}")
        )
        lines.append(f"  {f:<6g}  {tail:<15}  {time}")
    out = Output(data, "\n".join(lines))
    if plot is not None:
        from ..plot.equilibrium import plot_law

        fig = plot_law(s)
        out.writers[plot] = lambda path, fig=fig: fig.savefig(path, dpi=150)
        data["plot"] = str(plot)
    return out
