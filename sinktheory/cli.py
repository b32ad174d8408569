"""The ``sinktheory`` command.

Bad input prints one line on stderr and exits with status 2, writing nothing; a
numerical failure exits with status 1 and says where it happened.
"""

from __future__ import annotations

import argparse
import json
import re
import sys

from . import __version__
from .commands import COMMANDS
from .commands._common import write_outputs
from .errors import NumericalError, ParameterError

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


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="sinktheory",
        description="The stochastic energy sink (Pilipchuk, arXiv:1610.02939): "
        "symbolic model, periods, Floquet charts, simulations.",
    )
    parser.add_argument("--version", action="version", version=f"sinktheory {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for module in COMMANDS:
        p = sub.add_parser(module.NAME, help=module.HELP, description=module.HELP)
        module.add_arguments(p)
        p.set_defaults(module=module)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except UsageError as e:
        print(e, file=sys.stderr)
        return 2
    prog = f"sinktheory {args.command}"
    try:
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
