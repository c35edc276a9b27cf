"""Fig. phaseac: P_max over the adhesion ka and the cohesion kc (L = 6.45, D = 3.52)."""
from figures.phase_map import analyze_plane


def analyze(summary, out_dir):
    return analyze_plane(summary, out_dir, "phaseac", "ka", lambda r: float(r["knobs"]["ka"]),
                         "kc", lambda r: float(r["knobs"]["kc"]), True,
                         "ka within one decade decides (none to severe); kc over decades does not")
