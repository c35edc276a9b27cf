"""Fig. porelength: the pressure peaks P [P_out] against the deposited length L_dep [d] over
the twelve pore lengths of the appendix; the coefficient of P = c L_dep (a line through 0,
the paper's P_crit = sigma_c L_dep) and the Pearson coefficient (paper: 0.27(1), 0.91(1))."""
import numpy as np

from fit_stats import fmt, slope_through_origin
from figures.common import burst_fit, plt, result, save

PAPER_COEFFICIENT, PAPER_PEARSON = 0.27, 0.91


def analyze(summary, out_dir):
    groups, c, r = burst_fit(summary, "L_dep", slope_through_origin)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    runs = [run for run in summary["runs"] if run["state"] == "done"]
    for run, (x, y) in zip(runs, groups):
        ax.plot(x, y, "o", ms=4, label=f"L = {float(run['knobs']['Lp']):.2f}")
    top = max([max(x) for x, _ in groups if len(x)] or [1.0])
    xs = np.linspace(0, top, 2)
    if np.isfinite(c[0]):
        ax.plot(xs, c[0] * xs, "C3--", label=f"ours: {fmt(*c)}")
    ax.plot(xs, PAPER_COEFFICIENT * xs, "k:", label=f"paper: {PAPER_COEFFICIENT}")
    ax.set_xlabel("L_dep at the peak [d]")
    ax.set_ylabel("P_peak [P_out]")
    ax.set_title(f"Pearson {fmt(*r)} (paper {PAPER_PEARSON})", fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    return result(summary, "porelength", "c in P = c L_dep; Pearson",
                  f"{PAPER_COEFFICIENT}(1); {PAPER_PEARSON}(1)", f"{fmt(*c)}; {fmt(*r)}",
                  save(fig, out_dir, "porelength"), coefficient=c, pearson=r)
