"""Every command names a refused value by its keyword (issue 34).

The convention: a value the command refuses is named as Python names it, the option's
``dest`` (``plot = 'x.txt' is not allowed: ...``, ``container_energy = nan ...``), not as
the option (``--plot``); only a refusal of an option's presence ("left out with --n inf",
"absent with --stepper fixed") names the ``--option``.  The cases are walked from the
parsers: every output option of every command with the empty path, every numeric option
with NaN and every free-text option with "bogus", each added to a valid command line (220
in-process refusals, about 6 s).
"""

import argparse

import pytest
from _cli import refused

from sinktheory.cli import build_parser
from sinktheory.commands._common import number

WELL = ["--alpha", "0.5", "--beta", "0.3", "--n", "4"]
RUN = ["--runs", "2", "--periods", "2"]
PARAMS = ["--param", "alpha=0.5", "--param", "beta=0.1,0.2", "--param", "n=4"]
#: command -> a valid command line (after the command's name) that one bad option joins.
BASE = {
    "well": WELL,
    "sink": WELL,
    "derive": [],
    "simulate": [*WELL, *RUN, "--quiet"],
    "period": ["--n", "4", "--amplitude", "0.5"],
    "series": ["--n", "2", "--order", "2"],
    "reproduce": ["--figure", "2", "--quick", "--out", "figures"],
    "floquet": ["--alpha", "0.5", "--n", "4", "--beta", "0.1"],
    "nnm": [*WELL, "--continue-in", "energy"],
    "chaos": [*WELL, *RUN, "--quiet"],
    "design": ["--beta", "0.3", "--n", "4", "--out", "d.zarr", "--quiet"],
    "billiard": ["--alpha", "0.5", "--beta", "0.3", *RUN],
    "equilibrium": WELL,
    "lifetime": [*WELL, "--runs", "2", "--periods", "60"],
    "relaxation": WELL,
    "compare": ["--damping", "0.01"],
    "sweep": ["floquet", *PARAMS, "--out", "s.zarr"],
}
#: (command, option) -> the valid line it joins instead, where the base line would refuse
#: the option's presence (a scheme's option with the other stepper, the excluded one of
#: --beta, --lam and the ranges).
OTHER_BASE = {
    ("simulate", "eps"): [*BASE["simulate"], "--stepper", "adaptive"],
    ("floquet", "lam"): ["--n", "4"],
    ("floquet", "lam_range"): ["--n", "4"],
    ("floquet", "beta_range"): ["--alpha", "0.5", "--n", "4"],
}
#: The options that name a file or directory the command writes.
OUTPUTS = {"plot", "out", "wavelet_plot", "report"}


def _actions():
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    for command, p in sorted(sub.choices.items()):
        for a in p._actions:
            if a.option_strings and a.dest != "help":
                yield command, a


def _without(base: list[str], option: str) -> list[str]:
    """``base`` without ``option`` and its values (a bad value replaces a good one)."""
    if option not in base:
        return list(base)
    i = base.index(option)
    j = i + 1
    while j < len(base) and not base[j].startswith("--"):
        j += 1
    return base[:i] + base[j:]


def _case(command: str, action, value: str) -> list[str]:
    base = OTHER_BASE.get((command, action.dest), BASE[command])
    option = action.option_strings[0]
    count = action.nargs if isinstance(action.nargs, int) else 1
    return [command, *_without(base, option), option, *[value] * count]


OUTPUT_CASES = [(c, a.dest, _case(c, a, "")) for c, a in _actions() if a.dest in OUTPUTS]
NUMBER_CASES = [(c, a.dest, _case(c, a, "nan")) for c, a in _actions() if a.type is number]
#: Free-text options given "bogus" (argparse refuses a bad choice itself, naming the
#: option; a well file's refusal is a WellDefinitionError, "WHERE: TOKEN is refused: ...",
#: tested in test_well_file_*).
TEXT_CASES = [
    (c, a.dest, _case(c, a, "bogus"))
    for c, a in _actions()
    if a.type is None and a.nargs != 0 and not a.choices and a.dest not in OUTPUTS | {"well"}
]
#: Values that used to be blamed on another parameter.
BLAMED_CASES = [
    ("compare", "shapes", ["compare", *BASE["compare"], "--shapes", "square"]),  # shape
    ("design", "well_param", ["design", *BASE["design"], "--well-param", "a"]),  # --param
    ("lifetime", "periods", ["lifetime", *WELL, "--runs", "2", "--periods", "4"]),  # transient
]


def test_the_walk_sees_the_commands():
    """Every command is on the walk with a base line, and the walk finds what it must."""
    assert {c for c, _ in _actions()} == set(BASE)
    assert {c for c, _, _ in OUTPUT_CASES} >= {"simulate", "chaos", "compare", "billiard", "well",
                                                "design", "sweep", "reproduce"}  # fmt: skip
    assert ("compare", "wavelet_plot") in {(c, d) for c, d, _ in OUTPUT_CASES}
    assert len(NUMBER_CASES) > 100


CASES = OUTPUT_CASES + NUMBER_CASES + TEXT_CASES + BLAMED_CASES


@pytest.mark.parametrize(("command", "name", "argv"), CASES,
                         ids=lambda x: x if isinstance(x, str) else None)  # fmt: skip
def test_a_refused_value_is_named_by_its_keyword(command, name, argv, capsys, tmp_path,
                                                 monkeypatch):  # fmt: skip
    line = refused(argv, capsys, tmp_path, monkeypatch, name)
    assert line.startswith(f"sinktheory {command}: error: {name} = "), line


@pytest.mark.parametrize(
    ("argv", "option", "says"),
    [
        (["simulate", *BASE["simulate"], "--eps", "0.25"], "--eps", "absent with --stepper"),
        (["simulate", *WELL[:-1], "inf", *RUN, "--dt", "0.1"], "--dt", "left out with --n inf"),
    ],
)
def test_a_refused_presence_is_named_by_its_option(argv, option, says, capsys, tmp_path,
                                                   monkeypatch):  # fmt: skip
    line = refused(argv, capsys, tmp_path, monkeypatch, option)
    assert line.startswith(f"sinktheory simulate: error: {option} = ") and says in line, line
