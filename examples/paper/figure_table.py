#!/usr/bin/python3
"""doc/paper.md's table of the paper's figures: a row per figure with the paper's value, ours
with its 95 % interval, the runs finished of those planned and their length, their cost, the
verdict against the criteria (verdicts.py) and the plot. Read from what the repository keeps:
doc/paper/<figure>/results.json (analyze.py) and its runs' compact results; a figure drawn
from another study's runs (singlejump, collection) keeps its results in the same place
(`analyze.py doc/paper/<study> --figure singlejump --out doc/paper`).

  figure_table.py            rewrite the table between its markers in doc/paper.md
  figure_table.py --check    exit 1 if the table there is not the one the evidence gives
"""
import argparse
import glob
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_length  # noqa: E402
import studies  # noqa: E402
import study_io  # noqa: E402
import verdicts  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOC = os.path.join(REPO, "doc", "paper.md")
BEGIN, END = "<!-- paper:figures:begin (examples/paper/figure_table.py) -->", "<!-- paper:figures:end -->"
FIGURES = ("singlejump", "collection", "dropvol", "porelength", "porediameter", "phaseac",
           "phasead", "conc", "pvpflux")
# The runs a figure plans to take from other studies' folders beside its own (analyze.py
# --with), each one run: counted in its plan whether finished or not.
WITH = {"dropvol": studies.DROPVOL_BESIDE}
# The figures drawn from one run of another study.
FROM_ONE_RUN = ("singlejump", "collection")


def _power_of_ten(value):
    """2.52 x 10^5, 10^6."""
    exponent = len(str(int(value))) - 1
    mantissa = value / 10 ** exponent
    return f"10^{exponent}" if mantissa == 1 else f"{mantissa:.3g} x 10^{exponent}"


def _finished(folder):
    """The finished runs of a study folder, or 1 or 0 for one run's folder (its state.txt)."""
    if os.path.exists(os.path.join(folder, "knobs.json")):
        state = os.path.join(folder, "state.txt")
        if not os.path.exists(state):
            return 0
        with open(state) as f:
            return int(f.readline().strip() == "done")
    if not os.path.exists(os.path.join(folder, "summary.txt")):
        return 0
    return study_io.load_summary(folder)["finished"]


def row(figure, repo=REPO):
    evidence = os.path.join(repo, "doc", "paper", figure)
    path = os.path.join(evidence, "results.json")
    results = None
    if os.path.exists(path):
        with open(path) as f:
            results = json.load(f)
    cost = None
    if results and results.get("core_hours"):
        cost = f"{results['core_hours']:.1f}" + ("" if results.get("core_hours_exact") else " (at least)")
    if figure in FROM_ONE_RUN:
        planned, finished = 1, 1 if results and results.get("finished") else 0
        length = "one paper-length run"
        cost = cost or "—"
    else:
        runs = studies.runs_of(figure, "paper")
        beside = list(WITH.get(figure, ()))
        taken = results["with"] if results and "with" in results else beside
        planned = len(runs) + sum(max(1, _finished(os.path.join(repo, w))) for w in set(beside) | set(taken))
        finished = _finished(evidence) + sum(_finished(os.path.join(repo, w)) for w in taken)
        steps = {int(k["steps"]) // studies.run_dem_steps_per_fluid_step(k) for _, k in runs}
        length = " / ".join(_power_of_ten(s) for s in sorted(steps)) + " fluid steps after the warm-up"
        cost = cost or f"est. {studies.core_hours(runs):.0f}"
    ours, verdict = verdicts.verdict(figure, results, finished, planned)
    plot = ""
    if results and results.get("plot"):
        plot = f"![{figure}](paper/{figure}/{os.path.basename(results['plot'])})"
    cells = [figure, verdicts.PAPER[figure], ours or "—", f"{finished} of {planned}; {length}",
             cost, verdict, plot]
    return "| " + " | ".join(c.replace("|", "/") for c in cells) + " |"


# The finished paper-length runs, which set the phase diagrams' length (run_length.py).
PAPER_LENGTH_RUNS = ("doc/calibration/paper_run/runs/*", "doc/paper/porediameter/runs/*",
                     "doc/paper/porelength/runs/*", "doc/paper/dropvol/runs/*")


def paper_length_runs(repo=REPO):
    def done(run):
        try:
            with open(os.path.join(run, "state.txt")) as f:
                return f.readline().strip() == "done"
        except OSError:
            return False
    return sorted(run for pattern in PAPER_LENGTH_RUNS for run in glob.glob(os.path.join(repo, pattern))
                  if done(run))


def phase_diagram_length(repo=REPO):
    """(the length the rule gives on the committed paper-length runs, how many runs)."""
    runs = paper_length_runs(repo)
    shortest, _ = run_length.shortest_length(runs)
    return shortest, len(runs)


def table(repo=REPO):
    lines = ["| figure | paper | ours (95 % interval) | runs finished; length | core-hours | verdict | plot |",
             "|---|---|---|---|---|---|---|"]
    shortest, count = phase_diagram_length(repo)
    rule = (f"The phase diagrams' length by its rule (`run_length.py` on the {count} finished "
            f"paper-length runs kept): {_power_of_ten(shortest) if shortest else 'none'} fluid steps; "
            f"they run {_power_of_ten(studies.PHASE_DIAGRAM_STEPS // studies.N_DEM)}.")
    return "\n".join(lines + [row(f, repo) for f in FIGURES] + ["", rule])


def replaced(text, new_table):
    start, end = text.index(BEGIN) + len(BEGIN), text.index(END)
    return text[:start] + "\n" + new_table + "\n" + text[end:]


def rewrite_doc(check=False):
    """Rewrites the table in doc/paper.md; with check, only says whether it is current."""
    with open(DOC) as f:
        text = f.read()
    new = replaced(text, table())
    if check or new == text:
        return new == text
    with open(DOC + ".new", "w") as f:
        f.write(new)
    os.replace(DOC + ".new", DOC)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    if not rewrite_doc(args.check):
        print("doc/paper.md's table of the figures is not the one the evidence gives: "
              "run examples/paper/figure_table.py", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
