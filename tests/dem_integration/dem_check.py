#!/usr/bin/env python3
"""Physics checks of the liggghts-lbm styles: runs one input script and compares the thermo
output with the paper's analytic values. Prints each measured figure and its bound
(tests/harness/liggghts_run.py); exits 1 on failure.

usage: dem_check.py --driver PATH --scripts DIR [--mpirun mpirun] [--liggghts PATH] CASE
cases: bond_hold, bond_break, restitution, adhesion_hold, adhesion_break, tilt_stick,
       tilt_slide, parallel_equal, insert_gap, restart_version (needs --liggghts, Debian's
       liggghts)
"""
import math
import os
import re
import struct
from collections import namedtuple

from liggghts_run import at_step, check, main, thermo_rows

R = 3.5
K_C = K_A = 0.1
F_COHESION_MAX = 0.03 * K_C * R * R  # paper Eq. 2 at h = 0.03 (Ri+Rj): 0.03 kc Ri Rj
F_ADHESION_MAX = 0.03 * K_A * R * R  # paper Eq. 4 at h = 0.03 Ri: 0.03 ka R^2

# A short-range attraction loaded by a force ramped to `load_factor` x its peak and held:
# the script, the thermo column counting the contacts, the gap bound after settling, the
# peak force and its formula, the slope of the force in the gap (F = slope h) and its
# formula, and whether the pair must also be seen to separate after the break.
Attraction = namedtuple("Attraction", "name script column settled_gap peak peak_law slope "
                                      "slope_law separates")
BOND = Attraction("bond", "in.bond", "bonds", 0.21, F_COHESION_MAX, "0.03 kc Ri Rj",
                  K_C * R / 2, "kc R/2", True)  # F = h kc RiRj/(Ri+Rj)
ADHESION = Attraction("adhesion", "in.wall_adhesion", "wall[1]", 0.105, F_ADHESION_MAX,
                      "0.03 ka R^2", K_A * R, "ka R", False)  # F = h ka R


def hold_or_break(h, attraction, load_factor):
    """Below the peak (load_factor < 1) the contact holds at the static gap h = F / slope;
    above it, it breaks at the peak force."""
    a = attraction
    rows = thermo_rows(h.run(a.script, {"load_factor": load_factor}).output)
    settled = at_step(rows, 20000)
    check(f"{a.name}_formed_during_settling",
          settled[a.column] == 1 and abs(settled["gap"]) < a.settled_gap,
          f"{settled[a.column]:.0f} contact(s), gap {settled['gap']:.4g}",
          f"1 contact, |gap| < {a.settled_gap}")
    loaded = [r for r in rows if r["Step"] > 20000]
    if load_factor < 1.0:
        check(f"{a.name}_holds", all(r[a.column] == 1 for r in loaded),
              f"{sum(r[a.column] != 1 for r in loaded)} of {len(loaded)} loaded rows without it",
              f"none, at {load_factor} x the peak force {a.peak_law} = {a.peak:.5g}")
        # Static equilibrium in the attractive range: F = slope h -> h = F / slope.
        held = [r["gap"] for r in loaded if r["Step"] >= 52000]
        predicted = load_factor * a.peak / a.slope
        mean_gap = sum(held) / len(held)
        check(f"{a.name}_held_gap", abs(mean_gap - predicted) <= 0.05 * predicted,
              f"{mean_gap:.5g}", f"within 5 % of h = F/({a.slope_law}) = {predicted:.5g}")
        return
    broken = [r for r in loaded if r[a.column] == 0]
    check(f"{a.name}_breaks", len(broken) > 0, f"{len(broken)} loaded rows without it", "> 0")
    if not broken:
        return
    load = broken[0]["load"]
    err = (load - a.peak) / a.peak
    check(f"{a.name}_break_load", abs(err) <= 0.02, f"{load:.5g} (error {100 * err:+.2f} %)",
          f"within 2 % of {a.peak_law} = {a.peak:.5g}")
    if a.separates:
        # (They then leave the box; the largest gap seen shows they moved apart.)
        widest = max(r["gap"] for r in broken)
        check(f"{a.name}_separates_after_break", widest > 1.0, f"largest gap {widest:.3g}", "> 1")


def restitution(h):
    for zeta in (0.25, 0.5):
        rows = thermo_rows(h.run("in.collision", {"zeta": zeta}).output)
        e = rows[-1]["vrel"] / -rows[0]["vrel"]
        expected = math.exp(-math.pi * zeta / math.sqrt(1 - zeta * zeta))
        err = (e - expected) / expected
        check(f"restitution_zeta_{zeta}", abs(err) <= 0.01, f"{e:.5f} (error {100 * err:+.3f} %)",
              f"within 1 % of exp(-pi zeta / sqrt(1 - zeta^2)) = {expected:.5f}")
        check(f"no_bond_after_collision_zeta_{zeta}", rows[-1]["bonds"] == 0,
              f"{rows[-1]['bonds']:.0f} bonds", "0 (no cohesion)")


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


