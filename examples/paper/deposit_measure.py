#!/usr/bin/env python3
"""The deposit measure of the paper's figures, read off one run that recorded it.

The paper counts as deposited the particles "in a cohesive or adhesive bond" with "zero or
very low velocity", "located inside the pore radius", and gives no speed bound. A run of
in.pore with `-var deposit_speeds_every N` writes the speeds of the particles in the deposit
region (fix lbm/pore's deposit_speeds file) and thermo columns f_pore[28-33], the deposited
count under the run's bound times 1/4, 1/2, 2, 4, 8 and 16. From them this script shows:

  - the speed distribution of the bonded particles (touching the wall, bonded to other
    particles only) and of the unbonded ones in the region, and where the wall-bonded ones
    separate into resting deposits and moving particles (the valley between the two modes);
  - per bound: the count at each burst's peak against the count a tenth of the burst
    window before it (a bound that drops a moving deposit makes them disagree), the median
    count at several times before the peak, how far the window's largest count lies above
    its median over the window's first 60 % (before any release: the count's fluctuation),
    and the paper's law P - P_0 = K L_dep / D fitted to the largest count in the window
    (the figures' measure) and, beside it, to the count at the peak: K and Pearson;
  - the pressure loss at the peaks between the box's open faces (f_pore[16]) and across the
    pore (f_pore[27], "on both sides of the pore", as the paper measures it).

  python3 examples/paper/deposit_measure.py RUN_DIR [--out DIR]

writes DIR/deposit_measure.json and DIR/deposit_speeds.png (DIR defaults to RUN_DIR).
Intervals: 95 % bootstrap over the run's bursts (one run: they share its history).
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fit_stats import bootstrap, fmt, pearson, slope_through_origin  # noqa: E402
from study_io import burst_window_dem_steps, bursts, read_knobs, thermo  # noqa: E402

# f_pore[28 + i]: the deposited count with the bound times LADDER[i] (fix lbm/pore's doc).
LADDER = (0.25, 0.5, 2.0, 4.0, 8.0, 16.0)
# Times before a peak, in burst windows, at which the count is read (how it changes up to it).
LEADS = (0.0, 0.02, 0.05, 0.1, 0.2, 0.4)
KINDS = ("bonded, touching the wall", "bonded to other particles only", "not bonded")


def read_speeds(path):
    """(lower bin edges, counts[kind][bin] summed over the file's intervals, cells per length
    unit, time units per fluid step) of a deposit_speeds file; bin 0 is 'slower than the first
    edge'. Files written before the header gave the fluid step: nan for it."""
    cells_per_unit, time_per_step, rows = np.nan, np.nan, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if "cells per length unit" in line:
                    words = line.split(";")[1].split()
                    cells_per_unit = float(words[0])
                    if "time units per" in line:
                        time_per_step = float(words[words.index("and") + 1])
                continue
            if line.strip():
                rows.append([float(w) for w in line.split()])
    rows = np.asarray(rows, float)
    bins = rows.shape[1] - 3
    counts = np.array([rows[rows[:, 2] == k, 3:].sum(axis=0) for k in range(len(KINDS))])
    low, per_decade = -8, 10
    edges = np.array([0.0] + [10.0 ** (low + (b - 1) / per_decade) for b in range(1, bins)])
    return edges, counts, cells_per_unit, time_per_step


def valley(edges, counts, lo=1e-6, hi=1e-1):
    """The speed (geometric centre of a bin) where the wall-bonded particles' distribution,
    smoothed over three bins, is lowest between its slow mode (resting deposits) and a faster
    bin that holds more (moving particles): the bound between the two. None without such a
    second rise."""
    n = np.convolve(counts, np.ones(3) / 3, mode="same")
    inside = np.flatnonzero((edges >= lo) & (edges < hi))
    if len(inside) < 5:
        return None
    slow = inside[int(np.argmax(n[inside]))]
    candidates = [b for b in inside if b > slow and n[b] < 0.8 * n[b + 1:inside[-1] + 1].max(initial=0.0)]
    if not candidates:
        return None
    b = min(candidates, key=lambda c: n[c])
    return float(np.sqrt(edges[b] * edges[b + 1]))


def row_at_or_before(steps, step):
    k = int(np.searchsorted(steps, step, side="right")) - 1
    return max(k, 0)


def count_columns(columns):
    """{factor: column name} of the deposited counts the run's thermo rows carry."""
    out = {1.0: "pore[7]"}
    for i, f in enumerate(LADDER):
        name = f"pore[{28 + i}]"
        if name in columns:
            out[f] = name
    return out


