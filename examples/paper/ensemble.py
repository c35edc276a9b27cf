"""Runs an ensemble of in.pore runs through examples/paper/in.study, each in its own folder
(<study>/runs/<name>/: log.liggghts, bursts.txt, VTK files, stdout.txt), and reads back which
finished, which failed and why.

Two ways to launch, both through LIGGGHTS's multi-partition script in.study:

  partitions  `mpirun -np P*K liggghts-lbm -partition PxK -in in.study`, one run per
              partition (its index from a uloop variable), batch after batch (in.study says
              why not a queue per partition). LIGGGHTS 3.8 stops the whole universe when any
              partition hits an ERROR (Error::all calls MPI_Abort on MPI_COMM_WORLD with more
              than one partition; verified here), so the runs that were under way die with it.
              A run that failed is recorded with its ERROR line and not retried; the runs the
              abort cut short are launched again, until none is left. What that costs: each
              abort restarts the runs it cut short from their beginning. The right mode for a
              cluster allocation (one mpirun, Slurm sees one job step) when failures are rare.
  pool        one mpirun per run (the same in.study, one partition), P of them at a time:
              a failing run stops only itself. The right mode on a laptop, and wherever runs
              are long and failures not rare.

A run's state comes from its own log: `STUDY_RUN_DONE` (printed by in.study after the scene
returned) means finished; an `ERROR` line means failed, with that line as the reason; neither
means cut short (killed, timed out, or taken down by another partition's abort).
"""
import concurrent.futures
import json
import os
import re
import shutil
import signal
import subprocess
import threading
import time

import run_cost

HERE = os.path.dirname(os.path.abspath(__file__))
STUDY_SCRIPT = os.path.join(HERE, "in.study")
SCENE_SCRIPT = os.path.join(os.path.dirname(HERE), "pore", "in.pore")
DONE_MARK = "STUDY_RUN_DONE"


def _liggghts_string(value):
    text = str(value)
    if '"' in text:
        raise ValueError(f"knob value {text!r} may not contain a double quote")
    return f'"{text}"'


def scene_knobs(scene):
    """The knobs of a scene script: its `variable <name> index <default>` lines."""
    with open(scene) as f:
        return [m.group(1) for m in (re.match(r"variable\s+(\w+)\s+index\s", line) for line in f)
                if m]


def unknown_knobs(scene, knobs):
    """The knobs the scene script does not define: LIGGGHTS would take them and run without
    them (a study begun before a knob existed keeps the scene it copied then), so a run would
    silently repeat another."""
    defined = set(scene_knobs(scene))
    return sorted(k for k in knobs if k not in defined)


def study_scene(study_dir):
    """The study's own copy of the scene script, <study>/in.pore, made at its first launch:
    LIGGGHTS reads a script line by line while it runs, so a run would read a scene edited
    in the repository meanwhile half old and half new; the copy also records what ran."""
    copy = os.path.join(study_dir, "in.pore")
    if not os.path.exists(copy):
        shutil.copyfile(SCENE_SCRIPT, copy)
    return copy


def write_run_file(launch_dir, index, run_dir, knobs, scene):
    """<launch_dir>/<index>.in: the run's folder, its scene and its knobs for in.study.
    It first deletes every knob of the scene: `clear` keeps variables, so a partition's
    earlier run would otherwise leave its values (or the scene's index defaults, which a
    string of the same name may not redefine) to the next run."""
    lines = [f"variable {name} delete" for name in scene_knobs(scene)]
    lines += [f"variable run_dir string {_liggghts_string(run_dir)}",
              f"variable scene string {_liggghts_string(scene)}"]
    lines += [f"variable {k} string {_liggghts_string(v)}" for k, v in sorted(knobs.items())]
    with open(os.path.join(launch_dir, f"{index}.in"), "w") as f:
        f.write("\n".join(lines) + "\n")


