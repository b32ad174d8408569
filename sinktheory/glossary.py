"""One meaning for each parameter name, on the command line and in Python alike.

:data:`GLOSSARY` maps every name a user passes -- an option ``--foo-bar`` of a command,
the keyword ``foo_bar`` of a public function, a sweep parameter ``foo_bar=...`` -- to its
one meaning.  An option and the keyword it feeds have the same name (``-`` for ``_``).
tests/interface/test_names.py walks every command's parser, the public entry points'
signatures and the sweep kinds, and fails on a name that is not here, on an option whose
keyword is named differently, and on an option whose help does not say what the glossary
says (its :data:`MARKS`).

Names that changed keep working for one release: :func:`renamed` accepts an old keyword
with a DeprecationWarning that names the new one, and :func:`modern_argv` rewrites an old
option of a command (:data:`RENAMED_OPTIONS`) or an old sweep parameter of ``--param``
(:data:`RENAMED_PARAMETERS`) with a one-line note on stderr; a sweep store written under
the old parameter names still resumes and reads (:mod:`sinktheory.sweep.store`).

Examples
--------
>>> GLOSSARY["container_energy"].split(":")[0]
'E0'
>>> @renamed(energy="container_energy")
... def f(*, container_energy=0.5):
...     return container_energy
>>> import warnings
>>> with warnings.catch_warnings(record=True) as caught:
...     warnings.simplefilter("always")
...     f(energy=2.0), str(caught[0].message).split(" (")[0]
(2.0, "f: the keyword 'energy' is now 'container_energy'")
>>> modern_argv(["simulate", "--alpha", "0.5", "--energy=2"])
(['simulate', '--alpha', '0.5', '--container-energy=2'], ['--energy is now --container-energy'])
>>> modern_argv(["sweep", "ensemble", "--param", "energy=0.1,0.2"])[1]
['--param energy is now --param container_energy']
"""

from __future__ import annotations

import contextlib
import functools
import warnings
from collections.abc import Callable

__all__ = [
    "GLOSSARY",
    "MARKS",
    "RENAMED_KEYWORDS",
    "RENAMED_OPTIONS",
    "RENAMED_PARAMETERS",
    "old_attribute",
    "stepper_or_scheme",
]

