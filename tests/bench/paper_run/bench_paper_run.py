#!/usr/bin/env python3
"""bench_paper_run: how long a paper-length run takes at the particle loads the studies have,
timed from saved states of the paper's scene rather than from an empty box.

The scene is examples/pore/in.pore (Table I read in d-units at 7.1 cells per d: a 90 x 40 x 40
lattice, a pore of D = 25 cells, particles of d = 7 cells, N_DEM = 100) on 2 MPI ranks with
one OpenMP thread each, the lattice split across the flow (-var procs "1 * 1": both ranks
hold half of every region). Three states, each made once by running in.pore and kept (with its
fluid checkpoints) in --states-dir, then read back for every timed run:

  steady   u_lattice 0.02, c_in 0.05, the reference pressure removed (in.pore's defaults when
           these states were first made) after 2 x 10^6 DEM steps, with
           region I topped up every 100 time units (insert_period 100, as in.pore did when
           these figures were first recorded: the particles enter at about twice c_in, the
           load of c_in 0.1, the paper's highest): at least 50 particles in the box, deposits
           in the pore, voxel contacts; continued in steps of 10^5 DEM steps until it holds
           that load.
  clogged  u_lattice 0.0025, insert_period 100, the reference pressure removed (where
           deposits grow to 20-40 particles: doc/calibration.md)
           after 4 x 10^6 DEM steps, continued until at least 15 particles are deposited in
           the pore (deposits come and go in bursts: the state is the first such moment).
  paper    in.pore's defaults (the paper's regime: u_lattice 0.0025, the reference pressure
           kept) at the paper's highest concentration, c_in 0.1, after 8 x 10^6 DEM steps,
           continued until the box holds at least 100 particles with at least 15 deposited:
           particles queue upstream of the clogged pore.

A state is remade when its files are missing, when STATES gives it other knobs than it was
made with (state.json), or when the driver cannot read them (a restart format change);
--remake-states forces it. Each timed run resumes a state for
--fluid-steps fluid steps (N_DEM DEM substeps each); the states are timed in turn, --repeat
rounds, and the median and spread (min, max) of the rounds are printed. Per state:

  BENCH paper_run_<state>_particles, _deposited      the state's load (count)
  BENCH paper_run_<state>_fluid_step_ms [_min/_max]  fix lbm/pore's own "s per fluid step"
  BENCH paper_run_<state>_<part>_ms                  per fluid step: the coupling stages
        (mapping, refill, halo, static_walls, moving_walls, force, open_faces, collide_stream)
        and lubrication, diagnostics, dem_and_rest (the DEM substeps and LIGGGHTS's own work)
  BENCH paper_run_<state>_links_per_step            (rank 0)
  BENCH paper_run_<state>_links_busiest_rank_vs_mean, _coupling_busiest_rank_vs_mean  the
        busiest rank's links per step and coupling stages' seconds over the ranks' mean (a
        stage's time includes the waits at collective calls: these say where the work is)
  BENCH paper_run_<state>_ns_per_link                mapping + refill + moving walls + force
  BENCH paper_run_<state>_coupling_fluid_cell_updates_per_link  the same in collide-stream
        updates of the same run (the kernel keeps the boundary nodes' moments for the moving
        walls, FluidSolver::keep_node_moments: its updates include that work)
  BENCH paper_run_<state>_projected_hours [_min/_max]  10^6 fluid steps at this speed
  BENCH paper_run_<state>_projected_hours_n_dem_20     the DEM's share (DEM and the rest,
        lubrication) scaled by 20/100
  BENCH paper_run_<state>_projected_hours_5_cells_per_d[_n_dem_20]  the same physical time
        at 5 cells per d (acoustic scaling, in.pore's header: 10^6 x 5/7.1 fluid steps of
        142 DEM substeps), each part scaled by what it grows with: collide-stream and
        diagnostics by the cells, (5/7.1)^3; the other coupling stages by the links,
        (5/7.1)^2; the DEM per fluid step by the substeps, 7.1/5.
and, for the steady state (50-80 particles, the load of c_in 0.1), the headline figures without the
state's name: BENCH paper_run_projected_hours (goal <= 0.75, stretch 0.5; at the paper state
<= 1.0) and BENCH coupling_fluid_cell_updates_per_link (goal <= 3, stretch 1.5: waLBerla's
fitted workload model charges about 1.5 per link).
On the states of --layouts (default: paper), per round:
  BENCH paper_run_<state>_one_rank_two_threads_vs_two_ranks [_min/_max]  the time per fluid
        step on 1 rank of 2 OpenMP threads over that on 2 ranks of 1 (below 1: one rank is
        faster; the main example's default layout follows the faster)
  BENCH paper_run_<state>_side_by_side_runs_per_hour_vs_one_two_rank_run [_min/_max]  a study's
        throughput: two 1-rank, 1-thread runs of the state started together against one
        2-rank run, in runs per hour (above 1: side by side is faster; run_study.py's default
        follows the faster)
With --baseline-driver, each timed run is paired with one of that driver right before it
on the same state: BENCH paper_run_<state>_vs_baseline [_min/_max] is the median of the
pairs' ratios of the time per fluid step (below 1: --driver is faster). --baseline-knobs
NAME=VALUE,... gives the baseline's runs those in.pore knobs (with --driver itself when no
--baseline-driver is given): two paths of one build, e.g. moving_walls=sweep.
The stage and link figures are rank 0's (the end-of-run report of fix lbm/pore); a stage's
time includes the waits for the other rank at its collective calls.

usage: bench_paper_run.py --driver liggghts-lbm --script examples/pore/in.pore
                          [--states-dir DIR] [--remake-states] [--fluid-steps N] [--repeat N]
                          [--mpirun mpirun] [--states steady,clogged]
                          [--baseline-driver liggghts-lbm] [--baseline-knobs NAME=VALUE,...]
(--repeat 0 makes the missing states and times nothing.)
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

PAPER_STEPS = 1e6
N_DEM = 100
RANKS = 2
PROCS = "1 * 1"
WARMUP = 200000
CHUNK = 100000  # DEM steps between the restart files of a state's making
CELLS_PER_D, COARSE_CELLS_PER_D = 7.1, 5.0

# name -> (knobs, first end step, the load it must reach: (particles, deposited))
STATES = {
    "steady": ({"u_lattice": 0.02, "c_in": 0.05, "insert_period": 100, "reference_pressure": "remove"},
               2000000, (50, 1)),
    "clogged": ({"u_lattice": 0.0025, "c_in": 0.05, "insert_period": 100, "reference_pressure": "remove"},
                4000000, (0, 15)),
    # The paper's regime (in.pore's defaults: u_lattice 0.0025, the reference pressure kept)
    # at the paper's highest concentration, c_in 0.1, late in a run: particles queue upstream
    # of the clogged pore (at c_in 0.05 the box held 70 after 1.4 x 10^7 DEM steps).
    "paper": ({"u_lattice": 0.0025, "reference_pressure": "keep", "c_in": 0.1}, 8000000, (100, 15)),
}
MAX_EXTRA_STEPS = 6000000  # a state that has not reached its load by then is reported as is

RUN_LINE = re.compile(
    r"fix lbm/pore: (\d+) fluid steps in ([\d.eE+-]+) s: fluid ([\d.eE+-]+) s .*?\), lubrication "
    r"([\d.eE+-]+) s, diagnostics ([\d.eE+-]+) s, DEM and the rest ([\d.eE+-]+) s; ([\d.eE+-]+) s per fluid step")
STAGE_LINE = re.compile(r"fix lbm/pore: coupling stages since the lattice was built: (.*)")
LINK_LINE = re.compile(
    r"links of the moving surfaces on this rank: ([\d.]+) per fluid step; mapping, refill, moving "
    r"walls and force ([\d.]+) ns per link, ([\d.]+) fluid-cell updates per link")
BALANCE_LINE = re.compile(
    r"balance over \d+ ranks \(mean, busiest rank\): links per fluid step ([\d.]+), ([\d.]+); mapping, "
    r"refill, moving walls and force ([\d.]+) s, ([\d.]+) s; DEM and the rest ([\d.]+) s, ([\d.]+) s")
STAGES = ["mapping", "refill", "halo", "static walls", "moving walls", "force", "open faces", "collide-stream"]
LINK_STAGES = ["mapping", "refill", "moving walls", "force"]


def thermo_rows(text):
    """(step, atoms, deposited) of the thermo rows (in.pore: step atoms f_pore[1] f_pore[6] f_pore[7] ...)."""
    rows = []
    for line in text.splitlines():
        parts = line.split()
        if len(parts) >= 5 and parts[0].isdigit() and parts[1].isdigit():
            try:
                rows.append((int(parts[0]), int(parts[1]), float(parts[4])))
            except ValueError:
                pass
    return rows


def scene_command(args, knobs, driver=None, ranks=RANKS, bound=True):
    """bound=False for a rank of several threads and for runs side by side: every mpirun binds
    its first ranks to the first cores, whatever the other mpiruns do, so two 1-rank runs
    would share core 0 and a rank's threads its one core."""
    cmd = [args.mpirun, "-np", str(ranks), "--allow-run-as-root", "--oversubscribe"]
    cmd += [] if bound else ["--bind-to", "none"]
    cmd += [os.path.abspath(driver or args.driver), "-in", os.path.abspath(args.script)]
    for name, value in knobs.items():
        cmd += ["-var", name, str(value)]
    return cmd


