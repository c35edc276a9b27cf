#!/usr/bin/python3
"""A window of a study run replayed from one of its restart files, now with the VTK files the
long run did not write. The same knobs, scene, driver and rank count resume the same state;
the replay writes its restart files where the run did (writing one changes the trajectory at
round-off, measured: a replay without them parted from its run at the run's first restart
file) and the VTK files leave the trajectory alone, so the replay is the run's own
continuation from that file: bit for bit the run's rows where the run itself resumed from it
(a sitting's end, run_study.py) up to where the run was next stopped, and elsewhere, where the
run went on without reading it, the same to round-off at first and then apart as DEM
trajectories part (a resumed LIGGGHTS run rebuilds its neighbour lists). Its thermo rows are
compared with the run's at every step both have, and it says where they part. This is how the paper's snapshot figure (collection) is drawn from a
paper-size study run: a run of 10^6 fluid steps with a file every few hundred steps would
fill a disk, a window of it does not.

  replay_window.py <run folder> --restart FILE --fluid-steps N --out DIR
                   [--vtk-every M] [--driver liggghts-lbm] [--ranks K] [--scene FILE]
                   [--evidence EVIDENCE]

<run folder> is the study's runs/<name>/ (its knobs.json; the scene is the study's own copy,
<study>/in.pore, unless --scene: the one the run read when it wrote FILE); FILE one of its
restart files (restart.a, restart.b, restart_forced_liggghts_<step>.data) with the fluid
checkpoint it names beside it. DIR receives a copy of the scene (LIGGGHTS reads a script while
it runs), what in.pore writes (log.liggghts, bursts.txt, fluid_vtk/, particles_vtk/, restart
files) and knobs.json, cost.txt, replay.json (where it started, how far its rows agree with the run's). Then

  render_snapshot.py DIR --keep      # the three snapshots, and snapshots.npz that redraws them

--evidence EVIDENCE does that too and keeps the replay as the repository's snapshot figure:
its compact result (compact_study.py: knobs, bursts, thermo columns, snapshots.npz,
replay.json, cost) in EVIDENCE/runs/<run>_window and EVIDENCE/summary.txt, a one-run study
that `analyze.py EVIDENCE` draws (doc/paper/collection).
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ensemble  # noqa: E402
import run_cost  # noqa: E402
import studies  # noqa: E402
from study_io import read_knobs, thermo  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_DRIVER = os.path.join(REPO, "build", "liggghts_plugin", "liggghts-lbm")


def checkpoint_of(restart):
    """(DEM step, checkpoint name) of the fluid checkpoint a restart file names
    (fix lbm/pore writes <prefix>.<DEM step> into it; the files are <name>.<rank>)."""
    with open(restart, "rb") as f:
        m = re.search(rb"([\w.]+\.fluid)\.(\d+)", f.read())
    if not m:
        sys.exit(f"{restart}: names no fluid checkpoint (not a restart file of in.pore)")
    return int(m.group(2)), f"{m.group(1).decode()}.{m.group(2).decode()}"


def replay_knobs(knobs, restart, start, fluid_steps, vtk_every):
    """The run's knobs, resumed from `restart`, ending N fluid steps later, with VTK files."""
    n_dem = studies.run_dem_steps_per_fluid_step(knobs)
    end = start + fluid_steps * n_dem
    if end > int(knobs["warmup"]) + int(knobs["steps"]):
        sys.exit(f"--fluid-steps {fluid_steps}: the window ends past the run's last step "
                 f"{int(knobs['warmup']) + int(knobs['steps'])}")
    changed = dict(knobs, steps=end - int(knobs["warmup"]), vtk_every=vtk_every)
    return ensemble.resume_knobs(changed, os.path.abspath(restart))


def agreement(run_dir, replay_dir):
    """How the replay's thermo rows compare with the run's at the steps both have: the number
    of common steps, of those identical in every column, the first step that differs and the
    relative difference of P / P_out (pore[16]) there."""
    a, b = thermo(run_dir), thermo(replay_dir)
    if not a or not b:
        return dict(common=0, identical=0, first_difference=None, P_difference_there=None)
    columns = [c for c in b if c in a and c != "Step"]
    rows_a = {s: i for i, s in enumerate(a["Step"])}  # a resumed run's later row wins
    common = [(rows_a[s], j) for j, s in enumerate(b["Step"]) if s in rows_a]
    same = [all(a[c][i] == b[c][j] for c in columns) for i, j in common]
    first = next(((i, j) for (i, j), ok in zip(common, same) if not ok), None)
    difference = None
    if first and "pore[16]" in columns:
        p_run, p_replay = a["pore[16]"][first[0]], b["pore[16]"][first[1]]
        difference = abs(p_replay - p_run) / max(abs(p_run), 1e-300)
    return dict(common=len(common), identical=sum(same),
                first_difference=b["Step"][first[1]] if first else None, P_difference_there=difference)


