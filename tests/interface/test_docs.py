"""The documentation site builds with warnings as errors, and documents everything.

CI runs only pytest, so this is where the site is built in CI: the command of the
README's "Documentation" section (``sphinx-build -W --keep-going -b html docs OUT``),
into a temporary directory.  The build also runs ``sinktheory reproduce --quick`` for the
gallery and executes the notebooks (myst-nb), so it takes a minute or two; this is the
only place CI executes them.
"""

from __future__ import annotations

import functools
import importlib
import inspect
import os
import pkgutil
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

import sinktheory
from sinktheory.cli import build_parser

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    """Build a copy of docs/ (the build writes generated pages next to its sources, and
    two test runs at once must not share them) and return the HTML directory."""
    out = tmp_path_factory.mktemp("docs")
    ignore = shutil.ignore_patterns("_build", "_autogen", "generated", "notebooks", "__pycache__")
    shutil.copytree(DOCS, out / "docs", ignore=ignore)
    (out / "derivations").symlink_to(ROOT / "derivations")  # for literalinclude
    (out / "notebooks").symlink_to(ROOT / "notebooks")  # the build copies them in
    env = {k: v for k, v in os.environ.items() if k != "SINKTHEORY_DOCS_REUSE_GALLERY"}
    env["MPLBACKEND"] = "Agg"
    # -T: a crash (a notebook cell raising) prints its whole traceback, the cell's too
    cmd = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-T", "-b", "html"]
    cmd += ["-d", str(out / "doctrees"), str(out / "docs"), str(out / "html")]
    r = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=900)
    warnings = [
        line
        for line in r.stderr.splitlines()
        if ("WARNING" in line or "ERROR" in line) and not line.startswith(KERNEL_TCP_NOTE)
    ]
    assert r.returncode == 0 and not warnings, (
        f"sphinx-build failed (status {r.returncode}):\n" + "\n".join(warnings or [r.stderr])
    )
    return out / "html"


# ipykernel (7.x) logs this on its stderr whenever it listens on TCP, which is how every
# notebook runner starts it; the build's stderr carries it, but it is no docs warning
KERNEL_TCP_NOTE = "[IPKernelApp] WARNING | Kernel is running over TCP without encryption."


class _Tags(HTMLParser):
    """Scripts and stylesheets a page loads, and what a notebook's cell outputs hold."""

    def __init__(self, html: str):
        super().__init__(convert_charrefs=True)
        self.assets: list[str] = []  # src of <script>, href of <link rel=stylesheet>
        self.output_text: list[str] = []
        self.output_images: list[str] = []
        self.output_classes: list[str] = []
        self._divs: list[bool] = []  # for each open <div>: is it in a cell's output?
        self.feed(html)
        self.close()

    def handle_starttag(self, tag, attrs):
        a = {k: v or "" for k, v in attrs}
        if tag == "script" and a.get("src"):
            self.assets.append(a["src"])
        elif tag == "link" and "stylesheet" in a.get("rel", "").lower().split():
            self.assets.append(a.get("href", ""))
        inside = bool(self._divs) and self._divs[-1]
        if tag == "div":
            classes = a.get("class", "").split()
            self._divs.append(inside or "cell_output" in classes)
            if inside:
                self.output_classes += classes
        elif tag == "img" and inside:
            self.output_images.append(a.get("src", ""))

    def handle_endtag(self, tag):
        if tag == "div" and self._divs:
            self._divs.pop()

    def handle_data(self, data):
        if self._divs and self._divs[-1]:
            self.output_text.append(data)


REMOTE = re.compile(r"\s*(https?:|//)", re.I)
# the <script> and <link> tags of a page (quoted attribute values may hold a ">"): only
# these go through the HTML parser, which is slow on the large API pages
SCRIPT_OR_LINK = re.compile(r"""<(?:script|link)\b(?:[^>"']|"[^"]*"|'[^']*')*>""", re.I)


@functools.lru_cache(maxsize=4)
def _assets(html: str) -> tuple[str, ...]:
    tags = SCRIPT_OR_LINK.findall(html)
    # a <script> is closed at once, else the parser reads the tags after it as its code
    closed = [t + "</script>" if t[:7].lower() == "<script" else t for t in tags]
    return tuple(_Tags("".join(closed)).assets)


def _remote_assets(html: str) -> list[str]:
    return [url for url in _assets(html) if REMOTE.match(url)]


def _missing_local_assets(page: Path, html: str) -> list[str]:
    local = [url for url in _assets(html) if not REMOTE.match(url)]
    return [url for url in local if not (page.parent / url.split("?")[0]).is_file()]


def _bundled_mathjax(page: Path, html: str) -> Path | None:
    """The MathJax script a page loads, if it is the copy in the build's _static/."""
    for url in _assets(html):
        if REMOTE.match(url):
            continue
        path = (page.parent / url.split("?")[0]).resolve()
        if path.name == "tex-chtml.js" and path.parent.name == "mathjax":
            return path if path.is_file() else None
    return None


