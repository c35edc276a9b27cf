#!/usr/bin/env python3
"""Checks of fix wall/voxel's two wall models through liggghts-lbm: one particle of
R = 3.5 cells (d = 7, rho_p = 2.3, mu = 0.1) on voxel walls written here, in the d-unit
reading of the paper's table (k_w = 0.1 x 7^3 = 34.3, k_a = 0.1 x 7^2 = 4.9 lattice units)
and, where named, the lattice reading (k_w = k_a = 0.1). Every threshold is computed here
from the voxel geometry and the coefficients (voxel_sum_reference.py), independently of the
library; each check prints its measured figure and its bound (tests/harness/liggghts_run.py).

usage: wall_check.py --driver PATH --scripts DIR [--mpirun mpirun] CASE
cases: hold_slide_d_unit, hold_slide_lattice, pull_off_d_unit, pull_off_lattice, edge, corner,
       energy, restart_voxel_sum, restart_smooth, spring_overflow, parallel
"""
import math
import os

from liggghts_run import check, error_line, main, thermo_rows
import voxel_sum_reference as ref

R, DENSITY, MU = 3.5, 2.3, 0.1
D_UNIT = ref.Coefficients("d-unit", 0.1 * 7 ** 3, 0.1 * 7 ** 2, MU, R, DENSITY)
LATTICE = ref.Coefficients("lattice", 0.1, 0.1, MU, R, DENSITY)
DIMS = (48, 24, 16)
FLOOR_TOP = 1.5  # two voxel layers, k = 0, 1
FLOOR = [((0, 47), (0, 23), (0, 1))]
EDGE = [((0, 11), (0, 23), (0, 5))]     # a step: its outer edge is the line x = 11.5, z = 5.5
CORNER = [((0, 11), (0, 11), (0, 5))]   # a block: its outer corner is (11.5, 11.5, 5.5)
START = (12.0, 12.0)  # over the middle of floor voxel (12, 12)


def variables(h, coef, boxes, model="voxel_sum", dims=DIMS, spacing=1, **more):
    """The -var set of in.wall_run / in.wall_static: the wall file, the coefficients, the time
    step (1/100 of the resting normal period), no external force unless `more` sets one."""
    voxels = os.path.join(h.work, "walls.raw")
    ref.write_voxel_file(voxels, dims, boxes, spacing)
    out = {"voxels": voxels, "model": model, "kw": coef.k_w, "ka": coef.k_a, "mu": coef.mu,
           "dt": coef.time_step(), "wall_id": "wall", "every": 50, "settle": 6000, "steps": 0,
           "after": "", "ramp": 0, "fx": 0, "fy": 0, "fz": 0, "cx": 0, "cy": 0, "cz": 0,
           "leash": 1e9}
    out.update(more)
    return out


def ramp(points):
    """A piecewise-linear function of the step through (step, value) points, flat outside,
    as a LIGGGHTS equal-style expression without spaces."""
    terms = [f"{points[0][1]!r}"]
    for (a, fa), (b, fb) in zip(points, points[1:]):
        slope = (fb - fa) / (b - a)
        terms.append(f"({slope!r})*((step>{a})*(step<{b})*(step-{a})+(step>={b})*{b - a})")
    return "+".join(terms)


def rest_height(coef, load=0.0):
    """Where the particle over START rests, reached from above (the reference's root)."""
    return ref.balanced_height(FLOOR, coef, *START, load, (0, 0, 0),
                               FLOOR_TOP + coef.reach() - 1e-9)


def settled_check(coef, rows, settle, z_rest):
    row = next(r for r in rows if r["Step"] == settle)
    contacts = ref.voxel_sum(FLOOR, coef, (*START, z_rest)).contacts
    check(f"settled_{coef.name}", abs(row["pz"] - z_rest) < 1e-3 and row["wall[1]"] == contacts,
          f"z - z_rest = {row['pz'] - z_rest:.2e}, {row['wall[1]']:.0f} contacts",
          f"|z - z_rest| < 1e-3 cell (z_rest = {z_rest:.6f} from the reference's force "
          f"balance), {contacts} contacts")
    return row