def clean_pressure(columns, warmup, column="pore[16]", share=0.25):
    steps = np.asarray(columns["Step"], float)
    p = np.asarray(columns[column], float)
    keep = (steps > (1 - share) * warmup) & (steps <= warmup)
    return float(np.mean(p[keep])) if keep.any() else np.nan


def analyse(run_dir):
    knobs = read_knobs(run_dir)
    columns = thermo(run_dir)
    steps = np.asarray(columns["Step"], float)
    rows = bursts(run_dir)
    warmup = float(knobs.get("warmup", 0))
    D = float(knobs.get("D", 3.52))
    window = burst_window_dem_steps(run_dir, knobs)
    lead = window / 10.0
    p0 = clean_pressure(columns, warmup)
    # The mean volume of a deposited particle (V_dep / count over the rows with a deposit):
    # the ladder's counts come without volumes.
    count = np.asarray(columns["pore[7]"], float)
    volume = np.asarray(columns["pore[6]"], float)
    mean_volume = float(volume[count > 0].sum() / count[count > 0].sum()) if (count > 0).any() else np.nan
    area = np.pi * D * D / 4.0
    result = dict(run=os.path.basename(os.path.normpath(run_dir)), bursts=len(rows), P_0=p0,
                  mean_deposited_volume=mean_volume, lead_dem_steps=lead, bounds={})
    peaks = [row_at_or_before(steps, b["step"]) for b in rows]
    befores = [row_at_or_before(steps, b["step"] - lead) for b in rows]
    windows = [(steps >= b["step"] - window) & (steps <= b["step"]) for b in rows]
    early = [(steps >= b["step"] - window) & (steps <= b["step"] - 0.4 * window) for b in rows]
    P = np.array([b["P_peak"] for b in rows])
    for factor, name in sorted(count_columns(columns).items()):
        c = np.asarray(columns[name], float)
        at_peak = c[peaks] if rows else np.array([])
        before = c[befores] if rows else np.array([])
        largest = np.array([c[w].max() if w.any() else np.nan for w in windows])
        excess = np.array([c[w].max() - np.median(c[w]) for w in early if w.any()])

        def law(counts):
            """K on P - P_0 through 0 and Pearson on P, against L_dep / D of `counts`."""
            x = counts * mean_volume / area / D
            return (bootstrap([([xi], [yi]) for xi, yi in zip(x, P - p0)], slope_through_origin),
                    bootstrap([([xi], [yi]) for xi, yi in zip(x, P)], pearson))
        # the median count over the bursts at leads of 0 ... 0.4 burst windows before the peak
        by_lead = {f"{q:g}": float(np.median(c[[row_at_or_before(steps, b["step"] - q * window) for b in rows]]))
                   for q in LEADS} if rows else {}
        K, r = law(largest)
        K_peak, r_peak = law(at_peak)
        result["bounds"][str(factor)] = dict(
            factor=factor,
            count_at_peak_median=float(np.median(at_peak)) if len(at_peak) else np.nan,
            count_before_median=float(np.median(before)) if len(before) else np.nan,
            # bursts whose count at the peak is under half the count just before it: the
            # deposit slid out of the count before the peak
            collapsed=int(np.sum(at_peak < 0.5 * before)),
            median_count_by_lead=by_lead,
            largest_in_window_median=float(np.median(largest)) if len(largest) else np.nan,
            # before any release: the largest count above the median, over the bursts
            early_excess_median=float(np.median(excess)) if len(excess) else np.nan,
            early_excess_max=float(np.max(excess)) if len(excess) else np.nan,
            K=K, pearson=r, K_at_peak=K_peak, pearson_at_peak=r_peak)
    if "pore[27]" in columns and rows:
        faces = np.asarray(columns["pore[16]"], float)[peaks]
        across = np.asarray(columns["pore[27]"], float)[peaks]
        result["pressure_at_peaks"] = dict(
            faces_median=float(np.median(faces)), across_pore_median=float(np.median(across)),
            across_over_faces_median=float(np.median(across / faces)),
            across_over_faces_range=[float(np.min(across / faces)), float(np.max(across / faces))],
            clean_faces=p0, clean_across_pore=clean_pressure(columns, warmup, "pore[27]"))
    speeds = os.path.join(run_dir, "deposit_speeds.txt")
    if os.path.exists(speeds):
        edges, counts, cells, time_per_step = read_speeds(speeds)
        if not np.isfinite(time_per_step):  # in.pore's acoustic scaling: dt_f = 7.1 / cells_per_d
            time_per_step = 7.1 / float(knobs.get("cells_per_d", 7.1))
        bound = float(knobs["deposit_speed"]) * cells * time_per_step if "deposit_speed" in knobs else None
        result["speeds"] = dict(cells_per_length_unit=cells, time_per_fluid_step=time_per_step,
                                bound_cells_per_fluid_step=bound, lower_edges=edges.tolist(),
                                counts={KINDS[k]: counts[k].tolist() for k in range(len(KINDS))},
                                valley_cells_per_fluid_step=valley(edges, counts[0]))
    return result


