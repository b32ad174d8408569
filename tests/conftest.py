import os
import signal
from pathlib import Path

import pytest

os.environ.setdefault("MPLBACKEND", "Agg")

_STOPPING = {signal.SIGINT, signal.SIGTERM}


def _stopping_signals_state() -> tuple[set, set]:
    """(SIGINT/SIGTERM ignored, SIGINT/SIGTERM blocked in this thread) in this process."""
    ignored = {s for s in _STOPPING if signal.getsignal(s) is signal.SIG_IGN}
    status = Path("/proc/self/status")
    if status.exists():  # also what C code set, which getsignal does not see
        for line in status.read_text().splitlines():
            if line.startswith("SigIgn:"):
                mask = int(line.split()[1], 16)
                ignored |= {s for s in _STOPPING if mask >> (s - 1) & 1}
    blocked = _STOPPING & set(signal.pthread_sigmask(signal.SIG_BLOCK, []))
    return ignored, blocked


@pytest.fixture(autouse=True)
def _stopping_signals_left_alone():
    """A test must leave SIGINT and SIGTERM as it found them: ignored or blocked here, they
    stay so in every process a later test starts (an ignored signal survives exec), whose
    interrupts then never arrive -- the likely cause of a CI run in which two interrupt
    tests of one xdist worker timed out (tests/interface/test_interrupts.py)."""
    before = _stopping_signals_state()
    yield
    after = _stopping_signals_state()
    assert after == before, f"SIGINT/SIGTERM (ignored, blocked) were {before}, left {after}"
