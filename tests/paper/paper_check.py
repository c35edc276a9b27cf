"""The paper's study machinery on tiny scenes (ctest -L paper), each check reading the runs'
own files independently of the code it checks:

  ensemble  examples/paper/run_study.py conc --size tiny --mode partitions --parallel 3 with a
            third, deliberately failing run (boundary nonsense): LIGGGHTS aborts all three
            partitions, the runner relaunches the two good runs. The summary must list both
            as done with the largest P / P_out read here from their own log.liggghts, and the
            failing one as failed with its ERROR line; the analysis's mean burst jump per C_in
            must equal the mean of delta_P read here from each run's bursts.txt.
  snapshot  run_study.py collection --size tiny: the snapshot figure rendered from the run's
            own VTK files must exist and not be blank (many distinct colours, no single colour
            covering nearly all of it), with its three frames kept (snapshots.npz). A window of
            the run replayed from a restart file (replay_window.py) with VTK files and without:
            its rows within round-off of the run's, identical with and without the files; its
            figure redrawn from snapshots.npz alone with the same three frames.
  resume    run_study.py singlejump --size tiny (made longer) run once uninterrupted, and once
            killed (SIGKILL to the runner and its runs, as when a sitting ends) past 40 % of
            the run and started again with the same command. The second launch must resume
            from a restart file (not start anew), finish, and give the uninterrupted run's
            thermo rows: identical up to the restart step (the first launch's own rows), within
            round-off for the first fluid steps after it (a LIGGGHTS restart equals a run split
            at that step bit for bit, tests/faults; the split itself re-sorts the atoms, so
            the chaotic run then drifts away), every thermo step of the uninterrupted run once,
            and no burst recorded twice. Then SIGTERM to a runner alone (Ctrl-C, a batch
            system's end of job): it passes the request on, its run writes a forced restart
            file and stops, no process is left, and the same command resumes from that file.
            That runner keeps the study in an evidence folder (--evidence, as the paper size
            does in doc/paper/<study>): stopped, it parks the run there; a launch into an
            empty folder (a fresh clone) with the same evidence unpacks it, resumes it,
            finishes, keeps its compact result and drops the archive, and its burst records
            equal, byte for byte, those of the resume in the run's own folder.
            A third launch leaves the finished run alone. --stop-after 3 stops a runner as
            SIGTERM does: exit 143, no process left.

Usage: paper_check.py --driver liggghts-lbm --repo <source root> --python /usr/bin/python3 <case>
"""
import argparse
import json
import re
import os
import subprocess
import sys
import signal
import tempfile
import time


def check(name, ok, measured, bound):
    print(f"{'PASS' if ok else 'FAIL'} {name}: measured {measured}, bound {bound}", flush=True)
    return bool(ok)


def thermo_column(log, column):
    """(steps, values) of a thermo column, read straight from the log."""
    steps, values, header = [], [], None
    for line in open(log, errors="replace"):
        words = line.split()
        if words[:1] == ["Step"]:
            header = words
        elif header and len(words) == len(header):
            try:
                row = [float(w) for w in words]
            except ValueError:
                continue
            steps.append(row[0])
            values.append(row[header.index(column)])
    return steps, values


def run_study(args, work, *extra):
    cmd = [args.python, os.path.join(args.repo, "examples", "paper", "run_study.py"), *extra,
           "--driver", args.driver, "--out", work, "--timeout", "100"]
    print("run:", " ".join(cmd), flush=True)
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=170)
    print(done.stdout[-3000:], done.stderr[-2000:], flush=True)
    return done


