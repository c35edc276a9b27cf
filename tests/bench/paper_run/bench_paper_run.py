#!/usr/bin/env python3
"""bench_paper_run: how long one paper-length run (10^6 fluid steps, N_DEM = 100 DEM substeps
each) would take on this machine, from a few thousand fluid steps of the paper's scene.

The scene is examples/pore/in.pore at its defaults, which are the paper's (Table I read in
d-units at 7.1 cells per d): a 90 x 40 x 40 lattice (inlet I = 20, free III = 20, pore IV
L = 30, outlet II = 20, W = 40 cells), a pore of D = 25 cells, particles of d = 7 cells
inserted at c_in = 0.05 in region I every 100 fluid steps, inlet velocity 0.02 cells per
fluid step, N_DEM = 100. It runs on 2 MPI ranks with one OpenMP thread each. The particle-
free warm-up is one fluid step; the timed figure is fix lbm/pore's own "s per fluid step" of
the run with particles:
  fix lbm/pore: N fluid steps in T s: ... ; S s per fluid step
The ranks split the lattice across the flow (in.pore's -var procs "1 * 1": both ranks hold
half of every region, so both share the coupling of the particles arriving at the inlet);
_along_flow is in.pore's default grid ("* 1 1", the inlet's rank does the coupling alone);
_one_rank_two_threads is one rank with two OpenMP threads (the whole lattice on one rank: no
halo messages, no rank waiting for the other's particles, the coupling stages split over the
threads; the DEM runs on one thread).
The drivers given (--driver for the double-precision build, --single-driver for a
-DLBM_PORE_SINGLE_PRECISION=ON build) run --repeat times, interleaved (double, double along the
flow, single, double, ...), so that a shared machine's load swings fall on all. Prints the
median and min-max:
  BENCH paper_run_fluid_step_s[_along_flow|_one_rank_two_threads|_single|
  _single_one_rank_two_threads], BENCH paper_run_particles[...],
  BENCH paper_run_projected_hours[...] (goal <= 0.75 in double precision) with _min, _max.

usage: bench_paper_run.py --driver liggghts-lbm --script examples/pore/in.pore
                          [--single-driver liggghts-lbm] [--fluid-steps N] [--repeat N]
                          [--mpirun mpirun]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

PER_STEP = re.compile(r"fix lbm/pore: (\d+) fluid steps in [\d.eE+-]+ s: .*?; ([\d.eE+-]+) s per fluid step")
PAPER_STEPS = 1e6
N_DEM = 100
SCENE = {"cells_per_d": 7.1, "c_in": 0.05, "n_dem": N_DEM, "vtk_every": 0}


def time_run(driver, script, mpirun, fluid_steps, procs, ranks, threads):
    knobs = dict(SCENE, warmup=N_DEM, steps=fluid_steps * N_DEM, thermo_every=fluid_steps * N_DEM,
                 procs=procs)
    cmd = [mpirun, "-np", str(ranks), "--allow-run-as-root", "--oversubscribe"]
    # mpirun binds each of up to 2 ranks to one core: a rank's threads would share it.
    if threads > 1:
        cmd += ["--bind-to", "none"]
    cmd += [driver, "-in", script]
    for name, value in knobs.items():
        cmd += ["-var", name, str(value)]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    with tempfile.TemporaryDirectory(prefix="bench_paper_run_") as work:
        out = subprocess.run(cmd, cwd=work, env=env, capture_output=True, text=True,
                             errors="replace").stdout
    runs = PER_STEP.findall(out)
    atoms = [line.split()[1] for line in out.splitlines() if re.match(r"\s+\d+\s+\d+\s", line)]
    if len(runs) < 2:
        print(out[-3000:])
        sys.exit(f"bench_paper_run: {driver} did not complete both runs")
    # The timing line of the run with particles: where the step's time goes.
    lines = [line for line in out.splitlines() if line.startswith("fix lbm/pore:") and "fluid steps in" in line]
    print(f"bench_paper_run: {lines[-1]}", flush=True)
    return float(runs[1][1]), (atoms[-1] if atoms else "unknown")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--single-driver", default="")
    parser.add_argument("--script", required=True)
    parser.add_argument("--mpirun", default="mpirun")
    parser.add_argument("--fluid-steps", type=int, default=2000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    script = os.path.abspath(args.script)
    # (suffix, driver, LIGGGHTS processors grid, MPI ranks, OpenMP threads per rank): the
    # figure is for 2 ranks split across the flow (each rank holds half of every region, so
    # both do coupling work); _along_flow is in.pore's default grid (the inlet's rank holds
    # all the arriving particles); _one_rank_two_threads the same two cores as one rank.
    runs = [("", args.driver, "1 * 1", 2, 1), ("_along_flow", args.driver, "* 1 1", 2, 1),
            ("_one_rank_two_threads", args.driver, "1 1 1", 1, 2)]
    if args.single_driver:
        runs.append(("_single", args.single_driver, "1 * 1", 2, 1))
        runs.append(("_single_one_rank_two_threads", args.single_driver, "1 1 1", 1, 2))
    times = {run[0]: [] for run in runs}
    particles = {}
    for round_ in range(args.repeat):
        for suffix, driver, procs, ranks, threads in runs:
            per_step, count = time_run(os.path.abspath(driver), script, args.mpirun, args.fluid_steps,
                                       procs, ranks, threads)
            times[suffix].append(per_step)
            particles[suffix] = count
            print(f"bench_paper_run: round {round_ + 1}, {driver}, {ranks} rank(s) x {threads} "
                  f"thread(s), processors {procs}: {per_step:.4g} s per fluid step, {count} particles",
                  flush=True)
    for suffix, *_ in runs:
        t = sorted(times[suffix])
        median = statistics.median(t)
        print(f"BENCH paper_run_fluid_step_s{suffix} {median:.4g} s")
        print(f"BENCH paper_run_particles{suffix} {particles[suffix]} count")
        for name, value in (("", median), ("_min", t[0]), ("_max", t[-1])):
            print(f"BENCH paper_run_projected_hours{suffix}{name} {value * PAPER_STEPS / 3600:.3f} hours")


if __name__ == "__main__":
    main()
