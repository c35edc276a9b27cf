#!/usr/bin/python3
"""Analyses a finished study from its runs' own files: picks the figure module by the study's
name (figures/<study>.py), writes <study>/results.json and the plot, prints the row of
doc/paper.md (paper's value, ours with its 95 % bootstrap interval over runs, run cost).

Usage: analyze.py <study folder> [--figure NAME] [--runs REGEX] [--as-it-stands] [--out DIR]
                  [--with FOLDER ...]
(run_study.py calls it after the runs)

--figure analyses the folder's runs as another figure: e.g. the single-burst figure from the
largest burst among a seed ensemble, `analyze.py studies/dropvol --figure singlejump`
(results in <folder>/<NAME>/).
--runs REGEX analyses only the runs whose names match (and counts only their cost): the
single-burst figure from one run of a study, `analyze.py doc/paper/porediameter --figure
singlejump --runs '^D_3.52_seed_400009$' --out doc/paper`.
--as-it-stands also takes the runs cut short or still under way, with the rows and bursts they
have so far (a paper-length run built up over several sittings); the results name them.
--with FOLDER takes the finished runs of another study folder (or its compacted evidence)
beside the study's own, as if they were its runs: dropvol's new seeds with the calibration's
paper-length run, `analyze.py studies/dropvol --with doc/calibration/paper_run`. FOLDER may
be one run's folder of another study whose scene is this study's (it must differ from the
study's plan only in its seed and in what it writes; refused otherwise): porediameter's run
at the default pore as a dropvol seed, `--with doc/paper/porediameter/runs/D_3.52_seed_400009`.
--out writes the results and the plot into DIR instead (the study folder is left as it is: a
study's compacted evidence, compact_study.py, can be analysed again beside it).
"""
import argparse
import importlib
import json
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_cost  # noqa: E402
from study_io import kept_thermo, load_summary  # noqa: E402


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


def take_runs_as_they_stand(summary, study_dir):
    """Marks the runs that have a log but did not finish as done, for the analyses that take
    finished runs only; returns their names."""
    def has_rows(r):  # its log, or the thermo rows compacted evidence kept
        folder = r.get("folder") or os.path.join(study_dir, "runs", r["name"])
        return os.path.exists(os.path.join(folder, "log.liggghts")) or kept_thermo(folder) is not None
    partial = [r for r in summary["runs"] if r["state"] == "incomplete" and has_rows(r)]
    for r in partial:
        r["state"] = "done"
    summary["finished"] = sum(1 for r in summary["runs"] if r["state"] == "done")
    return [r["name"] for r in partial]


# Knobs that do not change a run's scene or physics (what it writes and when it saves), and
# the seed: a run of another study that differs from this study's plan only in these is a
# run of the same scene (the porediameter run at the default pore is a dropvol seed).
NOT_THE_SCENE = ("seed", "vtk_every", "thermo_extra", "restart_every", "checkpoint_keep")


def scene_differences(knobs, study, size):
    """The knobs (name: (run's, the plan's)) in which `knobs` differ from the first run that
    `study` plans at `size`, less NOT_THE_SCENE; numbers compared to 1e-9 relative."""
    import studies
    _, plan = getattr(studies, study)(size)[0]
    differ = {}
    for name in sorted(set(knobs) | set(plan)):
        if name in NOT_THE_SCENE:
            continue
        a, b = str(knobs.get(name, "")), str(plan.get(name, ""))
        try:
            same = abs(float(a) - float(b)) <= 1e-9 * max(1.0, abs(float(b)))
        except ValueError:
            same = a == b
        if not same:
            differ[name] = (a, b)
    return differ


def add_one_run(summary, run_dir):
    """One run's folder of another study (with its knobs.json) appended to `summary`, named
    <its study's folder>/<run>, if its scene is the study's (scene_differences); its cost
    where it kept its cost.txt."""
    from study_io import read_knobs
    knobs = read_knobs(run_dir)
    differ = scene_differences(knobs, summary["study"], summary["size"])
    if differ:
        raise SystemExit(f"--with {run_dir}: not the scene of study {summary['study']} ({summary['size']}): "
                         + ", ".join(f"{k} {a} against {b}" for k, (a, b) in differ.items()))
    state = "incomplete"
    if os.path.exists(os.path.join(run_dir, "state.txt")):
        with open(os.path.join(run_dir, "state.txt")) as f:
            state = f.readline().strip()
    study_folder = os.path.dirname(os.path.dirname(os.path.normpath(run_dir)))
    name = os.path.basename(study_folder) + "/" + os.path.basename(os.path.normpath(run_dir))
    summary["runs"] = summary["runs"] + [dict(name=name, state=state, reason="", folder=run_dir, knobs=knobs)]
    hours, exact = run_cost.study_core_hours([run_dir])
    summary["core_hours"] = summary["core_hours"] + hours
    summary["core_hours_exact"] = bool(summary.get("core_hours_exact") and exact)
    summary["finished"] = sum(1 for r in summary["runs"] if r["state"] == "done")


