#!/usr/bin/env python3
"""Plot and tabulate the accuracy study written by accuracy_cases.

    plot_accuracy.py accuracy.csv [--png accuracy_error_vs_time.png] [--markdown accuracy_table.md]

The PNG shows the error against wall-clock time, one panel per case and one curve per option
(points labelled by resolution or DEM steps per contact). The Markdown file has, per case, a
table of error and wall time for every option and resolution, and the full CSV as a table.
Needs matplotlib only for the PNG (Debian: python3-matplotlib); the table needs nothing.
"""
import argparse
import csv
import sys
from collections import OrderedDict

CASE_TITLES = OrderedDict([
    ("pipe", "1. Pipe Poiseuille: mean relative L2 error (resolution = radius R, cells)"),
    ("drag", "2. Fixed sphere in a simple-cubic array, chi = 0.5: |K/K_SA - 1| (resolution = d, cells)"),
    ("lubrication", "3. Sphere approaching a wall: rms of lambda/lambda_Brenner - 1 over delta/a = 1 ... 0.01 (d, cells)"),
    ("dashdot", "4. Dash-dot collision: mean |e/e_analytic - 1| (N = DEM steps per contact, dt = t_c/N)"),
    ("moving", "5. Sphere translating through a periodic array, chi = 0.5: |K/K_SA - 1| (d, cells)"),
])
SHORT_TITLES = {
    "pipe": "1. pipe Poiseuille (R)",
    "drag": "2. SC-array drag (d)",
    "lubrication": "3. sphere-wall lubrication (d)",
    "dashdot": "4. dash-dot restitution (N)",
    "moving": "5. moving sphere, long run (d)",
}


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in ("resolution", "error", "wall_seconds", "value", "reference_value"):
            r[key] = float(r[key])
        r["n_dem"] = int(r["n_dem"])
        r["steps"] = int(r["steps"])
        r["notes"] = dict(part.split("=", 1) for part in r["note"].split(";") if "=" in part)
    return rows


def axis_value(r):
    """The refinement parameter of a row: n_dem for the DEM case, else the resolution."""
    return r["n_dem"] if r["case"] == "dashdot" else r["resolution"]


def axis_label(r):
    v = axis_value(r)
    prefix = {"pipe": "R=", "dashdot": "N="}.get(r["case"], "d=")
    return f"{prefix}{v:g}"


def series(rows):
    """OrderedDict case -> OrderedDict option -> rows sorted by refinement."""
    out = OrderedDict()
    for r in rows:
        out.setdefault(r["case"], OrderedDict()).setdefault(r["option"], []).append(r)
    for options in out.values():
        for opt in options:
            options[opt].sort(key=axis_value)
    return out


def fmt_error(e):
    return f"{100 * e:.2f} %" if e >= 1e-4 else f"{100 * e:.1e} %"


def fmt_seconds(s):
    return f"{s:.2f} s" if s >= 0.01 else f"{s * 1e6:.0f} us"


