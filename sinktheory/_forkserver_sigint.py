"""Imported first by the sweep's forkserver (:func:`sinktheory.sweep.runner._context`): it
ignores SIGINT from then on.

Ctrl-C reaches the whole process group.  The forkserver ignores SIGINT once it has
imported its preload modules, but while it imports them (numba, scipy: seconds) a Ctrl-C
ended it with a traceback of 36 lines, and the driver's next ``submit`` failed with
EOFError instead of stopping with one line.  Its workers ignore SIGINT as well
(:func:`sinktheory.sweep.runner._start_worker`): the driver alone ends them.  Importing
this module anywhere else would make that process ignore Ctrl-C; nothing else does.
"""

import signal

__all__: list[str] = []

signal.signal(signal.SIGINT, signal.SIG_IGN)
