"""The layers contract (layers.toml): every module placed, no upward import, no cycle.

The check itself lives in docs/make_layers.py (it also draws the design page's diagram);
these tests run it on the package, show that it can fail, and keep the diagram current.
"""

import importlib.util
import sys
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("make_layers", ROOT / "docs" / "make_layers.py")
layers = importlib.util.module_from_spec(_spec)
sys.modules[_spec.name] = layers  # dataclasses look their module up there
_spec.loader.exec_module(layers)


def test_the_package_keeps_its_layers_contract():
    assert layers.check() == []


def test_an_upward_import_and_an_unplaced_module_are_caught():
    table = layers.read_table()
    names = [layer.name for layer in table]
    swapped = list(table)
    i, j = names.index("engine"), names.index("model")
    swapped[i], swapped[j] = swapped[j], swapped[i]  # the engine now sits below the model
    problems = layers.check(swapped)
    assert any("sinktheory.engine.cache (layer engine) imports sinktheory.model" in p
               for p in problems)  # fmt: skip
    dropped = [replace(layer, modules=tuple(m for m in layer.modules if m != "runstats"))
               for layer in table]  # fmt: skip
    assert layers.check(dropped) == ["sinktheory.runstats: not placed in any layer of layers.toml"]


def test_cycles_are_found_through_any_number_of_modules():
    edges = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": {"e2"}, "e2": set()}
    assert layers._cycles(edges) == [["a", "b", "c"]]
    assert layers._cycles({"a": {"b"}, "b": set()}) == []


def test_the_longest_listed_name_places_a_module():
    table = layers.read_table()
    names = [layer.name for layer in table]
    assert names[layers.place("sinktheory.nnm.agreement", table)] == "studies"
    assert names[layers.place("sinktheory.nnm.shooting", table)] == "analyses"
    assert layers.place("sinktheory.nowhere", table) is None


def test_the_design_diagram_is_drawn_from_the_table():
    assert layers.DIAGRAM.read_text() == layers.diagram()
