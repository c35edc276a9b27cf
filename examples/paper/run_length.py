#!/usr/bin/env python3
"""How long a phase-diagram run must be: the highest pressure loss P_max [P_out] (f_pore[16]
after the warm-up) that each run reaches within 10^5, 2.5 x 10^5, 5 x 10^5 and 10^6 fluid
steps, against its own at its full length. The phase diagrams (phaseac, phasead, conc,
pvpflux) may use the shortest length whose P_max is within 10 % of the full length's on every
run given (doc/paper.md, "The studies' settings").

  python3 examples/paper/run_length.py RUN_DIR [RUN_DIR ...]

A run folder holds log.liggghts or thermo.csv.gz (compact_study.py) and knobs.json.
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from study_io import thermo  # noqa: E402
from studies import run_dem_steps_per_fluid_step  # noqa: E402

LENGTHS = (1e5, 2.5e5, 5e5, 1e6)  # fluid steps
AGREEMENT = 0.10


def p_max_by_length(run_dir):
    with open(os.path.join(run_dir, "knobs.json")) as f:
        knobs = json.load(f)
    per_fluid_step = run_dem_steps_per_fluid_step(knobs)
    columns = thermo(run_dir)
    warmup = float(knobs.get("warmup", 0))
    rows = [(s / per_fluid_step, p) for s, p in zip(columns.get("Step", []), columns.get("pore[16]", []))
            if s > warmup]
    if not rows:
        return None
    full_length = rows[-1][0]
    full = max(p for _, p in rows)
    return full_length, full, {L: max((p for t, p in rows if t <= L), default=float("nan"))
                               for L in LENGTHS if L <= full_length * 1.0001}


def shortest_length(run_dirs):
    """(the shortest of LENGTHS whose P_max is within AGREEMENT of the full length's on every
    run, or None; a line per run)."""
    shortest_ok = {L: True for L in LENGTHS}
    lines = []
    for run_dir in run_dirs:
        found = p_max_by_length(run_dir)
        if found is None:
            lines.append(f"{run_dir}: no thermo rows after the warm-up")
            continue
        full_length, full, by_length = found
        parts = []
        for L in LENGTHS:
            if L not in by_length:
                shortest_ok[L] = False
                continue
            ratio = by_length[L] / full
            shortest_ok[L] &= abs(ratio - 1.0) <= AGREEMENT
            parts.append(f"{L:.3g}: {by_length[L]:.3f} ({ratio:.2f})")
        lines.append(f"{run_dir}: {full_length:.3g} fluid steps, P_max {full:.3f} P_out; within " + ", ".join(parts))
    ok = [L for L in LENGTHS if shortest_ok[L]]
    return (min(ok) if ok else None), lines


def main(argv):
    if not argv:
        sys.exit(__doc__)
    shortest, lines = shortest_length(argv)
    print("\n".join(lines))
    print(f"shortest length whose P_max is within {AGREEMENT:.0%} of the full length's on every run: "
          + (f"{shortest:.3g} fluid steps" if shortest else "none"))


if __name__ == "__main__":
    main(sys.argv[1:])
