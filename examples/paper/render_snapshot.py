#!/usr/bin/python3
"""The paper's snapshot figure (Fig. collection) from a run's own VTK files: the pore (1) before
any deposit, (2) at a pressure peak and (3) after the burst, each a slice of the fluid speed
through the pore's axis with the particles on it coloured by their drag per mass (blue to
yellow, low to high), beside the pressure loss with the three times marked.

Usage: render_snapshot.py <run folder> [--out collection.png] [--keep]
       render_snapshot.py <run folder> --at peak [--out snapshot_peak.png]

With --at peak it draws one snapshot, the clogged pore at the run's highest pressure peak:
the fluid file nearest the thermo row with the highest P / P_out once particles are in, with
the particle file of the same step, above the pressure loss with the peak, that frame and all
VTK frames marked; it says how far the frame lies from the peak and, when P there is more than
10 % below the peak, that the files are too far apart to catch it.

The run folder is what in.pore writes with vtk_every > 0: fluid_vtk/fluid_<fluid step>.vti
(.pvti on several ranks), particles_vtk/particles_<DEM step>.vtp (id radius mass x v
f_pore[1-3]), log.liggghts and bursts.txt. The three times: (2) the file nearest the peak of
the largest burst, (1) the pore least clogged before it (the lowest P / P_out with particles
in: pick_times), (3) the first file after that burst's minimum; a run without a burst
takes (2) at its largest P / P_out with particles in and (3) at its end, and says so in the
title. --keep also writes <run>/snapshots.npz, the three frames (slices and particles, some
hundred kB), from which the figure is redrawn once the VTK files are gone.

The files are read and sliced with VTK's Python bindings (Debian's python3-vtk9) and drawn with
matplotlib's Agg backend. VTK's own render window is not used: Debian builds python3-vtk9 for
X11/GLX only (no OSMesa or EGL), and without a display it aborts ("bad X server connection",
checked here); matplotlib draws without one, so the picture renders on any node.
"""
import argparse
import glob
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLPImageDataReader,  # noqa: E402
                                 vtkXMLPolyDataReader)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from study_io import bursts, lattice_timing, thermo  # noqa: E402


def fluid_files(run_dir):
    """{fluid step: path} of the run's fluid files."""
    files = {}
    for path in glob.glob(os.path.join(run_dir, "fluid_vtk", "fluid_*.*vti")):
        m = re.search(r"fluid_(\d+)\.p?vti$", path)
        if m:
            files[int(m.group(1))] = path
    return files


def read_fluid_slice(path):
    """(speed[x, y] on the mid-z plane, solid mask, spacing, origin) of a fluid file."""
    reader = vtkXMLPImageDataReader() if path.endswith(".pvti") else vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    nx, ny, nz = image.GetDimensions()
    data = image.GetPointData()
    velocity = vtk_to_numpy(data.GetArray("velocity")).reshape(nz, ny, nx, 3)
    node_type = vtk_to_numpy(data.GetArray("node_type")).reshape(nz, ny, nx)
    k = nz // 2
    speed = np.linalg.norm(velocity[k], axis=-1).T
    return speed, (node_type[k] != 0).T, image.GetSpacing(), image.GetOrigin()


