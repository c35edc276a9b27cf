"""Fits with confidence intervals from a bootstrap over runs: the runs of an ensemble are the
independent samples (the bursts of one run are not: they share its deposit history), so each
resample draws whole runs with replacement and refits all their points. A single run has
only its bursts to resample (figures.common.resampled), and the figures say so.
"""
import numpy as np


def slope(x, y):
    """Least-squares slope of y = a + b x (the paper's "linear fit with slope")."""
    return np.polyfit(x, y, 1)[0] if len(x) > 1 and np.ptp(x) > 0 else np.nan


def intercept(x, y):
    """Least-squares a of y = a + b x (the clean pore's share of a fit with an intercept)."""
    return np.polyfit(x, y, 1)[1] if len(x) > 1 and np.ptp(x) > 0 else np.nan


def slope_through_origin(x, y):
    """Least-squares b of y = b x (the paper's P = K L_dep / D, a line through 0)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    return float(x @ y / (x @ x)) if len(x) and x @ x > 0 else np.nan


def pearson(x, y):
    if len(x) < 2 or np.ptp(x) == 0 or np.ptp(y) == 0:
        return np.nan
    return float(np.corrcoef(x, y)[0, 1])


def bootstrap(groups, statistic, resamples=2000, level=0.95, seed=12345):
    """statistic(x, y) over all points of `groups` (a list, per run, of (x list, y list)) and
    its percentile interval over `resamples` draws of whole runs with replacement.
    Returns (value, low, high); low = high = nan with fewer than two runs that have points."""
    groups = [(np.asarray(x, float), np.asarray(y, float)) for x, y in groups if len(x)]
    if not groups:
        return np.nan, np.nan, np.nan
    value = statistic(np.concatenate([g[0] for g in groups]),
                      np.concatenate([g[1] for g in groups]))
    if len(groups) < 2:
        return float(value), np.nan, np.nan
    rng = np.random.default_rng(seed)
    draws = []
    for _ in range(resamples):
        pick = rng.integers(0, len(groups), len(groups))
        x = np.concatenate([groups[k][0] for k in pick])
        y = np.concatenate([groups[k][1] for k in pick])
        draws.append(statistic(x, y))
    draws = np.asarray(draws, float)
    draws = draws[np.isfinite(draws)]
    if not len(draws):
        return float(value), np.nan, np.nan
    tail = 100 * (1 - level) / 2
    return float(value), float(np.percentile(draws, tail)), float(np.percentile(draws, 100 - tail))


def stratified_bootstrap(strata, statistic, resamples=2000, level=0.95, seed=12345):
    """statistic(strata) over a list of strata (each a list of runs' point groups, such as the
    runs of one pore diameter) and its percentile interval over draws that resample the runs
    of each stratum with replacement within it, so that every draw keeps every stratum (the
    seeds of each diameter). `statistic` returns one value or a tuple of values; the result
    is a list of (value, low, high), one per value. Intervals are nan unless some stratum
    has two runs."""
    strata = [[(np.asarray(x, float), np.asarray(y, float)) for x, y in groups] for groups in strata]
    value = np.atleast_1d(np.asarray(statistic(strata), float))
    nan = [(float(v), np.nan, np.nan) for v in value]
    if not any(len(groups) > 1 for groups in strata):
        return nan
    rng = np.random.default_rng(seed)
    draws = np.asarray([np.atleast_1d(statistic([[groups[k] for k in rng.integers(0, len(groups), len(groups))]
                                                  for groups in strata]))
                        for _ in range(resamples)], float)
    tail = 100 * (1 - level) / 2
    out = []
    for v, column in zip(value, draws.T):
        column = column[np.isfinite(column)]
        out.append((float(v), float(np.percentile(column, tail)), float(np.percentile(column, 100 - tail)))
                   if len(column) else (float(v), np.nan, np.nan))
    return out


def fmt(value, low, high):
    """'1.15 [1.10, 1.20]' (95 % bootstrap interval), or 'n/a'."""
    if not np.isfinite(value):
        return "n/a"
    if not (np.isfinite(low) and np.isfinite(high)):
        return f"{value:.3g} [no interval: < 2 samples]"
    return f"{value:.3g} [{low:.3g}, {high:.3g}]"
