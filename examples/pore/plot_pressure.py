#!/usr/bin/env python3
"""Plot the pressure loss across the pore against time from a LIGGGHTS log, marking the
erosive bursts: sudden drops of the pressure loss (paper, Figs. 2-3).

Usage: plot_pressure.py log.liggghts [--fix pore] [--out pressure_loss.png] [--drop 0.1] [--window 10]

The log must contain a thermo block whose header has the columns `Step` and the fix's
pressure loss, e.g. `thermo_style custom step f_pore[16] f_pore[6] ...` (LIGGGHTS prints the
header as pore[16], pore[6]); P / P_out (f_ID[16]) is used when present, else f_ID[1]. With the deposited volume f_<ID>[6] in the block as well, it is
drawn on a second axis (the paper relates the pressure peaks to V_dep). A burst is a fall of
the pressure loss by more than `--drop` (fraction of the preceding peak, default 10 %) within
`--window` thermo rows (default 10: 1000 fluid steps in the example), followed to its
minimum; the rules are those of fix lbm/pore's online detector (find_bursts). Prints each
burst as `BURST step peak after drop_fraction` and writes the plot.
"""
import argparse
import sys


def read_thermo(path):
    """Returns (header, rows) of the log's thermo blocks that share the last block's columns
    (one block per run command), concatenated. A row whose step is not past the row before
    supersedes the rows from its step on: a run resumed from a restart file (appending to
    its log) repeats the steps between that file and where it was cut short."""
    blocks = read_thermo_blocks(path)
    if not blocks:
        sys.exit(f"{path}: no thermo block with a 'Step' header found")
    header = blocks[-1][0]
    kept = []
    for row in (row for h, rows in blocks if h == header for row in rows):
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
            except ValueError:
                header = None
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


def bursts_from_file(path, steps):
    """(peak, minimum) row indices of the bursts in fix lbm/pore's burst file: the rows nearest
    to each burst's peak step and to its peak step + Delta t / dt (the file's time is the fluid
    time, one unit per fluid step of n_dem DEM steps: the minimum's DEM step is estimated from
    the peak's and the fall's share of the run)."""
    rows = []
    with open(path) as burst_file:
        for line in burst_file:
            if line.startswith("#") or not line.split():
                continue
            words = line.split()
            peak_step, peak_time, duration = float(words[0]), float(words[1]), float(words[5])
            after_step = peak_step * (1.0 + duration / peak_time) if peak_time > 0 else peak_step
            nearest = lambda s: min(range(len(steps)), key=lambda i: abs(steps[i] - s))
            rows.append((nearest(peak_step), nearest(after_step)))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("log")
    parser.add_argument("--out", default="pressure_loss.png")
    parser.add_argument("--fix", default="pore", help="ID of the fix lbm/pore (default pore)")
    parser.add_argument("--column", default=None, help="thermo column of the pressure loss")
    parser.add_argument("--drop", type=float, default=0.1,
                        help="fall, as a fraction of the preceding peak, that counts as a burst")
    parser.add_argument("--window", type=int, default=10,
                        help="thermo rows within which the fall must happen")
    parser.add_argument("--bursts", default=None,
                        help="the burst file fix lbm/pore wrote (burst_file): mark its bursts, "
                             "found every fluid step with the deposit criterion, instead of "
                             "replaying the rules on the thermo rows")
    args = parser.parse_args()
    header, rows = read_thermo(args.log)
    def find(index):
        for name in (f"f_{args.fix}[{index}]", f"{args.fix}[{index}]"):
            if name in header:
                return name
        return None

    # The pressure loss in units of P_out (f_ID[16], the paper's unit) when the log has it.
    column = args.column or find(16) or find(1)
    if column not in header:
        sys.exit(f"{args.log}: no column {column!r} in thermo header {header}")
    c = header.index(column)
    steps = [r[0] for r in rows]
    pressure = [r[c] for r in rows]
    if args.bursts:
        bursts = bursts_from_file(args.bursts, steps)
    else:
        bursts = find_bursts(steps, pressure, args.drop, args.window)
    deposit_column = find(6)
    deposits = [r[header.index(deposit_column)] for r in rows] if deposit_column else None
    for peak, after in bursts:
        print(f"BURST step {steps[peak]:.0f} peak {pressure[peak]:.6g} after {pressure[after]:.6g} "
              f"drop {1 - pressure[after] / pressure[peak]:.3f}")
    print(f"{len(bursts)} burst(s) in {len(rows)} thermo rows")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed (apt-get install python3-matplotlib): no plot")
        return
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(steps, pressure, lw=1.2, label="pressure loss")
    for peak, after in bursts:
        ax.axvspan(steps[peak], steps[after], color="tab:red", alpha=0.25)
        ax.plot([steps[peak]], [pressure[peak]], "v", color="tab:red")
    if deposits:
        ax2 = ax.twinx()
        ax2.plot(steps, deposits, lw=1.0, color="tab:green", label="deposited volume")
        ax2.set_ylabel(f"deposited volume V_dep ({deposit_column})", color="tab:green")
    ax.set_xlabel("DEM step")
    unit = "P / P_out" if column == find(16) else "pressure units"
    ax.set_ylabel(f"pressure loss, {unit} ({column})")
    ax.set_title(f"{len(bursts)} erosive burst(s) marked")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
