"""The guided tour runs top to bottom."""

from pathlib import Path

import nbformat
from nbclient import NotebookClient

NOTEBOOKS = Path(__file__).resolve().parents[1] / "notebooks"


def test_tour_matches_its_generator():
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_tour", NOTEBOOKS / "make_tour.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    stored = nbformat.read(NOTEBOOKS / "tour.ipynb", as_version=4)
    assert [c.source for c in stored.cells] == [c.source for c in mod.build().cells]


def test_tour_executes(tmp_path, monkeypatch):
    # the kernel runs in tmp_path: make it import this work tree, not an installed copy
    monkeypatch.setenv("PYTHONPATH", str(NOTEBOOKS.parent))
    nb = nbformat.read(NOTEBOOKS / "tour.ipynb", as_version=4)
    NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    ).execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    text = "".join(o.get("text", "") for o in outputs)
    assert "stable intervals" in text and "max relative energy error" in text
    # the two figures (Floquet chart, recurrence plot) are PNG images, not "<Figure ...>"
    images = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(images) == 2, [o.get("data", {}).get("text/plain") for o in outputs]
    assert all(len(o["data"]["image/png"]) > 1000 for o in images)
