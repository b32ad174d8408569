"""The reproduction report: one section per figure with parameters, run time and claims.

The text ``sinktheory reproduce`` writes to report.md (:mod:`sinktheory.commands.reproduce`
builds the outcomes and renders them here); no API of its own.
"""

from __future__ import annotations

from dataclasses import dataclass

from .results import Result
from .scenes.base import BEYOND, FAILS, HOLDS, UNDECIDED, Scene, SceneResult

__all__ = []


@dataclass
class SceneOutcome(Result):
    """A scene as run: its result (None if it failed), image name, wall seconds, error
    text, and CPU seconds while it ran (the process's threads and its finished worker
    processes).

    ``as_dict()`` (what ``reproduce --json`` lists per figure): figure number, image,
    seconds, CPU seconds, error and the claims checked.
    """

    scene: Scene
    result: SceneResult | None
    image: str | None
    seconds: float
    error: str | None = None
    cpu_seconds: float = 0.0

    def items(self) -> dict:
        return {
            "figure": self.scene.number,
            "image": self.image,
            "seconds": self.seconds,
            "cpu_seconds": self.cpu_seconds,
            "error": self.error,
            "claims": [] if self.result is None else self.result.claims,
        }


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _anchor(number: int, index: int) -> str:
    return f"r{number}-{index}"


def render(outcomes: list[SceneOutcome], *, quick: bool, version: str) -> str:
    """Markdown text of report.md: a section per figure with its claims (rows numbered
    figure.row), the verdict counts, and the closing section (:func:`closing`)."""
    lines = [
        "# sinktheory: reproduction of Pilipchuk, arXiv:1610.02939",
        "",
        f"sinktheory {version}; fidelity: {'quick preview (--quick)' if quick else 'paper'}.",
        "Verdicts: *holds*, *does not hold*, *cannot be decided*.",
        "",
    ]
    counts: dict[str, int] = {}
    for o in outcomes:
        s = o.scene
        lines += [f"## Fig. {s.number}: {s.title}", ""]
        lines.append(f"- model computed: {s.needs}")
        lines.append(f"- run time: {o.seconds:.1f} s ({o.cpu_seconds:.1f} s CPU)")
        if o.error is not None:
            lines += [f"- **failed**: {_cell(o.error)}", ""]
            counts["failed"] = counts.get("failed", 0) + 1
            continue
        r = o.result
        lines.append(f"- image: `{o.image}`")
        params = ", ".join(f"{k} = {v}" for k, v in r.parameters.items())
        lines.append(f"- parameters: {params}")
        for note in r.notes:
            lines.append(f"- note: {note}")
        if r.claims:
            lines += ["", "| row | claim | measured | verdict |", "|---|---|---|---|"]
            for i, c in enumerate(r.claims, 1):
                row = f'<a id="{_anchor(s.number, i)}"></a>{s.number}.{i}'
                cells = (row, _cell(c.statement), _cell(c.measured), c.verdict)
                lines.append("| " + " | ".join(cells) + " |")
                counts[c.verdict] = counts.get(c.verdict, 0) + 1
        lines.append("")
    summary = ", ".join(f"{v} {k}" for k, v in sorted(counts.items())) or "no claims"
    lines += ["## Summary", "", summary, ""]
    lines += closing(outcomes, quick=quick)
    return "\n".join(lines)


def closing(outcomes: list[SceneOutcome], *, quick: bool) -> list[str]:
    """The closing section: what the paper gets right, what it gets wrong, what cannot be
    decided, each with the physics behind it (the claims' ``physics``, whose numbers are
    those of the row linked), then the report's own rows in one line."""
    groups: dict[str, list[str]] = {HOLDS: [], FAILS: [], UNDECIDED: []}
    beyond: dict[str, list[str]] = {HOLDS: [], FAILS: [], UNDECIDED: []}
    for o in outcomes:
        if o.result is None:
            continue
        for i, c in enumerate(o.result.claims, 1):
            link = f"[{o.scene.number}.{i}](#{_anchor(o.scene.number, i)})"
            if c.statement.startswith(BEYOND):
                beyond[c.verdict].append(link)
            else:
                text = _cell(c.physics) if c.physics else f"measured: {_cell(c.measured)}"
                groups[c.verdict].append(f"- {link} {_cell(c.statement)}. {text}")
    lines = ["## What the paper gets right and wrong, and why", ""]
    if quick:
        lines += ["(A --quick preview: lower fidelity and no long runs; judge the paper at "
                  "paper fidelity.)", ""]  # fmt: skip
    titles = {HOLDS: "Right", FAILS: "Wrong", UNDECIDED: "Cannot be decided"}
    for verdict, title in titles.items():
        if groups[verdict]:
            lines += [f"### {title}", "", *groups[verdict], ""]
    rows = "; ".join(f"{verdict}: {', '.join(links)}" for verdict, links in beyond.items() if links)
    if rows:
        lines += ["### Beyond the paper", "", f"The report's own rows ({rows}).", ""]
    return lines
