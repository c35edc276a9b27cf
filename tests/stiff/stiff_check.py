#!/usr/bin/env python3
"""Stiff and extreme cases of liggghts-lbm with fix lbm/pore (tiny scenes in the paper's
lattice units, in.scene) and of the contact guards alone (in.dem_guard). Each case asserts
something physical or the exact guard message; prints every measured figure and its bound
(tests/harness/liggghts_run.py); exits 1 on failure.

usage: stiff_check.py --driver PATH --scripts DIR [--mpirun mpirun] CASE
cases: stiff_kn100, near_pore, concentration, tau_051, fast_drive, overlap_warn,
       overlap_stop, nan_force, nan_position
"""
import math
import os
import re

from liggghts_run import check, error_line, has_nan, main, thermo_rows

RHO_P = 2.3


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


def scene_frames(run):
    """The particles of every dump frame of an in.scene or in.dem_guard run."""
    return dump_frames(os.path.join(run.work, "dump.particles"))


def largest_wall_overlap(rows):
    """f_walls[6]: the largest particle-wall overlap / R that fix wall/voxel saw."""
    return max(r["walls[6]"] for r in rows)


# ---- fluid cases ------------------------------------------------------------------------

def stiff_kn100(h):
    """kn = kw = 100 x the paper's. The fluid step is 4 (nu such that tau = 1): with n_dem 1
    the DEM step 4 is above t_c/10 of the particles insert/pack adds during the run, which
    the guard must catch when they arrive (none exist at init). Then the run with the n_dem
    the message recommends must stay stable with bounded kinetic energy."""
    base = {"kn": 10, "kw": 10, "dt_lbm": 4, "u_lat": 0.02, "c_in": 0.1, "mode": 0}
    line = error_line(h.run("in.scene", dict(base, n_dem=1, fluid_steps=50), expect_error=True).output)
    m = re.search(r"timestep 4 is too large for kn = 10 at step (\d+): .*\(mass ([0-9.e+-]+)\) "
                  r"is t_c = ([0-9.e+-]+).*use timestep <= ([0-9.e+-]+) or a smaller kn; with "
                  r"fix lbm/pore, multiply n_dem by (\d+)", line)
    if not check("stiff_inserted_particles_checked", m is not None, repr(line),
                 "an error naming kn, the mass, t_c, the limit and the n_dem factor"):
        return
    step, mass, tc, limit, factor = int(m[1]), float(m[2]), float(m[3]), float(m[4]), int(m[5])
    m_expected = RHO_P * 4.0 / 3.0 * math.pi * 3.5 ** 3
    zeta = 0.25
    tc_expected = math.pi / (math.sqrt(10 / (0.5 * m_expected)) * math.sqrt(1 - zeta ** 2))
    check("stiff_caught_at_step", step > 0, step, "> 0: after the insertion (none at init)")
    check("stiff_mass_and_contact_time",
          abs(mass - m_expected) < 1e-3 * m_expected and abs(tc - tc_expected) < 1e-3 * tc,
          f"mass {mass:.6g}, t_c {tc:.6g}",
          f"within 1e-3 of mass {m_expected:.6g} and t_c {tc_expected:.6g}")
    check("stiff_recommended_timestep", abs(limit - tc / 10) < 1e-4 * limit and factor == math.ceil(4 / limit),
          f"timestep {limit:.6g}, n_dem factor {factor}",
          f"t_c/10 = {tc / 10:.6g} within 1e-4, factor ceil(4/limit) = {math.ceil(4 / limit)}")

    n_dem = factor
    run = h.run("in.scene", dict(base, n_dem=n_dem, fluid_steps=1200, thermo_every=20, dump_every=20))
    out = run.output
    rows = [r for r in thermo_rows(out) if r["Atoms"] > 0]
    check("stiff_recommended_setting_runs", f"timestep limit t_c/10 = {limit:.6g}" in out and 4.0 / n_dem <= limit,
          f"n_dem {n_dem}: timestep {4.0 / n_dem:.4g}, no error in 1200 fluid steps",
          f"<= {limit:.6g}, the limit printed at setup")
    # Bounded energy: the particles are driven by the fluid only, so on aggregate they may not
    # move faster than the fastest fluid (KE <= M u_max^2 / 2), and no particle faster than
    # twice it. A contact instability pumps energy without bound.
    worst_ratio = max(r["KinEng"] / (0.5 * r["mtot"] * r["pore[9]"] ** 2) for r in rows)
    check("stiff_kinetic_energy_over_fluid", worst_ratio < 1.0, f"{worst_ratio:.3g}",
          "< 1 (KE / (M u_fluid_max^2 / 2))")
    u_fluid = max(r["pore[9]"] for r in rows)
    fastest = max(math.sqrt(a["vx"] ** 2 + a["vy"] ** 2 + a["vz"] ** 2)
                  for _, atoms in scene_frames(run) for a in atoms)
    check("stiff_fastest_particle", fastest <= 2 * u_fluid, f"{fastest:.4g}",
          f"<= 2 x fastest fluid {u_fluid:.4g}")
    check("stiff_particles_in_scene", rows[-1]["Atoms"] >= 8, f"{rows[-1]['Atoms']:.0f}", ">= 8")
    wall = largest_wall_overlap(rows)
    check("stiff_wall_overlap_over_R", wall < 0.05, f"{wall:.3g}", "< 0.05")


