"""The studies' settings (studies.settings): N_DEM = 100 DEM substeps per fluid step against 20,
on the same seeds in the chosen regime. Per run: the bursts, the largest deposit a burst tore
off (the figures' measure, figures.common.with_largest_deposits) and the median over the
bursts, and the highest pressure loss P_max [P_out] after the warm-up. N_DEM 20 agrees with
100 when each of its means lies within the spread (min to max) of the N_DEM 100 seeds; the
studies then may use it (doc/paper.md, "Criteria")."""
import numpy as np

from figures.common import bursts, finished_runs, plt, result, save, thermo, with_largest_deposits

QUANTITIES = (("bursts", "erosive bursts"), ("largest_deposit", "largest deposit [particles]"),
              ("median_deposit", "median deposit [particles]"), ("p_max", "P_max [P_out]"))


def run_figures(run):
    columns = thermo(run["folder"])
    rows = with_largest_deposits(run, bursts(run["folder"]), columns)
    counts = [b["deposit_count"] for b in rows]
    warmup = float(run["knobs"].get("warmup", 0))
    pressures = [p for s, p in zip(columns.get("Step", []), columns.get("pore[16]", [])) if s > warmup]
    return {"bursts": len(rows), "largest_deposit": max(counts) if counts else 0,
            "median_deposit": float(np.median(counts)) if counts else 0.0,
            "p_max": max(pressures) if pressures else float("nan")}


def compare(groups, labels, reference, others, out_dir, name):
    """Each quantity of runs grouped by setting (groups[setting][run] = run_figures), drawn per
    group; the verdict of each group of `others`: its mean within the spread (min to max) of
    `reference`'s runs or not. Returns the verdicts, the values per group and the plot's path."""
    fig, axes = plt.subplots(1, len(QUANTITIES), figsize=(11, 3.2))
    verdicts, table = [], {}
    for ax, (key, label) in zip(axes, QUANTITIES):
        values = {g: [r[key] for r in groups[g].values()] for g in labels}
        table[key] = {str(g): v for g, v in values.items()}
        for i, g in enumerate(labels):
            ax.plot([i] * len(values[g]), values[g], "o", alpha=0.7)
        ax.set_xticks(range(len(labels)))
        ax.set_xticklabels(list(labels.values()))
        ax.set_title(label, fontsize=9)
        for other in others:
            if values[reference] and values[other]:
                low, high = min(values[reference]), max(values[reference])
                mean = float(np.mean(values[other]))
                verdicts.append(f"{key}: {labels[other]} mean {mean:.3g} {'within' if low <= mean <= high else 'outside'} "
                                f"{labels[reference]}'s {low:.3g}-{high:.3g}")
    return verdicts, table, save(fig, out_dir, name)


def analyze(summary, out_dir):
    groups = {100: {}, 20: {}}
    for run in finished_runs(summary):
        n_dem = int(run["knobs"].get("n_dem", 100))
        groups.setdefault(n_dem, {})[run["name"]] = run_figures(run)
    verdicts, table, png = compare(groups, {100: "N_DEM 100", 20: "N_DEM 20"}, 100, (20,), out_dir, "settings")
    ours = "; ".join(verdicts) if verdicts else "no pair of finished runs yet"
    return result(summary, "settings", "N_DEM 20 against 100 (bursts, deposits, P_max)",
                  "the paper uses N_DEM 100 for stability and cost; its statistics should not depend on it",
                  ours, png, values=table,
                  runs_per_n_dem={str(n): len(groups[n]) for n in groups})
