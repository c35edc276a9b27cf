"""Figs. phaseac and phasead: the largest pressure loss P_max [P_out] of each run (f_pore[17]
at its end) over a plane of two knobs, interpolated between the runs, with the paper's 0.3
(slight clogging) and 0.6 (severe clogging) contours."""
import numpy as np

from figures.common import finished_runs, plt, result, save

CONTOURS = (0.3, 0.6)


def analyze_plane(summary, out_dir, figure, x_name, x_of, y_name, y_of, log_y, paper):
    runs = [r for r in finished_runs(summary) if r.get("max_P") is not None]
    x = np.array([x_of(r) for r in runs], float)
    y = np.array([y_of(r) for r in runs], float)
    p = np.array([r["max_P"] for r in runs], float)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    yy = np.log10(y) if log_y else y
    drawn = len(runs) >= 3 and np.ptp(x) > 0 and np.ptp(yy) > 0
    if drawn:
        levels = np.linspace(0, max(p.max(), 0.7), 15)
        filled = ax.tricontourf(x, yy, p, levels=levels, cmap="viridis")
        fig.colorbar(filled, ax=ax, label="P_max [P_out]")
        if p.max() >= min(CONTOURS):
            ax.tricontour(x, yy, p, levels=[c for c in CONTOURS if c <= p.max()],
                          colors="w", linestyles="--")
    points = ax.scatter(x, yy, c=p, edgecolor="k", cmap="viridis", zorder=3)
    if not drawn:
        fig.colorbar(points, ax=ax, label="P_max [P_out]")
    ax.set_xlabel(x_name)
    ax.set_ylabel(f"log10 {y_name}" if log_y else y_name)
    ax.set_title(f"dashed: P_max = 0.3 and 0.6 P_out (paper's contours)\npaper: {paper}",
                 fontsize=8)
    above = {c: int((p > c).sum()) for c in CONTOURS}
    ours = (f"P_max {p.min():.3g} ... {p.max():.3g} P_out over {len(p)} runs; "
            f"{above[0.3]} above 0.3, {above[0.6]} above 0.6") if len(p) else "no finished run"
    return result(summary, figure, f"P_max over ({x_name}, {y_name})", paper, ours,
                  save(fig, out_dir, figure),
                  points=[dict(x=float(a), y=float(b), P_max=float(c)) for a, b, c in zip(x, y, p)])