def add_runs_of(summary, folder):
    """The runs of another study folder (or compacted evidence) appended to `summary`, with
    their cost; the run names keep the folder's name in front, so that none collides. A
    single run's folder (knobs.json, no summary) is added by add_one_run."""
    if os.path.exists(os.path.join(folder, "knobs.json")):
        add_one_run(summary, folder)
        return
    other = load_summary(folder)
    prefix = os.path.basename(os.path.normpath(folder)) + "/"
    summary["runs"] = summary["runs"] + [dict(r, name=prefix + r["name"]) for r in other["runs"]]
    summary["core_hours"] = summary["core_hours"] + other["core_hours"]
    summary["core_hours_exact"] = bool(summary.get("core_hours_exact") and other.get("core_hours_exact"))
    summary["finished"] = sum(1 for r in summary["runs"] if r["state"] == "done")


def _repository_path(folder):
    """`folder` relative to the repository's root if it lies inside it, else absolute."""
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    path = os.path.abspath(folder)
    return os.path.relpath(path, repo) if path.startswith(repo + os.sep) else path


def keep_runs_matching(summary, pattern):
    """The summary with only the runs whose names match `pattern` (re.search), their finished
    count and their cost (exact where each kept its cost.txt, run_cost)."""
    summary["runs"] = [r for r in summary["runs"] if re.search(pattern, r["name"])]
    if not summary["runs"]:
        raise SystemExit(f"--runs {pattern!r}: no run of the study matches")
    summary["finished"] = sum(r["state"] == "done" for r in summary["runs"])
    summary["core_hours"], summary["core_hours_exact"] = run_cost.study_core_hours(r["folder"] for r in summary["runs"])


def analyze(study_dir, figure=None, as_it_stands=False, out=None, with_folders=(), runs=None):
    summary = load_summary(study_dir)
    if runs:
        keep_runs_matching(summary, runs)
    for folder in with_folders:
        add_runs_of(summary, folder)
    partial = take_runs_as_they_stand(summary, study_dir) if as_it_stands else []
    out_dir = out or study_dir
    if figure is not None and figure != summary["study"]:
        out_dir = os.path.join(out_dir, figure)
    os.makedirs(out_dir, exist_ok=True)
    module = importlib.import_module(f"figures.{figure or summary['study']}")
    result = module.analyze(summary, out_dir)
    result["core_hours"] = round(summary["core_hours"], 4)
    result["core_hours_exact"] = bool(summary.get("core_hours_exact", False))
    result["runs_of_study"] = summary["study"]
    result["as_it_stands"] = partial
    # the folders taken beside the study's own, relative to the repository where inside it
    # (figure_table.py counts their runs)
    result["with"] = [_repository_path(folder) for folder in with_folders]
    saved = dict(result)
    if saved.get("plot"):  # beside results.json: the folder may be moved (doc/ keeps evidence)
        saved["plot"] = os.path.relpath(saved["plot"], out_dir)
    with open(os.path.join(out_dir, "results.json"), "w") as f:
        json.dump(_plain(saved), f, indent=1)
    print(f"| {result['figure']} | {result['paper']} | {result['ours']} | "
          f"{result['finished']}/{result['runs']} runs, "
          f"{'' if result['core_hours_exact'] else 'at least '}{result['core_hours']:.3g} core-h"
          + (f"; as they stand: {', '.join(partial)}" if partial else "") + " |")
    return result


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study_dir")
    parser.add_argument("--figure")
    parser.add_argument("--runs", metavar="REGEX", help="only the runs whose names match")
    parser.add_argument("--as-it-stands", action="store_true")
    parser.add_argument("--out", help="folder for the results and the plot (default: the study's)")
    parser.add_argument("--with", dest="with_folders", action="append", default=[], metavar="FOLDER",
                        help="take the runs of another study folder beside the study's own")
    args = parser.parse_args()
    analyze(args.study_dir, args.figure, args.as_it_stands, args.out, args.with_folders, args.runs)
