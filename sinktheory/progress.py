"""Progress of long work on stderr (a tqdm bar on a terminal, plain lines in a log), and
interrupts of long compiled work.

:class:`ProgressBar` counts units of work and shows nothing for work shorter than
``delay`` seconds, so short runs stay clean.  After that:

* on a terminal, a tqdm bar redrawn in place (at most every :data:`TERMINAL_INTERVAL` s);
* on anything else (a log file, a CI console, a notebook's stderr), one plain line at most
  every :data:`LOG_INTERVAL` seconds and a last line when the work ends, instead of the
  carriage-return redraws a terminal bar would leave in the file.

Compiled (numba) code cannot act on a signal: Python runs the handler only when the
compiled call returns, and a handler that raises (Ctrl-C's KeyboardInterrupt) while numba
boxes the call's results breaks the boxing (a SystemError, or a segmentation fault).
:class:`HeldSignals` records SIGINT and SIGTERM instead and delivers them when the caller
chooses; :func:`chunks` cuts long compiled work into calls of about
:data:`CHUNK_SECONDS`, delivering a held signal between two calls, so that Ctrl-C ends
the work within a fraction of a second.

Examples
--------
>>> import io
>>> log = io.StringIO()                   # not a terminal: plain lines, here none
>>> bar = ProgressBar(10, stream=log)     # because the work ends before ``delay``
>>> bar.update(10); bar.close()
>>> log.getvalue()
''
>>> bar = ProgressBar(4, stream=log, delay=0, interval=0, label="demo")
>>> for _ in range(4):
...     bar.update(1)
>>> bar.close()
>>> lines = log.getvalue().splitlines()
>>> len(lines), lines[-1].startswith("demo 100% 4/4 [00:00 elapsed, 00:00 left")
(5, True)
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import time
from collections.abc import Iterator
from typing import TextIO

from tqdm.std import tqdm

from . import validation as v
from .errors import ParameterError

__all__ = [
    "CHUNK_SECONDS",
    "chunks",
    "HeldSignals",
    "LOG_INTERVAL",
    "ProgressBar",
    "TERMINAL_INTERVAL",
]

#: Seconds between the plain progress lines written when the stream is not a terminal.
LOG_INTERVAL = 15.0
#: Seconds between redraws of the bar on a terminal.
TERMINAL_INTERVAL = 0.5
#: Seconds of compiled work between two checks for an interrupt (:func:`chunks`).
CHUNK_SECONDS = 0.1
#: Seconds a held signal waits for the compiled call to return before it ends the
#: process anyway (a call that releases the GIL: one period of a billiard can be long).
FORCE_AFTER = 1.0


#: A log line: no bar, the count, the time so far and left, the rate.
_LOG_FORMAT = (
    "{desc} {percentage:3.0f}% {n_fmt}/{total_fmt} [{elapsed} elapsed, {remaining} left, "
    "{rate_fmt}]"
)


class _Tqdm(tqdm):
    # tqdm's monitor thread only tunes ``miniters``; without it no thread outlives the bar
    # (sweeps fork worker processes).
    monitor_interval = 0


class _Lines:
    """A file-like wrapper that turns tqdm's carriage-return redraws into whole lines."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream

    def write(self, text: str) -> None:
        line = text.replace("\r", "").strip()
        if line:
            self.stream.write(line + "\n")

    def flush(self) -> None:
        self.stream.flush()


