"""Shared by the CLI tests: run ``sinktheory`` in-process and capture its output."""

from sinktheory.cli import main


def run_cli(argv, capsys):
    """(exit status, stdout, stderr) of ``sinktheory ARGV``."""
    code = main(argv)
    out, err = capsys.readouterr()
    return code, out, err
