"""The subcommands of ``sinktheory``: one module each, listed in :data:`COMMANDS`.

Each module defines ``NAME``, ``HELP``, ``add_arguments(parser)`` and ``run(args)``, which
returns an :class:`~sinktheory.commands._common.Output`.  A command computes everything
before it writes any file, so bad input never leaves partial output behind.

These modules are the command line's, not a Python API: their ``__all__`` holds only
their constants, and ``add_arguments``/``run`` are reached through
:func:`sinktheory.cli.main` (an argv list) or the ``sinktheory`` command, whose every
option is checked by the command-line tests.  A Python user calls the library functions
the commands call.

Modules are imported only when needed (``load``): ``sinktheory --version`` and
``--help`` read the one-line summaries in :data:`HELP` and import no command, and a
command imports only what it uses.  ``COMMANDS`` (every module) is loaded on first use.
"""

from importlib import import_module

#: The one-line summary of each command, in the order ``sinktheory --help`` lists them;
#: each module's ``HELP`` is its entry here.
HELP = {
    "well": "describe a soft-wall well and optionally draw its level lines (like Fig. 2)",
    "sink": "validate and describe a container + particles set-up and its run settings",
    "derive": "print the model's equations derived symbolically from the Lagrangian",
    "simulate": "integrate an ensemble of the container + particles and report <E>(t) (Figs. 5, 8)",
    "period": "exact period T_n of x'' + x^(2n-1) = 0 from amplitude or energy, to any precision",
    "series": "successive approximations in the triangle wave tau: error table and bound check",
    "reproduce": "redraw the paper's figures and write report.md with each claim checked",
    "floquet": "Floquet stability of the normal mode y = 0: phi(beta) charts with located "
    "boundaries",
    "nnm": "normal modes of container + particles: continuation, multipliers, FEP plots",
    "chaos": "Lyapunov exponents, GALI/SALI, MEGNO and the transverse exponent of y = 0",
    "design": "explore absorber designs (shape, beta, n, k, m, E0): ranked, charted, reported",
    "billiard": "the rigid limit n -> oo: exact billiard of the well's rigid walls, fixed or "
    "moving container",
    "equilibrium": "exact equilibrium law of the container energy: mean, quantiles, tails, "
    "Kac return times",
    "lifetime": "measured return times of the container energy against Kac's prediction from "
    "the equilibrium law",
    "relaxation": "how fast the container energy settles at the law: predicted curve and "
    "settling time, measured with --measure",
    "compare": "the 1-D NES and vibro-impact absorbers beside the 2-D sink: efficiency against "
    "impulse energy, 90 % times, wavelet maps",
    "sweep": "parameter sweep of any analysis kind (sweep --help lists them) into a resumable "
    "Zarr store",
}
NAMES = tuple(HELP)


def load(name: str):
    """The module of command ``name`` (imported now)."""
    return import_module(f".{name}", __name__)


def __getattr__(name: str):
    if name == "COMMANDS":
        return tuple(load(n) for n in NAMES)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["COMMANDS", "HELP", "NAMES"]
