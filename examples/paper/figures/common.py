"""What the figure modules share: the runs' bursts as per-run point groups, and a plot saved
with the paper's value written beside ours."""
import os

import matplotlib
import numpy as np
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (the figure modules draw with it)

from study_io import bursts, finished_runs, lattice_timing, p_out, thermo  # noqa: E402,F401


def times(run, steps):
    """DEM steps of a run as times in the script's unit (the paper's fluid step)."""
    return np.asarray(steps, float) * lattice_timing(run["folder"])["dt_dem"]


def burst_groups(summary, x_of, y_of):
    """Per finished run, (x list, y list) over its bursts: the groups fit_stats.bootstrap
    resamples."""
    groups = []
    for run in finished_runs(summary):
        rows = bursts(run["folder"])
        groups.append(([x_of(run, b) for b in rows], [y_of(run, b) for b in rows]))
    return groups


def burst_fit(summary, x_key, statistic):
    """(groups, fit, pearson) of P_peak against a burst column (V_dep or L_dep) over the
    finished runs: `statistic` (fit_stats.slope or slope_through_origin) and the Pearson
    coefficient, each (value, low, high) from fit_stats.bootstrap."""
    from fit_stats import bootstrap, pearson
    groups = burst_groups(summary, lambda run, b: b[x_key], lambda run, b: b["P_peak"])
    return groups, bootstrap(groups, statistic), bootstrap(groups, pearson)


def result(summary, figure, quantity, paper, ours, out_png, **more):
    r = dict(figure=figure, quantity=quantity, paper=paper, ours=ours, plot=out_png,
             runs=len(summary["runs"]), finished=summary["finished"], size=summary["size"])
    r.update(more)
    return r


def save(fig, out_dir, name):
    path = os.path.join(out_dir, f"{name}.png")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path
