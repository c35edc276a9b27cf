"""What the figure modules share: the runs' bursts as per-run point groups, and a plot saved
with the paper's value written beside ours."""
import os

import matplotlib
import numpy as np
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (the figure modules draw with it)

from study_io import (burst_window_dem_steps, bursts, finished_runs, lattice_timing, p_out,  # noqa: E402,F401
                      thermo)


def times(run, steps):
    """DEM steps of a run as times in the script's unit (the paper's fluid step)."""
    return np.asarray(steps, float) * lattice_timing(run["folder"])["dt_dem"]


def row_durations(t):
    """The time each thermo row stands for (half the gaps to its neighbours). A study's
    compact result keeps every tenth row and every row of a burst's window, so a plain mean
    over its rows would weigh the bursts' windows ten times; weighted by these, a mean over
    the rows is the mean over time whichever rows were kept."""
    t = np.asarray(t, float)
    if len(t) < 2:
        return np.ones_like(t)
    gaps = np.diff(t)
    return np.concatenate([[gaps[0] / 2], (gaps[:-1] + gaps[1:]) / 2, [gaps[-1] / 2]])


def time_mean(t, y):
    """The mean of y over time (rows weighted by row_durations); NaN without rows."""
    y = np.asarray(y, float)
    if len(y) == 0:
        return np.nan
    return float(np.average(y, weights=row_durations(t))) if len(y) > 1 else float(y[0])


def burst_groups(summary, x_of, y_of):
    """Per finished run, (x list, y list) over its bursts: the groups fit_stats.bootstrap
    resamples."""
    groups = []
    for run in finished_runs(summary):
        rows = bursts(run["folder"])
        groups.append(([x_of(run, b) for b in rows], [y_of(run, b) for b in rows]))
    return groups


def burst_fit(summary, x_key, statistic):
    """(groups, fit, pearson) of P_peak against a burst column (V_dep or L_dep) over the
    finished runs: `statistic` (fit_stats.slope or slope_through_origin) and the Pearson
    coefficient, each (value, low, high) from fit_stats.bootstrap."""
    from fit_stats import bootstrap, pearson
    groups = burst_groups(summary, lambda run, b: b[x_key], lambda run, b: b["P_peak"])
    return groups, bootstrap(groups, statistic), bootstrap(groups, pearson)


def clean_pressure(run, share=0.25, column="pore[16]"):
    """P_0 [P_out]: the run's own particle-free pressure loss, the mean of P / P_out
    (f_pore[16], or `column`) over the thermo rows of the last `share` of its warm-up (the
    start-up transient is over by then; in.pore's warm-up). NaN without such rows."""
    columns = thermo(run["folder"])
    warmup = float(run["knobs"].get("warmup", 0))
    rows = [p for s, p in zip(columns.get("Step", []), columns.get(column, []))
            if (1 - share) * warmup < s <= warmup]
    return float(np.mean(rows)) if rows else np.nan


def largest_deposit_row(columns, peak_step, window_steps):
    """The index of the thermo row with the largest deposited count (f_pore[7]) among those
    of the `window_steps` DEM steps up to `peak_step` (the first such row on a tie); None
    without such rows."""
    steps = np.asarray(columns.get("Step", []), float)
    inside = np.flatnonzero((steps >= peak_step - window_steps) & (steps <= peak_step))
    if not len(inside) or "pore[7]" not in columns:
        return None
    return int(inside[int(np.argmax(np.asarray(columns["pore[7]"], float)[inside]))])


def largest_deposit_before(columns, peak_step, window_steps):
    """The deposit before its release, the figures' measure (DEPOSIT_MEASURES): (count,
    V_dep, L_dep) of the thermo row with the largest deposited count (f_pore[7], f_pore[6],
    f_pore[8]) among those of the `window_steps` DEM steps up to `peak_step`
    (largest_deposit_row); None without such rows. The burst record's median over the same
    window loses a deposit released more than half a window before the peak."""
    k = largest_deposit_row(columns, peak_step, window_steps)
    if k is None:
        return None
    at = [float(columns[c][k]) if c in columns else np.nan for c in ("pore[6]", "pore[8]")]
    return (int(round(columns["pore[7]"][k])), at[0], at[1])


def at_the_peak(rows):
    """Copies of burst rows whose deposit is the record's own at the peak (count_before,
    V_dep, L_dep): the paper's words read literally ("V_dep at each pressure peak")."""
    return [dict(b, deposit_count=b["count_before"], deposit_V=b["V_dep"], deposit_L=b["L_dep"]) for b in rows]


def with_largest_deposits(run, rows, columns=None):
    """Copies of a run's burst rows whose deposit (deposit_count, deposit_V, deposit_L) is the
    largest in the window before the peak (largest_deposit_before, from the run's thermo
    rows); a burst without rows in its window keeps the record's median."""
    columns = thermo(run["folder"]) if columns is None else columns
    window = burst_window_dem_steps(run["folder"], run["knobs"])
    out = []
    for b in rows:
        largest = largest_deposit_before(columns, b["step"], window)
        out.append(b if largest is None else
                   dict(b, deposit_count=largest[0], deposit_V=largest[1], deposit_L=largest[2]))
    return out


