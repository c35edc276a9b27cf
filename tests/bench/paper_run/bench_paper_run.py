#!/usr/bin/env python3
"""bench_paper_run: how long one paper-length run (10^6 fluid steps, N_DEM = 100 DEM substeps
each) would take on this machine, from a few thousand fluid steps of the paper's scene.

The scene is examples/pore/in.pore with its -var knobs set to the paper's lattice: 90 x 40 x 40
cells (inlet I = 20, free III = 20, pore IV L = 30, outlet II = 20, W = 40), a pore of D = 25
cells, particles of d = 7 cells inserted at c_in = 0.05 in region I (about 10 particles in the
scene: they drift at u_in = 0.001 cell per fluid step, so the load hardly changes in the run).
It runs on 2 MPI ranks with one OpenMP thread each. The particle-free warm-up is one fluid
step; the timed figure is fix lbm/pore's own "s per fluid step" of the run with particles:
  fix lbm/pore: N fluid steps in T s: ... ; S s per fluid step
Prints, for each driver given (--driver for the double-precision build, --single-driver for
a -DLBM_PORE_SINGLE_PRECISION=ON build):
  BENCH paper_run_fluid_step_s[_single], BENCH paper_run_particles[_single],
  BENCH paper_run_projected_hours[_single] (goal <= 0.75 in double precision).

usage: bench_paper_run.py --driver liggghts-lbm --script examples/pore/in.pore
                          [--single-driver liggghts-lbm] [--fluid-steps N] [--mpirun mpirun]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

PER_STEP = re.compile(r"fix lbm/pore: (\d+) fluid steps in [\d.eE+-]+ s: .*?; ([\d.eE+-]+) s per fluid step")
PAPER_STEPS = 1e6
N_DEM = 100
SCENE = {"Li": 20, "Lf": 20, "Lp": 30, "Lo": 20, "W": 40, "D": 25, "c_in": 0.05,
         "u_in": 0.001, "n_dem": N_DEM, "vtk_every": 0}


def time_run(driver, script, mpirun, fluid_steps):
    knobs = dict(SCENE, warmup=N_DEM, steps=fluid_steps * N_DEM, thermo_every=fluid_steps * N_DEM)
    cmd = [mpirun, "-np", "2", "--allow-run-as-root", "--oversubscribe", driver, "-in", script]
    for name, value in knobs.items():
        cmd += ["-var", name, str(value)]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    with tempfile.TemporaryDirectory(prefix="bench_paper_run_") as work:
        out = subprocess.run(cmd, cwd=work, env=env, capture_output=True, text=True,
                             errors="replace").stdout
    runs = PER_STEP.findall(out)
    atoms = [line.split()[1] for line in out.splitlines() if re.match(r"\s+\d+\s+\d+\s", line)]
    if len(runs) < 2:
        print(out[-3000:])
        sys.exit(f"bench_paper_run: {driver} did not complete both runs")
    return float(runs[1][1]), (atoms[-1] if atoms else "unknown")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--single-driver", default="")
    parser.add_argument("--script", required=True)
    parser.add_argument("--mpirun", default="mpirun")
    parser.add_argument("--fluid-steps", type=int, default=2000)
    args = parser.parse_args()
    script = os.path.abspath(args.script)
    drivers = [("", args.driver)] + ([("_single", args.single_driver)] if args.single_driver else [])
    for suffix, driver in drivers:
        per_step, particles = time_run(os.path.abspath(driver), script, args.mpirun, args.fluid_steps)
        print(f"BENCH paper_run_fluid_step_s{suffix} {per_step:.4g} s")
        print(f"BENCH paper_run_particles{suffix} {particles} count")
        print(f"BENCH paper_run_projected_hours{suffix} {per_step * PAPER_STEPS / 3600:.3f} hours")


if __name__ == "__main__":
    main()
