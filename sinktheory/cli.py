"""The ``sinktheory`` command.

Bad input prints one line on stderr and exits with status 2, writing nothing; a
numerical failure exits with status 1 and says where it happened.  Ctrl-C (SIGINT) or
SIGTERM prints one line and exits with status 130 or 143, writing nothing (commands
that keep a store add how to resume it).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import re
import signal
import sys

from . import commands
from .commands._common import interruptible, settle_zarr, write_outputs
from .errors import NumericalError, ParameterError
from .glossary import modern_argv

__all__ = ["build_parser", "main", "NEGATIVE_NUMBER", "UsageError"]

#: What argparse should read as a negative number, not an option: decimal and scientific
#: literals and -inf / -nan (argparse's own pattern knows only -1 and -1.5).
NEGATIVE_NUMBER = re.compile(
    r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.IGNORECASE
)


class UsageError(Exception):
    """An argument argparse could not parse."""


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = NEGATIVE_NUMBER  # "--lam -1e308" is a value

    def error(self, message: str):  # one line, no usage dump
        raise UsageError(f"{self.prog}: error: {message}")


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The parser of ``sinktheory``.

    With ``only`` (a command name) just that command gets its options and the others are
    listed by name and summary, so their modules (and what they import) are not loaded;
    this keeps ``--version``, ``--help`` and light commands fast.  Without it every
    command is built in full.
    """
    parser = _Parser(
        prog="sinktheory",
        description="The stochastic energy sink (Pilipchuk, arXiv:1610.02939): "
        "symbolic model, periods, Floquet charts, simulations.",
    )
    parser.add_argument("--version", action="version", version=f"sinktheory {_version()}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, summary in commands.HELP.items():
        # argparse %-formats help strings (not descriptions): a literal % is doubled
        p = sub.add_parser(name, help=summary.replace("%", "%%"), description=summary)
        if only is None or name == only:
            module = commands.load(name)
            module.add_arguments(p)
            p.set_defaults(module=module)
    return parser


def _version() -> str:
    from . import __version__

    return __version__


def _command(argv: list[str]) -> str | None:
    """The command named in ``argv``: its first word that is not an option."""
    for word in argv:
        if not word.startswith("-"):
            return word if word in commands.HELP else None
    return None


def _no_well(argv: list[str], command: str | None) -> str | None:
    """The one-line refusal of ``--well FILE`` (or ``--well-param``) given to a command
    that cannot use a user's well (its module's ``NO_WELL`` says why), else None.

    Examples
    --------
    >>> _no_well(["period", "--well", "w.toml", "--n", "4"], "period")  # doctest: +ELLIPSIS
    "well = 'w.toml' is not allowed: must be left out of period (it has no well: ..."
    >>> _no_well(["floquet", "--well", "w.toml"], "floquet") is None
    True
    """
    reason = getattr(commands.load(command), "NO_WELL", None) if command else None
    for i, word in enumerate(argv):
        name, _, value = word.partition("=")
        if reason and name in ("--well", "--well-param"):
            if not value and i + 1 < len(argv):
                value = argv[i + 1]
            return str(ParameterError(name[2:].replace("-", "_"), value or None,
                                      f"left out of {command} ({reason})"))  # fmt: skip
    return None


def main(argv: list[str] | None = None) -> int:
    """Run ``sinktheory ARGV`` (a list of strings; default: this process's own arguments)
    and return its exit status.  Without ``argv`` main is the process's command line
    (``python -m sinktheory``, the ``sinktheory`` script): an interrupt then ends the
    process at once (:func:`_exit_interrupted`); called with ``argv`` (tests, scripts), it
    raises SystemExit(130 or 143) instead."""
    whole = argv is None
    argv = sys.argv[1:] if argv is None else _words(argv)
    command = _command(argv)
    try:
        with interruptible(f"sinktheory {command}" if command else "sinktheory", hint=None):
            try:
                return _main(argv, command)
            finally:  # nothing may print after the command's last line
                settle_zarr()
    except SystemExit as e:
        if whole and e.code in INTERRUPTED:
            _exit_interrupted(e.code)
        raise


def _words(argv: object) -> list[str]:
    """``argv`` as a list of strings: a list or tuple of them, else a ParameterError naming
    ``argv`` (a string alone would be read letter by letter, a number not at all).

    >>> _words(("period", "--n", "2"))
    ['period', '--n', '2']
    >>> _words("period")
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: argv = 'period' is not allowed: must be a list of \
strings (the words of a command line) or None
    """
    if isinstance(argv, list | tuple) and all(isinstance(word, str) for word in argv):
        return list(argv)
    shown = argv if len(repr(argv)) <= 80 else f"a long {type(argv).__name__}"
    raise ParameterError("argv", shown, "a list of strings (the words of a command line) or None")


#: The exit statuses of an interrupt: SIGINT (Ctrl-C) and SIGTERM.
INTERRUPTED = (128 + signal.SIGINT, 128 + signal.SIGTERM)


def _exit_interrupted(status: int) -> None:
    """End an interrupted command's process now, its one line printed and its stores and
    worker processes closed.  Python's own tear-down of the imported modules takes 1-2 s
    once the compiled kernels, Dask and Zarr are loaded (measured at load 6), and a second
    Ctrl-C during it ended the process with status -2 (SIGINT's default action, which
    Python restores while tearing down): benchmarks/bench_interrupt_sweep.py --again 0.3,
    4 of 4.  So further signals are ignored and the process ends without the tear-down
    and without the exit handlers.  None is needed: the clean-ups ran before, in the
    ``finally`` blocks the interrupt passed through -- zarr's I/O settled
    (:func:`~sinktheory.commands._common.settle_zarr`), stores closed, a sweep's worker
    processes and forkserver ended and its pool freed, so that the pool's named
    semaphores are unlinked at once (:func:`sinktheory.sweep.runner._end_workers`; left
    over, the resource tracker would warn about them after the line)."""
    import os

    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, signal.SIG_IGN)
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    os._exit(status)