#: name -> its one meaning.  The part before the first colon, where there is one, is the
#: symbol of the paper or the short form the help texts use.
GLOSSARY: dict[str, str] = {
    # --- energies: each says whose energy it is
    "container_energy": "E0: the container's energy at the start of a run (displaced to "
    "X = sqrt(2 E0) and released at rest; the particles start at rest near the centre)",
    "total_energy": "E: the total energy H of container and particles, conserved by the "
    "dynamics (in a run E0 plus the particles' initial potential energy)",
    "particle_energy": "the energy of one particle in the well (kinetic plus potential)",
    "energy": "E_n = A0^(2n)/(2n): the energy of the power-law oscillator x'' + x^(2n-1) = 0 "
    "(no container, no particles)",
    "escape_potential": "V at the escape point, absolute; escape_energy is it above V(0, 0)",
    "energies": "E0 grid: initial container energies (impulse energies) LO, HI, COUNT log-spaced",
    "wavelet_energy": "E0 of the wavelet maps: the impulse energy of one run",
    "energy_bound": "bound: the largest relative total-energy error |H - H0|/H0 tolerated",
    # --- how the equations are integrated
    "stepper": "fixed (one step for the whole ensemble, from tol or dt) or adaptive (each run "
    "its own steps, set by eps)",
    "scheme": "splitting scheme of the fixed-step integrator (verlet, yoshida4, blanes-moan4, "
    "yoshida6, blanes-moan6, suzuki-umeno8)",
    "implementation": "which code runs a loop: compiled (numba), python, or auto (python for "
    "the first few single values, compiled after)",
    "dt": "step: the time step (shortened so a period is a whole number of steps)",
    "tol": "relative energy error wanted, from which the scheme and step are chosen",
    "eps": "step factor of the adaptive stepper",
    "steps": "steps per period",
    "renorm": "steps between renormalisations of the tangent vectors",
    "rtol": "per-step relative tolerance of an error-controlled integration",
    "dps": "decimal digits of working precision",
    "digits": "significant digits printed",
    # --- the well
    "alpha": "alpha: the wall parameter (alpha - beta is the wall distance on y = 0)",
    "beta": "beta: the curvature parameter of the walls (curvature/2)",
    "n": "n: the wall stiffness (exponent of the walls; inf is the rigid limit)",
    "gamma": "gamma: the well strength",
    "shape": "the well's shape (flat, symmetric, circular)",
    "values": "numbers for a well's symbolic parameters: a user's well's values by name "
    "(its defaults for the others), or where a general form leaves a question open",
    "nes_n": "the wall exponent of the 1-D NES",
    # --- particles and runs
    "particles": "k: the number of particles",
    "mass": "m: the particles' total mass",
    "runs": "ensemble size: the number of runs",
    "periods": "periods T = 2 pi of the container",
    "seed": "random seed of the initial positions (the same seed gives the same runs)",
    "box": "half-width of the square around the centre where particles start",
    "initial": "particle positions relative to the container at the start, at rest",
    "initial_state": "a previous result's final state to continue from",
    "record": "what a run keeps (container, particles, trajectory, final)",
    "stride": "steps between trajectory samples",
    "samples": "samples per period of the records",
    "transient": "periods left out at the start before measuring",
    "progress": "progress bar on stderr",
    "quiet": "no progress bar, no note before compiling an engine (and no estimate line)",
    "settings": "RunSettings: container energy E0, runs, periods, seed, box",
    "sink": "Sink: the well, the particles and their mass",
    "well": "the particles' well: a Well (shape, alpha, beta, n, gamma), a user's well "
    "definition, or on the command line a well file (--well FILE)",
    "parameter": "the name of a user's well's own parameter that a diagram runs over",
    "well_param": "NAME=VALUE: a value for a parameter of a well file (--well), within its "
    "range; the file's defaults otherwise",
    "well_check": "a user's well as sinktheory.userwell.check_well found it at the given "
    "values (so that it is not checked twice)",
    "user_well": "a user's well at its parameter values (sinktheory.wellat.WellAt) as an "
    "attachment's 2-D well, in place of shape, alpha, beta and n",
    # --- analyses
    "spectrum": "the Lyapunov spectrum (QR): all exponents or the D largest",
    "gali": "GALI_K order K",
    "megno": "MEGNO Y(t) and its time average",
    "transverse": "the transverse exponent of the invariant plane y = 0",
    "lyapunov": "the largest Lyapunov exponent lambda_1",
    "fixed": "a fixed container (only the particles move)",
    "fractions": "fractions f in (0, 1) of the total energy E selecting the sets {E_c >= f E}",
    "fraction": "f: the relative distance from the target that counts as settled",
    "target": "the level a relaxation approaches (the law's mean <E_c>)",
    "tail": "the relative excess below which an approach is fitted by one exponential",
    "window": "periods per window",
    "level": "confidence level of an interval",
    "resamples": "bootstrap resamples",
    "max_hours": "the most estimated work, in hours, a command that cannot resume may start "
    "(default 1; worklimit.interactive_limit)",
    "shell_energies": "starting container energies on the energy shell of the relaxation "
    "model's short runs",
    "shell_runs": "runs per starting energy of the relaxation model's short runs",
    "lag": "the largest lag, in periods, of the relaxation model's short runs",
    "cells": "grid cells of the Fokker-Planck solution",
    "measure": "(runs, periods) simulated from the paper's start to measure the settling",
    "energy_runs": "E(jT) of independent runs: the container energy records (runs x periods)",
    "series": "a 1-D series (such as the container energy E_k at t = kT)",
    "theiler": "Theiler window: points with |i - j| below it are left out",
    "l_min": "the shortest diagonal line counted",
    "v_min": "the shortest vertical line counted",
    "quantity": "what a section records (y, or energy: the container energy E(jT))",
    "count": "how many values (sections, grid points)",
    "levels": "probability levels of quantiles",
    "lo": "the low end of an interval",
    "hi": "the high end of an interval",
    "problem": "a HillProblem: Hill's equation of the normal mode y = 0",
    "hill": "a WellHill: Hill's equation along y = 0 of a user's well (well_hill)",
    "betas": "a grid of betas (on the command line COUNT betas over the interval)",
    "chaos": "a chaos map over the same betas",
    "chart": "a transverse chart over the same betas",
    "half_traces": "the transverse half-period half-traces phi_T/2 at every point",
    "subspace": "the invariant subspace an orbit is kept in",
    "block": "engine runs per block (the numbers do not depend on it)",
    "stop_early": "stop a point's runs once they are settled chaotic",
    "replica": "index of a repetition with its own seed",
    "store": "a Zarr store of the results",
    "params": "a sweep's parameters: NAME -> a value or a list of values",
    "kinds": "the absorbers compared (well, nes, impact)",
    "shapes": "the well shapes compared",
    "samples_per_period": "samples per period of the records",
    "att": "an Attachment: the absorber",
    "omega": "the frequency grid (LO, HI, COUNT) of a wavelet map",
    "run": "which run",
    "amplitude": "A0: the amplitude of the oscillator x(t)",
    "amplitude_range": "A0 grid: amplitudes LO, HI, COUNT of a Floquet chart of a well file",
    "order": "the highest order i of the successive approximations",
    "lam": "Lam: the coefficient of the pure Hill equation",
    "beta_range": "beta grid LO HI COUNT",
    "lam_range": "Lam grid LO HI COUNT",
    "mode": "the normal mode a branch starts from (container or particle)",
    "continue_in": "the parameter a branch is continued in (energy: the total energy, or a "
    "well parameter)",
    "interval": "[LO, HI]: the interval a continuation stays in",
    "points": "points per direction of a continuation",
    "ds": "the first arclength step of a continuation",
    "damping": "damping coefficient (what it acts on: damping_kind)",
    "damping_kind": "what damping of the 2-D well is (contact or dashpot)",
    "attachment": "the absorber attached (well, nes, impact)",
    "attachments": "the absorbers compared (well, nes, impact)",
    "wavelet": "the complex Morlet wavelet of a wavelet map (cmorB-C, e.g. cmor1.5-1.0)",
    "horizons": "periods at which the absorbed fraction is measured",
    "sigmas": "verdict threshold in standard errors",
    "risk_level": "absorbed level whose risk is measured",
    "rqa_eps": "RQA recurrence threshold eps / E0",
    "bootstrap": "bootstrap resamples",
    "lyapunov_runs": "runs for lambda_1",
    "lyapunov_periods": "periods for lambda_1",
    "top": "designs in the report",
    # --- commands and their outputs
    "plot": "FILE.png: a chart",
    "wavelet_plot": "FILE.png: wavelet maps over the normal modes",
    "out": "where results are written (a file or a store)",
    "report": "directory of the design report",
    "json": "one JSON object on stdout",
    "latex": "LaTeX instead of text",
    "fresh": "derive again instead of reading the cache",
    "figure": "the paper's figures to draw",
    "quick": "a low-fidelity preview",
    "kind": "the analysis a sweep runs",
    "param": "a swept parameter NAME=LO:HI:COUNT, NAME=V1,V2,... or NAME=VALUE",
    "resume": "continue the sweep in a store",
    "repair": "recompute the points of damaged chunks",
    "scheduler": "Dask scheduler",
    "workers": "local processes",
    "no_estimate": "skip the cost calibration",
}

