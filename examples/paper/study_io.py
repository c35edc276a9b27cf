"""Reads what the runs of a study wrote: each run's thermo rows (log.liggghts, by column name),
its erosive bursts (bursts.txt, fix lbm/pore's burst_file) and the study's summary.json.

Thermo columns are named as LIGGGHTS prints them: pore[16] is f_pore[16] (P / P_out),
pore[17] the largest P / P_out so far, pore[18] the burst count, pore[6] V_dep, pore[8] L_dep.
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pore"))
from plot_pressure import read_thermo  # noqa: E402  (the main example's log reader)

# A burst file's columns (fix lbm/pore's burst_file). V_dep, L_dep and count_before are taken
# at the peak; deposit_count, deposit_V and deposit_L are the deposit the burst tore off, the
# medians over the burst window up to the peak (at the peak a sliding deposit has dropped out
# of the count). Rows of files written before the last three existed have the first thirteen,
# before wall_F, on_wall and P_pi_D2_4 the first ten.
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
    with open(os.path.join(run_dir, "log.liggghts"), errors="replace") as f:
        for line in f:
            m = pattern.search(line)
            if m:
                return dict(dt_f=float(m.group(1)), n_dem=int(m.group(2)),
                            dt_dem=float(m.group(3)), dx=float(m.group(4)))
    raise ValueError(f"{run_dir}/log.liggghts: no fix lbm/pore setup line with dt_lbm and n_dem")


def p_out(run_dir, rho=1.0):
    """P_out = rho c_s^2 in the script's pressure units (c_s = dx / dt_f / sqrt 3)."""
    t = lattice_timing(run_dir)
    return rho * (t["dx"] / t["dt_f"]) ** 2 / 3.0


def thermo(run_dir):
    """{column: [values]} of all thermo rows of the run, or {} when it has none."""
    log = os.path.join(run_dir, "log.liggghts")
    if not os.path.exists(log):
        return {}
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
    with open(os.path.join(study_dir, "summary.json")) as f:
        return json.load(f)


def finished_runs(summary):
    return [r for r in summary["runs"] if r["state"] == "done"]