class ProgressBar:
    """Count ``total`` units of work and show their progress on ``stream``.

    Parameters
    ----------
    total : int
        Units of work (>= 0).
    enabled : bool
        False shows nothing at all.
    stream : text stream, default sys.stderr
    delay : float
        Seconds (>= 0) before anything is shown (shorter work shows nothing).
    label : str
        Text in front of the bar.
    unit : str
        What a unit of work is called (tqdm's rate column: ``3.2 segment/s``).
    interval : float, optional
        Seconds between updates shown; default :data:`TERMINAL_INTERVAL` on a terminal,
        :data:`LOG_INTERVAL` otherwise.

    Attributes
    ----------
    done, total : int
        Units done so far and in all.
    start : float
        ``time.perf_counter()`` at creation.
    enabled : bool
        True when an in-place bar is drawn on a terminal (subclasses that draw their own
        line test it); plain log lines are written whenever ``enabled`` was asked for.
    """

    def __init__(
        self,
        total: int,
        *,
        enabled: bool = True,
        stream: TextIO | None = None,
        delay: float = 2.0,
        label: str = "",
        unit: str = "it",
        interval: float | None = None,
    ) -> None:
        total = v.positive_int("total", total, minimum=0)
        delay = v.nonnegative("delay", delay)
        interval = None if interval is None else v.nonnegative("interval", interval)
        for name, text in (("label", label), ("unit", unit)):
            if not isinstance(text, str):
                raise ParameterError(name, text, "a text")
        if stream is not None and not callable(getattr(stream, "write", None)):
            raise ParameterError("stream", stream, "a text stream (with a write method) or None")
        self.total = max(total, 1)
        self.stream = sys.stderr if stream is None else stream
        terminal = bool(getattr(self.stream, "isatty", lambda: False)())
        self.enabled = bool(enabled) and terminal
        self.delay = delay
        self.label = label
        self.done = 0
        self.start = time.perf_counter()
        self.drawn = False
        if interval is None:
            interval = TERMINAL_INTERVAL if terminal else LOG_INTERVAL
        self._bar = _Tqdm(
            total=self.total,
            desc=label.strip() or None,
            unit=unit,
            file=self.stream if terminal else _Lines(self.stream),
            disable=not enabled,
            delay=delay,
            mininterval=interval,
            miniters=1,
            dynamic_ncols=terminal,
            bar_format=None if terminal else _LOG_FORMAT,
            leave=True,
        )
        self._terminal = terminal

    def update(self, units: int) -> None:
        """Record ``units`` more units done; show them if an update is due."""
        units = min(v.positive_int("units", units, minimum=0), self.total - self.done)
        self.done += units
        self._bar.update(units)

    def close(self) -> None:
        """End the progress display (a last line if anything was shown)."""
        bar = self._bar
        shown = not bar.disable and bar.last_print_t >= bar.start_t + bar.delay
        if shown and not self._terminal and bar.last_print_n == bar.n:
            bar.leave = False  # the last line written is already the final count
        bar.close()
        if self.drawn and not shown:  # a subclass drew its own line: end it
            self.stream.write("\n")
            self.stream.flush()
        self.drawn = self.drawn or shown


