"""What holds a deposit at its pressure peak: the force balance behind the paper's K.

The paper's theory (Sec. III) has adhesion hold the whole load of the pressure loss on the
pore's section, P pi D^2 / 4, so that P = 4 f_a L_dep / D. Per burst of every finished run:

- load: P_pi_D2_4, the burst record's P_peak pi D^2 / 4 (force units);
- wall: the wall's force on all particles along the flow at the peak, -wall_F (the record's);
- fluid: the fluid's force on all particles along the flow at the peak (f_pore[14], the
  thermo row nearest the peak; runs whose rows lack it give none);
- excess load: the load of P - P_0 only (P_0: the run's particle-free pressure loss,
  figures.common.clean_pressure), the pressure the deposit adds.

These sum over every particle in the box: at a peak the wall also holds the particles queued
in the outlet region and any plug on the pore's entrance face, and the deposit may have left
already (its largest count comes a few hundred fluid steps before the peak). So, where the
rows carry them (in.pore prints them since the deposit's own loads were recorded), the same
balance of the deposit alone, at the thermo row of the deposit the burst tears off (the
figures' measure, figures.common.largest_deposit_row):

- deposit wall, deposit fluid: the wall's and the fluid's force along the flow on the
  deposited particles (-f_pore[35], f_pore[34]);
- its load: P pi D^2 / 4 with P that row's P / P_out;
- on-wall share: the deposited particles touching the wall over all deposited (f_pore[26] /
  f_pore[7]);
- net: every force along the flow on the deposited particles (f_pore[36], their mass times
  acceleration), and the other particles' hold, what the fluid's push leaves after the wall's
  hold and the net force: fluid - wall - net (f_pore[34] + f_pore[35] - f_pore[36]), the
  contacts and cohesion of particles outside the deposit across its edge (those within it
  cancel). fluid = wall + others + net closes the deposit's balance. f_pore[34] is the fluid
  step's force; the DEM step applies it less the implicit term C (v - v_step) and plus the
  lubrication forces, both proportional to speeds a deposit (slower than deposit_speed) does
  not have. Under `substep_force fraction` the DEM applies only 1 / N_DEM of it, so a run
  with that knob gets no others and no net (NaN).

wall / fluid near 1 says the particles are at rest on the wall (no other body holds them);
fluid / load below 1 says the fluid puts the rest of the load on the pore's solid walls
directly: the flow through and around the deposit, and the clean pore's own loss P_0.
Medians over all bursts with 95 % intervals over runs (fit_stats.bootstrap: whole runs
resampled) where there are two runs or more."""
import numpy as np

from figures.common import (burst_window_dem_steps, bursts, clean_pressure, finished_runs,
                            largest_deposit_row, plt, result, save, thermo)
from fit_stats import bootstrap, fmt

# The fluid's share of the load by the height of the peak [P_out]: does it rise as the
# deposit closes the pore?
PEAK_BANDS = ((0.0, 0.15), (0.15, 0.25), (0.25, float("inf")))

RATIOS = (("wall_over_load", "all particles: wall / (P pi D^2/4)"),
          ("fluid_over_load", "all particles: fluid / (P pi D^2/4)"),
          ("wall_over_fluid", "all particles: wall / fluid"),
          ("fluid_over_excess_load", "all particles: fluid / ((P - P_0) pi D^2/4)"),
          ("deposit_wall_over_load", "the deposit: wall / (P pi D^2/4)"),
          ("deposit_fluid_over_load", "the deposit: fluid / (P pi D^2/4)"),
          ("deposit_wall_over_fluid", "the deposit: wall / fluid"),
          ("deposit_on_wall_share", "the deposit: share on the wall"),
          ("deposit_others_over_load", "the deposit: other particles' hold / (P pi D^2/4)"),
          ("deposit_net_over_load", "the deposit: net force / (P pi D^2/4)"))


OWN = 6  # the values deposit_forces gives per burst


def deposit_forces(run):
    """Per burst, at the thermo row of the deposit it tears off: (load, deposit wall, deposit
    fluid, deposited count, of them on the wall, net force); NaN where the rows lack the
    columns."""
    columns = thermo(run["folder"])
    window = burst_window_dem_steps(run["folder"], run["knobs"])
    balanced = run["knobs"].get("substep_force", "held") != "fraction"  # the module's docstring
    value = lambda name, k: float(columns[name][k]) if name in columns else np.nan  # noqa: E731
    out = []
    for b in bursts(run["folder"]):
        k = largest_deposit_row(columns, b["step"], window)
        if k is None or b["P_peak"] <= 0:
            out.append((np.nan,) * OWN)
            continue
        load = b["P_pi_D2_4"] * value("pore[16]", k) / b["P_peak"]
        out.append((load, -value("pore[35]", k), value("pore[34]", k), value("pore[7]", k), value("pore[26]", k),
                    value("pore[36]", k) if balanced else np.nan))
    return out


def burst_forces(run):
    """Per burst: (load, wall, fluid, excess load), fluid NaN where the rows lack f_pore[14]."""
    columns = thermo(run["folder"])
    steps = np.asarray(columns.get("Step", []), float)
    fluid_column = np.asarray(columns.get("pore[14]", []), float)
    p0 = clean_pressure(run)
    out = []
    for b in bursts(run["folder"]):
        load = b["P_pi_D2_4"]
        fluid = np.nan
        if len(fluid_column) and len(steps):
            fluid = float(fluid_column[int(np.argmin(np.abs(steps - b["step"])))])
        excess = load * (b["P_peak"] - p0) / b["P_peak"] if np.isfinite(p0) and b["P_peak"] > 0 else np.nan
        out.append((load, -b["wall_F"], fluid, excess))
    return out