START_MARK = "STUDY_RUN_START"
# The restart files in.pore writes in turn (restart_every), and the one LIGGGHTS writes when a
# run is stopped by SIGTERM or SIGINT (fix lbm/pore's signal handling).
RESTART_PATTERN = re.compile(r"^(restart\.[ab]|restart_forced_liggghts_\d+\.data)$")


def _last_segment(text):
    """The part of a log written by the latest launch of the run: a resumed run appends to
    its log.liggghts, each launch after a STUDY_RUN_START line of in.study."""
    lines = text.splitlines()
    starts = [i for i, line in enumerate(lines) if line.startswith(START_MARK)]
    return lines[starts[-1]:] if starts else lines


def run_state(run_dir):
    """(state, reason) of a run from the latest launch's part of its log: ('done', ''),
    ('failed', ERROR line) or ('incomplete', why)."""
    log = os.path.join(run_dir, "log.liggghts")
    if not os.path.exists(log):
        return "incomplete", "never started (no log.liggghts)"
    with open(log, errors="replace") as f:
        lines = _last_segment(f.read())
    error = next((line.strip() for line in lines if line.startswith("ERROR")), "")
    # an error on a rank other than the first reaches only the screen, i.e. stdout.txt
    stdout = os.path.join(run_dir, "stdout.txt")
    if not error and os.path.exists(stdout):
        with open(stdout, errors="replace") as f:
            error = next((line.strip() for line in _last_segment(f.read()) if line.startswith("ERROR")), "")
    if error:
        return "failed", error
    if any(line.startswith(DONE_MARK) for line in lines):
        return "done", ""
    return "incomplete", "stopped before the end (killed, timed out or another partition's abort)"


def restart_files(run_dir):
    """The run's restart files, newest first (a kill while one was written leaves it
    unreadable; the one before stays whole)."""
    if not os.path.isdir(run_dir):
        return []
    found = [os.path.join(run_dir, n) for n in os.listdir(run_dir) if RESTART_PATTERN.match(n)]
    return sorted(found, key=os.path.getmtime, reverse=True)


def _knobs_file(run_dir):
    return os.path.join(run_dir, "knobs.json")


# The knobs that say only how often a run saves itself, not what it computes: a run whose
# knobs differ in these alone resumes, and records the new ones, rather than starting anew.
# Writing a restart file changes the trajectory at round-off (replay_window.py measured it),
# as every resume does: a run resumed at another interval is another sample of the same
# physics, as a resumed run always is, not the same bits.
BOOKKEEPING_KNOBS = ("restart_every", "checkpoint_keep")


def _computed(knobs):
    """The knobs as knobs.json records them, less the bookkeeping ones."""
    return {k: str(v) for k, v in knobs.items() if k not in BOOKKEEPING_KNOBS}


def _write_knobs(run_dir, knobs):
    with open(_knobs_file(run_dir), "w") as f:
        json.dump({k: str(v) for k, v in knobs.items()}, f, indent=1, sort_keys=True)


def plan_run(run_dir, knobs, retry_failed=False):
    """What a launch of the study does with one run: ('skip', state) for a finished run (and
    a failed one unless retry_failed), ('resume', restart files newest first) for a run cut
    short that left restart files with the same knobs (BOOKKEEPING_KNOBS aside), else
    ('fresh', why)."""
    if not os.path.isdir(run_dir):
        return "fresh", "new"
    try:
        with open(_knobs_file(run_dir)) as f:
            same = _computed(json.load(f)) == _computed(knobs)
    except (OSError, ValueError):
        same = False
    if not same:
        return "fresh", "its knobs changed (or were never recorded): starts anew"
    state, _ = run_state(run_dir)
    if state == "done" or (state == "failed" and not retry_failed):
        return "skip", state
    files = restart_files(run_dir)
    return ("resume", files) if files and state == "incomplete" else ("fresh", state)


