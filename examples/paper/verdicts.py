"""Each figure's criterion (doc/paper.md, "Criteria", written before the paper-size runs) and
its verdict on the figure's results.json (analyze.py). A verdict is one of

  meets / misses      the criterion applied to our numbers (with what missed)
  not judged          the criterion needs what the paper does not give in numbers
  no numbers          the study's runs give no figure to judge (none finished, too few)

and is 'provisional' while the study has fewer finished runs than it plans. The fits the
law-type figures are judged on are those the criteria name, on P - P_0 through 0 (the
pressure the deposit adds to the clean pore's, as K's force balance reads it: PAPER_NOTES,
"Fits through the origin on the total pressure loss are dominated by P_0").
"""
import math

import numpy as np

from fit_stats import fmt


def _value(triple):
    """The central value of a (value, low, high) triple, NaN where missing."""
    if not triple or triple[0] is None:
        return math.nan
    return float(triple[0])


def _fmt(triple):
    return fmt(*[math.nan if v is None else float(v) for v in triple]) if triple else "n/a"


def _judge(checks):
    """'meets', or 'misses: <what>' from (ok, what) pairs; None if any value is missing."""
    if any(ok is None for ok, _ in checks):
        return None
    missed = [what for ok, what in checks if not ok]
    return "meets" if not missed else "misses: " + "; ".join(missed)


def _within(value, centre, half_width):
    return None if not math.isfinite(value) else abs(value - centre) <= half_width


def _over(r):
    """' (intervals over one run's bursts)' where a law-type figure has a single run, whose
    bootstrap resamples bursts, not runs (figures/common.py, resampled); ' (intervals over N
    runs)' where it has only a few (a bootstrap over 2-4 runs has few distinct draws and is
    narrow by that alone)."""
    if r.get("intervals_over") == "bursts":
        return " (intervals over one run's bursts)"
    runs = r.get("finished") or 0
    return f" (intervals over {runs} runs)" if r.get("intervals_over") == "runs" and 1 < runs < 5 else ""


def porediameter(r):
    law = r.get("diameter_law", {})
    K, a = law.get("K"), law.get("a")
    k, e = _value(K), _value(a)
    per_D = law.get("runs_per_D", [])
    seeded = sum(n >= 2 for n in per_D)
    ours = (f"K {_fmt(K)}, exponent of D {_fmt(a)} (intervals over seeds"
            + (f"; two or more at {seeded} of {len(per_D)} diameters)" if seeded < len(per_D) else ")"))
    across = r.get("diameter_law_across_pore", {})
    if math.isfinite(_value(across.get("K"))):
        ours += f"; P across the pore, beside: K {_fmt(across['K'])}, exponent {_fmt(across['a'])}"
    if not math.isfinite(k):  # one diameter so far: its bursts' K, not yet the law over D
        ours = (f"K {_fmt(r.get('K_excess'))} over the bursts of {r.get('finished')} run(s); "
                "the law over D not yet")
    return ours, _judge([(_within(k, 0.91, 0.1), f"K {k:.3g} outside 0.91 +- 0.1"),
                         (_within(e, 1.0, 0.2), f"exponent {e:.3g} outside 1 +- 0.2")])


def _across_pore(r, name):
    """'; P across the pore, beside: <name> X, Pearson Y' where the results carry it
    (figures.common.across_pore_fits), else ''."""
    across = r.get("across_pore", {})
    if not math.isfinite(_value(across.get("excess_through_origin"))):
        return ""
    return f"; P across the pore, beside: {name} {_fmt(across['excess_through_origin'])}, Pearson {_fmt(across['pearson'])}"


def porelength(r):
    c, p = r.get("excess_coefficient"), r.get("pearson")
    ours = f"c {_fmt(c)} on P - P_0 through 0, Pearson {_fmt(p)}{_over(r)}{_across_pore(r, 'c')}"
    cv, pv = _value(c), _value(p)
    return ours, _judge([(_within(cv, 0.27, 0.05), f"c {cv:.3g} outside 0.27 +- 0.05"),
                         (None if not math.isfinite(pv) else pv >= 0.8, f"Pearson {pv:.3g} below 0.8")])


def dropvol(r):
    s, p = r.get("excess_through_origin"), r.get("pearson")
    ours = f"slope {_fmt(s)} per D^3 on P - P_0 through 0, Pearson {_fmt(p)}{_over(r)}{_across_pore(r, 'slope')}"
    sv, pv = _value(s), _value(p)
    return ours, _judge([(_within(sv, 1.15, 0.25), f"slope {sv:.3g} outside 1.15 +- 0.25"),
                         (None if not math.isfinite(pv) else 0.5 <= pv <= 0.9,
                          f"Pearson {pv:.3g} outside 0.5-0.9")])


