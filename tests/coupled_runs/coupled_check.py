#!/usr/bin/env python3
"""Integration checks of fix lbm/pore: runs liggghts-lbm on the tiny scenes of this folder and
compares what it measures with a physical expectation or a reference run. Prints every figure
with its bound; exits 1 when one fails.

usage: coupled_check.py --driver liggghts-lbm --scripts DIR [--mpirun mpirun] CASE
CASE: adhesion | clog | parallel | restart | bad_arguments
"""
import argparse
import math
import re
import os
import subprocess
import sys
import tempfile

FAILURES = []


def check(name, value, ok, bound):
    print(f"{'PASS' if ok else 'FAIL'} {name} = {value} ({bound})")
    if not ok:
        FAILURES.append(name)


def run(cmd, cwd, timeout=240):
    result = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace",
                            timeout=timeout)
    return result.returncode, result.stdout + result.stderr


def liggghts(args, script, variables, cwd, ranks=1, expect_ok=True):
    cmd = [args.driver, "-in", os.path.join(args.scripts, script), "-var", "dir", args.scripts]
    for key, value in variables.items():
        cmd += ["-var", key, str(value)]
    if ranks > 1:
        cmd = [args.mpirun, "-np", str(ranks), "--oversubscribe"] + cmd
    code, out = run(cmd, cwd)
    if expect_ok and (code != 0 or "ERROR" in out):
        print(out[-3000:])
        sys.exit(f"FAIL {script} {variables}: liggghts-lbm failed (exit {code})")
    return code, out


def thermo(out):
    """The rows of the last thermo block, as dicts keyed by the header words without LIGGGHTS's
    v_/f_/c_ prefixes (it prints some headers with them, some without)."""
    header, rows = None, []
    for line in out.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header, rows = [re.sub(r"^[vfc]_", "", w) for w in words], []
            continue
        if header and len(words) == len(header):
            try:
                rows.append(dict(zip(header, (float(w) for w in words))))
            except ValueError:
                pass
    return rows


def at(rows, step):
    return next(r for r in rows if r["Step"] == step)


