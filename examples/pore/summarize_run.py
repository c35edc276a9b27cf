#!/usr/bin/env python3
"""Summary of a run of in.pore from its log: the particle-free pressure loss (the last thermo
row of the warm-up), the largest pressure loss once particles are in (both in P_out), the
largest deposited volume and count, the most wall contacts, and the erosive bursts the fix
recorded. Used for doc/paper_units.md (the two readings of the paper's table).

usage: summarize_run.py log.liggghts [--fix pore] [--walls walls] [--label NAME]
"""
import argparse
import sys

from plot_pressure import read_thermo_blocks


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("log")
    parser.add_argument("--fix", default="pore")
    parser.add_argument("--walls", default="walls")
    parser.add_argument("--label", default=None)
    args = parser.parse_args()
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


if __name__ == "__main__":
    main()
