"""Fig. dropvol: the pressure peak P [P_out] of every erosive burst against the deposited
volume V_dep at that peak, over the seeds; the fitted slope and the Pearson coefficient
(paper: 1.15(1) and 0.71(1), 100 seeds).

The paper's V_dep axis is normalised: from its own K = 0.91 (Fig. porediameter, the theory's
P = 16 f_a V_dep / (pi D^3)) the slope is 4 K / pi = 1.16 for V_dep in D^3 and K L / D = 1.09
for V_dep in pore volumes (pi D^2 L / 4), but 0.027 for V_dep in d^3 (doc/references.md).
So V_dep is plotted per D^3, the unit whose slope the paper's 1.15 matches, and the slope per
pore volume is given beside it; each with the three fits of figures.common.pressure_fits, on the
deposit every figure counts (figures.common.largest_deposit_before; doc/paper.md, "The
deposit"), and beside it (hollow markers) the median over the burst window and the count at the
peak, and P read across the pore (figures.common.across_pore_fits)."""
import numpy as np

from fit_stats import fmt
from figures.common import (across_pore_fits, across_pore_results, across_pore_text, beside_fits, beside_results,
                            beside_text, draw_across_pore, draw_beside, draw_fits, fits_text, plt, pressure_fits,
                            result, save)

PAPER_SLOPE, PAPER_PEARSON, PAPER_K = 1.15, 0.71, 0.91


def per_cube_of_diameter(run, burst):
    return burst["deposit_V"] / float(run["knobs"]["D"]) ** 3


def per_pore_volume(run, burst):
    D, L = float(run["knobs"]["D"]), float(run["knobs"]["Lp"])
    return burst["deposit_V"] / (np.pi * D * D * L / 4.0)


def analyze(summary, out_dir):
    fits = pressure_fits(summary, per_cube_of_diameter)
    pore = pressure_fits(summary, per_pore_volume)
    beside = beside_fits(summary, per_cube_of_diameter)
    across = across_pore_fits(summary, per_cube_of_diameter)
    groups = fits["groups"]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for x, y in groups:
        ax.plot(x, y, "o", ms=4, alpha=0.7)
    x = np.concatenate([g[0] for g in groups if len(g[0])] or [np.zeros(0)])
    draw_beside(ax, beside)
    draw_across_pore(ax, across)
    draw_fits(ax, fits, x.max() if len(x) else 1.0, PAPER_SLOPE)
    ax.set_xlabel("V_dep of the deposit the burst tore off [D^3]")
    ax.set_ylabel("P_peak [P_out]")
    ax.set_title(f"{len(x)} bursts from {sum(1 for g in groups if len(g[0]))} runs; "
                 f"Pearson {fmt(*fits['pearson'])} (paper {PAPER_PEARSON}); "
                 f"intervals over {fits['unit']}", fontsize=9)
    ax.legend(fontsize=7)
    return result(summary, "dropvol", "slope of P against V_dep [D^3] (per pore volume beside); Pearson",
                  f"{PAPER_SLOPE}(1) (4 K / pi = {4 * PAPER_K / np.pi:.3g} per D^3, K L / D = "
                  f"{PAPER_K * 4.23 / 3.52:.3g} per pore volume); {PAPER_PEARSON}(1)",
                  f"per D^3: {fits_text(fits)}; per pore volume: {fits_text(pore)}; "
                  f"Pearson {fmt(*fits['pearson'])}; {beside_text(beside)}; {across_pore_text(across)}",
                  save(fig, out_dir, "dropvol"), slope=fits["slope"],
                  through_origin=fits["through_origin"],
                  excess_through_origin=fits["excess_through_origin"], intercept=fits["intercept"],
                  per_pore_volume={k: pore[k] for k in ("through_origin", "excess_through_origin",
                                                        "slope", "intercept")},
                  pearson=fits["pearson"], bursts=int(len(x)), intervals_over=fits["unit"],
                  **beside_results(beside), **across_pore_results(across))
