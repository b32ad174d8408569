"""A tiny progress bar on stderr, shown only when it helps.

It draws nothing unless enabled, the stream is a terminal and the work has already taken
longer than ``delay`` seconds, so short runs and piped output stay clean.

Examples
--------
>>> import io
>>> bar = ProgressBar(10, enabled=True, stream=io.StringIO())  # not a terminal: silent
>>> bar.update(10); bar.close()
>>> bar.stream.getvalue()
''
"""

from __future__ import annotations

import sys
import time
from typing import TextIO


class ProgressBar:
    """Count ``total`` units of work; draw ``[####    ] 40% 12 s left`` on ``stream``.

    Parameters
    ----------
    total : int
        Units of work.
    enabled : bool
        False draws nothing at all.
    stream : text stream, default sys.stderr
    delay : float
        Seconds to wait before drawing the first time.
    label : str
        Text in front of the bar.
    """

    def __init__(
        self,
        total: int,
        *,
        enabled: bool = True,
        stream: TextIO | None = None,
        delay: float = 2.0,
        label: str = "",
    ) -> None:
        self.total = max(int(total), 1)
        self.stream = sys.stderr if stream is None else stream
        isatty = getattr(self.stream, "isatty", lambda: False)
        self.enabled = enabled and isatty()
        self.delay = delay
        self.label = label
        self.done = 0
        self.start = time.perf_counter()
        self.drawn = False

    def update(self, units: int) -> None:
        """Record ``units`` more units done and redraw if due."""
        self.done = min(self.done + units, self.total)
        if not self.enabled:
            return
        elapsed = time.perf_counter() - self.start
        if elapsed < self.delay:
            return
        frac = self.done / self.total
        left = elapsed * (1 - frac) / frac if frac > 0 else float("inf")
        width = 30
        fill = int(round(width * frac))
        self.stream.write(
            f"\r{self.label}[{'#' * fill}{' ' * (width - fill)}] {100 * frac:3.0f}% "
            f"{left:5.0f} s left"
        )
        self.stream.flush()
        self.drawn = True

    def close(self) -> None:
        """End the bar's line (if one was drawn)."""
        if self.drawn:
            self.stream.write("\n")
            self.stream.flush()
