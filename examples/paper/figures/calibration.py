"""The calibration of the inlet velocity (the paper gives none): per run of the calibration
study, what a deposit grows to and how it is held, and the pressure loss over time per run.

Per run, from its own files (every run, finished or cut short, up to its last thermo row):
the fluid steps made and how the run ended; the largest deposited count and V_dep [d^3];
P_0 (the clean pore, figures.common.clean_pressure) and P_max [P_out]; the bursts with the
deposits at their peaks; at each peak the wall's hold along the flow against P pi D^2 / 4
(burst records); the largest lattice Mach number; the paper's law of the bursts, P = K L_dep
/ D (burst_law), per run and pooled per velocity. A burst's deposit is the median over the
burst window up to its peak: the record's deposit_count and deposit_L, or, for records
written before they carried them, the medians over the BURST_WINDOW fluid steps of thermo rows
(deposit_before); never the record's count at the peak. Beside it, the largest deposit in
the same window (figures.common.largest_deposit_before), the deposit before it began to
slide: the law's K and Pearson coefficient on both. The study's default velocity is the
largest whose bursts carry at least 15 deposited particles at 0.3-0.6 P_out (CRITERION_COUNT,
CRITERION_P) and whose runs go on to their end.

Usage: analyze.py <calibration study folder>   (writes calibration.md beside the plot)"""
import os
import re

import numpy as np

from fit_stats import fmt
from figures.common import (bursts, clean_pressure, plt, result, row_durations, save, thermo, time_mean,
                            with_largest_deposits)
from study_io import BURST_WINDOW, burst_window_dem_steps, lattice_timing

CRITERION_COUNT, CRITERION_P = 15, (0.3, 0.6)
# in.pore's five size templates: radii (in d_particle) and number weights.
TEMPLATES = ((0.4, 0.054), (0.45, 0.244), (0.5, 0.404), (0.55, 0.244), (0.6, 0.054))


def inlet_rate_ratio(run, columns):
    """Particles crossing the inlet plane per fluid step after the warm-up (f_pore[4]) over
    the nominal c_in u_in W^2 / V_p (the mean template volume): 1 when region I is kept at
    c_in and its particles leave it with the flow."""
    knobs = run["knobs"]
    if "pore[4]" not in columns:
        return np.nan
    steps = np.asarray(columns["Step"], float)
    crossed = np.asarray(columns["pore[4]"], float)
    warmup = float(knobs["warmup"])
    n_dem = lattice_timing(run["folder"])["n_dem"]
    after = steps > warmup + 0.1 * (steps[-1] - warmup)  # past the first fill of region I
    if after.sum() < 2:
        return np.nan
    rate = (crossed[after][-1] - crossed[after][0]) / ((steps[after][-1] - steps[after][0]) / n_dem)
    cells = float(knobs["cells_per_d"])
    d = float(knobs.get("d_particle", 1.0)) * cells
    volume = sum(w * 4.0 / 3.0 * np.pi * (r * d) ** 3 for r, w in TEMPLATES)
    width = round(float(knobs["W"]) * cells)
    nominal = float(knobs.get("c_in", 0.05)) * float(knobs["u_lattice"]) * width * width / volume
    return rate / nominal


def window_median(columns, column, peak_step, window_steps):
    """The median of a thermo column over the rows of the `window_steps` DEM steps up to
    `peak_step`; None without rows in the window."""
    steps = np.asarray(columns["Step"], float)
    inside = (steps >= peak_step - window_steps) & (steps <= peak_step)
    if not inside.any():
        return None
    return float(np.median(np.asarray(columns[column], float)[inside]))


def deposit_before(columns, peak_step, window_steps):
    """The deposit a burst tears off: the median deposited count (f_pore[7]) over the thermo
    rows of the `window_steps` DEM steps up to its peak. The burst record's own count is taken
    at the peak itself, when the deposit has begun to slide: its particles are then faster than
    the count's speed bound (deposit_speed) and drop out of it, so a whole-pore deposit can read
    as one or two (doc/calibration.md). None without rows in the window."""
    count = window_median(columns, "pore[7]", peak_step, window_steps)
    return None if count is None else int(round(count))