def markdown(rows):
    lines = []
    # Rows marked shared_run reuse another row's lattice run (lubrication without the
    # correction): their time is not counted twice.
    total = sum(r["wall_seconds"] for r in rows if r["notes"].get("shared_run") != "1")
    lines.append(f"{len(rows)} rows, {total:.0f} s of wall-clock time in the cases (one core). "
                 "Each cell: error (wall-clock time of that run); signed errors where the sign "
                 "changes the reading (+ = too much drag).")
    lines.append("")
    grouped = series(rows)
    for case, options in grouped.items():
        lines.append(f"**{CASE_TITLES.get(case, case)}**")
        lines.append("")
        keys = sorted({axis_value(r) for opt in options.values() for r in opt})
        label = {"pipe": "R = ", "dashdot": "N = "}.get(case, "d = ")
        lines.append("| option | " + " | ".join(f"{label}{k:g}" for k in keys) + " |")
        lines.append("|---" * (len(keys) + 1) + "|")
        for opt, list_ in options.items():
            by_key = {axis_value(r): r for r in list_}
            cells = []
            for k in keys:
                r = by_key.get(k)
                if r is None:
                    cells.append("")
                    continue
                signed = r["notes"].get("signed_error")
                text = f"{100 * float(signed):+.2f} %" if signed is not None else fmt_error(r["error"])
                cells.append(f"{text} ({fmt_seconds(r['wall_seconds'])})")
            lines.append(f"| {opt} | " + " | ".join(cells) + " |")
        lines.append("")
        if case == "moving":
            lines.append("Mass drift over the run (relative) and rms fluctuation of the force:")
            lines.append("")
            lines.append("| option | d | steps | K (ref 2.842) | mass drift | per step | force rms / mean |")
            lines.append("|---|---|---|---|---|---|---|")
            for opt, list_ in options.items():
                for r in list_:
                    n = r["notes"]
                    lines.append(f"| {opt} | {r['resolution']:g} | {r['steps']} | {r['value']:.4f} | "
                                 f"{float(n.get('mass_drift', 'nan')):+.2e} | "
                                 f"{float(n.get('mass_drift_per_step', 'nan')):+.1e} | "
                                 f"{100 * float(n.get('force_rms/mean', 'nan')):.2f} % |")
            lines.append("")
    lines.append("<details><summary>All runs (the CSV)</summary>")
    lines.append("")
    lines.append("| case | option | resolution | n_dem | error | value | reference value | reference | wall s | steps |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        lines.append(f"| {r['case']} | {r['option']} | {r['resolution']:g} | {r['n_dem'] or ''} | "
                     f"{r['error']:.3e} | {r['value']:.5g} | {r['reference_value']:.5g} | "
                     f"{r['reference']} | {r['wall_seconds']:.3g} | {r['steps']} |")
    lines.append("")
    lines.append("</details>")
    return "\n".join(lines) + "\n"


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from matplotlib.ticker import NullFormatter

    grouped = series(rows)
    cases = list(grouped)
    ncols = 3
    panels = len(cases) + 1  # the last panel: every curve together
    nrows = (panels + ncols - 1) // ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(13, 4.2 * nrows), squeeze=False)
    for ax in axes.flat[panels:]:
        ax.axis("off")
    markers = "osD^v<>"
    combined = axes.flat[len(cases)]
    for ax, case in zip(axes.flat, cases):
        for i, (opt, list_) in enumerate(grouped[case].items()):
            x = [r["wall_seconds"] for r in list_]
            y = [max(r["error"], 1e-12) for r in list_]
            ax.loglog(x, y, marker=markers[i % len(markers)], label=opt)
            combined.loglog(x, y, marker=markers[i % len(markers)], markersize=4, linewidth=1,
                            label=f"{case}: {opt}")
            for r, xi, yi in zip(list_, x, y):
                ax.annotate(axis_label(r), (xi, yi), textcoords="offset points", xytext=(3, 3),
                            fontsize=7)
        ax.set_title(SHORT_TITLES.get(case, case), fontsize=10)
        ax.legend(fontsize=8)
    combined.set_title("all cases", fontsize=10)
    combined.legend(fontsize=6, ncol=2)
    for ax in list(axes.flat)[:panels]:
        ax.set_xlabel("wall-clock time of the run [s]")
        ax.set_ylabel("relative error")
        ax.grid(True, which="both", alpha=0.3)
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.yaxis.set_minor_formatter(NullFormatter())
    fig.suptitle("lbm-pore accuracy study: error against wall-clock time (1 core)", fontsize=12)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("--png", help="write the error-vs-time plot here")
    ap.add_argument("--markdown", help="write the Markdown tables here ('-' for stdout)")
    args = ap.parse_args()
    rows = read_rows(args.csv)
    if not rows:
        sys.exit(f"{args.csv}: no rows")
    if args.markdown:
        text = markdown(rows)
        if args.markdown == "-":
            sys.stdout.write(text)
        else:
            with open(args.markdown, "w") as f:
                f.write(text)
    if args.png:
        plot(rows, args.png)


if __name__ == "__main__":
    main()
