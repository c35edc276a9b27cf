"""What a running study shows while it runs: runs done, failed, running and to do, each
running run's DEM step (its log's last thermo row) and an estimate of the time left, printed
every few seconds and kept in <study>/progress.txt (`cat` it from another shell).

The estimate: each running run's speed is the steps it made since its launch over the time
since; the steps left (the running runs' and those still to run) over the study's total
speed (the mean speed times the runs at a time)."""
import os
import threading
import time

import ensemble
from repeating import Repeating


def last_step(run_dir):
    """The step of the last thermo row of the run's log (None before the first). Reads only
    the log's tail: a paper-length log holds thousands of rows."""
    log = os.path.join(run_dir, "log.liggghts")
    try:
        with open(log, "rb") as f:
            f.seek(0, os.SEEK_END)
            f.seek(max(0, f.tell() - 65536))
            lines = f.read().decode(errors="replace").splitlines()
    except OSError:
        return None
    for line in reversed(lines):
        words = line.split()
        if words and words[0].isdigit() and len(words) > 2:
            try:
                [float(w) for w in words]
            except ValueError:
                continue
            return int(words[0])
    return None


def end_step(knobs):
    return int(knobs.get("warmup", 0)) + int(knobs["steps"])


def _hours(seconds):
    return f"{seconds / 3600:.2f} h" if seconds >= 3600 else f"{seconds / 60:.1f} min"


class StudyProgress(Repeating):
    def __init__(self, study_dir, runs, parallel, every=60.0, printer=print):
        super().__init__(every)
        self.study_dir, self.runs, self.parallel = study_dir, dict(runs), max(1, parallel)
        self.printer = printer
        self.running = {}  # name -> (launch time, step at launch)
        self.lock = threading.Lock()

    def _dir(self, name):
        return os.path.join(self.study_dir, "runs", name)

    def started(self, name, launch_knobs):
        with self.lock:
            self.running[name] = (time.time(), last_step(self._dir(name)) or 0)

    def stopped(self, name):
        with self.lock:
            self.running.pop(name, None)

    def line(self):
        """One line: the counts, the running runs' steps and the time left."""
        counts = {"done": 0, "failed": 0}
        rates, left, parts, waiting = [], 0, [], 0
        with self.lock:
            running = dict(self.running)
        now = time.time()
        for name, knobs in self.runs.items():
            run_dir, end = self._dir(name), end_step(knobs)
            if name in running:
                launched, first = running[name]
                step = last_step(run_dir) or first
                if now > launched and step > first:
                    rates.append((step - first) / (now - launched))
                left += max(0, end - step)
                parts.append(f"{name} {step}/{end} ({100.0 * step / end:.0f} %)")
                continue
            state, _ = ensemble.run_state(run_dir) if os.path.isdir(run_dir) else ("incomplete", "")
            if state in counts:
                counts[state] += 1
            else:
                waiting += 1
                left += max(0, end - (last_step(run_dir) or 0))
        eta = _hours(left / (sum(rates) / len(rates) * min(self.parallel, len(rates) + waiting))) \
            if rates else "unknown (no step made yet)"
        return (f"progress: {counts['done']} done, {counts['failed']} failed, {len(parts)} running, "
                f"{waiting} to do of {len(self.runs)}; time left {eta}"
                + ("; " + ", ".join(parts) if parts else ""))

    def report(self):
        text = time.strftime("%Y-%m-%d %H:%M:%S ") + self.line()
        with open(os.path.join(self.study_dir, "progress.txt"), "w") as f:
            f.write(text + "\n")
        self.printer(text, flush=True)

    def tick(self):
        self.report()
