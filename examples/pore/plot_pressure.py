#!/usr/bin/env python3
"""Plot the pressure loss across the pore against time from a LIGGGHTS log, marking the
erosive bursts: sudden drops of the pressure loss (paper, Figs. 2-3), with the deposit on its
own panel below.

Usage: plot_pressure.py log.liggghts [--fix pore] [--bursts bursts.txt] [--out pressure_loss.png]
                        [--drop 0.1] [--window 10]

The log must contain a thermo block whose header has the columns `Step` and the fix's
pressure loss, e.g. `thermo_style custom step f_pore[16] f_pore[6] f_pore[7] ...` (LIGGGHTS
prints the header as pore[16], pore[6], ...); P / P_out (f_ID[16]) is used when present, else
f_ID[1]. The upper panel is the pressure loss against time (DEM step x dt, the paper's fluid
steps, read from fix lbm/pore's setup line in the log; DEM steps without it) with each burst
shaded from its peak to its minimum, a triangle on the peak and its number. The lower panel,
on the same time axis, is the deposit: the deposited particle count f_ID[7] and volume
V_dep f_ID[6] (the paper relates the pressure peaks to V_dep), when the thermo block has them.

The bursts are those of the fix's burst file with `--bursts` (found every fluid step, with
the deposit criterion); without it they are found on the thermo rows: a fall of the pressure
loss by more than `--drop` (fraction of the preceding peak, default 10 %) within `--window`
thermo rows (default: the rows of 1000 fluid steps, the detector's window in in.pore, read
off the log's thermo interval and DEM steps per fluid step), followed to its minimum, by the
rules of fix lbm/pore's online detector (find_bursts). Prints each burst as
`BURST step peak after drop_fraction` and writes the plot.
"""
import argparse
import re
import statistics
import sys


def read_thermo(path):
    """Returns (header, rows) of the log's thermo blocks that share the last block's columns
    (one block per run command), concatenated. A block with fewer of them (a run resumed by
    a scene that prints more columns since) keeps its rows, NaN in the columns it lacks; a
    block with columns the last lacks is left out. A row whose step is not past the row before
    supersedes the rows from its step on: a run resumed from a restart file (appending to
    its log) repeats the steps between that file and where it was cut short."""
    blocks = read_thermo_blocks(path)
    if not blocks:
        sys.exit(f"{path}: no thermo block with a 'Step' header found")
    header = blocks[-1][0]

    def in_last_columns(h, rows):
        if h == header:
            return rows
        if not set(h) <= set(header):
            return []
        where = [h.index(c) if c in h else None for c in header]
        return [[row[j] if j is not None else float("nan") for j in where] for row in rows]

    kept = []
    for row in (row for h, rows in blocks for row in in_last_columns(h, rows)):
        while kept and kept[-1][0] >= row[0]:
            kept.pop()
        kept.append(row)
    return header, kept


def read_thermo_blocks(path):
    """Every thermo block of the log as (header, rows), in order (one per run command)."""
    blocks, header = [], None
    with open(path, errors="replace") as log:  # LIGGGHTS can leave stray bytes after an ERROR
        for line in log:
            words = line.split()
            if words and words[0] == "Step":
                header = words
                blocks.append((header, []))
                continue
            if header is None or len(words) != len(header):
                continue
            try:
                blocks[-1][1].append([float(w) for w in words])
            except ValueError:  # a message of as many words as the header (a pair style's
                continue        # note at a run's start, stray bytes): not a row, the block goes on
    return [(h, rows) for h, rows in blocks if rows]


def find_bursts(steps, pressure, drop, window):
    """(peak, minimum) index pairs of the erosive bursts, by the rules of fix lbm/pore's online
    detector (coupling/diagnostics/burst_detector.h) with thermo rows as samples: a peak is a
    row with P > 0 that no row of the `window` rows before it exceeds; a burst starts at the
    first row below (1 - drop) P_peak at most `window` rows after the peak with no higher row
    in between; it is followed to its lowest row and ends at the first row above the peak or
    more than `window` rows after the fall last went on by more than drop/10 of the peak; the
    next peak comes after the minimum. A burst still being followed at the end is kept."""
    bursts, following, eligible_from = [], None, 0
    for j, p in enumerate(pressure):
        if following is not None:
            peak, low, floor = following
            if p > pressure[peak] or j - floor > window:
                bursts.append((peak, low))
                eligible_from, following = low + 1, None
            else:
                low = j if p < pressure[low] else low
                floor = j if p < pressure[floor] - 0.1 * drop * pressure[peak] else floor
                following = (peak, low, floor)
                continue
        # The highest row of the last `window` rows (the latest of equal ones), if it is a peak.
        first = max(0, j - window)
        i = max(range(first, j + 1), key=lambda k: (pressure[k], k))
        if (i != j and i >= eligible_from and pressure[i] > 0
                and not any(pressure[k] > pressure[i] for k in range(max(0, i - window), i))
                and p < (1 - drop) * pressure[i]):
            following = (i, j, j)
    if following is not None:
        bursts.append(following[:2])
    return bursts


