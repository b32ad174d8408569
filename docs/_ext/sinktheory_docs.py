"""Sphinx directives that build the sinktheory pages from the code itself.

``.. symbolic:: EXPR``
    Evaluates the Python expression EXPR (names available: ``S`` =
    :mod:`sinktheory.symbolic`, ``sp`` = sympy, and every public name of
    :mod:`sinktheory.symbolic`, such as ``x``, ``beta``, ``SHAPES``) and renders the
    result with :func:`sympy.latex` as a display equation.  Options:

    ``:lhs:``
        LaTeX written before ``=``.  With ``:each-shape:`` it may contain ``{shape}``.
    ``:zero:``
        Render ``EXPR = 0`` (for expressions that are equations set to zero).
    ``:each-shape:``
        Repeat for every well shape in ``sinktheory.symbolic.SHAPES`` (the name
        ``shape`` is bound in EXPR), so a new shape appears without editing the page.

    No formula on the theory pages is typed by hand: they are all computed here.

``.. cli-reference::``
    One section per subcommand of ``sinktheory.cli.build_parser()``: description,
    usage and every option with its help text (the same text ``--help`` prints).

``.. paper-gallery::``
    The figures of ``sinktheory reproduce --quick``, run in a subprocess while the other
    pages are read, each with the claims it checks and their verdicts.  Images go to
    ``docs/_autogen/gallery/`` (ignored by git).  Set ``SINKTHEORY_DOCS_REUSE_GALLERY=1``
    to reuse the last run instead of reproducing again (for quick local rebuilds).

The extension also empties ``docs/api/generated/`` before autosummary writes its stub
pages, so a module that was moved or deleted leaves no stale page behind, and copies the
notebooks of ``../notebooks/`` into ``docs/notebooks/`` (ignored by git), where myst-nb
executes and renders them; their kernels import the same sinktheory as the build.
"""

from __future__ import annotations

import argparse
import functools
import inspect
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import types
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import directives
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

logger = logging.getLogger(__name__)

HERE = Path(__file__).resolve().parent
DOCS = HERE.parent
AUTOGEN = DOCS / "_autogen"
GALLERY = AUTOGEN / "gallery"
API_GENERATED = DOCS / "api" / "generated"
NOTEBOOKS_SOURCE = DOCS.parent / "notebooks"
NOTEBOOKS = DOCS / "notebooks"


# --- equations from the symbolic model ------------------------------------------------
_cache: dict[str, object] = {}


@functools.cache
def _namespace() -> dict:
    """Names for the expressions: the model's functions memoised (pages reuse results)."""
    import sympy as sp

    from sinktheory import symbolic

    ns = {}
    for name in dir(symbolic):
        if name.startswith("_"):
            continue
        value = getattr(symbolic, name)
        ns[name] = functools.cache(value) if inspect.isfunction(value) else value
    ns.update(S=types.SimpleNamespace(**ns), sp=sp)
    return ns


def _symbol_names() -> dict:
    """LaTeX for the few symbol names sympy cannot guess (dots for time derivatives)."""
    import sympy as sp

    from sinktheory import symbolic as S

    names = {
        S.xdd: r"\ddot{x}",
        S.ydd: r"\ddot{y}",
        sp.Symbol("xd", real=True): r"\dot{x}",
        S.Dx: r"D_x",
        S.Dy: r"D_y",
        S.wall_distance: r"(\alpha - \beta)",
    }
    return names


def _evaluate(expr: str, extra: dict | None = None):
    key = expr + repr(sorted((extra or {}).items()))
    if key not in _cache:
        ns = {**_namespace(), **(extra or {})}
        _cache[key] = eval(expr, ns)  # noqa: S307 - our own pages, our own expressions
    return _cache[key]


def _latex(value) -> str:
    import sympy as sp

    return sp.latex(value, symbol_names=_symbol_names())


ALIGN = "\x00"  # alignment point, "&" when a display has several lines


