#!/usr/bin/env python3
"""Summary of a run of in.pore from its log: the particle-free pressure loss (the last thermo
row of the warm-up), the largest pressure loss once particles are in (both in P_out), the
largest deposited volume and count, the most wall contacts, and the erosive bursts the fix
recorded. Used for doc/paper_units.md (the two readings of the paper's table).

Then one line per erosive burst of the burst file (fix lbm/pore's burst_file, bursts.txt
beside the log unless --bursts names another): its fluid step, P_peak and P_after in P_out
and the deposit it tore off, in particles and in volume (the script's length unit cubed: d^3
in in.pore), by each measure there is, each named, the figures' own first:
  window largest the thermo row with the largest deposited count in the burst window up to
                 the peak (f_pore[7], f_pore[6]): the deposit before its release, which every
                 figure of the paper counts (doc/paper.md, "The deposit";
                 examples/paper/figures/common.py);
  window median  the medians of the deposited count and V_dep over the burst window up to the
                 peak (the record's deposit_count, deposit_V);
  at the peak    the record's count_before and V_dep (a deposit that has begun to slide has
                 dropped out of them), with count_after at the minimum.
A burst file written before the records had the window medians says so on each line.

usage: summarize_run.py log.liggghts [--fix pore] [--walls walls] [--label NAME] [--bursts FILE]
"""
import argparse
import math
import os
import re
import sys

from plot_pressure import read_thermo, read_thermo_blocks, run_timing

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "paper"))


def read_bursts(path):
    """The burst file's rows as dicts named by its header line ("# step time[s] P_peak[P_out]
    ...", the units dropped), in step order. A run resumed from a restart file records again
    the bursts after that file: a row with the step of an earlier one replaces it."""
    names, rows = None, {}
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                names = [re.sub(r"\[.*\]$", "", word) for word in line[1:].split()]
                continue
            if not line.split():
                continue
            if names is None:
                sys.exit(f"{path}: no header line before the rows")
            row = dict(zip(names, map(float, line.split())))
            rows[row["step"]] = row
    return [rows[step] for step in sorted(rows)]


def burst_window_dem_steps(log, n_dem, dt_dem):
    """The burst window in DEM steps: the time the fix lbm/pore command in the log gives
    burst_window (time units), else the fix's default of 1000 fluid steps."""
    window = None
    pattern = re.compile(r"lbm/pore\b.*\bburst_window\s+([0-9.eE+-]+)(\s|$)")
    with open(log, errors="replace") as f:
        for line in f:
            m = pattern.search(line)
            if m:
                window = float(m.group(1))
    return 1000 * n_dem if window is None else window / dt_dem


def largest_in_window(columns, peak_step, window_steps):
    """(count, V_dep) of the thermo row with the largest deposited count in the window up to
    the peak (examples/paper/figures/common.py's largest_deposit_before), or None."""
    try:
        from figures.common import largest_deposit_before
    except ImportError:  # numpy or matplotlib missing
        return None
    largest = largest_deposit_before(columns, peak_step, window_steps)
    return None if largest is None else largest[:2]


def number(value, digits=4):
    return "n/a" if value is None or (isinstance(value, float) and math.isnan(value)) else f"{value:.{digits}g}"


def burst_lines(log, bursts_path, fix="pore"):
    """The lines describing the bursts of `bursts_path` (a header and one line per burst)."""
    rows = read_bursts(bursts_path)
    timing = run_timing(log)
    n_dem, dt_dem = timing if timing else (1, 1.0)
    header, thermo_rows = read_thermo(log)
    # The thermo columns as the figures name them (pore[N]), whatever the fix's ID.
    columns = {re.sub(rf"^(f_)?{re.escape(fix)}\[", "pore[", name): [r[j] for r in thermo_rows]
               for j, name in enumerate(header)}
    window = burst_window_dem_steps(log, n_dem, dt_dem)
    lines = [f"erosive bursts ({bursts_path}): {len(rows)}; each deposit as particles, V_dep "
             f"(d^3 in in.pore); window: the {window / n_dem:g} fluid steps up to the peak"]
    for k, b in enumerate(rows, start=1):
        step = b["step"]
        where = f"fluid step {step / n_dem:.0f}" if timing else f"DEM step {step:.0f}"
        drop = 1 - b["P_after"] / b["P_peak"] if b["P_peak"] else float("nan")
        if "deposit_count" in b:
            median = f"window median {b['deposit_count']:.4g}, {number(b.get('deposit_V'))}"
        else:
            median = "window median not recorded (a burst file older than its columns)"
        largest = largest_in_window(columns, step, window)
        largest = (f"window largest {largest[0]}, {number(largest[1])}" if largest
                   else "window largest n/a (no thermo rows in the window)")
        lines.append(
            f"burst {k}: {where}, P_peak {b['P_peak']:.4g} P_out, P_after {b['P_after']:.4g} P_out "
            f"(fell {100 * drop:.0f} %); deposit torn off: {largest} | {median} | at the peak "
            f"{b['count_before']:.0f}, {number(b['V_dep'])}; at the minimum {b['count_after']:.0f} particles")
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("log")
    parser.add_argument("--fix", default="pore")
    parser.add_argument("--walls", default="walls")
    parser.add_argument("--label", default=None)
    parser.add_argument("--bursts", default=None,
                        help="the fix's burst file (default: bursts.txt beside the log)")
    args = parser.parse_args(argv)
    blocks = read_thermo_blocks(args.log)
    if len(blocks) < 2:
        sys.exit(f"{args.log}: needs the warm-up block and the particle block")
    header0, warm = blocks[0]
    header = blocks[1][0]  # the particle runs share one thermo style
    rows = [row for _, block in blocks[1:] for row in block]

    def col(h, name):
        return h.index(name)

    p = f"{args.fix}[16]"
    clean = warm[-1][col(header0, p)]
    largest = max(r[col(header, p)] for r in rows)
    vdep = max(r[col(header, f"{args.fix}[6]")] for r in rows)
    count = max(r[col(header, f"{args.fix}[7]")] for r in rows)
    walls = max(r[col(header, f"{args.walls}[1]")] for r in rows) if f"{args.walls}[1]" in header else float("nan")
    bursts = rows[-1][col(header, f"{args.fix}[18]")]
    steps = rows[-1][0]
    label = args.label or args.log
    print(f"{label}: DEM steps {steps:.0f}, clean P/P_out {clean:.4g}, largest P/P_out with particles "
          f"{largest:.4g} ({largest / clean:.2f} x clean), largest V_dep {vdep:.4g}, deposited {count:.0f}, "
          f"most wall contacts {walls:.0f}, erosive bursts {bursts:.0f}")
    bursts_path = args.bursts or os.path.join(os.path.dirname(args.log), "bursts.txt")
    if os.path.exists(bursts_path):
        for line in burst_lines(args.log, bursts_path, args.fix):
            print(line)
    else:
        print(f"no burst file {bursts_path}: the bursts are not listed")


if __name__ == "__main__":
    main()