def run_scene(args, work, knobs, driver=None, ranks=RANKS, threads=1):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    done = subprocess.run(scene_command(args, knobs, driver, ranks, bound=threads == 1), cwd=work, env=env,
                          capture_output=True, text=True, errors="replace")
    return done.returncode, done.stdout + done.stderr


def scene_knobs(state, end_step, extra):
    knobs = dict(STATES[state][0], cells_per_d=CELLS_PER_D, n_dem=N_DEM, vtk_every=0, procs=PROCS,
                 warmup=WARMUP, steps=end_step - WARMUP)
    knobs.update(extra)
    return knobs


def newest_restart(folder):
    files = [f for f in ("restart.a", "restart.b") if os.path.exists(os.path.join(folder, f))]
    return max(files, key=lambda f: os.path.getmtime(os.path.join(folder, f))) if files else None


def state_load(folder):
    """(step, particles, deposited) at the state's last thermo row, from its saved log."""
    with open(os.path.join(folder, "state.log")) as f:
        rows = thermo_rows(f.read())
    return rows[-1] if rows else None


def state_is_current(state, folder):
    """Whether `folder` holds the state as STATES defines it now: made to the end (its log
    kept) with the knobs STATES gives it (state.json)."""
    try:
        with open(os.path.join(folder, "state.json")) as f:
            knobs = json.load(f)
    except (OSError, ValueError):
        return False
    return os.path.exists(os.path.join(folder, "state.log")) and knobs == STATES[state][0]