def bursts_with_deposits(run, columns):
    """The run's bursts, each with "deposit" and "deposit_L": the deposit it tore off (count
    and L_dep), its record's deposit_count and deposit_L, or for a record written before
    records carried them, the same medians over the thermo rows (deposit_before; the record's
    values at its peak where no row lies in the window); and "largest", "largest_L": the
    largest deposit in the window (figures.common.with_largest_deposits; the record's median
    where no row lies in it)."""
    window = burst_window_dem_steps(run["folder"], run["knobs"])
    rows = bursts(run["folder"])
    for b in rows:
        b["deposit"] = int(b["deposit_count"])
        if not b["deposit_recorded"] and "pore[8]" in columns:
            count = deposit_before(columns, b["step"], window)
            length = window_median(columns, "pore[8]", b["step"], window)
            if count is not None:
                b["deposit"], b["deposit_L"] = count, length
    for b, largest in zip(rows, with_largest_deposits(run, rows, columns)):
        b["largest"], b["largest_L"] = int(largest["deposit_count"]), largest["deposit_L"]
    return rows


def burst_law(rows, D, p0):
    """The paper's law of the bursts, P = K L_dep / D (its Fig. porediameter: K = 0.91), on a
    run's (or runs') bursts with the deposits they tore off: K through the origin on P - P_0
    (the pressure the deposit adds) and on P, and the Pearson coefficient of P with L_dep / D,
    each (value, low, high) with a 95 % interval over bursts resampled (a study has too few
    seeds for an interval over runs). rows: bursts_with_deposits rows; p0 per row. Also K
    and Pearson on the largest deposit in the window (K_largest, pearson_largest) where the
    rows carry it ("largest_L")."""
    from fit_stats import bootstrap, pearson, slope_through_origin

    def on(length_key):
        x = [b[length_key] / D for b in rows]
        points = [([xi], [b["P_peak"]]) for xi, b in zip(x, rows)]
        excess = [([xi], [b["P_peak"] - p]) for xi, b, p in zip(x, rows, p0) if np.isfinite(p)]
        return bootstrap(excess, slope_through_origin), bootstrap(points, slope_through_origin), \
            bootstrap(points, pearson)

    K, K_total, r = on("deposit_L")
    law = dict(bursts=len(rows), K=K, K_total=K_total, pearson=r)
    if rows and all("largest_L" in b for b in rows):
        law["K_largest"], _, law["pearson_largest"] = on("largest_L")
    return law