def ratios(forces, own=None):
    """{ratio name: values} of one run's bursts (see RATIOS), from burst_forces and, for the
    deposit's own, deposit_forces (NaN without)."""
    a = np.asarray(forces, float).reshape(-1, 4)
    load, wall, fluid, excess = a.T
    d = np.asarray(own if own is not None else [(np.nan,) * OWN] * len(a), float).reshape(-1, OWN)
    own_load, own_wall, own_fluid, count, on_wall, net = d.T
    with np.errstate(divide="ignore", invalid="ignore"):
        return {"wall_over_load": wall / load, "fluid_over_load": fluid / load,
                "wall_over_fluid": wall / fluid, "fluid_over_excess_load": fluid / excess,
                "deposit_wall_over_load": own_wall / own_load, "deposit_fluid_over_load": own_fluid / own_load,
                "deposit_wall_over_fluid": own_wall / own_fluid,
                "deposit_on_wall_share": np.where(count > 0, on_wall / count, np.nan),
                "deposit_others_over_load": (own_fluid - own_wall - net) / own_load,
                "deposit_net_over_load": net / own_load}


def run_ratios(run):
    return ratios(burst_forces(run), deposit_forces(run))


def share_by_peak(summary):
    """Per band of PEAK_BANDS: (bursts, median fluid / load) over every finished run's bursts
    whose rows carry the fluid's force."""
    peaks, shares = [], []
    for run in finished_runs(summary):
        r = run_ratios(run)["fluid_over_load"]
        peaks += [b["P_peak"] for b in bursts(run["folder"])]
        shares += list(r)
    peaks, shares = np.asarray(peaks, float), np.asarray(shares, float)
    bands = []
    for low, high in PEAK_BANDS:
        inside = (peaks >= low) & (peaks < high) & np.isfinite(shares)
        bands.append(dict(low=low, high=high, bursts=int(inside.sum()),
                          median=float(np.median(shares[inside])) if inside.any() else np.nan))
    return bands


def median_of_finite(x, y):
    y = np.asarray(y, float)
    y = y[np.isfinite(y)]
    return float(np.median(y)) if len(y) else np.nan


def analyze(summary, out_dir):
    runs = {run["name"]: run_ratios(run) for run in finished_runs(summary)}
    table, texts = {}, []
    for key, label in RATIOS:
        groups = [(v[key], v[key]) for v in runs.values() if np.isfinite(v[key]).any()]
        value = bootstrap(groups, median_of_finite)
        table[key] = dict(median=value[0], low=value[1], high=value[2],
                          per_run={name: median_of_finite(None, v[key]) for name, v in runs.items()})
        if groups:
            texts.append(f"{label} {fmt(*value)}")
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    others_shown, first = False, next(iter(runs), None)
    for name, run in zip(runs, finished_runs(summary)):
        a = np.asarray(burst_forces(run), float).reshape(-1, 4)
        d = np.asarray(deposit_forces(run), float).reshape(-1, OWN)
        axes[0].plot(a[:, 0], a[:, 1], "o", ms=3, alpha=0.7, label=name)
        axes[1].plot(a[:, 2], a[:, 1], "o", ms=3, alpha=0.7)
        axes[2].plot(d[:, 0], d[:, 1], "o", ms=3, alpha=0.7, label=None if name != first else "the wall's (f_pore[35])")
        others = d[:, 2] - d[:, 1] - d[:, 5]  # fluid - wall - net: what other particles hold
        if np.isfinite(others).any():
            axes[2].plot(d[:, 0], others, "^", mfc="none", ms=4, alpha=0.7, color="grey",
                         label=None if others_shown else "other particles' (f_pore[36])")
            others_shown = True
    for ax, xlabel in zip(axes, ("load P pi D^2 / 4 at the peak", "fluid's force on the particles",
                                 "load at the deposit's largest count")):
        top = max([abs(v) for line in ax.get_lines() for v in line.get_xdata() if np.isfinite(v)] + [1e-30])
        ax.plot([0, top], [0, top], "k:", lw=1, label="all of it")
        ax.set_xlabel(xlabel + " [N]")
        ax.set_ylabel("wall's hold along the flow [N]")
    axes[0].legend(fontsize=6)
    axes[0].set_title("the wall's hold against the paper's load", fontsize=9)
    axes[1].set_title("the wall's hold against the fluid's force", fontsize=9)
    axes[2].set_ylabel("hold on the deposit alone [N]")
    axes[2].set_title("the deposit's own hold (rows with f_pore[35])", fontsize=9)
    # the last line is the "all of it" diagonal; the others the runs that recorded the deposit
    if any(np.isfinite(line.get_ydata()).any() for line in axes[2].get_lines()[:-1]):
        axes[2].legend(fontsize=6)
    else:
        axes[2].text(0.5, 0.5, "not recorded in these runs", transform=axes[2].transAxes, ha="center")
    bands = share_by_peak(summary)
    texts += [f"fluid / load {b['median']:.2f} at {b['bursts']} peaks in [{b['low']:g}, {b['high']:g}) P_out"
              for b in bands if b["bursts"]]
    ours = "; ".join(texts) if texts else "no bursts in finished runs"
    return result(summary, "hold", "what holds a deposit at its peak (force ratios, medians over bursts)",
                  "adhesion holds the whole load P pi D^2 / 4 (the theory behind K = 4 f_a)",
                  ours, save(fig, out_dir, "hold"), ratios=table, fluid_share_by_peak=bands,
                  bursts_per_run={name: int(len(v["wall_over_load"])) for name, v in runs.items()})