def _clean(run_dir, knobs):
    """A run starts from an empty folder (fix lbm/pore appends to bursts.txt) that records
    its knobs, so that a later launch resumes it only with the same ones."""
    if os.path.isdir(run_dir):
        shutil.rmtree(run_dir)
    os.makedirs(run_dir)
    _write_knobs(run_dir, knobs)


def resume_knobs(knobs, restart_file):
    """The knobs of a launch that continues a run from restart_file (in.pore's resume)."""
    return dict(knobs, resume=1, resume_file=restart_file)


def threads_per_rank(ranks_at_once, cores=None):
    """OpenMP threads for each rank when ranks_at_once ranks share the machine: its cores
    divided among them, at least one. Without it every rank starts one thread per core, and
    two runs side by side on two cores spin-wait on each other's cores (measured: ten times
    slower)."""
    cores = cores or os.cpu_count() or 1
    return max(1, cores // max(1, ranks_at_once))


def set_threads_per_rank(ranks_at_once):
    """Sets OMP_NUM_THREADS for the launches to come, unless the user has set it."""
    if not os.environ.get("OMP_NUM_THREADS"):
        os.environ["OMP_NUM_THREADS"] = str(threads_per_rank(ranks_at_once))
    return int(os.environ["OMP_NUM_THREADS"])


def _mpirun(mpirun, ranks, launches_at_once=1):
    return [mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + \
        binding_options(launches_at_once)


def binding_options(launches_at_once, threads=None):
    """mpirun's binding for one launch. Each mpirun binds its first ranks to the node's first
    cores, whatever the other mpiruns do: two 1-rank launches side by side would share core 0
    while core 1 idles, and a rank's OpenMP threads would share its one core. So a launch binds
    only when it runs alone with one thread per rank; otherwise the kernel places the ranks."""
    threads = threads or int(os.environ.get("OMP_NUM_THREADS") or 1)
    return [] if launches_at_once <= 1 and threads <= 1 else ["--bind-to", "none"]


# The launches under way (each in its own process group), so that a runner asked to stop can
# pass the request on: SIGTERM makes LIGGGHTS write a restart file at the next fluid step and
# quit, from which the next launch of the study resumes.
_RUNNING = set()
_RUNNING_LOCK = threading.Lock()
_STOPPING = threading.Event()  # set by stop_running_launches: no launch starts after it


def stop_running_launches(signum=signal.SIGTERM, wait=60):
    """Sends signum to every launch under way, lets no other start, and waits up to `wait` s
    for them to end."""
    _STOPPING.set()
    with _RUNNING_LOCK:
        running = list(_RUNNING)
    for proc in running:
        try:
            os.killpg(proc.pid, signum)
        except ProcessLookupError:
            pass
    deadline = time.time() + wait
    for proc in running:
        try:
            proc.wait(timeout=max(0.1, deadline - time.time()))
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)


def _execute(cmd, cwd, stdout_path, timeout):
    """Runs cmd in its own process group (so a timeout kills mpirun and its ranks, which
    `timeout mpirun ...` leaves running) and returns its exit code (None: timed out). The
    screen output is appended: a resumed run's launches follow each other in one file.
    Launches nothing (returns None) once the runner is stopping."""
    if _STOPPING.is_set():
        return None
    with open(stdout_path, "a") as out:
        proc = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT,
                                start_new_session=True)
        with _RUNNING_LOCK:
            _RUNNING.add(proc)
        if _STOPPING.is_set():  # the stop came between the check above and the start
            os.killpg(proc.pid, signal.SIGTERM)
        try:
            return proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGTERM)
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
            return None
        finally:
            with _RUNNING_LOCK:
                _RUNNING.discard(proc)


def study_command(driver, launch_dir, nruns, partitions, ranks_per_run, mpirun, launches_at_once=1):
    cmd = [driver]
    if partitions > 1:
        cmd += ["-partition", f"{partitions}x{ranks_per_run}"]
    cmd += ["-in", STUDY_SCRIPT, "-var", "launch", launch_dir, "-var", "nruns", str(nruns),
            "-log", os.path.join(launch_dir, "log.study")]
    if partitions * ranks_per_run > 1 or mpirun:
        cmd = _mpirun(mpirun or "mpirun", partitions * ranks_per_run, launches_at_once) + cmd
    return cmd


