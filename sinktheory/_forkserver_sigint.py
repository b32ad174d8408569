"""Imported first by the sweep's forkserver (:func:`sinktheory.sweep.runner._context`): it
ignores SIGINT from then on.

Ctrl-C reaches the whole process group.  The forkserver ignores SIGINT once it has
imported its preload modules, but while it imports them (numba, scipy: seconds) a Ctrl-C
ended it with a traceback of 36 lines, and the driver's next ``submit`` failed with
EOFError instead of stopping with one line.  Its workers ignore SIGINT as well
(:func:`sinktheory.sweep.runner._start_worker`): the driver alone ends them.

The driver starts the forkserver with SIGINT already ignored
(:func:`sinktheory.sweep.runner._start_forkserver`), which covers the interpreter's own
start-up, before this module runs; a forkserver started otherwise is covered from here on.

Only the forkserver is affected: the module looks for ``multiprocessing.forkserver.main``
among its callers, so importing it anywhere else (a doctest collector, an import test)
changes nothing.  An ignored SIGINT would otherwise stay ignored in that process and in
every process it starts, which a test run showed: its later interrupt tests timed out.
"""

import os
import signal
import sys

__all__: list[str] = []


def _in_forkserver() -> bool:
    """Whether this import runs inside ``multiprocessing.forkserver.main``."""
    frame = sys._getframe(1)
    tail = os.path.join("multiprocessing", "forkserver.py")
    while frame is not None:
        code = frame.f_code
        if code.co_name == "main" and code.co_filename.endswith(tail):
            return True
        frame = frame.f_back
    return False


if _in_forkserver():
    signal.signal(signal.SIGINT, signal.SIG_IGN)