def ensemble(args, work):
    run_study(args, work, "conc", "--size", "tiny", "--mode", "partitions", "--parallel", "3",
              "--add-run", "broken:boundary=nonsense")
    summary = json.load(open(os.path.join(work, "summary.json")))
    results = json.load(open(os.path.join(work, "results.json")))
    runs = {r["name"]: r for r in summary["runs"]}
    ok = check("runs listed", sorted(runs) == ["broken", "c_in_0.02", "c_in_0.05"],
               sorted(runs), "the two tiny runs and the broken one")
    ok &= check("relaunch after the abort", len(summary["launches"]) >= 2,
                len(summary["launches"]), ">= 2 launches")
    broken = runs.get("broken", {})
    ok &= check("failed run reported", broken.get("state") == "failed"
                and "ERROR" in broken.get("reason", "") and "boundary" in broken["reason"],
                f"{broken.get('state')}: {broken.get('reason')}", "failed, its ERROR line")
    for name in ("c_in_0.02", "c_in_0.05"):
        run = runs.get(name, {})
        log = os.path.join(work, "runs", name, "log.liggghts")
        steps, so_far = thermo_column(log, "pore[17]")
        _, now = thermo_column(log, "pore[16]")
        warmup = int(run["knobs"]["warmup"])
        at_warmup = max(m for s, m in zip(steps, so_far) if s <= warmup)
        expected = so_far[-1] if so_far[-1] > at_warmup else max(
            p for s, p in zip(steps, now) if s > warmup)
        ok &= check(f"{name} done", run.get("state") == "done", run.get("state"), "done")
        ok &= check(f"{name} max P/P_out from its log", run.get("max_P") == expected,
                    run.get("max_P"), f"== {expected} (read here from {log})")
        rows = [line.split() for line in open(os.path.join(work, "runs", name, "bursts.txt"))
                if line.strip() and not line.startswith("#")]
        mean_jump = sum(float(r[4]) for r in rows) / len(rows) if rows else 0.0
        c = str(float(run["knobs"]["c_in"]))
        got = results["means"][c][0]
        ok &= check(f"{name} mean jump from its bursts.txt", len(rows) > 0 and
                    abs(got - mean_jump) <= 1e-12 * max(1.0, abs(mean_jump)),
                    f"{got} over {len(rows)} bursts", f"== {mean_jump}")
    plot = os.path.join(work, results["plot"])  # results.json names its plot beside it
    ok &= check("plot written", os.path.getsize(plot) > 10000, os.path.getsize(plot), "> 10 kB")
    return ok


def study_rows(run_dir):
    """A run's thermo rows as the analyses read them (study_io.thermo), a list per step."""
    log = os.path.join(run_dir, "log.liggghts")
    if not os.path.exists(log):
        return []
    rows, header = [], None
    for line in open(log, errors="replace"):
        words = line.split()
        if words[:1] == ["Step"]:
            header = words
        elif header and len(words) == len(header) and words[0].isdigit():
            rows.append(words)
    return rows


def image_colours(args, png):
    """(distinct colours, the largest share of one colour) of a picture."""
    probe = ("import matplotlib.image as m, numpy as n, sys; a = m.imread(sys.argv[1])[..., :3];"
             "q = (a * 255).astype(int).reshape(-1, 3); u, c = n.unique(q, axis=0, return_counts=True);"
             "print(len(u), c.max() / len(q))")
    colours, top = subprocess.run([args.python, "-c", probe, png], capture_output=True,
                                  text=True, check=True).stdout.split()
    return int(colours), float(top)