def _unreadable_restart(run_dir, launch_knobs):
    """After a launch that resumed from launch_knobs['resume_file']: if it failed reading
    that file (a kill while it was written), the file is renamed out of the way (kept, as
    <name>.unreadable) so that the next plan resumes from the one before. True if it did."""
    restart = launch_knobs.get("resume_file")
    state, reason = run_state(run_dir)
    if not restart or state != "failed" or not re.search(r"restart|checkpoint", reason, re.I):
        return False
    if os.path.exists(restart):
        os.replace(restart, restart + ".unreadable")
    return True


def prepare_launch(run_dir, knobs, retry_failed=False):
    """The knobs of the next launch of a run, after cleaning its folder for a fresh start;
    None when the run is finished (or failed, unless retry_failed)."""
    action, detail = plan_run(run_dir, knobs, retry_failed)
    if action == "skip":
        return None
    if action == "resume":
        for name in ("log.liggghts", "stdout.txt"):  # a killed run may have left half a line
            path = os.path.join(run_dir, name)
            if os.path.exists(path) and os.path.getsize(path):
                with open(path, "rb+") as f:
                    f.seek(-1, os.SEEK_END)
                    if f.read(1) != b"\n":
                        f.write(b"\n")
        _write_knobs(run_dir, knobs)  # its bookkeeping knobs may have changed
        return resume_knobs(knobs, detail[0])
    _clean(run_dir, knobs)
    return dict(knobs)


def launch_partitions(driver, study_dir, runs, partitions, ranks_per_run, mpirun, timeout,
                      progress=None, retry_failed=False, settled=None):
    """Runs `runs` (list of (name, knobs)) in multi-partition launches of up to `partitions`
    runs each until every run is done or failed (or a launch times out or settles nothing);
    a run cut short continues from its newest restart file. settled(name), if given, is
    called for each run of a launch once the launch ends. Returns the launches made."""
    launches, pending = [], [name for name, _ in runs]
    knobs_of = dict(runs)
    while pending:
        batch, launch_knobs = [], {}
        for name in pending:
            if len(batch) == partitions:
                break
            knobs = prepare_launch(os.path.join(study_dir, "runs", name), knobs_of[name], retry_failed)
            if knobs is not None:
                batch.append(name)
                launch_knobs[name] = knobs
        pending = [name for name in pending if name not in batch and
                   plan_run(os.path.join(study_dir, "runs", name), knobs_of[name], retry_failed)[0] != "skip"]
        if not batch:
            break
        launch_dir = os.path.join(study_dir, "launches", str(len(launches) + 1))
        os.makedirs(launch_dir, exist_ok=True)
        for i, name in enumerate(batch, start=1):
            write_run_file(launch_dir, i, os.path.join(study_dir, "runs", name), launch_knobs[name],
                           study_scene(study_dir))
        cmd = study_command(driver, launch_dir, len(batch), len(batch), ranks_per_run, mpirun)
        start = time.time()
        if progress:
            for name in batch:
                progress.started(name, launch_knobs[name])
        with run_cost.LaunchClock([os.path.join(study_dir, "runs", name) for name in batch],
                                  ranks_per_run):
            code = _execute(cmd, launch_dir, os.path.join(launch_dir, "stdout.txt"), timeout)
        if progress:
            for name in batch:
                progress.stopped(name)
        launches.append(dict(command=cmd, runs=batch, exit_code=code,
                             seconds=round(time.time() - start, 1),
                             cores=len(batch) * ranks_per_run))
        retried = [name for name in batch
                   if _unreadable_restart(os.path.join(study_dir, "runs", name), launch_knobs[name])]
        cut_short = [name for name in batch
                     if run_state(os.path.join(study_dir, "runs", name))[0] == "incomplete"]
        for name in batch if settled else []:
            settled(name)
        if code is None or (cut_short == batch and not retried):
            break  # timed out, or nothing in the batch settled: stop rather than loop
        pending = retried + cut_short + pending
    return launches


