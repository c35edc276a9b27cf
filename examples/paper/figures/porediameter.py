"""Fig. porediameter: the pressure peaks P [P_out] against L_dep / D over the eight pore
diameters (inlet area scaled with D^2, L = 4.22, 10 seeds each); K of P_crit = K L_dep / D
(paper: 0.91 +- 0.04; also on P - P_0 and with an intercept, figures.common.pressure_fits),
and the theory P = 4 f_a L_dep / D with f_a measured from the model: the wall's hold on the
deposit along the flow per area of pore wall it covers (pi D L_dep), in P_out. Where the rows
carry it, the hold is the wall's force on the deposited particles alone (-f_pore[35]) at the
row of the deposit the burst tears off (the figures' measure); older runs have only the
wall's force on every particle at the peak (the burst record's wall_F, or -f_walls[2]), which
also holds particles outside the deposit: results.json's f_a_from says which per burst.
Beside the law (never instead of it), the same procedure with P read across the pore
(f_pore[27]) rather than between the box's faces: the queue in the outlet region and a plug
on the pore's entrance face add to the second only."""
import numpy as np

from fit_stats import bootstrap, fmt, slope_through_origin, stratified_bootstrap
from figures.common import (beside_fits, beside_results, beside_text, burst_window_dem_steps, bursts,
                            draw_beside, draw_fits, finished_runs, fits_text, largest_deposit_row, p_out,
                            plt, pressure_fits, resampled, result, run_points, save, thermo,
                            with_largest_deposits)

PAPER_K = 0.91


def _points(run):
    """(L_dep / D, P_peak, f_a [P_out], where f_a comes from) per burst of the run."""
    D = float(run["knobs"]["D"])
    unit = p_out(run["folder"])  # rho c_s^2 in the script's units
    columns = thermo(run["folder"])
    steps = np.asarray(columns.get("Step", []))
    hold = np.asarray(columns.get("walls[2]", []))
    own = np.asarray(columns.get("pore[35]", []), float)
    window = burst_window_dem_steps(run["folder"], run["knobs"])
    out = []
    # the deposit every figure counts (figures.common.largest_deposit_before), as K takes it
    for b in with_largest_deposits(run, bursts(run["folder"]), columns):
        f_a, source = np.nan, "none"
        k = largest_deposit_row(columns, b["step"], window) if len(own) else None
        area = np.pi * D * b["deposit_L"]
        if b["deposit_L"] <= 0:
            pass
        elif k is not None and np.isfinite(own[k]):  # the deposit's own hold
            f_a, source = -own[k] / area / unit, "deposit"
        elif "wall_F" in b:  # the burst record's hold on every particle at the peak
            f_a, source = -b["wall_F"] / area / unit, "all particles"
        elif len(hold):  # older records: the nearest thermo row
            k = int(np.argmin(abs(steps - b["step"])))
            f_a, source = -hold[k] / area / unit, "all particles"
        out.append((b["deposit_L"] / D, b["P_peak"], f_a, source))
    return out


def _law(diameters):
    """statistic for fit_stats.stratified_bootstrap: from strata of (L_dep, P - P_0) groups,
    one stratum per diameter, (K, a) of s_D = K D^-a, s_D the slope through the origin of
    each diameter's points, fitted as a line of log s_D on log D (diameters whose slope is
    not positive left out; nan with fewer than two)."""
    def statistic(groups_by_D):
        D, s = [], []
        for d, groups in zip(diameters, groups_by_D):
            x = np.concatenate([g[0] for g in groups]) if groups else np.zeros(0)
            y = np.concatenate([g[1] for g in groups]) if groups else np.zeros(0)
            slope = slope_through_origin(x, y)
            if np.isfinite(slope) and slope > 0:
                D.append(d)
                s.append(slope)
        if len(D) < 2:
            return np.nan, np.nan
        minus_a, log_K = np.polyfit(np.log(D), np.log(s), 1)
        return float(np.exp(log_K)), float(-minus_a)
    return statistic


