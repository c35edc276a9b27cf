#!/usr/bin/python3
"""The paper's snapshot figure (Fig. collection) from a run's own VTK files: the pore (1) before
any deposit, (2) at a pressure peak and (3) after the burst, each a slice of the fluid speed
through the pore's axis with the particles on it coloured by their drag per mass (blue to
yellow, low to high), beside the pressure loss with the three times marked.

Usage: render_snapshot.py <run folder> [--out collection.png]

The run folder is what in.pore writes with vtk_every > 0: fluid_vtk/fluid_<fluid step>.vti
(.pvti on several ranks), particles_vtk/particles_<DEM step>.vtp (id radius mass x v
f_pore[1-3]), log.liggghts and bursts.txt. The three times: (1) the last fluid file before the
first deposit (f_pore[6] still 0), (2) the file nearest the peak of the largest burst, (3) the
first file after that burst's minimum; a run without a burst takes (2) at its largest P / P_out
and (3) at its end, and says so in the title.

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


def pick_times(run_dir, steps):
    """The three fluid steps (before, peak, after) among `steps` and a note on how they were
    chosen."""
    columns = thermo(run_dir)
    rows = list(zip(columns.get("Step", []), columns.get("pore[6]", []),
                    columns.get("pore[16]", [])))
    timing = lattice_timing(run_dir)  # the run's own DEM steps per fluid step and fluid step
    fluid_step = lambda dem_step: dem_step / timing["n_dem"]  # noqa: E731
    nearest = lambda t: min(steps, key=lambda s: abs(s - t))  # noqa: E731
    first_deposit = next((step for step, v_dep, _ in rows if v_dep > 0), None)
    if first_deposit is None:
        before = steps[len(steps) // 2]  # nothing deposits: any time is "before"
    else:
        before = max([s for s in steps if s < fluid_step(first_deposit)] or [steps[0]])
    events = bursts(run_dir)
    if events:
        largest = max(events, key=lambda b: b["delta_P"])
        peak = nearest(fluid_step(largest["step"]))
        # delta_t is a time (the script's unit); dt_f of it make one fluid step
        after_time = fluid_step(largest["step"]) + largest["delta_t"] / timing["dt_f"]
        after = min([s for s in steps if s >= after_time] or [steps[-1]])
        note = f"largest burst: P {largest['P_peak']:.3g} -> {largest['P_after']:.3g} P_out"
    else:
        top = max(rows, key=lambda r: r[2]) if rows else (steps[-1] * timing["n_dem"], 0, 0)
        peak, after = nearest(fluid_step(top[0])), steps[-1]
        note = "no burst in this run: (2) at its largest P / P_out, (3) at its end"
    return (before, peak, after), note


def render(run_dir, out):
    files = fluid_files(run_dir)
    if not files:
        sys.exit(f"{run_dir}: no fluid_vtk/fluid_*.vti (run with vtk_every > 0)")
    steps = sorted(files)
    times, note = pick_times(run_dir, steps)
    n_dem = lattice_timing(run_dir)["n_dem"]
    fig, axes = plt.subplots(4, 1, figsize=(8, 11), gridspec_kw=dict(height_ratios=[1, 1, 1, 1]))
    speeds = [read_fluid_slice(files[s]) for s in times]
    vmax = max(float(s[0].max()) for s in speeds) or 1.0
    drags = []
    for s in times:
        path = os.path.join(run_dir, "particles_vtk", f"particles_{s * n_dem}.vtp")
        drags.append(read_particles(path) if os.path.exists(path) else (np.zeros(0),) * 5)
    dmax = max([float(d[4].max()) for d in drags if len(d[4])] or [1.0]) or 1.0
    for n, (ax, s, (speed, solid, spacing, origin), parts) in enumerate(
            zip(axes, times, speeds, drags), start=1):
        extent = [origin[0] - spacing[0] / 2, origin[0] + (speed.shape[0] - 0.5) * spacing[0],
                  origin[1] - spacing[1] / 2, origin[1] + (speed.shape[1] - 0.5) * spacing[1]]
        shown = np.ma.masked_where(solid, speed)
        ax.set_facecolor("0.55")  # walls and particles (solid nodes) in grey
        image = ax.imshow(shown.T, origin="lower", extent=extent, cmap="rainbow", vmin=0,
                          vmax=vmax, interpolation="nearest")
        x, y, _, r, drag = parts
        if len(x):
            circles = PatchCollection([Circle((a, b), c) for a, b, c in zip(x, y, r)],
                                      cmap="viridis", edgecolor="k", linewidth=0.3)
            circles.set_array(drag)
            circles.set_clim(0, dmax)
            ax.add_collection(circles)
        ax.set_title(f"({n}) fluid step {s}: {len(x)} particles")
        ax.set_aspect("equal")
        fig.colorbar(image, ax=ax, label="fluid speed [cells / fluid step]", shrink=0.8)
    ax = axes[3]
    columns = thermo(run_dir)
    if "pore[16]" in columns:
        t = np.asarray(columns["Step"]) / n_dem
        ax.plot(t, columns["pore[16]"], "k-")
        for n, s in enumerate(times, start=1):
            ax.axvline(s, color="C3", ls=":")
            ax.text(s, ax.get_ylim()[1], f"({n})", ha="center", va="bottom")
    ax.set_xlabel("fluid step")
    ax.set_ylabel("P / P_out")
    fig.suptitle(f"{os.path.basename(os.path.abspath(run_dir))}: {note}\n"
                 f"particles: drag per mass 0 (blue) ... {dmax:.3g} (yellow)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print(f"wrote {out}: fluid steps {times}; {note}")
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run_dir")
    parser.add_argument("--out", default="collection.png")
    args = parser.parse_args()
    render(args.run_dir, args.out)


if __name__ == "__main__":
    main()
