#!/usr/bin/env python3
"""bench_dem_substep: the cost of one DEM substep with this project's styles against stock
LIGGGHTS on the same scene (in.dem_substep: 36 particles in a 52 x 24 x 24 pore scene).

  lbm:    pair_style lbm/dashdot + fix wall/voxel model voxel_sum (the paper's, in.pore's)
          + fix lbm/pore (n_dem 100)
  smooth: the same with fix wall/voxel's default model smooth (in.pore_small's)
  stock_touching: pair_style gran model hooke + fix wall/gran planes, no fluid fix, with as
          many contacts as lbm: the particles 7.25 across, so that lattice neighbours and the
          walls overlap, held by LIGGGHTS's SJKR cohesion (lbm's pairs are cohesive at gaps
          of 0.2, inside their range; stock's touch only when they overlap)
  stock:  the same without the overlap and cohesion (the particles 7 across): far fewer
          contacts (about a third of lbm's pairs, after the packing has met the block)

The fluid step's own cost is left out: per substep, lbm = (loop time - the fluid and
diagnostics times fix lbm/pore reports for the run) / DEM steps; what stays is what every
substep pays (pair, wall, the substep load and lubrication of fix lbm/pore, integration,
communication, neighbour lists) plus, spread over its n_dem substeps, the per-fluid-step
gathering that the fix's fluid timer does not hold. The cases run in turn (stock, lbm,
smooth, stock, ...), --repeat rounds; the ratio of each round, then the median and the spread
(min, max).

Prints `BENCH <name> <value> <unit>` lines:
  BENCH dem_substep_ratio <median>          lbm / stock_touching per substep (goal <= 1.5)
  BENCH dem_substep_ratio_min / _max        spread over the rounds
  BENCH dem_substep_ratio_fewer_contacts[_min|_max]  lbm / stock
  BENCH dem_substep_<case>_pair_contacts    mean pairs in contact over the thermo rows
  BENCH dem_substep_ratio_smooth[_min|_max] smooth / stock
  BENCH dem_substep_<case>_us               microseconds per substep (medians)
  BENCH dem_substep_<case>_<part>_us        per component: pair, neigh, comm, output, and
      modify_other (fixes, integration, the rest); for lbm and smooth also the lubrication
      (part of modify_other)
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


CASES = {"stock": ["-var", "lbm", "0"],
         "stock_touching": ["-var", "lbm", "0", "-var", "touch", "1"],
         "lbm": ["-var", "lbm", "1", "-var", "wall_model", "voxel_sum"],
         "smooth": ["-var", "lbm", "1", "-var", "wall_model", "smooth"]}


def run_case(driver, case, fluid_steps, work):
    lbm = not case.startswith("stock")
    cmd = [driver, "-in", os.path.join(HERE, "in.dem_substep"), "-log", "none",
           "-var", "fluid_steps", str(fluid_steps)] + CASES[case]
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
    # Thermo rows "step atoms pairs": the pairs in contact, averaged over the run.
    rows = [line.split() for line in out.stdout.splitlines()]
    pairs = [float(r[2]) for r in rows if len(r) == 3 and r[0].isdigit() and r[1].isdigit()]
    parts["pair_contacts"] = statistics.mean(pairs) / us if pairs else float("nan")  # undone by * us
    return total * us, {name: seconds * us for name, seconds in parts.items()}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--fluid-steps", type=int, default=500)
    args = parser.parse_args()
    driver = os.path.abspath(args.driver)
    per_step = {case: [] for case in CASES}
    parts = {case: [] for case in CASES}
    with tempfile.TemporaryDirectory(prefix="bench_dem_substep_") as work:
        for _ in range(args.repeat):
            for case in CASES:
                total, by_part = run_case(driver, case, args.fluid_steps, work)
                per_step[case].append(total)
                parts[case].append(by_part)
    for case in CASES:
        print(f"BENCH dem_substep_{case}_us {statistics.median(per_step[case]):.3f} us")
        for part in parts[case][0]:
            value = statistics.median(p[part] for p in parts[case])
            if part == "pair_contacts":
                print(f"BENCH dem_substep_{case}_pair_contacts {value:.1f} count")
            else:
                print(f"BENCH dem_substep_{case}_{part}_us {value:.3f} us")
    for case, stock, suffix in (("smooth", "stock_touching", "_smooth"),
                                ("lbm", "stock", "_fewer_contacts"), ("lbm", "stock_touching", "")):
        ratios = [a / b for a, b in zip(per_step[case], per_step[stock])]
        print(f"BENCH dem_substep_ratio{suffix}_min {min(ratios):.3f} ratio")
        print(f"BENCH dem_substep_ratio{suffix}_max {max(ratios):.3f} ratio")
        print(f"BENCH dem_substep_ratio{suffix} {statistics.median(ratios):.3f} ratio")


if __name__ == "__main__":
    main()
