"""The guided tour is what its generator writes, without outputs.

It is executed by the documentation build (myst-nb), which renders it as a page with its
outputs; ``tests/interface/test_docs.py::test_tour_notebook_is_a_page_with_its_outputs`` checks that
page (the printed results, the two figures, no error), so CI executes it only once.
"""

import importlib.util
from pathlib import Path

import nbformat

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"


def _generated() -> nbformat.NotebookNode:
    spec = importlib.util.spec_from_file_location("make_tour", NOTEBOOKS / "make_tour.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod.build()


def test_tour_matches_its_generator():
    stored = nbformat.read(NOTEBOOKS / "tour.ipynb", as_version=4)
    assert [c.source for c in stored.cells] == [c.source for c in _generated().cells]


def _outputs(nb: nbformat.NotebookNode) -> list[int]:
    """Indices of the code cells that carry outputs or an execution count."""
    return [
        i
        for i, c in enumerate(nb.cells)
        if c.cell_type == "code" and (c.outputs or c.execution_count is not None)
    ]


def test_tour_is_committed_without_outputs():
    """The outputs come from the docs build; a committed one would be stale (and big)."""
    assert _outputs(nbformat.read(NOTEBOOKS / "tour.ipynb", as_version=4)) == []
    executed = _generated()
    executed.cells[1].execution_count = 1
    executed.cells[3].outputs = [nbformat.v4.new_output("stream", text="x-equation")]
    assert _outputs(executed) == [1, 3]
