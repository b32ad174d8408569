"""The layers contract: place every module of sinktheory by ``layers.toml`` and check it.

``python docs/make_layers.py`` checks the package against the table (exit 1 with one line
per broken rule) and writes ``docs/design/layers.inc``, the diagram of the design page.
``tests/foundations/test_layers.py`` runs the same check and compares the diagram with a
fresh one, so the table, the code and the docs cannot drift apart.

The import graph comes from grimp (import-linter's graph library), which reads every
import statement, including those inside functions, without importing the package.
"""

from __future__ import annotations

import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path

import grimp

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = "sinktheory"
TABLE = ROOT / "layers.toml"
DIAGRAM = ROOT / "docs" / "design" / "layers.inc"


@dataclass(frozen=True)
class Layer:
    name: str
    what: str
    modules: tuple[str, ...]


def read_table(path: Path = TABLE) -> list[Layer]:
    """The layers of ``path``, top first."""
    data = tomllib.loads(path.read_text())
    return [Layer(d["name"], d["what"], tuple(d["modules"])) for d in data["layer"]]


def place(module: str, layers: list[Layer]) -> int | None:
    """Index (0 = top) of the layer of ``module`` by the longest listed prefix, or None."""
    tail = module.removeprefix(PACKAGE + ".")
    best, depth = None, -1
    for i, layer in enumerate(layers):
        for entry in layer.modules:
            if (tail == entry or tail.startswith(entry + ".")) and entry.count(".") > depth:
                best, depth = i, entry.count(".")
    return best


def _cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan, iterative)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = 0
    for root in sorted(edges):
        if root in index:
            continue
        work = [(root, iter(sorted(edges[root])))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on.add(child)
                    work.append((child, iter(sorted(edges.get(child, ())))))
                elif child in on:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    out.append(sorted(component))
    return out


def check(layers: list[Layer] | None = None) -> list[str]:
    """Every broken rule of the contract, one line each (empty when it holds)."""
    layers = read_table() if layers is None else layers
    graph = grimp.build_graph(PACKAGE, cache_dir=None)
    modules = sorted(m for m in graph.modules if m.startswith(PACKAGE + "."))
    problems = [f"{m}: not placed in any layer of layers.toml" for m in modules
                if place(m, layers) is None]  # fmt: skip
    listed = {e for layer in layers for e in layer.modules}
    problems += [f"layers.toml lists {e}, which is no module of the package"
                 for e in sorted(listed) if f"{PACKAGE}.{e}" not in graph.modules]  # fmt: skip
    edges: dict[str, set[str]] = {m: set() for m in modules}
    for m in modules:
        for t in graph.find_modules_directly_imported_by(m):
            if t == PACKAGE or not t.startswith(PACKAGE + "."):
                continue  # the package root (its version) and other packages
            edges[m].add(t)
            a, b = place(m, layers), place(t, layers)
            if a is not None and b is not None and b < a:
                lines = graph.get_import_details(importer=m, imported=t)
                where = ", ".join(str(d["line_number"]) for d in lines)
                problems.append(
                    f"{m} (layer {layers[a].name}) imports {t} (layer {layers[b].name}, "
                    f"above it) at line {where}"
                )
    problems += [f"import cycle: {' -> '.join(c)}" for c in _cycles(edges)]
    return problems


def diagram(layers: list[Layer] | None = None) -> str:
    """The layers as an RST table, top first (what ``docs/design/layers.inc`` holds)."""
    layers = read_table() if layers is None else layers
    rows = [(layer.name, ", ".join(f"``{m}``" for m in layer.modules), layer.what)
            for layer in layers]  # fmt: skip
    head = (
        ".. Generated by docs/make_layers.py from layers.toml -- do not edit by hand.\n\n"
        ".. list-table:: The layers, top to bottom (a module imports only from its own "
        "layer and those below)\n"
        "   :header-rows: 1\n   :widths: 12 38 50\n\n"
        "   * - layer\n     - modules\n     - what it holds\n"
    )
    body = "".join(f"   * - {n}\n     - {m}\n     - {w}\n" for n, m, w in rows)
    return head + body


def main() -> int:
    problems = check()
    for line in problems:
        print(line, file=sys.stderr)
    DIAGRAM.parent.mkdir(parents=True, exist_ok=True)
    DIAGRAM.write_text(diagram())
    print(f"{len(problems)} broken rule(s); wrote {DIAGRAM.relative_to(ROOT)}")
    return 1 if problems else 0


if __name__ == "__main__":
    raise SystemExit(main())