def keep_as_evidence(replay_dir, run_name, evidence):
    """The replay's snapshot frames (render_snapshot --keep) and compact result kept in
    `evidence` as the collection figure's one run."""
    import compact_study
    from render_snapshot import render
    render(replay_dir, os.path.join(replay_dir, "collection.png"), keep=True,
           name=f"{run_name}, a window replayed from its restart file")
    name = f"{run_name}_window"
    compact_study.compact_run(replay_dir, os.path.join(evidence, "runs", name))
    with open(os.path.join(evidence, "summary.txt"), "w") as f:
        f.write(f"study collection (paper, replay): 1 finished, 0 failed, 0 incomplete of 1 kept here\n"
                f"  {name:<28} done\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--restart", required=True)
    parser.add_argument("--fluid-steps", type=int, required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--vtk-every", type=int, default=250,
                        help="fluid steps between VTK files (default 250: a burst's fall takes "
                             "some thousands at the paper's regime)")
    parser.add_argument("--driver", default=DEFAULT_DRIVER)
    parser.add_argument("--ranks", type=int, default=1,
                        help="MPI ranks: those of the run (run_study.py's default 1)")
    parser.add_argument("--scene", help="scene script (default: <study>/in.pore)")
    parser.add_argument("--evidence", help="keep the replay as the repository's snapshot figure here")
    args = parser.parse_args()

    run_dir = os.path.abspath(args.run_dir)
    knobs = read_knobs(run_dir)
    start, checkpoint = checkpoint_of(args.restart)
    out = os.path.abspath(args.out)
    if os.path.exists(os.path.join(out, "log.liggghts")):
        sys.exit(f"{out}: holds a replay already; give another --out")
    os.makedirs(out, exist_ok=True)
    scene = os.path.join(out, "in.pore")
    shutil.copyfile(args.scene or os.path.join(run_dir, "..", "..", "in.pore"), scene)
    # in.pore reads the checkpoint by the name the restart file holds, from the run's folder
    for path in glob.glob(os.path.join(os.path.dirname(os.path.abspath(args.restart)), checkpoint + ".*")):
        target = os.path.join(out, os.path.basename(path))
        if not os.path.exists(target):
            os.symlink(path, target)
    launch = replay_knobs(knobs, args.restart, start, args.fluid_steps, args.vtk_every)
    with open(os.path.join(out, "knobs.json"), "w") as f:
        json.dump({k: str(v) for k, v in launch.items() if k not in ("resume", "resume_file")},
                  f, indent=1, sort_keys=True)
    launch_dir = os.path.join(out, "launch")
    os.makedirs(launch_dir, exist_ok=True)
    ensemble.write_run_file(launch_dir, 1, out, launch, scene)
    cmd = ensemble.study_command(args.driver, launch_dir, 1, 1, args.ranks, None)
    # One thread per rank, as the study's runs beside each other (the bits do not depend on
    # it); a rank's threads on a machine the study's runs already fill would wait on each other.
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    print("replay: " + " ".join(cmd), flush=True)
    with open(os.path.join(out, "stdout.txt"), "w") as log, run_cost.LaunchClock([out], args.ranks):
        rc = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT)
    agree = agreement(run_dir, out)
    record = dict(run=os.path.basename(run_dir), restart=os.path.basename(args.restart),
                  start_dem_step=start, fluid_steps=args.fluid_steps, vtk_every=args.vtk_every,
                  ranks=args.ranks, exit_code=rc, **agree)
    with open(os.path.join(out, "replay.json"), "w") as f:
        json.dump(record, f, indent=1)
    print(f"replay: exit {rc}; thermo rows in common with the run {agree['common']}, identical "
          f"{agree['identical']}, first difference at step {agree['first_difference']} "
          f"(P / P_out there {agree['P_difference_there']} apart, relative)")
    if rc == 0 and args.evidence:
        keep_as_evidence(out, record["run"], os.path.abspath(args.evidence))
        print(f"replay: kept in {args.evidence}; draw it with analyze.py {args.evidence}")
    sys.exit(rc)


if __name__ == "__main__":
    main()