def make_state(args, state, folder):
    """Runs in.pore until the state holds its load; keeps the newest restart file and the
    fluid checkpoints it names in `folder`."""
    knobs, end_step, (min_particles, min_deposited) = STATES[state]
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    extra = {"restart_every": CHUNK, "checkpoint_keep": 2, "thermo_every": CHUNK}
    print(f"bench_paper_run: making state '{state}' ({knobs}) to DEM step {end_step} in {folder}", flush=True)
    code, out = run_scene(args, folder, scene_knobs(state, end_step, extra))
    log = out
    last = end_step + MAX_EXTRA_STEPS
    while True:
        rows = thermo_rows(out)
        if code != 0 or not rows:
            print(out[-3000:])
            sys.exit(f"bench_paper_run: making state '{state}' failed")
        step, particles, deposited = rows[-1]
        if (particles >= min_particles and deposited >= min_deposited) or step >= last:
            break
        end_step = step + CHUNK
        resume = dict(extra, resume=1, resume_file=newest_restart(folder))
        code, out = run_scene(args, folder, scene_knobs(state, end_step, resume))
        log += out
    with open(os.path.join(folder, "state.log"), "w") as f:
        f.write(log)
    with open(os.path.join(folder, "state.json"), "w") as f:
        json.dump(knobs, f)
    print(f"bench_paper_run: state '{state}' at DEM step {step}: {particles} particles, "
          f"{deposited:g} deposited", flush=True)


