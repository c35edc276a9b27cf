"""Fig. conc: the mean pressure jump (mean Delta P of the bursts, 0 without any) [P_out]
against the inlet concentration C_in (L = 4.23, D = 3.52); the paper finds no clogging below
C_in ~ 0.013 and clogging with bursts above. Ours: the smallest C_in whose runs burst, and
per run the concentration the inlet realised (realised_concentration), drawn beside C_in."""
import numpy as np

from fit_stats import bootstrap, fmt
from figures.common import bursts, finished_runs, lattice_timing, plt, result, save, thermo, times

PAPER_ONSET = 0.013


def realised_concentration(run):
    """The inlet concentration the run realised: the particle volume through the inlet plane
    (the end of region I, f_pore[12], in d^3) per time over u_in W^2 (W in whole cells, as
    in.pore rounds it), from one crossing of region I after the warm-up (the first fill has
    then reached the plane) to the run's end. c_in when region I delivers what in.pore inserts
    (tests/inlet: 0.97-0.98 c_in); less when a clog backs the particles up into region I.
    NaN without the column (studies.conc asks for it with thermo_extra)."""
    columns = thermo(run["folder"])
    if "pore[12]" not in columns:
        return np.nan
    knobs, timing = run["knobs"], lattice_timing(run["folder"])
    u_in = float(knobs["u_lattice"]) * timing["dx"] / timing["dt_f"]
    width = round(float(knobs["W"]) / timing["dx"]) * timing["dx"]
    t = times(run, columns["Step"])
    start = float(knobs["warmup"]) * timing["dt_dem"] + float(knobs["Li"]) / u_in
    after = t >= start
    if after.sum() < 2:
        return np.nan
    volume = np.asarray(columns["pore[12]"], float)[after]
    return float((volume[-1] - volume[0]) / ((t[after][-1] - t[after][0]) * u_in * width ** 2))


def analyze(summary, out_dir):
    by_c, realised = {}, {}
    for run in finished_runs(summary):
        jumps = [b["delta_P"] for b in bursts(run["folder"])]
        by_c.setdefault(float(run["knobs"]["c_in"]), []).append(jumps)
        realised.setdefault(float(run["knobs"]["c_in"]), []).append(realised_concentration(run))
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
    for c, m in zip(cs, means):  # hollow: the same runs at the concentration they realised
        ax.plot(realised[c], [m[0]] * len(realised[c]), "o", mfc="none", color="C1",
                label="ours at the realised C" if c == cs[0] else None)
    ax.axvline(PAPER_ONSET, color="k", ls=":", label=f"paper: onset C_in ~ {PAPER_ONSET}")
    ax.set_xlabel("C_in")
    ax.set_ylabel("mean Delta P of the bursts [P_out]")
    ax.legend(fontsize=8)
    ours = (f"first C_in with bursts: {onset}" if onset is not None else "no bursts at any C_in")
    ours += "; mean jumps " + ", ".join(f"{c:g}: {fmt(*m)}" for c, m in zip(cs, means))
    ours += "; realised C " + ", ".join(f"{c:g}: " + ", ".join(f"{r:.3g}" for r in realised[c]) for c in cs)
    return result(summary, "conc", "onset of clogging in C_in", f"~ {PAPER_ONSET}", ours,
                  save(fig, out_dir, "conc"), onset=onset,
                  means={str(c): m for c, m in zip(cs, means)},
                  realised={str(c): realised[c] for c in cs})
