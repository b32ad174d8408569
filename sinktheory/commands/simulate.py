"""``sinktheory simulate``: ensemble of full-dynamics runs, <E>(t) of the container (Figs. 5, 8).

``mean_energy[j]`` is the ensemble mean of the container energy E = (Xdot^2 + X^2)/2 at
t = jT (j = 0..P) and ``stderr[j]`` its standard error std(ddof=1)/sqrt(R); a single run
has none (NaN, null in JSON: the rule of :mod:`sinktheory.runstats`).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import ParameterError
from ..validation import choice, time_step
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_sink_arguments,
    add_well_arguments,
    add_work_limit,
    number,
    output_file,
    parameters_text,
    png_path,
    rigid_limit,
    user_well_from_args,
    well_from_args,
)

__all__ = ["HELP", "NAME", "QUOTED"]

if TYPE_CHECKING:
    import numpy as np

    from ..model import RunSettings, Sink
    from ..simulate import SimulationResult

NAME = "simulate"
HELP = HELPS[NAME]
#: What the help quotes from the integrator registry (:data:`sinktheory.integrators.SCHEMES`,
#: ``DEFAULT_SCHEME``), the step-size rule (:data:`sinktheory.stepsize.TOL_RANGE`,
#: ``DEFAULT_TOL``), the simulator (:data:`sinktheory.simulate.ENERGY_BOUND`) and the
#: adaptive step (:data:`sinktheory.limits.DEFAULT_EPS`, ``MAX_EPS``), written out
#: so that ``--help`` imports neither numpy nor numba; tests/foundations/test_startup.py checks each
#: against its source.
QUOTED = {
    "schemes": ("verlet", "yoshida4", "blanes-moan4", "yoshida6", "blanes-moan6", "suzuki-umeno8"),
    "default_scheme": "blanes-moan6",
    "tol_range": (1e-12, 1e-4),
    "default_tol": 1e-8,
    "energy_bound": 1e-6,
    "default_eps": 0.25,
    "max_eps": 0.25,
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser, rigid=True, well_file=True)
    g = add_sink_arguments(
        parser, runs_default=None, runs_help="ensemble size (default 25; 1 with --initial)"
    )
    g.add_argument(
        "--initial",
        type=number,
        nargs="+",
        metavar="X Y",
        help="start the particles at these positions (x1 y1 x2 y2 ...), relative to the "
        "container, at rest, instead of at random",
    )
    i = parser.add_argument_group("integrator")
    i.add_argument(
        "--stepper",
        default=None,
        help="fixed (the default: one step for the whole ensemble, from --tol or --dt) or "
        "adaptive: each run its own steps, cheaper for stiff walls (n >~ 10)",
    )
    i.add_argument(
        "--scheme",
        default=None,
        help=f"splitting scheme of the fixed stepper: one of {', '.join(QUOTED['schemes'])} "
        f"(default: the cheapest for --tol; {QUOTED['default_scheme']} with --dt)",
    )
    i.add_argument(
        "--eps",
        type=number,
        default=None,
        help=f"step factor of --stepper adaptive, in (0, {QUOTED['max_eps']}] (default "
        f"{QUOTED['default_eps']}: |dH|/H0 below 1e-8 over 40 periods of Fig. 8's ensemble, "
        "4e-7 over 10^4)",
    )
    i.add_argument(
        "--tol",
        type=number,
        default=None,
        help=f"relative total-energy error wanted over the run, {QUOTED['tol_range'][0]:g} to "
        f"{QUOTED['tol_range'][1]:g} (default {QUOTED['default_tol']:g}): picks scheme and step",
    )
    i.add_argument("--dt", type=number, default=None, help="step, overriding --tol")
    i.add_argument(
        "--energy-bound",
        type=number,
        default=None,
        help=f"stop when the relative total-energy error exceeds this (default: the larger "
        f"of {QUOTED['energy_bound']:g} and 100 x tol)",
    )
    o = parser.add_argument_group("output")
    o.add_argument("--out", help="save the recorded arrays and parameters to FILE.npz")
    o.add_argument("--plot", help="draw <E>(t/T) with its standard-error band to FILE.png")
    o.add_argument("--quiet", action="store_true", help="no progress bar")
    add_json(parser)
    add_work_limit(parser)


def _npz_path(value: str | None) -> Path | None:
    return output_file("out", value, (".npz",))


def _initial(values: list | None, sink: Sink) -> np.ndarray | None:
    if values is None:
        return None
    particles = sink.particles
    if len(values) != 2 * particles:
        raise ParameterError(
            "initial",
            f"{len(values)} number(s)",
            f"2 x particles = {2 * particles} numbers (x y for each particle)",
        )
    import numpy as np

    positions = np.array(values, dtype=float).reshape(particles, 2)
    for x, y in positions:
        sink.well.check_position("initial", x, y)
    return positions


def _check_size(args: argparse.Namespace, sink: Sink, settings: RunSettings, initial) -> None:
    """Refuse, before any work, what cannot run: --runs with --initial, a step too small,
    an ensemble too large for memory (estimates in the message).  The work limit is
    checked by :func:`~sinktheory.simulate.simulate` before it integrates."""
    if initial is not None and args.runs not in (None, 1):
        raise ParameterError(
            "runs", args.runs, "1 with --initial (one set of positions starts one run)"
        )
    settings.check_memory(sink, ("container",))
    if args.dt is not None:
        time_step("dt", args.dt)
    from ..simulate import STEPPERS

    chosen = STEPPERS[choice("stepper", args.stepper or "fixed", tuple(STEPPERS))]
    for name in ("scheme", "dt", "tol", "eps"):
        value = getattr(args, name)
        if value is not None and name not in chosen.options:
            takes = ", ".join("--" + o for o in chosen.options if hasattr(args, o))
            raise ParameterError(f"--{name}", value, f"absent with --stepper {chosen.name} (it "
                                 f"takes {takes})")  # fmt: skip


def run(args: argparse.Namespace) -> Output:
    plot = png_path("plot", args.plot)
    out = _npz_path(args.out)
    user = user_well_from_args(args)
    unsupported = {
        "--initial": args.initial, "--stepper": args.stepper, "--scheme": args.scheme,
        "--tol": args.tol, "--dt": args.dt, "--energy-bound": args.energy_bound,
        "--out": args.out, "--eps": args.eps,
    }  # fmt: skip
    if user is None and rigid_limit(args, unsupported):
        return _rigid(args, plot)
    from ..model import RunSettings, Sink  # numpy and numba: after the cheap checks
    from ..simulate import simulate
    from ..wellat import WellAt

    well = well_from_args(args) if user is None else WellAt(user[0], **user[1])
    sink = Sink(well, particles=args.particles, mass=args.mass)
    initial = _initial(args.initial, sink)
    runs = args.runs if args.runs is not None else (1 if initial is not None else 25)
    settings = RunSettings(
        container_energy=args.container_energy, runs=runs, periods=args.periods, seed=args.seed
    )
    _check_size(args, sink, settings, initial)
    result = simulate(
        sink,
        settings,
        stepper=args.stepper,
        scheme=args.scheme,
        dt=args.dt,
        tol=args.tol,
        initial=initial,
        record=("container", "final"),
        energy_bound=args.energy_bound,
        progress=not args.quiet,
        eps=args.eps,
    )
    mean, stderr = result.ensemble_energy()
    data = result.as_dict()
    w = sink.well
    from ..runstats import plus_minus  # numpy: after the early refusals

    described = (
        f"alpha={w.alpha:g} beta={w.beta:g} n={w.n} gamma={w.gamma:g}"
        if user is None
        else parameters_text(w.parameters)
    )
    text = "\n".join(
        [
            f"{w.shape} well {described}; k={sink.particles}, m={sink.mass:g}",
            result.message,
            f"<E>(0) = {mean[0]:.6f}   <E>({settings.periods} T) = "
            + plus_minus(mean[-1], stderr[-1], ".6f")
            + f" (over {settings.runs} run(s))",
        ]
    )
    writers = {}
    if out is not None:
        writers[out] = lambda path: _save(path, result, args)
    if plot is not None:
        from ..plot.simulate import plot_ensemble_energy

        fig = plot_ensemble_energy(result, sink)
        writers[plot] = lambda path: fig.savefig(path, dpi=120)
    return Output(data, text, writers)


def _rigid(args: argparse.Namespace, plot) -> Output:
    """--n inf: the same runs in the rigid billiard (moving container); gamma plays no part."""
    from ..billiard import billiard
    from ..model import RunSettings
    from ..runstats import ensemble_mean, plus_minus
    from ..validation import positive

    positive("gamma", 1.0 if args.gamma is None else args.gamma)
    shape = "flat" if args.shape is None else args.shape  # None: refused beside --well
    runs = 25 if args.runs is None else args.runs
    settings = RunSettings(
        container_energy=args.container_energy, runs=runs, periods=args.periods, seed=args.seed
    )
    result = billiard(shape, args.alpha, args.beta, particles=args.particles,
                      mass=args.mass, settings=settings)  # fmt: skip
    mean, stderr = ensemble_mean(result.container_energy)
    data = result.as_dict() | {"n": "inf", "rigid": True, "mean_energy": mean.tolist(),
                               "stderr": stderr.tolist()}  # fmt: skip
    text = "\n".join(
        [
            f"{shape} well alpha={args.alpha:g} beta={args.beta:g} n=inf: the rigid "
            f"billiard; k={args.particles}, m={args.mass:g}",
            f"{runs} run(s) x {args.periods} period(s), exact flights, "
            f"{int(result.collisions.sum())} impacts: max relative energy error "
            f"{result.max_relative_energy_error:.3g}",
            f"<E>(0) = {mean[0]:.6f}   <E>({args.periods} T) = "
            + plus_minus(mean[-1], stderr[-1], ".6f")
            + f" (over {runs} run(s))",
        ]
    )
    writers = {}
    if plot is not None:
        from ..plot.billiard import billiard_figure

        fig = billiard_figure(result)
        writers[plot] = lambda path: fig.savefig(path, dpi=120)
    return Output(data, text, writers)


def _save(path, result: SimulationResult, args) -> None:
    parameters = {
        **result.parameters,
        "initial": args.initial,
        "stepper": result.stepper,
        "scheme": result.scheme,
        "dt": result.dt,
        "energy_bound": args.energy_bound,
    }
    import numpy as np

    from .. import __version__

    mean, stderr = result.ensemble_energy()
    with open(path, "wb") as f:
        np.savez(
            f,
            times=result.times,
            container_energy=result.container_energy,
            mean_energy=mean,
            stderr=stderr,
            run_errors=result.run_errors,
            initial_energy=result.initial_energy,
            final_state=result.final_state.values,
            parameters=json.dumps(parameters),
            seed=result.parameters["seed"],
            version=__version__,
        )
