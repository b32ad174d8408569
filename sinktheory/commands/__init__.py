"""The subcommands of ``sinktheory``: one module each, listed in :data:`COMMANDS`.

Each module defines ``NAME``, ``HELP``, ``add_arguments(parser)`` and ``run(args)``, which
returns an :class:`~sinktheory.commands._common.Output`.  A command computes everything
before it writes any file, so bad input never leaves partial output behind.
"""

from . import derive, floquet, period, reproduce, series, simulate, sink, sweep, well

COMMANDS = (well, sink, derive, simulate, period, series, reproduce, floquet, sweep)