class SymbolicMath(SphinxDirective):
    required_arguments = 1
    final_argument_whitespace = True
    option_spec = {
        "lhs": directives.unchanged,
        "zero": directives.flag,
        "each-shape": directives.flag,
    }

    def run(self):
        from sinktheory import symbolic as S

        expr = self.arguments[0]
        shapes = S.SHAPES if "each-shape" in self.options else [None]
        lines = []
        for shape in shapes:
            extra = {"shape": shape} if shape is not None else {}
            try:
                value = _evaluate(expr, extra)
            except Exception as e:  # the page must say so, and -W fails the build
                raise self.error(f"symbolic: {expr!r} raised {type(e).__name__}: {e}") from e
            body = _latex(value)
            lhs = self.options.get("lhs")
            if lhs:
                if shape is not None:
                    lhs = lhs.replace("{shape}", rf"{{\text{{{shape}}}}}")
                body = f"{lhs} {ALIGN}= {body}"
            elif "zero" in self.options:
                body = f"{body} = 0"
                if shape is not None:
                    body = rf"\text{{{shape}:}} \quad {ALIGN} {body}"
            lines.append(body)
        # several lines are aligned at "=" (Sphinx wraps them in an aligned environment)
        lines = [line.replace(ALIGN, "&" if len(lines) > 1 else "") for line in lines]
        node = nodes.math_block("\n\n".join(lines), "\n\n".join(lines), nowrap=False, number=None)
        node["docname"] = self.env.docname
        node["label"] = None
        self.set_source_info(node)
        return [node]


# --- CLI reference ----------------------------------------------------------------------
def _section(directive: SphinxDirective, title: str, label: str) -> nodes.section:
    """A section with a title and an explicit label usable from :ref:."""
    section = nodes.section(ids=[label], names=[label])
    section += nodes.title(title, title)
    directive.state.document.note_explicit_target(section)
    return section


def _formatter(prog: str) -> argparse.HelpFormatter:
    return argparse.HelpFormatter(prog, width=78, max_help_position=30)


def _subparsers(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return dict(action.choices)
    return {}


def _options(parser: argparse.ArgumentParser) -> nodes.definition_list:
    fmt = parser._get_formatter()
    dl = nodes.definition_list()
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction) or action.help == argparse.SUPPRESS:
            continue
        term_text = fmt._format_action_invocation(action)
        help_text = fmt._expand_help(action) if action.help else ""
        extras = []
        if action.required and action.option_strings:
            extras.append("required")
        if action.choices is not None and not isinstance(action.choices, dict):
            extras.append("one of: " + ", ".join(map(str, action.choices)))
        if extras:
            help_text = f"{help_text} ({'; '.join(extras)})" if help_text else "; ".join(extras)
        item = nodes.definition_list_item()
        term = nodes.term()
        term += nodes.literal(term_text, term_text)
        item += term
        definition = nodes.definition()
        definition += nodes.paragraph(help_text, help_text)
        item += definition
        dl += item
    return dl


def _usage_block(text: str) -> nodes.literal_block:
    block = nodes.literal_block(text, text)
    block["language"] = "text"
    return block


class CliReference(SphinxDirective):
    has_content = False

    def run(self):
        from sinktheory.cli import build_parser

        parser = build_parser()
        parser.formatter_class = _formatter
        out: list[nodes.Node] = []
        usage = parser.format_usage().strip()
        out.append(nodes.paragraph(parser.description or "", parser.description or ""))
        out.append(_usage_block(usage))
        out.append(_options(parser))
        for name, sub in _subparsers(parser).items():
            sub.formatter_class = _formatter
            section = _section(self, f"sinktheory {name}", f"cli-{name}")
            if sub.description:
                section += nodes.paragraph(sub.description, sub.description)
            text = sub.format_usage().strip()
            section += _usage_block(text)
            section += _options(sub)
            out.append(section)
        return out


def _target(new) -> str:
    """A rename's new name, or what its function says for one that depends on the value."""
    return new if isinstance(new, str) else inspect.getdoc(new).splitlines()[0]


class NamesGlossary(SphinxDirective):
    """The glossary of :mod:`sinktheory.glossary`: every name with its option and its one
    meaning, then the names that changed (options per command, sweep parameters, keywords
    per function)."""

    has_content = False

    def run(self):
        import importlib
        import pkgutil

        import sinktheory
        from sinktheory import glossary as g

        for info in pkgutil.walk_packages(sinktheory.__path__, "sinktheory."):
            importlib.import_module(info.name)  # each renamed() registers its keywords
        rows = [[f"``{name}``", g.option_of(name), meaning]
                for name, meaning in sorted(g.GLOSSARY.items())]  # fmt: skip
        names = _section(self, "Names and their meanings", "glossary-names")
        names += _table(["keyword", "option", "meaning"], rows, [20, 22, 58])
        options = _section(self, "Renamed options", "glossary-renamed-options")
        rows = [[f"sinktheory {command}", old, _target(new)]
                for command, table in sorted(g.RENAMED_OPTIONS.items())
                for old, new in table.items()]  # fmt: skip
        rows += [["sinktheory sweep", f"--param {old}=...", f"--param {new}=..."]
                 for old, new in g.RENAMED_PARAMETERS.items()]  # fmt: skip
        options += _table(["command", "old option", "now"], rows, [30, 30, 40])
        keywords = _section(self, "Renamed keywords", "glossary-renamed-keywords")
        rows = [[where, old, _target(new)]
                for where, table in sorted(g.RENAMED_KEYWORDS.items())
                for old, new in table.items()]  # fmt: skip
        keywords += _table(["function", "old keyword", "now"], rows, [50, 20, 30])
        return [names, options, keywords]


