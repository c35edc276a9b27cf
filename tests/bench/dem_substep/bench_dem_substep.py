#!/usr/bin/env python3
"""bench_dem_substep: the cost of one DEM substep with this project's styles against stock
LIGGGHTS on the same scene (in.dem_substep: 36 particles in a 52 x 24 x 24 pore scene).

  lbm:   pair_style lbm/dashdot + fix wall/voxel (voxel sum) + fix lbm/pore (n_dem 100)
  stock: pair_style gran model hooke + fix wall/gran planes, no fluid fix

The fluid step's own cost is left out: per substep, lbm = (loop time - the fluid and
diagnostics times fix lbm/pore reports for the run) / DEM steps; what stays is what every
substep pays (pair, wall, the substep load and lubrication of fix lbm/pore, integration,
communication, neighbour lists) plus, spread over its n_dem substeps, the per-fluid-step
gathering that the fix's fluid timer does not hold. The two cases run alternately (ABAB...),
--repeat pairs; the ratio of each pair, then the median and the spread (min, max).

Prints `BENCH <name> <value> <unit>` lines:
  BENCH dem_substep_ratio <median>          lbm / stock per substep (goal <= 1.3)
  BENCH dem_substep_ratio_min / _max        spread over the pairs
  BENCH dem_substep_lbm_us / _stock_us      microseconds per substep (medians)
  BENCH dem_substep_<case>_<part>_us        per component: pair, neigh, comm, output, and
      modify_other (fixes, integration, the rest); for lbm also its lubrication share
usage: bench_dem_substep.py --driver liggghts-lbm [--repeat 5] [--fluid-steps 1000]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ENV = dict(os.environ, OMP_NUM_THREADS="1")
LOOP = re.compile(r"Loop time of ([0-9.e+-]+) on \d+ procs for (\d+) steps")
PART = re.compile(r"^(Pair|Neigh|Comm|Outpt|Other)\s+time \(%\) = ([0-9.e+-]+)", re.M)
FIX = re.compile(r"fix lbm/pore: \d+ fluid steps in [0-9.e+-]+ s: fluid ([0-9.e+-]+) s .*?\), "
                 r"lubrication ([0-9.e+-]+) s, diagnostics ([0-9.e+-]+) s")
PARTS = {"Pair": "pair", "Neigh": "neigh", "Comm": "comm", "Outpt": "output", "Other": "modify_other"}


def run_case(driver, lbm, fluid_steps, work):
    cmd = [driver, "-in", os.path.join(HERE, "in.dem_substep"), "-log", "none",
           "-var", "lbm", str(lbm), "-var", "fluid_steps", str(fluid_steps)]
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, errors="replace", env=ENV)
    loop = LOOP.search(out.stdout)
    if out.returncode != 0 or "ERROR" in out.stdout or not loop:
        print(out.stdout[-3000:])
        sys.exit("bench_dem_substep: liggghts-lbm failed")
    steps = int(loop[2])
    parts = {PARTS[name]: float(seconds) for name, seconds in PART.findall(out.stdout)}
    total = float(loop[1])
    if lbm:
        fix = FIX.search(out.stdout)
        fluid, lubrication, diagnostics = (float(fix[k]) for k in (1, 2, 3))
        total -= fluid + diagnostics  # both inside LIGGGHTS's "Other" (modify) time
        parts["modify_other"] -= fluid + diagnostics
        parts["lubrication"] = lubrication
    us = 1e6 / steps
    return total * us, {name: seconds * us for name, seconds in parts.items()}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--fluid-steps", type=int, default=1000)
    args = parser.parse_args()
    driver = os.path.abspath(args.driver)
    per_step = {1: [], 0: []}
    parts = {1: [], 0: []}
    with tempfile.TemporaryDirectory(prefix="bench_dem_substep_") as work:
        for _ in range(args.repeat):
            for lbm in (1, 0):
                total, by_part = run_case(driver, lbm, args.fluid_steps, work)
                per_step[lbm].append(total)
                parts[lbm].append(by_part)
    ratios = [a / b for a, b in zip(per_step[1], per_step[0])]
    for lbm, name in ((1, "lbm"), (0, "stock")):
        print(f"BENCH dem_substep_{name}_us {statistics.median(per_step[lbm]):.3f} us")
        for part in parts[lbm][0]:
            value = statistics.median(p[part] for p in parts[lbm])
            print(f"BENCH dem_substep_{name}_{part}_us {value:.3f} us")
    print(f"BENCH dem_substep_ratio_min {min(ratios):.3f} ratio")
    print(f"BENCH dem_substep_ratio_max {max(ratios):.3f} ratio")
    print(f"BENCH dem_substep_ratio {statistics.median(ratios):.3f} ratio")


if __name__ == "__main__":
    main()