def snapshot(args, work):
    run_study(args, work, "collection", "--size", "tiny", "--restart-every", "40")
    png = os.path.join(work, "collection.png")
    if not check("image written", os.path.exists(png), os.path.exists(png), "exists"):
        return False
    colours, top = image_colours(args, png)
    ok = check("image has many colours", colours > 200, colours, "> 200 distinct")
    ok &= check("not one colour", top < 0.9, top, "< 0.9 of the pixels (blank: 1)")
    run_dir = os.path.join(work, "runs", "snapshot")
    kept = os.path.join(run_dir, "snapshots.npz")
    ok &= check("the three frames kept for the repository", os.path.exists(kept)
                and os.path.getsize(kept) < 2e6, os.path.exists(kept) and os.path.getsize(kept),
                "snapshots.npz, < 2 MB")
    # A window of the run replayed from its older restart file (restart files every 40 fluid
    # steps of 178 DEM steps: restart.a at fluid step 120, restart.b at 160) to the run's end,
    # with VTK files every 10 fluid steps and without: the files leave the trajectory alone
    # (the two replays' rows identical), and the replay continues the run (P / P_out within
    # round-off of the run's at the first row after the restart; the run went on without
    # reading the file, so the two part later, as the resume case shows).
    restarts = sorted((os.path.join(run_dir, n) for n in ("restart.a", "restart.b")), key=os.path.getmtime)
    records = {}
    evidence = os.path.join(work, "evidence")
    for name, every in (("replay", "10"), ("replay_no_vtk", "0")):
        kept = ["--evidence", evidence] if name == "replay" else []
        done = subprocess.run([args.python, os.path.join(args.repo, "examples", "paper", "replay_window.py"),
                               run_dir, "--restart", restarts[0], "--fluid-steps", "59", "--vtk-every", every,
                               "--out", os.path.join(work, name), "--driver", args.driver, *kept],
                              capture_output=True, text=True, timeout=170)
        print(done.stdout[-2000:], done.stderr[-2000:], flush=True)
        path = os.path.join(work, name, "replay.json")
        records[name] = json.load(open(path)) if done.returncode == 0 and os.path.exists(path) else {}
    replay = os.path.join(work, "replay")
    record = records["replay"]
    ok &= check("the replay continues the run", record.get("common", 0) >= 10
                and (record["first_difference"] is None or record["P_difference_there"] < 1e-6),
                {k: record.get(k) for k in ("start_dem_step", "common", "identical", "first_difference",
                                            "P_difference_there")},
                ">= 10 thermo rows in common, P / P_out within 1e-6 where they first differ")
    with_files, without = study_rows(replay), study_rows(os.path.join(work, "replay_no_vtk"))
    ok &= check("its VTK files leave the trajectory alone", with_files and with_files == without,
                f"{len(with_files)} rows against {len(without)}", "every thermo row identical")
    # The replay kept as the collection figure's evidence, which analyze.py draws.
    analysed = subprocess.run([args.python, os.path.join(args.repo, "examples", "paper", "analyze.py"), evidence],
                              capture_output=True, text=True, timeout=120)
    print(analysed.stdout[-1000:], analysed.stderr[-1000:], flush=True)
    results = json.load(open(os.path.join(evidence, "results.json"))) if analysed.returncode == 0 else {}
    ok &= check("the replay kept as evidence and drawn from it", results.get("finished") == 1
                and os.path.exists(os.path.join(evidence, "collection.png"))
                and os.path.exists(os.path.join(evidence, "runs", "snapshot_window", "snapshots.npz")),
                {k: results.get(k) for k in ("figure", "finished", "ours")},
                "results.json of 1 finished run, collection.png, the kept frames")
    frames = sorted(os.listdir(os.path.join(replay, "fluid_vtk"))) if os.path.isdir(
        os.path.join(replay, "fluid_vtk")) else []
    ok &= check("the replay writes its VTK files", len([f for f in frames if f.endswith(".vti")]) >= 5,
                frames, ">= 5 fluid files (fluid steps 130 ... 170)")
    # Its figure drawn from the files with --keep, then again from snapshots.npz alone.
    render = os.path.join(args.repo, "examples", "paper", "render_snapshot.py")
    first, second = os.path.join(work, "replay_files.png"), os.path.join(work, "replay_kept.png")
    drawn = subprocess.run([args.python, render, replay, "--keep", "--out", first], capture_output=True,
                           text=True, timeout=120)
    if os.path.isdir(os.path.join(replay, "fluid_vtk")):
        os.rename(os.path.join(replay, "fluid_vtk"), os.path.join(replay, "fluid_vtk.gone"))
    redrawn = subprocess.run([args.python, render, replay, "--out", second], capture_output=True,
                             text=True, timeout=120)
    print(drawn.stdout[-1000:], drawn.stderr[-1000:], redrawn.stdout[-1000:], redrawn.stderr[-1000:],
          flush=True)
    steps = lambda out: re.findall(r"fluid steps (\([^)]*\))", out)  # noqa: E731
    same_steps = drawn.returncode == 0 and steps(drawn.stdout) and steps(drawn.stdout) == steps(redrawn.stdout)
    colours, top = image_colours(args, second) if os.path.exists(second) else (0, 1.0)
    ok &= check("redrawn from snapshots.npz without the VTK files", redrawn.returncode == 0
                and colours > 200 and top < 0.9 and same_steps,
                (redrawn.returncode, colours, top, steps(drawn.stdout), steps(redrawn.stdout)),
                "exit 0, > 200 colours, < 0.9 of one colour, the same three fluid steps")
    return ok


