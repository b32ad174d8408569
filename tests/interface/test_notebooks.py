"""The notebooks are what their generator writes, without outputs.

They are executed by the documentation build (myst-nb), which renders each as a page with
its outputs; ``tests/interface/test_docs.py::test_each_notebook_is_a_page_with_its_outputs``
checks those pages (the printed results, the figures, no error), so CI executes them only
once.
"""

import importlib.util
from pathlib import Path

import nbformat

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"


def _generator():
    spec = importlib.util.spec_from_file_location("make_notebooks", NOTEBOOKS / "make_notebooks.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _generated(name: str = "tour") -> nbformat.NotebookNode:
    return _generator().build(name)


def test_every_notebook_matches_its_generator():
    names = sorted(_generator().NOTEBOOKS)
    assert names == sorted(p.stem for p in NOTEBOOKS.glob("*.ipynb")) == ["tour", "your_own_well"]
    for name in names:
        stored = nbformat.read(NOTEBOOKS / f"{name}.ipynb", as_version=4)
        assert [c.source for c in stored.cells] == [c.source for c in _generated(name).cells]


def _outputs(nb: nbformat.NotebookNode) -> list[int]:
    """Indices of the code cells that carry outputs or an execution count."""
    return [
        i
        for i, c in enumerate(nb.cells)
        if c.cell_type == "code" and (c.outputs or c.execution_count is not None)
    ]


def test_notebooks_are_committed_without_outputs():
    """The outputs come from the docs build; a committed one would be stale (and big)."""
    for path in NOTEBOOKS.glob("*.ipynb"):
        assert _outputs(nbformat.read(path, as_version=4)) == [], path.name
    executed = _generated()
    executed.cells[1].execution_count = 1
    executed.cells[3].outputs = [nbformat.v4.new_output("stream", text="x-equation")]
    assert _outputs(executed) == [1, 3]
