"""Shared by the tests: run ``sinktheory`` in-process and capture its output, check a
clean refusal (exit 2, one line naming the parameter, nothing written); call an API entry
point with one hostile argument; and wells typed as a user would, independently of the
registry."""

import dataclasses
import math
import os
import signal
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np

from sinktheory.cli import main
from sinktheory.errors import NumericalError, ParameterError, WellDefinitionError


def run_cli(argv, capsys):
    """(exit status, stdout, stderr) of ``sinktheory ARGV``."""
    code = main(argv)
    out, err = capsys.readouterr()
    return code, out, err


def snapshot(root: Path) -> set[str]:
    """Every path under ``root`` (hidden files included)."""
    return {str(p.relative_to(root)) for p in root.rglob("*")}


def refused(argv, capsys, tmp_path, monkeypatch, name: str) -> str:
    """Run ARGV in ``tmp_path``; assert a clean refusal naming ``name``; return stderr."""
    monkeypatch.chdir(tmp_path)
    before = snapshot(tmp_path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        code, out, err = run_cli(argv, capsys)
    # a warning would reach the user's terminal before the one-line message
    assert not [w for w in caught if issubclass(w.category, RuntimeWarning)], caught[0].message
    assert code == 2, (code, err)
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert "Traceback" not in err
    assert f"error: {name} = " in lines[0] or f"argument {name}" in lines[0], lines[0]
    assert snapshot(tmp_path) == before, "a file was written"
    return lines[0]


#: Modules that cost 0.05-1 s to import: a quick answer imports none of them.
HEAVY = ("numpy", "numba", "sympy", "mpmath", "matplotlib", "scipy", "xarray", "zarr", "dask")

PROBE = """
import sys
from sinktheory.cli import main
try:
    status = main(sys.argv[1:])
except SystemExit as e:  # --help exits through argparse
    status = e.code
heavy = [m for m in {heavy!r} if m in sys.modules]
print("STATUS", status, "HEAVY", ",".join(heavy), file=sys.stderr)
"""


def probe(args, tmp_path):
    """(exit status, heavy modules imported, process) of ``sinktheory ARGS`` run in a
    fresh process in ``tmp_path``."""
    proc = subprocess.run(
        [sys.executable, "-c", PROBE.format(heavy=HEAVY), *args],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    last = proc.stderr.strip().splitlines()[-1].split()
    assert last[0] == "STATUS", proc.stderr
    heavy = last[3].split(",") if len(last) > 3 else []
    return int(last[1]), heavy, proc


#: Starts ``sinktheory ARGV`` as a terminal starts a foreground command and as ``python -m
#: sinktheory`` runs it (``main()`` reads the process's own arguments and may end the
#: process itself): SIGINT and SIGTERM at their usual actions and unblocked, whatever the
#: test process passed on (a shell's background job ignores SIGINT, an ignored signal stays
#: ignored across exec, and Python then leaves it ignored: such a command never sees Ctrl-C,
#: which is right for it, but not what an interrupt test means).  It says "ready" on stderr
#: once the package is imported (a signal during Python's own start-up is not the
#: command's to handle).
LAUNCH = (
    "import signal, sys; signal.signal(signal.SIGINT, signal.default_int_handler); "
    "signal.signal(signal.SIGTERM, signal.SIG_DFL); "
    "signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGTERM}); "
    "from sinktheory.cli import main; print('ready', file=sys.stderr, flush=True); "
    "sys.exit(main())"
)


def launch(argv, cwd, env=None, group=False) -> subprocess.Popen:
    """``sinktheory ARGV`` started by :data:`LAUNCH` in ``cwd`` (in a session and process
    group of its own with ``group``, so that ``os.killpg`` reaches it as Ctrl-C would), once
    it says ready; stdout and stderr are text pipes."""
    proc = subprocess.Popen(
        [sys.executable, "-c", LAUNCH, *argv], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        text=True, cwd=cwd, env=env, start_new_session=group,
    )  # fmt: skip
    line = proc.stderr.readline()
    if line != "ready\n":
        proc.kill()
        out, err = proc.communicate()
        raise AssertionError(f"the command did not start: {line}{err}")
    return proc


def _stat(pid: int) -> list[str]:
    """The fields of /proc/PID/stat after the command name (empty if it is gone)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()
    except OSError:
        return []


def descendants(pid: int) -> list[int]:
    """Every process below ``pid`` (Linux /proc; a sweep's forkserver, resource tracker
    and the workers the forkserver forks)."""
    found = []
    for entry in os.listdir("/proc"):
        fields = _stat(int(entry)) if entry.isdigit() else []
        if fields and int(fields[1]) == pid:
            found += [int(entry), *descendants(int(entry))]
    return found


def cpu_ticks(pid: int) -> int:
    """Clock ticks process ``pid`` has computed in user mode (0 if it is gone)."""
    fields = _stat(pid)
    return int(fields[11]) if fields else 0


def alive(pid: int) -> bool:
    """Whether process ``pid`` exists and is not a zombie."""
    fields = _stat(pid)
    return bool(fields) and fields[0] != "Z"


#: The registry's shapes, an elliptic well and Henon-Heiles typed as a user would (the
#: paper's parameters: defaults with ranges).
BUILT_IN = {
    "flat": "gamma/(2*n) * ((x/(alpha + beta*(y**2 - 1)))**(2*n) + y**(2*n))",
    "symmetric": "gamma/(2*n) * ((x/(alpha + beta*(y**2 - 1)))**(2*n)"
    " + (y/(alpha + beta*(x**2 - 1)))**(2*n))",
    "circular": "gamma/(2*n) * ((x**2 + y**2)/(alpha - beta)**2)**n",
}
PAPER = {"alpha": 0.5, "beta": (0.3, (-5.0, 0.45)), "gamma": 1.0, "n": (4, (1, 1000))}
ELLIPTIC = "gamma/(2*n) * ((x/a)**2 + (y/b)**2)**n"
HH = "(x**2 + y**2)/2 + x**2*y - y**3/3"
#: Hénon–Heiles lifted by 1 (V(0, 0) = 1): the engine tests use it, so that one Hénon–Heiles
#: engine is compiled, and each of them also checks that energies count from V(0, 0).
LIFTED_HH = "1 + " + HH


def write_well_file(directory: Path, name: str, potential: str, parameters=None,
                    wall_ratios=()) -> Path:  # fmt: skip
    """A TOML well file ``directory/name.toml``: ``parameters`` maps a name to its default
    or to (default, (lo, hi)) as :data:`PAPER` does."""
    lines = [f'name = "{name}"', f'potential = "{potential}"']
    if wall_ratios:
        lines.append("wall_ratios = [" + ", ".join(f'"{r}"' for r in wall_ratios) + "]")
    lines.append("[parameters]")
    for key, spec in (parameters or {}).items():
        default, bounds = spec if isinstance(spec, tuple) else (spec, None)
        extra = f", range = [{bounds[0]!r}, {bounds[1]!r}]" if bounds else ""
        lines.append(f"{key} = {{ default = {default!r}{extra} }}")
    path = directory / f"{name}.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def refused_well(argv, capsys, tmp_path, monkeypatch, reason: str) -> str:
    """Run ARGV in ``tmp_path``; assert a refusal of a well (exit 2, one line on stderr
    that says ``reason``, nothing on stdout, nothing written); return the line."""
    monkeypatch.chdir(tmp_path)
    before = snapshot(tmp_path)
    code, out, err = run_cli(argv, capsys)
    lines = err.strip().splitlines()
    assert code == 2 and out == "", (code, out, err)
    assert len(lines) == 1 and f"sinktheory {argv[0]}: error: " in lines[0], err
    assert reason in lines[0], lines[0]
    assert snapshot(tmp_path) == before, "a file was written"
    return lines[0]


#: Hostile values tried for every argument of an API entry point (valid ones among them
#: are fine too): wrong types, bools, NaN, infinities, huge and tiny numbers, negative
#: counts, wrong shapes, text, complex numbers.
HOSTILE = [
    None, True, np.True_, -1, 0, 1, 2, 2.5, -0.5, 10**12, 1e12, 1e308, -1e308, 1e-300,
    math.nan, math.inf, -math.inf, "x", "", [], [1.0, 2.0], [[5.0, 5.0]], [[math.nan]],
    {"a": 1}, object(), 3 + 1j,
]  # fmt: skip

#: Examples per fuzzed entry point are multiplied by this (environment variable
#: SINKTHEORY_FUZZ_SCALE, default 1): CI runs the small fuzz, a larger run sets it.
FUZZ_SCALE = max(1, int(os.environ.get("SINKTHEORY_FUZZ_SCALE", "1")))
#: Estimated seconds of work a hostile call may start (the interactive limit lowered to
#: this, so a huge but valid size is refused by the work estimate, as it would be at its
#: own scale): the fuzz stays fast, and the estimates are tried too.
FUZZ_WORK_SECONDS = 2.0
#: Seconds one hostile call may take before it counts as a hang (work started beyond its
#: estimate, or a loop no estimate covers).
HANG_SECONDS = 60


class Hang(AssertionError):
    """A call with one hostile argument ran past :data:`HANG_SECONDS`."""


def non_finite(value, depth: int = 0) -> str | None:
    """Where ``value`` (a number, array, sequence, mapping or dataclass result) holds a
    NaN, an infinity or a complex number, or None if nowhere."""
    if depth > 4 or isinstance(value, str | bytes | bool | np.bool_):
        return None
    if isinstance(value, complex | np.complexfloating):
        return f"complex {value}"
    if isinstance(value, float | np.floating):
        return None if math.isfinite(value) else f"{value}"
    if isinstance(value, np.ndarray):
        if value.dtype.kind == "c":
            return f"a complex array {value.shape}"
        if value.dtype.kind == "f" and not np.all(np.isfinite(value)):
            return f"an array {value.shape} holding NaN or inf"
        return None
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        items = {f.name: getattr(value, f.name) for f in dataclasses.fields(value)}.items()
    elif isinstance(value, dict):
        items = value.items()
    elif isinstance(value, list | tuple):
        items = enumerate(value)
    else:
        return None
    for key, item in items:
        where = non_finite(item, depth + 1)
        if where:
            return f"{key}: {where}"
    return None


def call_hostile(function, valid: dict, argument: str, value):
    """``function(**valid)`` with ``argument`` replaced by ``value``, under the work limit
    :data:`FUZZ_WORK_SECONDS`: the result, or None if it was refused as documented -- a
    one-line ParameterError naming its parameter first, or a NumericalError.  Any other
    exception escapes; a call running past :data:`HANG_SECONDS` raises :class:`Hang`.  A
    result holding NaN, inf or a complex number where the valid call's result holds none
    is a silently wrong number (see :func:`fuzz_one`)."""

    def alarm(*_):
        raise Hang(f"{argument} = {value!r}: still running after {HANG_SECONDS} s")

    from sinktheory.worklimit import interactive_limit

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(HANG_SECONDS)
    try:
        with interactive_limit(hours=FUZZ_WORK_SECONDS / 3600):
            return function(**{**valid, argument: value})
    except ParameterError as e:
        text = str(e)
        lead = f"{e.name}: " if isinstance(e, WellDefinitionError) else f"{e.name} = "
        assert e.name and text.startswith(lead) and "\n" not in text, text
    except NumericalError as e:
        assert "\n" not in str(e), str(e)
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    return None


def fuzz_one(function, valid: dict, data, values=HOSTILE, baseline=None) -> None:
    """Draw one argument of ``valid`` and one of ``values`` (hypothesis ``data``) and call
    :func:`call_hostile`; a result with a NaN, inf or complex number fails unless
    ``baseline`` (the valid call's :func:`non_finite`) has one too."""
    from hypothesis import strategies as st

    argument = data.draw(st.sampled_from(sorted(valid)), label="argument")
    value = data.draw(st.sampled_from(values), label="value")
    result = call_hostile(function, valid, argument, value)
    if result is not None and baseline is None:
        where = non_finite(result)
        assert where is None, f"{argument} = {value!r} returned {where} silently"


def cli_json(argv, capsys) -> dict:
    """The JSON object ``sinktheory ARGV --json`` prints (asserting exit status 0)."""
    import json

    code, out, err = run_cli([*argv, "--json"], capsys)
    assert code == 0, err
    return json.loads(out)
