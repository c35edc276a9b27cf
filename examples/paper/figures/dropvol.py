"""Fig. dropvol: the pressure peak P [P_out] of every erosive burst against the deposited
volume V_dep [d^3] at that peak, over the seeds; a linear fit's slope and the Pearson
coefficient (paper: 1.15(1) and 0.71(1), 100 seeds)."""
import numpy as np

from fit_stats import fmt, slope
from figures.common import burst_fit, plt, result, save

PAPER_SLOPE, PAPER_PEARSON = 1.15, 0.71


def analyze(summary, out_dir):
    groups, fit, r = burst_fit(summary, "V_dep", slope)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for x, y in groups:
        ax.plot(x, y, "o", ms=4, alpha=0.7)
    x = np.concatenate([g[0] for g in groups if len(g[0])] or [np.zeros(0)])
    y = np.concatenate([g[1] for g in groups if len(g[1])] or [np.zeros(0)])
    if len(x) > 1 and np.isfinite(fit[0]):
        xs = np.linspace(0, x.max(), 2)
        b = np.polyfit(x, y, 1)
        ax.plot(xs, np.polyval(b, xs), "C3--", label=f"ours: slope {fmt(*fit)}")
        # the paper gives the slope, not the intercept: drawn through our points' centroid
        ax.plot(xs, y.mean() + PAPER_SLOPE * (xs - x.mean()), "k:",
                label=f"paper: slope {PAPER_SLOPE} (through our centroid)")
    ax.set_xlabel("V_dep at the peak [d^3]")
    ax.set_ylabel("P_peak [P_out]")
    ax.set_title(f"{len(x)} bursts from {sum(1 for g in groups if len(g[0]))} runs; "
                 f"Pearson {fmt(*r)} (paper {PAPER_PEARSON})", fontsize=9)
    ax.legend(fontsize=8)
    return result(summary, "dropvol", "slope of P against V_dep; Pearson",
                  f"{PAPER_SLOPE}(1); {PAPER_PEARSON}(1)", f"{fmt(*fit)}; {fmt(*r)}",
                  save(fig, out_dir, "dropvol"), slope=fit, pearson=r, bursts=int(len(x)))
