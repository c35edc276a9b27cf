#!/usr/bin/env python3
"""Plot the pressure loss across the pore against time from a LIGGGHTS log, marking the
erosive bursts: sudden drops of the pressure loss (paper, Figs. 2-3).

Usage: plot_pressure.py log.liggghts [--fix pore] [--out pressure_loss.png] [--drop 0.1] [--window 10]

The log must contain a thermo block whose header has the columns `Step` and the fix's
pressure loss, e.g. `thermo_style custom step f_pore[1] f_pore[6] ...` (LIGGGHTS prints the
header as pore[1], pore[6]). With the deposited volume f_<ID>[6] in the block as well, it is
drawn on a second axis (the paper relates the pressure peaks to V_dep). A burst is a fall of
the pressure loss by more than `--drop` (fraction of the preceding peak, default 10 %) within
`--window` thermo rows (default 10: 1000 fluid steps in the example). Prints each burst as
`BURST step peak after drop_fraction` and writes the plot.
"""
import argparse
import sys


def read_thermo(path):
    """Returns (header, rows) of every thermo block in the log, concatenated."""
    header, rows = None, []
    with open(path) as log:
        for line in log:
            words = line.split()
            if words and words[0] == "Step":
                header = words
                continue
            if header is None or len(words) != len(header):
                continue
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                header = None if words and words[0].startswith("Loop") else header
    if header is None or not rows:
        sys.exit(f"{path}: no thermo block with a 'Step' header found")
    return header, rows


def find_bursts(steps, pressure, drop, window):
    """(peak, after) index pairs: a peak is the highest value since `window` rows before it and
    until the pressure's lowest point within `window` rows after it, which lies more than
    `drop` (fraction of the peak) below it."""
    bursts, i, n = [], 0, len(pressure)
    while i < n:
        peak = pressure[i]
        if peak <= 0 or any(pressure[k] > peak for k in range(max(0, i - window), i)):
            i += 1
            continue
        low = i
        for j in range(i + 1, min(n, i + window + 1)):
            if pressure[j] > peak:
                break
            if pressure[j] < pressure[low]:
                low = j
        if pressure[low] < (1 - drop) * peak:
            bursts.append((i, low))
            i = low
        i += 1
    return bursts


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
    args = parser.parse_args()
    header, rows = read_thermo(args.log)
    def find(index):
        for name in (f"f_{args.fix}[{index}]", f"{args.fix}[{index}]"):
            if name in header:
                return name
        return None

    column = args.column or find(1)
    if column not in header:
        sys.exit(f"{args.log}: no column {column!r} in thermo header {header}")
    c = header.index(column)
    steps = [r[0] for r in rows]
    pressure = [r[c] for r in rows]
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
    ax.set_ylabel(f"pressure loss ({column})")
    ax.set_title(f"{len(bursts)} erosive burst(s) marked")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