# --- gallery of the paper's figures -----------------------------------------------------
def _start_reproduce(app, env, docnames) -> None:
    """Start ``sinktheory reproduce --quick`` if the gallery page is about to be read."""
    app._sinktheory_gallery = None
    if "gallery" not in docnames:
        return
    reuse = os.environ.get("SINKTHEORY_DOCS_REUSE_GALLERY") == "1"
    if reuse and (GALLERY / "reproduce.json").exists():
        return
    AUTOGEN.mkdir(exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix="gallery-", dir=AUTOGEN))
    env_vars = {**os.environ, "MPLBACKEND": "Agg"}
    cmd = [sys.executable, "-m", "sinktheory", "reproduce", "--quick", "--out", str(tmp), "--json"]
    proc = subprocess.Popen(
        cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env_vars
    )
    app._sinktheory_gallery = (proc, tmp)
    logger.info("gallery: started %s", " ".join(cmd[1:]))


def _gallery_results(app) -> dict:
    """Wait for the reproduction (if running) and return its JSON."""
    pending = getattr(app, "_sinktheory_gallery", None)
    if pending is not None:
        proc, tmp = pending
        app._sinktheory_gallery = None
        stdout, stderr = proc.communicate()
        try:
            data = json.loads(stdout)
        except json.JSONDecodeError:
            shutil.rmtree(tmp, ignore_errors=True)
            raise RuntimeError(
                f"sinktheory reproduce --quick failed (status {proc.returncode}): {stderr}"
            ) from None
        if proc.returncode != 0:
            logger.warning("gallery: sinktheory reproduce exited %d: %s", proc.returncode, stderr)
        (tmp / "reproduce.json").write_text(json.dumps(data, indent=1))
        shutil.rmtree(GALLERY, ignore_errors=True)
        tmp.rename(GALLERY)
    return json.loads((GALLERY / "reproduce.json").read_text())


def _stop_reproduce(app, exception) -> None:
    pending = getattr(app, "_sinktheory_gallery", None)
    if pending is not None:
        proc, tmp = pending
        proc.kill()
        proc.communicate()
        shutil.rmtree(tmp, ignore_errors=True)


def _titles() -> dict[int, str]:
    """Figure titles from the report's headings ("## Fig. 8: ...")."""
    report = GALLERY / "report.md"
    if not report.exists():
        return {}
    return {
        int(m.group(1)): m.group(2).strip()
        for m in re.finditer(r"^## Fig\. (\d+): (.+)$", report.read_text(), re.M)
    }


def _table(header: list[str], rows: list[list[str]], widths: list[int]) -> nodes.table:
    table = nodes.table()
    group = nodes.tgroup(cols=len(header))
    table += group
    for w in widths:
        group += nodes.colspec(colwidth=w)

    def row(cells):
        r = nodes.row()
        for c in cells:
            entry = nodes.entry()
            entry += nodes.paragraph(c, c)
            r += entry
        return r

    head = nodes.thead()
    head += row(header)
    group += head
    body = nodes.tbody()
    for cells in rows:
        body += row(cells)
    group += body
    return table


class PaperGallery(SphinxDirective):
    has_content = False

    def run(self):
        try:
            data = _gallery_results(self.env.app)
        except (RuntimeError, OSError) as e:
            raise self.error(str(e)) from e
        titles = _titles()
        self.env.note_dependency(str(GALLERY / "reproduce.json"))
        out: list[nodes.Node] = []
        for fig in data["figures"]:
            number = fig["figure"]
            title = f"Fig. {number}: {titles.get(number, '')}".rstrip(": ")
            section = _section(self, title, f"gallery-fig{number:02d}")
            if fig.get("error"):
                msg = f"The quick reproduction of this figure failed: {fig['error']}"
                section += nodes.paragraph(msg, msg)
                logger.warning("gallery: Fig. %d failed: %s", number, fig["error"])
            else:
                image = nodes.image(uri=f"/_autogen/gallery/{fig['image']}", alt=title)
                image["width"] = "100%"
                section += image
                caption = f"computed in {fig['seconds']:.1f} s (quick preview)"
                section += nodes.paragraph(caption, caption)
            if fig["claims"]:
                rows = [[c["statement"], c["measured"], c["verdict"]] for c in fig["claims"]]
                section += _table(["claim", "measured", "verdict"], rows, [35, 50, 15])
            out.append(section)
        return out


