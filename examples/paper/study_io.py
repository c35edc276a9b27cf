"""Reads what the runs of a study wrote: each run's thermo rows (log.liggghts, by column name),
its erosive bursts (bursts.txt, fix lbm/pore's burst_file) and the study's summary.json.

A study's evidence compacted for the repository (compact_study.py: summary.txt, and per run
knobs.json, state.txt, bursts.txt and thermo.csv, no log) reads the same way, so the figures
of doc/ can be drawn again from it: the thermo rows come from thermo.csv, the time steps from
the run's knobs (in.pore's acoustic scaling), the summary from the runs' files.

Thermo columns are named as LIGGGHTS prints them: pore[16] is f_pore[16] (P / P_out),
pore[17] the largest P / P_out so far, pore[18] the burst count, pore[6] V_dep, pore[8] L_dep.
"""
import csv
import glob
import gzip
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pore"))
from plot_pressure import read_thermo  # noqa: E402  (the main example's log reader)
import run_cost  # noqa: E402

# A burst file's columns (fix lbm/pore's burst_file). V_dep, L_dep and count_before are taken
# at the peak; deposit_count, deposit_V and deposit_L are the medians over the burst window
# up to the peak (at the peak a sliding deposit has dropped out of the count; the figures take
# the largest count in the window from the thermo rows: figures/common.py). Rows of files written before the last three existed have the first thirteen,
# before wall_F, on_wall and P_pi_D2_4 the first ten.
# The burst window of fix lbm/pore's detector (in.pore's default, in the paper's fluid steps):
# the time up to a peak over which a burst record takes its deposit (the median count, V_dep
# and L_dep).
BURST_WINDOW = 1000
BURST_COLUMNS = ("step", "time", "P_peak", "P_after", "delta_P", "delta_t", "V_dep", "L_dep",
                 "count_before", "count_after", "wall_F", "on_wall", "P_pi_D2_4",
                 "deposit_count", "deposit_V", "deposit_L")


def lattice_timing(run_dir):
    """The run's own time steps, from fix lbm/pore's setup line in log.liggghts
    ("... dt_lbm = 1.42 (n_dem = 142 x dt_dem = 0.01), dx = 0.2"): dict(n_dem, dt_dem, dt_f, dx)
    in the script's units. A coarse run (in.pore's acoustic scaling) has a longer fluid step
    than the paper's, so neither the DEM steps per fluid step nor the pressure unit
    P_out = rho (dx / dt_f)^2 / 3 may be assumed."""
    pattern = re.compile(r"dt_lbm = (\S+) \(n_dem = (\d+) x dt_dem = (\S+)\), dx = (\S+)")
    log = os.path.join(run_dir, "log.liggghts")
    if not os.path.exists(log) and os.path.exists(os.path.join(run_dir, "knobs.json")):
        return timing_of_knobs(read_knobs(run_dir))
    with open(log, errors="replace") as f:
        for line in f:
            m = pattern.search(line)
            if m:
                return dict(dt_f=float(m.group(1)), n_dem=int(m.group(2)),
                            dt_dem=float(m.group(3)), dx=float(m.group(4)))
    raise ValueError(f"{run_dir}/log.liggghts: no fix lbm/pore setup line with dt_lbm and n_dem")


def burst_window_dem_steps(run_dir, knobs):
    """The run's burst window (its knob burst_window, in the paper's fluid steps) in DEM steps."""
    return float(knobs.get("burst_window", BURST_WINDOW)) / lattice_timing(run_dir)["dt_dem"]


def read_knobs(run_dir):
    with open(os.path.join(run_dir, "knobs.json")) as f:
        return json.load(f)


def timing_of_knobs(knobs):
    """lattice_timing of a compacted run, which has no log: in.pore's own arithmetic on its
    knobs (dx = 1 / cells_per_d, the fluid step 7.1 dx, n_dem_used = round(n_dem dt_f))."""
    from studies import PAPER_CELLS_PER_D, run_dem_steps_per_fluid_step
    dx = 1.0 / float(knobs["cells_per_d"])
    dt_f = dx * PAPER_CELLS_PER_D
    n_dem = run_dem_steps_per_fluid_step(knobs)
    return dict(dt_f=dt_f, n_dem=n_dem, dt_dem=dt_f / n_dem, dx=dx)


def p_out(run_dir, rho=1.0):
    """P_out = rho c_s^2 in the script's pressure units (c_s = dx / dt_f / sqrt 3)."""
    t = lattice_timing(run_dir)
    return rho * (t["dx"] / t["dt_f"]) ** 2 / 3.0


# The thermo rows a compacted run kept (compact_study.py): gzip-compressed, or plain as the
# folders compacted before it compressed them.
KEPT_THERMO = ("thermo.csv.gz", "thermo.csv")


def kept_thermo(run_dir):
    """The path of a compacted run's kept thermo rows, or None."""
    for name in KEPT_THERMO:
        if os.path.exists(os.path.join(run_dir, name)):
            return os.path.join(run_dir, name)
    return None


