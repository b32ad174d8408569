"""The README and the docs stay true: every `sinktheory ...` command and option they quote
exists.

Command lines are read from the README's shell code blocks (continuation lines joined) and
inline code spans, and from the RST pages of docs/ (``code`` blocks and ````literal````
spans: the command table of docs/guide/overview.rst, the guides); each names a subcommand
of the real parser and only options that subcommand (or the top-level parser) accepts.  Placeholders
(``...``, ``KIND``, ``FILE.png``) and values are not options, so only the words that look
like options (``--name``) are checked.
"""

import re
from pathlib import Path

import pytest

from sinktheory.cli import build_parser
from sinktheory.commands import HELP

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
DOCS = ROOT / "docs"
#: The page with the table of every command (moved out of the README, which links to it).
OVERVIEW = DOCS / "guide" / "overview.rst"
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


def rst_command_lines(text: str) -> list[str]:
    """Every quoted ``sinktheory <word> ...`` command line of an RST page: the lines of its
    ``code``/``code-block`` blocks (continuations joined) and its ````literal```` spans."""
    lines, block = [], None
    for line in text.splitlines() + [""]:
        if block is not None and (not line.strip() or line.startswith(" ")):
            block.append(line)
            continue
        if block is not None:  # the block ended: read its commands
            joined = re.sub(r"\\\n\s*", " ", "\n".join(block))
            for code in joined.splitlines():
                lines += re.findall(r"\bsinktheory\s+[^&;#]*", code)
            block = None
        if re.match(r"\.\. code(-block)?::", line.strip()):
            shell = line.split("::", 1)[1].strip() in ("bash", "sh", "console", "")
            block = [] if shell else None
    for span in re.findall(r"``([^`]+)``", text.replace("\n", " ")):
        lines += re.findall(r"\bsinktheory\s+[^&;]*", span)
    return [" ".join(line.split()) for line in lines]


def quoted_lines() -> list[str]:
    """The command lines quoted by the README and every RST page of the docs."""
    lines = command_lines(README.read_text())
    for page in sorted(DOCS.rglob("*.rst")):
        lines += rst_command_lines(page.read_text())
    return sorted(set(lines))


def parsers():
    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    return parser, sub.choices


def test_the_readme_quotes_commands():
    lines = command_lines(README.read_text())
    assert len(lines) >= 5
    assert "sinktheory reproduce --out out/" in lines


def test_the_docs_quote_commands_too():
    assert len(rst_command_lines(OVERVIEW.read_text())) > 20
    assert len(quoted_lines()) > len(set(command_lines(README.read_text()))) + 20


@pytest.mark.parametrize("line", quoted_lines())
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
    table = re.findall(r"^   \* - ``sinktheory (\w+)", OVERVIEW.read_text(), re.M)
    named = set(table)
    assert named == set(HELP), set(HELP) ^ named


def test_the_extractor_sees_wrong_commands():
    """The check can fail: a made-up option and command are caught."""
    text = "```bash\nsinktheory well --alpha 1 \\\n    --no-such 2\n```\nand `sinktheory nope --x`"
    lines = command_lines(text)
    assert lines == ["sinktheory well --alpha 1 --no-such 2", "sinktheory nope --x"]
    rst = (
        ".. code:: bash\n\n   sinktheory well --alpha 1 \\\n       --no-such 2\n\n"
        ".. code:: python\n\n   import sinktheory as st\n\nand ``sinktheory nope --x``\n"
    )
    assert rst_command_lines(rst) == lines
    _, subparsers = parsers()
    assert "--no-such" not in subparsers["well"]._option_string_actions
    assert "nope" not in subparsers