def near_pore(h):
    """Particles of d = 0.9 D driven through the pore: none may pass through the wall."""
    scene = {"Li": 16, "Lf": 6, "Lp": 10, "Lo": 12, "W": 20, "D": 10}
    run = h.run("in.scene", dict(scene, mode=1, R=4.5, u_lat=0.01, fluid_steps=1400,
                                 thermo_every=10, dump_every=10))
    geometry = PoreScene(scene["Li"], scene["Lf"], scene["Lp"], scene["W"], scene["D"])
    worst, worst_at, furthest = 0.0, None, {}
    for step, atoms in scene_frames(run):
        for a in atoms:
            d = geometry.distance_to_solid(a["x"], a["y"], a["z"])
            overlap = (a["radius"] - d) / a["radius"]
            if overlap > worst:
                worst, worst_at = overlap, (step, int(a["id"]))
            furthest[a["id"]] = max(furthest.get(a["id"], 0.0), a["x"])
    check("near_pore_voxel_overlap_over_R", worst < 0.05, f"{worst:.3g} at (step, id) {worst_at}",
          "< 0.05: no particle enters the wall")
    through = sum(1 for x in furthest.values() if x > geometry.x1 + 4.5)
    check("near_pore_particles_through", through >= 1,
          f"{through} of {len(furthest)} (d/D = 0.9; furthest x {max(furthest.values()):.3g}, "
          f"pore ends at {geometry.x1})", ">= 1")
    wall = largest_wall_overlap(thermo_rows(run.output))
    check("near_pore_wall_overlap_over_R", wall < 0.05, f"{wall:.3g} (seen by fix wall/voxel)", "< 0.05")


def concentration(h):
    """insert/pack at volume fraction 0.1: counts, masses and overlaps consistent."""
    scene = {"Li": 20, "Lf": 6, "Lp": 10, "Lo": 12, "W": 24, "D": 14}
    run = h.run("in.scene", dict(scene, mode=0, c_in=0.1, u_lat=0.01, fluid_steps=600,
                                 thermo_every=10, dump_every=10))
    out = run.output
    m_p = RHO_P * 4.0 / 3.0 * math.pi * 3.5 ** 3
    v_p = 4.0 / 3.0 * math.pi * 3.5 ** 3
    v_region = (scene["Li"] - 1) * scene["W"] ** 2
    inserted = [(int(n), float(m), int(s)) for n, m, s in re.findall(
        r"inserted (\d+) particle templates \(mass ([0-9.e+-]+)\) at step (\d+)", out)]
    total = re.findall(r"a total of (\d+) particle templates \(mass ([0-9.e+-]+)\)", out)
    n_total, m_total = int(total[-1][0]), float(total[-1][1])
    rows = thermo_rows(out)
    last = rows[-1]
    check("concentration_nothing_left_the_scene",
          last["Atoms"] == n_total and abs(last["mtot"] - m_total) < 1e-6 * m_total,
          f"atoms {last['Atoms']:.0f}, mass {last['mtot']:.6g}",
          f"= inserted {n_total}, within 1e-6 of the inserted mass {m_total:.6g}")
    check("concentration_mass_per_atom",
          all(abs(r["mtot"] - r["Atoms"] * m_p) < 1e-6 * max(1.0, r["mtot"]) for r in rows),
          f"{sum(abs(r['mtot'] - r['Atoms'] * m_p) >= 1e-6 * max(1.0, r['mtot']) for r in rows)} "
          f"of {len(rows)} rows off", f"mass = atoms x {m_p:.6g} in every row")
    first = inserted[0][0]
    fraction = first * v_p / v_region
    check("concentration_first_insertion_fraction", 0.1 - v_p / v_region <= fraction <= 0.1 + 1e-9,
          f"{fraction:.4f} ({first} particles)",
          f"target 0.1 of the inlet region, less at most one particle = {v_p / v_region:.4f}")
    worst = max((pair_overlap(atoms) for _, atoms in scene_frames(run)), default=0.0)
    wall = largest_wall_overlap(rows)
    check("concentration_overlap_over_R",
          worst < 0.05 and wall < 0.05 and "overlap" not in out.replace("overlapcheck", ""),
          f"particles {worst:.3g}, wall {wall:.3g}", "< 0.05 (the guard's warning), no warning printed")
    check("concentration_refilled", len(inserted) >= 2 and n_total > first,
          f"{n_total} particles in {len(inserted)} insertions", f"> {first} in >= 2 insertions")