def thermo(run_dir):
    """{column: [values]} of all thermo rows of the run, or {} when it has none (a compacted
    run: the rows its thermo.csv.gz or thermo.csv kept)."""
    log = os.path.join(run_dir, "log.liggghts")
    if not os.path.exists(log):
        kept = kept_thermo(run_dir)
        if kept is None:
            return {}
        opener = gzip.open if kept.endswith(".gz") else open
        with opener(kept, "rt", newline="") as f:
            rows = list(csv.reader(f))
        # a blank: a column compact_study keeps only in the bursts' windows (WINDOW_COLUMNS)
        return {name: [float(row[j]) if row[j] else math.nan for row in rows[1:]] for j, name in enumerate(rows[0])}
    try:
        header, rows = read_thermo(log)
    except SystemExit:  # read_thermo exits on a log without thermo rows
        return {}
    return {name: [row[j] for row in rows] for j, name in enumerate(header)}


def bursts(run_dir):
    """The run's erosive bursts, one dict per row of bursts.txt (pressures in P_out). A run
    resumed from a restart file records again the bursts it had recorded after that file was
    written: a row with the step of an earlier one replaces it. A row written before the
    records carried the deposit before the peak takes the peak's own (deposit_count,
    deposit_V, deposit_L from count_before, V_dep, L_dep) and has deposit_recorded False."""
    path = os.path.join(run_dir, "bursts.txt")
    rows = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                if line.strip() and not line.startswith("#"):
                    row = dict(zip(BURST_COLUMNS, map(float, line.split())))
                    row["deposit_recorded"] = "deposit_count" in row
                    for deposit, at_peak in (("deposit_count", "count_before"), ("deposit_V", "V_dep"),
                                             ("deposit_L", "L_dep")):
                        row.setdefault(deposit, row[at_peak])
                    rows[row["step"]] = row
    return sorted(rows.values(), key=lambda r: r["step"])


def largest_pressure(columns, warmup):
    """The largest P / P_out once particles are in (DEM step > warmup). f_pore[17], the
    largest so far sampled every fluid step, is exact when it grew after the warm-up; when it
    did not (the start-up transient of the flow was higher), the largest thermo row of
    f_pore[16] after the warm-up stands in."""
    steps, so_far, now = columns["Step"], columns["pore[17]"], columns["pore[16]"]
    at_warmup = max([m for s, m in zip(steps, so_far) if s <= warmup] or [0.0])
    if so_far[-1] > at_warmup:
        return so_far[-1]
    return max([p for s, p in zip(steps, now) if s > warmup] or [now[-1]])


def run_figures(run_dir, warmup=0):
    """The figures the summary lists per run, read from the run's own files: the largest
    P / P_out after the warm-up (largest_pressure) and the number of bursts."""
    columns = thermo(run_dir)
    if "pore[17]" not in columns:
        return dict(max_P=None, bursts=len(bursts(run_dir)), last_step=None)
    return dict(max_P=largest_pressure(columns, warmup), bursts=len(bursts(run_dir)),
                last_step=int(columns["Step"][-1]))


def load_summary(study_dir):
    """The study's summary.json, or for compacted evidence (no summary.json) the same from its
    summary.txt's first line and each run's knobs.json and state.txt."""
    path = os.path.join(study_dir, "summary.json")
    if os.path.exists(path) or not os.path.exists(os.path.join(study_dir, "summary.txt")):
        with open(path) as f:
            return json.load(f)
    with open(os.path.join(study_dir, "summary.txt")) as f:
        m = re.match(r"study (\S+) \((\w+)", f.readline())
    runs = []
    for folder in sorted(glob.glob(os.path.join(study_dir, "runs", "*"))):
        if not os.path.exists(os.path.join(folder, "knobs.json")):
            continue
        state, reason = "incomplete", ""
        if os.path.exists(os.path.join(folder, "state.txt")):
            with open(os.path.join(folder, "state.txt")) as f:
                state, _, reason = f.read().partition("\n")
        runs.append(dict(name=os.path.basename(folder), state=state.strip(), reason=reason.strip(),
                         folder=folder, knobs=read_knobs(folder)))
    # Each run's cost.txt where every run kept it (run_cost), else what the study's last
    # analysis recorded.
    core_hours, exact = run_cost.study_core_hours(r["folder"] for r in runs)
    if not exact and os.path.exists(os.path.join(study_dir, "results.json")):
        with open(os.path.join(study_dir, "results.json")) as f:
            recorded = json.load(f)
        core_hours = recorded.get("core_hours") or 0.0
        exact = recorded.get("core_hours_exact", False)
    return dict(study=m.group(1), size=m.group(2), runs=runs, core_hours=core_hours,
                core_hours_exact=exact,
                finished=sum(r["state"] == "done" for r in runs),
                failed=sum(r["state"] == "failed" for r in runs),
                incomplete=sum(r["state"] == "incomplete" for r in runs))


def finished_runs(summary):
    return [r for r in summary["runs"] if r["state"] == "done"]