def launch_pool(driver, study_dir, runs, parallel, ranks_per_run, mpirun, timeout,
                progress=None, retry_failed=False, settled=None):
    """Runs each run in its own mpirun, `parallel` at a time; a run cut short continues from
    its newest restart file, a finished one is left alone. settled(name), if given, is called
    once a run's launches end. Returns the launches made."""
    def one(item):
        name, knobs = item
        run_dir = os.path.join(study_dir, "runs", name)
        made = []
        for _ in range(3):  # a fresh start, or a resume and its fallbacks to older files
            launch_knobs = prepare_launch(run_dir, knobs, retry_failed)
            if launch_knobs is None:
                break
            launch_dir = os.path.join(run_dir, "launch")
            os.makedirs(launch_dir, exist_ok=True)
            write_run_file(launch_dir, 1, run_dir, launch_knobs, study_scene(study_dir))
            cmd = study_command(driver, launch_dir, 1, 1, ranks_per_run, mpirun, parallel)
            start = time.time()
            if progress:
                progress.started(name, launch_knobs)
            with run_cost.LaunchClock([run_dir], ranks_per_run):
                code = _execute(cmd, launch_dir, os.path.join(run_dir, "stdout.txt"), timeout)
            if progress:
                progress.stopped(name)
            made.append(dict(command=cmd, runs=[name], exit_code=code,
                             seconds=round(time.time() - start, 1), cores=ranks_per_run))
            if not _unreadable_restart(run_dir, launch_knobs):
                break
        if settled:
            settled(name)
        return made

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, parallel)) as pool:
        return [launch for made in pool.map(one, runs) for launch in made]


def write_summary(study_dir, study, size, runs, launches, mode):
    """summary.json and summary.txt: every run with its state, the reason of a failure, its
    largest P / P_out and burst count from its own log, and its core-hours over all its
    launches (run_cost)."""
    from study_io import run_figures  # local import: study_io needs examples/pore on the path
    entries = []
    for name, knobs in runs:
        run_dir = os.path.join(study_dir, "runs", name)
        state, reason = run_state(run_dir)
        entry = dict(name=name, state=state, reason=reason, folder=run_dir, knobs=knobs)
        entry.update(run_figures(run_dir, int(knobs.get("warmup", 0))))
        entry["core_hours"], entry["core_hours_exact"] = run_cost.run_core_hours(run_dir)
        entries.append(entry)
    # Every launch of every run, this runner's and earlier ones' (run_cost).
    core_hours = sum(e["core_hours"] for e in entries)
    exact = all(e["core_hours_exact"] for e in entries)
    summary = dict(study=study, size=size, mode=mode, runs=entries, launches=launches,
                   core_hours=core_hours, core_hours_exact=exact,
                   finished=sum(e["state"] == "done" for e in entries),
                   failed=sum(e["state"] == "failed" for e in entries),
                   incomplete=sum(e["state"] == "incomplete" for e in entries))
    with open(os.path.join(study_dir, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    lines = [f"study {study} ({size}, {mode}): {summary['finished']} finished, "
             f"{summary['failed']} failed, {summary['incomplete']} incomplete of {len(entries)}"]
    for e in entries:
        figures = (f"max P/P_out {e['max_P']:.4g}, bursts {e['bursts']}"
                   if e.get("max_P") is not None else "no thermo rows")
        figures += f", {'' if e['core_hours_exact'] else 'at least '}{e['core_hours']:.2f} core-h"
        lines.append(f"  {e['name']:<28} {e['state']:<10} {figures}"
                     + (f"  -- {e['reason']}" if e["reason"] else ""))
    with open(os.path.join(study_dir, "summary.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines), flush=True)
    return summary