def tau_051(h):
    """tau = 0.51: either stable with mass conserved (flux in = flux out), or a clear error."""
    out = h.run("in.scene", {"tau": 0.51, "mode": 1, "u_lat": 0.01, "fluid_steps": 2000,
                             "thermo_every": 1, "dump_every": 1000}, expect_error=True).output
    line = error_line(out)
    if line:
        check("tau_051_clear_error",
              re.search(r"fix lbm/pore: .*(tau|unstable)", line) is not None and not has_nan(out),
              repr(line), "a fluid error naming tau or unstable, no NaN printed")
        return
    # Sampled every fluid step: at tau = 0.51 sound waves are hardly damped and the outlet
    # flux oscillates by +-50 %; their mean over 1000 fluid steps is what mass conservation fixes.
    rows = thermo_rows(out)
    late = rows[len(rows) // 2:]
    q_in = sum(r["pore[2]"] for r in late) / len(late)
    q_out = sum(r["pore[3]"] for r in late) / len(late)
    check("tau_051_flux_in_vs_out", abs(q_in - q_out) <= 0.03 * q_in,
          f"{abs(q_in - q_out) / q_in:.3%} (mean flux in {q_in:.5g}, out {q_out:.5g} over the last "
          f"{len(late)} fluid steps)",
          "<= 3 % (sound waves, hardly damped at tau 0.51, still move mass back and forth)")
    mach = max(r["pore[9]"] for r in rows) / (1 / math.sqrt(3))
    check("tau_051_largest_lattice_mach", mach < 0.5, f"{mach:.3g}", "< 0.5")


def fast_drive(h):
    """Inlet velocity 0.5 lattice: a clear error naming 'velocity', never NaN."""
    out = h.run("in.scene", {"u_lat": 0.5, "mode": 0, "fluid_steps": 100}, expect_error=True).output
    line = error_line(out)
    check("fast_drive_error", "velocity" in line and not has_nan(out) and "fix lbm/pore" in line,
          repr(line), "an error of fix lbm/pore naming 'velocity', no NaN")


# ---- contact guards without fluid -------------------------------------------------------

def overlap_warn(h):
    """F = 0.035 presses two particles (kn 0.1) and one on the wall (kw 0.1): static overlap
    F/k = 0.35 = 10 % of R: one warning each, and the run goes on."""
    out = h.run("in.dem_guard", {"push": 0.035}).output
    rows = thermo_rows(out)
    pair = re.findall(r"WARNING: pair_style lbm/dashdot: particles 1 and 2 overlap by "
                      r"[0-9.]+ % of the smaller radius at step \d+", out)
    check("overlap_warn_pair_warnings", len(pair) == 1, len(pair),
          "1 warning naming particles 1 and 2 and the step")
    wall = re.findall(r"WARNING: fix wall/voxel: particle 3 at .* overlaps the wall by "
                      r"[0-9.]+ % of its radius at step \d+", out)
    check("overlap_warn_wall_warnings", len(wall) == 1, len(wall),
          "1 warning naming particle 3 and the step")
    gap, wall_gap, ratio = rows[-1]["gap"], rows[-1]["wallgap"], rows[-1]["walls[6]"]
    check("overlap_warn_static_overlaps",
          abs(gap + 0.35) < 0.01 and abs(wall_gap + 0.35) < 0.01 and abs(ratio - 0.1) < 0.003,
          f"pair {-gap:.4g}, wall {-wall_gap:.4g}, f_walls[6] {ratio:.4g}",
          "F/k = 0.35 within 0.01 each, f_walls[6] = 0.35/3.5 within 0.003")


def guard_error(h, name, variables, pattern, bound):
    """A run that the guard must stop with an error matching `pattern`."""
    out = h.run("in.dem_guard", variables, expect_error=True).output
    check(name, re.search(pattern, out) is not None, repr(error_line(out)), bound)


def overlap_stop(h):
    guard_error(h, "overlap_stop_pair", {"push": 0.3, "push_wall": 0.0},
                r"ERROR on proc 0: pair_style lbm/dashdot: particles 1 and 2 overlap by "
                r"\d+ % of the smaller radius at step \d+ \(limit 50 %\): they pass through",
                "stops above 50 % naming particles 1, 2 and the step")
    guard_error(h, "overlap_stop_wall", {"push": 0.0, "push_wall": 0.3},
                r"ERROR on proc 0: fix wall/voxel: particle 3 at .* overlaps the wall by "
                r"\d+ % of its radius at step \d+ \(limit 50 %\): it passes through the wall",
                "stops above 50 % naming particle 3 and the step")


def nan_force(h):
    guard_error(h, "nan_force", {"nan": 1},
                re.escape("ERROR on proc 0: fix wall/voxel: particle 1 has a non-finite force at step 0"),
                "stopped by fix wall/voxel at step 0 naming particle 1")


def nan_position(h):
    guard_error(h, "nan_position", {"nan": 2},
                r"ERROR on proc 0: pair_style lbm/dashdot: particle 1 has a non-finite "
                r"position \(\S+ 5 5\) at step 1",
                "stopped by pair lbm/dashdot at step 1 naming particle 1")


if __name__ == "__main__":
    main({f.__name__: f for f in (stiff_kn100, near_pore, concentration, tau_051, fast_drive,
                                  overlap_warn, overlap_stop, nan_force, nan_position)}, __doc__)
