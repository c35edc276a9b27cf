"""A study's runs as the repository keeps them, so that `run_study.py --evidence DIR` continues
a study on a machine that holds nothing but a clone:

- a finished (or failed) run's compact result, DIR/runs/<name>/ (compact_study.compact_run),
  written as soon as the run settles: it is never run again;
- a run cut short, parked in DIR/parked/<name>.tar.xz: its knobs, log, burst records and cost,
  its newest restart file and the fluid checkpoint (one file per rank) that file names. A
  launch on a machine without the run's own folder unpacks it and resumes from it, giving
  the same rows, byte for byte, as a resume in the run's own folder (a resumed run differs
  from the uninterrupted one only as LIGGGHTS's second `run` does: tests/faults/kill_check.py).
  The archive is removed once the run's compact result is kept: git keeps it, the tree not.

The fluid checkpoint dominates a parked run (the paper's scene: 14-32 MB of populations,
8-19 MB compressed: the low bits of doubles do not compress), so runs are parked only when a
runner stops with them unfinished, never as a matter of course, and only once they are
MIN_PARKED_SHARE done: git keeps every archive, and a run's first quarter costs less to make
again than its archive weighs in the history.

DIR/summary.txt says what is kept: its first line is what study_io.load_summary reads.
"""
import json
import os
import re
import shutil
import tarfile

import compact_study
from ensemble import restart_files, run_state
from study_progress import end_step, last_step

PARKED = "parked"
MIN_PARKED_SHARE = 0.25
# The files a run needs to continue besides its restart file and checkpoint (stdout.txt
# repeats the log; a resumed launch appends to both, so a missing one is simply begun anew).
KEPT_TO_RESUME = ("knobs.json", "log.liggghts", "bursts.txt", "cost.txt", "deposit_speeds.txt")
# A fluid checkpoint's file: <prefix>.fluid.<DEM step>.<rank> (restart_record.h)
_CHECKPOINT_FILE = re.compile(r"^(.+\.fluid\.\d+)\.\d+$")


def parked_archive(evidence, name):
    return os.path.join(evidence, PARKED, f"{name}.tar.xz")


def committed_state(evidence, name):
    """'done' or 'failed' for a run whose compact result is kept in evidence, else None."""
    try:
        with open(os.path.join(evidence, "runs", name, "state.txt")) as f:
            state = f.readline().strip()
    except OSError:
        return None
    return state if state in ("done", "failed") else None


def checkpoint_files(run_dir, restart_file):
    """The fluid checkpoint files (one per rank) that restart_file names: fix lbm/pore's
    restart record ends with the checkpoint's path, relative to the run's folder, and a
    terminating zero (liggghts_plugin/lbm_pore/restart_record.h)."""
    with open(restart_file, "rb") as f:
        data = f.read()
    return sorted(os.path.join(run_dir, name) for name in os.listdir(run_dir)
                  if _CHECKPOINT_FILE.match(name)
                  and _CHECKPOINT_FILE.match(name).group(1).encode() + b"\x00" in data)


def share_done(run_dir):
    """How much of its steps the run has made (0 when unknown)."""
    try:
        with open(os.path.join(run_dir, "knobs.json")) as f:
            knobs = json.load(f)
        return (last_step(run_dir) or 0) / end_step(knobs)
    except (OSError, ValueError, KeyError, ZeroDivisionError):
        return 0.0


def park(run_dir, evidence, name, min_share=MIN_PARKED_SHARE):
    """Packs a run cut short into evidence/parked/<name>.tar.xz; returns the archive's path,
    or None when the run has no restart file (or no checkpoint beside it) to continue from,
    or has made less than min_share of its steps."""
    if share_done(run_dir) < min_share:
        return None
    for restart in restart_files(run_dir):
        checkpoints = checkpoint_files(run_dir, restart)
        if checkpoints:
            break
    else:
        return None
    archive = parked_archive(evidence, name)
    os.makedirs(os.path.dirname(archive), exist_ok=True)
    members = [os.path.join(run_dir, f) for f in KEPT_TO_RESUME if os.path.exists(os.path.join(run_dir, f))]
    with tarfile.open(archive + ".new", "w:xz", preset=6) as tar:
        for path in members + [restart] + checkpoints:
            tar.add(path, arcname=os.path.basename(path))
    os.replace(archive + ".new", archive)
    return archive


def unpark(evidence, name, run_dir):
    """Unpacks a parked run into run_dir when run_dir holds no restart file of its own (a
    fresh machine): True if it did. A run folder that can resume by itself is left alone."""
    archive = parked_archive(evidence, name)
    if not os.path.exists(archive) or restart_files(run_dir):
        return False
    shutil.rmtree(run_dir, ignore_errors=True)
    os.makedirs(run_dir)
    with tarfile.open(archive, "r:xz") as tar:
        for member in tar.getmembers():
            if not member.isfile() or os.path.basename(member.name) != member.name:
                raise ValueError(f"{archive}: unexpected member {member.name!r}")
        tar.extractall(run_dir)
    return True


def keep_settled(run_dir, evidence, name):
    """Keeps the compact result of a run that finished or failed, and drops its parked copy.
    True if the run had settled."""
    if run_state(run_dir)[0] not in ("done", "failed"):
        return False
    compact_study.compact_run(run_dir, os.path.join(evidence, "runs", name))
    if os.path.exists(parked_archive(evidence, name)):
        os.remove(parked_archive(evidence, name))
        if not os.listdir(os.path.join(evidence, PARKED)):
            os.rmdir(os.path.join(evidence, PARKED))
    return True


def write_summary(evidence, study, size, names):
    """evidence/summary.txt: each of the study's runs (names) as the repository holds it."""
    states = {n: committed_state(evidence, n) or ("parked" if os.path.exists(parked_archive(evidence, n))
                                                  else "to do") for n in names}
    count = lambda s: sum(v == s for v in states.values())  # noqa: E731
    kept = count("done") + count("failed")
    lines = [f"study {study} ({size}, pool): {count('done')} finished, {count('failed')} failed, "
             f"0 incomplete of {kept} kept here; {count('parked')} parked, {count('to do')} to do "
             f"of {len(names)}"]
    lines += [f"  {n:<28} {s}" for n, s in states.items()]
    os.makedirs(evidence, exist_ok=True)
    with open(os.path.join(evidence, "summary.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