def resampled(groups):
    """(groups, unit) for fit_stats.bootstrap: whole runs, unless a single run has bursts:
    then its bursts one by one (a paper-length run is one run). An interval
    over one run's bursts leaves out the spread between runs and the bursts' shared deposit
    history, so the figures say which it is."""
    if sum(1 for x, _ in groups if len(x)) != 1:
        return groups, "runs"
    return [([xi], [yi]) for x, y in groups for xi, yi in zip(x, y)], "bursts"


# The deposit a burst tears off, as every figure counts it (doc/paper.md, "The deposit"): the
# largest count of particles at rest (bonded, inside the pore radius, slower than in.pore's
# deposit_speed, 0.1408 d per 1000 time units) in the burst window before the peak. A deposit
# is released before the pressure peaks, sooner or later from burst to burst, so no fixed time
# reads it whole; under this bound the count at rest is steady until the release (its largest
# exceeds its median over the window's first 60 % by 0 particles in the median burst), so its
# largest is the deposit, not a fluctuation. The window's median and the count at the peak
# are shown beside it.
DEPOSIT_MEASURES = ("largest", "median", "peak")
# Where the pressure loss is read: between the box's open faces (the burst records' P_peak,
# f_pore[16], the figures' measure) or across the pore (f_pore[27], between the node planes
# next to the pore's ends, "on both sides of the pore" as the paper words it), beside it.
PRESSURES = {"faces": "pore[16]", "across": "pore[27]"}


def across_pore_peaks(run, rows):
    """The rows (bursts) with P_peak read across the pore: f_pore[27] at the thermo row
    nearest each peak; a burst without a row within a hundredth of the burst window of its
    peak (in.pore's thermo rows: one every hundredth) or a run without the column is left
    out."""
    columns = thermo(run["folder"])
    if "pore[27]" not in columns or not columns.get("Step"):
        return []
    steps = np.asarray(columns["Step"], float)
    across = np.asarray(columns["pore[27]"], float)
    near = burst_window_dem_steps(run["folder"], run["knobs"]) / 100
    out = []
    for b in rows:
        k = int(np.argmin(np.abs(steps - b["step"])))
        if abs(steps[k] - b["step"]) <= near and np.isfinite(across[k]):
            out.append(dict(b, P_peak=float(across[k])))
    return out


def run_points(run, x_of, deposit="largest", pressure="faces"):
    """One run's bursts as (x, P_peak, P_peak - P_0) lists, x = x_of(run, burst) with the
    burst's deposit counted by `deposit` (pressure_fits) and the pressure read where
    `pressure` says (PRESSURES; P_0 read at the same place); the last list is empty when the
    run has no clean pressure P_0 (clean_pressure)."""
    if deposit not in DEPOSIT_MEASURES:
        raise ValueError(f"deposit must be one of {', '.join(DEPOSIT_MEASURES)}, not {deposit!r}")
    if pressure not in PRESSURES:
        raise ValueError(f"pressure must be one of {', '.join(PRESSURES)}, not {pressure!r}")
    rows = bursts(run["folder"])
    if deposit == "largest":
        rows = with_largest_deposits(run, rows)
    elif deposit == "peak":
        rows = at_the_peak(rows)
    if pressure == "across":
        rows = across_pore_peaks(run, rows)
    p0 = clean_pressure(run, column=PRESSURES[pressure])
    x = [x_of(run, b) for b in rows]
    return x, [b["P_peak"] for b in rows], [b["P_peak"] - p0 for b in rows] if np.isfinite(p0) else []


def pressure_fits(summary, x_of, deposit="largest", pressure="faces"):
    """The fits of the peak pressure against x_of(run, burst), the same three for every
    figure so that like is compared with like: the paper's line through the origin on P, the
    same on the pressure the deposit adds, P - P_0 (P_0 = clean_pressure of each run), and a
    line with an intercept on P. Each value (value, low, high) with fit_stats.bootstrap's
    interval over runs (over bursts for a single run: `resampled`); also the Pearson
    coefficient, the per-run point groups and `unit`, what the intervals resample.
    deposit: "largest", the figures' measure (largest_deposit_before); "median", the burst
    records' deposit (the median over the burst window); or "peak", the record's count at the
    peak (at_the_peak). pressure: where P is read (PRESSURES), the faces' unless told."""
    from fit_stats import bootstrap, intercept, pearson, slope, slope_through_origin
    groups, excess = [], []
    for run in finished_runs(summary):
        x, p, p_excess = run_points(run, x_of, deposit, pressure)
        groups.append((x, p))
        excess.append((x, p_excess))
    excess = [(x, y) for x, y in excess if len(y)]
    samples, unit = resampled(groups)
    excess_samples, _ = resampled(excess)
    return dict(groups=groups, excess_groups=excess, unit=unit,
                through_origin=bootstrap(samples, slope_through_origin),
                excess_through_origin=bootstrap(excess_samples, slope_through_origin),
                slope=bootstrap(samples, slope), intercept=bootstrap(samples, intercept),
                pearson=bootstrap(samples, pearson))


