"""``sinktheory simulate``: ensemble of full-dynamics runs, <E>(t) of the container (Figs. 5, 8).

``mean_energy[j]`` is the ensemble mean of the container energy E = (Xdot^2 + X^2)/2 at
t = jT (j = 0..P) and ``stderr[j]`` its standard error std(ddof=1)/sqrt(R); with a single
run the standard error is reported as 0.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from .. import __version__
from ..errors import ParameterError
from ..integrators import DEFAULT_SCHEME, SCHEMES
from ..model import RunSettings, Sink, check_work
from ..simulate import ENERGY_BOUND, SimulationResult, simulate
from ..stepsize import DEFAULT_TOL, TOL_RANGE
from ..validation import time_step
from . import HELP as HELPS
from ._common import (
    Output,
    add_json,
    add_sink_arguments,
    add_well_arguments,
    number,
    output_file,
    png_path,
    well_from_args,
)

NAME = "simulate"
HELP = HELPS[NAME]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_well_arguments(parser)
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
        "--method",
        default=None,
        help=f"one of {', '.join(SCHEMES)} (default: the cheapest for --tol; "
        f"{DEFAULT_SCHEME} with --dt)",
    )
    i.add_argument(
        "--tol",
        type=number,
        default=None,
        help=f"relative total-energy error wanted over the run, {TOL_RANGE[0]:g} to "
        f"{TOL_RANGE[1]:g} (default {DEFAULT_TOL:g}): picks scheme and step",
    )
    i.add_argument("--dt", type=number, default=None, help="step, overriding --tol")
    i.add_argument(
        "--energy-bound",
        type=number,
        default=None,
        help=f"stop when the relative total-energy error exceeds this (default: the larger "
        f"of {ENERGY_BOUND:g} and 100 x tol)",
    )
    o = parser.add_argument_group("output")
    o.add_argument("--out", help="save the recorded arrays and parameters to FILE.npz")
    o.add_argument("--plot", help="draw <E>(t/T) with its standard-error band to FILE.png")
    o.add_argument("--quiet", action="store_true", help="no progress bar")
    add_json(parser)


def _npz_path(value: str | None) -> Path | None:
    return output_file("--out", value, (".npz",))


def _initial(values: list | None, sink: Sink) -> np.ndarray | None:
    if values is None:
        return None
    particles = sink.particles
    if len(values) != 2 * particles:
        raise ParameterError(
            "--initial",
            f"{len(values)} number(s)",
            f"2 x particles = {2 * particles} numbers (x y for each particle)",
        )
    positions = np.array(values, dtype=float).reshape(particles, 2)
    for x, y in positions:
        sink.well.check_position("--initial", x, y)
    return positions


def _check_size(args: argparse.Namespace, sink: Sink, settings: RunSettings, initial) -> None:
    """Refuse, before any work, what cannot run: --runs with --initial, a step too small,
    an ensemble too large for memory or too long to finish (estimates in the message)."""
    if initial is not None and args.runs not in (None, 1):
        raise ParameterError(
            "--runs", args.runs, "1 with --initial (one set of positions starts one run)"
        )
    settings.check_memory(sink, ("container",))
    if args.dt is not None:
        dt = time_step("--dt", args.dt)
        check_work(settings, sink, math.ceil(2 * math.pi / dt - 1e-9))


def run(args: argparse.Namespace) -> Output:
    plot = png_path("--plot", args.plot)
    out = _npz_path(args.out)
    sink = Sink(well_from_args(args), particles=args.particles, mass=args.mass)
    initial = _initial(args.initial, sink)
    runs = args.runs if args.runs is not None else (1 if initial is not None else 25)
    settings = RunSettings(energy=args.energy, runs=runs, periods=args.periods, seed=args.seed)
    _check_size(args, sink, settings, initial)
    result = simulate(
        sink,
        settings,
        method=args.method,
        dt=args.dt,
        tol=args.tol,
        initial=initial,
        record=("container", "final"),
        energy_bound=args.energy_bound,
        progress=not args.quiet,
    )
    mean, stderr = result.ensemble_energy()
    data = {
        "mean_energy": mean.tolist(),
        "stderr": stderr.tolist(),
        "max_relative_energy_error": result.max_relative_energy_error,
        "runs": settings.runs,
        "periods": settings.periods,
        "method": result.method,
        "dt": result.dt,
        "tol": result.tol,
        "steps_per_period": result.steps_per_period,
        "seed": settings.seed,
    }
    w = sink.well
    text = "\n".join(
        [
            f"{w.shape} well alpha={w.alpha:g} beta={w.beta:g} n={w.n} gamma={w.gamma:g}; "
            f"k={sink.particles}, m={sink.mass:g}",
            result.message,
            f"<E>(0) = {mean[0]:.6f}   <E>({settings.periods} T) = {mean[-1]:.6f} "
            f"+- {stderr[-1]:.2g} (standard error over {settings.runs} run(s))",
        ]
    )
    writers = {}
    if out is not None:
        writers[out] = lambda path: _save(path, result, mean, stderr, args, settings)
    if plot is not None:
        writers[plot] = lambda path: _plot(path, result, mean, stderr, sink, settings)
    return Output(data, text, writers)


def _save(path, result: SimulationResult, mean, stderr, args, settings) -> None:
    parameters = {
        "shape": args.shape,
        "alpha": args.alpha,
        "beta": args.beta,
        "gamma": args.gamma,
        "n": args.n,
        "particles": args.particles,
        "mass": args.mass,
        "energy": settings.energy,
        "runs": settings.runs,
        "periods": settings.periods,
        "seed": settings.seed,
        "initial": args.initial,
        "method": result.method,
        "dt": result.dt,
        "energy_bound": args.energy_bound,
    }
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
            seed=settings.seed,
            version=__version__,
        )


def _plot(path, result: SimulationResult, mean, stderr, sink: Sink, settings) -> None:
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8, 4.5), layout="constrained")
    ax = fig.add_subplot()
    t = result.times / (2 * np.pi)
    ax.fill_between(t, mean - stderr, mean + stderr, color="C0", alpha=0.3, label="± std. error")
    ax.plot(t, mean, color="C0", lw=1.0, label=r"$\langle E\rangle$")
    ax.set_xlabel(r"$t/T$")
    ax.set_ylabel(r"$\langle E\rangle$ (container energy)")
    w = sink.well
    ax.set_title(
        rf"{w.shape} well, $\alpha$={w.alpha:g}, $\beta$={w.beta:g}, n={w.n}, "
        rf"k={sink.particles}, m={sink.mass:g}; {settings.runs} run(s)"
    )
    ax.set_xlim(t[0], t[-1])
    ax.legend(loc="upper right")
    ax.grid(alpha=0.3)
    fig.savefig(path, dpi=120)
