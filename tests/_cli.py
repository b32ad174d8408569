"""Shared by the tests: run ``sinktheory`` in-process and capture its output, check a
clean refusal (exit 2, one line naming the parameter, nothing written); and wells typed
as a user would, independently of the registry."""

import subprocess
import sys
import warnings
from pathlib import Path

from sinktheory.cli import main


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