# --- plain-text math in docstrings ----------------------------------------------------------
_LONE_STAR = re.compile(r"(?<=, )\*(?=[A-Za-z_][^*]*$)")


def _escape_prose(text: str) -> str:
    """Escape ``|`` and star-unpacking ``, *name`` outside inline literals."""
    parts = text.split("``")
    for i in range(0, len(parts), 2):  # even parts are outside ``...``
        parts[i] = _LONE_STAR.sub(r"\\*", parts[i].replace("|", r"\|"))
    return "``".join(parts)


def escape_plain_math(app, what, name, obj, options, lines: list[str]) -> None:
    """Let docstrings keep their plain-text math (``|x|``, ``(len(i), *dims)``).

    The package's docstrings are written to read well in ``help()``: absolute values as
    ``|x|`` and shapes as ``(len(indices), *extra)``.  reStructuredText reads ``|x|`` as a
    substitution and ``*extra`` as unterminated emphasis; no docstring uses either
    construct, so ``|`` and ``, *name`` are escaped in prose.  Inline literals,
    doctests and literal blocks (after ``::``) are left exactly as written.
    """
    literal_indent: int | None = None  # indentation of the paragraph that opened a ``::``
    in_doctest = False
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        indent = len(line) - len(stripped)
        if not stripped:
            in_doctest = False
            continue
        if literal_indent is not None:
            if indent > literal_indent:
                continue
            literal_indent = None
        if stripped.startswith(">>>") or in_doctest:
            in_doctest = True
            continue
        escaped = line[:indent] + _escape_prose(stripped)
        underline = lines[i + 1].strip() if i + 1 < len(lines) else ""
        if escaped != line and len(set(underline)) == 1 and len(underline) >= len(line):
            lines[i + 1] = underline[0] * len(escaped)  # keep a section title's underline long
        lines[i] = escaped
        if stripped.endswith("::"):
            literal_indent = indent


# --- API stubs ------------------------------------------------------------------------
def _clean_api_stubs(app) -> None:
    """Remove autosummary's stub pages so moved or deleted modules leave nothing stale."""
    shutil.rmtree(API_GENERATED, ignore_errors=True)


# --- notebooks ----------------------------------------------------------------------------
def _copy_notebooks(app) -> None:
    """Mirror ``../notebooks/*.ipynb`` into ``docs/notebooks/`` for myst-nb.

    A notebook whose bytes did not change is left alone (its time stamp too), so an
    incremental build does not execute it again; one deleted from ``../notebooks/`` is
    deleted here.  The kernels myst-nb starts inherit ``PYTHONPATH``: the imported
    sinktheory's folder goes first, so the notebooks run the code these pages document
    rather than some other installed copy.
    """
    if not NOTEBOOKS_SOURCE.is_dir():
        logger.warning("notebooks: %s not found, no notebook pages", NOTEBOOKS_SOURCE)
        return
    NOTEBOOKS.mkdir(exist_ok=True)
    wanted = {p.name: p for p in NOTEBOOKS_SOURCE.glob("*.ipynb")}
    for stale in NOTEBOOKS.glob("*.ipynb"):
        if stale.name not in wanted:
            stale.unlink()
    for name, source in wanted.items():
        target = NOTEBOOKS / name
        if not target.exists() or target.read_bytes() != source.read_bytes():
            shutil.copyfile(source, target)
    import sinktheory

    root = str(Path(sinktheory.__file__).resolve().parents[1])
    paths = [root] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    os.environ["PYTHONPATH"] = os.pathsep.join(dict.fromkeys(paths))


def setup(app):
    app.add_directive("symbolic", SymbolicMath)
    app.add_directive("cli-reference", CliReference)
    app.add_directive("names-glossary", NamesGlossary)
    app.add_directive("paper-gallery", PaperGallery)
    app.connect("builder-inited", _clean_api_stubs, priority=100)  # before autosummary
    app.connect("builder-inited", _copy_notebooks)  # before the sources are listed
    app.connect("env-before-read-docs", _start_reproduce)
    app.connect("build-finished", _stop_reproduce)
    app.connect("autodoc-process-docstring", escape_plain_math, priority=100)  # before numpydoc
    return {"version": "1", "parallel_read_safe": False, "parallel_write_safe": True}
