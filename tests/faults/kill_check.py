#!/usr/bin/env python3
"""A killed run loses nothing, an error stays the last line, nothing is lost in a long run.
Runs liggghts-lbm on tests/faults/in.kill* (the coupled tests'
pore scene with four particles moving into the pore) and in.bookkeeping; prints every
figure with its bound (tests/harness/liggghts_run.py).

  sigterm_resume          2 ranks, SIGTERM to each rank at a random moment (seeded:
                          LBM_PORE_KILL_SEED=<n> repeats a draw; the seed, the delays and the
                          step it stopped at are printed). LIGGGHTS writes its forced restart
                          (with the fluid checkpoint) at the next fluid step and quits; the
                          resumed run must equal the same run split into two `run` commands
                          bit for bit, and the uninterrupted run within RESUME_BOUNDS.
  kill_during_checkpoint  `restart 4000 a b` (alternating files), kill -9 while the third
                          checkpoint is being written (LBM_PORE_TEST_SLOW_WRITE holds each
                          write open): the file being rewritten is lost, the other restart and
                          the checkpoint it names are intact, and a resume from them matches.
  rank_error_last         2 ranks, an error on rank 1 only, during a run (Error::one) and at a
                          resume (a fluid checkpoint missing on one rank): the last non-empty
                          line of the combined output is the project's ERROR line.
  bookkeeping             10^4 fluid steps of a clogging run: particles inserted = present +
                          removed at the outlet + lost, lost = 0; fluid mass in - out = change
                          of the mass held (+ the mass the particles displace).

usage: kill_check.py --driver liggghts-lbm --scripts tests/faults [--mpirun mpirun] CASE
"""
import glob
import math
import os
import random
import signal
import subprocess
import sys
import time

from liggghts_run import check, main, mpi_environment, relative_difference, thermo_rows

N_DEM = 100        # in.kill's fluid step: a forced restart comes at a multiple of it
KILL_STEPS = 60000
# Columns of in.kill_run compared with the uninterrupted run, with their bounds (relative):
# the fix's pressure loss and the particle positions within the existing restart test's
# 1e-6 (tests/coupled_runs, case restart), the total hydrodynamic force along x within its
# 1e-3 (a sum of large contributions of both signs); the outlet flux and the velocities,
# which that test does not compare, within 1e-5. Measured: up to 4e-7 (velocities, flux),
# 7e-5 (force). A resumed run is bit-identical to the same script split into two `run`
# commands in one process (checked too); what separates both from one uninterrupted run is
# the second run's setup: LIGGGHTS recomputes the forces there at the end-of-step velocity,
# where the uninterrupted run carries the forces of the half-step velocity into the next
# step (it matters for the velocity-dependent damping and the fluid's load F - C (v - v_step)).
RESUME_BOUNDS = {"pore[1]": 1e-6, "pore[3]": 1e-5, "pore[14]": 1e-3, "x1": 1e-6, "vx1": 1e-5,
                 "z2": 1e-6, "vz2": 1e-5, "x3": 1e-6, "vy4": 1e-5}
KILL_COLUMNS = tuple(RESUME_BOUNDS)


def kill_variables(steps, **extra):
    return dict({"steps": steps}, **extra)


def final_row(output):
    rows = thermo_rows(output)
    return rows[-1] if rows else {}


def compare_rows(name, reference, resumed, bounds=None):
    """Final rows column by column: bit-identical without `bounds`, else within them."""
    check(f"{name}_same_final_step", reference.get("Step") == resumed.get("Step"),
          resumed.get("Step"), f"== {reference.get('Step')}")
    for column in KILL_COLUMNS:
        bound = bounds[column] if bounds else 0
        diff = relative_difference(reference[column], resumed[column])
        check(f"{name}_relative_difference_{column}", diff <= bound, f"{diff:.3g}",
              "== 0 (bit-identical)" if bound == 0 else f"<= {bound:g}")


