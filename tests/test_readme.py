"""The README stays true: every `sinktheory ...` command and option it quotes exists.

Command lines are read from the README's shell code blocks (continuation lines joined) and
inline code spans (the command table, the prose); each names a subcommand of the real
parser and only options that subcommand (or the top-level parser) accepts.  Placeholders
(``...``, ``KIND``, ``FILE.png``) and values are not options, so only the words that look
like options (``--name``) are checked.
"""

import re
from pathlib import Path

import pytest

from sinktheory.cli import build_parser
from sinktheory.commands import HELP

README = Path(__file__).resolve().parents[1] / "README.md"
OPTION = re.compile(r"(?<![\w-])--[a-z][a-z0-9-]*")


def split_fences(text: str) -> tuple[list[str], str]:
    """The shell code blocks of a Markdown text and the text outside all code blocks."""
    blocks, prose, block, lang = [], [], None, ""
    for line in text.splitlines():
        if line.startswith("```"):
            if block is None:
                block, lang = [], line[3:].strip()
            else:
                if lang in ("bash", "sh", "console", ""):
                    blocks.append("\n".join(block))
                block = None
        elif block is None:
            prose.append(line)
        else:
            block.append(line)
    return blocks, "\n".join(prose)


def command_lines(text: str) -> list[str]:
    """Every quoted ``sinktheory <word> ...`` command line of a Markdown text."""
    blocks, prose = split_fences(text)
    lines = []
    for block in blocks:
        joined = re.sub(r"\\\n\s*", " ", block)
        for line in joined.splitlines():
            lines += re.findall(r"\bsinktheory\s+[^&;#]*", line)
    for span in re.findall(r"`([^`]+)`", prose.replace("\n", " ")):
        lines += re.findall(r"\bsinktheory\s+[^&;]*", span)
    return [" ".join(line.split()) for line in lines]


def parsers():
    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    return parser, sub.choices


def test_the_readme_quotes_commands():
    lines = command_lines(README.read_text())
    assert len(lines) > 20
    assert "sinktheory reproduce --out out/" in lines


@pytest.mark.parametrize("line", sorted(set(command_lines(README.read_text()))))
def test_quoted_command_exists_with_its_options(line):
    top, subparsers = parsers()
    word = line.split()[1]
    if word.startswith("-"):
        options, name = set(top._option_string_actions), None
    else:
        assert word in subparsers, f"{line!r}: no command {word!r}"
        name = word
        options = set(subparsers[word]._option_string_actions)
    unknown = [o for o in OPTION.findall(line) if o not in options]
    assert not unknown, f"{line!r}: {name or 'sinktheory'} has no option {unknown}"


def test_every_command_has_a_row_in_the_command_table():
    table = [line for line in README.read_text().splitlines() if line.startswith("| `sinktheory ")]
    named = {line.split()[2] for line in table}
    assert named == set(HELP), set(HELP) ^ named


def test_the_extractor_sees_wrong_commands():
    """The check can fail: a made-up option and command are caught."""
    text = "```bash\nsinktheory well --alpha 1 \\\n    --no-such 2\n```\nand `sinktheory nope --x`"
    lines = command_lines(text)
    assert lines == ["sinktheory well --alpha 1 --no-such 2", "sinktheory nope --x"]
    _, subparsers = parsers()
    assert "--no-such" not in subparsers["well"]._option_string_actions
    assert "nope" not in subparsers