def tilt(h, slide):
    mu, g, mass = 0.3, 1e-5, 2.3 * 4.0 / 3.0 * math.pi * R ** 3
    friction_angle = math.degrees(math.atan(mu))
    angle = friction_angle + (3.0 if slide else -3.0)
    tilted = f"tilt {angle:.2f} deg {'>' if slide else '<'} atan(mu) = {friction_angle:.2f}"
    voxels = os.path.join(h.work, "floor.raw")
    make_floor(voxels)
    rows = thermo_rows(h.run("in.tilted_wall", {"voxels": voxels, "angle": angle, "mu": mu}).output)
    start = at_step(rows, 10000)
    end = rows[-1]
    overlap = 2.5 + R - start["zpos"]
    check("tilt_settled_overlap", abs(overlap - mass * g / 0.1) < 0.01 * mass * g / 0.1,
          f"{overlap:.5g}", f"within 1 % of m g / kw = {mass * g / 0.1:.5g}")
    distance = end["xpos"] - start["xpos"]
    theta = math.radians(angle)
    if slide:
        # Acceleration from the velocity after the normal load has adjusted to the tilt
        # (the first 2000 steps carry the normal rebound to the new overlap m g cos / kw).
        steady = [r for r in rows if r["Step"] >= 12000]
        accel = (steady[-1]["speed"] - steady[0]["speed"]) / (steady[-1]["Step"] - steady[0]["Step"])
        predicted = g * (math.sin(theta) - mu * math.cos(theta))
        err = (accel - predicted) / predicted
        check("tilt_slide_acceleration", abs(err) <= 0.01,
              f"{accel:.6g} (error {100 * err:+.3f} %; slid {distance:.4g} cells, across "
              f"{int(distance)} voxels)", f"within 1 % of g (sin - mu cos) = {predicted:.6g} at {tilted}")
        # Smooth sliding over the voxel faces: the height does not change.
        heights = [r["zpos"] for r in steady]
        check("tilt_slide_height_variation", max(heights) - min(heights) < 1e-6,
              f"{max(heights) - min(heights):.3g}", "< 1e-6")
    else:
        # The tangential spring stretches by m g sin / kt and then holds: no creep.
        spring = mass * g * math.sin(theta) / (0.1 * 2.0 / 7.0)
        check("tilt_stick", abs(distance) <= 2.0 * spring and abs(end["speed"]) < 1e-7,
              f"moved {distance:.3g}, final speed {end['speed']:.2g}",
              f"|moved| <= 2 x the spring stretch {spring:.3g}, |speed| < 1e-7 at {tilted}")


def parallel_equal(h):
    """Serial and 2-rank runs of the bond script give the same thermo numbers."""
    a = thermo_rows(h.run("in.bond", {"load_factor": 1.2}).output)
    b = thermo_rows(h.run("in.bond", {"load_factor": 1.2}, ranks=2).output)
    worst = max(abs(x[k] - y[k]) for x, y in zip(a, b) for k in x)
    check("serial_vs_2_ranks_largest_difference", len(a) == len(b) and worst < 1e-9,
          f"{worst:.3g} over {len(a)} vs {len(b)} rows", "< 1e-9, same number of rows")


VERSION_WARNING = "Restart file version does not match"


def restart_version_record(path):
    """The first record of a LIGGGHTS 3.8 restart file: the int 0 (VERSION), the length of the
    version string and the string with its NUL."""
    with open(path, "rb") as f:
        flag, length = struct.unpack("ii", f.read(8))
        return flag, f.read(length).rstrip(b"\0").decode(errors="replace")


