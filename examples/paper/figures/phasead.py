"""Fig. phasead: P_max over the adhesion ka and the particle / pore diameter ratio d / D at
L = 1.2 D. As the paper's caption says ("since we change here the particle diameter"), the
particles' diameter changes (in.pore's d_particle, in the table's unit d, so the table's
coefficients stay as they are) and the pore keeps the default's D."""
from figures.phase_map import analyze_plane


def d_over_D(run):
    knobs = run["knobs"]
    return float(knobs.get("d_particle", 1.0)) / float(knobs["D"])


def analyze(summary, out_dir):
    return analyze_plane(summary, out_dir, "phasead", "ka", lambda r: float(r["knobs"]["ka"]),
                         "d / D", d_over_D, False,
                         "larger d / D: larger pressure build-up and bursts")