def read_particles(path):
    """(x, y, z, radius, drag per mass) of a particle file; empty arrays when it has none."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    if poly.GetNumberOfPoints() == 0:
        return (np.zeros(0),) * 5
    xyz = vtk_to_numpy(poly.GetPoints().GetData())
    data = poly.GetPointData()
    radius = vtk_to_numpy(data.GetArray("radius"))
    mass = vtk_to_numpy(data.GetArray("mass"))
    force = vtk_to_numpy(data.GetArray("f_pore[1-3]")).reshape(-1, 3)
    return xyz[:, 0], xyz[:, 1], xyz[:, 2], radius, np.linalg.norm(force, axis=1) / mass


def draw_frame(ax, fluid, particles, vmax, dmax):
    """One snapshot on `ax`: the fluid slice (read_fluid_slice) coloured by speed from 0 to
    vmax (rainbow), walls in grey, and the particles (read_particles) as circles of their own
    radius coloured by drag per mass from 0 to dmax (viridis). Returns (the fluid's image, the
    particles' collection or None)."""
    speed, solid, spacing, origin = fluid
    extent = [origin[0] - spacing[0] / 2, origin[0] + (speed.shape[0] - 0.5) * spacing[0],
              origin[1] - spacing[1] / 2, origin[1] + (speed.shape[1] - 0.5) * spacing[1]]
    shown = np.ma.masked_where(solid, speed)
    ax.set_facecolor("0.55")  # walls and particles (solid nodes) in grey
    image = ax.imshow(shown.T, origin="lower", extent=extent, cmap="rainbow", vmin=0,
                      vmax=vmax, interpolation="nearest")
    x, y, _, r, drag = particles
    circles = None
    if len(x):
        circles = PatchCollection([Circle((a, b), c) for a, b, c in zip(x, y, r)],
                                  cmap="viridis", edgecolor="k", linewidth=0.3)
        circles.set_array(drag)
        circles.set_clim(0, dmax)
        ax.add_collection(circles)
    ax.set_aspect("equal")
    return image, circles


def particle_file(run_dir, fluid_step, n_dem):
    """The particle file written with fluid step `fluid_step` (its DEM step in the name)."""
    return os.path.join(run_dir, "particles_vtk", f"particles_{fluid_step * n_dem}.vtp")


def highest_peak(run_dir):
    """(DEM step, P / P_out) of the thermo row with the highest P / P_out (f_pore[16]) once
    particles are in the scene (Atoms > 0: the start-up transient of the particle-free flow
    overshoots and is no peak of a clogged pore); all rows when none has particles."""
    columns = thermo(run_dir)
    if "pore[16]" not in columns:
        sys.exit(f"{run_dir}: no thermo column pore[16] (P / P_out) in the log")
    rows = list(zip(columns["Step"], columns["pore[16]"], columns.get("Atoms", columns["Step"])))
    with_particles = [r for r in rows if r[2] > 0 and "Atoms" in columns]
    step, p, _ = max(with_particles or rows, key=lambda r: r[1])
    return step, p


def render_peak(run_dir, out):
    """The clogged pore at the run's highest pressure peak: the fluid file nearest to the
    highest P / P_out once particles are in (highest_peak) and the particle file of the same
    step, drawn as draw_frame does, above the pressure loss with the peak and the frame
    marked. Returns dict(frame, peak_step, peak_P, distance, particles, drag_max): the frame
    and the peak in fluid steps, their distance, the particles drawn and the largest drag per
    mass among them."""
    files = fluid_files(run_dir)
    if not files:
        sys.exit(f"{run_dir}: no fluid_vtk/fluid_*.vti (run with vtk_every > 0)")
    n_dem = lattice_timing(run_dir)["n_dem"]
    peak_dem_step, peak_p = highest_peak(run_dir)
    peak = peak_dem_step / n_dem
    frame = min(sorted(files), key=lambda s: abs(s - peak))
    fluid = read_fluid_slice(files[frame])
    path = particle_file(run_dir, frame, n_dem)
    parts = read_particles(path) if os.path.exists(path) else (np.zeros(0),) * 5
    vmax = float(fluid[0].max()) or 1.0
    dmax = float(parts[4].max()) if len(parts[4]) else 0.0
    speed, _, spacing, _ = fluid
    height = 7.0 * (speed.shape[1] * spacing[1]) / (speed.shape[0] * spacing[0])  # the slice's
    fig = plt.figure(figsize=(8, height + 3.4))
    grid = fig.add_gridspec(3, 2, height_ratios=[height, 0.12, 2.0], hspace=0.5, wspace=0.25)
    ax, trace = fig.add_subplot(grid[0, :]), fig.add_subplot(grid[2, :])
    image, circles = draw_frame(ax, fluid, parts, vmax, dmax or 1.0)
    ax.set_xlabel("x (along the flow)")
    ax.set_ylabel("y")
    bars = [fig.colorbar(image, cax=fig.add_subplot(grid[1, 0]), orientation="horizontal",
                         label="fluid speed [cells / fluid step]")]
    if circles is not None:
        bars.append(fig.colorbar(circles, cax=fig.add_subplot(grid[1, 1]), orientation="horizontal",
                                 label="particle drag per mass, |f_pore[1-3]| / m"))
    for bar in bars:
        bar.ax.xaxis.set_major_locator(MaxNLocator(4))
    distance = frame - peak
    columns = thermo(run_dir)
    t = np.asarray(columns["Step"]) / n_dem
    frame_p = columns["pore[16]"][int(np.argmin(np.abs(t - frame)))]  # the nearest thermo row's
    ax.set_title(f"fluid step {frame}: the VTK frame nearest the highest peak, P = {frame_p:.3g} "
                 f"P_out, {len(parts[0])} particles\nthe peak: P = {peak_p:.3g} P_out at fluid "
                 f"step {peak:g} ({distance:+g} fluid steps); fluid: slice through the pore axis",
                 fontsize=9)
    trace.plot(t, columns["pore[16]"], "k-", lw=1)
    trace.plot([peak], [peak_p], "v", color="C3", label="highest peak")
    trace.axvline(frame, color="C0", ls=":", label="frame shown")
    trace.plot(sorted(files), [0.0] * len(files), "|", color="C0", ms=8,
               transform=trace.get_xaxis_transform(), clip_on=False, label="VTK frames")
    trace.legend(fontsize=8, loc="upper left")
    trace.set_xlabel("fluid step")
    trace.set_ylabel("P / P_out")
    fig.savefig(out, dpi=100, bbox_inches="tight")
    print(f"wrote {out}: fluid step {frame}, the VTK frame nearest the highest peak "
          f"(P {peak_p:.4g} P_out at fluid step {peak:g}, {distance:+g} fluid steps away), "
          f"{len(parts[0])} particles, drag per mass up to {dmax:.3g}")
    if frame_p < 0.9 * peak_p:
        spacing = np.diff(sorted(files))
        print(f"note: the frame misses the peak (P there {frame_p:.4g} P_out, "
              f"{100 * (1 - frame_p / peak_p):.0f} % below it): the VTK files are "
              f"{int(spacing.max()) if len(spacing) else 0} fluid steps apart; write them more "
              f"often (in.pore: -var vtk_every) to catch a peak")
    return dict(frame=frame, peak_step=peak, peak_P=peak_p, frame_P=frame_p, distance=distance,
                particles=len(parts[0]), drag_max=dmax)


def pick_times(run_dir, steps):
    """The three fluid steps (before, peak, after) among `steps` and a note on how they were
    chosen. (1) is the pore least clogged before the burst's peak: among the files before it
    with particles in (Atoms > 0, the flow past its start-up), the one at the lowest P / P_out,
    on a tie the one with the least deposited (f_pore[6]), then the latest. In a run's first
    part that is the clean pore before any deposit; in a window replayed from a clogging run
    (replay_window.py) the pore after the burst before, as the deposit that bursts starts to
    form. The deposited count alone would not do there: it flickers between 0 and some 20
    within a few hundred fluid steps as a creeping deposit's particles pass the speed bound."""
    columns = thermo(run_dir)
    rows = list(zip(columns.get("Step", []), columns.get("pore[6]", []),
                    columns.get("pore[16]", []), columns.get("Atoms", [1.0] * len(columns.get("Step", [])))))
    timing = lattice_timing(run_dir)  # the run's own DEM steps per fluid step and fluid step
    fluid_step = lambda dem_step: dem_step / timing["n_dem"]  # noqa: E731
    nearest = lambda t: min(steps, key=lambda s: abs(s - t))  # noqa: E731
    events = bursts(run_dir)
    if events:
        largest = max(events, key=lambda b: b["delta_P"])
        peak = nearest(fluid_step(largest["step"]))
        # delta_t is a time (the script's unit); dt_f of it make one fluid step
        after_time = fluid_step(largest["step"]) + largest["delta_t"] / timing["dt_f"]
        after = min([s for s in steps if s >= after_time] or [steps[-1]])
        note = f"largest burst: P {largest['P_peak']:.3g} -> {largest['P_after']:.3g} P_out"
    else:
        top = highest_peak(run_dir)[0] if rows else steps[-1] * timing["n_dem"]
        peak, after = nearest(fluid_step(top)), steps[-1]
        note = "no burst in this run: (2) at its largest P / P_out, (3) at its end"
    # each file's thermo row: the nearest one
    row_steps = np.asarray([fluid_step(r[0]) for r in rows], float)
    at = lambda s: rows[int(np.argmin(np.abs(row_steps - s)))]  # noqa: E731
    earlier = [s for s in steps if s < peak] or [steps[0]]
    candidates = [s for s in earlier if at(s)[3] > 0] or earlier if rows else earlier
    before = min(candidates, key=lambda s: (at(s)[2], at(s)[1], -s)) if rows else candidates[-1]
    return (before, peak, after), note


def collection_frames(run_dir):
    """What the snapshot figure draws, from the run's VTK files: the three fluid steps, the
    note on them, each step's fluid slice (read_fluid_slice) and particles (read_particles),
    and the pressure loss over the run (fluid step, P / P_out)."""
    files = fluid_files(run_dir)
    if not files:
        sys.exit(f"{run_dir}: no fluid_vtk/fluid_*.vti (run with vtk_every > 0) and no {KEPT}")
    times, note = pick_times(run_dir, sorted(files))
    n_dem = lattice_timing(run_dir)["n_dem"]
    parts = []
    for s in times:
        path = particle_file(run_dir, s, n_dem)
        parts.append(read_particles(path) if os.path.exists(path) else (np.zeros(0),) * 5)
    columns = thermo(run_dir)
    trace = (np.asarray(columns["Step"]) / n_dem, np.asarray(columns["pore[16]"])) \
        if "pore[16]" in columns else (np.zeros(0), np.zeros(0))
    return dict(name=os.path.basename(os.path.abspath(run_dir)), times=tuple(times), note=note,
                fluid=[read_fluid_slice(files[s]) for s in times], particles=parts, trace=trace)


# The three frames of a run's snapshot figure, small enough for the repository (the slices
# and the particles, not the VTK files): `render_snapshot.py <run> --keep` writes it, and
# render() draws from it where the VTK files are gone (compact_study.py keeps it).
KEPT = "snapshots.npz"


def save_frames(frames, path):
    arrays = dict(name=frames["name"], times=np.asarray(frames["times"]), note=frames["note"],
                  trace_t=frames["trace"][0], trace_P=frames["trace"][1])
    for n, (fluid, parts) in enumerate(zip(frames["fluid"], frames["particles"])):
        speed, solid, spacing, origin = fluid
        arrays.update({f"speed{n}": speed.astype(np.float32), f"solid{n}": solid,
                       f"spacing{n}": np.asarray(spacing), f"origin{n}": np.asarray(origin),
                       f"particles{n}": np.asarray(parts, dtype=np.float32).reshape(5, -1)})
    np.savez_compressed(path, **arrays)


def load_frames(path):
    with np.load(path) as a:
        return dict(name=str(a["name"]), times=tuple(int(t) for t in a["times"]), note=str(a["note"]),
                    trace=(a["trace_t"], a["trace_P"]),
                    fluid=[(a[f"speed{n}"], a[f"solid{n}"], tuple(a[f"spacing{n}"]), tuple(a[f"origin{n}"]))
                           for n in range(3)],
                    particles=[tuple(a[f"particles{n}"].astype(float)) for n in range(3)])


def draw_collection(frames, out):
    times = frames["times"]
    fig, axes = plt.subplots(4, 1, figsize=(8, 11), gridspec_kw=dict(height_ratios=[1, 1, 1, 1]))
    vmax = max(float(f[0].max()) for f in frames["fluid"]) or 1.0
    dmax = max([float(p[4].max()) for p in frames["particles"] if len(p[4])] or [1.0]) or 1.0
    for n, (ax, s, fluid, parts) in enumerate(zip(axes, times, frames["fluid"], frames["particles"]),
                                              start=1):
        image, _ = draw_frame(ax, fluid, parts, vmax, dmax)
        ax.set_title(f"({n}) fluid step {s}: {len(parts[0])} particles")
        fig.colorbar(image, ax=ax, label="fluid speed [cells / fluid step]", shrink=0.8)
    ax = axes[3]
    t, p = frames["trace"]
    if len(t):
        ax.plot(t, p, "k-")
        for n, s in enumerate(times, start=1):
            ax.axvline(s, color="C3", ls=":")
            ax.text(s, ax.get_ylim()[1], f"({n})", ha="center", va="bottom")
    ax.set_xlabel("fluid step")
    ax.set_ylabel("P / P_out")
    fig.suptitle(f"{frames['name']}: {frames['note']}\n"
                 f"particles: drag per mass 0 (blue) ... {dmax:.3g} (yellow)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print(f"wrote {out}: fluid steps {times}; {frames['note']}")


def render(run_dir, out, keep=False, name=None):
    """The snapshot figure of a run, from its VTK files or, where they are gone, from the
    frames kept in <run>/snapshots.npz; keep=True writes that file, with `name` for the run
    in the title (default: its folder's). Returns the three steps."""
    kept = os.path.join(run_dir, KEPT)
    if not fluid_files(run_dir) and os.path.exists(kept):
        frames = load_frames(kept)
    else:
        frames = collection_frames(run_dir)
        frames["name"] = name or frames["name"]
        if keep:
            save_frames(frames, kept)
            print(f"kept the three frames in {kept} ({os.path.getsize(kept) / 1e3:.0f} kB)")
    draw_collection(frames, out)
    return frames["times"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run_dir")
    parser.add_argument("--out", default=None,
                        help="the picture (default collection.png, with --at peak snapshot_peak.png)")
    parser.add_argument("--at", choices=["collection", "peak"], default="collection",
                        help="collection: before, at the largest burst's peak and after (default); "
                             "peak: one frame, the one nearest the highest P / P_out")
    parser.add_argument("--keep", action="store_true",
                        help=f"collection: also write <run>/{KEPT}, the three frames small enough "
                             "to keep in the repository, from which the figure is redrawn")
    args = parser.parse_args()
    if args.at == "peak":
        render_peak(args.run_dir, args.out or "snapshot_peak.png")
    else:
        render(args.run_dir, args.out or "collection.png", args.keep)


if __name__ == "__main__":
    main()
