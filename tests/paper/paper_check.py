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
            covering nearly all of it).

Usage: paper_check.py --driver liggghts-lbm --repo <source root> --python /usr/bin/python3 <case>
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


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
    ok &= check("plot written", os.path.getsize(results["plot"]) > 10000,
                os.path.getsize(results["plot"]), "> 10 kB")
    return ok


def snapshot(args, work):
    run_study(args, work, "collection", "--size", "tiny")
    png = os.path.join(work, "collection.png")
    if not check("image written", os.path.exists(png), os.path.exists(png), "exists"):
        return False
    probe = ("import matplotlib.image as m, numpy as n, sys; a = m.imread(sys.argv[1])[..., :3];"
             "q = (a * 255).astype(int).reshape(-1, 3); u, c = n.unique(q, axis=0, return_counts=True);"
             "print(len(u), c.max() / len(q))")
    colours, top = subprocess.run([args.python, "-c", probe, png], capture_output=True,
                                  text=True, check=True).stdout.split()
    ok = check("image has many colours", int(colours) > 200, colours, "> 200 distinct")
    ok &= check("not one colour", float(top) < 0.9, top, "< 0.9 of the pixels (blank: 1)")
    return ok


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--repo", required=True)
    parser.add_argument("--python", default="/usr/bin/python3")
    parser.add_argument("case", choices=["ensemble", "snapshot"])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix=f"paper_{args.case}_") as work:
        ok = {"ensemble": ensemble, "snapshot": snapshot}[args.case](args, work)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
