#!/usr/bin/python3
"""The same runs (by name) of two study folders side by side: for each run that both hold,
over the time after the warm-up that both reached, the mean deposited count and the mean
P / P_out with 95 % block-bootstrap intervals, the bursts per 10^4 time units and the mean
deposited count and P at the bursts' peaks (figures/calibration.py's twin statistics).
For a change of the model or of in.pore between two otherwise equal studies, e.g. the
calibration study made before and after the inlet region was topped up once per crossing:

    compare_studies.py studies/calibration studies/calibration_corrected --runs 5_cells \\
        --labels "every 100 time units" "once per crossing"

Prints a markdown table. Usage: compare_studies.py A B [--runs REGEX] [--labels LA LB]
"""
import argparse
import json
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures.calibration import TWIN_HEADER, run_times, twin_row, twin_statistics  # noqa: E402


def study_runs(study):
    """name -> run dict (name, folder, knobs) of every run folder of the study."""
    runs = {}
    top = os.path.join(study, "runs")
    for name in sorted(os.listdir(top)) if os.path.isdir(top) else []:
        folder = os.path.join(top, name)
        knobs_file = os.path.join(folder, "knobs.json")
        if os.path.exists(os.path.join(folder, "log.liggghts")) and os.path.exists(knobs_file):
            with open(knobs_file) as f:
                runs[name] = dict(name=name, folder=folder, knobs=json.load(f))
    return runs


def compare(study_a, study_b, pattern=".", labels=("A", "B")):
    rng = np.random.default_rng(1)
    a_runs, b_runs = study_runs(study_a), study_runs(study_b)
    lines = [TWIN_HEADER[0].replace("| variant |", "| study |"), TWIN_HEADER[1]]
    for name in sorted(set(a_runs) & set(b_runs)):
        if not re.search(pattern, name):
            continue
        times = [run_times(runs[name]) for runs in (a_runs, b_runs)]
        if any(t is None or not len(t[0]) for t in times):
            continue
        until = min(t[0][-1] - t[1] for t in times)
        for runs, t, label in zip((a_runs, b_runs), times, labels):
            lines.append(twin_row(name, label, twin_statistics(runs[name], t, rng, until)))
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study_a")
    parser.add_argument("study_b")
    parser.add_argument("--runs", default=".", help="only the runs whose names match")
    parser.add_argument("--labels", nargs=2, default=None, help="the two studies' names in the table")
    args = parser.parse_args()
    labels = args.labels or (os.path.basename(os.path.normpath(args.study_a)),
                             os.path.basename(os.path.normpath(args.study_b)))
    print(compare(args.study_a, args.study_b, args.runs, labels))


if __name__ == "__main__":
    main()