#: name -> what the help text of its option must say (default: the glossary's symbol,
#: the part before the first colon, when there is one).
MARKS: dict[str, str] = {
    "container_energy": "E0",
    "total_energy": "total energy",
    "particle_energy": "particle energy",
    "energy": "E_n",
    "energies": "container energies",
    "scheme": "verlet",
    "stepper": "adaptive",
}


def _stepper_or_scheme(value: str) -> str:
    """--stepper (for adaptive) or --scheme (any other value)"""
    return "--stepper" if value == "adaptive" else "--scheme"


def stepper_or_scheme(value: object) -> str:
    """stepper (for "adaptive") or scheme (any other value)"""
    return "stepper" if value == "adaptive" else "scheme"


#: command -> old option -> its new name, or a function of the option's value giving it.
RENAMED_OPTIONS: dict[str, dict[str, str | Callable[[str], str]]] = {
    **{command: {"--energy": "--container-energy"} for command in ("sink", "billiard", "design")},
    "lifetime": {"--energy": "--container-energy", "--fraction": "--fractions"},
    "compare": {
        "--shape": "--shapes",
        "--samples": "--samples-per-period",
        "--wavelet": "--wavelet-plot",
    },
    "simulate": {"--energy": "--container-energy", "--method": _stepper_or_scheme},
    "well": {"--energy": "--particle-energy"},
    "equilibrium": {"--energy": "--total-energy", "--fraction": "--fractions"},
    "nnm": {
        "--energy": "--total-energy",
        "--continue": "--continue-in",
        "--range": "--interval",
        "--agreement": "--betas",
    },
    "chaos": {"--energy": "--container-energy", "--method": "--scheme"},
}


#: Sweep parameters (``--param NAME=...``, the ``params`` of a sweep) renamed: old -> new.
RENAMED_PARAMETERS: dict[str, str] = {"energy": "container_energy", "method": "scheme"}


#: "module.function" -> old keyword -> its new name (or a function of the value giving
#: it), filled by :func:`renamed` as the modules that use it are imported.
RENAMED_KEYWORDS: dict[str, dict[str, str | Callable[[object], str]]] = {}


def option_of(name: str) -> str:
    """The option of a keyword: ``container_energy`` -> ``--container-energy``."""
    return "--" + name.replace("_", "-")


