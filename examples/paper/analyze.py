#!/usr/bin/python3
"""Analyses a finished study from its runs' own files: picks the figure module by the study's
name (figures/<study>.py), writes <study>/results.json and the plot, prints the row of
doc/paper.md (paper's value, ours with its 95 % bootstrap interval over runs, run cost).

Usage: analyze.py <study folder> [--figure NAME]   (run_study.py calls it after the runs)

--figure analyses the folder's runs as another figure: e.g. the single-burst figure from the
largest burst among a seed ensemble, `analyze.py studies/dropvol --figure singlejump`
(results in <folder>/<NAME>/).
"""
import importlib
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from study_io import load_summary  # noqa: E402


def _plain(value):
    """JSON-safe: numpy scalars to floats, nan to None."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, (float, np.floating)):
        return float(value) if np.isfinite(value) else None
    if isinstance(value, np.integer):
        return int(value)
    return value


def analyze(study_dir, figure=None):
    summary = load_summary(study_dir)
    out_dir = study_dir
    if figure is not None and figure != summary["study"]:
        out_dir = os.path.join(study_dir, figure)
        os.makedirs(out_dir, exist_ok=True)
    module = importlib.import_module(f"figures.{figure or summary['study']}")
    result = module.analyze(summary, out_dir)
    result["core_hours"] = round(summary["core_hours"], 4)
    result["runs_of_study"] = summary["study"]
    with open(os.path.join(out_dir, "results.json"), "w") as f:
        json.dump(_plain(result), f, indent=1)
    print(f"| {result['figure']} | {result['paper']} | {result['ours']} | "
          f"{result['finished']}/{result['runs']} runs, {result['core_hours']} core-h |")
    return result


if __name__ == "__main__":
    if len(sys.argv) == 2:
        analyze(sys.argv[1])
    elif len(sys.argv) == 4 and sys.argv[2] == "--figure":
        analyze(sys.argv[1], sys.argv[3])
    else:
        sys.exit(__doc__)
