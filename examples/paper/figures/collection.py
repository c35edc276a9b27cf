"""Fig. collection: three snapshots of the run (before deposition, at a pressure peak, after
the burst) rendered from its own VTK files (render_snapshot.py)."""
import os

from figures.common import finished_runs, result
from render_snapshot import render


def analyze(summary, out_dir):
    runs = finished_runs(summary)
    if not runs:
        return result(summary, "collection", "snapshots", "three snapshots", "no finished run", None)
    out = os.path.join(out_dir, "collection.png")
    times = render(runs[0]["folder"], out)
    return result(summary, "collection", "snapshots", "three snapshots (drag per mass, speed)",
                  f"rendered at fluid steps {list(times)}", out)