def crossing(xs, ps, level):
    """The x at which P_max first reaches `level` along increasing x (linear between the
    points), None if it never does."""
    order = np.argsort(xs)
    xs, ps = np.asarray(xs, float)[order], np.asarray(ps, float)[order]
    for i in range(len(xs)):
        if ps[i] >= level:
            if i == 0:
                return float(xs[0])
            return float(xs[i - 1] + (level - ps[i - 1]) * (xs[i] - xs[i - 1]) / (ps[i] - ps[i - 1]))
    return None


def phaseac(r):
    """The contours' k_a at each k_c; 'no trend in k_c': the crossings at every k_c lie
    within a factor 2 of each other. Where the paper's contours lie it gives only as a
    picture, so that half of the criterion is not judged here."""
    points = r.get("points", [])
    by_kc = {}
    for pt in points:
        by_kc.setdefault(pt["y"], []).append((pt["x"], pt["P_max"]))
    parts, checks = [], []
    for level in (0.3, 0.6):
        found = {kc: crossing([x for x, _ in v], [p for _, p in v], level)
                 for kc, v in sorted(by_kc.items()) if len(v) >= 2}
        at = [ka for ka in found.values() if ka is not None and ka > 0]
        parts.append(f"{level} P_out at k_a " + (f"{min(at):.3g}-{max(at):.3g} over {len(at)} k_c"
                                                   if at else "never reached"))
        if len(at) >= 2:
            checks.append((max(at) / min(at) <= 2.0, f"the {level} contour's k_a varies by "
                                                      f"{max(at) / min(at):.2g} over k_c"))
    ours = "; ".join(parts)
    verdict = _judge(checks) if checks else None
    if verdict == "meets":
        verdict = "no trend in k_c; the contours' place in k_a not judged (the paper draws it only)"
    return ours, verdict


def spearman(x, y):
    """Spearman's rank correlation (average ranks for ties)."""
    def ranks(v):
        v = np.asarray(v, float)
        order = np.argsort(v, kind="mergesort")
        rank = np.empty(len(v))
        rank[order] = np.arange(len(v), dtype=float)
        for value in np.unique(v):
            tied = v == value
            rank[tied] = rank[tied].mean()
        return rank
    if len(x) < 3:
        return math.nan
    rx, ry = ranks(x), ranks(y)
    if np.ptp(rx) == 0 or np.ptp(ry) == 0:
        return math.nan
    return float(np.corrcoef(rx, ry)[0, 1])


def phasead(r):
    points = r.get("points", [])
    rho = spearman([pt["y"] for pt in points], [pt["P_max"] for pt in points])
    ours = f"Spearman of P_max with d / D: {rho:.2f} over {len(points)} runs" if math.isfinite(rho) \
        else f"{len(points)} runs"
    return ours, _judge([(None if not math.isfinite(rho) else rho > 0,
                          f"P_max falls with d / D (Spearman {rho:.2f})")])


def conc(r):
    onset = r.get("onset")
    ours = f"onset at C_in {onset}" if onset is not None else "no bursts at any C_in"
    ok = None if onset is None else 0.013 / 2 <= float(onset) <= 0.013 * 2
    return ours, _judge([(ok, f"onset {onset} outside 0.0065-0.026")])


def pvpflux(r):
    threshold = r.get("threshold")
    ours = f"particle flux from P {threshold} P_out" if threshold is not None else "no particle flux"
    ok = None if threshold is None else abs(float(threshold) - 0.35) <= 0.1
    return ours, _judge([(ok, f"threshold {threshold} outside 0.35 +- 0.1")])


def shown(r):
    """The figures the paper draws without a number to meet (one burst, the snapshots)."""
    return r.get("ours", ""), "not judged"


# What the paper gives for each figure (references.md, PAPER_NOTES).
PAPER = dict(singlejump="a fall by Delta P within Delta t (a curve)",
             collection="three snapshots: before deposition, at a peak, after the burst",
             dropvol="slope 1.15(1) per D^3, Pearson 0.71(1)",
             porelength="c 0.27(1), Pearson 0.91(1)",
             porediameter="K 0.91 +- 0.04, exponent of D 1",
             phaseac="contours 0.3, 0.6 P_out: k_a decides within a decade, k_c over decades not",
             phasead="P_max rises with d / D",
             conc="onset of clogging at C_in ~ 0.013",
             pvpflux="particle flux from P ~ 0.35 P_out")

JUDGES = dict(singlejump=shown, collection=shown, dropvol=dropvol, porelength=porelength,
              porediameter=porediameter, phaseac=phaseac, phasead=phasead, conc=conc,
              pvpflux=pvpflux)


def verdict(figure, results, finished, planned):
    """(ours, verdict) of a figure's results.json with `finished` of `planned` runs done."""
    if finished == 0:
        return "", "no numbers: no run finished"
    if not results:
        return "", "no numbers: not analysed yet (analyze.py)"
    ours, judged = JUDGES[figure](results)
    judged = judged or "no numbers: too few runs for the figure"
    if finished < planned:
        judged = f"provisional ({finished} of {planned} runs): {judged}"
    return ours, judged