def run_row(run):
    columns = thermo(run["folder"])
    row = dict(name=run["name"], u=float(run["knobs"]["u_lattice"]), seed=run["knobs"]["seed"],
               n_dem=int(run["knobs"].get("n_dem", 100)), cells_per_d=float(run["knobs"]["cells_per_d"]),
               state=run["state"], reason=run.get("reason", ""))
    if "pore[16]" not in columns:
        return row, columns
    steps = np.asarray(columns["Step"], float)
    n_dem = lattice_timing(run["folder"])["n_dem"]
    warmup = float(run["knobs"]["warmup"])
    after = steps > warmup
    rows = bursts_with_deposits(run, columns)
    p0 = clean_pressure(run)
    row["burst_rows"] = [dict(b, P0=p0, D=float(run["knobs"]["D"])) for b in rows]
    law = burst_law(rows, float(run["knobs"]["D"]), [p0] * len(rows))
    holds = [(-b["wall_F"] / b["P_pi_D2_4"]) for b in rows if b.get("P_pi_D2_4")]
    row.update(fluid_steps=int(steps[-1] // n_dem), count=int(np.max(columns["pore[7]"])),
               V_dep=float(np.max(columns["pore[6]"])), P0=p0, K=law["K"], pearson=law["pearson"],
               P_max=float(np.max(np.asarray(columns["pore[16]"])[after])) if after.any() else np.nan,
               mach=float(np.max(columns["pore[10]"])), bursts=len(rows),
               inlet=inlet_rate_ratio(run, columns),
               peaks=[(b["P_peak"], b["deposit"]) for b in rows],
               hold=float(np.median(holds)) if holds else np.nan,
               qualifying=sum(1 for b in rows if b["deposit"] >= CRITERION_COUNT
                              and CRITERION_P[0] <= b["P_peak"] <= CRITERION_P[1]))
    return row, columns


def stop_reason(error):
    """The ERROR line in a few words: the fluid guard with its node's density and speed."""
    m = re.search(r"fluid became unstable at DEM step (\d+).*density ([-\w.]+), speed ([-\w.]+)", error)
    if m:
        return f"fluid guard at DEM step {m.group(1)} (density {m.group(2)}, speed {m.group(3)})"
    return error.replace("ERROR on proc 0: ", "")[:80]


def table(rows):
    lines = ["| run | u_lattice | N_DEM | cells per d | ended | fluid steps | largest deposit (count, V_dep [d^3]) | P_0 | P_max "
             "| bursts (P_peak: deposited over the 1000 fluid steps before it, median) | wall hold / (P pi D^2/4) at peaks, median | max Mach "
             "| inlet rate / c_in u_in W^2 / V_p | K of P - P_0 = K L_dep / D (paper 0.91) | Pearson (P, L_dep) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    waiting = [r["name"] for r in rows if "fluid_steps" not in r]
    for r in rows:
        if "fluid_steps" not in r:
            continue
        ended = r["state"] if r["state"] != "failed" else "stopped: " + stop_reason(r["reason"])
        peaks = ", ".join(f"{p:.2f}: {c}" for p, c in r["peaks"][:8]) + (" ..." if len(r["peaks"]) > 8 else "")
        lines.append(f"| {r['name']} | {r['u']:g} | {r['n_dem']} | {r['cells_per_d']:g} | {ended} | {r['fluid_steps']} | {r['count']}, {r['V_dep']:.2f} "
                     f"| {r['P0']:.3f} | {r['P_max']:.3f} | {r['bursts']} ({peaks or 'none'}) "
                     f"| {r['hold']:.2f} | {r['mach']:.3f} | {r['inlet']:.2f} | {fmt(*r['K'])} "
                     f"| {fmt(*r['pearson'])} |")
    if waiting:  # a study run in parts (--runs) lists the runs it has not made in one line
        lines.append(f"\nWithout a thermo row yet ({len(waiting)}): {', '.join(waiting)}.")
    return "\n".join(lines)


def law_table(rows):
    """The paper's law of the bursts pooled per velocity over the seeds (the runs at the
    paper's N_DEM and resolution; burst_law), beside the paper's K = 0.91 (0.87-0.95) and
    the Pearson coefficient of its Fig. dropvol, 0.71."""
    lines = ["| u_lattice | runs | bursts | K of P - P_0 = K L_dep / D (95 % over bursts) | K of P through 0 "
             "| Pearson (P, L_dep) | on the largest deposit in the window: K of P - P_0 | Pearson |",
             "|---|---|---|---|---|---|---|---|"]
    base = [r for r in rows if "burst_rows" in r and variant_label(r["name"]) == VARIANTS[0][1]]
    for u in sorted({r["u"] for r in base}):
        runs = [r for r in base if r["u"] == u]
        bursts_of = [b for r in runs for b in r["burst_rows"]]
        if not bursts_of:
            continue
        # burst_law takes one D; the runs of one velocity share the scene, and each row its own P_0.
        law = burst_law(bursts_of, bursts_of[0]["D"], [b["P0"] for b in bursts_of])
        nan = (np.nan,) * 3
        lines.append(f"| {u:g} | {len(runs)} | {law['bursts']} | {fmt(*law['K'])} | {fmt(*law['K_total'])} "
                     f"| {fmt(*law['pearson'])} | {fmt(*law.get('K_largest', nan))} "
                     f"| {fmt(*law.get('pearson_largest', nan))} |")
    return "\n".join(lines) if len(lines) > 2 else ""


VARIANTS = (("", "N_DEM 100, 7.1 cells/d"), ("_n_dem_20", "N_DEM 20"), ("_5_cells_per_d", "5 cells/d"),
            ("_min_gap", "min_gap 0.25 d"), ("_no_gap", "no minimum insertion distance"),
            ("_keep_pressure", "reference pressure kept"),
            ("_fraction", "F_h / N_DEM per substep"), ("_pore_deposits", "deposits in the pore only"),
            ("_slow_deposits", "deposited below u_in / 2"))


def variant_label(name):
    """The variants a run's name carries (its suffixes, in order), or the base's label."""
    found = [label for suffix, label in VARIANTS[1:] if suffix in name]
    return ", ".join(found) if found else VARIANTS[0][1]
BLOCK = 2000.0  # the paper's fluid steps per block of the block bootstrap (burst cycles are shorter)


def block_mean(t, y, rng, draws=2000):
    """Mean of a time series over time and its 95 % interval from a block bootstrap (blocks
    of BLOCK time units, so that the correlation within a burst cycle stays in a block). Rows
    weigh the time they stand for (row_durations): a compact result keeps a burst's window
    at every row and the rest at every tenth."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    if len(y) < 2:
        return (np.nan, np.nan, np.nan)
    w = row_durations(t)
    labels = ((t - t[0]) // BLOCK).astype(int)
    blocks = [(y[labels == b] * w[labels == b]).sum() for b in np.unique(labels)]
    spans = [w[labels == b].sum() for b in np.unique(labels)]
    blocks, spans = np.asarray(blocks), np.asarray(spans)
    picks = rng.integers(0, len(blocks), (draws, len(blocks)))
    means = blocks[picks].sum(axis=1) / spans[picks].sum(axis=1)
    return (time_mean(t, y), float(np.percentile(means, 2.5)), float(np.percentile(means, 97.5)))


def run_times(run):
    """(times of the thermo rows, time the warm-up ends, the thermo columns) in the paper's
    fluid steps, or None. The columns are read once here: a run still under way writes more
    rows between two reads of its log."""
    columns = thermo(run["folder"])
    if "pore[16]" not in columns:
        return None
    dt = lattice_timing(run["folder"])["dt_dem"]
    return np.asarray(columns["Step"], float) * dt, float(run["knobs"]["warmup"]) * dt, columns


def twin_statistics(run, times, rng, until):
    """What the N_DEM and resolution comparisons compare, per run (its run_times `times`),
    from the end of its warm-up to `until` time units after it: the mean deposited count and
    the mean P / P_out over time (block-bootstrap intervals), the largest deposited count and
    P_max, the bursts per 10^4 time units (the paper's fluid steps), the mean deposit torn off
    (bursts_with_deposits) and P at the peaks, and the wall's hold per deposited particle
    touching it at the peaks (-wall_F / on_wall, median; the script's force unit, which the
    resolution does not change)."""
    t, warmup, columns = times
    warm = (t > warmup) & (t <= warmup + until)
    if warm.sum() < 2:
        return None
    dt = lattice_timing(run["folder"])["dt_dem"]
    rows = [b for b in bursts_with_deposits(run, columns) if warmup < b["step"] * dt <= warmup + until]
    span = t[warm][-1] - t[warm][0]
    count = np.asarray(columns["pore[7]"], float)[warm]
    pressure = np.asarray(columns["pore[16]"], float)[warm]
    holds = [-b["wall_F"] / b["on_wall"] for b in rows if b.get("on_wall", 0) > 0]
    return dict(time=span, count=block_mean(t[warm], count, rng),
                P=block_mean(t[warm], pressure, rng), largest=int(count.max()), P_max=float(pressure.max()),
                hold=float(np.median(holds)) if holds else np.nan,
                burst_rate=1e4 * len(rows) / span if span > 0 else np.nan,
                peak_count=float(np.mean([b["deposit"] for b in rows])) if rows else np.nan,
                peak_P=float(np.mean([b["P_peak"] for b in rows])) if rows else np.nan)


TWIN_HEADER = ["| run | variant | time after warm-up | mean deposited | mean P [P_out] | largest deposit "
               "| P_max [P_out] | bursts per 10^4 | deposit torn off, mean | P_peak, mean "
               "| wall hold per particle at the peaks |", "|---|---|---|---|---|---|---|---|---|---|---|"]


def twin_row(name, label, stats):
    """One row of a twins table: twin_statistics of run `name` under `label`, or dashes."""
    if stats is None:
        return f"| {name} | {label} |" + " - |" * (len(TWIN_HEADER[1].split("|")) - 4)
    fmt = lambda v: f"{v[0]:.2f} [{v[1]:.2f}, {v[2]:.2f}]"
    return (f"| {name} | {label} | {stats['time']:.0f} | {fmt(stats['count'])} | {fmt(stats['P'])} "
            f"| {stats['largest']} | {stats['P_max']:.3f} | {stats['burst_rate']:.2f} "
            f"| {stats['peak_count']:.1f} | {stats['peak_P']:.3f} | {stats['hold']:.3g} |")


def twins_table(runs):
    """Per run and each of its twins (its name with a VARIANTS suffix: _n_dem_20 and
    _5_cells_per_d of a 7.1-cells run, the model's twins of a 5-cells run) that has thermo
    rows: the twin statistics of both over the time after the warm-up that both reached, one
    row each. Intervals that overlap read as agreement within
    one run's noise; across seeds the table holds one pair of rows per seed."""
    rng = np.random.default_rng(1)
    by_name = {run["name"]: run for run in runs}
    times = {name: run_times(run) for name, run in by_name.items()}
    times = {name: t for name, t in times.items() if t is not None and len(t[0])}
    lines = list(TWIN_HEADER)
    # Every run with a twin (its name and a variant's suffix): a 5-cells run is the 7.1 run's
    # twin and the base of the model's twins at 5 cells.
    for name in times:
        for suffix, _ in VARIANTS[1:]:
            if name + suffix not in times:
                continue
            until = min(times[n][0][-1] - times[n][1] for n in (name, name + suffix))
            for run_name in (name, name + suffix):
                stats = twin_statistics(by_name[run_name], times[run_name], rng, until)
                lines.append(twin_row(name, variant_label(run_name), stats))
    return "\n".join(lines) if len(lines) > 2 else ""


def analyze(summary, out_dir):
    runs = summary["runs"]
    rows, series = [], []
    for run in runs:
        row, columns = run_row(run)
        rows.append(row)
        series.append((row, columns))
    fig, axes = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True)
    for k, (row, columns) in enumerate(series):
        if "pore[16]" not in columns:
            continue
        # The paper's fluid steps (time units): runs at another N_DEM or resolution line up.
        t = np.asarray(columns["Step"], float) * lattice_timing(runs[k]["folder"])["dt_dem"]
        variant = variant_label(row["name"])
        axes[0].plot(t, columns["pore[16]"], lw=0.7, label=f"u {row['u']:g}, seed {row['seed']}"
                     + ("" if variant == VARIANTS[0][1] else f", {variant}"))
        axes[1].plot(t, columns["pore[7]"], lw=0.7)
    axes[0].axhspan(*CRITERION_P, color="0.9", zorder=0)
    axes[0].set_ylabel("P [P_out]")
    axes[1].set_ylabel("deposited particles")
    axes[1].axhline(CRITERION_COUNT, color="0.5", ls=":")
    axes[1].set_xlabel("time [the paper's fluid steps]")
    axes[0].legend(fontsize=7, ncol=2)
    plot = save(fig, out_dir, "calibration")
    text = table(rows)
    twins = twins_table(runs)
    law = law_table(rows)
    for row in rows:
        row.pop("burst_rows", None)
    with open(os.path.join(out_dir, "calibration.md"), "w") as f:
        f.write(text + "\n")
        if law:
            f.write("\nThe paper's law of the bursts, P = K L_dep / D with the deposit each burst tore off "
                    f"(the median over the {BURST_WINDOW} fluid steps before the peak; beside it the largest "
                    "deposit in that window), pooled per velocity over the seeds (paper: K = 0.91 +- 0.04; "
                    "Pearson 0.71 in its Fig. dropvol):\n\n" + law + "\n")
        if twins:
            f.write("\nEach run beside its twins (the same run at N_DEM 20 or at 5 cells per d; a 5-cells "
                    "run with one of the model's open points switched), each pair over the time after "
                    "the warm-up that both reached (in the paper's fluid steps; 95 % block-bootstrap "
                    "intervals):\n\n" + twins + "\n")
    # The default velocity is chosen at the paper's N_DEM and resolution; the other runs
    # only compare.
    qualifying = sorted({r["u"] for r in rows if r.get("qualifying") and r["state"] == "done"
                         and r["n_dem"] == 100 and r["cells_per_d"] == 7.1})
    choice = f"u_lattice {max(qualifying):g}" if qualifying else "none of the runs qualifies yet"
    return result(summary, "calibration", "the largest u_lattice whose bursts carry >= 15 deposited "
                  "particles at 0.3-0.6 P_out and whose runs reach their end",
                  "not given (the paper's bursts: 0.3-0.6 P_out, 20-40 deposited particles)", choice, plot,
                  table=text, law_table=law, runs_rows=rows)