def farthest(rows, start, axis, last_step):
    return max(abs(r[axis] - start[axis]) for r in rows if start["Step"] <= r["Step"] <= last_step)


def hold_slide(h, coef):
    """A tangential force along +x rising slowly (each stage over 50 periods of the particle's
    tangential oscillation on its 9 springs): up to 95 % of the friction limit at rest (sum of
    mu (|F_n,k| + F_a,k)) the springs hold it; up to and at 95 % of the largest resistance
    met sliding over the next two cells (friction at the limit plus the tangential part of
    the normal forces, the height balanced) it stays in its cell; at 105 % it slides on."""
    z_rest = rest_height(coef)
    at_rest, largest = ref.slide_threshold(FLOOR, coef, *START, z_rest)
    period = 2 * math.pi * math.sqrt(coef.mass / (2 / 7 * coef.k_w * 9)) / coef.time_step()
    stage, settle = int(50 * period), 6000
    t1, t2, t3, t4 = settle + stage, settle + 2 * stage, settle + 3 * stage, settle + 3 * stage + stage // 5
    schedule = [(settle, 0.0), (t1, 0.95 * at_rest), (t2, 0.95 * largest), (t3, 0.95 * largest),
                (t4, 1.05 * largest)]
    rows = thermo_rows(h.run("in.wall_run", variables(
        h, coef, FLOOR, x0=START[0], y0=START[1], z0=z_rest + 0.01, settle=settle,
        steps=t4 + stage - settle, ramp=ramp(schedule), fx=1, leash=3.0)).output)
    start = settled_check(coef, rows, settle, z_rest)
    stuck, crept = farthest(rows, start, "px", t1), farthest(rows, start, "px", t3)
    slid = farthest(rows, start, "px", t4 + stage)
    check(f"held_by_springs_{coef.name}", stuck < 0.2, f"moved {stuck:.4f} cell",
          f"< 0.2 cell up to 0.95 x the friction limit at rest {at_rest:.5g}")
    check(f"held_below_threshold_{coef.name}", crept < 1.0, f"moved {crept:.4f} cell",
          f"< 1 cell up to and held at 0.95 x the sliding threshold {largest:.5g}")
    check(f"slides_above_threshold_{coef.name}", slid > 2.0, f"moved {slid:.2f} cells",
          f"> 2 cells at 1.05 x the sliding threshold {largest:.5g}")


