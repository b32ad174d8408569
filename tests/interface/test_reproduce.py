"""`sinktheory reproduce`: figures, report, and refusal of unknown figures."""

import json

from sinktheory.cli import main
from sinktheory.model import Well
from sinktheory.scenes import SCENES
from sinktheory.scenes.wells import level_line_curvature


def test_reproduce_writes_figures_and_report(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["reproduce", "--figure", "2", "10", "--out", str(out), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [f["figure"] for f in data["figures"]] == [2, 10]
    claim = data["figures"][1]["claims"][0]  # Fig. 10: the x <-> y symmetry, exact
    assert set(claim) == {"statement", "measured", "verdict", "physics"}
    assert claim["verdict"] == "holds" and claim["physics"]
    for name in ("fig02.png", "fig10.png"):
        assert (out / name).read_bytes()[:4] == b"\x89PNG"
    report = (out / "report.md").read_text()
    assert "## Fig. 2" in report and "| row | claim | measured | verdict |" in report
    # the closing section links each of the paper's claims to its row's anchor
    right = report.split("### Right")[1]
    assert "[10.1](#r10-1)" in right and '<a id="r10-1"></a>10.1' in report


def test_unknown_figure_is_refused_and_nothing_written(tmp_path, capsys):
    out = tmp_path / "never"
    assert main(["reproduce", "--figure", "99", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "figure = 99" in err and not out.exists()


def test_every_scene_declares_what_it_computes():
    for number, scene in SCENES.items():
        assert scene.number == number and scene.needs and scene.title


def test_level_line_curvature_against_a_circle():
    """Independent check of the finite-difference curvature: the n = 1 symmetric well with
    beta = 0 has circular level lines x^2 + y^2 = 2E alpha^2 / gamma (curvature 1/r)."""
    well = Well(alpha=1.0, beta=0.0, n=1, shape="symmetric")
    r = (2 * 0.5) ** 0.5
    assert abs(level_line_curvature(well, 0.5) - (-1 / r)) < 1e-5


class _Recorder(dict):
    """The engine cache's dict of loaded engines, noting every engine asked for."""

    def __init__(self, loaded, asked):
        super().__init__(loaded)
        self.asked = asked

    def __contains__(self, name):
        self.asked.append(name)
        return super().__contains__(name)


def test_quick_reproduction_of_every_figure(tmp_path, capsys, monkeypatch):
    """The README's main job at preview fidelity: every scene draws and reports, and each
    runs exactly the engines its estimate counts (sinktheory.scenes.ENGINES)."""
    from sinktheory.commands import reproduce
    from sinktheory.engine import cache
    from sinktheory.scenes import ENGINES

    asked = []
    monkeypatch.setattr(cache, "_loaded", _Recorder(cache._loaded, asked))
    say = reproduce._say
    monkeypatch.setattr(reproduce, "_say", lambda text: (asked.append(text), say(text)))
    out = tmp_path / "all"
    assert main(["reproduce", "--quick", "--out", str(out), "--json"]) == 0
    runs, figure = {}, None
    for item in asked:
        if item.startswith("Fig. ") and "/" in item.split(":")[0]:
            figure = int(item.split()[1])
            runs[figure] = set()
        elif figure is not None and not item.startswith(("Fig. ", "reproduce:")):
            runs[figure].add(item)
    assert sorted(runs) == sorted(ENGINES)
    earlier = set()
    for f in sorted(runs):  # a figure may reuse a result an earlier figure computed
        assert set(ENGINES[f]) - earlier <= runs[f] <= set(ENGINES[f]), f
        earlier |= runs[f]
    data = json.loads(capsys.readouterr().out)
    assert sorted(f["figure"] for f in data["figures"]) == sorted(SCENES)
    assert all(f["error"] is None and f["claims"] for f in data["figures"])
    report = (out / "report.md").read_text()
    for number in SCENES:
        assert f"## Fig. {number}:" in report
        assert (out / f"fig{number:02d}.png").exists()
