#!/usr/bin/python3
"""Copies what a study's evidence needs into a small folder that can be kept in the
repository (a study's own folder holds restart files and fluid checkpoints of tens of MB):
summary.txt, results.json and the plots, the analysis's table if any, and per run its
bursts.txt, its cost (cost.txt, run_cost), its deposit speed survey (deposit_speeds.txt), its
snapshot figure's frames (snapshots.npz, render_snapshot.py --keep) and replay record
(replay.json, replay_window.py) if any, and the thermo columns the analyses read
(thermo.csv.gz, every `every`-th row and every row from a burst's window before its peak,
BURST_WINDOW fluid steps, to half a window after it; COLUMNS and those the run's thermo_extra
asked for; whole numbers exactly, the rest at KEPT_DIGITS significant digits), with the ERROR
line of a run that stopped. analyze.py reads the compacted folder as it reads the study
(study_io).

Usage: compact_study.py <study folder> <destination> [--every N]
       compact_study.py --reround <compacted run folder>...   (a folder kept at more digits)
"""
import argparse
import csv
import glob
import gzip
import io
import math
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study_io  # noqa: E402
from ensemble import run_state  # noqa: E402
import run_cost  # noqa: E402

# pore[27]: P across the pore; pore[28-33]: the deposited count under the scaled speed bounds;
# pore[26], [34], [35], [36]: the deposit's particles on the wall, the fluid's, the wall's and
# every force on it
COLUMNS = ("Step", "Atoms", "pore[16]", "pore[17]", "pore[7]", "pore[6]", "pore[8]", "pore[10]",
           "walls[2]", "pore[14]", "pore[18]", "pore[27]") + tuple(f"pore[{i}]" for i in range(28, 34)) + \
    ("pore[26]", "pore[34]", "pore[35]", "pore[36]")
# Significant digits of a kept value that is not a whole number: a pressure of 0.3 P_out to
# 10^-6 P_out, far below any digit doc/ reports, and a paper-length run's rows within about
# 0.5 MB (8 digits took 0.4-0.8 MB a run at 27-66 bursts).
KEPT_DIGITS = 6


def kept_value(value):
    """A thermo value as the compact result writes it: steps, atom and deposit counts (whole
    numbers) exactly, the rest at KEPT_DIGITS significant digits."""
    if math.isfinite(value) and value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return f"{value:.{KEPT_DIGITS}g}"


def write_kept_thermo(out, names, columns, kept_rows):
    """out/thermo.csv.gz: the columns `names` at the row indices `kept_rows`, replacing any
    kept thermo file of an earlier compaction."""
    for old in study_io.KEPT_THERMO:  # a folder compacted before keeps no stale copy
        if os.path.exists(os.path.join(out, old)):
            os.remove(os.path.join(out, old))
    # gzip without a time stamp: the same rows give the same bytes (git sees no change)
    with open(os.path.join(out, "thermo.csv.gz"), "wb") as raw, \
            gzip.GzipFile(fileobj=raw, mode="wb", mtime=0) as packed, \
            io.TextIOWrapper(packed, newline="") as f:
        w = csv.writer(f)
        w.writerow(names)
        for i in kept_rows:
            w.writerow([kept_value(float(columns[c][i])) for c in names])


def asked_columns(knobs):
    """The thermo columns a run's knob thermo_extra added (in.pore's `thermo_extra`), named as
    LIGGGHTS heads them (f_pore[3] -> pore[3], c_x -> x, v_x -> x): the study that asked for
    them reads them (pvpflux the fluxes and the inlet velocity, conc the particle volume
    through the inlet plane), so they are kept beside COLUMNS."""
    return tuple(re.sub(r"^[fcv]_", "", word) for word in knobs.get("thermo_extra", "").split())


def compact(study, dest, every=10):
    os.makedirs(dest, exist_ok=True)
    for pattern in ("summary.txt", "results.json", "*.png", "calibration.md", "progress.txt"):
        for path in glob.glob(os.path.join(study, pattern)):
            shutil.copy(path, dest)
            if path.endswith((".txt", ".json", ".md")):  # the study's own paths, relative
                target = os.path.join(dest, os.path.basename(path))
                with open(target) as f:
                    text = f.read()
                with open(target, "w") as f:
                    f.write(text.replace(os.path.abspath(study) + "/", "").replace(os.path.abspath(study), "."))
    for run in sorted(glob.glob(os.path.join(study, "runs", "*"))):
        compact_run(run, os.path.join(dest, "runs", os.path.basename(run)), every)


def compact_run(run, out, every=10):
    """One run's compact result in `out` (see the module's docstring)."""
    os.makedirs(out, exist_ok=True)
    for keep in ("bursts.txt", "knobs.json", "deposit_speeds.txt", run_cost.COST_FILE,
                 "snapshots.npz", "replay.json"):
        if os.path.exists(os.path.join(run, keep)):
            shutil.copy(os.path.join(run, keep), out)
    state, reason = run_state(run)
    with open(os.path.join(out, "state.txt"), "w") as f:
        f.write(f"{state}\n{reason}\n")
    columns = study_io.thermo(run)
    if not columns:
        return
    knobs = study_io.read_knobs(run)
    names = [c for c in dict.fromkeys(COLUMNS + asked_columns(knobs)) if c in columns]
    peaks = [b["step"] for b in study_io.bursts(run)]
    steps = columns["Step"]
    window = study_io.burst_window_dem_steps(run, knobs)
    near = lambda s: any(-window <= s - p <= window / 2 for p in peaks)  # noqa: E731
    write_kept_thermo(out, names, columns,
                      [i for i, s in enumerate(steps) if i % every == 0 or i == len(steps) - 1 or near(s)])


def reround(kept_run):
    """A compacted run's kept rows rewritten at KEPT_DIGITS (kept_value): the same rows and
    columns, for a folder compacted when the rows kept 8 digits."""
    columns = study_io.thermo(kept_run)
    if columns:
        write_kept_thermo(kept_run, list(columns), columns, range(len(columns["Step"])))


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("study", nargs="?")
    parser.add_argument("dest", nargs="?")
    parser.add_argument("--every", type=int, default=10)
    parser.add_argument("--reround", nargs="+", metavar="KEPT_RUN", default=[])
    args = parser.parse_args()
    if args.reround:
        for run in args.reround:
            reround(run)
    elif args.study and args.dest:
        compact(args.study, args.dest, args.every)
    else:
        parser.error("give <study folder> <destination>, or --reround <compacted run folder>...")