def relative(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def case_adhesion(args, work):
    """A particle pressed on the pore's floor by its net weight is held by wall friction and
    adhesion at a low inlet velocity and torn off at a high one; the threshold predicted from
    the held particle's drag (Stokes: linear in velocity) and Coulomb's mu N lies between."""
    u_low, u_high, steps = 5e-5, 4e-4, 60000
    rows_low = thermo(liggghts(args, "in.adhesion", {"u": u_low, "steps": steps}, work)[1])
    rows_high = thermo(liggghts(args, "in.adhesion", {"u": u_high, "steps": steps}, work)[1])
    # Displacement along the flow after the particle settled (step 20000 on).
    held = abs(at(rows_low, steps)["px"] - at(rows_low, 20000)["px"])
    torn = at(rows_high, steps)["px"] - at(rows_high, 20000)["px"]
    check("adhesion_held_displacement_cells", f"{held:.4g}", held < 0.05, "< 0.05 at u = 5e-5")
    check("adhesion_torn_off_displacement_cells", f"{torn:.4g}", torn > 0.1, "> 0.1 at u = 4e-4")
    drag = sum(r["fx"] for r in rows_low if 30000 <= r["Step"] <= 50000) / \
        sum(1 for r in rows_low if 30000 <= r["Step"] <= 50000)
    volume = 4.0 / 3.0 * math.pi * 3.5 ** 3
    normal = (2.3 - 1.0) * volume * 1e-4  # net weight (rho_p - rho) V g
    threshold = 0.5 * normal / (drag / u_low)  # mu N / (drag per inlet velocity)
    print(f"INFO held drag {drag:.4g}, drag per inlet velocity {drag / u_low:.4g}, "
          f"mu N = {0.5 * normal:.4g}, predicted threshold u* = {threshold:.4g}")
    check("adhesion_threshold_above_held_velocity", f"{threshold / u_low:.3g}",
          threshold / u_low > 1.2, "u*/u_low > 1.2")
    check("adhesion_threshold_below_tear_off_velocity", f"{u_high / threshold:.3g}",
          u_high / threshold > 1.2, "u_high/u* > 1.2")


def case_clog(args, work):
    """Four particles jam in the mouth of a pore narrower than two diameters: the pressure
    loss must rise well above its particle-free value."""
    out = liggghts(args, "in.clog", {"clean_steps": 100000, "steps": 150000,
                                     "restart_read": "", "restart_write": ""}, work)[1]
    clean = float(next(l.split()[1] for l in out.splitlines() if l.startswith("CLEAN_PRESSURE")))
    final = thermo(out)[-1]["p"]
    check("clog_pressure_rise", f"{final / clean:.3g}", final / clean > 2.0,
          f"pressure loss {final:.4g} vs particle-free {clean:.4g}: ratio > 2")


def case_parallel(args, work):
    """Two particles cross the middle of the lattice, where 2 ranks split the fluid and the
    particles: pressure loss, hydrodynamic force and positions equal the serial run."""
    variables = {"steps": 200000}
    serial = thermo(liggghts(args, "in.transit", dict(variables, px=1), work)[1])
    split = thermo(liggghts(args, "in.transit", dict(variables, px=2), work, ranks=2)[1])
    crossed = any(r["x1"] > 15.0 for r in serial)
    check("parallel_particle_crossed_the_rank_boundary", crossed, crossed, "x1 > 15 at some step")
    for column, bound in (("p", 1e-5), ("x1", 1e-5), ("y2", 1e-5), ("fx", 1e-3)):
        # Relative to the column's largest magnitude: the force passes through zero.
        scale = max(abs(r[column]) for r in serial)
        worst = max(abs(a[column] - b[column]) for a, b in zip(serial, split)) / scale
        check(f"parallel_max_difference_{column}", f"{worst:.3g}", worst < bound,
              f"< {bound:g} of its largest value (1 vs 2 ranks; contacts amplify round-off)")


def case_restart(args, work):
    """write_restart + read_restart in a second process continue as if never stopped."""
    common = {"clean_steps": 100000, "restart_read": ""}
    whole = thermo(liggghts(args, "in.clog", dict(common, steps=40000, restart_write=""), work)[1])
    liggghts(args, "in.clog", dict(common, steps=20000, restart_write="write_restart clog.restart"), work)
    second = thermo(liggghts(args, "in.restart_b", {"restart_file": "clog.restart", "steps": 20000}, work)[1])
    a, b = whole[-1], second[-1]
    check("restart_same_final_step", b["Step"], a["Step"] == b["Step"], f"== {a['Step']:.0f}")
    for column, bound in (("p", 1e-6), ("x1", 1e-6), ("z5", 1e-6), ("pore[14]", 1e-3)):
        diff = relative(a[column], b[column])
        check(f"restart_relative_difference_{column}", f"{diff:.3g}", diff < bound, f"< {bound:g}")


BAD = "scene pore inlet 6 free 4 length 14 outlet 6 width 20 diameter 15"
BAD_CASES = [  # (fix line, second line, boundary, words the error must contain)
    (f"fix f all lbm/pore {BAD} velocity 0.001", "", "p", ["'dx'", "> 0", "required"]),
    (f"fix f all lbm/pore dx 1 nu -1 {BAD} velocity 0.001", "", "p", ["'nu'", "(0, inf]"]),
    (f"fix f all lbm/pore dx 1 n_dem 0 {BAD} velocity 0.001", "", "p", ["'n_dem'", "[1, 100000]"]),
    (f"fix f all lbm/pore dx 1 colour red {BAD} velocity 0.001", "", "p", ["'colour'", "valid keywords"]),
    ("fix f all lbm/pore dx 1 scene pore inlet 6 free 4 length 14 outlet 6 width 20 diameter 25 "
     "velocity 0.001", "", "p", ["diameter", "width"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 1.0", "", "p", ["velocity", "0.30"]),
    (f"fix f all lbm/pore dx 1 {BAD} pressure_loss 5", "", "p", ["pressure_loss", "0.1"]),
    ("fix f all lbm/pore dx 1 scene pore inlet 6 free 4 length 14 outlet 16 width 20 diameter 15 "
     "velocity 0.001", "", "p", ["scene", "simulation box"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001 lateral wall", "", "p", ["lateral", "boundary"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001 boundary fancy", "", "p", ["'boundary'", "mls"]),
    ("fix f all lbm/pore dx 1 scene voxels /nonexistent.raw velocity 0.001", "", "p",
     ["/nonexistent.raw", "cannot be opened"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001", "fix w all wall/voxel lbm nothere", "p",
     ["wall/voxel", "'nothere'"]),
]


def case_bad_arguments(args, work):
    """Every bad input stops with a LIGGGHTS ERROR naming the keyword (and the range), quickly,
    without a crash or a NaN."""
    for line, line2, boundary, words in BAD_CASES:
        try:
            code, out = liggghts(args, "in.bad", {"fixline": line, "fixline2": line2, "bnd": boundary},
                                 work, expect_ok=False)
        except subprocess.TimeoutExpired:
            check(f"bad_arguments[{line}]", "timeout", False, "an error within the timeout")
            continue
        error = next((l for l in out.splitlines() if l.startswith("ERROR")), "")
        ok = code != 0 and error and all(w in error for w in words) and "nan" not in error.lower()
        check(f"bad_arguments[{line2 or line}]", repr(error[:160]), ok, f"ERROR naming {words}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--scripts", required=True)
    parser.add_argument("--mpirun", default="mpirun")
    parser.add_argument("case")
    args = parser.parse_args()
    args.scripts = os.path.abspath(args.scripts)
    with tempfile.TemporaryDirectory(prefix=f"coupled_{args.case}_") as work:
        globals()[f"case_{args.case}"](args, work)
    if FAILURES:
        sys.exit(f"{len(FAILURES)} check(s) failed: {', '.join(FAILURES)}")


if __name__ == "__main__":
    main()