def plot(result, run_dir, out_png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    s = result["speeds"]
    edges = np.asarray(s["lower_edges"])
    fig, ax = plt.subplots(figsize=(7, 4))
    centres = np.sqrt(edges[1:-1] * edges[2:])
    for k, kind in enumerate(KINDS):
        n = np.asarray(s["counts"][kind])[1:-1]
        total = np.asarray(s["counts"][kind]).sum()
        if total:
            ax.step(centres, n / total, where="mid", label=f"{kind} ({total:.3g} samples)")
    knobs = read_knobs(run_dir)
    valley_speed = s["valley_cells_per_fluid_step"]
    if valley_speed:
        ax.axvline(valley_speed, color="k", ls=":", label=f"valley of the wall-bonded: {valley_speed:.2g}")
    if s.get("bound_cells_per_fluid_step"):
        ax.axvline(s["bound_cells_per_fluid_step"], color="0.5", ls="--",
                   label=f"the run's deposit_speed: {s['bound_cells_per_fluid_step']:.2g}")
    ax.set_xscale("log")
    ax.set_xlabel("speed [lattice cells per fluid step]")
    ax.set_ylabel("share of the kind's samples per 0.1 decade")
    ax.set_title(f"particles in the deposit region, {result['run']}", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out_png, dpi=120)
    plt.close(fig)


def table(result, base=1.0):
    """The bounds as multiples of `base` (a factor of the run's own deposit_speed)."""
    lines = ["| bound | count at the peak | a tenth of a window before | collapsed | largest in the window | "
             "its excess before release (median, max) | K on P - P_0 (largest) | Pearson (largest) | "
             "K at the peak | Pearson at the peak |", "|---" * 10 + "|"]
    for b in result["bounds"].values():
        lines.append(f"| x {b['factor'] / base:g} | {b['count_at_peak_median']:.0f} | {b['count_before_median']:.0f} | "
                     f"{b['collapsed']} of {result['bursts']} | {b['largest_in_window_median']:.0f} | "
                     f"{b['early_excess_median']:.0f}, {b['early_excess_max']:.0f} | "
                     f"{fmt(*b['K'])} | {fmt(*b['pearson'])} | {fmt(*b['K_at_peak'])} | {fmt(*b['pearson_at_peak'])} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir")
    parser.add_argument("--out", help="folder for the results (default: the run's)")
    parser.add_argument("--relative-to", type=float, default=1.0,
                        help="give the bounds as multiples of this factor of the run's deposit_speed "
                             "(4 for a run made at a quarter of in.pore's bound)")
    args = parser.parse_args()
    out = args.out or args.run_dir
    os.makedirs(out, exist_ok=True)
    result = analyse(args.run_dir)
    with open(os.path.join(out, "deposit_measure.json"), "w") as f:
        json.dump(result, f, indent=1, default=float)
    if "speeds" in result:
        plot(result, args.run_dir, os.path.join(out, "deposit_speeds.png"))
        print(f"valley of the wall-bonded speeds: {result['speeds']['valley_cells_per_fluid_step']} "
              f"lattice cells per fluid step")
    print(table(result, args.relative_to))
    print("median count at leads before the peak (burst windows): " + ", ".join(f"{q:g}" for q in LEADS))
    for b in result["bounds"].values():
        print(f"  bound x {b['factor'] / args.relative_to:g}: " + " ".join(f"{v:.0f}" for v in b["median_count_by_lead"].values()))
    if "pressure_at_peaks" in result:
        p = result["pressure_at_peaks"]
        print(f"pressure loss at the peaks: across the pore / between the faces, median "
              f"{p['across_over_faces_median']:.3f} (range {p['across_over_faces_range'][0]:.3f}-"
              f"{p['across_over_faces_range'][1]:.3f}); clean: {p['clean_across_pore']:.4f} / {p['clean_faces']:.4f}")


if __name__ == "__main__":
    main()