def resume_knobs(args, state, folder, work, layout=None):
    """Links the state's files into `work`; the knobs that resume it for --fluid-steps."""
    step, _, _ = state_load(folder)
    restart = newest_restart(folder)
    for name in os.listdir(folder):
        if name.startswith("pore.fluid.") or name == restart:
            os.symlink(os.path.join(folder, name), os.path.join(work, name))
    steps = args.fluid_steps * N_DEM
    extra = {"resume": 1, "resume_file": restart, "thermo_every": steps}
    if layout:
        extra["procs"] = layout
    return scene_knobs(state, step + steps, extra)


def time_state(args, state, folder, driver=None, ranks=RANKS, threads=1, extra=None):
    """One timed run resuming the state (with `driver`, or --driver) on `ranks` ranks of
    `threads` threads (the fluid checkpoint is read on any decomposition), with the in.pore
    knobs `extra` on top: fix lbm/pore's report, parsed."""
    with tempfile.TemporaryDirectory(prefix="bench_paper_run_") as work:
        knobs = resume_knobs(args, state, folder, work, None if ranks == RANKS else "1 1 1")
        knobs.update(extra or {})
        code, out = run_scene(args, work, knobs, driver, ranks, threads)
    runs = RUN_LINE.findall(out)
    stages = STAGE_LINE.findall(out)
    links = LINK_LINE.findall(out)
    if code != 0 or not runs or not stages:
        print(out[-3000:])
        return None
    n, total, _, lubrication, diagnostics, dem, per_step = (float(v) for v in runs[-1])
    times = {name: float(value) for name, value in
             re.findall(r"([a-z -]+?) ([\d.eE+-]+) s", stages[-1])}
    times = {name.strip(): value for name, value in times.items()}
    result = {"fluid_step_ms": 1e3 * per_step, "lubrication": lubrication / n,
              "diagnostics": diagnostics / n, "dem_and_rest": dem / n}
    for name in STAGES:
        result[name] = times.get(name, 0.0) / n
    # A driver older than the link report (a before/after comparison) gives no link figures.
    result["links"], result["ns_per_link"], result["fcu_per_link"] = (
        (float(v) for v in links[-1]) if links else (float("nan"),) * 3)
    # The busiest rank against the mean (RunTimer::balance_report; nan from an older driver).
    balance = BALANCE_LINE.findall(out)
    b = [float(v) for v in balance[-1]] if balance else [float("nan")] * 6
    result["links_busiest_vs_mean"] = b[1] / b[0] if b[0] else float("nan")
    result["coupling_busiest_vs_mean"] = b[3] / b[2] if b[2] else float("nan")
    rows = thermo_rows(out)
    result["particles"], result["deposited"] = (rows[-1][1], rows[-1][2]) if rows else (0, 0)
    return result