#: What each notebook's page must show: texts its cells print, and how many figures.
NOTEBOOK_PAGES = {
    "tour": (("stable intervals: [(", "max relative energy error"), 2),
    "your_own_well": (("largest |phi - cos(pi a/b)|: ", "escape energy - 1/6 = ", "refused: ",
                       "late <E_c> = "), 3),
}  # fmt: skip


def _notebook_problems(page: Path, html: str, needles=NOTEBOOK_PAGES["tour"][0],
                       images: int = 2) -> list[str]:  # fmt: skip
    """What is wrong with a rendered notebook: missing outputs, figures or an error."""
    tags = _Tags(html)
    text = "".join(tags.output_text)
    problems = [f"no output {needle!r}" for needle in needles if needle not in text]
    if "Traceback" in text or {"traceback", "stderr"} & set(tags.output_classes):
        problems.append("an error or stderr output")
    # the figures as PNG files, not "<Figure ...>"
    if len(tags.output_images) != images:
        problems.append(f"{len(tags.output_images)} images, not {images}")
    for src in tags.output_images:
        png = page.parent / src
        if not png.is_file() or png.stat().st_size < 1000:
            problems.append(f"image {src} missing or empty")
        elif png.read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
            problems.append(f"image {src} is no PNG")
    return problems


def _public_modules() -> list[str]:
    names = ["sinktheory"]
    for info in pkgutil.walk_packages(sinktheory.__path__, "sinktheory."):
        if not any(part.startswith("_") for part in info.name.split(".")):
            names.append(info.name)
    return names


def test_site_builds_without_warnings(site):
    for page in ("index", "getting_started", "cli", "gallery", "api/index", "theory/index"):
        assert (site / f"{page}.html").exists(), page


def test_no_page_loads_a_remote_script_or_stylesheet(site):
    """Opened without a network, every page has all it loads (math included)."""
    pages = sorted(site.rglob("*.html"))
    assert len(pages) > 50
    remote, missing, local = {}, {}, 0
    for page in pages:
        html = page.read_text()
        name = str(page.relative_to(site))
        remote[name] = _remote_assets(html)
        missing[name] = _missing_local_assets(page, html)
        local += len(_assets(html))
    assert local > 3 * len(pages)  # the check saw the pages' scripts and stylesheets
    assert not {k: v for k, v in remote.items() if v}, "loaded from another site"
    assert not {k: v for k, v in missing.items() if v}, "not in the build"


def test_pages_with_math_load_the_bundled_mathjax(site):
    with_math = []
    for page in sorted(site.rglob("*.html")):
        html = page.read_text()
        if 'class="math' in html:
            with_math.append(page.relative_to(site).as_posix())
            assert _bundled_mathjax(page, html), page
    assert {"theory/potential.html", "notebooks/tour.html"} <= set(with_math)
    mathjax = site / "_static" / "mathjax"
    assert (mathjax / "tex-chtml.js").stat().st_size > 100_000
    # the fonts MathJax's HTML output loads, relative to its script
    assert len(list((mathjax / "output" / "chtml" / "fonts" / "woff-v2").glob("*.woff"))) > 10


def test_the_checks_of_offline_pages_catch_a_remote_or_missing_file(tmp_path):
    remote = [
        '<script src="https://cdn.example.org/mathjax/tex-chtml.js"></script>',
        '<SCRIPT defer SRC="HTTP://cdn.example.org/a.js"></SCRIPT>',
        '<link rel="stylesheet" href="//fonts.example.org/a.css">',
        '<link href="https://example.org/a.css" rel="preload stylesheet">',
        '<script data-note="a > b" src="https://cdn.example.org/a.js"></script>',
        '<script src="_static/a.js"></script>\n<script src="https://cdn.example.org/b.js">',
    ]
    for tag in remote:
        assert _remote_assets(f"<html><head>{tag}</head></html>"), tag
    harmless = '<a href="https://arxiv.org/abs/1610.02939">paper</a><link rel="icon" href="//x">'
    assert not _remote_assets(harmless + '<script src="_static/a.js?v=1"></script>')
    page = tmp_path / "theory" / "page.html"
    page.parent.mkdir()
    local = '<script defer src="../_static/mathjax/tex-chtml.js"></script>'
    assert _missing_local_assets(page, local) == ["../_static/mathjax/tex-chtml.js"]
    assert _bundled_mathjax(page, local) is None  # referenced, but not in the build
    assert _bundled_mathjax(page, remote[0]) is None
    (tmp_path / "_static" / "mathjax").mkdir(parents=True)
    (tmp_path / "_static" / "mathjax" / "tex-chtml.js").write_text("//")
    assert _missing_local_assets(page, local) == []
    assert _bundled_mathjax(page, local) == tmp_path / "_static" / "mathjax" / "tex-chtml.js"


