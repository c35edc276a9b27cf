#!/usr/bin/env python3
"""Integration checks of fix lbm/pore: runs liggghts-lbm on the tiny scenes of this folder and
compares what it measures with a physical expectation or a reference run. Prints every figure
with its bound (tests/harness/liggghts_run.py); exits 1 when one fails.

usage: coupled_check.py --driver liggghts-lbm --scripts DIR [--mpirun mpirun] CASE
CASE: adhesion | clog | clog_pressure | clog_capped | parallel | mpi_splits | outputs | restart | bad_arguments |
      substep_force | reused_tag | outlet_exit
"""
import math
import os
import subprocess
import tempfile

from liggghts_run import (at_step, check, error_line, has_nan, main, relative_difference,
                          thermo_rows)


def case_adhesion(h):
    """A particle resting on the pore's flat floor, pressed by its net weight N = (rho_p - rho)
    V g, is held by wall friction at a low inlet velocity and torn off at a high one. In the
    Stokes regime its drag is linear in the inlet velocity, so the drag measured on the held
    particle predicts the tear-off velocity u* = mu N / (drag / u). Runs at u* / 1.5 (must
    hold) and 1.5 u* (must slide) check that prediction within a factor 1.5. The wall's
    adhesion, at most 0.03 ka R^2, acts only across a gap (zero in contact): had it added to
    N, u* would be (1 + 0.03 ka R^2 / N) = 16.7 times higher and the 1.5 u* run would hold."""
    radius, rho_p, g, mu, kw, ka, steps = 3.5, 2.3, 1e-4, 0.5, 100.0, 1.0, 100000
    normal = (rho_p - 1.0) * 4.0 / 3.0 * math.pi * radius ** 3 * g
    # Start in contact with the floor (z = 3) at the overlap that carries N: no settling phase.
    z0 = 3.0 + radius - normal / kw

    def displacement(u):
        rows = thermo_rows(h.run("in.adhesion", {"u": u, "steps": steps, "z0": f"{z0:.10g}"}).output)
        return rows, at_step(rows, steps)["px"] - at_step(rows, 0)["px"]

    u_low, u_high = 3e-5, 2e-3
    rows_low, held = displacement(u_low)
    _, torn = displacement(u_high)
    check("adhesion_held_displacement_cells", abs(held) < 0.05, f"{held:.3g}",
          f"|dx| < 0.05 over {steps} steps at u = {u_low:g} (the friction spring's stretch is ~3e-4)")
    check("adhesion_torn_off_displacement_cells", torn > 3.0, f"{torn:.3g}",
          f"> 3 over {steps} steps at u = {u_high:g}")
    # Drag of the held particle once the flow is steady (second half of the run).
    late = [r["fx"] for r in rows_low if r["Step"] >= steps // 2]
    drag = sum(late) / len(late)
    threshold = mu * normal / (drag / u_low)
    print(f"INFO held drag {drag:.4g} at u = {u_low:g} ({drag / u_low:.4g} per inlet velocity), "
          f"N = {normal:.4g}, mu N = {mu * normal:.4g}, adhesion limit 0.03 ka R^2 = "
          f"{0.03 * ka * radius ** 2:.4g} (not in contact), predicted tear-off u* = {threshold:.4g}")
    check("adhesion_predicted_threshold_between_runs", 2.0 * u_low < threshold < u_high / 2.0,
          f"{threshold:.3g}", f"between 2 u_low = {2 * u_low:g} and u_high / 2 = {u_high / 2:g}")
    _, below = displacement(threshold / 1.5)
    _, above = displacement(threshold * 1.5)
    check("adhesion_held_at_threshold_over_1.5", abs(below) < 0.05, f"{below:.3g}",
          f"|dx| < 0.05 cells at u = u*/1.5 = {threshold / 1.5:.4g}")
    check("adhesion_slides_at_threshold_times_1.5", above > 0.05, f"{above:.3g}",
          f"dx > 0.05 cells at u = 1.5 u* = {threshold * 1.5:.4g}")


def case_clog(h):
    """Four particles with strong adhesion and cohesion (ka = kc = 2) jam in the mouth of a
    pore narrower than two diameters: the pressure loss must rise well above its
    particle-free value and the fix must count them as deposited."""
    out = h.run("in.clog", {"clean_steps": 100000, "steps": 150000,
                            "restart_read": "", "restart_write": ""}).output
    clean = float(next(l.split()[1] for l in out.splitlines() if l.startswith("CLEAN_PRESSURE")))
    last = thermo_rows(out)[-1]
    final = last["p"]
    check("clog_pressure_rise", final / clean > 2.0, f"{final / clean:.3g}",
          f"pressure loss {final:.4g} vs particle-free {clean:.4g}: ratio > 2")
    check("clog_deposited_count", last["pore[7]"] > 0, f"{last['pore[7]']:.0f}",
          "> 0 particles deposited (in the pore's cylinder, bonded, slower than 10 % of u)")
    # The hold the burst records carry: fix lbm/pore's wall force along the flow is fix
    # wall/voxel's own total at the same step (thermo steps are fluid steps), the jam is held
    # against the flow, and the deposits on the wall are some of the deposited ones.
    rows = [r for r in thermo_rows(out) if "walls[2]" in r]
    worst = max(abs(r["pore[25]"] - r["walls[2]"]) / max(abs(r["walls[2]"]), 1e-300) for r in rows
                if r["walls[2]"] != 0.0)
    check("clog_wall_hold_is_the_wall_fix_total", worst < 1e-12, f"{worst:.3g}",
          "relative difference < 1e-12 at every thermo row with a wall force")
    check("clog_wall_holds_against_the_flow", last["pore[25]"] < 0, f"{last['pore[25]']:.4g}", "< 0")
    # The jam at rest passes the fluid's push on to the wall: the wall's hold balances the
    # hydrodynamic force on the particles (their pair forces cancel), and that force is the
    # pressure loss on the pore's section, P pi D^2 / 4 (paper, theory section), to within
    # the clean pore's own loss and the fluid's shear on the wall.
    balance = abs(last["pore[25]"] + last["pore[14]"]) / abs(last["pore[14]"])
    check("clog_wall_hold_balances_the_fluid", balance < 0.02, f"{balance:.3g}",
          f"|wall + fluid| / fluid < 0.02 (wall {last['pore[25]']:.4g}, fluid {last['pore[14]']:.4g})")
    section = final * math.pi * 11.0 ** 2 / 4.0
    check("clog_hold_is_the_pressure_on_the_section", 0.7 < -last["pore[25]"] / section < 1.3,
          f"{-last['pore[25]'] / section:.3g}", f"wall hold / (P pi D^2 / 4 = {section:.4g}) within 0.7 ... 1.3")
    check("clog_deposits_on_the_wall", 0 < last["pore[26]"] <= last["pore[7]"],
          f"{last['pore[26]']:.0f} of {last['pore[7]']:.0f}", "0 < on the wall <= deposited")


def case_clog_pressure(h):
    """The same jam under a constant pressure loss (Delta rho = 0.03): the flux through the
    outlet falls as the pore clogs, while the speed in the gaps stays bounded, so the run goes
    on (a velocity drive would force the imposed flux through sub-cell gaps until the fluid
    guard stops it)."""
    rows = thermo_rows(h.run("in.clog_pressure", {"steps": 400000, "p_loss": 0.01}).output)
    clean = at_step(rows, 100000)["pore[3]"]
    last = rows[-1]
    check("clog_pressure_ran_to_the_end", last["Step"] == 500000, last["Step"], "== 500000 (no guard stopped it)")
    check("clog_pressure_flux_falls", last["pore[3]"] / clean < 0.3, f"{last['pore[3]'] / clean:.3g}",
          f"outlet flux {last['pore[3]']:.4g} vs particle-free {clean:.4g}: ratio < 0.3")
    check("clog_pressure_deposited", last["pore[7]"] == 4, f"{last['pore[7]']:.0f}", "== 4 deposited")
    fastest = max(r["pore[9]"] for r in rows)
    check("clog_pressure_gap_speeds_bounded", fastest < 0.05, f"{fastest:.3g}",
          "largest fluid speed < 0.05 lattice (the fluid guard stops at 0.5)")
    check("clog_pressure_pressure_held", abs(last["pore[16]"] - 0.03) < 1e-9, last["pore[16]"], "P / P_out == 0.03")


def case_clog_capped(h):
    """The jam of in.clog under a ceiling on the velocity inlet's pressure loss (fix lbm/pore
    max_pressure_loss, lbm::CappedVelocityDrive) at twice the particle-free loss: the jam
    raises the loss (to 5.4 times the particle-free one without the ceiling) up to the ceiling,
    where the inlet velocity falls instead and holds it; a restart carries the drive's state."""
    u, clean = 0.003, 0.01294124
    cap = 2.0 * clean
    common = {"clean_steps": 100000, "restart_read": "", "fix_extra": f"max_pressure_loss {cap:.8g}",
              "thermo_extra": "f_pore[37]"}
    # The rows with particles (the particle-free run before them has other columns).
    whole = [r for r in thermo_rows(h.run("in.clog", dict(common, steps=300000, restart_write="")).output)
             if "pore[37]" in r]
    held = [r for r in whole if r["Step"] >= 250000]
    peak = max(r["p"] for r in whole)
    check("capped_loss_never_far_above_the_ceiling", peak < 1.03 * cap, f"{peak / cap:.4g}",
          "largest loss / ceiling < 1.03 (the drive answers over a few acoustic transits)")
    check("capped_loss_held_at_the_ceiling", all(abs(r["p"] / cap - 1.0) < 0.02 for r in held),
          f"{max(abs(r['p'] / cap - 1.0) for r in held):.3g}", "|loss / ceiling - 1| < 0.02 over the last 50000 steps")
    last = whole[-1]
    check("capped_inlet_velocity_lowered", last["pore[37]"] < 0.7 * u, f"{last['pore[37]'] / u:.3g}",
          "inlet velocity / u < 0.7 while the jam holds the loss at the ceiling")
    check("capped_inlet_velocity_at_most_u", max(r["pore[37]"] for r in whole) <= u, "", "<= u throughout")
    check("capped_jam_deposited", last["pore[7]"] == 4, f"{last['pore[7]']:.0f}", "== 4 deposited")
    first = h.run("in.clog", dict(common, steps=150000, restart_write="write_restart clog.restart"))
    resumed = thermo_rows(h.run("in.restart_b", {"restart_file": "clog.restart", "steps": 150000,
                                                 "fix_extra": common["fix_extra"], "thermo_extra": "f_pore[37]"},
                                cwd=first.work).output)[-1]
    # The same as the uninterrupted run (measured: 0): without the drive's state the inlet would
    # restart at u and the inlet velocity differ by 4e-5 at the end.
    for column in ("p", "pore[37]"):
        diff = relative_difference(last[column], resumed[column])
        check(f"capped_restart_relative_difference_{column}", diff < 1e-6, f"{diff:.3g}", "< 1e-6")


def case_parallel(h):
    """Two particles head for the middle of the lattice, where 2 ranks split the fluid and the
    particles (processors 2 1 1, ranks meet at x = 15); particle 1 crosses it. Pressure loss,
    hydrodynamic force and positions must equal the serial run to round-off, before and after a
    sphere crosses the rank boundary. (Before the halo was exchanged ahead of the refill, a
    node uncovered next to the boundary was refilled from one-step-old halo densities and the
    runs drifted apart by 1e-7 after the crossing.)"""
    variables = {"steps": 200000}
    serial_run = h.run("in.transit", dict(variables, px=1))
    split_run = h.run("in.transit", dict(variables, px=2), ranks=2)
    serial, split = thermo_rows(serial_run.output), thermo_rows(split_run.output)
    # The end-of-run report compares the ranks' work (RunTimer::balance_report) on 2 ranks only.
    balance = next((line for line in split_run.output.splitlines() if "balance over 2 ranks" in line), "")
    check("parallel_report_compares_the_ranks", "links per fluid step" in balance
          and "balance over" not in serial_run.output, repr(balance[:120]),
          "a 'balance over 2 ranks' line on 2 ranks, none on 1")
    crossed = any(r["x1"] > 15.0 for r in serial)
    check("parallel_particle_crossed_the_rank_boundary", crossed, crossed, "x1 > 15 at some step")
    check("parallel_same_rows", len(split) == len(serial) > 10, f"{len(split)} vs {len(serial)}",
          "same number of thermo rows (> 10)")
    before = [i for i, r in enumerate(serial) if max(r["x1"], r["x2"]) < 14.5]
    for column in ("p", "fx", "x1", "y2"):
        # Relative to the column's largest magnitude: the force passes through zero.
        scale = max(abs(r[column]) for r in serial)
        early = max(abs(serial[i][column] - split[i][column]) for i in before) / scale
        check(f"parallel_max_difference_{column}_before_boundary", early < 1e-10, f"{early:.3g}",
              f"< 1e-10 of its largest value over the {len(before)} rows with both centres at x < 14.5")
    for column in ("p", "x1", "y2", "fx"):
        scale = max(abs(r[column]) for r in serial)
        worst = max(abs(a[column] - b[column]) for a, b in zip(serial, split)) / scale
        check(f"parallel_max_difference_{column}", worst < 1e-9, f"{worst:.3g}",
              "< 1e-9 of its largest value over the whole run (round-off: sums in another order)")


def case_outputs(h):
    """The per-atom hydrodynamic force (f_pore[1..3], for dump custom, as the paper's snapshot
    colours particles by drag per mass) is the force the fluid puts on each particle: on a
    free particle, the only force, it must equal its acceleration times its mass. Velocity
    Verlet gives m (v(n+1) - v(n)) / dt = (F(n) + F(n+1)) / 2 exactly, checked every substep
    across a fluid step. The dump file holds the column. With 'rotation no' (the paper's
    translation-only particles) the fix adds no torque: a particle in the shear of the pore
    then keeps omega = 0, while with rotation it spins up."""
    steps, dt = 60000, 0.01
    rotating = h.run("in.outputs", {"steps": steps})
    rows = thermo_rows(rotating.output)
    fine = [r for r in rows if r["Step"] > steps]
    scale = max(abs(r["drag_x"]) for r in fine)
    worst = max(abs(b["m"] * (b["vx"] - a["vx"]) / dt - 0.5 * (a["drag_x"] + b["drag_x"]))
                for a, b in zip(fine, fine[1:])) / scale
    check("outputs_peratom_force_is_mass_times_acceleration", len(fine) > 100 and worst < 1e-6, f"{worst:.3g}",
          f"< 1e-6 of the largest force over {len(fine)} consecutive substeps")
    late = [r for r in rows if steps // 2 <= r["Step"] <= steps]
    check("outputs_drag_along_the_flow", all(r["drag_x"] > 0.0 for r in late), min(r["drag_x"] for r in late), "> 0")
    with open(os.path.join(rotating.work, "dump.particles")) as dump:
        lines = dump.read().splitlines()
    header = max(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))  # the last snapshot
    values = dict(zip(lines[header].split()[2:], map(float, lines[header + 1].split())))
    check("outputs_dump_has_the_force", values.get("f_pore[1]", 0.0) > 0.0, values.get("f_pore[1]"),
          "> 0 (dragged along the flow) in the f_pore[1] column of dump custom's last snapshot")
    spin = max(r["wmax"] for r in late)
    check("outputs_rotation_spins_up", spin > 1e-6, f"{spin:.3g}", "|omega| > 1e-6 with rotation")
    still = thermo_rows(h.run("in.outputs", {"steps": steps, "fix_extra": "rotation no"}).output)
    check("outputs_rotation_no_keeps_omega_zero", max(r["wmax"] for r in still) == 0.0,
          max(r["wmax"] for r in still), "== 0 with 'rotation no'")
    # Pressure in units of P_out = rho_out c_s^2 = 1/3 (lattice units): P / P_out = 3 p here,
    # its running maximum, no burst in a clean pore (the burst file holds its header only).
    worst = max(abs(r["pore[16]"] - 3.0 * r["pore[1]"]) for r in rows if r["Step"] > 0)
    check("outputs_pressure_in_outlet_units", worst < 1e-12, f"{worst:.3g}", "|P/P_out - 3 p| < 1e-12")
    running = max(r["pore[16]"] for r in rows if r["Step"] <= steps)
    check("outputs_largest_pressure_loss", abs(rows[-1]["pore[17]"] - running) <= 1e-12 + 0.02 * running,
          rows[-1]["pore[17]"], f"the largest P/P_out sampled by thermo, {running:.6g}, within 2 % (every fluid step is sampled)")
    check("outputs_no_burst_in_a_clean_pore", rows[-1]["pore[18]"] == 0, rows[-1]["pore[18]"], "== 0")
    # The paper's regime: a pressure loss of 0.1 lattice units is a density difference of
    # 0.3, beyond the weakly compressible 0.1: it runs, with a warning stating the error.
    strong = h.run("in.outputs", {"steps": 2000, "drive": "pressure_loss", "drive_value": 0.1,
                                     "fix_extra": "burst_file bursts.txt"})
    warning = next((line for line in strong.output.splitlines() if "WARNING" in line and "pressure_loss" in line), "")
    check("outputs_strong_drive_warns_with_its_error", "23 %" in warning, warning or "no warning",
          "a WARNING naming pressure_loss and the 23 % velocity error at 0.3 (doc/stability.md)")
    last = thermo_rows(strong.output)[-1]
    check("outputs_strong_drive_pressure_in_outlet_units", abs(last["pore[16]"] - 0.3) < 0.01,
          last["pore[16]"], "0.3 +- 0.01 P_out")
    with open(os.path.join(strong.work, "bursts.txt")) as bursts:
        lines = bursts.read().splitlines()
    check("outputs_burst_file_has_its_header_only", len(lines) == 1 and lines[0].startswith("#"), lines,
          "one header line, no burst")


def case_substep_force(h):
    """'substep_force fraction' (the paper's "a fraction of the hydrodynamic force in each
    time step" read literally): each DEM substep applies 1/n_dem of the fluid step's load.
    in.outputs' particle, carried by the flow for 3000 DEM steps, then every substep printed:
    at the first printed substep the force applied (the per-atom f_pore[1] summed, which
    m dv/dt follows: case outputs) is the fluid step's force (f_pore[14]) with 'held' and a
    hundredth of it with 'fraction'; and the particle, pushed a hundred times more weakly,
    has picked up far less of the flow's speed."""
    steps = 3000
    held = thermo_rows(h.run("in.outputs", {"steps": steps}).output)
    part = thermo_rows(h.run("in.outputs", {"steps": steps, "fix_extra": "substep_force fraction"}).output)
    # The last row of that step: the second run's first (the first run ends on it too).
    a = [r for r in held if r["Step"] == steps][-1]
    b = [r for r in part if r["Step"] == steps][-1]
    check("substep_force_held_applies_the_step_force", abs(a["drag_x"] - a["fx"]) <= 1e-12 * abs(a["fx"]),
          f"{a['drag_x']:.12g} against {a['fx']:.12g}", "equal to 1e-12")
    check("substep_force_fraction_applies_one_hundredth", abs(b["drag_x"] - b["fx"] / 100) <= 1e-12 * abs(b["fx"]),
          f"{b['drag_x']:.12g} against {b['fx'] / 100:.12g}", "f_pore[14] / 100 to 1e-12")
    check("substep_force_fraction_carries_the_particle_more_slowly", b["vx"] < 0.2 * a["vx"],
          f"vx {b['vx']:.3g} against {a['vx']:.3g} held", "< 0.2 of the held run's")


def case_reused_tag(h):
    """A particle inserted mid-run in the slot of one that left under the same (reused) tag
    starts its coupling state afresh (fix lbm/pore's create_attribute and set_arrays): its
    first fluid steps' displacement is what it moved, not the 25 cells to where the former
    particle was last seen (in.reused_tag), and the run goes on."""
    run = h.run("in.reused_tag", {}, expect_error=True)
    rows = thermo_rows(run.output)
    before = [r for r in rows if r["Step"] <= 5000]
    after = [r for r in rows if r["Step"] > 5000]
    check("reused_tag_first_particle_left", bool(before) and before[-1]["Atoms"] == 0,
          f"{before[-1]['Atoms'] if before else None} particles at step 5000", "0 (it left the box)")
    check("reused_tag_inserted_particle_present", bool(after) and after[-1]["Atoms"] == 1,
          f"{after[-1]['Atoms'] if after else None} particles at the end", "1")
    check("reused_tag_run_completes", run.code == 0 and bool(after) and after[-1]["Step"] == 6000,
          error_line(run.output) or f"last step {after[-1]['Step'] if after else None}", "runs to step 6000")
    shift = max(r["shift"] for r in after) if after else float("inf")
    check("reused_tag_new_particle_moves_as_carried", shift < 0.5,
          f"largest displacement per fluid step {shift:.3g} cells", "< 0.5 (the speed guard's limit)")


def case_outlet_exit(h):
    """A particle carried out through the outlet face in open fluid (in.outlet_exit) takes the
    same path with the reference pressure kept as removed: the part of it beyond the face feels
    the outlet's pressure (the links the lattice does not hold), so the kept reading no longer
    shoots it out (the build before: out of the box within 80 fluid steps, at up to 0.27 cells
    per fluid step, 2.4 cells ahead of the removed reading's path). Both leave the box, at the
    fluid's pace; kept, 2 ranks meeting through the particle carry it as 1 does."""
    rows = {}
    for reading in ("remove", "keep"):
        run = h.run("in.outlet_exit", {"fix_extra": f"reference_pressure {reading}"})
        rows[reading] = [r for r in thermo_rows(run.output) if r["Atoms"] == 1]
        check(f"outlet_exit_{reading}_leaves", run.code == 0 and thermo_rows(run.output)[-1]["Atoms"] == 0,
              error_line(run.output) or f"{thermo_rows(run.output)[-1]['Atoms']} particles at the end", "0")
    steps = [r["Step"] for r in rows["remove"]]
    check("outlet_exit_same_time_in_the_box", steps == [r["Step"] for r in rows["keep"]] and len(steps) > 40,
          f"{len(rows['remove'])} rows removed, {len(rows['keep'])} kept, last {steps[-1] if steps else None}",
          "the same rows, > 40 (20 000 DEM steps)")
    apart = max((abs(a["x1"] - b["x1"]) for a, b in zip(rows["remove"], rows["keep"])), default=float("inf"))
    check("outlet_exit_kept_path_as_removed", apart < 1e-6,
          f"largest difference in x {apart:.3g} cells", "< 1e-6 (round-off of the reference share)")
    fastest = max((r["vx1"] for r in rows["keep"]), default=float("inf"))
    check("outlet_exit_kept_at_the_fluids_pace", fastest < 0.03,
          f"largest speed {fastest:.3g} cells per time unit", "< 0.03 (six times u; the fluid at the axis: 2 u to 4 u)")
    # Two ranks meeting through the particle (processors 1 2 1): each counts the links of the
    # face nodes it owns, the ghost copy's share summed into the owner's.
    split = [r for r in thermo_rows(h.run("in.outlet_exit", {"fix_extra": "reference_pressure keep", "py": 2},
                                          ranks=2).output) if r["Atoms"] == 1]
    worst = max((abs(a[c] - b[c]) / max(abs(a[c]), 1e-30) for a, b in zip(rows["keep"], split) for c in ("x1", "vx1")),
                default=float("inf"))
    check("outlet_exit_kept_two_ranks_as_one", len(split) == len(rows["keep"]) and worst < 1e-9,
          f"{len(split)} rows against {len(rows['keep'])}, largest relative difference {worst:.3g}",
          "the same rows, < 1e-9 (round-off: sums in another order)")


def case_mpi_splits(h):
    """1 rank against 3 (processors 3 1 1) and 4 (2 2 1, 1 2 2; oversubscribed on 2 cores), and
    with the mass correction in the moving walls' sweep 1 rank against the kernel's pass (the
    default: the same rows) and against 4, and the links in a sweep against the kernel's pass
    (the default: the same rows, on 1 rank and on 4).
    In in.transit a weak gravity along (0, 1, 1) makes particle 1 sink across y = 10 and
    z = 10 while the flow carries it across x = 10 and x = 15, so that it changes owner across
    an x, a y and a z face of the grids (checked in the serial run), passing near the y-z edge
    of the 1 2 2 grid, and particle 2 stays across the y split: fluid halos, ghost particles
    and their reverse-communicated loads cross every kind of subdomain face. Same bound as
    pore_parallel."""
    variables = {"steps": 100000}
    serial = thermo_rows(h.run("in.transit", dict(variables, px=1)).output)
    for axis, column, split_at in (("x", "x1", 15.0), ("y", "y1", 10.0), ("z", "z1", 10.0)):
        start, end = serial[0][column], serial[-1][column]
        check(f"mpi_particle_1_crosses_the_{axis}_split", start < split_at < end,
              f"{start:.3g} -> {end:.3g}", f"from below {split_at:g} to above it")
    def compare(name, reference, rows, bound):
        check(f"{name}_same_rows", len(rows) == len(reference) > 5, f"{len(rows)} vs {len(reference)}",
              "same number of thermo rows (> 5)")
        for column in ("p", "fx", "x1", "y1", "z1", "y2", "x2"):
            scale = max(abs(r[column]) for r in reference)
            worst = max(abs(a[column] - b[column]) for a, b in zip(reference, rows)) / scale
            if bound == 0.0:
                check(f"{name}_max_difference_{column}", worst == 0.0, f"{worst:.3g}", "0: the same rows")
            else:
                check(f"{name}_max_difference_{column}", worst < bound, f"{worst:.3g}",
                      f"< {bound:g} of its largest value over the run")

    splits = {}
    for px, py, pz in ((3, 1, 1), (2, 2, 1), (1, 2, 2)):
        split = thermo_rows(h.run("in.transit", dict(variables, px=px, py=py, pz=pz), ranks=px * py * pz).output)
        compare(f"mpi_{px}{py}{pz}", serial, split, 1e-9)
        splits[(px, py, pz)] = split
    # The link mass correction in the moving walls' sweep (mass_correction sweep) instead of
    # the kernel's pass (the default): the same operations on the same values, so the same
    # rows to the last digit printed, and split as closely.
    sweep_variables = dict(variables, fix_extra="mass_correction sweep")
    sweep = thermo_rows(h.run("in.transit", dict(sweep_variables, px=1)).output)
    compare("sweep_correction_against_kernel", serial, sweep, 0.0)
    split = thermo_rows(h.run("in.transit", dict(sweep_variables, px=2, py=2, pz=1), ranks=4).output)
    compare("sweep_correction_mpi_221", sweep, split, 1e-9)
    # The moving walls' links in a sweep before the kernel (moving_walls sweep) instead of in
    # its pass (the default): the same rows to the last digit printed, on 1 rank and split.
    links_variables = dict(variables, fix_extra="moving_walls sweep")
    links = thermo_rows(h.run("in.transit", dict(links_variables, px=1)).output)
    compare("sweep_links_against_kernel", serial, links, 0.0)
    split = thermo_rows(h.run("in.transit", dict(links_variables, px=1, py=2, pz=2), ranks=4).output)
    compare("sweep_links_against_kernel_mpi_122", splits[(1, 2, 2)], split, 0.0)


def case_restart(h):
    """write_restart + read_restart in a second process continue as if never stopped."""
    common = {"clean_steps": 100000, "restart_read": ""}
    whole = thermo_rows(h.run("in.clog", dict(common, steps=40000, restart_write="")).output)
    # The second half runs in the folder where the first half wrote its restart file.
    first = h.run("in.clog", dict(common, steps=20000, restart_write="write_restart clog.restart"))
    resumed = h.run("in.restart_b", {"restart_file": "clog.restart", "steps": 20000},
                    cwd=first.work).output
    second = thermo_rows(resumed)
    # The file carries LIGGGHTS's own version string (plugin_common/restart_version.h).
    warned = "Restart file version does not match" in resumed
    check("restart_read_without_version_warning", not warned,
          "warned" if warned else "no warning", "no 'Restart file version does not match'")
    a, b = whole[-1], second[-1]
    check("restart_same_final_step", a["Step"] == b["Step"], b["Step"], f"== {a['Step']:.0f}")
    check("restart_same_deposited_count", a["pore[7]"] == b["pore[7]"], f"{b['pore[7]']:.0f}",
          f"== {a['pore[7]']:.0f} (uninterrupted run)")
    # Not bit-identical. The wall's friction springs now go to the restart file (tests/wall_models
    # shows them restored exactly); this difference did not change with them, so it comes from
    # elsewhere in splitting the run (not investigated). pore[17], the largest P / P_out of the
    # run, comes back with the burst detector state (it is the current pressure loss while
    # that rises, so it differs like p).
    for column, bound in (("p", 1e-6), ("x1", 1e-6), ("z5", 1e-6), ("pore[14]", 1e-3), ("pore[17]", 1e-6)):
        diff = relative_difference(a[column], b[column])
        check(f"restart_relative_difference_{column}", diff < bound, f"{diff:.3g}", f"< {bound:g}")


BAD = "scene pore inlet 6 free 4 length 14 outlet 6 width 20 diameter 15"
BAD_CASES = [  # (fix line, second line, boundary "x yz", words the error must contain)
    (f"fix f all lbm/pore {BAD} velocity 0.001", "", "f p", ["'dx'", "> 0", "required"]),
    (f"fix f all lbm/pore dx 1 nu -1 {BAD} velocity 0.001", "", "f p", ["'nu'", "(0, inf]"]),
    (f"fix f all lbm/pore dx 1 n_dem 0 {BAD} velocity 0.001", "", "f p", ["'n_dem'", "[1, 100000]"]),
    (f"fix f all lbm/pore dx 1 magic 0 {BAD} velocity 0.001", "", "f p", ["'magic'", "(0, 10]"]),
    (f"fix f all lbm/pore dx 1 lubrication_cutoff 5 {BAD} velocity 0.001", "", "f p",
     ["'lubrication_cutoff'", "(0, 2]"]),
    (f"fix f all lbm/pore dx 1 colour red {BAD} velocity 0.001", "", "f p", ["'colour'", "valid keywords"]),
    (f"fix f all lbm/pore dx 1 {BAD}", "", "f p", ["drive", "'velocity", "'pressure_loss"]),
    ("fix f all lbm/pore dx 1 scene pore inlet 6 free 4 length 14 outlet 6 width 20 diameter 25 "
     "velocity 0.001", "", "f p", ["diameter", "width"]),
    # 1.0 with dt 0.01, n_dem 100 (the default), dx 1 is 1 cell per fluid step.
    (f"fix f all lbm/pore dx 1 {BAD} velocity 1.0", "", "f p", ["velocity", "0.30"]),
    (f"fix f all lbm/pore dx 1 {BAD} pressure_loss 5", "", "f p", ["pressure_loss", "0.9"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001 max_pressure_loss 5", "", "f p", ["max_pressure_loss", "0.9"]),
    (f"fix f all lbm/pore dx 1 {BAD} pressure_loss 0.01 max_pressure_loss 0.02", "", "f p",
     ["'max_pressure_loss'", "velocity inlet"]),
    ("fix f all lbm/pore dx 1 scene pore inlet 6 free 4 length 14 outlet 16 width 20 diameter 15 "
     "velocity 0.001", "", "f p", ["scene", "simulation box"]),
    # 20 cells of 1.01 fill the box's width 20 to half a cell, but as a periodic length it
    # would put LIGGGHTS's images of a particle 0.2 away from the lattice's.
    (f"fix f all lbm/pore dx 1.01 {BAD} velocity 0.001", "", "f p",
     ["periodic along y", "whole number of cells", "20.2"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001 lateral wall", "", "f p", ["lateral", "boundary"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001 lateral periodic", "", "f f",
     ["lateral", "periodic", "boundary"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001", "", "p p", ["flow axis x", "periodic"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001 boundary fancy", "", "f p", ["'boundary'", "mls"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001 substep_force half", "", "f p",
     ["'substep_force'", "'held'", "'fraction'"]),
    ("fix f all lbm/pore dx 1 scene voxels /nonexistent.raw velocity 0.001", "", "f p",
     ["/nonexistent.raw", "cannot be opened"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001", "fix w all wall/voxel lbm nothere", "f p",
     ["wall/voxel", "'nothere'"]),
    (f"fix f all lbm/pore dx 1 {BAD} velocity 0.001", "fix w all wall/voxel lbm f mu -1", "f p",
     ["wall/voxel", "mu", ">= 0"]),
]


def case_bad_arguments(h):
    """Every bad input stops within 20 s with a LIGGGHTS ERROR naming the keyword (and the
    range), a non-zero exit, no crash (signal) and no NaN anywhere in the output."""
    for line, line2, boundary, words in BAD_CASES:
        bx, bnd = boundary.split()
        name = f"bad_arguments[{line2 or line} | boundary {bx} {bnd} {bnd}]"
        try:
            run = h.run("in.bad", {"fixline": line, "fixline2": line2, "bx": bx, "bnd": bnd},
                        expect_error=True, timeout=20)
        except subprocess.TimeoutExpired:
            check(name, False, "timeout", "an error within 20 s")
            continue
        code, out = run.code, run.output
        error = error_line(out)
        crashed = code < 0 or "Segmentation fault" in out or "signal" in out.lower()
        ok = code != 0 and not crashed and not has_nan(out) and error and all(w in error for w in words)
        check(name, ok, f"exit {code}, {error[:170]!r}", f"ERROR naming {words}, exit != 0, no crash, no NaN")


def case_threads_on_one_core(h):
    """Two OpenMP threads in a process that may run on one core only (what mpirun's default
    binding, one core per rank for up to 2 ranks, does to OMP_NUM_THREADS=2): the set-up
    says how many threads each rank runs and warns, naming the cores and the mpirun options
    that lift the binding; one thread on the same core gives no warning."""
    core = min(os.sched_getaffinity(0))
    outputs = {}
    for threads in (2, 1):
        env = dict(os.environ, OMP_NUM_THREADS=str(threads))
        cmd = [h.driver, "-in", os.path.join(h.scripts, "in.outputs"), "-var", "dir", h.scripts,
               "-var", "steps", "100", "-log", "none"]
        with tempfile.TemporaryDirectory(dir=h.work) as work:
            result = subprocess.run(cmd, cwd=work, env=env, capture_output=True, text=True, errors="replace",
                                    timeout=120, preexec_fn=lambda: os.sched_setaffinity(0, {core}))
        outputs[threads] = result.stdout + result.stderr
        check(f"threads_on_one_core_{threads}_thread_run", result.returncode == 0 and not error_line(outputs[threads]),
              f"exit {result.returncode}", "exit 0, no ERROR")
    warning = next((line for line in outputs[2].splitlines() if line.startswith("WARNING: fix lbm/pore: rank")), "")
    check("threads_on_one_core_warns", "2 OpenMP threads on 1 core" in warning and "--bind-to none" in warning,
          repr(warning[:150]), "a WARNING naming 2 threads on 1 core and 'mpirun --bind-to none'")
    check("threads_on_one_core_summary", "fix lbm/pore: 2 OpenMP threads per rank, 1 rank" in outputs[2],
          "summary line" if "OpenMP threads per rank" in outputs[2] else "none", "'2 OpenMP threads per rank, 1 rank'")
    check("one_thread_on_one_core_does_not_warn", "WARNING: fix lbm/pore: rank" not in outputs[1],
          "no warning" if "WARNING: fix lbm/pore: rank" not in outputs[1] else "a warning", "no warning")


if __name__ == "__main__":
    main({"adhesion": case_adhesion, "clog": case_clog, "clog_pressure": case_clog_pressure,
          "clog_capped": case_clog_capped,
          "parallel": case_parallel, "mpi_splits": case_mpi_splits, "outputs": case_outputs,
          "restart": case_restart, "bad_arguments": case_bad_arguments,
          "threads_on_one_core": case_threads_on_one_core, "substep_force": case_substep_force,
          "reused_tag": case_reused_tag, "outlet_exit": case_outlet_exit}, __doc__)
