"""The link mass correction in the fluid kernel's pass (studies.correction: mass_correction
kernel) against the moving walls' sweep (the settings study's N_DEM 100 runs, the same
seeds, knobs and length), read with the settings figure's measures: the bursts, the largest
and the median deposit a burst tore off, P_max [P_out]. The two agree to round-off step by
step, so the runs part ways as a chaotic flow does; the kernel's may become the default when
each of its means lies within the spread (min to max) of the sweep's seeds. The control, the
sweep's correction with the lattice split another way, shows how far a change of the last
bits alone moves the same figures. The sweep's runs come from doc/paper/settings:

    analyze.py doc/paper/correction"""
import os

from figures.common import finished_runs, result
from figures.settings import compare, run_figures
from study_io import load_summary

# The sweep's runs: the settings study's N_DEM 100 runs, kept in the repository.
SETTINGS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "doc", "paper", "settings")
LABELS = {"sweep": "in the sweep", "kernel": "in the kernel", "control": "sweep split across"}


def group_of(run):
    knobs = run["knobs"]
    if int(knobs.get("n_dem", 100)) != 100:
        return None  # the settings study's N_DEM 20 runs
    if knobs.get("mass_correction") == "kernel":
        return "kernel"
    # the control: the sweep's correction, the lattice split another way
    return "control" if "procs" in knobs else "sweep"


def analyze(summary, out_dir):
    groups = {g: {} for g in LABELS}
    for run in finished_runs(summary):
        group = group_of(run)
        if group:
            groups[group][run["name"]] = run_figures(run)
    if not groups["sweep"] and os.path.isdir(SETTINGS):
        for run in finished_runs(load_summary(SETTINGS)):
            if group_of(run) == "sweep":
                groups["sweep"]["settings/" + run["name"]] = run_figures(run)
    verdicts, table, png = compare(groups, LABELS, "sweep", ("kernel", "control"), out_dir, "correction")
    ours = "; ".join(verdicts) if verdicts else "no pair of finished runs yet"
    return result(summary, "correction", "mass correction in the kernel against the sweep (bursts, deposits, P_max)",
                  "not in the paper: a change of the summation order must not move the statistics",
                  ours, png, values=table, runs_per_group={g: len(groups[g]) for g in LABELS},
                  per_run=groups)
