"""Fig. conc: the mean pressure jump (mean Delta P of the bursts, 0 without any) [P_out]
against the inlet concentration C_in (L = 4.23, D = 3.52); the paper finds no clogging below
C_in ~ 0.013 and clogging with bursts above. Ours: the smallest C_in whose runs burst."""
import numpy as np

from fit_stats import bootstrap, fmt
from figures.common import bursts, finished_runs, plt, result, save

PAPER_ONSET = 0.013


def analyze(summary, out_dir):
    by_c = {}
    for run in finished_runs(summary):
        jumps = [b["delta_P"] for b in bursts(run["folder"])]
        by_c.setdefault(float(run["knobs"]["c_in"]), []).append(jumps)
    cs = sorted(by_c)
    means = [bootstrap([(j, j) for j in by_c[c]] or [([0.0], [0.0])],
                       lambda x, y: float(np.mean(x)))
             if any(len(j) for j in by_c[c]) else (0.0, np.nan, np.nan) for c in cs]
    onset = next((c for c, m in zip(cs, means) if m[0] > 0), None)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(cs, [m[0] for m in means], "o-", label="ours")
    for c, m in zip(cs, means):
        if np.isfinite(m[1]):
            ax.plot([c, c], m[1:], "C0-", lw=1)
    ax.axvline(PAPER_ONSET, color="k", ls=":", label=f"paper: onset C_in ~ {PAPER_ONSET}")
    ax.set_xlabel("C_in")
    ax.set_ylabel("mean Delta P of the bursts [P_out]")
    ax.legend(fontsize=8)
    ours = (f"first C_in with bursts: {onset}" if onset is not None else "no bursts at any C_in")
    ours += "; mean jumps " + ", ".join(f"{c:g}: {fmt(*m)}" for c, m in zip(cs, means))
    return result(summary, "conc", "onset of clogging in C_in", f"~ {PAPER_ONSET}", ours,
                  save(fig, out_dir, "conc"), onset=onset,
                  means={str(c): m for c, m in zip(cs, means)})
