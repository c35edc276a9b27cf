"""Fig. pvpflux: particle and fluid volume flux through the outlet, each over their sum,
against an imposed constant pressure loss P [P_out] (ka = 0.05); the paper finds no particle
flux below P ~ 0.35. P is the ceiling P_max on in.pore's inlet velocity (the pore fills at u_in,
the loss is then held at P_max; studies.pvpflux). Fluxes over the second half of each run: the fluid's mean f_pore[3],
the particles' growth rate of f_pore[13] (cumulative particle volume through the outlet).
The fluid's mean is over time (figures.common.time_mean): a compact result keeps the bursts'
windows at every row. Beside them, per run, the share of that time the ceiling held the loss
(the inlet velocity f_pore[37] below 0.99 of its largest, u_in at the start): where the
deposit reaches P_max and holds, no burst comes, and the particles pile up upstream."""
import numpy as np

from figures.common import finished_runs, plt, result, save, thermo, time_mean, times

PAPER_THRESHOLD = 0.35


def _fluxes(run):
    """Fluid and particle flux over the run's second half, and the share of it the ceiling
    held the loss (NaN without the inlet velocity's column)."""
    columns = thermo(run["folder"])
    if "pore[3]" not in columns or len(columns["Step"]) < 4:
        return np.nan, np.nan, np.nan
    t = times(run, columns["Step"])
    half = t >= t[0] + (t[-1] - t[0]) / 2
    fluid = time_mean(t[half], np.asarray(columns["pore[3]"], float)[half])
    volume = np.asarray(columns["pore[13]"], float)[half]
    particles = float((volume[-1] - volume[0]) / (t[half][-1] - t[half][0]))
    held = np.nan
    if "pore[37]" in columns:
        inlet = np.asarray(columns["pore[37]"], float)
        held = time_mean(t[half], (inlet[half] < 0.99 * inlet.max()).astype(float))
    return fluid, max(particles, 0.0), held


def analyze(summary, out_dir):
    runs = sorted(finished_runs(summary), key=lambda r: float(r["knobs"]["P_max"]))
    P = [float(r["knobs"]["P_max"]) for r in runs]
    flux = [_fluxes(r) for r in runs]
    total = [f + p for f, p, _ in flux]
    phi_f = [f / s if s > 0 else np.nan for (f, _, _), s in zip(flux, total)]
    phi_p = [p / s if s > 0 else np.nan for (_, p, _), s in zip(flux, total)]
    held = [h for _, _, h in flux]
    threshold = next((p for p, q in zip(P, phi_p) if q > 0), None)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(P, phi_p, "o-", label="particles / total")
    ax.plot(P, phi_f, "s-", label="fluid / total")
    ax.set_yscale("log")
    ax.axvline(PAPER_THRESHOLD, color="k", ls=":", label=f"paper: particle flux from P ~ {PAPER_THRESHOLD}")
    ax.set_xlabel("imposed P [P_out]")
    ax.set_ylabel("flux / total flux")
    ax.legend(fontsize=8)
    ours = (f"first P with particle flux: {threshold}" if threshold is not None
            else "no particle flux at any P")
    return result(summary, "pvpflux", "P below which no particle leaves", f"~ {PAPER_THRESHOLD}",
                  ours, save(fig, out_dir, "pvpflux"), threshold=threshold,
                  points=[dict(P=a, fluid=b, particles=c, held=h) for a, b, c, h in zip(P, phi_f, phi_p, held)])
