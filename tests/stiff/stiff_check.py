#!/usr/bin/env python3
"""Stiff and extreme cases of liggghts-lbm with fix lbm/pore (tiny scenes in the paper's
lattice units, in.scene) and of the contact guards alone (in.dem_guard). Each case asserts
something physical or the exact guard message; prints every measured figure and its bound;
exits 1 on failure.

usage: stiff_check.py --driver PATH --scripts DIR CASE
cases: stiff_kn100, near_pore, concentration, tau_051, fast_drive, overlap_warn,
       overlap_stop, nan_force, nan_position
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

RHO_P = 2.3


def run(args, script, variables, expect_error=False):
    work = tempfile.mkdtemp(prefix="stiff_")
    cmd = [args.driver, "-in", os.path.abspath(os.path.join(args.scripts, script)), "-log", os.path.join(work, "log")]
    for name, value in variables.items():
        cmd += ["-var", name, str(value)]
    print("run:", " ".join(cmd[1:]))
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, errors="replace", timeout=300)
    failed = out.returncode != 0 or "ERROR" in out.stdout
    if failed and not expect_error:
        print(out.stdout[-3000:])
        sys.exit("FAIL liggghts-lbm stopped with an error")
    return out.stdout, work


def thermo_rows(output):
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
                rows.append(dict(zip(header, [float(w) for w in words])))
            except ValueError:
                continue
    return rows


def dump_frames(path):
    """dump custom frames: list of (step, [dict per atom])."""
    frames = []
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            cols = lines[i + 8].split()[2:]
            atoms = [dict(zip(cols, map(float, lines[i + 9 + k].split()))) for k in range(n)]
            frames.append((step, atoms))
            i += 9 + n
        else:
            i += 1
    return frames


def check(condition, message):
    print(("PASS " if condition else "FAIL ") + message)
    return condition


def error_line(output):
    for line in output.splitlines():
        if "ERROR" in line:
            return line
    return ""


def pair_overlap(atoms):
    """Largest overlap / smaller radius over all pairs (periodic y, z ignored: tiny scenes)."""
    worst = 0.0
    for a in range(len(atoms)):
        for b in range(a + 1, len(atoms)):
            p, q = atoms[a], atoms[b]
            d = math.dist((p["x"], p["y"], p["z"]), (q["x"], q["y"], q["z"]))
            worst = max(worst, (p["radius"] + q["radius"] - d) / min(p["radius"], q["radius"]))
    return worst


class PoreScene:
    """The voxels of lbm::make_pore_scene as fix lbm/pore places them (origin box corner +
    dx/2, dx = 1): solid cubes [i, i+1] x [j, j+1] x [k, k+1] for i in the block whose node
    (j + 1/2, k + 1/2)... lies outside the pore radius."""

    def __init__(self, Li, Lf, Lp, W, D):
        self.x0, self.x1 = Li + Lf, Li + Lf + Lp
        self.W, self.r = W, 0.5 * D
        axis = 0.5 * (W - 1)
        self.solid = [(j, k) for j in range(W) for k in range(W)
                      if (j - axis) ** 2 + (k - axis) ** 2 >= self.r ** 2]

    def distance_to_solid(self, x, y, z):
        """Signed-free distance from a point to the nearest solid cube (0 inside one)."""
        dx = max(self.x0 - x, 0.0, x - self.x1)
        best = float("inf")
        for j, k in self.solid:
            dy = max(j - y, 0.0, y - (j + 1))
            dz = max(k - z, 0.0, z - (k + 1))
            best = min(best, dx * dx + dy * dy + dz * dz)
        return math.sqrt(best)


# ---- fluid cases ------------------------------------------------------------------------

def stiff_kn100(args):
    """kn = kw = 100 x the paper's. The fluid step is 4 (nu such that tau = 1): with n_dem 1
    the DEM step 4 is above t_c/10 of the particles insert/pack adds during the run, which
    the guard must catch when they arrive (none exist at init). Then the run with the n_dem
    the message recommends must stay stable with bounded kinetic energy."""
    base = {"kn": 10, "kw": 10, "dt_lbm": 4, "u_lat": 0.02, "c_in": 0.1, "mode": 0}
    out, _ = run(args, "in.scene", dict(base, n_dem=1, fluid_steps=50), expect_error=True)
    line = error_line(out)
    print("message:", line)
    m = re.search(r"timestep 4 is too large for kn = 10 at step (\d+): .*\(mass ([0-9.e+-]+)\) "
                  r"is t_c = ([0-9.e+-]+).*use timestep <= ([0-9.e+-]+) or a smaller kn; with "
                  r"fix lbm/pore, multiply n_dem by (\d+)", line)
    ok = check(m is not None, "inserted particles are checked: the error names kn, the mass, "
                              "t_c, the limit and the n_dem factor")
    if not m:
        return False
    step, mass, tc, limit, factor = int(m[1]), float(m[2]), float(m[3]), float(m[4]), int(m[5])
    m_expected = RHO_P * 4.0 / 3.0 * math.pi * 3.5 ** 3
    zeta = 0.25
    tc_expected = math.pi / (math.sqrt(10 / (0.5 * m_expected)) * math.sqrt(1 - zeta ** 2))
    ok &= check(step > 0, f"caught at step {step}, after the insertion (none at init)")
    ok &= check(abs(mass - m_expected) < 1e-3 * m_expected and abs(tc - tc_expected) < 1e-3 * tc,
                f"mass {mass:.6g} (expected {m_expected:.6g}), t_c {tc:.6g} (expected {tc_expected:.6g})")
    ok &= check(abs(limit - tc / 10) < 1e-4 * limit and factor == math.ceil(4 / limit),
                f"recommended timestep {limit:.6g} = t_c/10, n_dem factor {factor} = ceil(4/limit)")

    n_dem = factor
    out, work = run(args, "in.scene", dict(base, n_dem=n_dem, fluid_steps=1200, thermo_every=20,
                                           dump_every=20))
    rows = [r for r in thermo_rows(out) if r["Atoms"] > 0]
    ok &= check(f"timestep limit t_c/10 = {limit:.6g}" in out and 4.0 / n_dem <= limit,
                f"recommended setting n_dem {n_dem}: timestep {4.0 / n_dem:.4g} <= {limit:.6g}, "
                "no error in 1200 fluid steps")
    # Bounded energy: the particles are driven by the fluid only, so on aggregate they may not
    # move faster than the fastest fluid (KE <= M u_max^2 / 2), and no particle faster than
    # twice it. A contact instability pumps energy without bound.
    worst_ratio = max(r["KinEng"] / (0.5 * r["mtot"] * r["pore[9]"] ** 2) for r in rows)
    ok &= check(worst_ratio < 1.0, f"KE / (M u_fluid_max^2 / 2) <= {worst_ratio:.3g} (bound 1)")
    u_fluid = max(r["pore[9]"] for r in rows)
    fastest = max(math.sqrt(a["vx"] ** 2 + a["vy"] ** 2 + a["vz"] ** 2)
                  for _, atoms in dump_frames(os.path.join(work, "dump.particles")) for a in atoms)
    ok &= check(fastest <= 2 * u_fluid,
                f"fastest particle {fastest:.4g} <= 2 x fastest fluid {u_fluid:.4g}")
    ok &= check(rows[-1]["Atoms"] >= 8, f"{rows[-1]['Atoms']:.0f} particles in the scene (>= 8)")
    wall = max(r["walls[6]"] for r in rows)
    ok &= check(wall < 0.05, f"largest wall overlap/R {wall:.3g} (bound 0.05)")
    return ok


def near_pore(args):
    """Particles of d = 0.9 D driven through the pore: none may pass through the wall."""
    scene = {"Li": 16, "Lf": 6, "Lp": 10, "Lo": 12, "W": 20, "D": 10}
    out, work = run(args, "in.scene", dict(scene, mode=1, R=4.5, u_lat=0.01, fluid_steps=1400,
                                           thermo_every=10, dump_every=10))
    geometry = PoreScene(scene["Li"], scene["Lf"], scene["Lp"], scene["W"], scene["D"])
    frames = dump_frames(os.path.join(work, "dump.particles"))
    worst, worst_at, furthest = 0.0, None, {}
    for step, atoms in frames:
        for a in atoms:
            d = geometry.distance_to_solid(a["x"], a["y"], a["z"])
            overlap = (a["radius"] - d) / a["radius"]
            if overlap > worst:
                worst, worst_at = overlap, (step, int(a["id"]))
            furthest[a["id"]] = max(furthest.get(a["id"], 0.0), a["x"])
    ok = check(worst < 0.05, f"largest overlap with the solid voxels {worst:.3g} R at "
                             f"{worst_at} (bound 0.05 R: no particle enters the wall)")
    through = sum(1 for x in furthest.values() if x > geometry.x1 + 4.5)
    ok &= check(through >= 1, f"{through} of {len(furthest)} particles went through the pore "
                              f"(d/D = 0.9; furthest x {max(furthest.values()):.3g}, pore ends at {geometry.x1})")
    rows = thermo_rows(out)
    wall = max(r["walls[6]"] for r in rows)
    ok &= check(wall < 0.05, f"largest wall overlap/R seen by fix wall/voxel {wall:.3g} (bound 0.05)")
    return ok


def concentration(args):
    """insert/pack at volume fraction 0.1: counts, masses and overlaps consistent."""
    scene = {"Li": 20, "Lf": 6, "Lp": 10, "Lo": 12, "W": 24, "D": 14}
    out, work = run(args, "in.scene", dict(scene, mode=0, c_in=0.1, u_lat=0.01, fluid_steps=600,
                                           thermo_every=10, dump_every=10))
    m_p = RHO_P * 4.0 / 3.0 * math.pi * 3.5 ** 3
    v_p = 4.0 / 3.0 * math.pi * 3.5 ** 3
    v_region = (scene["Li"] - 1) * scene["W"] ** 2
    inserted = [(int(n), float(m), int(s)) for n, m, s in re.findall(
        r"inserted (\d+) particle templates \(mass ([0-9.e+-]+)\) at step (\d+)", out)]
    total = re.findall(r"a total of (\d+) particle templates \(mass ([0-9.e+-]+)\)", out)
    n_total, m_total = int(total[-1][0]), float(total[-1][1])
    rows = thermo_rows(out)
    last = rows[-1]
    ok = check(last["Atoms"] == n_total and abs(last["mtot"] - m_total) < 1e-6 * m_total,
               f"atoms {last['Atoms']:.0f} = inserted {n_total}; mass {last['mtot']:.6g} = "
               f"inserted mass {m_total:.6g} (nothing left the scene)")
    ok &= check(all(abs(r["mtot"] - r["Atoms"] * m_p) < 1e-6 * max(1.0, r["mtot"]) for r in rows),
                f"mass = atoms x {m_p:.6g} in every row")
    first = inserted[0][0]
    fraction = first * v_p / v_region
    ok &= check(0.1 - v_p / v_region <= fraction <= 0.1 + 1e-9,
                f"first insertion: {first} particles, volume fraction {fraction:.4f} of the inlet "
                f"region (target 0.1, one particle = {v_p / v_region:.4f})")
    frames = dump_frames(os.path.join(work, "dump.particles"))
    worst = max((pair_overlap(atoms) for _, atoms in frames), default=0.0)
    wall = max(r["walls[6]"] for r in rows)
    ok &= check(worst < 0.05 and wall < 0.05 and "overlap" not in out.replace("overlapcheck", ""),
                f"largest overlap/R: particles {worst:.3g}, wall {wall:.3g} (guard's warning 0.05; "
                "no warning printed)")
    ok &= check(len(inserted) >= 2 and n_total > first,
                f"{n_total} particles inserted in {len(inserted)} insertions (the region refilled)")
    return ok


def tau_051(args):
    """tau = 0.51: either stable with mass conserved (flux in = flux out), or a clear error."""
    out, work = run(args, "in.scene", {"tau": 0.51, "mode": 1, "u_lat": 0.01, "fluid_steps": 2000,
                                       "thermo_every": 1, "dump_every": 1000}, expect_error=True)
    line = error_line(out)
    if line:
        print("message:", line)
        return check(re.search(r"fix lbm/pore: .*(tau|unstable)", line) is not None and
                     re.search(r"\bnan\b", out, re.I) is None,
                     "stopped with a clear fluid error (tau / unstable), no NaN printed")
    # Sampled every fluid step: at tau = 0.51 sound waves are hardly damped and the outlet
    # flux oscillates by +-50 %; their mean over 1000 fluid steps is what mass conservation fixes.
    rows = thermo_rows(out)
    late = rows[len(rows) // 2:]
    q_in = sum(r["pore[2]"] for r in late) / len(late)
    q_out = sum(r["pore[3]"] for r in late) / len(late)
    ok = check(abs(q_in - q_out) <= 0.03 * q_in,
               f"stable; mean flux in {q_in:.5g}, out {q_out:.5g} over the last {len(late)} fluid steps "
               f"(difference {abs(q_in - q_out) / q_in:.3%}, bound 3 %: sound waves, hardly damped at tau 0.51, still move mass back and forth)")
    mach = max(r["pore[9]"] for r in rows) / (1 / math.sqrt(3))
    ok &= check(mach < 0.5, f"largest lattice Mach {mach:.3g} (bound 0.5)")
    return ok


def fast_drive(args):
    """Inlet velocity 0.5 lattice: a clear error naming 'velocity', never NaN."""
    out, _ = run(args, "in.scene", {"u_lat": 0.5, "mode": 0, "fluid_steps": 100},
                 expect_error=True)
    line = error_line(out)
    print("message:", line)
    return check("velocity" in line and re.search(r"\bnan\b", out, re.I) is None and
                 "fix lbm/pore" in line,
                 "fix lbm/pore stops with an error naming 'velocity' (no NaN)")


# ---- contact guards without fluid -------------------------------------------------------

def overlap_warn(args):
    """F = 0.035 presses two particles (kn 0.1) and one on the wall (kw 0.1): static overlap
    F/k = 0.35 = 10 % of R: one warning each, and the run goes on."""
    out, _ = run(args, "in.dem_guard", {"push": 0.035})
    rows = thermo_rows(out)
    ok = check(len(re.findall(r"WARNING: pair_style lbm/dashdot: particles 1 and 2 overlap by "
                              r"[0-9.]+ % of the smaller radius at step \d+", out)) == 1,
               "one pair warning naming particles 1 and 2 and the step")
    ok &= check(len(re.findall(r"WARNING: fix wall/voxel: particle 3 at .* overlaps the wall by "
                               r"[0-9.]+ % of its radius at step \d+", out)) == 1,
                "one wall warning naming particle 3 and the step")
    gap, wall_gap, ratio = rows[-1]["gap"], rows[-1]["wallgap"], rows[-1]["walls[6]"]
    ok &= check(abs(gap + 0.35) < 0.01 and abs(wall_gap + 0.35) < 0.01 and abs(ratio - 0.1) < 0.003,
                f"static overlaps {-gap:.4g} (pair), {-wall_gap:.4g} (wall) = F/k = 0.35; "
                f"f_walls[6] = {ratio:.4g} = 0.35/3.5")
    return ok


def overlap_stop(args):
    out, _ = run(args, "in.dem_guard", {"push": 0.3, "push_wall": 0.0}, expect_error=True)
    ok = check(re.search(r"ERROR on proc 0: pair_style lbm/dashdot: particles 1 and 2 overlap by "
                         r"\d+ % of the smaller radius at step \d+ \(limit 50 %\): they pass through",
                         out) is not None, "pair: stops above 50 % naming particles 1, 2 and the step")
    out, _ = run(args, "in.dem_guard", {"push": 0.0, "push_wall": 0.3}, expect_error=True)
    ok &= check(re.search(r"ERROR on proc 0: fix wall/voxel: particle 3 at .* overlaps the wall by "
                          r"\d+ % of its radius at step \d+ \(limit 50 %\): it passes through the wall",
                          out) is not None, "wall: stops above 50 % naming particle 3 and the step")
    return ok


def nan_force(args):
    out, _ = run(args, "in.dem_guard", {"nan": 1}, expect_error=True)
    return check("ERROR on proc 0: fix wall/voxel: particle 1 has a non-finite force at step 0" in out,
                 "NaN force: stopped by fix wall/voxel at step 0 naming particle 1")


def nan_position(args):
    out, _ = run(args, "in.dem_guard", {"nan": 2}, expect_error=True)
    return check(re.search(r"ERROR on proc 0: pair_style lbm/dashdot: particle 1 has a non-finite "
                           r"position \(\S+ 5 5\) at step 1", out) is not None,
                 "NaN position: stopped by pair lbm/dashdot at step 1 naming particle 1")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--driver", required=True)
    parser.add_argument("--scripts", required=True)
    parser.add_argument("case")
    args = parser.parse_args()
    cases = {f.__name__: f for f in (stiff_kn100, near_pore, concentration, tau_051, fast_drive,
                                      overlap_warn, overlap_stop, nan_force, nan_position)}
    sys.exit(0 if cases[args.case](args) else 1)


if __name__ == "__main__":
    main()
