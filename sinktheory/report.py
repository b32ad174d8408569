"""The reproduction report: one section per figure with parameters, run time and claims."""

from __future__ import annotations

from dataclasses import dataclass

from .results import Result
from .scenes.base import Scene, SceneResult

__all__ = ["render", "SceneOutcome"]


@dataclass
class SceneOutcome(Result):
    """A scene as run: its result (None if it failed), image name, seconds, error text.

    ``as_dict()`` (what ``reproduce --json`` lists per figure): figure number, image,
    seconds, error and the claims checked.
    """

    scene: Scene
    result: SceneResult | None
    image: str | None
    seconds: float
    error: str | None = None

    def items(self) -> dict:
        return {
            "figure": self.scene.number,
            "image": self.image,
            "seconds": self.seconds,
            "error": self.error,
            "claims": [] if self.result is None else self.result.claims,
        }


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def render(outcomes: list[SceneOutcome], *, quick: bool, version: str) -> str:
    """Markdown text of report.md."""
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
        lines.append(f"- run time: {o.seconds:.1f} s")
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
            lines += ["", "| claim | measured | verdict |", "|---|---|---|"]
            for c in r.claims:
                lines.append(f"| {_cell(c.statement)} | {_cell(c.measured)} | {c.verdict} |")
                counts[c.verdict] = counts.get(c.verdict, 0) + 1
        lines.append("")
    summary = ", ".join(f"{v} {k}" for k, v in sorted(counts.items())) or "no claims"
    lines += ["## Summary", "", summary, ""]
    return "\n".join(lines)
