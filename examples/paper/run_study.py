#!/usr/bin/python3
"""Runs one study of the paper (a figure) as an ensemble and analyses it.

  run_study.py <study> [--size tiny|quick|paper] [--out DIR] [--parallel P] [--ranks-per-run K]
               [--mode pool|partitions] [--driver liggghts-lbm] [--mpirun mpirun]
               [--timeout S] [--add-run NAME:knob=value,...] [--set knob=value ...]
               [--restart-every FLUID_STEPS] [--fresh] [--retry-failed] [--runs REGEX]
               [--progress-every S] [--summarize] [--evidence DIR | --no-evidence] [--park]
               [--stop-after S]
               [--dry-run] [--no-analysis]

Studies: singlejump collection dropvol porelength porediameter phaseac phasead conc pvpflux
(studies.py lists their runs). Before it starts it prints the runs, the command and the
estimated cost of this size and of the paper size in core-hours (from a cost per lattice cell
and fluid step measured here, studies.CORE_SECONDS_PER_CELL_STEP). Every run writes into
<out>/runs/<name>/ (log.liggghts, bursts.txt, VTK, stdout.txt); <out>/summary.txt and
summary.json say which runs finished, which failed and why (the ERROR line of their log);
then analyze.py fits and plots (<out>/results.json, <out>/<study>.png).

--mode pool (default): one mpirun per run, P at a time: a failing run stops only itself.
--mode partitions: one `mpirun -np P*K liggghts-lbm -partition PxK -in in.study`; LIGGGHTS
  aborts every partition when one fails, and the runs cut short are relaunched (ensemble.py).
--add-run adds a run with the study's knobs changed (e.g. a deliberately failing one);
--set changes a knob of every run (e.g. --set u_lattice=0.005).

Long studies survive interruption: every run writes restart files in turn (in.pore's
restart_every, by default every 1/50 of the run and at least every 4000 fluid steps, and
keeps the two fluid checkpoints they name). Rerunning the same command leaves finished runs
(and failed ones, unless --retry-failed) alone, continues each run that was cut short from its
newest readable restart file, and starts anew a run whose knobs changed (not those that only
say how often it saves itself, --restart-every); --fresh deletes every run first.
While the runs go on it prints, every --progress-every seconds (and keeps in
<out>/progress.txt), the runs done and to do, each running run's step and the time left.

What the repository keeps (--evidence DIR; at the paper size doc/paper/<study> unless
--no-evidence; committed_runs.py): each run's compact result as soon as it finishes, which no
later launch runs again, and, when the runner is stopped or ends with runs cut short (a
timeout; or --park from another shell), each such run with its newest restart file and fluid
checkpoint, which a launch on a fresh clone unpacks and resumes. Commit DIR after each sitting
and the same command continues the study anywhere. --stop-after S stops the runner S seconds
after it starts as SIGTERM does (the runs write a restart file, those cut short are parked):
for a sitting of known length, the runs are in the tree before the machine goes.
"""
import argparse
import glob
import json
import re
import os
import shlex
import shutil
import signal
import sys
import threading

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import committed_runs  # noqa: E402
import ensemble  # noqa: E402
import studies  # noqa: E402
from study_progress import StudyProgress  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_DRIVER = os.path.join(REPO, "build", "liggghts_plugin", "liggghts-lbm")


def parse_added_run(text, base):
    name, _, assignments = text.partition(":")
    knobs = dict(base)
    for item in filter(None, assignments.split(",")):
        key, _, value = item.partition("=")
        knobs[key.strip()] = value.strip()
    return name, knobs


# The most fluid steps between two restart files by default: a few minutes of a paper-size
# run, the work a run loses when its sitting ends without warning. Changing it resumes a run
# (ensemble.BOOKKEEPING_KNOBS).
MAX_RESTART_FLUID_STEPS = 4000


