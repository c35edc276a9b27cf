"""Fig. collection: three snapshots of the run (before deposition, at a pressure peak, after
the burst) rendered from its own VTK files, or from the frames kept of them (render_snapshot.py,
snapshots.npz) in a study's compact evidence."""
import os

from figures.common import finished_runs, result
from render_snapshot import render


def analyze(summary, out_dir):
    runs = finished_runs(summary)
    if not runs:
        return result(summary, "collection", "snapshots", "three snapshots", "no finished run", None)
    out = os.path.join(out_dir, "collection.png")
    times = render(runs[0]["folder"], out, keep=True)  # its frames kept beside its files
    return result(summary, "collection", "snapshots", "three snapshots (drag per mass, speed)",
                  f"rendered at fluid steps {list(times)}", out)