def resume(args, work):
    sys.path.insert(0, os.path.join(args.repo, "examples", "paper"))
    import study_io  # the analyses' own reader (superseding the rows a resume repeats)
    base = ["singlejump", "--size", "tiny", "--set", "steps=1000000", "--no-analysis",
            "--progress-every", "1"]
    whole, cut = os.path.join(work, "whole"), os.path.join(work, "cut")
    run_study(args, whole, *base)
    run_dir = os.path.join(cut, "runs", "seed_100003")
    log = os.path.join(run_dir, "log.liggghts")
    cmd = [args.python, os.path.join(args.repo, "examples", "paper", "run_study.py"), *base,
           "--driver", args.driver, "--out", cut]
    runner = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              start_new_session=True)
    killed_at, deadline = None, time.time() + 150
    while runner.poll() is None and time.time() < deadline:
        time.sleep(0.05)
        steps = thermo_column(log, "pore[16]")[0] if os.path.exists(log) else []
        if steps and steps[-1] >= 0.4 * 1002000:
            # The runner, then its run (its own process group): as a sitting that ends does.
            os.killpg(runner.pid, signal.SIGKILL)
            subprocess.run(["pkill", "-KILL", "-f", cut])
            time.sleep(1)  # until the ranks are gone
            killed_at = steps[-1]
            break
    runner.wait()
    ok = check("killed mid-run", killed_at is not None and killed_at < 1002000, killed_at,
               "a step between 40 % and the end")
    # Resumed with restart files at another interval (a knob that says only how often a run
    # saves itself): it continues, and records the new interval.
    second = run_study(args, cut, *base, "--restart-every", "50")
    ok &= check("resumed, not restarted, at another restart interval", "resumes from restart" in second.stdout
                and json.load(open(os.path.join(run_dir, "knobs.json")))["restart_every"] == str(50 * 178),
                [line for line in second.stdout.splitlines() if "seed_100003:" in line and "-var" not in line],
                "'resumes from restart...', knobs.json's restart_every 50 fluid steps")
    summary = json.load(open(os.path.join(cut, "summary.json")))
    ok &= check("finished", summary["finished"] == 1, summary["finished"], "1 run done")
    a = study_io.thermo(os.path.join(whole, "runs", "seed_100003"))
    b = study_io.thermo(run_dir)
    resumed_from = max(s for s in b["Step"] if s not in a["Step"]) if set(b["Step"]) - set(a["Step"]) \
        else None  # the restart step prints a row of its own unless it is a thermo step
    first_launch = [line for line in open(log, errors="replace")]
    starts = [i for i, line in enumerate(first_launch) if line.startswith("STUDY_RUN_START")]
    ok &= check("two launches in one log", len(starts) == 2, len(starts), "2 STUDY_RUN_START lines")
    row_a = {s: i for i, s in enumerate(a["Step"])}
    row_b = {s: i for i, s in enumerate(b["Step"])}
    ok &= check("every thermo step once", set(a["Step"]) <= set(b["Step"])
                and len(b["Step"]) == len(set(b["Step"])), (len(a["Step"]), len(b["Step"])),
                "the uninterrupted run's steps, none twice")
    # The restart step: the first row of the second launch's part of the log.
    second_rows = [line.split() for line in first_launch[starts[-1]:]]
    restart_step = next(float(w[0]) for w in second_rows
                        if len(w) == len(study_io.thermo(run_dir)) and w[0].isdigit())
    before = [s for s in a["Step"] if s <= restart_step]
    same_before = all(a[c][row_a[s]] == b[c][row_b[s]] for s in before for c in a)
    ok &= check("identical before the restart step", same_before and len(before) > 10,
                f"{len(before)} rows up to step {restart_step:.0f} (resumed from {resumed_from})",
                "bit for bit")
    # P / P_out within round-off for about 5 fluid steps (1000 DEM steps of 178) after it.
    after = [s for s in a["Step"] if restart_step < s <= restart_step + 1000]
    worst = max((abs(a["pore[16]"][row_a[s]] - b["pore[16]"][row_b[s]]) / abs(a["pore[16]"][row_a[s]])
                 for s in after), default=None)
    ok &= check("P / P_out just after the restart", worst is not None and worst < 1e-6, worst,
                "< 1e-6 relative")
    burst_steps = [r["step"] for r in study_io.bursts(run_dir)]
    raw = [line.split()[0] for line in open(os.path.join(run_dir, "bursts.txt"))
           if line.strip() and not line.startswith("#")]
    ok &= check("bursts read once each", len(burst_steps) == len(set(burst_steps)) and len(burst_steps) > 0,
                f"{len(burst_steps)} read, {len(raw)} rows in the file", "no step twice, at least one")
    progress = open(os.path.join(cut, "progress.txt")).read()
    ok &= check("progress kept", "1 done" in progress and "time left" in progress, progress.strip(),
                "'1 done ... time left'")
    shown = [line for line in second.stdout.splitlines() if "progress:" in line and "seed_100003 " in line]
    ok &= check("progress shows the running run's step", bool(shown), shown[-1:] if shown else None,
                "a line with the run, its step and the time left")
    # SIGTERM to the runner alone (Ctrl-C, a batch system's end of job): it passes the
    # request on, the run writes its forced restart file at the next fluid step and stops,
    # and the same command resumes from that file.
    term = os.path.join(work, "term")
    term_log = os.path.join(term, "runs", "seed_100003", "log.liggghts")
    evidence = os.path.join(work, "evidence")
    cmd_term = [args.python, os.path.join(args.repo, "examples", "paper", "run_study.py"), *base,
                "--driver", args.driver, "--out", term, "--evidence", evidence]
    runner = subprocess.Popen(cmd_term, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              start_new_session=True)
    deadline = time.time() + 150
    while runner.poll() is None and time.time() < deadline:
        time.sleep(0.05)
        steps = thermo_column(term_log, "pore[16]")[0] if os.path.exists(term_log) else []
        if steps and steps[-1] >= 0.4 * 1002000:
            runner.send_signal(signal.SIGTERM)
            break
    try:
        runner.wait(timeout=90)
    except subprocess.TimeoutExpired:
        os.killpg(runner.pid, signal.SIGKILL)
    left = subprocess.run(["pgrep", "-f", term], capture_output=True, text=True).stdout.split()
    forced = [n for n in os.listdir(os.path.dirname(term_log)) if n.startswith("restart_forced_liggghts_")]
    ok &= check("SIGTERM stops the runs with a restart file", not left and len(forced) == 1,
                f"processes left {left}, forced restart files {forced}", "none left, one file")
    parked = os.path.join(evidence, "parked", "seed_100003.tar.xz")
    ok &= check("the stopped run parked in the evidence", os.path.exists(parked), parked, "exists")
    fresh = os.path.join(work, "fresh")
    unpacked = run_study(args, fresh, *base, "--evidence", evidence)
    with open(os.path.join(evidence, "runs", "seed_100003", "state.txt")) as f:
        kept = f.readline().strip()
    ok &= check("a fresh folder continues from the evidence", "unpacked from" in unpacked.stdout
                and "resumes from restart_forced_liggghts_" in unpacked.stdout and kept == "done"
                and not os.path.exists(parked),
                [line for line in unpacked.stdout.splitlines() if "seed_100003:" in line and "-var" not in line]
                + [f"kept: {kept}", f"parked left: {os.path.exists(parked)}"],
                "unpacked, resumed from the forced restart, kept as done, archive dropped")
    resumed = run_study(args, term, *base)
    same = open(os.path.join(term, "runs", "seed_100003", "bursts.txt")).read() == \
        open(os.path.join(fresh, "runs", "seed_100003", "bursts.txt")).read()
    ok &= check("the unpacked resume equals the resume in place", same, same, "bursts.txt byte for byte")
    ok &= check("resumed from the forced restart", "resumes from restart_forced_liggghts_" in resumed.stdout
                and json.load(open(os.path.join(term, "summary.json")))["finished"] == 1,
                [line for line in resumed.stdout.splitlines() if "seed_100003:" in line and "-var" not in line],
                "'resumes from restart_forced_liggghts_...', then done")
    third = run_study(args, cut, *base)
    ok &= check("a finished run is left alone", "left alone (done)" in third.stdout
                and "launch (" not in third.stdout.split("progress:")[-1], "see above", "left alone, no launch")
    # --stop-after: the runner stops itself as on SIGTERM, for a sitting of known length.
    timed_out = os.path.join(work, "timed")
    timed = run_study(args, timed_out, *base, "--stop-after", "3")
    left = subprocess.run(["pgrep", "-f", timed_out], capture_output=True, text=True).stdout.split()
    ok &= check("--stop-after stops the runner as SIGTERM does",
                timed.returncode == 128 + signal.SIGTERM and "signal 15" in timed.stdout and not left,
                f"exit {timed.returncode}, processes left {left}", f"exit {128 + signal.SIGTERM}, none left")
    return ok


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--repo", required=True)
    parser.add_argument("--python", default="/usr/bin/python3")
    parser.add_argument("case", choices=["ensemble", "snapshot", "resume"])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix=f"paper_{args.case}_") as work:
        ok = {"ensemble": ensemble, "snapshot": snapshot, "resume": resume}[args.case](args, work)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
