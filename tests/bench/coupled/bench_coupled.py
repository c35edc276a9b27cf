#!/usr/bin/env python3
"""bench_coupled: the cost of one coupled fluid step with its N_DEM DEM substeps on the small
pore scene, split into fluid, coupling and DEM, against the pure fluid step on the same
lattice, interleaved so that a shared machine's changing load falls on both alike.

in.coupled_interleaved runs examples/pore/in.pore_small (its particle-free warm-up, then
--steps DEM steps with particles that build up the particle load) and then --pairs pairs of
  A: examples/pore_fluid on the same lattice, --pure-steps fluid steps, in its own process
     (LIGGGHTS `shell`), its MLUPS row written to pure_<pair>.txt;
  B: --chunk DEM steps of the coupled run; at the end of each run fix lbm/pore prints
  fix lbm/pore: N fluid steps in T s: fluid A s (of which mapping, refill, moving walls and
    force B s since the lattice was built), lubrication C s, diagnostics D s, DEM and the
    rest E s; S s per fluid step
Each pair gives a ratio B / A; printed are the median and the spread of the pairs.
Prints BENCH lines (per fluid step, i.e. per N_DEM DEM steps; medians over the pairs):
  pure_fluid_step_s (A), coupled_step_s (B), coupled_fluid_s (collide-stream, boundaries,
  halo), coupled_coupling_s (mapping, refill, moving walls, force, lubrication),
  coupled_dem_s (DEM and the rest, diagnostics), warmup_pure_fluid_step_s (fix lbm/pore's own
  particle-free step in the warm-up), particles, coupled_vs_pure_fluid_min / _max and
  coupled_vs_pure_fluid (the median ratio; goal <= 1.3), and its two parts per pair:
  coupled_dem_vs_pure_fluid (the DEM substeps and diagnostics; the goal needs this below
  0.3) and coupled_fluid_and_coupling_vs_pure_fluid (the rest).

usage: bench_coupled.py --driver liggghts-lbm --pore-fluid pore_fluid
                        --script examples/pore/in.pore_small [--pairs 9] [--chunk 50000] ...
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TIMING = re.compile(
    r"fix lbm/pore: (\d+) fluid steps in ([\d.eE+-]+) s: fluid ([\d.eE+-]+) s \(of which mapping, "
    r"refill, moving walls and force ([\d.eE+-]+) s[^)]*\), lubrication ([\d.eE+-]+) s, diagnostics "
    r"([\d.eE+-]+) s, DEM and the rest ([\d.eE+-]+) s; ([\d.eE+-]+) s per fluid step")
PURE_LATTICE = re.compile(r"pore_fluid: (\d+) x (\d+) x (\d+) lattice")


def pure_step_seconds(path, steps):
    """s per fluid step of one pore_fluid run, from its lattice size and last MLUPS row."""
    with open(path) as f:
        text = f.read()
    dims = PURE_LATTICE.search(text)
    rows = [line.split() for line in text.splitlines() if re.match(r"\s+\d+\s", line)]
    if not dims or not rows or int(rows[-1][0]) != steps:
        sys.exit(f"bench_coupled: pore_fluid did not finish ({path}):\n{text[-1000:]}")
    nodes = int(dims[1]) * int(dims[2]) * int(dims[3])
    return nodes / (float(rows[-1][-1]) * 1e6)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--pore-fluid", required=True)
    parser.add_argument("--script", required=True, help="examples/pore/in.pore_small")
    parser.add_argument("--warmup", type=int, default=200000, help="DEM steps without particles")
    parser.add_argument("--steps", type=int, default=1000000,
                        help="DEM steps with particles before the pairs (builds the load)")
    parser.add_argument("--pairs", type=int, default=9)
    parser.add_argument("--chunk", type=int, default=50000, help="DEM steps of each coupled run")
    parser.add_argument("--pure-steps", type=int, default=500, help="fluid steps of each pure run")
    args = parser.parse_args()
    knobs = {"pore_small": os.path.abspath(args.script),
             "pore_fluid": os.path.abspath(args.pore_fluid), "warmup": args.warmup,
             "steps": args.steps, "vtk_every": 0, "thermo_every": args.chunk, "pairs": args.pairs,
             "chunk": args.chunk, "pure_steps": args.pure_steps,
             # region I topped up every 100 fluid steps: the load (about twice c_in) at which
             # the figures of doc/performance.md were recorded
             "insert_period": 100}
    cmd = [os.path.abspath(args.driver), "-in", os.path.join(HERE, "in.coupled_interleaved")]
    for name, value in knobs.items():
        cmd += ["-var", name, str(value)]
    with tempfile.TemporaryDirectory(prefix="bench_coupled_") as work:
        out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True, errors="replace").stdout
        runs = [list(map(float, r)) for r in TIMING.findall(out)]
        if len(runs) < 2 + args.pairs:
            print(out[-3000:])
            sys.exit("bench_coupled: the runs did not all complete")
        pure = [pure_step_seconds(os.path.join(work, f"pure_{p}.txt"), args.pure_steps)
                for p in range(1, args.pairs + 1)]
    warmup, chunks = runs[0], runs[2:]
    # B (mapping, refill, moving walls, force) is counted since the lattice was built: each
    # chunk's own share is the difference from the run before it.
    coupling_stages = [c[3] - before[3] for before, c in zip(runs[1:], chunks)]
    atoms = [line.split()[1] for line in out.splitlines() if re.match(r"\s+\d+\s+\d+\s", line)]
    per_chunk = {
        "coupled_step_s": [c[7] for c in chunks],
        "coupled_fluid_s": [(c[2] - b) / c[0] for c, b in zip(chunks, coupling_stages)],
        "coupled_coupling_s": [(b + c[4]) / c[0] for c, b in zip(chunks, coupling_stages)],
        "coupled_dem_s": [(c[5] + c[6]) / c[0] for c in chunks],
    }
    ratios = [c[7] / a for c, a in zip(chunks, pure)]
    print("bench_coupled: pair ratios " + " ".join(f"{r:.3f}" for r in ratios))
    print(f"BENCH pure_fluid_step_s {statistics.median(pure):.4g} s")
    for name, values in per_chunk.items():
        print(f"BENCH {name} {statistics.median(values):.4g} s")
    print(f"BENCH warmup_pure_fluid_step_s {warmup[7]:.4g} s")
    print(f"BENCH particles {atoms[-1] if atoms else 'unknown'} count")
    print(f"BENCH coupled_vs_pure_fluid_min {min(ratios):.3f} ratio")
    print(f"BENCH coupled_vs_pure_fluid_max {max(ratios):.3f} ratio")
    print(f"BENCH coupled_vs_pure_fluid {statistics.median(ratios):.3f} ratio")
    # The two parts of the ratio, per pair: the DEM substeps alone (no fluid code in them
    # but the substep load and lubrication; at or above 0.3 the goal cannot be met by any
    # coupling), and the rest, the fluid step with the coupling stages.
    dem = [d / a for d, a in zip(per_chunk["coupled_dem_s"], pure)]
    rest = [(f + c) / a for f, c, a in zip(per_chunk["coupled_fluid_s"], per_chunk["coupled_coupling_s"], pure)]
    print(f"BENCH coupled_dem_vs_pure_fluid {statistics.median(dem):.3f} ratio")
    print(f"BENCH coupled_fluid_and_coupling_vs_pure_fluid {statistics.median(rest):.3f} ratio")


if __name__ == "__main__":
    main()
