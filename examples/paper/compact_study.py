#!/usr/bin/python3
"""Copies what a study's evidence needs into a small folder that can be kept in the
repository (a study's own folder holds restart files and fluid checkpoints of tens of MB):
summary.txt, results.json and the plots, the analysis's table if any, and per run its
bursts.txt, its cost (cost.txt, run_cost), its deposit speed survey (deposit_speeds.txt), its
snapshot figure's frames (snapshots.npz, render_snapshot.py --keep) and replay record
(replay.json, replay_window.py) if any, and the thermo columns the analyses read
(thermo.csv.gz, every `every`-th row and every row from a burst's window before its peak,
BURST_WINDOW fluid steps, to half a window after it; COLUMNS and those the run's thermo_extra
asked for, WINDOW_COLUMNS left blank in the rows outside those windows; whole numbers exactly,
the rest at KEPT_DIGITS significant digits), with the ERROR line of a run that stopped.
analyze.py reads the compacted folder as it reads the study (study_io).

Usage: compact_study.py <study folder> <destination> [--every N]
       compact_study.py --blank-between-bursts <compacted run folder>...   (a run kept before
                                                                  with WINDOW_COLUMNS in every row)
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
# Read only at a burst's peak or in its window (figures.hold, figures.porediameter's f_a,
# deposit_measure.py): the forces on all particles and on the deposit, its particles on the
# wall, the deposited counts under the scaled speed bounds. Blank in the rows kept between
# the bursts' windows, they take about a third less room (a paper-length run of 79 bursts:
# 0.81 -> 0.6 MB); study_io.thermo reads a blank as NaN.
WINDOW_COLUMNS = ("walls[2]", "pore[14]", "pore[26]") + tuple(f"pore[{i}]" for i in range(28, 37))
# Significant digits of a kept value that is not a whole number: a pressure of 0.3 P_out to
# 10^-6 P_out, far below any digit doc/ reports, and a paper-length run's rows within about
# 0.5 MB (8 digits took 0.4-0.8 MB a run at 27-66 bursts).
KEPT_DIGITS = 6


def kept_value(value, digits=KEPT_DIGITS):
    """A thermo value as the compact result writes it: steps, atom and deposit counts (whole
    numbers) exactly, the rest at `digits` significant digits (None: every digit it has)."""
    if math.isfinite(value) and value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return repr(value) if digits is None else f"{value:.{digits}g}"


def write_kept_thermo(out, names, columns, kept_rows, in_window, digits=KEPT_DIGITS):
    """out/thermo.csv.gz: the columns `names` at the row indices `kept_rows` (kept_value at
    `digits`), WINDOW_COLUMNS blank where in_window(row index) is false, replacing any kept
    thermo file of an earlier compaction."""
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
            inside = in_window(i)
            w.writerow([kept_value(float(columns[c][i]), digits) if inside or c not in WINDOW_COLUMNS else ""
                        for c in names])


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
    steps = columns["Step"]
    near = near_a_burst(run, knobs, steps)
    write_kept_thermo(out, names, columns,
                      [i for i in range(len(steps)) if i % every == 0 or i == len(steps) - 1 or near(i)], near)


def near_a_burst(run, knobs, steps):
    """near(i): whether thermo row i lies in a burst's window before its peak (BURST_WINDOW)
    or half a window after it."""
    peaks = [b["step"] for b in study_io.bursts(run)]
    window = study_io.burst_window_dem_steps(run, knobs)
    return lambda i: any(-window <= steps[i] - p <= window / 2 for p in peaks)


def blank_between_bursts(kept_run):
    """A run compacted before WINDOW_COLUMNS were left blank outside the bursts' windows,
    rewritten so: the same rows and columns, every other value exactly as it was kept (so
    every analysis of it gives what it gave)."""
    columns = study_io.thermo(kept_run)
    if columns:
        near = near_a_burst(kept_run, study_io.read_knobs(kept_run), columns["Step"])
        write_kept_thermo(kept_run, list(columns), columns, range(len(columns["Step"])), near, digits=None)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("study", nargs="?")
    parser.add_argument("dest", nargs="?")
    parser.add_argument("--every", type=int, default=10)
    parser.add_argument("--blank-between-bursts", nargs="+", metavar="KEPT_RUN", default=[])
    args = parser.parse_args()
    if args.blank_between_bursts:
        for run in args.blank_between_bursts:
            blank_between_bursts(run)
    elif args.study and args.dest:
        compact(args.study, args.dest, args.every)
    else:
        parser.error("give <study folder> <destination>, or --blank-between-bursts <compacted run folder>...")