def restart_knobs(knobs, restart_every=None):
    """The knobs that make a run resumable: restart files every restart_every fluid steps
    (default 1/50 of the run, at least one fluid step and at most MAX_RESTART_FLUID_STEPS), as
    DEM steps (a multiple of the DEM steps per fluid step, so the continuation is exact), and
    the two checkpoints they name."""
    n_dem = studies.run_dem_steps_per_fluid_step(knobs)
    fluid_steps = (int(knobs["steps"]) + int(knobs["warmup"])) // n_dem
    every = restart_every if restart_every else max(1, min(fluid_steps // 50, MAX_RESTART_FLUID_STEPS))
    return dict(knobs, restart_every=every * n_dem, checkpoint_keep=2)


def refresh_evidence(evidence, no_analysis=False):
    """The analysis of the kept runs and, for the repository's own evidence, doc/paper.md's
    table of the figures (figure_table.py), so that a commit of the folder is consistent."""
    if no_analysis:
        return
    import analyze
    import figure_table
    try:
        analyze.analyze(evidence)
    except Exception as error:  # noqa: BLE001  a figure that cannot be drawn yet stops no run
        print(f"run_study: the analysis of {evidence} failed: {error}", flush=True)
        return
    if os.path.dirname(os.path.abspath(evidence)) == os.path.join(REPO, "doc", "paper"):
        figure_table.rewrite_doc()


def park_cut_short(out, evidence, runs, study, size):
    """Keeps each settled run's compact result in evidence and parks each run cut short
    (committed_runs), and says so."""
    for name, _ in runs:
        run_dir = os.path.join(out, "runs", name)
        if not os.path.exists(os.path.join(run_dir, "log.liggghts")) or \
                committed_runs.committed_state(evidence, name):
            continue  # never started (a queued run the stop found), or kept already
        if committed_runs.keep_settled(run_dir, evidence, name):
            print(f"  {name}: kept in {evidence}", flush=True)
        elif ensemble.run_state(run_dir)[0] == "incomplete":
            archive = committed_runs.park(run_dir, evidence, name)
            share = committed_runs.share_done(run_dir)
            print(f"  {name}: " + (f"parked in {archive} ({os.path.getsize(archive) / 1e6:.1f} MB)" if archive
                                   else f"not parked ({share:.0%} done; parked from "
                                        f"{committed_runs.MIN_PARKED_SHARE:.0%} with a restart file)"),
                  flush=True)
    committed_runs.write_summary(evidence, study, size, [name for name, _ in runs])
    print(f"run_study: commit {evidence} to keep the study's state in the repository", flush=True)


def main():
    parser = argparse.ArgumentParser(description="Run one study of the paper as an ensemble.")
    parser.add_argument("study", choices=sorted(studies.STUDIES))
    parser.add_argument("--size", default="quick", choices=sorted(studies.SIZES))
    parser.add_argument("--out", help="study folder (default ./<study>_<size>)")
    # Two 1-rank runs side by side on 2 cores and one 2-rank run at a time are about even in
    # runs per hour (bench_paper_run's
    # paper_run_paper_side_by_side_runs_per_hour_vs_one_two_rank_run, doc/performance.md:
    # 1.08 at the median of six rounds, 0.82-1.51); 1-rank runs need no MPI exchange.
    parser.add_argument("--parallel", type=int, default=2, help="runs at a time (default 2)")
    parser.add_argument("--ranks-per-run", type=int, default=1, help="MPI ranks per run (default 1)")
    parser.add_argument("--mode", default="pool", choices=["pool", "partitions"])
    parser.add_argument("--driver", default=DEFAULT_DRIVER)
    parser.add_argument("--mpirun", default=None,
                        help="mpirun to launch with (default: mpirun when a launch needs > 1 rank)")
    parser.add_argument("--timeout", type=float, default=None, help="seconds per launch")
    parser.add_argument("--add-run", action="append", default=[], metavar="NAME:knob=value,...")
    parser.add_argument("--set", action="append", default=[], metavar="knob=value",
                        help="change a knob of every run")
    parser.add_argument("--restart-every", type=int, default=None, metavar="FLUID_STEPS",
                        help="fluid steps between restart files (default: 1/50 of a run, at most "
                             f"{MAX_RESTART_FLUID_STEPS}); changing it resumes a run, not restarts it")
    parser.add_argument("--fresh", action="store_true", help="delete the runs made before")
    parser.add_argument("--runs", metavar="REGEX", default=None,
                        help="launch only the runs whose names match (the others are left as they are)")
    parser.add_argument("--retry-failed", action="store_true",
                        help="run again the runs that failed (from their restart files)")
    parser.add_argument("--progress-every", type=float, default=60.0, metavar="S")
    parser.add_argument("--dry-run", action="store_true", help="print the plan and the cost only")
    parser.add_argument("--summarize", action="store_true",
                        help="launch nothing: summarize and analyze the runs as they stand (also "
                             "while the study runs, from another shell)")
    parser.add_argument("--no-analysis", action="store_true")
    parser.add_argument("--evidence", metavar="DIR", default=None,
                        help="where the repository keeps the study's runs (default at the paper "
                             "size: doc/paper/<study>)")
    parser.add_argument("--no-evidence", action="store_true", help="keep nothing in the repository")
    parser.add_argument("--stop-after", type=float, default=None, metavar="S",
                        help="stop as on SIGTERM S seconds after the start: the runs write a "
                             "restart file, those cut short are parked into --evidence")
    parser.add_argument("--park", action="store_true",
                        help="launch nothing: keep the finished runs and park the runs cut short "
                             "into --evidence as they stand")
    args = parser.parse_args()

    runs = studies.runs_of(args.study, args.size)
    runs += [parse_added_run(text, runs[0][1]) for text in args.add_run]
    changed = dict(parse_added_run(":" + ",".join(args.set), {})[1]) if args.set else {}
    runs = [(name, restart_knobs(dict(knobs, **changed), args.restart_every)) for name, knobs in runs]
    out = os.path.abspath(args.out or f"{args.study}_{args.size}")
    evidence = None if args.no_evidence else (
        args.evidence or (os.path.join(REPO, "doc", "paper", args.study) if args.size == "paper"
                          else None))
    paper_runs = studies.runs_of(args.study, "paper")
    paper_cost = studies.core_hours(paper_runs)
    fluid_steps = max((int(k["steps"]) + int(k["warmup"])) / studies.run_dem_steps_per_fluid_step(k)
                      for _, k in paper_runs)
    cost = studies.core_hours(runs)
    cores = args.parallel * args.ranks_per_run
    threads = ensemble.set_threads_per_rank(cores)
    print(f"study {args.study}, size {args.size}: {len(runs)} runs into {out} "
          f"({args.parallel} at a time, {args.ranks_per_run} rank(s) each, {threads} OpenMP thread(s) per rank)")
    print(f"estimated cost: {cost:.3g} core-hours ({cost / cores:.3g} h on {cores} cores); "
          f"the paper size: {paper_cost:.3g} core-hours "
          f"({len(paper_runs)} runs of {fluid_steps:.3g} fluid steps)", flush=True)
    for name, knobs in runs:
        print(f"  {name}: " + " ".join(f"-var {k} {shlex.quote(str(v))}"
                                       for k, v in sorted(knobs.items())))
    if args.dry_run:
        return 0
    if not os.path.exists(args.driver):
        sys.exit(f"no liggghts-lbm at {args.driver} (build first, or pass --driver)")
    if args.fresh:
        for folder in ("runs", "launches"):
            shutil.rmtree(os.path.join(out, folder), ignore_errors=True)
        if os.path.exists(os.path.join(out, "in.pore")):
            os.remove(os.path.join(out, "in.pore"))  # a fresh copy of the scene (ensemble.study_scene)
    elif not args.summarize:
        shutil.rmtree(os.path.join(out, "launches"), ignore_errors=True)  # partitions' scratch
    os.makedirs(out, exist_ok=True)
    names = [name for name, _ in runs]
    if args.park:
        if not evidence:
            sys.exit("--park needs --evidence (or --size paper)")
        park_cut_short(out, evidence, runs, args.study, args.size)
        return 0
    scene = ensemble.study_scene(out) if not args.summarize else None
    kept = {}  # runs whose compact result the repository keeps: never run again
    for name, knobs in runs if not args.summarize else []:
        if args.runs and not re.search(args.runs, name):
            continue
        if evidence:
            kept[name] = committed_runs.committed_state(evidence, name)
            if kept[name]:
                print(f"  {name}: kept in {evidence} ({kept[name]}): not run again")
                continue
            if committed_runs.unpark(evidence, name, os.path.join(out, "runs", name)):
                print(f"  {name}: unpacked from {committed_runs.parked_archive(evidence, name)}")
        unknown = ensemble.unknown_knobs(scene, knobs)
        if unknown:
            sys.exit(f"run {name}: knob(s) {', '.join(unknown)} not defined by {scene}, the copy of "
                     "in.pore this study made at its first launch (the scene has changed since): "
                     "run this study in a new folder (--out), or leave the run out (--runs)")
        action, detail = ensemble.plan_run(os.path.join(out, "runs", name), knobs, args.retry_failed)
        what = {"skip": f"left alone ({detail})", "fresh": f"starts ({detail})",
                "resume": f"resumes from {os.path.basename(detail[0]) if detail else ''}"}[action]
        print(f"  {name}: {what}")
    def stop(signum, _frame):
        # Ctrl-C, or the end of a batch job: every run writes a restart file and quits, and
        # the same command later resumes them.
        print(f"run_study: signal {signum}: asking the runs under way to write a restart "
              "file and stop; rerun the same command to resume", flush=True)
        ensemble.stop_running_launches()
        if evidence:
            park_cut_short(out, evidence, runs, args.study, args.size)
        sys.exit(128 + signum)
    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    if args.stop_after is not None:
        # The signal reaches the main thread, which stops as it would on one from outside.
        timer = threading.Timer(args.stop_after, os.kill, (os.getpid(), signal.SIGTERM))
        timer.daemon = True
        timer.start()
    launch = ensemble.launch_pool if args.mode == "pool" else ensemble.launch_partitions
    launches = []
    chosen = [(name, knobs) for name, knobs in runs
              if (not args.runs or re.search(args.runs, name)) and not kept.get(name)]
    lock = threading.Lock()

    def settled(name):  # a run's compact result is kept the moment it finishes
        with lock:
            if evidence and committed_runs.keep_settled(os.path.join(out, "runs", name), evidence, name):
                committed_runs.write_summary(evidence, args.study, args.size, names)
                print(f"  {name}: kept in {evidence}", flush=True)
                refresh_evidence(evidence, args.no_analysis)
    if not args.summarize:
        with StudyProgress(out, chosen, args.parallel, args.progress_every) as progress:
            launches = launch(args.driver, out, chosen, args.parallel, args.ranks_per_run, args.mpirun,
                              args.timeout, progress=progress, retry_failed=args.retry_failed,
                              settled=settled)
    for entry in launches:
        print(f"launch ({entry['seconds']} s, exit {entry['exit_code']}): "
              + " ".join(shlex.quote(c) for c in entry["command"]))
    earlier = os.path.join(out, "summary.json")
    if not args.fresh and os.path.exists(earlier):  # the launches of earlier sittings count too
        with open(earlier) as f:
            launches = json.load(f).get("launches", []) + launches
    summary = ensemble.write_summary(out, args.study, args.size, runs, launches, args.mode)
    if evidence and launches:  # runs a launch cut short (a timeout) are parked as when stopped
        park_cut_short(out, evidence, runs, args.study, args.size)
    elif evidence:
        committed_runs.write_summary(evidence, args.study, args.size, names)
    if evidence and glob.glob(os.path.join(evidence, "runs", "*", "state.txt")):
        refresh_evidence(evidence, args.no_analysis)
    elif not args.no_analysis and (summary["finished"] or args.summarize):
        import analyze
        analyze.analyze(out)
    return 0 if summary["finished"] else 1


if __name__ == "__main__":
    sys.exit(main())