def renamed(**renames: str | Callable[[object], str]):
    """Decorator: accept the old keywords of a function (or a class's constructor) for one
    more release, each with a DeprecationWarning naming its new name (or the name the
    value decides: ``method="adaptive"`` -> ``stepper``).  The signature shows the new
    names only."""

    def wrap(obj):
        target = obj.__init__ if isinstance(obj, type) else obj
        owner = obj.__qualname__
        RENAMED_KEYWORDS[f"{obj.__module__}.{owner}"] = dict(renames)

        @functools.wraps(target)
        def modern(*args, **kwargs):
            for old, new in renames.items():
                if old in kwargs:
                    value = kwargs.pop(old)
                    name = new(value) if callable(new) else new
                    warnings.warn(
                        f"{owner}: the keyword {old!r} is now {name!r} (the old name goes in "
                        "the next release)",
                        DeprecationWarning,
                        stacklevel=2,
                    )
                    if name in kwargs:
                        from .errors import ParameterError

                        raise ParameterError(old, value, f"left out: {name} is given too")
                    kwargs[name] = value
            return target(*args, **kwargs)

        if isinstance(obj, type):
            obj.__init__ = modern
            return obj
        return modern

    return wrap


class old_attribute:  # noqa: N801 (used like a property)
    """A read-only attribute kept under its old name for one release: reading it gives the
    attribute ``new`` with a DeprecationWarning naming it (an old attribute split in two,
    ``old_attribute("stepper", "scheme", read=f)``: ``f(obj)``, its old value, with a
    warning naming both).

    Examples
    --------
    >>> class Settings:
    ...     container_energy = 0.5
    ...     energy = old_attribute("container_energy")
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     Settings().energy, str(caught[0].message).split(" (")[0]
    (0.5, "Settings: the attribute 'energy' is now 'container_energy'")
    """

    def __init__(self, *new: str, read: Callable[[object], object] | None = None) -> None:
        self.new, self.read = new, read

    def __set_name__(self, owner, name: str) -> None:
        self.old, self.owner = name, owner.__qualname__

    def __get__(self, obj, objtype=None):
        if obj is None:
            return self
        names = " and ".join(repr(name) for name in self.new)
        warnings.warn(
            f"{self.owner}: the attribute {self.old!r} is now {names} (the old name goes "
            "in the next release)",
            DeprecationWarning,
            stacklevel=2,
        )
        return getattr(obj, self.new[0]) if self.read is None else self.read(obj)


@contextlib.contextmanager
def refusals_named(**names: str):
    """Inside, a ParameterError that names a keyword of a lower-level function (``stop``)
    names the caller's keyword (``interval``) instead, so the user reads the name they typed.

    Examples
    --------
    >>> from sinktheory.errors import ParameterError
    >>> with refusals_named(stop="interval"):
    ...     raise ParameterError("stop", (2, 1), "LO < HI")
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: interval = (2, 1) is not allowed: must be LO < HI
    """
    from .errors import ParameterError

    try:
        yield
    except ParameterError as e:
        new = names.get(e.name)
        if new is None or not str(e).startswith(f"{e.name} = "):
            raise
        error = ParameterError(new, e.value, e.allowed)
        error.args = (new + str(e)[len(e.name) :],)
        raise error from None


def modern_argv(argv: list[str]) -> tuple[list[str], list[str]]:
    """``argv`` with the old options of its command (:data:`RENAMED_OPTIONS`) and the old
    sweep parameters of its ``--param NAME=...`` (:data:`RENAMED_PARAMETERS`) renamed, and
    one note ``--old is now --new`` for each; other words are left as they are."""
    at = next((i for i, w in enumerate(argv) if not w.startswith("-")), len(argv))
    table = RENAMED_OPTIONS.get(argv[at] if at < len(argv) else "", {})
    out, notes = [], []
    for i, word in enumerate(argv):
        option, sep, value = word.partition("=")
        note = None
        if i > at and option in table and word.startswith("--"):
            new = table[option]
            if callable(new):
                given = value if sep else (argv[i + 1] if i + 1 < len(argv) else "")
                new = new(given)
            note = f"{option} is now {new}"
            word = new + sep + value
        elif i > at and ((option == "--param" and sep) or argv[i - 1] == "--param"):
            word, note = _modern_param(word)
        if note is not None and note not in notes:
            notes.append(note)
        out.append(word)
    return out, notes


def _modern_param(word: str) -> tuple[str, str | None]:
    """A ``--param`` value (``NAME=...``, or the whole ``--param=NAME=...``) with an old
    NAME renamed, and its note (None if NAME is not old)."""
    prefix = "--param=" if word.startswith("--param=") else ""
    name, sep, rest = word[len(prefix) :].partition("=")
    new = RENAMED_PARAMETERS.get(name.strip())
    if not sep or new is None:
        return word, None
    return prefix + new + sep + rest, f"--param {name.strip()} is now --param {new}"
