"""Fig. porelength: the pressure peaks P [P_out] against the deposited length L_dep [d] over
the twelve pore lengths of the appendix; the coefficient of P = c L_dep (a line through 0,
the paper's P_crit = sigma_c L_dep) and the Pearson coefficient (paper: 0.27(1), 0.91(1)).

A line through 0 on the total P is dominated by the clean pore's own loss P_0 when the
deposits are small (P_0 / L_dep whatever the physics), so the coefficient is also fitted on
P - P_0 and with an intercept (figures.common.pressure_fits), on the deposit every figure
counts (figures.common.largest_deposit_before), and beside it the median over the burst
window and the count at the peak, and P read across the pore (figures.common.across_pore_fits)."""
from fit_stats import fmt
from figures.common import (across_pore_fits, across_pore_results, across_pore_text, beside_fits, beside_results,
                            beside_text, draw_across_pore, draw_beside, draw_fits, fits_text, plt, pressure_fits,
                            result, save)

PAPER_COEFFICIENT, PAPER_PEARSON = 0.27, 0.91


def analyze(summary, out_dir):
    fits = pressure_fits(summary, lambda run, b: b["deposit_L"])
    beside = beside_fits(summary, lambda run, b: b["deposit_L"])
    across = across_pore_fits(summary, lambda run, b: b["deposit_L"])
    groups = fits["groups"]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    runs = [run for run in summary["runs"] if run["state"] == "done"]
    for run, (x, y) in zip(runs, groups):
        ax.plot(x, y, "o", ms=4, label=f"L = {float(run['knobs']['Lp']):.2f}")
    top = max([max(x) for x, _ in groups if len(x)] or [1.0])
    draw_beside(ax, beside)
    draw_across_pore(ax, across)
    draw_fits(ax, fits, top, PAPER_COEFFICIENT)
    ax.set_xlabel("L_dep of the deposit the burst tore off [d]")
    ax.set_ylabel("P_peak [P_out]")
    ax.set_title(f"Pearson {fmt(*fits['pearson'])} (paper {PAPER_PEARSON}); "
                 f"intervals over {fits['unit']}", fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    return result(summary, "porelength", "c in P = c L_dep; Pearson",
                  f"{PAPER_COEFFICIENT}(1); {PAPER_PEARSON}(1)",
                  f"{fits_text(fits)}; Pearson {fmt(*fits['pearson'])}; {beside_text(beside)}; "
                  f"{across_pore_text(across)}",
                  save(fig, out_dir, "porelength"), coefficient=fits["through_origin"],
                  excess_coefficient=fits["excess_through_origin"], slope=fits["slope"],
                  intercept=fits["intercept"], pearson=fits["pearson"], intervals_over=fits["unit"],
                  **beside_results(beside), **across_pore_results(across))
