#!/usr/bin/env python3
"""Physics checks of the liggghts-lbm styles: runs one input script and compares the thermo
output with the paper's analytic values. Prints the measured figures; exits 1 on failure.

usage: dem_check.py --driver PATH --scripts DIR CASE
cases: bond_hold, bond_break, restitution, adhesion_hold, adhesion_break, tilt_stick,
       tilt_slide, parallel_equal
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

R = 3.5
K_C = K_A = 0.1
F_COHESION_MAX = 0.03 * K_C * R * R  # paper Eq. 2 at h = 0.03 (Ri+Rj): 0.03 kc Ri Rj
F_ADHESION_MAX = 0.03 * K_A * R * R  # paper Eq. 4 at h = 0.03 Ri: 0.03 ka R^2


def run(driver, scripts, script, variables, ranks=1):
    work = tempfile.mkdtemp(prefix="dem_check_")
    cmd = [driver, "-in", os.path.join(scripts, script), "-log", os.path.join(work, "log"),
           "-var", "dir", scripts]
    for name, value in variables.items():
        cmd += ["-var", name, str(value)]
    if ranks > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, errors="replace", timeout=120)
    if out.returncode != 0 or "ERROR" in out.stdout:
        print(out.stdout[-3000:])
        sys.exit("liggghts-lbm failed")
    return out.stdout, work


def thermo_rows(output):
    """All thermo rows of all runs, as dicts keyed by the column names."""
    rows, header = [], None
    for line in output.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header = words
            continue
        if header and words and words[0] == "Loop":
            header = None
            continue
        if header and len(words) == len(header):
            try:
                values = [float(w) for w in words]
            except ValueError:
                continue
            rows.append(dict(zip(header, values)))
    return rows


def check(condition, message):
    print(("PASS " if condition else "FAIL ") + message)
    return condition


def bond(args, load_factor):
    out, _ = run(args.driver, args.scripts, "in.bond", {"load_factor": load_factor})
    rows = thermo_rows(out)
    settled = [r for r in rows if r["Step"] == 20000][0]
    ok = check(settled["bonds"] == 1 and abs(settled["gap"]) < 0.21,
               f"bond formed during settling: bonds={settled['bonds']:.0f} gap={settled['gap']:.4g}")
    loaded = [r for r in rows if r["Step"] > 20000]
    if load_factor < 1.0:
        ok &= check(all(r["bonds"] == 1 for r in loaded),
                    f"bond holds at {load_factor} x the peak cohesive force {F_COHESION_MAX:.5g}")
        # Static equilibrium in the cohesive range: F = h kc RiRj/(Ri+Rj) -> h = F / (kc R/2).
        held = [r["gap"] for r in loaded if r["Step"] >= 52000]
        predicted = load_factor * F_COHESION_MAX / (K_C * R / 2)
        mean_gap = sum(held) / len(held)
        ok &= check(abs(mean_gap - predicted) <= 0.05 * predicted,
                    f"held gap {mean_gap:.5g} vs predicted {predicted:.5g} (bound 5%)")
    else:
        broken = [r for r in loaded if r["bonds"] == 0]
        ok &= check(len(broken) > 0, "bond breaks")
        if broken:
            load = broken[0]["load"]
            err = (load - F_COHESION_MAX) / F_COHESION_MAX
            ok &= check(abs(err) <= 0.02,
                        f"break load {load:.5g} vs predicted 0.03 kc Ri Rj = {F_COHESION_MAX:.5g} "
                        f"(error {100 * err:+.2f}%, bound 2%)")
            # (They then leave the box; the largest gap seen shows they moved apart.)
            widest = max(r["gap"] for r in broken)
            ok &= check(widest > 1.0, f"particles separate after the break: gap reaches {widest:.3g}")
    return ok


def restitution(args):
    ok = True
    for zeta in (0.25, 0.5):
        out, _ = run(args.driver, args.scripts, "in.collision", {"zeta": zeta})
        rows = thermo_rows(out)
        e = rows[-1]["vrel"] / -rows[0]["vrel"]
        expected = math.exp(-math.pi * zeta / math.sqrt(1 - zeta * zeta))
        err = (e - expected) / expected
        ok &= check(abs(err) <= 0.01, f"zeta {zeta}: restitution {e:.5f} vs analytic {expected:.5f} "
                                      f"(error {100 * err:+.3f}%, bound 1%)")
        ok &= check(rows[-1]["bonds"] == 0, "no bond without cohesion after the collision")
    return ok


def adhesion(args, load_factor):
    out, _ = run(args.driver, args.scripts, "in.wall_adhesion", {"load_factor": load_factor})
    rows = thermo_rows(out)
    settled = [r for r in rows if r["Step"] == 20000][0]
    ok = check(settled["wall[1]"] == 1 and abs(settled["gap"]) < 0.105,
               f"particle adheres: contacts={settled['wall[1]']:.0f} gap={settled['gap']:.4g}")
    loaded = [r for r in rows if r["Step"] > 20000]
    if load_factor < 1.0:
        ok &= check(all(r["wall[1]"] == 1 for r in loaded),
                    f"holds at {load_factor} x the adhesion limit {F_ADHESION_MAX:.5g}")
        held = [r["gap"] for r in loaded if r["Step"] >= 52000]
        predicted = load_factor * F_ADHESION_MAX / (K_A * R)
        mean_gap = sum(held) / len(held)
        ok &= check(abs(mean_gap - predicted) <= 0.05 * predicted,
                    f"held gap {mean_gap:.5g} vs predicted h = F/(ka R) = {predicted:.5g} (bound 5%)")
    else:
        off = [r for r in loaded if r["wall[1]"] == 0]
        ok &= check(len(off) > 0, "particle torn off")
        if off:
            load = off[0]["load"]
            err = (load - F_ADHESION_MAX) / F_ADHESION_MAX
            ok &= check(abs(err) <= 0.02,
                        f"tear-off load {load:.5g} vs predicted 0.03 ka R^2 = {F_ADHESION_MAX:.5g} "
                        f"(error {100 * err:+.2f}%, bound 2%)")
    return ok


def make_floor(path):
    nx, ny, nz = 240, 12, 6
    data = bytearray(nx * ny * nz)
    for k in range(3):  # solid k = 0..2: top face at z = 2.5
        for j in range(ny):
            for i in range(nx):
                data[(k * ny + j) * nx + i] = 1
    with open(path, "wb") as f:
        f.write(f"LBMPORE_VOXELS 1\n{nx} {ny} {nz}\n1 0 0 0\n".encode())
        f.write(bytes(data))


def tilt(args, slide):
    mu, g, mass = 0.3, 1e-5, 2.3 * 4.0 / 3.0 * math.pi * R ** 3
    friction_angle = math.degrees(math.atan(mu))
    angle = friction_angle + (3.0 if slide else -3.0)
    voxels = os.path.join(tempfile.mkdtemp(prefix="dem_floor_"), "floor.raw")
    make_floor(voxels)
    out, _ = run(args.driver, args.scripts, "in.tilted_wall",
                 {"voxels": voxels, "angle": angle, "mu": mu})
    rows = thermo_rows(out)
    start = [r for r in rows if r["Step"] == 10000][0]
    end = rows[-1]
    overlap = 2.5 + R - start["zpos"]
    ok = check(abs(overlap - mass * g / 0.1) < 0.01 * mass * g / 0.1,
               f"settled overlap {overlap:.5g} vs m g / kw = {mass * g / 0.1:.5g} (bound 1%)")
    distance = end["xpos"] - start["xpos"]
    t = end["Step"] - start["Step"]
    theta = math.radians(angle)
    if slide:
        # Acceleration from the velocity after the normal load has adjusted to the tilt
        # (the first 2000 steps carry the normal rebound to the new overlap m g cos / kw).
        steady = [r for r in rows if r["Step"] >= 12000]
        accel = (steady[-1]["speed"] - steady[0]["speed"]) / (steady[-1]["Step"] - steady[0]["Step"])
        predicted = g * (math.sin(theta) - mu * math.cos(theta))
        err = (accel - predicted) / predicted
        ok &= check(abs(err) <= 0.01,
                    f"tilt {angle:.2f} deg > atan(mu) = {friction_angle:.2f}: slides {distance:.4g} "
                    f"(across {int(distance)} voxels) with acceleration {accel:.6g} vs "
                    f"g (sin - mu cos) = {predicted:.6g} (error {100 * err:+.3f}%, bound 1%)")
        # Smooth sliding over the voxel faces: the height does not change.
        heights = [r["zpos"] for r in steady]
        ok &= check(max(heights) - min(heights) < 1e-6,
                    f"height variation while sliding {max(heights) - min(heights):.3g} (bound 1e-6)")
    else:
        # The tangential spring stretches by m g sin / kt and then holds: no creep.
        spring = mass * g * math.sin(theta) / (0.1 * 2.0 / 7.0)
        ok &= check(abs(distance) <= 2.0 * spring and abs(end["speed"]) < 1e-7,
                    f"tilt {angle:.2f} deg < atan(mu) = {friction_angle:.2f}: moved {distance:.3g} "
                    f"(spring stretch {spring:.3g}, bound 2x), final speed {end['speed']:.2g} (bound 1e-7)")
    return ok


def parallel_equal(args):
    """Serial and 2-rank runs of the bond script give the same thermo numbers."""
    serial, _ = run(args.driver, args.scripts, "in.bond", {"load_factor": 1.2})
    parallel, _ = run(args.driver, args.scripts, "in.bond", {"load_factor": 1.2}, ranks=2)
    a, b = thermo_rows(serial), thermo_rows(parallel)
    worst = max(abs(x[k] - y[k]) for x, y in zip(a, b) for k in x)
    return check(len(a) == len(b) and worst < 1e-9,
                 f"serial vs 2 ranks: {len(a)} rows, largest difference {worst:.3g} (bound 1e-9)")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--scripts", required=True)
    parser.add_argument("case")
    args = parser.parse_args()
    cases = {
        "bond_hold": lambda: bond(args, 0.95),
        "bond_break": lambda: bond(args, 1.2),
        "restitution": lambda: restitution(args),
        "adhesion_hold": lambda: adhesion(args, 0.95),
        "adhesion_break": lambda: adhesion(args, 1.2),
        "tilt_stick": lambda: tilt(args, False),
        "tilt_slide": lambda: tilt(args, True),
        "parallel_equal": lambda: parallel_equal(args),
    }
    sys.exit(0 if cases[args.case]() else 1)


if __name__ == "__main__":
    main()