def side_by_side_seconds(args, state, folder):
    """Wall-clock seconds of two one-rank, one-thread runs of the state started together (a
    study's independent runs sharing the machine's cores)."""
    works = [tempfile.mkdtemp(prefix="bench_paper_run_") for _ in range(2)]
    try:
        env = dict(os.environ, OMP_NUM_THREADS="1")
        start = time.monotonic()
        runs = [subprocess.Popen(scene_command(args, resume_knobs(args, state, folder, w, "1 1 1"), ranks=1,
                                               bound=False),
                                 cwd=w, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                for w in works]
        codes = [r.wait() for r in runs]
        elapsed = time.monotonic() - start
    finally:
        for w in works:
            shutil.rmtree(w, ignore_errors=True)
    return elapsed if all(c == 0 for c in codes) else None


def one_run_seconds(args, state, folder):
    """Wall-clock seconds of one run of the state on RANKS ranks, one thread each."""
    with tempfile.TemporaryDirectory(prefix="bench_paper_run_") as work:
        knobs = resume_knobs(args, state, folder, work)
        start = time.monotonic()
        code, _ = run_scene(args, work, knobs)
        return time.monotonic() - start if code == 0 else None


def projections(parts, fluid_step_s):
    """Hours for the paper's run length at 7.1 and 5 cells per d, N_DEM 100 and 20 (see the
    module's docstring for the scaling of each part)."""
    r = COARSE_CELLS_PER_D / CELLS_PER_D
    dem = parts["dem_and_rest"] + parts["lubrication"]
    cells = parts["collide-stream"] + parts["diagnostics"]
    surface = fluid_step_s - dem - cells
    hours = lambda per_step, steps: per_step * steps / 3600
    return {
        "": hours(fluid_step_s, PAPER_STEPS),
        "_n_dem_20": hours(fluid_step_s - dem * (1 - 20 / N_DEM), PAPER_STEPS),
        "_5_cells_per_d": hours(cells * r**3 + surface * r**2 + dem / r, PAPER_STEPS * r),
        "_5_cells_per_d_n_dem_20": hours(cells * r**3 + surface * r**2 + dem / r * 20 / N_DEM,
                                         PAPER_STEPS * r),
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--script", required=True)
    parser.add_argument("--mpirun", default="mpirun")
    parser.add_argument("--states-dir", default=os.path.join(os.getcwd(), "paper_run_states"))
    parser.add_argument("--states", default="steady,clogged,paper")
    parser.add_argument("--remake-states", action="store_true")
    parser.add_argument("--fluid-steps", type=int, default=1000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--layouts", default="paper",
                        help="states on which 1 rank of 2 threads is paired with 2 ranks of 1 thread, "
                             "and a study's throughput (two 1-rank runs side by side against one "
                             "2-rank run) measured; '' for none")
    parser.add_argument("--baseline-driver", default="",
                        help="another liggghts-lbm (e.g. a build of the code before a change), "
                             "timed on the same states in pairs with --driver")
    parser.add_argument("--baseline-knobs", default="", metavar="NAME=VALUE,...",
                        help="in.pore knobs of the baseline's runs (with --baseline-driver, or "
                             "--driver itself): e.g. moving_walls=sweep pairs two paths of one build")
    args = parser.parse_args()
    try:
        baseline_knobs = dict(kv.split("=", 1) for kv in args.baseline_knobs.split(",") if kv)
    except ValueError:
        sys.exit(f"bench_paper_run: --baseline-knobs '{args.baseline_knobs}': must be NAME=VALUE,...")
    paired = bool(args.baseline_driver or baseline_knobs)
    states = [s for s in args.states.split(",") if s]
    for state in states:
        if state not in STATES:
            sys.exit(f"bench_paper_run: unknown state '{state}'; known: {', '.join(STATES)}")
    folders = {s: os.path.join(os.path.abspath(args.states_dir), s) for s in states}
    for state, folder in folders.items():
        if args.remake_states or not state_is_current(state, folder):
            make_state(args, state, folder)
    if args.repeat <= 0:  # --repeat 0: make the states only
        return
    results = {s: [] for s in states}
    pair_ratios = {s: [] for s in states}
    layouts = [s for s in args.layouts.split(",") if s in states]
    layout_ratios = {s: [] for s in layouts}
    throughput_ratios = {s: [] for s in layouts}
    for round_ in range(args.repeat):
        for state in states:
            if paired:
                # Right before the run it is paired with: a load swing falls on both.
                base = time_state(args, state, folders[state], args.baseline_driver or None,
                                  extra=baseline_knobs)
                if base is None:
                    sys.exit(f"bench_paper_run: the baseline's timed run of state '{state}' failed")
            result = time_state(args, state, folders[state])
            if result is None:  # unreadable by this driver (a format change): made again once
                make_state(args, state, folders[state])
                result = time_state(args, state, folders[state])
            if result is None:
                sys.exit(f"bench_paper_run: the timed run of state '{state}' failed")
            results[state].append(result)
            if paired:
                pair_ratios[state].append(result["fluid_step_ms"] / base["fluid_step_ms"])
                print(f"bench_paper_run: round {round_ + 1}, state {state}, baseline: "
                      f"{base['fluid_step_ms']:.3f} ms per fluid step", flush=True)
            if state in layouts:
                threaded = time_state(args, state, folders[state], ranks=1, threads=2)
                if threaded is not None:
                    layout_ratios[state].append(threaded["fluid_step_ms"] / result["fluid_step_ms"])
                one, pair = one_run_seconds(args, state, folders[state]), side_by_side_seconds(args, state, folders[state])
                if one and pair:
                    # Runs per hour: 2 per `pair` side by side against 1 per `one`.
                    throughput_ratios[state].append(2.0 * one / pair)
                print(f"bench_paper_run: round {round_ + 1}, state {state}: 1 rank x 2 threads "
                      f"{threaded['fluid_step_ms'] if threaded else float('nan'):.3f} ms per fluid step; "
                      f"one 2-rank run {one or float('nan'):.1f} s, two 1-rank runs side by side "
                      f"{pair or float('nan'):.1f} s", flush=True)
            print(f"bench_paper_run: round {round_ + 1}, state {state}: {result['fluid_step_ms']:.3f} ms "
                  f"per fluid step, {result['links']:.0f} links, {result['particles']} particles, "
                  f"{result['deposited']:g} deposited", flush=True)
    for state in states:
        runs = results[state]
        median = lambda key: statistics.median(r[key] for r in runs)
        step_ms = sorted(r["fluid_step_ms"] for r in runs)
        particles, deposited = runs[-1]["particles"], runs[-1]["deposited"]
        name = f"paper_run_{state}"
        print(f"BENCH {name}_particles {particles} count")
        print(f"BENCH {name}_deposited {deposited:g} count")
        print(f"BENCH {name}_fluid_step_ms {statistics.median(step_ms):.3f} ms")
        print(f"BENCH {name}_fluid_step_ms_min {step_ms[0]:.3f} ms")
        print(f"BENCH {name}_fluid_step_ms_max {step_ms[-1]:.3f} ms")
        parts = {key: median(key) for key in STAGES + ["lubrication", "diagnostics", "dem_and_rest"]}
        for key, value in parts.items():
            print(f"BENCH {name}_{key.replace(' ', '_').replace('-', '_')}_ms {1e3 * value:.3f} ms")
        print(f"BENCH {name}_links_per_step {median('links'):.0f} count")
        print(f"BENCH {name}_ns_per_link {median('ns_per_link'):.1f} ns")
        print(f"BENCH {name}_links_busiest_rank_vs_mean {median('links_busiest_vs_mean'):.3f} ratio")
        print(f"BENCH {name}_coupling_busiest_rank_vs_mean {median('coupling_busiest_vs_mean'):.3f} ratio")
        fcu = median("fcu_per_link")
        print(f"BENCH {name}_coupling_fluid_cell_updates_per_link {fcu:.2f} ratio")
        # The parts are medians of their own; the projections scale the median step by them.
        step_s = statistics.median(step_ms) / 1e3
        for suffix, hours in projections(parts, step_s).items():
            print(f"BENCH {name}_projected_hours{suffix} {hours:.3f} hours")
        print(f"BENCH {name}_projected_hours_min {step_ms[0] / 1e3 * PAPER_STEPS / 3600:.3f} hours")
        print(f"BENCH {name}_projected_hours_max {step_ms[-1] / 1e3 * PAPER_STEPS / 3600:.3f} hours")
        if pair_ratios[state]:
            ratios = sorted(pair_ratios[state])
            print(f"BENCH {name}_vs_baseline {statistics.median(ratios):.3f} ratio")
            print(f"BENCH {name}_vs_baseline_min {ratios[0]:.3f} ratio")
            print(f"BENCH {name}_vs_baseline_max {ratios[-1]:.3f} ratio")
        if layout_ratios.get(state):
            r = sorted(layout_ratios[state])
            print(f"BENCH {name}_one_rank_two_threads_vs_two_ranks {statistics.median(r):.3f} ratio")
            print(f"BENCH {name}_one_rank_two_threads_vs_two_ranks_min {r[0]:.3f} ratio")
            print(f"BENCH {name}_one_rank_two_threads_vs_two_ranks_max {r[-1]:.3f} ratio")
        if throughput_ratios.get(state):
            r = sorted(throughput_ratios[state])
            print(f"BENCH {name}_side_by_side_runs_per_hour_vs_one_two_rank_run {statistics.median(r):.3f} ratio")
            print(f"BENCH {name}_side_by_side_runs_per_hour_vs_one_two_rank_run_min {r[0]:.3f} ratio")
            print(f"BENCH {name}_side_by_side_runs_per_hour_vs_one_two_rank_run_max {r[-1]:.3f} ratio")
        if state == "steady":
            print(f"BENCH paper_run_projected_hours {step_s * PAPER_STEPS / 3600:.3f} hours")
            print(f"BENCH coupling_fluid_cell_updates_per_link {fcu:.2f} ratio")


if __name__ == "__main__":
    main()
