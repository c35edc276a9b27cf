#!/usr/bin/env python3
"""bench_features: what each optional physics costs per step of liggghts-lbm with fix lbm/pore
(in.features: 36 particles in a 52 x 24 x 24 pore scene, n_dem 100), and what fix lbm/pore
costs without particles against the pure-fluid solver (examples/pore_fluid) on the same lattice.

Prints `BENCH <name> <value> <unit>` lines:
  BENCH <feature>_on_vs_off <ratio> ratio   for cohesion (kc 0 / 0.1), adhesion (ka 0 / 0.1),
      friction (mu 0 / 0.1), lubrication (no / yes), fluid_output (vtk 0 / every 10 fluid steps):
      loop time per DEM step with the feature on / off, best of --repeat alternating runs
  BENCH no_particles_vs_pure_fluid <ratio> ratio   (goal <= 1.1): fix lbm/pore without
      particles (n_dem 1) against pore_fluid, time per fluid step, each from the difference of a
      short and a long run (setup cancels), pore_fluid run right before
  and the absolute figures (s per DEM step, s per fluid step).

usage: bench_features.py --driver liggghts-lbm --pore-fluid pore_fluid [--repeat 3]
Both programs run on one core (OMP_NUM_THREADS=1); run on an otherwise idle machine.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = {"Li": 20, "Lf": 10, "Lp": 10, "Lo": 12, "W": 24, "D": 14}
ENV = dict(os.environ, OMP_NUM_THREADS="1")


def liggghts(driver, variables, work):
    cmd = [driver, "-in", os.path.join(HERE, "in.features"), "-log", "none"]
    for name, value in {**SCENE, **variables}.items():
        cmd += ["-var", name, str(value)]
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, errors="replace", env=ENV)
    if out.returncode != 0 or "ERROR" in out.stdout:
        print(out.stdout[-3000:])
        sys.exit("bench_features: liggghts-lbm failed")
    loop = re.search(r"Loop time of ([0-9.e+-]+) on \d+ procs for (\d+) steps", out.stdout)
    fix = re.search(r"fix lbm/pore: (\d+) fluid steps in ([0-9.e+-]+) s: fluid ([0-9.e+-]+) s.*"
                    r"; ([0-9.e+-]+) s per fluid step", out.stdout)
    return {"per_step": float(loop[1]) / int(loop[2]), "fluid_steps": int(fix[1]),
            "fix_total": float(fix[2]), "fix_fluid": float(fix[3]), "fix_per_fluid_step": float(fix[4])}


def pore_fluid(program, steps, work):
    cmd = [program, f"steps={steps}", "print_every=0", "output_every=0", f"width={SCENE['W']}",
           f"inlet={SCENE['Li']}", f"free={SCENE['Lf']}", f"pore_length={SCENE['Lp']}",
           f"outlet={SCENE['Lo']}", f"pore_diameter={SCENE['D']}", "tau=1.0", "inlet_velocity=0.01"]
    start = time.perf_counter()
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         env=ENV)
    elapsed = time.perf_counter() - start
    if out.returncode != 0:
        print(out.stdout[-2000:])
        sys.exit("bench_features: pore_fluid failed")
    return elapsed


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--pore-fluid", required=True)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--fluid-steps", type=int, default=100, help="per feature run (x n_dem 100)")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="bench_features_")

    # Everything on (the paper's table) is the reference; each feature is switched off alone.
    features = [("cohesion", {"kc": 0.0}, {"kc": 0.1}),
                ("adhesion", {"ka": 0.0}, {"ka": 0.1}),
                ("friction", {"mu": 0.0}, {"mu": 0.1}),
                ("lubrication", {"lub": "no"}, {"lub": "yes"}),
                ("fluid_output", {"vtk": 0}, {"vtk": 10})]
    liggghts(args.driver, {"fluid_steps": 5}, work)  # warm the file cache
    for name, off, on in features:
        best = {"off": float("inf"), "on": float("inf")}
        for _ in range(args.repeat):
            for label, settings in (("off", off), ("on", on)):
                r = liggghts(args.driver, dict(settings, fluid_steps=args.fluid_steps), work)
                best[label] = min(best[label], r["per_step"])
        print(f"BENCH {name}_off_step {best['off']:.4g} s")
        print(f"BENCH {name}_on_step {best['on']:.4g} s")
        print(f"BENCH {name}_on_vs_off {best['on'] / best['off']:.3f} ratio", flush=True)

    # Fluid without particles: per fluid step from the difference of n and 2n fluid steps.
    n = 300
    pure, fix = float("inf"), float("inf")
    fix_own = float("inf")
    for _ in range(args.repeat):
        pure = min(pure, (pore_fluid(args.pore_fluid, 2 * n, work) -
                          pore_fluid(args.pore_fluid, n, work)) / n)
        short = liggghts(args.driver, {"particles": 0, "n_dem": 1, "fluid_steps": n}, work)
        long = liggghts(args.driver, {"particles": 0, "n_dem": 1, "fluid_steps": 2 * n}, work)
        fix = min(fix, (long["fix_total"] - short["fix_total"]) / n)
        fix_own = min(fix_own, long["fix_per_fluid_step"])
    nodes = (SCENE["Li"] + SCENE["Lf"] + SCENE["Lp"] + SCENE["Lo"]) * SCENE["W"] ** 2
    print(f"BENCH pure_fluid_step {pure:.4g} s   ({nodes} nodes, {nodes / pure / 1e6:.2f} MLUPS)")
    print(f"BENCH no_particles_fluid_step {fix:.4g} s   ({nodes / fix / 1e6:.2f} MLUPS; the fix's "
          f"own end-of-run figure {fix_own:.4g} s per fluid step)")
    print(f"BENCH no_particles_vs_pure_fluid {fix / pure:.3f} ratio   (goal <= 1.1)")


if __name__ == "__main__":
    main()