class HeldSignals:
    """SIGINT and SIGTERM recorded, not acted on, inside the ``with`` block, and delivered
    to the handlers in place before (Ctrl-C's KeyboardInterrupt, a command's SIGTERM
    handler) by :meth:`release`, at a point of the caller's choosing.

    Used around compiled calls (module docstring) and around a process pool's own code
    (an exception raised there by a signal could leave the pool half done).  Outside the
    main thread (where signal handlers cannot be set) nothing is held.

    A compiled call that runs without the GIL (``nogil``) may take longer than expected
    (one period of a billiard at a huge energy).  On the command line (when
    :attr:`forced_line` is set) a watcher thread, woken by the signal itself
    (:func:`signal.set_wakeup_fd`), waits :data:`FORCE_AFTER` seconds for the handler to
    run and otherwise writes ``forced_line`` and ends the process with status 128 + the
    signal's number (no clean-up: only what a kill would leave; outputs are written only
    after the work, and stores survive a kill).

    Examples
    --------
    >>> with HeldSignals() as held:
    ...     signal.raise_signal(signal.SIGINT)  # recorded, nothing raised
    ...     try:
    ...         held.release()                  # delivered: the default handler raises
    ...     except KeyboardInterrupt:
    ...         print("interrupted")
    interrupted
    """

    SIGNALS = (signal.SIGINT, signal.SIGTERM)
    #: The line a forced end writes on stderr (set by the command line's interrupt
    #: handler); None: no watcher.
    forced_line: str | None = None

    def __enter__(self) -> HeldSignals:
        self.held: list[int] = []
        self.previous = {}
        self.acted = threading.Event()
        if threading.current_thread() is threading.main_thread():
            self.previous = {s: signal.signal(s, self._hold) for s in self.SIGNALS}
            if self.forced_line is not None:
                _start_watcher()
                _HOLDING.append(self)
        return self

    def _hold(self, signum, frame) -> None:
        self.held.append(signum)
        self.acted.set()

    def release(self) -> None:
        """If a signal was held: restore the handlers and deliver it (what its handler
        raises is raised here)."""
        if not self.held:
            return
        held, self.held = self.held, []
        self._restore()
        for signum in dict.fromkeys(held):
            signal.raise_signal(signum)  # the handler runs before this returns

    def _restore(self) -> None:
        for signum, handler in self.previous.items():
            signal.signal(signum, signal.SIG_DFL if handler is None else handler)
        self.previous = {}
        if self in _HOLDING:
            _HOLDING.remove(self)

    def __exit__(self, kind, error, traceback) -> None:
        if kind is None:
            self.release()
        self._restore()


#: The HeldSignals holding now, innermost last (their watcher's view).
_HOLDING: list[HeldSignals] = []
_WATCHER: list[threading.Thread] = []


def _start_watcher() -> None:
    """Start, once per process, the thread woken by each signal (its number written to a
    pipe by Python's C-level handler, :func:`signal.set_wakeup_fd`)."""
    if _WATCHER:
        return
    read, write = os.pipe()
    os.set_blocking(write, False)
    signal.set_wakeup_fd(write, warn_on_full_buffer=False)
    _WATCHER.append(threading.Thread(target=_watch, args=(read,), daemon=True))
    _WATCHER[0].start()


def _watch(read: int) -> None:
    """:class:`HeldSignals`' watcher: a SIGINT or SIGTERM whose handler has not run
    :data:`FORCE_AFTER` seconds later while signals are held ends the process."""
    while data := os.read(read, 16):
        ours = [s for s in data if s in HeldSignals.SIGNALS]
        holding = _HOLDING[-1] if _HOLDING else None
        line = HeldSignals.forced_line
        if not ours or holding is None or line is None:
            continue
        if not holding.acted.wait(FORCE_AFTER) and not holding.acted.is_set():
            os.write(2, (line + "\n").encode())
            os._exit(128 + ours[0])


def chunks(
    total: int, seconds: float = CHUNK_SECONDS, most: int | None = None
) -> Iterator[tuple[int, int]]:
    """Ranges ``(start, stop)`` covering ``range(total)`` in order, each sized to take
    about ``seconds`` (timed from the ones before: the first is 1 unit, then at most 4
    times the last) and at most ``most`` units, with SIGINT and SIGTERM held while the
    caller works on a range and delivered before the next one (:class:`HeldSignals`).

    Examples
    --------
    >>> ranges = list(chunks(100, seconds=1.0))
    >>> ranges[:3], ranges[-1][1]
    ([(0, 1), (1, 5), (5, 21)], 100)
    >>> max(stop - start for start, stop in chunks(100, seconds=1.0, most=10))
    10
    """
    most = total if most is None else max(1, int(most))
    start, size = 0, 1
    with HeldSignals() as held:
        while start < total:
            stop = min(total, start + size)
            began = time.perf_counter()
            yield start, stop
            held.release()
            elapsed = time.perf_counter() - began
            grow = 4.0 if elapsed <= 0 else min(4.0, seconds / elapsed)
            size = min(most, max(1, int((stop - start) * grow)))
            start = stop