def burst_records(path):
    """The rows of fix lbm/pore's burst file as dicts of its first six columns (step: the DEM
    step of the peak, time, P_peak, P_after in P_out, delta_P, delta_t: peak to minimum), in
    step order; a row with the step of an earlier one (a run resumed from a restart file
    records again the bursts after that file) replaces it."""
    names = ("step", "time", "P_peak", "P_after", "delta_P", "delta_t")
    rows = {}
    with open(path) as burst_file:
        for line in burst_file:
            if line.startswith("#") or not line.split():
                continue
            row = dict(zip(names, map(float, line.split()[:6])))
            rows[row["step"]] = row
    return [rows[step] for step in sorted(rows)]


def run_timing(path):
    """(n_dem, dt_dem) from fix lbm/pore's setup line in the log ("... dt_lbm = 1 (n_dem = 100 x
    dt_dem = 0.01) ..."), or None for a log without one."""
    pattern = re.compile(r"dt_lbm = \S+ \(n_dem = (\d+) x dt_dem = (\S+)\)")
    with open(path, errors="replace") as log:
        for line in log:
            m = pattern.search(line)
            if m:
                return int(m.group(1)), float(m.group(2))
    return None


def load(log, fix="pore", column=None, bursts=None, drop=0.1, window=None):
    """What the plot shows, read from the log (and the burst file): a dict with the thermo
    steps, the pressure loss and its column, the x values (time, or DEM steps without the
    fix's setup line) and their label, the deposited count and volume as (column, values),
    (None, None) where the thermo block lacks them, and the bursts: dicts of the peak's DEM
    step, P_peak and P_after (P_after None when the plot is not in P_out) and the x values of
    the peak and the minimum. With `bursts` (the fix's burst file) the file's own peaks and
    minima, else those find_bursts finds on the thermo rows."""
    header, rows = read_thermo(log)

    def find(index):
        for name in (f"f_{fix}[{index}]", f"{fix}[{index}]"):
            if name in header:
                return name
        return None

    # The pressure loss in units of P_out (f_ID[16], the paper's unit) when the log has it.
    column = column or find(16) or find(1)
    if column not in header:
        sys.exit(f"{log}: no column {column!r} in thermo header {header}")
    steps = [r[0] for r in rows]
    pressure = [r[header.index(column)] for r in rows]
    timing = run_timing(log)
    if timing:
        n_dem, dt_dem = timing
        x = [s * dt_dem for s in steps]
        x_label = (f"time t = DEM step x {dt_dem:g} (in.pore: the paper's fluid steps; "
                   f"{n_dem} DEM steps per fluid step of this run)")
    else:
        x, x_label = steps, "DEM step"
    # Each burst as its step, its pressures and where its span starts and ends on the x axis:
    # the burst file's own peak (found every fluid step) and minimum, or the thermo rows'.
    unit = "P / P_out" if column == find(16) else "pressure units"
    marks = []
    if bursts:
        nearest = lambda s: min(range(len(steps)), key=lambda i: abs(steps[i] - s))  # noqa: E731
        for b in burst_records(bursts):
            if timing:
                x_peak, x_after = b["step"] * dt_dem, b["step"] * dt_dem + b["delta_t"]
            else:  # DEM steps: the minimum's from the peak's and the fall's share of the run
                x_peak = b["step"]
                x_after = b["step"] * (1.0 + b["delta_t"] / b["time"]) if b["time"] > 0 else b["step"]
            in_p_out = unit == "P / P_out"
            marks.append(dict(step=b["step"], x_peak=x_peak, x_after=x_after,
                              P_peak=b["P_peak"] if in_p_out else pressure[nearest(b["step"])],
                              P_after=b["P_after"] if in_p_out else None))
    else:
        if window is None:  # the rows of 1000 fluid steps (100 DEM steps each without the setup line)
            interval = statistics.median(b - a for a, b in zip(steps, steps[1:])) if len(steps) > 1 else 1
            window = max(1, round(1000 * (timing[0] if timing else 100) / max(interval, 1)))
        for peak, after in find_bursts(steps, pressure, drop, window):
            marks.append(dict(step=steps[peak], x_peak=x[peak], x_after=x[after],
                              P_peak=pressure[peak], P_after=pressure[after]))
    series = {}
    for index, name in ((7, "count"), (6, "volume")):
        c = find(index)
        series[name] = (c, [r[header.index(c)] for r in rows]) if c else (None, None)
    return dict(steps=steps, x=x, x_label=x_label, pressure=pressure, column=column, unit=unit,
                bursts=marks, bursts_from_file=bool(bursts), count=series["count"],
                volume=series["volume"])


