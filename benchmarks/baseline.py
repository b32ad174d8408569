"""Run a script against the package as it was at an earlier commit, for benchmarks that
compare today's code with an older one in the same run (same machine, same load).

The commit is checked out once into a temporary git worktree (``git worktree add
--detach``) and the script runs there in a subprocess with that tree first on the path.

Usage: ``from baseline import run_at; seconds = float(run_at("de40031", script))``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path


def worktree(rev: str) -> Path:
    """A checkout of ``rev`` in the temporary folder (made on first use)."""
    folder = Path(tempfile.gettempdir()) / f"sinktheory-baseline-{rev}"
    if not folder.exists():
        # from the checkout this script belongs to, whatever the working directory
        repo = Path(__file__).resolve().parents[1]
        subprocess.run(
            ["git", "worktree", "add", "--detach", str(folder), rev], check=True, cwd=repo
        )
    return folder


def run_at(rev: str | None, script: str, env: dict | None = None) -> str:
    """The last line ``script`` prints when run with the package at ``rev`` (None: this
    checkout), in a fresh Python process; its error output if it fails."""
    folder = worktree(rev) if rev else Path(__file__).resolve().parents[1]
    environment = dict(os.environ, PYTHONPATH=str(folder), **(env or {}))
    # run inside the tree: "python -c" puts the working directory first on sys.path
    res = subprocess.run(
        [sys.executable, "-c", script], env=environment, cwd=folder, capture_output=True,
        text=True,
    )  # fmt: skip
    if res.returncode != 0:
        raise RuntimeError(f"script failed at {rev or 'this checkout'}:\n{res.stderr}")
    return res.stdout.strip().splitlines()[-1]