@pytest.mark.parametrize("name", sorted(NOTEBOOK_PAGES))
def test_each_notebook_is_a_page_with_its_outputs(site, name):
    """The docs build executed the notebook (committed without outputs) and shows what it
    printed and its figures; a cell that raised would have failed the build."""
    page = site / "notebooks" / f"{name}.html"
    needles, images = NOTEBOOK_PAGES[name]
    assert _notebook_problems(page, page.read_text(), needles, images) == []
    assert f"notebooks/{name}.html" in (site / "index.html").read_text()  # in the contents


def test_your_own_well_checks_itself_against_closed_forms(site):
    """The notebook's printed checks: the elliptic well's Floquet trace at n = 1 against
    cos(pi a / b) (held to 1e-10) and the Hénon–Heiles-type escape energy against 1/6
    (held to 1e-12)."""
    text = "".join(_Tags((site / "notebooks" / "your_own_well.html").read_text()).output_text)
    floquet = float(re.search(r"largest \|phi - cos\(pi a/b\)\|: (\S+)", text).group(1))
    escape = float(re.search(r"escape energy - 1/6 = (\S+)", text).group(1))
    assert floquet < 1e-10 and abs(escape) < 1e-12, (floquet, escape)


def test_the_notebook_check_catches_missing_figures_and_errors(tmp_path):
    def cell(body):
        return f'<div class="cell_output docutils container">{body}</div>'

    printed = (
        '<div class="output stream"><pre>stable intervals: [(-0.56, 0.0)]\n'
        "max relative energy error 2e-12</pre></div>"
    )
    (tmp_path / "a.png").write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(2000))
    (tmp_path / "b.png").write_bytes(b"<Figure size 800x450 with 1 Axes>" + bytes(2000))
    good = cell(printed) + cell('<img src="a.png">') + cell('<img src="a.png">')
    page = tmp_path / "tour.html"
    assert _notebook_problems(page, good) == []
    error = '<div class="output traceback"><pre>ZeroDivisionError</pre></div>'
    assert _notebook_problems(page, good + cell(error)) == ["an error or stderr output"]
    stderr = '<div class="output stderr"><pre>RuntimeWarning</pre></div>'
    assert _notebook_problems(page, good + cell(stderr)) == ["an error or stderr output"]
    # the printed text only in the code, not in an output
    source = '<div class="cell_input"><pre>print("stable intervals: [(")</pre></div>'
    assert len(_notebook_problems(page, source + cell('<img src="a.png">') * 2)) == 2
    one = cell(printed) + cell('<img src="a.png">')
    assert _notebook_problems(page, one) == ["1 images, not 2"]
    bad = cell(printed) + cell('<img src="a.png">') + cell('<img src="b.png">')
    assert _notebook_problems(page, bad) == ["image b.png is no PNG"]
    gone = cell(printed) + cell('<img src="a.png">') + cell('<img src="c.png">')
    assert _notebook_problems(page, gone) == ["image c.png missing or empty"]


def test_every_public_function_and_class_is_documented(site):
    """A newcomer finds every public module, function and class in the API reference."""
    missing = []
    for name in _public_modules():
        page = site / "api" / "generated" / f"{name}.html"
        if not page.exists():
            missing.append(name)
            continue
        html = page.read_text()
        module = importlib.import_module(name)
        for attr, obj in vars(module).items():
            if attr.startswith("_") or not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue
            if getattr(obj, "__module__", None) != name:
                continue  # imported from elsewhere: documented where it is defined
            if f'id="{name}.{attr}"' not in html:
                missing.append(f"{name}.{attr}")
    assert not missing, f"not in the API reference: {missing}"


def test_cli_reference_lists_every_subcommand_and_option(site):
    html = (site / "cli.html").read_text()
    parser = build_parser()
    (sub,) = [a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction"]
    for name, p in sub.choices.items():
        assert f'id="cli-{name}"' in html, name
        for action in p._actions:
            for option in action.option_strings:
                assert option in html, f"sinktheory {name} {option}"


def test_theory_pages_render_equations_from_the_model(site):
    html = (site / "theory" / "potential.html").read_text()
    assert r"\frac{\gamma" in html  # sympy.latex of the potential, not typed by hand
    for shape in importlib.import_module("sinktheory.symbolic").SHAPES:
        assert rf"\text{{{shape}}}" in html, shape


def test_gallery_shows_every_figure_of_the_quick_reproduction(site):
    html = (site / "gallery.html").read_text()
    figures = re.findall(r'id="gallery-fig(\d\d)"', html)
    assert len(figures) >= 10
    for number in figures:
        assert f"fig{number}.png" in html
        assert (site / "_images" / f"fig{number}.png").exists()


def test_getting_started_has_the_readme_set_up_commands():
    readme = (ROOT / "README.md").read_text()
    setup = readme.split("## Set-up", 1)[1].split("\n## ", 1)[0]
    commands = re.findall(r"```bash\n(.+?)\n```", setup, re.S)
    assert len(commands) == 2
    page = (DOCS / "getting_started.rst").read_text()
    for command in commands:
        assert command.strip() in page, command