def _main(argv: list[str], command: str | None) -> int:
    argv, notes = modern_argv(argv)
    for note in notes:  # an old option name: works for one more release
        print(f"sinktheory {command}: note: {note} (the old name goes in the next release)",
              file=sys.stderr)  # fmt: skip
    parser = build_parser(command or "")
    refusal = _no_well(argv, command)
    if refusal:  # before argparse asks for the options a well file would replace
        print(f"sinktheory {command}: error: {refusal}", file=sys.stderr)
        return 2
    try:
        args = parser.parse_args(argv)
    except UsageError as e:
        print(e, file=sys.stderr)
        return 2
    prog = f"sinktheory {args.command}"
    try:
        hours = getattr(args, "max_hours", None)  # --max-hours; None: the default limit
        if hours is None:  # (worklimit imports numpy: not for a command refused early)
            limit = contextlib.nullcontext()
        else:
            from .worklimit import interactive_limit

            limit = interactive_limit(hours)
        if getattr(args, "quiet", False):  # no note before compiling an engine either
            notes = contextlib.nullcontext()
        else:
            from .engine.cache import compilation_notes

            notes = compilation_notes()
        with limit, notes:
            out = args.module.run(args)
        write_outputs(out.writers)
    except ParameterError as e:
        print(f"{prog}: error: {e}", file=sys.stderr)
        return 2
    except NumericalError as e:
        print(f"{prog}: numerical failure: {e}", file=sys.stderr)
        return 1
    except OSError as e:  # an output checked writable failed later (disk full, ...)
        print(f"{prog}: could not write {e.filename or ''}: {e.strerror or e}", file=sys.stderr)
        return 1
    if args.json:
        print(json.dumps(out.data, allow_nan=False))
    else:
        print(out.text)
    return out.exit_status


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