def restart_version(h):
    """Restart files of liggghts-lbm carry LIGGGHTS's own version string, so liggghts-lbm and
    Debian's liggghts read each other's files without the version warning; liggghts-lbm prints
    the project's version under LIGGGHTS's in its header."""
    written = h.run("in.restart_write", {})
    stock = h.run("in.restart_write", {}, program=h.liggghts)
    lines = written.output.splitlines()
    cmake = open(os.path.join(h.scripts, "..", "..", "CMakeLists.txt")).read()
    version = re.search(r"project\(lbm_pore VERSION ([0-9.]+)", cmake).group(1)
    header = lines[lines.index(next(l for l in lines if l.startswith("LIGGGHTS ("))) + 1]
    check("restart_version_project_version_in_header",
          header.startswith(f"liggghts-lbm {version} "), header,
          f"'liggghts-lbm {version} ...' under LIGGGHTS's version line")
    with open(os.path.join(written.work, "log.liggghts")) as log:
        check("restart_version_project_version_in_log", f"liggghts-lbm {version} " in log.read(),
              "log.liggghts", f"holds 'liggghts-lbm {version}'")
    expected = restart_version_record(os.path.join(stock.work, "restart.written"))
    # write_restart, `restart N a b` and `restart N file.*` during the run.
    for name in ("restart.written", "restart.a", "restart.80"):
        path = os.path.join(written.work, name)
        check(f"restart_version_{name}_header", restart_version_record(path) == expected,
              restart_version_record(path)[1], f"LIGGGHTS's own: {expected[1]}")
    for reader, program in (("liggghts-lbm", None), ("liggghts", h.liggghts)):
        for writer, run in (("liggghts-lbm", written), ("liggghts", stock)):
            for name in ("restart.written", "restart.b"):
                out = h.run("in.restart_read", {"file": os.path.join(run.work, name)},
                            program=program).output
                check(f"restart_version_{reader}_reads_{writer}_{name}",
                      VERSION_WARNING not in out and "Loop time" in out,
                      "warned" if VERSION_WARNING in out else "no warning",
                      f"no '{VERSION_WARNING}', the run continues")


def dumped_particles(path):
    """(positions, radii, masses) of the last snapshot of a LIGGGHTS custom dump."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = max(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    cols = lines[start].split()[2:]
    rows = [[float(v) for v in line.split()] for line in lines[start + 1:] if line.strip()]
    pick = lambda name: [row[cols.index(name)] for row in rows]
    return list(zip(pick("x"), pick("y"), pick("z"))), pick("radius"), pick("mass")


def smallest_gap(positions, radii, box=8.0):
    """The smallest surface gap over all pairs, with the periodic images of in.insert_gap's box."""
    smallest = math.inf
    for i in range(len(positions)):
        for j in range(i):
            d = [a - b for a, b in zip(positions[i], positions[j])]
            d = [c - box * round(c / box) for c in d]
            smallest = min(smallest, math.sqrt(sum(c * c for c in d)) - radii[i] - radii[j])
    return smallest


def insert_gap(h):
    """fix insert/pack/gap keeps every pair of inserted particles at least min_gap apart, across
    the periodic boundaries and the ranks' borders, and between two insertion steps; the
    particles keep their template's radius and mass. LIGGGHTS's insert/pack at the same
    density places pairs closer than that (so that the check can fail)."""
    gap = 0.25
    mass = 4.0 / 3.0 * math.pi * 0.5 ** 3 * 2.3
    for ranks in (1, 2):
        run = h.run("in.insert_gap", {"gap": gap}, ranks=ranks)
        positions, radii, masses = dumped_particles(os.path.join(run.work, "insert_gap.dump"))
        smallest = smallest_gap(positions, radii)
        check(f"insert_gap_smallest_gap_{ranks}_ranks", len(positions) > 50 and smallest >= gap - 1e-9,
              f"{smallest:.4g} over {len(positions)} particles", f">= min_gap {gap}, more than 50 inserted")
        check(f"insert_gap_template_radius_and_mass_{ranks}_ranks",
              all(r == 0.5 for r in radii) and all(abs(m - mass) <= 1e-5 * mass for m in masses),
              f"radii {min(radii)}-{max(radii)}, masses {min(masses):.6g}-{max(masses):.6g}",
              f"0.5 and {mass:.6g} (the template's, to the dump's 6 digits)")
    run = h.run("in.insert_gap", {"gap": 0})
    positions, radii, _ = dumped_particles(os.path.join(run.work, "insert_gap.dump"))
    smallest = smallest_gap(positions, radii)
    check("insert_pack_places_closer", 0.0 <= smallest < gap, f"{smallest:.4g}",
          f"in [0, {gap}): insert/pack checks overlap only")


if __name__ == "__main__":
    main({"bond_hold": lambda h: hold_or_break(h, BOND, 0.95),
          "bond_break": lambda h: hold_or_break(h, BOND, 1.2),
          "restitution": restitution,
          "adhesion_hold": lambda h: hold_or_break(h, ADHESION, 0.95),
          "adhesion_break": lambda h: hold_or_break(h, ADHESION, 1.2),
          "tilt_stick": lambda h: tilt(h, False),
          "tilt_slide": lambda h: tilt(h, True),
          "parallel_equal": parallel_equal,
          "restart_version": restart_version,
          "insert_gap": insert_gap}, __doc__)
