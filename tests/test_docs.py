"""The documentation site builds with warnings as errors, and documents everything.

CI runs only pytest, so this is where the site is built in CI: the command of the
README's "Documentation" section (``sphinx-build -W --keep-going -b html docs OUT``),
into a temporary directory.  The build also runs ``sinktheory reproduce --quick`` for the
gallery, so it takes about a minute.
"""

from __future__ import annotations

import importlib
import inspect
import os
import pkgutil
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import sinktheory
from sinktheory.cli import build_parser

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    """Build a copy of docs/ (the build writes generated pages next to its sources, and
    two test runs at once must not share them) and return the HTML directory."""
    out = tmp_path_factory.mktemp("docs")
    ignore = shutil.ignore_patterns("_build", "_autogen", "generated", "__pycache__")
    shutil.copytree(DOCS, out / "docs", ignore=ignore)
    (out / "derivations").symlink_to(ROOT / "derivations")  # for literalinclude
    env = {k: v for k, v in os.environ.items() if k != "SINKTHEORY_DOCS_REUSE_GALLERY"}
    env["MPLBACKEND"] = "Agg"
    cmd = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-b", "html"]
    cmd += ["-d", str(out / "doctrees"), str(out / "docs"), str(out / "html")]
    r = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=900)
    warnings = [line for line in r.stderr.splitlines() if "WARNING" in line or "ERROR" in line]
    assert r.returncode == 0 and not warnings, (
        f"sphinx-build failed (status {r.returncode}):\n" + "\n".join(warnings or [r.stderr])
    )
    return out / "html"


def _public_modules() -> list[str]:
    names = ["sinktheory"]
    for info in pkgutil.walk_packages(sinktheory.__path__, "sinktheory."):
        if not any(part.startswith("_") for part in info.name.split(".")):
            names.append(info.name)
    return names


def test_site_builds_without_warnings(site):
    for page in ("index", "getting_started", "cli", "gallery", "api/index", "theory/index"):
        assert (site / f"{page}.html").exists(), page


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
