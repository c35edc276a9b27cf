"""Fig. porediameter: the pressure peaks P [P_out] against L_dep / D over the eight pore
diameters (inlet area scaled with D^2, L = 4.22, 10 seeds each); K of P_crit = K L_dep / D
(paper: 0.91 +- 0.04; also on P - P_0 and with an intercept, figures.common.pressure_fits),
and the theory P = 4 f_a L_dep / D with f_a measured from the model:
the wall's hold on the particles along the flow (-f_walls[2], the total wall force in x) at
the peak, per area of pore wall the deposit covers (pi D L_dep), in P_out. The wall also holds
particles that are not in the deposit, so this f_a is an upper estimate."""
import numpy as np

from fit_stats import bootstrap, fmt
from figures.common import (beside_fits, beside_results, beside_text, bursts, draw_beside, draw_fits,
                            finished_runs, fits_text, p_out, plt, pressure_fits, resampled, result, save, thermo,
                            with_largest_deposits)

PAPER_K = 0.91


def _points(run):
    """(L_dep / D, P_peak, f_a [P_out]) per burst of the run."""
    D = float(run["knobs"]["D"])
    unit = p_out(run["folder"])  # rho c_s^2 in the script's units
    columns = thermo(run["folder"])
    steps = np.asarray(columns.get("Step", []))
    hold = np.asarray(columns.get("walls[2]", []))
    out = []
    # the deposit every figure counts (figures.common.largest_deposit_before), as K takes it
    for b in with_largest_deposits(run, bursts(run["folder"]), columns):
        f_a = np.nan
        if b["deposit_L"] > 0 and "wall_F" in b:  # the burst record's own hold at the peak
            f_a = -b["wall_F"] / (np.pi * D * b["deposit_L"]) / unit
        elif len(hold) and b["deposit_L"] > 0:  # older records: the nearest thermo row
            k = int(np.argmin(abs(steps - b["step"])))
            f_a = -hold[k] / (np.pi * D * b["deposit_L"]) / unit
        out.append((b["deposit_L"] / D, b["P_peak"], f_a))
    return out


def analyze(summary, out_dir):
    runs = finished_runs(summary)
    points = [_points(run) for run in runs]
    fits = pressure_fits(summary, lambda run, b: b["deposit_L"] / float(run["knobs"]["D"]))
    beside = beside_fits(summary, lambda run, b: b["deposit_L"] / float(run["knobs"]["D"]))
    groups = fits["groups"]
    K = fits["through_origin"]
    f_a_groups = [([p[2] for p in ps if np.isfinite(p[2])],) * 2 for ps in points]
    f_a = bootstrap(resampled(f_a_groups)[0], lambda x, y: float(np.mean(x)) if len(x) else np.nan)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for D in sorted({float(run["knobs"]["D"]) for run in runs}):
        x = [p[0] for run, ps in zip(runs, points) if float(run["knobs"]["D"]) == D for p in ps]
        y = [p[1] for run, ps in zip(runs, points) if float(run["knobs"]["D"]) == D for p in ps]
        ax.plot(x, y, "o", ms=4, label=f"D = {D:.2f}")
    top = max([max(g[0]) for g in groups if len(g[0])] or [1.0])
    xs = np.linspace(0, top, 2)
    draw_beside(ax, beside)
    draw_fits(ax, fits, top, PAPER_K, "paper K")
    if np.isfinite(f_a[0]):
        ax.plot(xs, 4 * f_a[0] * xs, "C4:", label=f"theory 4 f_a, f_a = {fmt(*f_a)} P_out")
    ax.set_xlabel("L_dep / D")
    ax.set_ylabel("P_peak [P_out]")
    ax.legend(fontsize=7, ncol=2)
    return result(summary, "porediameter", "K in P = K L_dep / D; theory 4 f_a",
                  f"{PAPER_K} +- 0.04; f_a = K/4 = {PAPER_K / 4:.3g}",
                  f"K {fits_text(fits)}; f_a = {fmt(*f_a)}; K {beside_text(beside)}",
                  save(fig, out_dir, "porediameter"),
                  K=K, K_excess=fits["excess_through_origin"], slope=fits["slope"],
                  intercept=fits["intercept"], f_a=f_a,
                  **beside_results(beside))
