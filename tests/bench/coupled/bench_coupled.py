#!/usr/bin/env python3
"""bench_coupled: the cost of one coupled fluid step with its N_DEM DEM substeps on the main
example's scene, split into fluid, coupling and DEM, against the same lattice without
particles in the same process.

examples/pore/in.pore_small runs twice inside one liggghts-lbm process: a particle-free warm-up
(fix lbm/pore takes the pure fluid step when no particle exists) and the run with particles.
At the end of each run fix lbm/pore prints where the time went; this script reads those lines:
  fix lbm/pore: N fluid steps in T s: fluid A s (of which mapping, refill, moving walls and
    force B s ...), lubrication C s, diagnostics D s, DEM and the rest E s; S s per fluid step
Prints BENCH lines (per fluid step, i.e. per N_DEM DEM steps):
  coupled_step_s, coupled_fluid_s (collide-stream, boundaries, halo), coupled_coupling_s
  (mapping, refill, moving walls, force, lubrication), coupled_dem_s (DEM and the rest,
  diagnostics), pure_fluid_step_s, particles, coupled_vs_pure_fluid (goal <= 2).

usage: bench_coupled.py --driver liggghts-lbm --script examples/pore/in.pore_small [--steps N]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

TIMING = re.compile(
    r"fix lbm/pore: (\d+) fluid steps in ([\d.eE+-]+) s: fluid ([\d.eE+-]+) s \(of which mapping, "
    r"refill, moving walls and force ([\d.eE+-]+) s[^)]*\), lubrication ([\d.eE+-]+) s, diagnostics "
    r"([\d.eE+-]+) s, DEM and the rest ([\d.eE+-]+) s; ([\d.eE+-]+) s per fluid step")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--script", required=True)
    parser.add_argument("--warmup", type=int, default=200000,
                        help="DEM steps without particles (2000 fluid steps: a stable pure-fluid figure)")
    parser.add_argument("--steps", type=int, default=1500000, help="DEM steps with particles")
    args = parser.parse_args()
    args.driver, args.script = os.path.abspath(args.driver), os.path.abspath(args.script)
    with tempfile.TemporaryDirectory(prefix="bench_coupled_") as work:
        cmd = [args.driver, "-in", args.script, "-var", "warmup", str(args.warmup),
               "-var", "steps", str(args.steps), "-var", "vtk_every", "0",
               "-var", "thermo_every", str(args.steps)]
        out = subprocess.run(cmd, cwd=work, capture_output=True, text=True, errors="replace").stdout
    runs = TIMING.findall(out)
    atoms = [line.split()[1] for line in out.splitlines()
             if re.match(r"\s+\d+\s+\d+\s", line)]
    if len(runs) < 2:
        print(out[-3000:])
        sys.exit("bench_coupled: the example did not complete both runs")
    pure, coupled = [list(map(float, r)) for r in runs[:2]]
    n = coupled[0]
    fluid = (coupled[2] - coupled[3]) / n
    coupling = (coupled[3] + coupled[4]) / n
    dem = (coupled[5] + coupled[6]) / n
    print(f"BENCH pure_fluid_step_s {pure[7]:.4g} s")
    print(f"BENCH coupled_step_s {coupled[7]:.4g} s")
    print(f"BENCH coupled_fluid_s {fluid:.4g} s")
    print(f"BENCH coupled_coupling_s {coupling:.4g} s")
    print(f"BENCH coupled_dem_s {dem:.4g} s")
    print(f"BENCH particles {atoms[-1] if atoms else 'unknown'} count")
    print(f"BENCH coupled_vs_pure_fluid {coupled[7] / pure[7]:.3f} ratio")


if __name__ == "__main__":
    main()