def fits_text(fits):
    """The three fits in one line, for results.json and the plot's title."""
    from fit_stats import fmt
    over = " (intervals over the bursts of one run)" if fits["unit"] == "bursts" else ""
    return (f"through 0: {fmt(*fits['through_origin'])}; P - P_0 through 0: "
            f"{fmt(*fits['excess_through_origin'])}; with intercept: {fmt(*fits['slope'])} "
            f"(intercept {fmt(*fits['intercept'])}){over}")


# The measures shown beside the figures' own, and how each is named on a plot.
BESIDE = {"median": ("the median over the burst window", "s", "C7"),
          "peak": ("the count at the peak", "o", "0.5")}


def beside_fits(summary, x_of):
    """pressure_fits of each measure shown beside the figures' deposit (BESIDE)."""
    return {m: pressure_fits(summary, x_of, deposit=m) for m in BESIDE}


def beside_text(beside):
    """The fits on the other deposit measures, in one phrase."""
    from fit_stats import fmt
    return "; ".join(f"on {BESIDE[m][0]}: P - P_0 through 0 {fmt(*f['excess_through_origin'])}, "
                     f"Pearson {fmt(*f['pearson'])}" for m, f in beside.items())


def beside_results(beside):
    """The other measures' fits for results.json."""
    return {f"deposit_{m}": {k: f[k] for k in ("excess_through_origin", "pearson")} for m, f in beside.items()}


def draw_beside(ax, beside):
    """The bursts with the other measures' deposits, as hollow markers beside the figure's."""
    for m, fits in beside.items():
        x = [xi for g in fits["groups"] for xi in g[0]]
        y = [yi for g in fits["groups"] for yi in g[1]]
        label, marker, colour = BESIDE[m]
        if x:
            ax.plot(x, y, marker, ms=5, mfc="none", mec=colour, mew=0.8,
                    label=f"deposit {label} (Pearson {fits['pearson'][0]:.2f})")


def across_pore_fits(summary, x_of):
    """pressure_fits of the figures' deposit with P read across the pore (PRESSURES), shown
    beside the figure's own: the pressure the paper measures "on both sides of the pore",
    without what the plug on the entrance face and the queue beyond the pore add."""
    return pressure_fits(summary, x_of, pressure="across")


def across_pore_text(fits):
    """The across-the-pore fit in one phrase, for results.json."""
    from fit_stats import fmt
    return (f"beside it, P across the pore (f_pore[27]): P - P_0 through 0 "
            f"{fmt(*fits['excess_through_origin'])}, Pearson {fmt(*fits['pearson'])}")


def across_pore_results(fits):
    """The across-the-pore fit for results.json (verdicts.py shows it beside the figure's)."""
    return dict(across_pore={k: fits[k] for k in ("excess_through_origin", "pearson")})


def draw_across_pore(ax, fits):
    """The bursts with P read across the pore, as hollow triangles beside the figure's."""
    x = [xi for g in fits["groups"] for xi in g[0]]
    y = [yi for g in fits["groups"] for yi in g[1]]
    if x:
        ax.plot(x, y, "^", ms=5, mfc="none", mec="C9", mew=0.8,
                label=f"P across the pore (Pearson {fits['pearson'][0]:.2f})")


def draw_fits(ax, fits, top, paper=None, paper_label="paper"):
    """The three fitted lines (and the paper's through 0) from 0 to top."""
    xs = np.linspace(0, top, 2)
    if np.isfinite(fits["through_origin"][0]):
        ax.plot(xs, fits["through_origin"][0] * xs, "C3--", label="ours, P through 0")
    if np.isfinite(fits["excess_through_origin"][0]):
        ax.plot(xs, fits["excess_through_origin"][0] * xs, "C2-.", label="ours, P - P_0 through 0")
    if np.isfinite(fits["slope"][0]):
        ax.plot(xs, fits["intercept"][0] + fits["slope"][0] * xs, "C1-", lw=1,
                label="ours, P with intercept")
    if paper is not None:
        ax.plot(xs, paper * xs, "k:", label=f"{paper_label}: {paper}")


def result(summary, figure, quantity, paper, ours, out_png, **more):
    r = dict(figure=figure, quantity=quantity, paper=paper, ours=ours, plot=out_png,
             runs=len(summary["runs"]), finished=summary["finished"], size=summary["size"])
    r.update(more)
    return r


def save(fig, out_dir, name):
    path = os.path.join(out_dir, f"{name}.png")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path
