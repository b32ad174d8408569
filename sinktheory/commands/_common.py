"""Pieces shared by the subcommands: argument types, the well options, output files."""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import math
import os
import shutil
import signal
import sys
import threading
import uuid
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import ParameterError
from ..validation import writable_directory


@dataclass
class Output:
    """What a command produced: a JSON-ready dict, its text rendering, files to write.

    ``writers`` maps a path to a callable that writes it; they run only after the
    command has finished computing, so an error never leaves a partial file.
    """

    data: dict[str, Any]
    text: str
    writers: dict[Path, Any] = field(default_factory=dict)
    #: 1 when the command finished but part of it failed numerically (reported in data)
    exit_status: int = 0


#: Seconds after which an interrupt swallowed by a callback is sent again (:func:`interruptible`).
RESEND_SECONDS = 0.05


class Interrupted(KeyboardInterrupt):
    """SIGTERM turned into an exception, so it unwinds like Ctrl-C (stores closed, workers
    ended); ``signum`` is the signal received."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


@contextlib.contextmanager
def interruptible(
    prog: str, hint: str | Callable[[], str | None] | None = "--resume continues"
) -> Iterator[None]:
    """Turn SIGINT (Ctrl-C) and SIGTERM into one line on stderr and the shell's status.

    Inside, SIGTERM raises :class:`Interrupted` (SIGINT raises KeyboardInterrupt, as
    always), so ``finally`` blocks close the store and end the worker processes.  Then
    ``PROG: interrupted; HINT`` (or ``PROG: interrupted`` without a hint; a callable
    ``hint`` is asked at that moment, e.g. whether there is a store to resume) is printed and
    SystemExit raised with status 128 + the signal's number: 130 for SIGINT, 143 for
    SIGTERM (what a shell reports for a process the signal ended, so job managers see the
    usual codes).
    """

    def on_term(signum, frame):
        raise Interrupted(signum)

    def on_unraisable(unraisable) -> None:
        """An interrupt raised where Python can only print it (a ctypes callback, e.g.
        llvmlite's while numba compiles) is not lost: the signal is sent again
        :data:`RESEND_SECONDS` later, from a thread, so that its handler runs in the main
        thread's Python outside the callback (sent at once, it would run inside this hook,
        where it is swallowed too)."""
        if not isinstance(unraisable.exc_value, KeyboardInterrupt):
            return hook(unraisable)
        signum = getattr(unraisable.exc_value, "signum", signal.SIGINT)
        resend = threading.Timer(RESEND_SECONDS, os.kill, (os.getpid(), signum))
        resend.daemon = True
        resend.start()

    try:
        previous = signal.signal(signal.SIGTERM, on_term)
    except ValueError:  # not the main thread: leave SIGTERM alone
        previous = None
    hook, sys.unraisablehook = sys.unraisablehook, on_unraisable
    from ..progress import HeldSignals

    # a compiled call that keeps a held signal waiting too long ends the process with it
    forced, HeldSignals.forced_line = HeldSignals.forced_line, f"{prog}: interrupted"
    try:
        try:
            yield
        except Exception as e:  # an interrupt behind another error: see interrupt_behind
            interrupt = interrupt_behind(e)
            if interrupt is None:
                raise
            raise interrupt from None
    except KeyboardInterrupt as e:
        signum = getattr(e, "signum", signal.SIGINT)
        e.__traceback__ = None  # let the frames go: a pool's queues are freed before exit
        said = hint() if callable(hint) else hint
        print(f"{prog}: interrupted" + (f"; {said}" if said else ""), file=sys.stderr, flush=True)
        status = 128 + int(signum)
    else:
        status = None
    finally:
        HeldSignals.forced_line = forced
        sys.unraisablehook = hook
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)
    if status is not None:
        raise SystemExit(status)


def settle_zarr(timeout: float = 1.0) -> None:
    """Let zarr's I/O thread finish the reads and writes left in flight by an interrupt or
    an error (a chunk that does not decode fails a read while the others go on), so that
    exiting does not close its event loop under them: that printed "Task was destroyed but
    it is pending!" or "Event loop is closed" after the command's last line.  Nothing to do
    when zarr was not used."""
    sync = sys.modules.get("zarr.core.sync")
    loop = None if sync is None else sync.loop[0]
    if loop is None or loop.is_closed() or not loop.is_running():
        return

    async def pending() -> None:
        tasks = asyncio.all_tasks() - {asyncio.current_task()}
        if tasks:
            await asyncio.wait(tasks, timeout=timeout)

    with contextlib.suppress(Exception):  # a loop that cannot settle only prints more
        asyncio.run_coroutine_threadsafe(pending(), loop).result(timeout + 0.5)


def interrupt_behind(error: BaseException) -> KeyboardInterrupt | None:
    """The KeyboardInterrupt (or :class:`Interrupted`) among the causes of ``error``, if any.

    A signal that arrives while a compiled (numba) function runs is acted on when it
    returns, and if that is while numba boxes its results (which calls Python), the
    interrupt surfaces as a SystemError ("returned a result with an exception set") caused
    by it; one that arrives while a C extension module initialises (SciPy's, on a
    command's first import of it) surfaces as an ImportError ("initialization failed").
    Long compiled loops hold the signals (:func:`sinktheory.progress.chunks`); this finds
    the interrupt behind any other error.

    Examples
    --------
    >>> try:
    ...     try:
    ...         raise KeyboardInterrupt
    ...     except KeyboardInterrupt as e:
    ...         raise SystemError("returned a result with an exception set") from e
    ... except SystemError as e:
    ...     found = interrupt_behind(e)
    >>> type(found).__name__, interrupt_behind(SystemError("other"))
    ('KeyboardInterrupt', None)
    """
    seen = set()
    while error is not None and id(error) not in seen:
        if isinstance(error, KeyboardInterrupt):
            return error
        seen.add(id(error))
        error = error.__cause__ or error.__context__
    return None


def resume_hint(store: str) -> Callable[[], str | None]:
    """The hint of an interrupted sweep: ``--resume continues`` once its store exists."""
    return lambda: "--resume continues" if Path(store).exists() else None


def damage_note(repaired: int) -> str:
    """`` (N of them found damaged in the store and recomputed)`` or nothing.

    Examples
    --------
    >>> damage_note(0), damage_note(3)
    ('', ' (3 of them found damaged in the store and recomputed)')
    """
    return f" ({repaired} of them found damaged in the store and recomputed)" if repaired else ""


def number(text: str) -> int | float:
    """argparse type: an int or float literal (nan and inf pass, so the model can name them)."""
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None


def add_json(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object on stdout")


def add_work_limit(parser: argparse.ArgumentParser) -> None:
    """``--max-hours``: the limit of estimated work the command may start (default one hour;
    see :mod:`sinktheory.worklimit`), applied around the command by :mod:`sinktheory.cli`."""
    parser.add_argument(
        "--max-hours",
        type=number,
        default=None,
        metavar="H",
        help="refuse work estimated above H hours (default 1, at most 720)",
    )


def add_well_arguments(
    parser: argparse.ArgumentParser,
    *,
    beta: bool = True,
    rigid: bool = False,
    well_file: bool = False,
) -> None:
    """The well options; ``rigid`` says the command also takes ``--n inf`` (the rigid
    billiard, see :func:`rigid_limit`); ``well_file`` says it also takes ``--well FILE``
    instead of them (:func:`add_well_file`; then --alpha, --beta and --n are required
    only without it, see :func:`well_from_args`)."""
    from .._generated.shapes import NAMES as SHAPES  # the model's names, without numba

    g = parser.add_argument_group("well")
    unless = " (unless --well)" if well_file else ""
    g.add_argument("--alpha", type=number, required=not well_file, help="alpha > 0" + unless)
    if beta:
        g.add_argument(
            "--beta", type=number, required=not well_file,
            help="beta < alpha (curvature/2)" + unless,
        )  # fmt: skip
    g.add_argument(
        "--n",
        type=number,
        required=not well_file,
        help="wall stiffness, integer >= 1"
        + (
            ", or inf: the rigid limit, an exact billiard (as 'sinktheory billiard')"
            if rigid
            else ""
        )
        + unless,
    )
    # with a well file the defaults are filled in by well_from_args, so that a given
    # --gamma or --shape is seen and refused beside --well
    default = None if well_file else 1.0
    g.add_argument("--gamma", type=number, default=default, help="well strength > 0 (default 1)")
    g.add_argument(
        "--shape", default=None if well_file else "flat",
        help=f"one of {', '.join(SHAPES)} (default flat)",
    )  # fmt: skip
    if well_file:
        add_well_file(g)


#: The options of a registered shape that a well file replaces, by their dest.
_SHAPE_OPTIONS = ("shape", "alpha", "beta", "n", "gamma")


def add_well_file(parser, exclusive=None) -> None:
    """``--well FILE`` (a TOML well file, :func:`sinktheory.userwell.load_well`; in the
    mutually exclusive group ``exclusive`` if given) and ``--well-param NAME=VALUE``
    (repeated: values of its parameters, the file's defaults otherwise), read by
    :func:`user_well_from_args`."""
    (parser if exclusive is None else exclusive).add_argument(
        "--well",
        metavar="FILE",
        help="a TOML well file instead of --shape and its parameters (parsed without running "
        "code; see docs/guide/user_wells.rst)",
    )
    parser.add_argument(
        "--well-param",
        metavar="NAME=VALUE",
        action="append",
        default=[],
        help="a value for a parameter of the well file, within its range (repeat for more; "
        "the file's defaults otherwise)",
    )


def user_well_from_args(args: argparse.Namespace):
    """``(well, given, report)``: the :class:`~sinktheory.userwell.UserWell` of ``--well
    FILE``, the parameter values of ``--well-param`` by name, and the well's
    :class:`~sinktheory.userwell.WellCheck` at those values; None without ``--well``.

    The file is loaded and its well checked (:func:`sinktheory.userwell.check_well`); a
    file or well that is refused, an option of a registered shape given beside it, or a
    ``--well-param`` that is not NAME=NUMBER raises a ParameterError (one line, exit
    status 2).

    Examples
    --------
    >>> user_well_from_args(argparse.Namespace(well=None, well_param=[])) is None
    True
    >>> user_well_from_args(argparse.Namespace(well="w.toml", well_param=[], alpha=0.5))
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: well = 'w.toml' is not allowed: must be given without \
--alpha (the well file defines the well)
    """
    if args.well is None:
        if args.well_param:
            raise ParameterError("well_param", args.well_param[0], "given with --well FILE")
        return None
    for name in _SHAPE_OPTIONS:
        if getattr(args, name, None) is not None:
            raise ParameterError(
                "well", args.well, f"given without --{name} (the well file defines the well)"
            )
    given = {}
    for item in args.well_param:
        name, sep, text = item.partition("=")
        try:
            value = number(text.strip())
        except argparse.ArgumentTypeError:
            value = None
        if not sep or not name.strip() or value is None:
            raise ParameterError("well_param", item, "NAME=VALUE, VALUE a number")
        given[name.strip()] = value
    from ..userwell import check_well, load_well

    well = load_well(args.well)
    return well, given, check_well(well, **given)


def parameters_text(parameters: dict[str, float]) -> str:
    """A user's well's parameter values as the commands print them.

    Examples
    --------
    >>> parameters_text({"a": 0.3, "n": 4.0}), parameters_text({})
    ('a=0.3 n=4', '(no parameters)')
    """
    return " ".join(f"{k}={v:g}" for k, v in parameters.items()) or "(no parameters)"


def well_text(well) -> str:
    """The parameters of the well of a sink as the commands print them: a registered
    shape's alpha, beta, n and gamma, a user's well's own (:func:`parameters_text`).

    Examples
    --------
    >>> from sinktheory.model import Well
    >>> well_text(Well(0.5, 0.3, 4))
    'alpha=0.5 beta=0.3 n=4 gamma=1'
    """
    if hasattr(well, "definition"):  # a user's well (sinktheory.wellat.WellAt)
        return parameters_text(well.parameters)
    return f"alpha={well.alpha:g} beta={well.beta:g} n={well.n} gamma={well.gamma:g}"


def sink_well_from_args(args: argparse.Namespace):
    """The well of a command that takes ``--well`` beside the shape options: a user's
    :class:`~sinktheory.wellat.WellAt` (the file at the ``--well-param`` values), else the
    :class:`~sinktheory.model.Well` of the shape options (:func:`well_from_args`)."""
    user = user_well_from_args(args)
    if user is None:
        return well_from_args(args)
    from ..wellat import WellAt

    return WellAt(user[0], **user[1])


def well_from_args(args: argparse.Namespace):
    """The :class:`~sinktheory.model.Well` of the well options (for a command that also
    takes ``--well``, when it is not given: --alpha, --beta and --n are required then)."""
    from ..model import Well

    for name in ("alpha", "beta", "n"):
        if hasattr(args, name) and getattr(args, name) is None:
            raise ParameterError(name, None, "given (or --well FILE instead of the shape)")
    gamma = 1.0 if args.gamma is None else args.gamma
    shape = "flat" if args.shape is None else args.shape
    return Well(args.alpha, args.beta, args.n, gamma=gamma, shape=shape)


def add_sink_arguments(
    parser: argparse.ArgumentParser,
    *,
    runs_default: int | None = 25,
    runs_help: str = "ensemble size, integer >= 1 (default 25)",
):
    """Options of the particles and the run: particles, mass, container energy, runs,
    periods, seed.

    Returns the argument group, so a command can add options of its own to it.
    """
    g = add_particle_arguments(parser, "sink and run")
    g.add_argument("--runs", type=number, default=runs_default, help=runs_help)
    g.add_argument(
        "--periods", type=number, default=1500, help="periods T = 2 pi, integer >= 1 (default 1500)"
    )
    g.add_argument("--seed", type=number, default=0, help="random seed, integer >= 0 (default 0)")
    return g


def add_particle_arguments(parser: argparse.ArgumentParser, title: str):
    """Options of the particles and the start: particles, mass, container energy (E0, the
    particles at rest), in a new argument group called ``title``, which is returned."""
    g = parser.add_argument_group(title)
    g.add_argument("--particles", type=number, default=1, help="k, integer >= 1 (default 1)")
    g.add_argument(
        "--mass", type=number, default=0.2, help="total particle mass m > 0 (default 0.2)"
    )
    g.add_argument(
        "--container-energy",
        type=number,
        default=0.5,
        help="the container's initial energy E0 > 0 (default 0.5)",
    )
    return g


def rigid_limit(args: argparse.Namespace, unsupported: dict[str, object] | None = None) -> bool:
    """True when ``--n inf`` asks for the rigid limit n -> oo; then each option named in
    ``unsupported`` (option -> its value) must be unset (None, False or 0), else it is
    refused: the billiard engine has no use for it.

    Examples
    --------
    >>> rigid_limit(argparse.Namespace(n=float("inf")), {"--dt": None})
    True
    >>> rigid_limit(argparse.Namespace(n=float("inf")), {"--dt": 0.1})
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: --dt = 0.1 is not allowed: must be left out with \
--n inf (not available for the rigid billiard)
    """
    from ..validation import stiffness

    if stiffness("n", args.n) != math.inf:
        return False
    for name, value in (unsupported or {}).items():
        if value not in (None, False, 0):
            raise ParameterError(
                name, value, "left out with --n inf (not available for the rigid billiard)"
            )
    return True


def png_path(name: str, value: str | None) -> Path | None:
    """Validate an output PNG path: suffix .png, a file we can create (see :func:`output_file`)."""
    return output_file(name, value, (".png",))


def output_file(name: str, value: str | None, suffixes: Iterable[str]) -> Path | None:
    """Check, before any computing, that the file ``value`` can be written.

    The name must end in one of ``suffixes``; the path must not be a directory or a
    special file; its directory must exist and accept a new file (tried with a probe
    file that is removed at once).  Raises ParameterError naming ``name`` otherwise.
    """
    if value is None:
        return None
    suffixes = tuple(suffixes)
    allowed = "a file name ending in " + " or ".join(suffixes)
    if not str(value).strip():
        raise ParameterError(name, value, allowed)
    path = Path(value)
    if path.suffix.lower() not in suffixes:
        raise ParameterError(name, value, allowed)
    if path.is_dir():
        raise ParameterError(name, value, allowed, why="it is a directory")
    if path.exists() and not path.is_file():
        raise ParameterError(name, value, allowed, why="it exists and is not a regular file")
    writable_directory(name, value, path.parent)
    return path


def output_directory(name: str, value: str | None) -> Path | None:
    """Check, before any computing, that directory ``value`` exists and can take new files,
    or can be created (its nearest existing ancestor takes new files)."""
    if value is None:
        return None
    if not str(value).strip():
        raise ParameterError(name, value, "a directory name (not empty)")
    path = Path(value)
    if path.exists() and not path.is_dir():
        raise ParameterError(name, value, "a directory", why="it exists and is not a directory")
    writable_directory(name, value, existing_ancestor(path))
    return path


def existing_ancestor(path: Path) -> Path:
    """``path`` itself if it exists, else its nearest existing ancestor."""
    path = Path(os.path.abspath(path))
    while not path.exists() and path != path.parent:
        path = path.parent
    return path


def as_directory(write: Callable[[Path], None]) -> Callable[[Path], None]:
    """Mark an output writer as one that fills a directory (see :func:`write_outputs`)."""
    write.directory = True  # type: ignore[attr-defined]
    return write


def write_outputs(writers: dict[Path, Callable[[Path], None]]) -> None:
    """Write every output or none.

    Each writer writes a hidden staging file (same directory, same suffix, so matplotlib
    still knows the format) or, for a directory writer, a hidden staging directory; only
    when all have succeeded are they moved into place (``os.replace``).  On any error the
    staged files are removed and the error is raised: no output is left half-written.
    """
    staged: list[tuple[Path, Path, bool]] = []
    try:
        for path, write in writers.items():
            path = Path(path)
            directory = bool(getattr(write, "directory", False))
            tag = uuid.uuid4().hex[:12]
            if directory:
                tmp = existing_ancestor(path) / f".sinktheory-partial-{tag}"
            else:
                tmp = path.with_name(f".{path.stem}.partial-{tag}{path.suffix}")
            staged.append((tmp, path, directory))
            try:
                write(tmp)
            except OSError as e:  # name the output, not the hidden staging file (or none)
                raise OSError(e.errno, e.strerror or str(e), str(path)) from e
        for tmp, path, directory in staged:
            if directory:
                path.mkdir(parents=True, exist_ok=True)
                for child in tmp.iterdir():
                    os.replace(child, path / child.name)
                tmp.rmdir()
            else:
                os.replace(tmp, path)
    finally:
        for tmp, _, directory in staged:
            if directory:
                shutil.rmtree(tmp, ignore_errors=True)
            elif tmp.exists():
                tmp.unlink()


def add_fractions_argument(group, default, what: str) -> None:
    """``--fractions F ...``: fractions f in (0, 1) of the total energy (``what`` says what
    they select), checked by the equilibrium law."""
    group.add_argument(
        "--fractions",
        type=number,
        nargs="+",
        default=list(default),
        metavar="F",
        help=f"fractions f in (0, 1) {what} (default {' '.join(map(str, default))})",
    )