def figure(data):
    """The plot: the pressure loss with the bursts marked (a shaded span from each peak to its
    minimum, a triangle on the peak, its number above it) on the upper panel; the deposited
    particle count and volume on their own panel below, on the same x axis, the bursts shaded
    there too."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x, pressure, bursts = data["x"], data["pressure"], data["bursts"]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6),
                                      gridspec_kw=dict(height_ratios=[2, 1]))
    top.plot(x, pressure, lw=1.2, color="tab:blue", label="pressure loss")
    for n, b in enumerate(bursts, start=1):
        for ax in (top, bottom):
            ax.axvspan(b["x_peak"], b["x_after"], color="tab:red", alpha=0.25, lw=0)
        top.plot([b["x_peak"]], [b["P_peak"]], "v", color="tab:red",
                 label="erosive burst: peak to minimum" if n == 1 else None)
        top.annotate(str(n), (b["x_peak"], b["P_peak"]), textcoords="offset points",
                     xytext=(0, 6), ha="center", fontsize=8, color="tab:red")
    top.set_ylabel(f"pressure loss, {data['unit']}\n({data['column']})")
    source = "recorded by fix lbm/pore" if data["bursts_from_file"] else "found on the thermo rows"
    top.set_title(f"{len(bursts)} erosive burst(s) {source}")
    top.legend(loc="upper left", fontsize=8)
    (count_column, count), (volume_column, volume) = data["count"], data["volume"]
    lines = []
    if count is not None:
        lines += bottom.plot(x, count, lw=1.0, color="tab:green", drawstyle="steps-post",
                             label=f"deposited particles ({count_column})")
        bottom.set_ylabel("deposited particles", color="tab:green")
    if volume is not None:
        right = bottom.twinx() if count is not None else bottom
        lines += right.plot(x, volume, lw=1.0, color="tab:purple", drawstyle="steps-post",
                            label=f"deposited volume V_dep ({volume_column})")
        right.set_ylabel("V_dep (d^3 in in.pore)", color="tab:purple")
    if lines:
        # Head room for the legend above the curves.
        for line in lines:
            high = max(line.get_ydata(), default=0.0)
            line.axes.set_ylim(-0.05 * (high or 1.0), 1.6 * (high or 1.0))
        bottom.legend(lines, [line.get_label() for line in lines], loc="upper left", fontsize=8,
                      ncol=2)
    else:
        bottom.text(0.5, 0.5, "no deposit columns (f_ID[6], f_ID[7]) in the thermo block",
                    transform=bottom.transAxes, ha="center", va="center")
    bottom.set_xlabel(data["x_label"])
    fig.tight_layout()
    return fig


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("log")
    parser.add_argument("--out", default="pressure_loss.png")
    parser.add_argument("--fix", default="pore", help="ID of the fix lbm/pore (default pore)")
    parser.add_argument("--column", default=None, help="thermo column of the pressure loss")
    parser.add_argument("--drop", type=float, default=0.1,
                        help="fall, as a fraction of the preceding peak, that counts as a burst")
    parser.add_argument("--window", type=int, default=None,
                        help="thermo rows within which the fall must happen (default: those of "
                             "1000 fluid steps)")
    parser.add_argument("--bursts", default=None,
                        help="the burst file fix lbm/pore wrote (burst_file): mark its bursts, "
                             "found every fluid step with the deposit criterion, instead of "
                             "replaying the rules on the thermo rows")
    args = parser.parse_args(argv)
    data = load(args.log, args.fix, args.column, args.bursts, args.drop, args.window)
    for b in data["bursts"]:
        after = "n/a" if b["P_after"] is None else f"{b['P_after']:.6g}"
        drop = "n/a" if b["P_after"] is None else f"{1 - b['P_after'] / b['P_peak']:.3f}"
        print(f"BURST step {b['step']:.0f} peak {b['P_peak']:.6g} after {after} drop {drop}")
    print(f"{len(data['bursts'])} burst(s) in {len(data['steps'])} thermo rows")
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("matplotlib not installed (apt-get install python3-matplotlib): no plot")
        return None
    fig = figure(data)
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")
    return fig


if __name__ == "__main__":
    main()
