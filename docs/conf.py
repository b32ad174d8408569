"""Sphinx configuration for the sinktheory documentation.

Build with warnings as errors (this is what tests/interface/test_docs.py runs)::

    sphinx-build -W --keep-going -b html docs docs/_build/html

The equations on the theory pages are rendered from :mod:`sinktheory.symbolic`, the CLI
reference from :func:`sinktheory.cli.build_parser`, the API reference from the
docstrings of every public module found at build time, and the gallery from
``sinktheory reproduce --quick`` (see ``_ext/sinktheory_docs.py``).
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent / "_ext"))

import sinktheory  # noqa: E402

project = "sinktheory"
author = "the sinktheory authors"
copyright = "the sinktheory authors"
release = sinktheory.__version__
version = ".".join(release.split(".")[:2])

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    # copies MathJax 3 into _static/mathjax/ and points mathjax_path at it: the math
    # renders in a browser without a network (the default loads MathJax from a CDN)
    "sphinx-mathjax-offline",
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_nb",
    "sinktheory_docs",
]

templates_path = ["_templates"]
exclude_patterns = ["_build", "_autogen"]
root_doc = "index"
# no Markdown pages: .ipynb are the notebooks of ../notebooks, copied in by sinktheory_docs
source_suffix = {".rst": "restructuredtext", ".ipynb": "myst-nb"}

# --- notebooks: executed at every build, an error fails it ----------------------------
# They are committed without outputs, so the build is where their outputs come from
# (tests/interface/test_docs.py checks the rendered tour; nothing else executes it in CI).
nb_execution_mode = "force"
nb_execution_raise_on_error = True
nb_execution_timeout = 600
nb_execution_in_temp = True  # a notebook that writes files leaves nothing in docs/
nb_merge_streams = True
nb_ipywidgets_js = {}  # the default loads require.js from a CDN on pages with widgets
myst_enable_extensions = ["dollarmath"]  # $...$ in Markdown cells is math, as in Jupyter

# --- API reference: autosummary over the package, discovered at build time ---------
autosummary_generate = True
autosummary_imported_members = False
autodoc_default_options = {}
autodoc_member_order = "bysource"
autodoc_typehints = "none"  # numpydoc's Parameters sections carry the types

# numpydoc: no per-member stub tables for classes (autodoc documents the members).
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# --- HTML ---------------------------------------------------------------------------
html_theme = "alabaster"
html_title = f"sinktheory {release}"
html_static_path = []
html_theme_options = {
    "description": "The stochastic energy sink (Pilipchuk, arXiv:1610.02939)",
    "fixed_sidebar": True,
    "page_width": "1100px",
    "sidebar_width": "230px",
}
html_sidebars = {"**": ["about.html", "navigation.html", "searchbox.html"]}
