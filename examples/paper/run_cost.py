"""What each run of a study has cost: the wall time and cores of every launch of the run,
kept in its own folder (cost.txt, one line per launch: seconds and cores) so that the cost
of a study resumed over several sittings is the sum over all its launches, not over the
last runner's. The line of a running launch is rewritten every minute, so a launch killed
with its runner (a machine reset) still counts up to its last update.

A run made before cost.txt existed falls back to its log's "Loop time of T on N procs"
lines, which a killed launch never wrote: that figure is a lower bound."""
import os
import re
import threading
import time

from repeating import Repeating

COST_FILE = "cost.txt"
_LOOP_TIME = re.compile(r"^Loop time of ([0-9.eE+-]+) on (\d+) procs", re.M)


def _read_lines(run_dir):
    try:
        with open(os.path.join(run_dir, COST_FILE)) as f:
            return [line.split() for line in f if line.strip()]
    except OSError:
        return None


def _write_lines(run_dir, lines):
    path = os.path.join(run_dir, COST_FILE)
    with open(path + ".new", "w") as f:
        f.write("".join(f"{float(s):.1f} {int(c)}\n" for s, c in lines))
    os.replace(path + ".new", path)  # never half a file, whenever the runner dies


class LaunchClock(Repeating):
    """Context manager around one launch of the runs in `run_dirs`, each on `cores` cores:
    appends the launch's line to each run's cost.txt and keeps it up to date."""

    def __init__(self, run_dirs, cores, every=60.0):
        super().__init__(every)
        self.run_dirs, self.cores = list(run_dirs), int(cores)
        self.start = None
        self.lock = threading.Lock()

    def begin(self):
        self.start = time.time()
        self._update(first=True)

    def tick(self):
        self._update()

    def _update(self, first=False):
        seconds = time.time() - self.start
        with self.lock:
            for run_dir in self.run_dirs:
                lines = _read_lines(run_dir) or []
                if first:
                    lines.append([0.0, self.cores])
                lines[-1] = [seconds, self.cores]
                _write_lines(run_dir, lines)


def run_core_hours(run_dir):
    """(core-hours, exact): the sum over the run's launches from cost.txt (exact: True), or,
    without it, from its log's Loop time lines (exact: False, a lower bound)."""
    lines = _read_lines(run_dir)
    if lines is not None:
        return sum(float(s) * int(c) for s, c in lines) / 3600.0, True
    try:
        with open(os.path.join(run_dir, "log.liggghts"), errors="replace") as f:
            text = f.read()
    except OSError:
        return 0.0, False
    return sum(float(t) * int(n) for t, n in _LOOP_TIME.findall(text)) / 3600.0, False


def study_core_hours(run_dirs):
    """(core-hours, exact) summed over runs: exact only if every run's is."""
    total, exact = 0.0, True
    for run_dir in run_dirs:
        hours, run_exact = run_core_hours(run_dir)
        total += hours
        exact = exact and run_exact
    return total, exact
