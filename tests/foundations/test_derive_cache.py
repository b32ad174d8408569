"""`sinktheory derive` reads its equations from a cache keyed by the symbolic source."""

import json
import shutil

import pytest

from sinktheory.cli import main
from sinktheory.commands import derive


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("SINKTHEORY_CACHE", str(tmp_path / "cache"))
    return tmp_path / "cache"


@pytest.fixture
def counted(monkeypatch):
    """renderings() replaced by a cheap stand-in that counts its calls."""
    calls = []

    def fake():
        calls.append(1)
        return {"json": {"e": f"x + {len(calls)}"}, "text": f"e: x + {len(calls)}", "latex": "x"}

    monkeypatch.setattr(derive, "renderings", fake)
    return calls


def test_cached_result_is_the_fresh_derivation(cache, capsys):
    """The real derivation once, then the cache file: the same JSON and text, and equal to
    what derive computes without the cache (--fresh)."""
    assert main(["derive", "--json"]) == 0
    first = capsys.readouterr().out
    assert derive.cache_file().exists()
    assert main(["derive", "--json"]) == 0
    assert capsys.readouterr().out == first
    assert main(["derive", "--json", "--fresh"]) == 0
    assert capsys.readouterr().out == first
    assert main(["derive", "--latex"]) == 0
    assert "\\frac" in capsys.readouterr().out


def test_second_call_reads_the_cache(cache, counted, capsys):
    assert main(["derive", "--json"]) == 0
    assert main(["derive", "--json"]) == 0
    assert len(counted) == 1
    outs = capsys.readouterr().out.splitlines()
    assert outs[0] == outs[1] == json.dumps({"e": "x + 1"})
    assert main(["derive", "--fresh"]) == 0  # derives again
    assert len(counted) == 2


def test_cache_invalidated_when_the_source_changes(cache, counted, tmp_path, monkeypatch, capsys):
    source = tmp_path / "symbolic.py"
    shutil.copy(derive.SOURCES[0], source)
    monkeypatch.setattr(derive, "SOURCES", (source, *derive.SOURCES[1:]))
    assert main(["derive", "--json"]) == 0
    before = derive.cache_file()
    source.write_text(source.read_text() + "\n# an edit of the symbolic model\n")
    assert derive.cache_file() != before
    assert main(["derive", "--json"]) == 0
    assert len(counted) == 2  # derived again, not read from the old file
    outs = capsys.readouterr().out.splitlines()
    assert outs == [json.dumps({"e": "x + 1"}), json.dumps({"e": "x + 2"})]


def test_unwritable_cache_still_answers(tmp_path, counted, monkeypatch, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("not a directory")
    monkeypatch.setenv("SINKTHEORY_CACHE", str(blocker / "cache"))
    assert main(["derive", "--json"]) == 0
    assert json.loads(capsys.readouterr().out) == {"e": "x + 1"}