def pull_off(h, coef):
    """A normal pull rising slowly (50 normal periods) to 97 % of the reference pull-off force
    (the largest net attraction of the voxels from the rest height up) and held: the particle
    stays on the floor; then to 103 %: it is torn off."""
    z_rest = rest_height(coef)
    force = ref.pull_off_force(FLOOR, coef, *START, z_rest, FLOOR_TOP)
    stage, settle = 5000, 6000
    schedule = [(settle, 0.0), (settle + stage, 0.97 * force), (settle + 2 * stage, 0.97 * force),
                (settle + 2 * stage + stage // 5, 1.03 * force)]
    end = settle + 3 * stage + stage // 5
    rows = thermo_rows(h.run("in.wall_run", variables(
        h, coef, FLOOR, x0=START[0], y0=START[1], z0=z_rest + 0.01, settle=settle,
        steps=end - settle, ramp=ramp(schedule), fz=1, leash=3.0)).output)
    start = settled_check(coef, rows, settle, z_rest)
    held = [r for r in rows if settle <= r["Step"] <= settle + 2 * stage]
    rose = max(r["pz"] - start["pz"] for r in held)
    touching = min(r["wall[1]"] for r in held)
    torn = rows[-1]["pz"] - start["pz"]
    smooth = 0.03 * coef.k_a * R * R
    check(f"pull_off_held_{coef.name}", rose < 0.2 and touching > 0,
          f"rose {rose:.4f} cell, at least {touching:.0f} contacts",
          f"< 0.2 cell and touching, at 0.97 x the pull-off force {force:.5g} "
          f"({force / smooth:.2f} x the smooth wall's 0.03 ka R^2 = {smooth:.4g})")
    check(f"pull_off_torn_{coef.name}", torn > 1.0 and rows[-1]["wall[1]"] == 0,
          f"rose {torn:.1f} cells, {rows[-1]['wall[1]']:.0f} contacts",
          f"> 1 cell and no contact at 1.03 x {force:.5g}")


def static_run(h, coef, boxes, positions, **more):
    """The wall force at each position, the particle held there (run 0 per position)."""
    path = os.path.join(h.work, "positions.in")
    with open(path, "w") as f:
        for c in positions:
            f.write(f"set atom 1 x {c[0]!r} y {c[1]!r} z {c[2]!r}\nrun 0\n")
    return h.run("in.wall_static", variables(h, coef, boxes, x0=20, y0=12, z0=12,
                                              positions=path, **more))


def static_rows(h, coef, boxes, positions):
    return thermo_rows(static_run(h, coef, boxes, positions).output)


def compare_static(name, coef, boxes, positions, rows):
    """Force and contact count of each held position against the reference sum."""
    worst, counts_equal = 0.0, len(rows) == len(positions)
    for c, row in zip(positions, rows):
        want = ref.voxel_sum(boxes, coef, c)
        got = (row["wall[2]"], row["wall[3]"], row["wall[4]"])
        scale = 1.0 + math.sqrt(sum(x * x for x in want.normal))
        worst = max(worst, max(abs(g - w) for g, w in zip(got, want.normal)) / scale)
        counts_equal = counts_equal and row["wall[1]"] == want.contacts
    check(f"{name}_force_is_the_voxel_sum", worst < 1e-10 and counts_equal,
          f"largest difference {worst:.2e} (relative to 1 + |F|) over {len(rows)} positions, "
          f"contact counts {'equal' if counts_equal else 'differ'}",
          "< 1e-10, the same contact counts as the reference sum")


def settle_under_load(h, coef, boxes, corner, direction, load, name):
    """Pressed along -direction onto the feature at `corner` with a constant force `load`,
    the particle settles on the line through it where the reference sum carries the load
    (root of the sum's component along `direction`), to within the band the friction springs
    can hold: their capacity sum mu |F_k| over the sum's stiffness along the line (the springs
    of voxels whose normal is tilted from the line carry part of the load while it settles)."""
    def on_line(d0):
        return tuple(corner[a] + d0 * direction[a] for a in range(3))

    def carried(d0):
        s = ref.voxel_sum(boxes, coef, on_line(d0))
        return sum(s.normal[a] * direction[a] for a in range(3)) - load
    lo, hi = R - 0.5, R + 0.01  # carried(lo) > 0 > carried(hi) (adhesion or nothing)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if carried(mid) > 0 else (lo, mid)
    d0 = 0.5 * (lo + hi)
    at_d0 = ref.voxel_sum(boxes, coef, on_line(d0))
    stiffness = (carried(d0 - 1e-6) - carried(d0 + 1e-6)) / 2e-6
    band = at_d0.capacity / stiffness
    start = on_line(R + 0.02)
    push = {f"c{axis}": -load * direction[a] for a, axis in enumerate("xyz")}
    rows = thermo_rows(h.run("in.wall_run", variables(
        h, coef, boxes, x0=start[0], y0=start[1], z0=start[2], settle=0, steps=20000,
        **push)).output)
    end = rows[-1]
    at = (end["px"], end["py"], end["pz"])
    along = sum((at[a] - corner[a]) * direction[a] for a in range(3))
    off_line = math.sqrt(sum((at[a] - corner[a] - along * direction[a]) ** 2 for a in range(3)))
    check(f"{name}_settles_where_the_sum_carries_the_load",
          abs(along - d0) <= band and off_line < 1e-9 and end["wall[1]"] == at_d0.contacts,
          f"distance {along:.8f} (reference {d0:.8f}, off by {abs(along - d0):.1e}), "
          f"{off_line:.1e} off the line, {end['wall[1]']:.0f} contacts",
          f"off by <= {band:.2e} (friction band), < 1e-9 off the line, {at_d0.contacts} "
          f"contacts, under a load {load} (one voxel's overlap {load / coef.k_w:.4f})")


def edge(h):
    """Over the outer edge of a step: the fix's force at held positions (over a voxel's
    middle, over the joint of two, in between; overlapping and adhering) is the reference sum
    of the edge row, and a particle pressed onto the edge along its bisector settles where
    that sum carries the load."""
    coef = D_UNIT
    b = (1 / math.sqrt(2), 0.0, 1 / math.sqrt(2))
    positions = [(11.5 + d0 * b[0], y, 5.5 + d0 * b[2]) for y in (12.0, 12.5, 12.2)
                 for d0 in (R - 0.05, R - 0.01, R + 0.02, R + 0.09)]
    compare_static("edge", coef, EDGE, positions, static_rows(h, coef, EDGE, positions))
    settle_under_load(h, coef, EDGE, (11.5, 12.0, 5.5), b, 1.0, "edge")


def corner(h):
    """Over the outer corner of a block: on the diagonal only the corner voxel is in reach
    (one contact, force along the diagonal), off it the fix's force is the reference sum; a
    particle pressed onto the corner along the diagonal settles at overlap load / k_w."""
    coef = D_UNIT
    s3 = 1 / math.sqrt(3)
    diagonal = (s3, s3, s3)
    positions = [(11.5 + d0 * s3, 11.5 + d0 * s3, 5.5 + d0 * s3)
                 for d0 in (R - 0.05, R - 0.01, R + 0.02, R + 0.09)]
    positions += [(11.5 - 0.3, 11.5 - 0.2, 5.5 + R - 0.04), (11.5 + 0.4, 11.5 - 1.2, 5.5 + R + 0.03),
                  (12.5, 12.5, 5.5 + R - 0.2)]
    rows = static_rows(h, coef, CORNER, positions)
    compare_static("corner", coef, CORNER, positions, rows)
    alone = all(r["wall[1]"] == 1 for r in rows[:4])
    check("corner_voxel_acts_alone_on_the_diagonal", alone,
          f"contacts {[int(r['wall[1]']) for r in rows[:4]]}", "1 at each diagonal position")
    settle_under_load(h, coef, CORNER, (11.5, 11.5, 5.5), diagonal, 1.0, "corner")


def contact_energy(coef, boxes, c):
    """Potential of the conservative voxel forces, each continuous through its range:
    k_w delta^2 / 2 overlapping, k_a R h^2 / 2 adhering, constant beyond (taken as zero)."""
    rng = ref.RANGE * coef.radius
    beyond = 0.5 * coef.k_a * coef.radius * rng * rng
    energy = 0.0
    for voxel in ref.solid_near(boxes, c, coef.reach() + 0.5):
        d = ref.cube_offset(c, voxel)
        gap = math.sqrt(sum(x * x for x in d)) - coef.radius
        if gap < 0.0:
            energy += 0.5 * coef.k_w * gap * gap - beyond
        elif gap <= rng:
            energy += 0.5 * coef.k_a * coef.radius * gap * gap - beyond
    return energy


def energy(h):
    """Energy does not grow for a particle resting on the wall: released at rest 0.05 cell
    along the floor and half the adhesion range above its rest, its energy (kinetic plus the
    voxels' potentials, from its printed position and velocity) never exceeds the start by
    more than 1.5 % of what it was given (the unit test's bound: friction springs, not
    counted here, hold a little while they load), its maximum over each block of 1000 steps
    does not grow from one block to the next, and it ends below half of what it was given."""
    coef = D_UNIT
    z_rest = rest_height(coef)
    start = (START[0] + 0.05, START[1] + 0.02, z_rest + 0.5 * ref.RANGE * R)
    rows = thermo_rows(h.run("in.wall_run", variables(
        h, coef, FLOOR, x0=start[0], y0=start[1], z0=start[2], settle=10000, every=10)).output)
    rows = [r for r in rows if r["Step"] <= 10000]

    def total(r):
        kinetic = 0.5 * coef.mass * (r["vx"] ** 2 + r["vy"] ** 2 + r["vz"] ** 2)
        return kinetic + contact_energy(coef, FLOOR, (r["px"], r["py"], r["pz"]))
    e0 = total(rows[0])
    given = e0 - contact_energy(coef, FLOOR, (*START, z_rest))
    energies = [total(r) for r in rows]
    highest = max(energies)
    blocks = [max(e for r, e in zip(rows, energies) if b * 1000 < r["Step"] <= (b + 1) * 1000)
              for b in range(10)]
    growth = max(b - a for a, b in zip(blocks, blocks[1:]))
    check("energy_never_above_start", highest <= e0 + 0.015 * given,
          f"highest {(highest - e0) / given:+.2e} of the energy given ({given:.4g})",
          "<= +1.5e-02 of it")
    check("energy_block_maximum_does_not_grow", growth <= 1e-9 * given,
          f"largest growth of the block maximum {growth / given:+.2e} of the energy given",
          "<= 1e-9 of it (blocks of 1000 steps)")
    check("energy_dissipated", energies[-1] < e0 - 0.5 * given,
          f"lost {(e0 - energies[-1]) / given:.3f} of it", "> 0.5 of it")


def restart(h, model):
    """Springs survive write_restart/read_restart: a particle on the floor under a normal
    load and a tangential force below its friction limit, run N + M steps in one process
    (two runs), against N steps, write_restart, and M steps after read_restart in a second
    process. Both call LIGGGHTS's setup at step N, so the positions must agree to round-off.
    The same restart with the wall fix under a new ID (its springs start from zero) must
    not: it shows how far lost springs move the particle. Read by the other model, the
    springs are refused with an error naming both models."""
    coef = D_UNIT
    load = 0.05 * coef.k_a * R * R
    if model == "voxel_sum":
        z_rest = rest_height(coef, load)
        capacity = ref.voxel_sum(FLOOR, coef, (*START, z_rest)).capacity
    else:  # one contact, overlap load / k_w: friction limit mu k_w delta = mu load
        z_rest = FLOOR_TOP + R - load / coef.k_w
        capacity = coef.mu * load
    settle, first, second = 6000, 8000, 4000
    schedule = [(settle, 0.0), (settle + 4000, 0.6 * capacity)]
    common = variables(h, coef, FLOOR, model=model, x0=START[0], y0=START[1], z0=z_rest + 0.01,
                       settle=settle, ramp=ramp(schedule), fx=1, cz=-load)
    whole = thermo_rows(h.run("in.wall_run", dict(common, steps=first,
                                                  after=f"run {second}")).output)
    written = h.run("in.wall_run", dict(common, steps=first, after="write_restart wall.restart"))
    resume = dict(common, restart_file="wall.restart", steps=second, xs=0, ys=0, zs=0)
    resumed = thermo_rows(h.run("in.wall_resume", resume, cwd=written.work).output)
    fresh = thermo_rows(h.run("in.wall_resume", dict(resume, wall_id="renamed"),
                              cwd=written.work).output)
    a, b, c = whole[-1], resumed[-1], fresh[-1]
    step = settle + first + second
    difference = max(abs(a[k] - b[k]) for k in ("px", "py", "pz"))
    lost = max(abs(a[k] - c[k]) for k in ("px", "py", "pz"))
    check(f"restart_{model}_same_final_step", a["Step"] == b["Step"] == step, f"{b['Step']:.0f}",
          f"== {step}")
    check(f"restart_{model}_springs_kept", difference < 1e-12 and b["wall[1]"] == a["wall[1]"],
          f"largest position difference {difference:.2e} cell, {b['wall[1]']:.0f} contacts",
          f"< 1e-12 cell (round-off) from the uninterrupted run, {a['wall[1]']:.0f} contacts; "
          f"tangential force 0.6 x the friction limit {capacity:.4g}")
    check(f"restart_{model}_lost_springs_would_show", lost > 1e3 * max(difference, 1e-15),
          f"{lost:.2e} cell with the springs started from zero",
          "> 1000 x the difference with the springs kept")
    other = "smooth" if model == "voxel_sum" else "voxel_sum"
    refused = h.run("in.wall_resume", dict(resume, model=other), cwd=written.work,
                    expect_error=True)
    expected = f"springs written by model {model}, this fix has model {other}"
    check(f"restart_{model}_read_by_{other}_refused", expected in refused.output,
          error_line(refused.output) or "no error", f"an ERROR saying '{expected}'")


def spring_overflow(h):
    """More voxel contacts than a particle's spring store holds (64) are never silent: on a
    floor of quarter-cell voxels a particle at 5 % overlap touches about a hundred; the fix
    counts the springs it could not keep (f_ID[7], cumulative) and warns once per run."""
    coef = D_UNIT
    floor = [((0, 191), (0, 95), (0, 3))]  # top face z = 3.5 x 0.25
    top = 3.5 * 0.25
    positions = [(24.0, 12.0, top + 0.95 * R), (24.1, 12.0, top + 0.95 * R)]
    run = static_run(h, coef, floor, positions, dims=(192, 96, 8), spacing=0.25)
    rows = thermo_rows(run.output)
    dropped = [r["wall[7]"] for r in rows]
    contacts = [r["wall[1]"] for r in rows]
    expected = [sum(c - 64 for c in contacts[:n + 1]) for n in range(len(contacts))]
    warnings = run.output.count("found no room for their tangential spring")
    check("spring_overflow_counted", dropped == expected,
          f"f_wall[7] {dropped} with {contacts} contacts", f"{expected} (contacts beyond 64, summed)")
    check("spring_overflow_warned_once_per_run", warnings == len(rows),
          f"{warnings} warnings in {len(rows)} runs", "one per run")


def parallel(h):
    """The springs travel with their atom between ranks: a particle pushed along the floor
    from x = 20 with a force above the sliding threshold for 5 cells slides across the rank
    boundary at x = 24 and comes to rest; 1 and 2 ranks give the same thermo rows."""
    coef = D_UNIT
    z_rest = ref.balanced_height(FLOOR, coef, 20.0, 12.0, 0.0, (0, 0, 0),
                                 FLOOR_TOP + coef.reach() - 1e-9)
    common = variables(h, coef, FLOOR, x0=20.0, y0=12.0, z0=z_rest + 0.01, every=100,
                       steps=20000, ramp=ramp([(6000, 0.0), (9000, 2.3)]), fx=1, leash=5.0)
    serial = thermo_rows(h.run("in.wall_run", common).output)
    split = thermo_rows(h.run("in.wall_run", common, ranks=2).output)
    worst = max(abs(a[k] - b[k]) for a, b in zip(serial, split) for k in a)
    end = serial[-1]
    check("parallel_crosses_the_rank_boundary", end["px"] > 26.0 and end["wall[1]"] == 9,
          f"from x = 20 to {end['px']:.3f}, {end['wall[1]']:.0f} contacts at rest",
          "beyond x = 24 + R, held by 9 voxels")
    check("parallel_serial_vs_2_ranks", len(serial) == len(split) and worst < 1e-9,
          f"largest difference {worst:.2e} over {len(serial)} vs {len(split)} rows",
          "< 1e-9, the same rows")


if __name__ == "__main__":
    main({"hold_slide_d_unit": lambda h: hold_slide(h, D_UNIT),
          "hold_slide_lattice": lambda h: hold_slide(h, LATTICE),
          "pull_off_d_unit": lambda h: pull_off(h, D_UNIT),
          "pull_off_lattice": lambda h: pull_off(h, LATTICE),
          "edge": edge, "corner": corner, "energy": energy,
          "restart_voxel_sum": lambda h: restart(h, "voxel_sum"),
          "restart_smooth": lambda h: restart(h, "smooth"),
          "spring_overflow": spring_overflow, "parallel": parallel}, __doc__)