def start(h, script, variables, ranks, work, env=None):
    """Starts liggghts-lbm in the background (output to work/out.txt); returns the Popen."""
    cmd = [h.driver, "-in", os.path.join(h.scripts, script), "-log", os.path.join(work, "log.liggghts"),
           "-var", "dir", h.scripts]
    for name, value in variables.items():
        cmd += ["-var", name, str(value)]
    if ranks > 1:
        cmd = [h.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
    print("start:", " ".join(cmd[cmd.index("-in") + 1:]), flush=True)
    out = open(os.path.join(work, "out.txt"), "w")
    return subprocess.Popen(cmd, cwd=work, stdout=out, stderr=subprocess.STDOUT,
                            env=mpi_environment(env), start_new_session=True)


def children(pid):
    """The processes whose parent is `pid` (the ranks mpirun started)."""
    try:
        with open(f"/proc/{pid}/task/{pid}/children") as f:
            return [int(p) for p in f.read().split()]
    except OSError:
        return []


def latest_row(log):
    """The step of the last thermo row in a run's screen output so far (-1 before the first)."""
    if not os.path.exists(log):
        return -1
    with open(log, errors="replace") as f:
        rows = [line.split() for line in f if line[:1] == " " and line.split()[:1] != []]
    steps = [int(r[0]) for r in rows if r[0].isdigit() and len(r) > 5]
    return steps[-1] if steps else -1


def wait_for(predicate, timeout, what):
    deadline = time.time() + timeout
    while time.time() < deadline:
        if predicate():
            return True
        time.sleep(0.01)
    print(f"INFO gave up waiting for {what} after {timeout} s", flush=True)
    return False


def case_sigterm_resume(h):
    seed = int(os.environ.get("LBM_PORE_KILL_SEED", random.SystemRandom().randrange(1 << 30)))
    draw = random.Random(seed)
    whole = h.run("in.kill", kill_variables(KILL_STEPS), ranks=2)
    reference = final_row(whole.output)
    # A random moment between 5 % and 80 % of the run, found by the run's progress (its thermo
    # rows, every 1000 steps) plus up to 50 ms, not by a time measured in another run: on a
    # shared machine the run's speed changes (a delay drawn from the reference run's loop time
    # once fell after the end of a faster run). Rank 1 up to 20 ms later: a batch system
    # signals the ranks of a job one after another, and ranks a step apart must still agree.
    row = 1000 * draw.randint(KILL_STEPS // 20000, (KILL_STEPS * 4) // 5000)
    delay = draw.uniform(0.0, 0.05)
    stagger = draw.uniform(0.0, 0.02)
    print(f"INFO seed {seed} (LBM_PORE_KILL_SEED={seed} repeats it): SIGTERM to rank 0 {delay * 1000:.1f} ms "
          f"after the row of step {row}, to rank 1 {stagger * 1000:.1f} ms later", flush=True)
    work = os.path.join(h.work, "interrupted")
    os.makedirs(work)
    run = start(h, "in.kill", kill_variables(KILL_STEPS), 2, work)
    # The screen, not log.liggghts: the driver line-buffers stdout, the log is block-buffered
    # (its rows appear thousands of steps late).
    screen = os.path.join(work, "out.txt")
    header_seen = wait_for(lambda: latest_row(screen) >= row, 300, f"the row of step {row}")
    time.sleep(delay)
    ranks = children(run.pid)
    for i, pid in enumerate(ranks):
        if i:
            time.sleep(stagger)
        os.kill(pid, signal.SIGTERM)
    code = run.wait(timeout=120)
    output = open(os.path.join(work, "out.txt")).read()
    forced = sorted(glob.glob(os.path.join(work, "restart_forced_liggghts_*.data")))
    stopped = int(forced[0].rsplit("_", 1)[1].split(".")[0]) if forced else -1
    print(f"INFO stopped at step {stopped}", flush=True)
    check("sigterm_two_ranks_signalled", header_seen and len(ranks) == 2, len(ranks), "2 ranks, signalled in the run")
    check("sigterm_clean_exit", code == 0 and "ERROR" not in output, code, "exit 0, no ERROR")
    check("sigterm_caught_by_liggghts", "SIGINT/SIGTERM caught" in output, "SIGINT/SIGTERM caught" in output,
          "LIGGGHTS's handler message present")
    check("sigterm_one_forced_restart", len(forced) == 1, len(forced), "== 1 restart_forced_liggghts_<step>.data")
    check("sigterm_stopped_at_a_fluid_step", stopped > 0 and stopped % N_DEM == 0 and stopped < KILL_STEPS,
          stopped, f"a multiple of n_dem = {N_DEM} below {KILL_STEPS}")
    checkpoints = [os.path.join(work, f"pore.fluid.{stopped}.{r}") for r in (0, 1)]
    check("sigterm_fluid_checkpoint_written", all(os.path.exists(p) for p in checkpoints),
          [os.path.basename(p) for p in checkpoints if os.path.exists(p)], "pore.fluid.<step>.0 and .1")
    if stopped <= 0:
        return
    resumed = h.run("in.kill_resume", kill_variables(KILL_STEPS, resume=os.path.basename(forced[0])),
                    ranks=2, cwd=work)
    split = h.run("in.kill", kill_variables(KILL_STEPS, first_run=f"run {stopped} upto"), ranks=2)
    compare_rows("sigterm_resume_vs_split_run", final_row(split.output), final_row(resumed.output))
    compare_rows("sigterm_resume_vs_uninterrupted", reference, final_row(resumed.output), RESUME_BOUNDS)


def case_kill_during_checkpoint(h):
    steps, every = 20000, 4000
    whole = final_row(h.run("in.kill", kill_variables(steps)).output)
    work = os.path.join(h.work, "killed")
    os.makedirs(work)
    # Each checkpoint write pauses 1.5 s after its header: the third (step 12000, into
    # restart file a) is killed in that pause, with a's new content not written yet.
    run = start(h, "in.kill", kill_variables(steps, restart=f"restart {every} a.restart b.restart"), 1, work,
                env={"LBM_PORE_TEST_SLOW_WRITE": "1.5"})
    partial = os.path.join(work, "pore.fluid.12000.0.partial")
    in_write = wait_for(lambda: os.path.exists(partial), 120, partial)
    time.sleep(0.3)
    run.send_signal(signal.SIGKILL)
    run.wait(timeout=30)
    files = sorted(os.listdir(work))
    print("INFO files after the kill:", files, flush=True)
    check("kill_during_checkpoint_killed_while_writing", in_write and run.returncode == -signal.SIGKILL,
          run.returncode, "-9 while pore.fluid.12000.0.partial exists")
    sizes = {f: os.path.getsize(os.path.join(work, f)) for f in ("a.restart", "b.restart") if f in files}
    check("kill_during_checkpoint_file_being_rewritten_is_lost",
          sizes.get("a.restart", 0) < sizes.get("b.restart", 0), sizes,
          "a.restart (opened for step 12000) shorter than b.restart: LIGGGHTS writes restart files in place")
    check("kill_during_checkpoint_new_checkpoint_not_published", "pore.fluid.12000.0" not in files,
          "pore.fluid.12000.0" in files, "only its .partial exists (written to a temporary name, then renamed)")
    check("kill_during_checkpoint_previous_pair_intact", "pore.fluid.8000.0" in files and "b.restart" in files,
          [f for f in files if f.startswith("pore.fluid.8000") or f == "b.restart"],
          "b.restart (step 8000) and the checkpoint it names, pore.fluid.8000.0")
    resumed = final_row(h.run("in.kill_resume", kill_variables(steps, resume="b.restart"), cwd=work).output)
    split = final_row(h.run("in.kill", kill_variables(steps, first_run="run 8000 upto")).output)
    compare_rows("kill_during_checkpoint_resume_vs_split_run", split, resumed)
    compare_rows("kill_during_checkpoint_resume_vs_uninterrupted", whole, resumed, RESUME_BOUNDS)


def last_line(text):
    lines = [l for l in text.splitlines() if l.strip()]
    return lines[-1] if lines else ""


def case_rank_error_last(h):
    """Error::one on rank 1 during a run: its fluid checkpoint cannot be renamed (a folder of
    that name is in the way). Then error->all after all ranks agree: a resume with rank 1's
    checkpoint file missing (it used to hang: rank 1 alone called error->all). Both under
    `mpirun -q`, which silences mpirun's own notices on a non-zero exit (the one part of the
    noise only mpirun's command line or environment can change); the driver silences Open
    MPI's abort notice itself (first run, also checked without -q)."""
    work = os.path.join(h.work, "one_rank")
    os.makedirs(os.path.join(work, "pore.fluid.2000.1"))
    for quiet in (False, True):
        mpirun = [h.mpirun, "--allow-run-as-root", "--oversubscribe"] + (["-q"] if quiet else [])
        run = subprocess.run(mpirun + ["-np", "2", h.driver, "-in", os.path.join(h.scripts, "in.kill"),
                                       "-var", "dir", h.scripts, "-var", "steps", "3000",
                                       "-var", "restart", "restart 2000 r.*"],
                             cwd=work, capture_output=True, text=True, errors="replace", timeout=120)
        line = last_line(run.stdout + run.stderr)
        name = "rank_error_last_error_one" + ("_mpirun_q" if quiet else "")
        check(name, run.returncode != 0 and line.startswith("ERROR on proc 1: fluid checkpoint"),
              f"exit {run.returncode}, last line {line[:150]!r}",
              "exit != 0, last line 'ERROR on proc 1: fluid checkpoint ...'")
    # A stop at step 1000 with both checkpoints, then a resume without rank 1's file.
    work = os.path.join(h.work, "missing")
    os.makedirs(work)
    h.run("in.kill", kill_variables(1000, restart="restart 1000 r.*"), ranks=2, cwd=work)
    os.remove(os.path.join(work, "pore.fluid.1000.1"))
    try:
        run = subprocess.run([h.mpirun, "--allow-run-as-root", "--oversubscribe", "-q", "-np", "2", h.driver,
                              "-in", os.path.join(h.scripts, "in.kill_resume"), "-var", "dir", h.scripts,
                              "-var", "steps", "2000", "-var", "resume", "r.1000"],
                             cwd=work, capture_output=True, text=True, errors="replace", timeout=60)
        code, line = run.returncode, last_line(run.stdout + run.stderr)
    except subprocess.TimeoutExpired:
        code, line = "timeout", ""
    check("rank_error_last_missing_checkpoint_on_one_rank",
          code == 1 and line.startswith("ERROR: fix lbm/pore: restart: rank 1: fluid checkpoint"),
          f"exit {code}, last line {line[:150]!r}", "exit 1 within 60 s, last line 'ERROR: ... rank 1: fluid checkpoint ...'")


def case_bookkeeping(h):
    """Particles: LIGGGHTS's insert/pack count (f_insert[1]) = atoms present + removed at the
    outlet + lost. Removed at the outlet = net crossings of the outlet plane (f_pore[5]) minus
    those still beyond it (count(all,outlet)): boundary f drops them where they leave the box
    at x = 30. Lost = what remains: atoms LIGGGHTS dropped elsewhere (it does not stop on lost
    atoms with `thermo_modify lost ignore`), or a crossing the counter missed; must be 0.
    Fluid: mass in (f_pore[19]) - out (f_pore[20]) = change of the mass held (f_pore[21]) +
    the mass the particles displace (f_pore[22]) - what the coupling put into the fluid: the
    moving surfaces' wall terms (f_pore[23]) and the refilled over the covered nodes' density
    beyond rho0 (f_pore[24]). The fluxes are the populations that crossed the open faces, so
    the budget closes to round-off, with and without particles. The surfaces' term is the
    physics of the scene, not a loss: a sphere leaving through the outlet end draws in, at its
    rear, the fluid that fills the space it frees while its front is already outside the
    lattice (0.66 particle volumes per particle removed, measured with ka 2: LIGGGHTS drops it
    up to half a skin past the end), and spheres touching each other or a wall push no fluid
    where they touch (more in a clogging run) (doc/stability.md, "The fluid budget with moving
    particles"). ka 20 makes it a clogging run: up to 5 particles deposit and the pressure
    loss (f_pore[1]) rises to 0.13 (0.03 at the end of the same run with ka 2)."""
    steps = 100000  # 10^4 fluid steps at n_dem 10
    clean = thermo_rows(h.run("in.bookkeeping", {"steps": 50000, "insert_start": 10 ** 9}).output)
    first, last = clean[0], clean[-1]
    through = last["pore[19]"]
    defect = last["pore[19]"] - last["pore[20]"] - (last["pore[21]"] - first["pore[21]"])
    check("bookkeeping_fluid_mass_without_particles", abs(defect) < 1e-9 * through,
          f"{abs(defect) / through:.3g}", f"|in - out - change of held| < 1e-9 of the mass in ({through:.6g})")
    rows = thermo_rows(h.run("in.bookkeeping", {"steps": steps, "ka": 20}).output)
    last = rows[-1]
    check("bookkeeping_ran_10000_fluid_steps", last["Step"] == steps, last["Step"], f"== {steps}")
    lost = [r["inserted"] - r["Atoms"] - (r["pore[5]"] - r["beyond"]) for r in rows]
    removed = last["pore[5]"] - last["beyond"]
    deposit = max(r["pore[7]"] for r in rows)
    print(f"INFO inserted {last['inserted']:.0f}, present {last['Atoms']:.0f}, removed at the outlet "
          f"{removed:.0f}, largest deposit {deposit:.0f} particles, largest pressure loss f_pore[1] "
          f"{max(r['pore[1]'] for r in rows):.3g}", flush=True)
    check("bookkeeping_particles_flowed_through", last["inserted"] >= 30 and removed >= 10,
          f"{last['inserted']:.0f} inserted, {removed:.0f} removed", ">= 30 inserted, >= 10 removed at the outlet")
    check("bookkeeping_run_clogs", deposit >= 3, f"{deposit:.0f} deposited at most", ">= 3")
    check("bookkeeping_particles_lost", all(l == 0 for l in lost), max(abs(l) for l in lost),
          "inserted - present - removed at the outlet == 0 at every row")
    volume = 4.0 / 3.0 * math.pi * 2.0 ** 3  # d = 4 cells, rho = 1, dx = 1: mass units
    through = last["pore[19]"]
    surfaces, refill = last["pore[23]"], last["pore[24]"]
    worst = 0.0
    for r in rows:
        booked = r["pore[21]"] - rows[0]["pore[21]"] + r["pore[22]"] - r["pore[23]"] - r["pore[24]"]
        worst = max(worst, abs(r["pore[19]"] - r["pore[20]"] - booked))
    print(f"INFO fluid mass: in {through:.6g}, out {last['pore[20]']:.6g}, held {rows[0]['pore[21]']:.6g} -> "
          f"{last['pore[21]']:.6g}, displaced {last['pore[22]']:.6g}, moving surfaces {surfaces:.6g} "
          f"({-surfaces / volume / max(removed, 1):.3g} particle volumes per particle removed), "
          f"refill {refill:.4g}; largest defect {worst:.3g}", flush=True)
    check("bookkeeping_fluid_mass_with_particles", worst < 1e-9 * through, f"{worst / through:.3g}",
          f"|in - out - (change of held + displaced - surfaces - refill)| < 1e-9 of the mass in "
          f"({through:.6g}) at every row")
    # The surfaces' term is of the size of the particle volume that left through the outlet
    # end and of the contacts (measured 1.1 particle volumes per particle removed), not zero
    # and not of another order.
    check("bookkeeping_surface_mass_is_exits_and_contacts",
          0.3 * volume * removed < -surfaces < 2.0 * volume * removed,
          f"{-surfaces / volume / max(removed, 1):.3g}", "between 0.3 and 2 particle volumes per particle removed")


if __name__ == "__main__":
    main({"sigterm_resume": case_sigterm_resume, "kill_during_checkpoint": case_kill_during_checkpoint,
          "rank_error_last": case_rank_error_last, "bookkeeping": case_bookkeeping}, __doc__)
