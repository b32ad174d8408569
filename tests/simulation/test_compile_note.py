"""The note before an engine's first compilation: when it is written, once, and --quiet.

Compiling an engine takes about a minute, so these tests never compile: the decision
(:func:`sinktheory.engine.cache.compiled`) is checked on an empty cache and on one holding
numba's index of the engine's ``advance``, and the note on a load whose import is replaced.
"""

from sinktheory.engine import cache


def test_compiled_reads_numba_index_of_advance(tmp_path, monkeypatch):
    monkeypatch.setenv("SINKTHEORY_CACHE", str(tmp_path))
    assert not cache.compiled("sink_flat")
    index = tmp_path / "__pycache__" / f"sink_flat_{cache._digest()}.advance-12.py311.nbi"
    index.parent.mkdir()
    index.write_bytes(b"")
    assert cache.compiled("sink_flat")
    assert not cache.compiled("sink_symmetric")  # another engine's index does not count


def _fake_load(tmp_path, monkeypatch):
    monkeypatch.setenv("SINKTHEORY_CACHE", str(tmp_path))
    monkeypatch.setattr(cache, "_loaded", {})
    imports = []
    monkeypatch.setattr(cache, "import_generated", lambda path, text, module: imports.append(path))
    return imports


def test_note_once_before_the_first_compilation(tmp_path, monkeypatch, capsys):
    imports = _fake_load(tmp_path, monkeypatch)
    with cache.compilation_notes():
        cache.load("sink_flat")
        cache.load("sink_flat")
    err = capsys.readouterr().err
    assert err.splitlines() == [
        f"sinktheory: compiling the engine sink_flat (about 1 min, once; cached in {tmp_path})"
    ]
    assert len(imports) == 1


def test_no_note_when_compiled_or_from_the_library(tmp_path, monkeypatch, capsys):
    """A library call (a notebook, a sweep's worker) writes nothing to stderr; nor does a
    load of a compiled engine."""
    _fake_load(tmp_path, monkeypatch)
    cache.load("sink_flat")
    monkeypatch.setattr(cache, "compiled", lambda name: True)
    with cache.compilation_notes():
        cache.load("sink_symmetric")
    assert capsys.readouterr().err == ""


def test_quiet_option_silences_the_note(tmp_path, monkeypatch, capsys):
    """``simulate`` runs inside compilation_notes, ``simulate --quiet`` does not."""
    from sinktheory.cli import main
    from sinktheory.commands import simulate

    seen = []

    def fake_run(args):
        cache.load("sink_flat")
        seen.append(args.quiet)
        raise cache.ParameterError("runs", 0, "stop here")

    _fake_load(tmp_path, monkeypatch)
    monkeypatch.setattr(simulate, "run", fake_run)
    argv = ["simulate", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--runs", "2"]
    assert main([*argv, "--periods", "1", "--quiet"]) == 2
    assert "compiling" not in capsys.readouterr().err
    cache._loaded.clear()
    assert main([*argv, "--periods", "1"]) == 2
    assert capsys.readouterr().err.count("compiling the engine sink_flat") == 1
    assert seen == [True, False]


def test_interactive_check_counts_a_first_compilation(monkeypatch):
    """A job of a few particle steps is refused under a 36 s limit only when its engine
    must be compiled first (COMPILE_SECONDS, 75 s); a sweep's points never count it."""
    import pytest

    from sinktheory import RunSettings, Sink, Well
    from sinktheory.errors import ParameterError
    from sinktheory.worklimit import check_work, interactive_limit, resumable, tally

    settings, sink = RunSettings(runs=2, periods=1), Sink(Well(0.5, 0.3, 4))
    monkeypatch.setattr(cache, "compiled", lambda name: True)
    with interactive_limit(hours=0.01), tally() as estimates:
        check_work(settings, sink, steps_per_period=10)
    assert estimates[0] < 1e-3
    monkeypatch.setattr(cache, "compiled", lambda name: False)
    with interactive_limit(hours=0.01), pytest.raises(ParameterError) as refusal:
        check_work(settings, sink, steps_per_period=10)
    assert "plus compiling the engine sink_flat first (75 s)" in str(refusal.value)
    with resumable(), tally() as estimates:
        check_work(settings, sink, steps_per_period=10)
    assert estimates[0] < 1e-3