def diameter_law(summary, deposit="largest", pressure="faces"):
    """The paper's procedure for P = K L_dep / D^a: per pore diameter D the slope s_D of
    P - P_0 against L_dep through the origin over that D's runs, then s_D against D in
    log-log (_law). Intervals over seeds: a bootstrap that resamples each diameter's runs
    within it (fit_stats.stratified_bootstrap), not over bursts. pressure: where P is read
    (figures.common.PRESSURES). Returns the diameters, the slopes with their intervals, K
    and a."""
    by_D = {}
    for run in finished_runs(summary):
        x, _, excess = run_points(run, lambda r, b: b["deposit_L"], deposit, pressure)
        if len(excess):
            by_D.setdefault(float(run["knobs"]["D"]), []).append((x, excess))
    diameters = sorted(by_D)
    strata = [by_D[d] for d in diameters]
    slopes = [bootstrap(groups, slope_through_origin) for groups in strata]  # over its runs
    K, a = stratified_bootstrap(strata, _law(diameters)) if len(diameters) > 1 else \
        ((np.nan,) * 3, (np.nan,) * 3)
    return dict(D=diameters, slope_per_D=slopes, runs_per_D=[len(g) for g in strata], K=K, a=a)


def _draw_law(ax, law, across=None):
    """The slopes per diameter against D in log-log, the fitted K D^-a and the paper's K / D;
    beside them (hollow) the same with P read across the pore."""
    if not law["D"]:
        return
    if across and across["D"]:
        s_across = [v[0] for v in across["slope_per_D"]]
        label = "the same, P across the pore (f_pore[27])"
        if np.isfinite(across["K"][0]):
            label += f": K {fmt(*across['K'])}, a {fmt(*across['a'])}"
        ax.plot(across["D"], s_across, "o", mfc="none", color="C2", label=label)
    D = np.asarray(law["D"])
    s = np.asarray([v[0] for v in law["slope_per_D"]])
    err = np.asarray([[v[0] - v[1], v[2] - v[0]] for v in law["slope_per_D"]]).T
    ax.errorbar(D, s, yerr=np.where(np.isfinite(err), err, 0), fmt="o", capsize=3,
                label="slope of P - P_0 on L_dep per D (interval over seeds)")
    xs = np.linspace(0.9 * D.min(), 1.1 * D.max(), 20)
    ax.plot(xs, PAPER_K / xs, "k--", label=f"paper: {PAPER_K} / D")
    if np.isfinite(law["K"][0]):
        ax.plot(xs, law["K"][0] * xs ** -law["a"][0], "C1-",
                label=f"ours: K {fmt(*law['K'])}, a {fmt(*law['a'])}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("D [d]")
    if across and np.isfinite(across["K"][0]):
        ax.plot(xs, across["K"][0] * xs ** -across["a"][0], "C2:")
    ax.set_ylabel("slope of P on L_dep [P_out / d]")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13))


def analyze(summary, out_dir):
    runs = finished_runs(summary)
    points = [_points(run) for run in runs]
    fits = pressure_fits(summary, lambda run, b: b["deposit_L"] / float(run["knobs"]["D"]))
    beside = beside_fits(summary, lambda run, b: b["deposit_L"] / float(run["knobs"]["D"]))
    groups = fits["groups"]
    K = fits["through_origin"]
    f_a_groups = [([p[2] for p in ps if np.isfinite(p[2])],) * 2 for ps in points]
    f_a = bootstrap(resampled(f_a_groups)[0], lambda x, y: float(np.mean(x)) if len(x) else np.nan)
    law = diameter_law(summary)
    law_across = diameter_law(summary, pressure="across")
    fig, (ax, ax_law) = plt.subplots(1, 2, figsize=(14, 7))
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
    # below the axes: above them it hid the bursts of the narrow pores
    ax.legend(fontsize=7, ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.13))
    _draw_law(ax_law, law, law_across)
    return result(summary, "porediameter", "K in P = K L_dep / D; theory 4 f_a",
                  f"{PAPER_K} +- 0.04; f_a = K/4 = {PAPER_K / 4:.3g}",
                  f"K {fits_text(fits)}; by the paper's procedure (a slope per D, then the slopes "
                  f"against D; intervals over seeds): P - P_0 = K L_dep / D^a with K {fmt(*law['K'])}, "
                  f"a {fmt(*law['a'])}; beside it, P across the pore (f_pore[27]): K {fmt(*law_across['K'])}, "
                  f"a {fmt(*law_across['a'])}; f_a = {fmt(*f_a)}; K {beside_text(beside)}",
                  save(fig, out_dir, "porediameter"),
                  K=K, K_excess=fits["excess_through_origin"], slope=fits["slope"],
                  intercept=fits["intercept"], f_a=f_a, diameter_law=law, diameter_law_across_pore=law_across,
                  f_a_from={source: sum(p[3] == source for ps in points for p in ps)
                            for source in ("deposit", "all particles", "none")},
                  **beside_results(beside))
