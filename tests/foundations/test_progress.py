"""Progress on stderr: a bar on a terminal, a few plain lines in a log, nothing when off."""

import io
import os
import signal
import subprocess
import sys

from sinktheory.progress import LOG_INTERVAL, ProgressBar


class Terminal(io.StringIO):
    def isatty(self):
        return True


def test_terminal_bar_redraws_in_place():
    term = Terminal()
    bar = ProgressBar(5, stream=term, delay=0, interval=0, label="engine ")
    for _ in range(5):
        bar.update(1)
    bar.close()
    out = term.getvalue()
    assert out.count("\r") >= 5 and out.endswith("\n") and out.count("\n") == 1
    assert "engine: 100%" in out and "5/5" in out and bar.drawn


def test_log_gets_lines_not_a_flood():
    """Not a terminal: whole lines, at most one per interval (here the first at the start,
    since delay = 0, then none for 10,000 quick updates) plus the final count."""
    log = io.StringIO()
    bar = ProgressBar(10_000, stream=log, delay=0, label="sweep ", unit="point")
    for _ in range(10_000):
        bar.update(1)
    bar.close()
    lines = log.getvalue().splitlines()
    assert "\r" not in log.getvalue()
    assert len(lines) == 2, lines
    assert lines[0].startswith("sweep   0% 0/10000")
    assert lines[1].startswith("sweep 100% 10000/10000") and "point/s" in lines[1]
    assert LOG_INTERVAL >= 10  # a long run writes a line every LOG_INTERVAL s, no more


def test_short_work_and_disabled_bars_print_nothing():
    for kwargs in ({"enabled": True}, {"enabled": False, "delay": 0, "interval": 0}):
        for stream in (io.StringIO(), Terminal()):
            bar = ProgressBar(3, stream=stream, **kwargs)
            bar.update(2)
            bar.update(5)  # more than the total is clipped
            bar.close()
            assert stream.getvalue() == "" and bar.done == 3 and not bar.drawn


def test_enabled_attribute_means_a_terminal_bar():
    """Subclasses that draw their own line (the sweep's point counter) test ``enabled``:
    True only on a terminal, as before tqdm."""
    assert ProgressBar(1, stream=Terminal()).enabled
    assert not ProgressBar(1, stream=io.StringIO()).enabled
    assert not ProgressBar(1, stream=Terminal(), enabled=False).enabled


def test_reproduce_progress_reaches_a_log_file(tmp_path):
    """`reproduce` with stderr redirected to a file: the announcement with the estimate
    before the figure and its time after it are lines in the file, stdout stays clean."""
    log = tmp_path / "log.txt"
    env = {**os.environ, "MPLBACKEND": "Agg"}
    with open(log, "w") as err:
        proc = subprocess.run(
            [sys.executable, "-m", "sinktheory", "reproduce", "--figure", "2", "--quick"]
            + ["--out", str(tmp_path / "out")],
            stdout=subprocess.PIPE,
            stderr=err,
            text=True,
            env=env,
        )
    assert proc.returncode == 0
    lines = log.read_text().splitlines()
    assert lines[0].startswith("reproduce: 1 figure(s) at quick fidelity, expected about ")
    assert lines[1].startswith("Fig. 2 (1/1): shapes of the flat well; about ")
    assert lines[2].startswith("Fig. 2: done in ")
    assert "Fig. 2: " in proc.stdout and "about" not in proc.stdout


def test_a_subclass_drawing_its_own_line_still_ends_it():
    """The sweep's point counter overrides update() and writes its own line; close() ends
    that line as the hand-written bar did."""

    class Own(ProgressBar):
        def update(self, units):
            self.done += units
            if self.enabled:
                self.stream.write(f"\r{self.done}/{self.total} points")
                self.drawn = True

    term = Terminal()
    bar = Own(2, stream=term)  # tqdm itself waits its delay (2 s) and shows nothing
    bar.update(2)
    bar.close()
    assert term.getvalue() == "\r2/2 points\n"


def test_the_forkservers_sigint_module_changes_no_other_process(tmp_path):
    """sinktheory._forkserver_sigint ignores SIGINT in the sweep's forkserver only: imported
    anywhere else (say, by a doctest collector) it leaves Ctrl-C alone -- an ignored SIGINT
    is inherited by every process started later, whose interrupts then never arrive.  In
    a forkserver it does ignore SIGINT, already while the later preload modules import."""
    plain = subprocess.run(
        [sys.executable, "-c", "import signal, sinktheory._forkserver_sigint; "
         "print(signal.getsignal(signal.SIGINT) is signal.default_int_handler)"],
        capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert plain.stdout.strip() == "True", plain.stderr
    probe = tmp_path / "probe_mod.py"
    probe.write_text("import signal, pathlib\npathlib.Path(__file__).with_suffix('.out')"
                     ".write_text(str(signal.getsignal(signal.SIGINT)))\n")  # fmt: skip
    script = (
        "import multiprocessing as mp, time, pathlib\n"
        "if __name__ == '__main__':\n"
        "    mp.set_forkserver_preload(['sinktheory._forkserver_sigint', 'probe_mod'])\n"
        "    from multiprocessing import forkserver\n"
        "    forkserver.ensure_running()\n"
        "    out = pathlib.Path('probe_mod.out')\n"
        "    for _ in range(300):\n"
        "        if out.exists() and out.read_text():\n"
        "            break\n"
        "        time.sleep(0.1)\n"
        "    print(out.read_text())\n"
    )
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(tmp_path), *sys.path])}
    served = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            timeout=60, cwd=tmp_path, env=env)  # fmt: skip
    assert served.stdout.strip() == str(int(signal.SIG_IGN)), served.stderr
