"""Fig. phasead: P_max over the adhesion ka and the particle / pore diameter ratio d / D
(L = 1.2 D; here d = 1 and D = 1 / (d / D), so the table's units stay those of d)."""
from figures.phase_map import analyze_plane


def analyze(summary, out_dir):
    return analyze_plane(summary, out_dir, "phasead", "ka", lambda r: float(r["knobs"]["ka"]),
                         "d / D", lambda r: 1.0 / float(r["knobs"]["D"]), False,
                         "larger d / D: larger pressure build-up and bursts")
