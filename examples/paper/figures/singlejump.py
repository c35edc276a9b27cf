"""Fig. singlejump: the largest erosive burst of a run, P / Delta P against (t - t_peak) /
Delta t (Delta P, Delta t: the burst's fall and its duration, bursts.txt), from the run's
thermo rows of P / P_out. The paper shows its curve beside an experiment's and its mesoscale
model's; it gives no numbers, so the paper's shape is drawn schematically: a fall by one
Delta P within one Delta t."""
import numpy as np

from figures.common import bursts, finished_runs, plt, result, save, thermo, times


def analyze(summary, out_dir):
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ours = "no burst in the run"
    shown = None
    for run in finished_runs(summary):
        rows = bursts(run["folder"])
        if not rows:
            continue
        b = max(rows, key=lambda r: r["delta_P"])
        columns = thermo(run["folder"])
        t = times(run, columns["Step"])
        P = np.asarray(columns["pore[16]"], float)
        t_peak = b["time"]
        tt = (t - t_peak) / b["delta_t"]
        keep = (tt > -3) & (tt < 4)
        ax.plot(tt[keep], (P[keep] - b["P_after"]) / b["delta_P"], "C3-", label=run["name"])
        ours = (f"Delta P = {b['delta_P']:.3g} P_out ({100 * b['delta_P'] / b['P_peak']:.0f} % "
                f"of the peak) in Delta t = {b['delta_t']:.0f} (the paper's fluid steps)")
        shown = b
        break
    ax.plot([-3, 0, 1, 4], [1, 1, 0, 0], "k:", label="paper's shape (schematic, no data given)")
    ax.set_xlabel("(t - t_peak) / Delta t")
    ax.set_ylabel("(P - P_after) / Delta P")
    ax.legend(fontsize=8)
    return result(summary, "singlejump", "shape of one burst", "a fall by Delta P within Delta t",
                  ours, save(fig, out_dir, "singlejump"), burst=shown)
