"""The analyses' fits on synthetic data with known answers (ctest paper_fits): the fit
functions of examples/paper/fit_stats.py, and the figures' fits on runs written here (thermo
rows of a warm-up and burst rows) whose peaks are P = P_0 + c x exactly, so that each fit
must return what it is defined to measure:
  - through the origin on P: c + P_0 / x weighted, not c (what the old fits reported);
  - through the origin on P - P_0 (P_0 read from each run's own warm-up): c;
  - with an intercept: c and P_0.
Also the V_dep units of dropvol (per D^3 and per pore volume), the bootstrap's interval, and
the study runner's check of knobs against its study's copy of in.pore.

Usage: test_fits.py <source root>   (or python3 -m unittest with LBM_PORE_REPO set)
"""
import json
import math
import os
import random
import sys
import tempfile
import unittest

REPO = os.environ.get("LBM_PORE_REPO") or (sys.argv.pop(1) if len(sys.argv) > 1 else
                                           os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "examples", "paper"))

import numpy as np  # noqa: E402

import fit_stats  # noqa: E402
from figures import common, dropvol  # noqa: E402

# As LIGGGHTS prints the header of in.pore's thermo_style (f_ and c_ dropped).
HEADER = ("Step Atoms pore[1] pore[6] pore[7] pore[8] pore[4] pore[5] pore[10] bonds walls[1] "
          "pore[16] pore[17] pore[18]")


def write_run(folder, p0, bursts, warmup=2000, D=3.5, Lp=4.25, deposits=None, extra=()):
    """A finished run: a log whose warm-up rows hold P / P_out = p0 (after a start-up
    overshoot), and a burst file with the given (V_dep, L_dep, P_peak) rows; with `deposits`
    (count, V, L per burst: the deposit before the peak) in today's columns, else in those
    written before the records carried it. `extra`: more thermo columns (as thermo_extra
    adds them), each the step times its position."""
    os.makedirs(folder)
    names = HEADER.split() + list(extra)
    with open(os.path.join(folder, "log.liggghts"), "w") as f:
        f.write("fix lbm/pore: ... dt_lbm = 1 (n_dem = 100 x dt_dem = 0.01), dx = 0.140845\n")
        f.write(" ".join(names) + "\n")
        for step in range(0, 2 * warmup + 1, 100):
            p = 3.0 * p0 if step < warmup / 2 else p0  # the overshoot must not enter P_0
            row = {name: step * (k + 1.0) for k, name in enumerate(extra)}
            row.update(dict.fromkeys(HEADER.split(), 0.0))
            row.update({"Step": step, "pore[16]": p, "pore[17]": 3.0 * p0})
            f.write(" ".join(f"{row[n]:.12g}" for n in names) + "\n")
    with open(os.path.join(folder, "bursts.txt"), "w") as f:
        f.write("# step time P_peak P_after delta_P delta_t V_dep L_dep count_before count_after "
                "wall_F on_wall P_pi_D2_4" + (" deposit_count deposit_V deposit_L" if deposits else "") + "\n")
        for k, (v, length, p) in enumerate(bursts):
            extra = " ".join(map(repr, deposits[k])) if deposits else ""
            f.write(f"{10000 + 100 * k} 0 {p!r} {0.5 * p!r} {0.5 * p!r} 1 {v!r} {length!r} 5 2 -1 3 1 {extra}\n")
    return dict(name=os.path.basename(folder), state="done", folder=folder,
                knobs=dict(warmup=str(warmup), D=str(D), Lp=str(Lp)))


class FitFunctions(unittest.TestCase):
    def test_exact_lines(self):
        x = np.array([0.5, 1.0, 2.0, 3.0])
        self.assertAlmostEqual(fit_stats.slope_through_origin(x, 2.0 * x), 2.0, places=12)
        self.assertAlmostEqual(fit_stats.slope(x, 0.3 + 1.5 * x), 1.5, places=12)
        self.assertAlmostEqual(fit_stats.intercept(x, 0.3 + 1.5 * x), 0.3, places=12)
        self.assertAlmostEqual(fit_stats.pearson(x, 0.3 + 1.5 * x), 1.0, places=12)
        # Through the origin, a line with an intercept is not its slope: c + a sum(x) / sum(x^2).
        expected = 1.5 + 0.3 * x.sum() / (x @ x)
        self.assertAlmostEqual(fit_stats.slope_through_origin(x, 0.3 + 1.5 * x), expected, places=12)

    def test_degenerate_inputs_give_nan(self):
        for f in (fit_stats.slope, fit_stats.intercept, fit_stats.pearson):
            self.assertTrue(math.isnan(f(np.array([1.0, 1.0]), np.array([2.0, 3.0]))))
        self.assertTrue(math.isnan(fit_stats.slope_through_origin(np.zeros(3), np.ones(3))))

    def test_bootstrap_of_exact_data_has_no_spread_and_of_noisy_data_covers_the_truth(self):
        x = [np.array([1.0, 2.0]), np.array([0.5, 3.0]), np.array([1.5, 2.5])]
        groups = [(xi, 0.7 * xi) for xi in x]
        value, low, high = fit_stats.bootstrap(groups, fit_stats.slope_through_origin)
        self.assertAlmostEqual(value, 0.7, places=12)
        self.assertAlmostEqual(low, 0.7, places=12)
        self.assertAlmostEqual(high, 0.7, places=12)
        rng = random.Random(7)
        noisy = []
        for _ in range(30):
            xi = np.array([rng.uniform(0.2, 2.0) for _ in range(4)])
            noisy.append((xi, 0.7 * xi + np.array([rng.gauss(0, 0.05) for _ in range(4)])))
        value, low, high = fit_stats.bootstrap(noisy, fit_stats.slope_through_origin)
        self.assertLess(low, 0.7)
        self.assertGreater(high, 0.7)
        self.assertLess(high - low, 0.1)
        one = fit_stats.bootstrap(groups[:1], fit_stats.slope_through_origin)
        self.assertTrue(math.isnan(one[1]) and math.isnan(one[2]))


class FiguresCompareLikeWithLike(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.c = 0.95
        self.runs = []
        # Two runs with different clean losses; peaks P = P_0 + c L_dep exactly.
        for k, (p0, lengths) in enumerate(((0.08, [0.05, 0.4, 1.2]), (0.06, [0.1, 0.9, 2.0]))):
            rows = [(length * math.pi * 3.5 ** 2 / 4, length, p0 + self.c * length) for length in lengths]
            self.runs.append(write_run(os.path.join(self.tmp.name, f"run{k}"), p0, rows))
        self.summary = dict(runs=self.runs, finished=len(self.runs), study="porelength", size="tiny",
                            core_hours=0.0)

    def tearDown(self):
        self.tmp.cleanup()

    def test_clean_pressure_is_the_end_of_the_warm_up(self):
        self.assertAlmostEqual(common.clean_pressure(self.runs[0]), 0.08, places=12)
        self.assertAlmostEqual(common.clean_pressure(self.runs[1]), 0.06, places=12)

    def test_the_three_fits_measure_what_they_say(self):
        fits = common.pressure_fits(self.summary, lambda run, b: b["L_dep"], deposit="median")
        self.assertAlmostEqual(fits["excess_through_origin"][0], self.c, places=9)
        self.assertAlmostEqual(fits["excess_through_origin"][1], self.c, places=9)  # no spread
        # Through the origin on P, the clean loss inflates the slope.
        x = np.array([0.05, 0.4, 1.2, 0.1, 0.9, 2.0])
        p = np.array([0.08] * 3 + [0.06] * 3) + self.c * x
        self.assertAlmostEqual(fits["through_origin"][0], float(x @ p / (x @ x)), places=9)
        self.assertGreater(fits["through_origin"][0], self.c + 0.02)
        # A line with an intercept over both runs: slope c within the P_0 spread, intercept
        # between the two clean losses.
        self.assertAlmostEqual(fits["slope"][0], float(np.polyfit(x, p, 1)[0]), places=9)
        self.assertTrue(0.06 <= fits["intercept"][0] <= 0.08)
        self.assertAlmostEqual(fits["pearson"][0], float(np.corrcoef(x, p)[0, 1]), places=9)

    def test_dropvol_units(self):
        D, L = 3.5, 4.25
        burst = dict(deposit_V=2.0 * D ** 3)
        run = self.runs[0]
        self.assertAlmostEqual(dropvol.per_cube_of_diameter(run, burst), 2.0, places=12)
        self.assertAlmostEqual(dropvol.per_pore_volume(run, burst), 2.0 * D ** 3 / (math.pi * D * D * L / 4),
                               places=12)
        # V_dep = L_dep pi D^2 / 4, so V_dep / D^3 = L_dep pi / (4 D) and against P - P_0 the
        # slope is c 4 D / pi.
        fits = common.pressure_fits(self.summary, dropvol.per_cube_of_diameter, deposit="median")
        self.assertAlmostEqual(fits["excess_through_origin"][0], 4 * self.c * D / math.pi, places=9)

    def test_one_run_resamples_its_bursts_and_says_so(self):
        """A paper-length run is one run: its intervals come from its bursts, and the text
        says so; two runs resample whole runs."""
        self.assertEqual(common.pressure_fits(self.summary, lambda run, b: b["L_dep"])["unit"], "runs")
        rng = random.Random(11)
        rows = []
        for _ in range(40):
            length = rng.uniform(0.2, 2.0)
            rows.append((length, length, 0.07 + self.c * length + rng.gauss(0, 0.05)))
        one = write_run(os.path.join(self.tmp.name, "one"), 0.07, rows)
        summary = dict(self.summary, runs=[one], finished=1)
        fits = common.pressure_fits(summary, lambda run, b: b["L_dep"], deposit="median")
        self.assertEqual(fits["unit"], "bursts")
        value, low, high = fits["excess_through_origin"]
        self.assertLess(low, self.c)
        self.assertGreater(high, self.c)
        self.assertLess(high - low, 0.1)
        self.assertTrue(low < value < high)
        self.assertIn("over the bursts of one run", common.fits_text(fits))
        # One burst alone has no interval.
        lone = write_run(os.path.join(self.tmp.name, "lone"), 0.07, rows[:1])
        fits = common.pressure_fits(dict(self.summary, runs=[lone], finished=1), lambda run, b: b["L_dep"], deposit="median")
        self.assertTrue(math.isnan(fits["through_origin"][1]))

    def test_figure_results_name_all_three_fits(self):
        from figures import porelength
        out = os.path.join(self.tmp.name, "out")
        os.makedirs(out)
        r = porelength.analyze(self.summary, out)
        # the synthetic runs' thermo rows hold no deposit: the records' median measures them
        self.assertAlmostEqual(r["deposit_median"]["excess_through_origin"][0], self.c, places=9)
        for words in ("through 0", "P - P_0", "intercept"):
            self.assertIn(words, r["ours"])
        self.assertTrue(os.path.getsize(r["plot"]) > 5000)


class BurstDeposit(unittest.TestCase):
    """A burst's deposit is counted over the fluid steps before its peak: at the peak itself
    the deposit has begun to slide and its particles drop out of the count one by one."""

    def test_the_deposit_before_the_peak_not_at_it(self):
        from figures import calibration
        # A deposit of 29 built by step 9000, flickering to 27 now and then, sliding from step
        # 9800 on (counted 12, then 2 at the peak, 10 000).
        steps = list(range(0, 10001, 100))
        counts = [min(29, s // 300) for s in steps]
        counts = [27 if (s % 700 == 0 and c == 29) else c for s, c in zip(steps, counts)]
        counts[-3:] = [12, 5, 2]
        columns = {"Step": steps, "pore[7]": counts}
        self.assertEqual(calibration.deposit_before(columns, 10000, 1000), 29)
        self.assertEqual(counts[-1], 2)  # what the record's count at the peak says
        self.assertEqual(calibration.deposit_before(columns, 3000, 600), 9)  # median of 8, 9, 9, ...
        self.assertIsNone(calibration.deposit_before(columns, 50, 0))

    def test_the_record_deposit_is_what_the_analyses_take(self):
        """A record that carries the deposit before the peak: the calibration counts it and the
        fits take its L_dep, not the peak's (whose deposit has slid); a record written before
        falls back to the thermo rows (which hold no deposit here: 0)."""
        from figures import calibration, porelength
        with tempfile.TemporaryDirectory() as tmp:
            c, p0 = 0.95, 0.08
            lengths = [0.4, 1.2, 2.0]
            peaks = [(0.01, 0.02, p0 + c * length) for length in lengths]  # slid: tiny at the peak
            deposits = [(29, length * math.pi * 3.5 ** 2 / 4, length) for length in lengths]
            today = write_run(os.path.join(tmp, "today"), p0, peaks, deposits=deposits)
            before = write_run(os.path.join(tmp, "before"), p0, peaks)
            columns = common.thermo(today["folder"])
            self.assertEqual([b["deposit"] for b in calibration.bursts_with_deposits(today, columns)], [29] * 3)
            self.assertEqual([b["deposit"] for b in calibration.bursts_with_deposits(before, columns)], [0] * 3)
            summary = dict(runs=[today], finished=1, study="porelength", size="tiny", core_hours=0.0)
            out = os.path.join(tmp, "out")
            os.makedirs(out)
            median = porelength.analyze(summary, out)["deposit_median"]
            self.assertAlmostEqual(median["excess_through_origin"][0], c, places=9)


def sliding_deposit(peak, full, window=100000, step=1000):
    """(DEM step, deposited count) rows every `step` DEM steps: a deposit of `full` particles
    held until 80 % of the window before the peak, then sliding out one particle per row,
    down to 1 at the peak. Its V_dep is count / 2, its L_dep count / 20."""
    rows = []
    for s in range(peak - 2 * window, peak + 1, step):
        n = full if s < peak - 0.8 * window else max(1, full - (s - (peak - 0.8 * window)) // step)
        rows.append((s, int(n)))
    return rows


def add_sliding_deposits(run, peaks, fulls, p0):
    """Moves a write_run run's bursts to `peaks` (window 10^5 DEM steps at its n_dem 100) and
    appends thermo rows in which a deposit of each `fulls` slides out before its peak."""
    with open(os.path.join(run["folder"], "bursts.txt")) as f:
        head, *lines = f.read().splitlines()
    with open(os.path.join(run["folder"], "bursts.txt"), "w") as f:
        f.write(head + "\n" + "".join(f"{peak} " + line.split(" ", 1)[1] + "\n"
                                       for peak, line in zip(peaks, lines)))
    names = HEADER.split()
    with open(os.path.join(run["folder"], "log.liggghts"), "a") as f:
        for peak, full in zip(peaks, fulls):
            for step, n in sliding_deposit(peak, full)[100:]:
                row = dict.fromkeys(names, 0.0)
                row.update({"Step": step, "pore[16]": p0, "pore[17]": p0, "pore[7]": n,
                            "pore[6]": n / 2, "pore[8]": n / 20})
                f.write(" ".join(f"{row[k]:.12g}" for k in names) + "\n")


class LargestDepositInTheWindow(unittest.TestCase):
    """Beside the record's median, the largest deposit in the burst window: a deposit that
    slid out of the count for more than half of the window is lost by the median and kept by
    the largest, with the V_dep and L_dep of the same thermo row."""

    def test_the_largest_keeps_a_deposit_the_median_loses(self):
        from figures import calibration
        rows = sliding_deposit(300000, 29)
        columns = {"Step": [s for s, _ in rows], "pore[7]": [n for _, n in rows],
                   "pore[6]": [n / 2 for _, n in rows], "pore[8]": [n / 20 for _, n in rows]}
        self.assertLess(calibration.deposit_before(columns, 300000, 100000), 10)
        self.assertEqual(common.largest_deposit_before(columns, 300000, 100000), (29, 14.5, 1.45))
        self.assertIsNone(common.largest_deposit_before(columns, 10 ** 7, 100))  # no row in the window
        del columns["pore[6]"]
        count, v, length = common.largest_deposit_before(columns, 300000, 100000)
        self.assertEqual((count, length), (29, 1.45))
        self.assertTrue(math.isnan(v))

    def test_fits_on_the_largest_deposit_measure_what_they_say(self):
        """Peaks on P = P_0 + c L exactly for the full deposits, records carrying the slid
        medians: the fit on the largest deposit returns c, the records' does not."""
        c, p0, peaks = 0.95, 0.08, (300000, 700000, 1100000)
        fulls = (12, 21, 33)
        with tempfile.TemporaryDirectory() as tmp:
            lengths = [n / 20 for n in fulls]
            run = write_run(os.path.join(tmp, "run"), p0, [(0.5, 0.05, p0 + c * x) for x in lengths],
                            deposits=[(3, 0.5, 0.05)] * 3)
            add_sliding_deposits(run, peaks, fulls, p0)
            summary = dict(runs=[run], finished=1, study="porelength", size="tiny", core_hours=0.0)
            largest = common.pressure_fits(summary, lambda r, b: b["deposit_L"], deposit="largest")
            self.assertAlmostEqual(largest["excess_through_origin"][0], c, places=9)
            self.assertAlmostEqual(largest["pearson"][0], 1.0, places=9)
            median = common.pressure_fits(summary, lambda r, b: b["deposit_L"], deposit="median")
            self.assertTrue(math.isnan(median["pearson"][0]))  # every record says 0.05: no spread
            from figures import calibration
            rows = calibration.bursts_with_deposits(run, common.thermo(run["folder"]))
            self.assertEqual([b["largest"] for b in rows], list(fulls))
            law = calibration.burst_law(rows, 3.5, [p0] * 3)
            self.assertAlmostEqual(law["K_largest"][0], c * 3.5, places=9)
            with self.assertRaises(ValueError):
                common.pressure_fits(summary, lambda r, b: b["deposit_L"], deposit="mean")


class CompactedEvidence(unittest.TestCase):
    """A study compacted for the repository (compact_study.py) reads back as the study: the
    same summary, time steps, thermo columns and fits, so that doc/'s figures can be drawn
    again from the evidence alone."""

    def test_the_compacted_folder_gives_the_study_s_fits(self):
        import json
        import compact_study
        import study_io
        with tempfile.TemporaryDirectory() as tmp:
            study = os.path.join(tmp, "study")
            p0, c = 0.07, 0.9
            lengths = [0.3, 0.8, 1.5, 2.1]
            run = write_run(os.path.join(study, "runs", "run0"), p0,
                            [(x * 9.6, x, p0 + c * x + 0.01 * k) for k, x in enumerate(lengths)],
                            deposits=[(10 * k, x * 9.6, x) for k, x in enumerate(lengths)])
            add_sliding_deposits(run, (300000, 700000, 1100000, 1500000), (12, 30, 21, 33), p0)
            knobs = dict(run["knobs"], cells_per_d="7.1")
            with open(os.path.join(run["folder"], "knobs.json"), "w") as f:
                json.dump(knobs, f)
            with open(os.path.join(study, "summary.txt"), "w") as f:
                f.write("study porelength (tiny, pool): 1 finished, 0 failed, 0 incomplete of 1\n")
            evidence = os.path.join(tmp, "evidence")
            compact_study.compact(study, evidence)
            self.assertFalse(os.path.exists(os.path.join(evidence, "runs", "run0", "log.liggghts")))
            summary = study_io.load_summary(evidence)
            self.assertEqual((summary["study"], summary["size"]), ("porelength", "tiny"))
            kept, = summary["runs"]
            self.assertEqual(kept["knobs"], knobs)
            self.assertEqual(kept["state"], "incomplete")  # write_run's log has no end mark
            for key, value in study_io.lattice_timing(run["folder"]).items():
                self.assertAlmostEqual(study_io.lattice_timing(kept["folder"])[key], value, places=5)
            # The kept rows are the study's (every 10th, and all of a burst's window: 10^5 DEM
            # steps before the peak to half of that after).
            original, compacted = common.thermo(run["folder"]), common.thermo(kept["folder"])
            index = [original["Step"].index(step) for step in compacted["Step"]]
            # whole numbers (steps, counts) exactly, the rest to compact_study.KEPT_DIGITS
            for name, values in compacted.items():
                np.testing.assert_allclose(values, np.asarray(original[name])[index],
                                           rtol=0.5 * 10.0 ** (1 - compact_study.KEPT_DIGITS))
            self.assertEqual(compacted["Step"], [original["Step"][i] for i in index])
            self.assertEqual(compact_study.kept_value(100200000.0), "100200000")
            self.assertEqual(compact_study.kept_value(0.123456789), "0.123457")
            in_windows = [step for step in original["Step"] if any(-1e5 <= step - p <= 5e4 for p in
                                                                   (300000, 700000, 1100000, 1500000))]
            self.assertTrue(set(in_windows) <= set(compacted["Step"]))
            self.assertLess(len(compacted["Step"]), len(original["Step"]))
            kept["state"] = "done"
            full = dict(runs=[dict(run, knobs=knobs)], finished=1, study="porelength", size="tiny", core_hours=0.0)
            # analyze.py on the evidence, its results elsewhere: the evidence stays as it was.
            import analyze
            before = sorted(os.listdir(evidence))
            redrawn = os.path.join(tmp, "redrawn")
            result = analyze.analyze(evidence, figure="porelength", as_it_stands=True, out=redrawn)
            self.assertEqual(sorted(os.listdir(evidence)), before)
            with open(os.path.join(redrawn, "results.json")) as f:  # the study's own figure
                self.assertEqual(json.load(f)["plot"], "porelength.png")  # no machine path
            self.assertEqual(result["as_it_stands"], ["run0"])
            for deposit in ("median", "largest"):
                a = common.pressure_fits(full, lambda r, b: b["deposit_L"], deposit=deposit)
                b = common.pressure_fits(summary, lambda r, b: b["deposit_L"], deposit=deposit)
                for key in ("excess_through_origin", "pearson"):
                    self.assertTrue(np.isfinite(a[key][0]))
                    self.assertAlmostEqual(a[key][0], b[key][0], places=6)


    def test_the_columns_a_run_asked_for_are_kept(self):
        """pvpflux reads its fluxes and inlet velocity, conc the volume through the inlet
        plane: columns its runs add with thermo_extra, which the compact result keeps beside
        the fixed ones (and those of a run that did not ask, it drops)."""
        import json
        import compact_study
        self.assertEqual(compact_study.asked_columns(dict(thermo_extra="f_pore[3] f_pore[13] v_u_in c_bonds")),
                         ("pore[3]", "pore[13]", "u_in", "bonds"))
        self.assertEqual(compact_study.asked_columns({}), ())
        with tempfile.TemporaryDirectory() as tmp:
            extra = ("pore[3]", "pore[13]", "pore[37]")
            for name, asked in (("asked", "f_pore[3] f_pore[13] f_pore[37]"), ("not_asked", "")):
                run = write_run(os.path.join(tmp, "study", "runs", name), 0.05, [(1.0, 0.5, 0.2)], extra=extra)
                with open(os.path.join(run["folder"], "knobs.json"), "w") as f:
                    json.dump(dict(run["knobs"], cells_per_d="7.1", thermo_extra=asked), f)
            compact_study.compact(os.path.join(tmp, "study"), os.path.join(tmp, "evidence"))
            kept = common.thermo(os.path.join(tmp, "evidence", "runs", "asked"))
            original = common.thermo(os.path.join(tmp, "study", "runs", "asked"))
            index = [original["Step"].index(step) for step in kept["Step"]]
            for name in extra:
                np.testing.assert_allclose(kept[name], np.asarray(original[name])[index], rtol=1e-5)
            self.assertIn("pore[16]", kept)
            dropped = common.thermo(os.path.join(tmp, "evidence", "runs", "not_asked"))
            self.assertFalse(set(extra) & set(dropped))
            self.assertIn("pore[16]", dropped)

    def test_the_forces_are_kept_in_the_bursts_windows_only(self):
        """The forces on the deposit and on all particles are read at a burst's peak: the
        compact result keeps them in the bursts' windows (10^5 DEM steps before a peak to half
        of that after) and leaves them blank between, read back as NaN; the pressures and
        counts stay in every kept row. A run kept before with them in every row, rewritten by
        blank_between_bursts, is byte for byte what compact_run writes now."""
        import json
        import compact_study
        with tempfile.TemporaryDirectory() as tmp:
            forces = ("walls[2]", "pore[35]")
            run = write_run(os.path.join(tmp, "study", "runs", "run0"), 0.05, [(1.0, 0.5, 0.2), (2.0, 0.9, 0.3)],
                            warmup=100000, extra=forces)  # rows to DEM step 2e5, bursts at 1e4, 1.01e4
            with open(os.path.join(run["folder"], "knobs.json"), "w") as f:
                json.dump(dict(run["knobs"], cells_per_d="7.1"), f)
            kept_run = os.path.join(tmp, "evidence", "runs", "run0")
            compact_study.compact(os.path.join(tmp, "study"), os.path.join(tmp, "evidence"))
            original, kept = common.thermo(run["folder"]), common.thermo(kept_run)
            index = [original["Step"].index(step) for step in kept["Step"]]
            inside = np.array([-1e5 <= s - p <= 5e4 for s in kept["Step"] for p in (10100,)])
            self.assertTrue(inside.any() and (~inside).any())
            for name in forces:
                values = np.asarray(kept[name])
                np.testing.assert_allclose(values[inside], np.asarray(original[name])[index][inside], rtol=1e-5)
                self.assertTrue(np.isnan(values[~inside]).all())
            for name in ("Step", "pore[16]", "pore[7]"):
                self.assertTrue(np.isfinite(kept[name]).all())
            with open(os.path.join(kept_run, "thermo.csv.gz"), "rb") as f:
                now = f.read()
            # as a compaction that kept every column in every row wrote it
            compact_study.write_kept_thermo(kept_run, list(kept), original, index, lambda i: True)
            self.assertFalse(np.isnan(common.thermo(kept_run)["walls[2]"]).any())
            compact_study.blank_between_bursts(kept_run)
            with open(os.path.join(kept_run, "thermo.csv.gz"), "rb") as f:
                self.assertEqual(f.read(), now)


class TimeMeans(unittest.TestCase):
    """Means over time from a compact result, which keeps every row of the bursts' windows and
    every tenth elsewhere, equal the full log's: rows weigh the time they stand for."""

    def test_the_compacted_rows_give_the_full_rows_time_mean(self):
        from figures import calibration
        t = np.arange(0.0, 10000.0, 1.0)
        y = np.where((t % 1000) > 900, 30.0, 2.0)  # a high count in each burst's window
        kept = (np.arange(len(t)) % 10 == 0) | ((t % 1000) > 850)
        self.assertGreater(abs(np.mean(y[kept]) - np.mean(y)), 2.0)  # the plain mean is biased
        self.assertAlmostEqual(common.time_mean(t[kept], y[kept]), np.mean(y), delta=0.05)
        self.assertAlmostEqual(common.time_mean(t, y), np.mean(y), delta=0.01)  # the ends weigh half
        mean, low, high = calibration.block_mean(t[kept], y[kept], np.random.default_rng(1))
        self.assertAlmostEqual(mean, np.mean(y), delta=0.05)
        self.assertLessEqual(low, mean)
        self.assertGreaterEqual(high, mean)
        self.assertEqual(common.time_mean([5.0], [3.0]), 3.0)
        self.assertTrue(np.isnan(common.time_mean([], [])))


class BurstLaw(unittest.TestCase):
    """The calibration's check of the paper's law of the bursts, P = K L_dep / D, on bursts
    whose peaks lie exactly on P = P_0 + K L_dep / D: K on P - P_0 is K, through the origin on
    P it is inflated by P_0, and the deposit's L_dep comes from the thermo rows before the peak
    when the record predates the deposit columns."""

    def test_K_of_exact_bursts_and_the_deposit_length_before_the_peak(self):
        from figures import calibration
        K, p0, D = 0.91, 0.02, 3.5
        rows = [dict(P_peak=p0 + K * length / D, deposit_L=length) for length in (0.5, 1.0, 1.5, 2.2)]
        law = calibration.burst_law(rows, D, [p0] * len(rows))
        self.assertEqual(law["bursts"], 4)
        for value in law["K"]:
            self.assertAlmostEqual(value, K, places=12)  # exact points: no spread over bursts
        self.assertGreater(law["K_total"][0], K + 0.01)
        self.assertAlmostEqual(law["pearson"][0], 1.0, places=12)
        with tempfile.TemporaryDirectory() as tmp:
            run = write_run(os.path.join(tmp, "run"), p0, [(0.01, 0.02, 0.3)])  # slid: L_dep 0.02 at the peak
            columns = {"Step": [9000, 9500, 9800, 9900, 10000], "pore[7]": [20, 21, 21, 21, 2],
                       "pore[8]": [1.3, 1.4, 1.4, 1.4, 0.1]}
            row, = calibration.bursts_with_deposits(run, columns)
            self.assertEqual((row["deposit"], row["deposit_L"]), (21, 1.4))


class TwinStatistics(unittest.TestCase):
    """What the N_DEM and resolution comparisons report per run: deposit sizes and pressures
    after the warm-up only, the deposits the bursts tore off and the wall's hold per deposited
    particle touching it at the peaks."""

    def test_statistics_of_a_known_run(self):
        from figures import calibration
        with tempfile.TemporaryDirectory() as tmp:
            # Bursts at DEM steps 10 000 and 10 100 (time 100 and 101), deposits of 20 and 24,
            # each record's wall force -1 on 3 deposited particles touching the wall.
            run = write_run(os.path.join(tmp, "run"), 0.05, [(9.0, 1.2, 0.30), (11.0, 1.4, 0.33)],
                            deposits=[(20, 9.0, 1.2), (24, 11.0, 1.4)])
            steps = np.arange(0, 12001, 100)
            count = np.where(steps < 2000, 40, np.minimum(steps // 500, 17))  # the warm-up's 40 must not count
            pressure = np.where(steps < 2000, 0.9, 0.05 + 0.28 * (steps == 10000))
            columns = {"Step": list(steps), "pore[7]": list(count), "pore[16]": list(pressure)}
            times = (steps * 0.01, 20.0, columns)
            stats = calibration.twin_statistics(run, times, np.random.default_rng(1), until=1000.0)
        self.assertEqual(stats["largest"], 17)
        self.assertAlmostEqual(stats["P_max"], 0.33, places=12)
        self.assertAlmostEqual(stats["hold"], 1.0 / 3.0, places=12)
        self.assertAlmostEqual(stats["peak_count"], 22.0, places=12)
        self.assertAlmostEqual(stats["peak_P"], 0.315, places=12)
        row = calibration.twin_row("run", "5 cells/d", stats)
        self.assertEqual(row.count("|"), calibration.TWIN_HEADER[1].count("|"))
        self.assertIn("| 17 | 0.330 |", row)


class CalibrationTable(unittest.TestCase):
    def test_runs_not_yet_made_are_listed_in_one_line(self):
        """A study run in parts (the paper-length run is one of 24) lists its other runs once,
        not as 23 rows of dashes."""
        from figures import calibration
        base = dict(u=0.0025, n_dem=100, cells_per_d=7.1)
        made = dict(base, name="u_0.0025_seed_100003", state="done", reason="", fluid_steps=10 ** 6,
                    count=39, V_dep=20.7, P0=0.009, P_max=0.357, bursts=1, peaks=[(0.35, 30)], hold=0.7,
                    mach=0.19, inlet=0.97, K=(0.6, 0.5, 0.7), pearson=(0.9, 0.8, 1.0))
        waiting = [dict(base, name=f"u_0.0025_seed_{s}", state="incomplete") for s in (1, 2)]
        text = calibration.table([waiting[0], made, waiting[1]])
        self.assertEqual(sum(1 for line in text.splitlines() if line.startswith("| u_")), 1)
        self.assertIn("| 0.357 | 1 (0.35: 30) |", text)
        self.assertIn("Without a thermo row yet (2): u_0.0025_seed_1, u_0.0025_seed_2.", text)


class AnalysisAsItStands(unittest.TestCase):
    def test_runs_under_way_are_taken_only_when_asked_and_named(self):
        import analyze
        with tempfile.TemporaryDirectory() as tmp:
            done = write_run(os.path.join(tmp, "runs", "done"), 0.05, [(1.0, 0.5, 0.2)])
            going = write_run(os.path.join(tmp, "runs", "going"), 0.05, [(2.0, 1.0, 0.4)])
            going["state"] = "incomplete"
            waiting = dict(name="waiting", state="incomplete", folder=os.path.join(tmp, "runs", "waiting"))
            summary = dict(runs=[done, going, waiting], finished=1)
            self.assertEqual(len(common.finished_runs(summary)), 1)
            self.assertEqual(analyze.take_runs_as_they_stand(summary, tmp), ["going"])
            self.assertEqual([r["name"] for r in common.finished_runs(summary)], ["done", "going"])
            self.assertEqual(summary["finished"], 2)


class StudyScene(unittest.TestCase):
    """A study resumed after in.pore gained a knob keeps its old copy of in.pore, which would
    take the knob and ignore it: run_study refuses such a run (ensemble.unknown_knobs)."""

    def test_knobs_the_scene_does_not_define_are_named(self):
        import ensemble
        with tempfile.TemporaryDirectory() as tmp:
            scene = os.path.join(tmp, "in.pore")
            with open(scene, "w") as f:
                f.write("variable  seed index 1\nvariable  u_lattice index 0.02   # comment\n"
                        "variable  dx equal 1.0/7.1\n")
            self.assertEqual(ensemble.unknown_knobs(scene, {"seed": 3, "u_lattice": 0.01}), [])
            self.assertEqual(ensemble.unknown_knobs(scene, {"seed": 3, "min_gap": 0.25, "dx": 1}),
                             ["dx", "min_gap"])
        # The repository's scene defines every knob of every study.
        import studies
        scene = os.path.join(REPO, "examples", "pore", "in.pore")
        for study in studies.STUDIES:
            for size in ("tiny", "quick", "paper"):
                for name, knobs in studies.runs_of(study, size):
                    self.assertEqual(ensemble.unknown_knobs(scene, knobs), [], f"{study} {size} {name}")


class PaperSizePlan(unittest.TestCase):
    """The paper size runs what doc/paper.md's criteria need, on seeds no example, calibration
    or settings run uses, the phase diagrams at their shorter length."""

    def test_counts_seeds_and_lengths(self):
        import studies
        used = {100003, 101009, 200003, 201007, 202021, 203011, 204007, 300007, 300017}
        counts = dict(porediameter=8, porelength=6, dropvol=2, phaseac=9, phasead=6, conc=6, pvpflux=6)
        for study, count in counts.items():
            runs = studies.runs_of(study, "paper")
            self.assertEqual(len(runs), count, study)
            for name, knobs in runs:
                self.assertNotIn(int(knobs["seed"]), used, f"{study} {name}")
                # after the warm-up, as run_length.py counts them
                fluid_steps = int(knobs["steps"]) / studies.run_dem_steps_per_fluid_step(knobs)
                self.assertEqual(fluid_steps, 1e6)  # the phase diagrams too, by their length rule
        diameters = sorted({float(k["D"]) for _, k in studies.runs_of("porediameter", "paper")})
        self.assertEqual([round(d, 2) for d in diameters], [2.11, 2.82, 3.52, 4.23])
        self.assertEqual(len({k["seed"] for _, k in studies.runs_of("porediameter", "paper")}), 2)

    def test_n_dem_by_the_settings_verdict(self):
        """The studies begun after the settings verdict run at STUDY_N_DEM; porediameter and
        dropvol, whose fits take runs made before it, at N_DEM; the same physical run either
        way (the thermo rows as many fluid steps apart)."""
        import studies
        for study in ("porelength", "phaseac", "phasead", "conc", "pvpflux"):
            for name, knobs in studies.runs_of(study, "paper"):
                self.assertEqual(int(knobs["n_dem"]), studies.STUDY_N_DEM, f"{study} {name}")
                per_fluid_step = studies.run_dem_steps_per_fluid_step(knobs)
                self.assertEqual(int(knobs["thermo_every"]) / per_fluid_step, 10)
                self.assertEqual(int(knobs["warmup"]) / per_fluid_step, 2000)
        for study in ("porediameter", "dropvol"):
            for name, knobs in studies.runs_of(study, "paper"):
                self.assertEqual(int(knobs.get("n_dem", studies.N_DEM)), studies.N_DEM, f"{study} {name}")
        for study in ("porelength", "conc"):  # the quick size keeps the table's N_DEM
            for name, knobs in studies.runs_of(study, "quick"):
                self.assertNotIn("n_dem", knobs)

    def test_cost_estimate_counts_the_dem_share(self):
        """A run at N_DEM 20 is estimated at 1 - 0.8 DEM_COST_SHARE of the same run at 100."""
        import studies
        name, knobs = studies.runs_of("dropvol", "paper")[0]
        at_100 = studies.core_hours([(name, knobs)])
        at_20 = studies.core_hours([(name, studies.with_n_dem(knobs, 20))])
        self.assertAlmostEqual(at_20 / at_100, 1.0 - 0.8 * studies.DEM_COST_SHARE)

    def test_dropvol_has_five_seeds_of_its_scene(self):
        """dropvol's new seeds and the runs of other studies it takes beside them
        (studies.DROPVOL_BESIDE) are the default pore's scene, on 5 different seeds."""
        import analyze
        import studies
        import study_io
        seeds = {int(k["seed"]) for _, k in studies.runs_of("dropvol", "paper")}
        porediameter = dict(studies.runs_of("porediameter", "paper"))
        for path in studies.DROPVOL_BESIDE:
            name = os.path.basename(path)
            if path.startswith("doc/paper/porediameter/runs/"):
                knobs = porediameter[name]  # planned there, finished or not
            else:  # a study folder of one run
                runs = os.path.join(REPO, path, "runs")
                knobs = study_io.read_knobs(os.path.join(runs, os.listdir(runs)[0]))
            self.assertEqual(analyze.scene_differences(knobs, "dropvol", "paper"), {}, path)
            seeds.add(int(knobs["seed"]))
        self.assertEqual(len(seeds), 5)


class RunLength(unittest.TestCase):
    """run_length.py: P_max within each length of a run's own, counted in fluid steps after
    the warm-up, and the shortest length within 10 % of the full length's."""

    def test_p_max_by_length(self):
        import run_length
        with tempfile.TemporaryDirectory() as run:
            with open(os.path.join(run, "knobs.json"), "w") as f:
                json.dump({"cells_per_d": 7.1, "warmup": 1000, "n_dem": 100}, f)
            # 1000 DEM steps of warm-up (a spike there does not count), then P rising to 0.2
            # at 2 x 10^5 fluid steps and to 0.21 at 8 x 10^5.
            rows = [(500, 0.9), (1e7, 0.1), (2e7, 0.2), (5e7, 0.15), (8e7, 0.21), (1e8, 0.18)]
            with open(os.path.join(run, "thermo.csv"), "w") as f:
                f.write("Step,pore[16]\n" + "".join(f"{s:g},{p}\n" for s, p in rows))
            full_length, full, by_length = run_length.p_max_by_length(run)
        self.assertAlmostEqual(full_length, 1e6)
        self.assertEqual(full, 0.21)
        self.assertEqual(by_length[1e5], 0.1)
        self.assertEqual(by_length[2.5e5], 0.2)
        self.assertEqual(by_length[1e6], 0.21)


class DepositHold(unittest.TestCase):
    """figures/hold.py: the wall's hold and the fluid's force on the particles against the
    paper's load P pi D^2 / 4, per burst, on runs with known forces."""

    def run_with_forces(self, folder, load, wall, fluid=None):
        run = write_run(folder, 0.05, [(1.0, 0.1, 0.2), (2.0, 0.2, 0.4)])
        with open(os.path.join(folder, "bursts.txt")) as f:
            lines = f.read().splitlines()
        rows = [line.split() for line in lines[1:]]
        for row in rows:
            row[10], row[12] = repr(-wall), repr(load)
        with open(os.path.join(folder, "bursts.txt"), "w") as f:
            f.write("\n".join([lines[0]] + [" ".join(r) for r in rows]) + "\n")
        if fluid is not None:
            with open(os.path.join(folder, "log.liggghts")) as f:
                log = f.read().splitlines()
            log = [line + " pore[14]" if line.startswith("Step") else
                   line + f" {fluid!r}" if line[:1].isdigit() else line for line in log]
            with open(os.path.join(folder, "log.liggghts"), "w") as f:
                f.write("\n".join(log) + "\n")
        return run

    def test_ratios_of_known_forces(self):
        from figures import hold
        with tempfile.TemporaryDirectory() as tmp:
            runs = [self.run_with_forces(os.path.join(tmp, "a"), load=2.0, wall=1.0, fluid=1.25),
                    self.run_with_forces(os.path.join(tmp, "b"), load=4.0, wall=2.0)]
            summary = dict(runs=runs, finished=2, study="hold", size="tiny", core_hours=0.0)
            r = hold.analyze(summary, tmp)["ratios"]
        self.assertAlmostEqual(r["wall_over_load"]["median"], 0.5, places=12)
        self.assertAlmostEqual(r["wall_over_load"]["low"], 0.5, places=12)  # both runs alike
        # the fluid's force only where the rows carry it (run a)
        self.assertAlmostEqual(r["fluid_over_load"]["per_run"]["a"], 0.625, places=12)
        self.assertTrue(math.isnan(r["fluid_over_load"]["per_run"]["b"]))
        self.assertAlmostEqual(r["wall_over_fluid"]["median"], 0.8, places=12)
        # the excess load is the load of P - P_0: P_0 = 0.05 at peaks 0.2 and 0.4
        self.assertAlmostEqual(r["fluid_over_excess_load"]["per_run"]["a"],
                               float(np.median([1.25 / (2.0 * 0.15 / 0.2), 1.25 / (2.0 * 0.35 / 0.4)])), places=12)


    def test_the_deposits_own_balance_at_its_largest_count(self):
        """Where the rows carry the deposit's own loads (f_pore[7], [26], [34], [35], [36]),
        the ratios are read at the row of the largest deposited count before each peak, with
        the load of that row's P; the totals stay as they are. The other particles' hold is
        what the fluid's push leaves after the wall's hold and the net force."""
        from figures import hold
        with tempfile.TemporaryDirectory() as tmp:
            folder = os.path.join(tmp, "a")
            run = self.run_with_forces(folder, load=2.0, wall=1.0, fluid=1.25)
            with open(os.path.join(folder, "log.liggghts")) as f:
                log = f.read().splitlines()
            # 10 deposited at step 3000 (4 on the wall, the fluid's 0.8 on them, the wall's
            # -0.6, every force on them 0.05), none before or after; P / P_out there is P_0 = 0.05
            log = [line + " pore[7] pore[26] pore[34] pore[35] pore[36]" if line.startswith("Step") else
                   line + (" 10 4 0.8 -0.6 0.05" if line.split()[0] == "3000" else " 0 0 0 0 0")
                   if line[:1].isdigit() else line for line in log]
            with open(os.path.join(folder, "log.liggghts"), "w") as f:
                f.write("\n".join(log) + "\n")
            summary = dict(runs=[run], finished=1, study="hold", size="tiny", core_hours=0.0)
            r = hold.analyze(summary, tmp)["ratios"]
            # with each DEM step applying 1 / N_DEM of the fluid step's force, fluid - wall -
            # net is not the other particles' hold: no others, no net; the rest as it was
            fraction = dict(run, knobs=dict(run["knobs"], substep_force="fraction"))
            f = hold.run_ratios(fraction)
        self.assertTrue(np.isnan(f["deposit_others_over_load"]).all())
        self.assertTrue(np.isnan(f["deposit_net_over_load"]).all())
        self.assertAlmostEqual(float(np.nanmedian(f["deposit_wall_over_fluid"])), 0.75, places=12)
        # the bursts' peaks 0.2 and 0.4 P_out with load 2.0: at P 0.05 the loads are 0.5, 0.25
        self.assertAlmostEqual(r["deposit_wall_over_load"]["median"], np.median([0.6 / 0.5, 0.6 / 0.25]), places=12)
        self.assertAlmostEqual(r["deposit_fluid_over_load"]["median"], np.median([0.8 / 0.5, 0.8 / 0.25]), places=12)
        self.assertAlmostEqual(r["deposit_wall_over_fluid"]["median"], 0.75, places=12)
        self.assertAlmostEqual(r["deposit_on_wall_share"]["median"], 0.4, places=12)
        # others: 0.8 - 0.6 - 0.05 = 0.15 of loads 0.5 and 0.25; net 0.05
        self.assertAlmostEqual(r["deposit_others_over_load"]["median"], np.median([0.15 / 0.5, 0.15 / 0.25]),
                               places=12)
        self.assertAlmostEqual(r["deposit_net_over_load"]["median"], np.median([0.05 / 0.5, 0.05 / 0.25]), places=12)
        self.assertAlmostEqual(r["wall_over_load"]["median"], 0.5, places=12)  # the totals' unchanged


class StudyThreads(unittest.TestCase):
    """Runs side by side share the cores: each rank gets its share as OpenMP threads, unless
    the user chose (two runs of two threads each on two cores ran ten times slower)."""

    def test_each_rank_gets_its_share_of_the_cores(self):
        import ensemble
        self.assertEqual(ensemble.threads_per_rank(2, cores=2), 1)
        self.assertEqual(ensemble.threads_per_rank(1, cores=2), 2)
        self.assertEqual(ensemble.threads_per_rank(3, cores=16), 5)
        self.assertEqual(ensemble.threads_per_rank(8, cores=2), 1)

    def test_the_users_choice_stands(self):
        import ensemble
        saved = os.environ.get("OMP_NUM_THREADS")
        try:
            os.environ["OMP_NUM_THREADS"] = "3"
            self.assertEqual(ensemble.set_threads_per_rank(1), 3)
            del os.environ["OMP_NUM_THREADS"]
            self.assertEqual(ensemble.set_threads_per_rank(10 ** 6), 1)
            self.assertEqual(os.environ["OMP_NUM_THREADS"], "1")
        finally:
            os.environ.pop("OMP_NUM_THREADS", None)
            if saved is not None:
                os.environ["OMP_NUM_THREADS"] = saved


class StudyBinding(unittest.TestCase):
    """Each mpirun binds its ranks to the node's first cores whatever the other mpiruns do:
    two 1-rank launches side by side shared core 0, and a rank's threads shared its one core."""

    def test_a_launch_binds_only_alone_on_one_thread_per_rank(self):
        import ensemble
        self.assertEqual(ensemble.binding_options(1, threads=1), [])
        self.assertEqual(ensemble.binding_options(2, threads=1), ["--bind-to", "none"])
        self.assertEqual(ensemble.binding_options(1, threads=2), ["--bind-to", "none"])

    def test_an_unbound_launch_may_run_on_every_core(self):
        import ensemble
        import subprocess
        def allowed(options):
            out = subprocess.run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "1"] + options +
                                 ["grep", "Cpus_allowed_list", "/proc/self/status"],
                                 capture_output=True, text=True, check=True).stdout
            return out.split()[-1]
        with open("/proc/self/status") as f:
            ours = [line.split()[-1] for line in f if line.startswith("Cpus_allowed_list")][0]
        self.assertEqual(allowed(ensemble.binding_options(2, threads=1)), ours)


class StudyCost(unittest.TestCase):
    """A study's cost is the sum over every launch of every run, including the launches of
    earlier runners (a study resumed over sittings counted only its last runner's)."""

    def test_every_launch_counts_and_a_killed_one_up_to_its_last_update(self):
        import time
        import run_cost
        with tempfile.TemporaryDirectory() as run:
            with open(os.path.join(run, run_cost.COST_FILE), "w") as f:
                f.write("3600.0 2\n")  # an earlier runner's launch: 2 core-hours
            with run_cost.LaunchClock([run], 1, every=0.05):
                time.sleep(0.3)
                hours, exact = run_cost.run_core_hours(run)  # while it runs
                self.assertTrue(exact)
                self.assertGreater(hours, 2.0 + 0.1 / 3600)
            hours, exact = run_cost.run_core_hours(run)
            self.assertAlmostEqual(hours, 2.0 + 0.3 / 3600, delta=2.0 / 3600)
            with open(os.path.join(run, run_cost.COST_FILE)) as f:
                self.assertEqual(len(f.read().splitlines()), 2)

    def test_a_run_without_a_cost_file_counts_its_logged_loops_as_a_lower_bound(self):
        import run_cost
        with tempfile.TemporaryDirectory() as run:
            with open(os.path.join(run, "log.liggghts"), "w") as f:
                f.write("Loop time of 1800 on 2 procs for 10 steps with 0 atoms\n"
                        "Loop time of 360.0 on 1 procs for 10 steps with 9 atoms\n")
            hours, exact = run_cost.run_core_hours(run)
            self.assertAlmostEqual(hours, 1.1)
            self.assertFalse(exact)
            self.assertEqual(run_cost.study_core_hours([run, run]), (2.2, False))


class DiameterLaw(unittest.TestCase):
    """porediameter by the paper's procedure: a slope of P - P_0 on L_dep per pore diameter,
    then the slopes against D, with intervals over seeds."""

    def test_the_slopes_against_D_give_K_and_the_exponent(self):
        from figures import porediameter
        rng = random.Random(5)
        K, a = 0.9, 1.0
        with tempfile.TemporaryDirectory() as tmp:
            runs = []
            for D in (2.11, 2.82, 3.52, 4.23):
                for seed in range(3):
                    k_run = K * (1 + 0.05 * (seed - 1))  # the seeds differ by +-5 %
                    lengths = [rng.uniform(0.5, 4.0) for _ in range(6)]
                    rows = [(0.0, L, 0.01 + k_run * L / D ** a) for L in lengths]
                    runs.append(write_run(os.path.join(tmp, f"D_{D}_seed_{seed}"), 0.01, rows, D=D,
                                          deposits=[(10, 0.0, L) for L in lengths]))
            # the synthetic logs have no deposit rows: the records' own deposit measures them
            law = porediameter.diameter_law(dict(runs=runs, finished=len(runs)), deposit="median")
            self.assertEqual(law["D"], [2.11, 2.82, 3.52, 4.23])
            self.assertEqual(law["runs_per_D"], [3, 3, 3, 3])
            for D, (s, low, high) in zip(law["D"], law["slope_per_D"]):
                self.assertTrue(low <= K / D <= high)
                self.assertLess(high - low, 0.15 * K / D)
            k, k_low, k_high = law["K"]
            exponent, a_low, a_high = law["a"]
            self.assertAlmostEqual(exponent, a, delta=0.05)
            self.assertAlmostEqual(k, K, delta=0.05)
            self.assertTrue(k_low < K < k_high and a_low < a < a_high)
            self.assertLess(a_high - a_low, 0.3)

    def test_beside_it_the_law_with_P_across_the_pore(self):
        """P read across the pore (f_pore[27]) at the thermo row of each peak, with P_0 read
        there too: runs whose f_pore[27] is 0.8 of f_pore[16] everywhere give 0.8 of K and the
        same exponent; a peak without a thermo row near it is left out, not misread."""
        from figures import porediameter
        with tempfile.TemporaryDirectory() as tmp:
            runs, rows_of_D = [], {}
            for D in (2.11, 3.52):
                lengths = [0.5, 1.0, 2.0, 3.0]
                rows = rows_of_D[D] = [(0.0, L, 0.01 + 0.9 * L / D) for L in lengths]
                run = write_run(os.path.join(tmp, f"D_{D}"), 0.01, rows, D=D,
                                deposits=[(10, 0.0, L) for L in lengths])
                log_path = os.path.join(run["folder"], "log.liggghts")
                with open(log_path) as f:
                    lines = f.read().splitlines()
                names = HEADER.split() + ["pore[27]"]
                out = [lines[0], " ".join(names)]
                for line in lines[2:]:
                    out.append(line + f" {0.8 * float(line.split()[HEADER.split().index('pore[16]')])!r}")
                for k, (_, _, p) in enumerate(rows):
                    row = dict.fromkeys(names, 0.0)
                    row.update({"Step": 10000 + 100 * k, "pore[16]": p, "pore[27]": 0.8 * p})
                    out.append(" ".join(f"{row[n]!r}" for n in names))
                with open(log_path, "w") as f:
                    f.write("\n".join(out) + "\n")
                runs.append(run)
            summary = dict(runs=runs, finished=len(runs))
            faces = porediameter.diameter_law(summary, deposit="median")
            across = porediameter.diameter_law(summary, deposit="median", pressure="across")
            from figures import common
            near, far = dict(step=10100, P_peak=0.5), dict(step=10 ** 7, P_peak=0.5)  # far: no row near
            self.assertEqual([b["P_peak"] for b in common.across_pore_peaks(runs[0], [near, far])],
                             [0.8 * rows_of_D[2.11][1][2]])
            # the fits porelength and dropvol show beside their own read it the same way
            fits = common.pressure_fits(summary, lambda r, b: b["deposit_L"] / float(r["knobs"]["D"]),
                                        deposit="median", pressure="across")
        self.assertAlmostEqual(fits["excess_through_origin"][0], 0.72, places=9)
        self.assertAlmostEqual(faces["K"][0], 0.9, places=9)
        self.assertAlmostEqual(across["K"][0], 0.72, places=9)
        self.assertAlmostEqual(across["a"][0], faces["a"][0], places=9)
        with self.assertRaises(ValueError):
            common.run_points(runs[0], lambda r, b: 1.0, pressure="inlet")


class AnalysisWithOtherRuns(unittest.TestCase):
    """analyze.py --with: the runs of another study folder beside the study's own (dropvol's
    new seeds with the calibration's paper-length run)."""

    def test_the_other_folders_runs_and_cost_are_added(self):
        import analyze
        with tempfile.TemporaryDirectory() as tmp:
            folders = []
            for k, name in enumerate(("study", "paper_run")):
                folder = os.path.join(tmp, name)
                run = write_run(os.path.join(folder, "runs", "run0"), 0.05, [(1.0, 1.0, 0.5 + 0.1 * k)])
                with open(os.path.join(folder, "summary.txt"), "w") as f:
                    f.write("study dropvol (paper, pool): 1 finished, 0 failed, 0 incomplete of 1\n")
                with open(os.path.join(run["folder"], "knobs.json"), "w") as f:
                    json.dump(run["knobs"], f)
                with open(os.path.join(run["folder"], "state.txt"), "w") as f:
                    f.write("done\n\n")
                with open(os.path.join(run["folder"], "cost.txt"), "w") as f:
                    f.write(f"{3600.0 * (k + 1)} 1\n")
                folders.append(folder)
            import study_io
            summary = study_io.load_summary(folders[0])
            analyze.add_runs_of(summary, folders[1])
            self.assertEqual([r["name"] for r in summary["runs"]], ["run0", "paper_run/run0"])
            self.assertEqual(summary["finished"], 2)
            self.assertAlmostEqual(summary["core_hours"], 3.0)
            self.assertTrue(summary["core_hours_exact"])
            # --runs: only the matching runs, their count and their cost
            analyze.keep_runs_matching(summary, "^paper_run/")
            self.assertEqual([r["name"] for r in summary["runs"]], ["paper_run/run0"])
            self.assertEqual(summary["finished"], 1)
            self.assertAlmostEqual(summary["core_hours"], 2.0)
            with self.assertRaises(SystemExit):
                analyze.keep_runs_matching(summary, "^no_such_run$")

    def test_one_run_of_another_study_at_the_same_scene(self):
        """--with <one run's folder>: a run of another study whose knobs differ from this
        study's plan only in its seed and in what it writes is taken (porediameter's run at the
        default pore as a dropvol seed); a run of another scene is refused, naming the knobs."""
        import analyze
        import studies
        _, plan = studies.dropvol("paper")[0]
        with tempfile.TemporaryDirectory() as tmp:
            same = os.path.join(tmp, "porediameter", "runs", "D_3.52_seed_7")
            other = os.path.join(tmp, "porediameter", "runs", "D_2.82_seed_7")
            for folder, knobs in ((same, dict(plan, seed=7, restart_every=400000)),
                                  (other, dict(plan, seed=7, D="2.816901408"))):
                os.makedirs(folder)
                with open(os.path.join(folder, "knobs.json"), "w") as f:
                    json.dump({k: str(v) for k, v in knobs.items()}, f)
                with open(os.path.join(folder, "state.txt"), "w") as f:
                    f.write("done\n\n")
                with open(os.path.join(folder, "cost.txt"), "w") as f:
                    f.write("7200.0 1\n")
            summary = dict(study="dropvol", size="paper", runs=[], core_hours=0.0, core_hours_exact=True,
                           finished=0)
            analyze.add_runs_of(summary, same)
            self.assertEqual([r["name"] for r in summary["runs"]], ["porediameter/D_3.52_seed_7"])
            self.assertEqual((summary["finished"], summary["core_hours"]), (1, 2.0))
            with self.assertRaises(SystemExit) as refused:
                analyze.add_runs_of(summary, other)
            self.assertIn("D 2.816901408 against 3.521126761", str(refused.exception))
            import figure_table
            self.assertEqual(figure_table._finished(same), 1)


class CommittedRuns(unittest.TestCase):
    """A study continues from what the repository keeps (committed_runs.py): a run cut short
    is parked with its newest restart file and the checkpoint that file names, unpacked on a
    machine that lacks it, and replaced by its compact result once it finishes."""

    @staticmethod
    def cut_short_run(folder):
        """A run's folder (write_run) with restart files and fluid checkpoints beside it; the
        bytes of each file by name."""
        run = write_run(folder, 0.07, [(10.0, 1.0, 0.9)])
        extra = {"cost.txt": b"60.0 1\n", "knobs.json": json.dumps(run["knobs"]).encode(), "stdout.txt": b"screen",
                 # fix lbm/pore's record ends with the checkpoint's path and a zero
                 "restart.a": b"\x00\x01atoms.fluid.pore.fluid.2000\x00", "pore.fluid.2000.0": b"A" * 64,
                 "pore.fluid.2000.1": b"B" * 64, "pore.fluid.1000.0": b"old"}
        for name, data in extra.items():
            with open(os.path.join(folder, name), "wb") as f:
                f.write(data)
        os.utime(os.path.join(folder, "restart.a"), (1e9, 1e9))
        with open(os.path.join(folder, "restart.b"), "wb") as f:  # newer, names no checkpoint here
            f.write(b"pore.fluid.3000\x00")
        files = {}
        for name in os.listdir(folder):
            with open(os.path.join(folder, name), "rb") as f:
                files[name] = f.read()
        return files

    def test_a_parked_run_unpacks_on_a_fresh_machine_and_goes_once_kept(self):
        import committed_runs
        import ensemble
        with tempfile.TemporaryDirectory() as tmp:
            run, evidence = os.path.join(tmp, "here", "run0"), os.path.join(tmp, "evidence")
            files = self.cut_short_run(run)
            # write_run's knobs give no length: as far as the runner can tell, nothing is done
            self.assertIsNone(committed_runs.park(run, evidence, "run0"))
            archive = committed_runs.park(run, evidence, "run0", min_share=0.0)
            self.assertEqual(archive, committed_runs.parked_archive(evidence, "run0"))
            committed_runs.write_summary(evidence, "porelength", "paper", ["run0", "run1"])
            with open(os.path.join(evidence, "summary.txt")) as f:
                self.assertIn("1 parked, 1 to do of 2", f.readline())
            self.assertIsNone(committed_runs.committed_state(evidence, "run0"))
            # A machine with its own copy resumes from it; a fresh one unpacks the archive:
            # the newest restart file with a checkpoint (restart.a), both ranks' checkpoint
            # files, and what the run appends to; not the older checkpoint, not the screen.
            self.assertFalse(committed_runs.unpark(evidence, "run0", run))
            fresh = os.path.join(tmp, "there", "run0")
            self.assertTrue(committed_runs.unpark(evidence, "run0", fresh))
            expected = sorted(set(files) - {"pore.fluid.1000.0", "stdout.txt", "restart.b"})
            self.assertEqual(sorted(os.listdir(fresh)), expected)
            for name in expected:
                with open(os.path.join(fresh, name), "rb") as f:
                    self.assertEqual(f.read(), files[name])
            # Once it finishes, its compact result replaces the parked copy.
            with open(os.path.join(fresh, "log.liggghts"), "a") as f:
                f.write(ensemble.DONE_MARK + "\n")
            self.assertTrue(committed_runs.keep_settled(fresh, evidence, "run0"))
            self.assertEqual(committed_runs.committed_state(evidence, "run0"), "done")
            self.assertFalse(os.path.exists(os.path.join(evidence, committed_runs.PARKED)))

    def test_a_run_is_parked_from_a_quarter_of_its_steps(self):
        import committed_runs
        with tempfile.TemporaryDirectory() as tmp:
            run, evidence = os.path.join(tmp, "run0"), os.path.join(tmp, "evidence")
            self.cut_short_run(run)
            with open(os.path.join(run, "knobs.json"), "w") as f:
                json.dump(dict(steps="7000", warmup="1000"), f)  # 8000 steps in all
            for last, parked in ((1000, False), (2000, True)):
                with open(os.path.join(run, "log.liggghts"), "a") as f:
                    f.write(f"{last} 3 0.5 0.1\n")
                self.assertAlmostEqual(committed_runs.share_done(run), last / 8000)
                self.assertEqual(committed_runs.park(run, evidence, "run0") is not None, parked, last)

    def test_a_run_without_a_checkpoint_is_not_parked(self):
        import committed_runs
        with tempfile.TemporaryDirectory() as tmp:
            run = os.path.join(tmp, "run0")
            os.makedirs(run)
            with open(os.path.join(run, "restart.a"), "wb") as f:
                f.write(b"pore.fluid.2000\x00")  # its checkpoint was never written
            self.assertIsNone(committed_runs.park(run, os.path.join(tmp, "evidence"), "run0", min_share=0.0))
            self.assertFalse(committed_runs.keep_settled(run, os.path.join(tmp, "evidence"), "run0"))


class FigureTable(unittest.TestCase):
    """doc/paper.md's table of the figures is the one the committed evidence gives, and each
    verdict applies the criterion written before the runs (verdicts.py)."""

    def test_the_doc_s_table_is_the_evidence_s(self):
        import figure_table
        with open(figure_table.DOC) as f:
            text = f.read()
        self.assertEqual(figure_table.replaced(text, figure_table.table()), text,
                         "run examples/paper/figure_table.py")

    def test_the_phase_diagrams_are_as_long_as_their_rule_asks(self):
        # The rule fixed before them (doc/paper.md, "The studies' settings"), applied to every
        # finished paper-length run the repository keeps: a run that raises the length fails
        # here until studies.PHASE_DIAGRAM_STEPS follows.
        import figure_table
        import studies
        shortest, count = figure_table.phase_diagram_length()
        self.assertGreaterEqual(count, 2)
        self.assertIsNotNone(shortest)
        self.assertLessEqual(shortest, studies.PHASE_DIAGRAM_STEPS // studies.N_DEM)

    def test_law_verdicts_apply_the_criteria(self):
        import verdicts
        met = dict(excess_coefficient=[0.25, 0.2, 0.3], pearson=[0.85, 0.7, 0.9])
        self.assertEqual(verdicts.verdict("porelength", met, 6, 6)[1], "meets")
        low = dict(met, pearson=[0.74, 0.5, 0.9])
        self.assertEqual(verdicts.verdict("porelength", low, 6, 6)[1], "misses: Pearson 0.74 below 0.8")
        self.assertEqual(verdicts.verdict("porelength", met, 3, 6)[1], "provisional (3 of 6 runs): meets")
        self.assertEqual(verdicts.verdict("porelength", None, 0, 6)[1], "no numbers: no run finished")
        across = dict(met, across_pore=dict(excess_through_origin=[0.15, 0.13, 0.17], pearson=[0.63, 0.4, 0.8]))
        ours, judged = verdicts.verdict("porelength", across, 6, 6)
        self.assertIn("; P across the pore, beside: c 0.15 [0.13, 0.17], Pearson 0.63 [0.4, 0.8]", ours)
        self.assertEqual(judged, "meets")  # judged on the figures' measure, the faces'
        law = dict(diameter_law=dict(K=[1.2, 1.0, 1.4], a=[0.9, 0.7, 1.1]))
        self.assertEqual(verdicts.verdict("porediameter", law, 8, 8)[1],
                         "misses: K 1.2 outside 0.91 +- 0.1")
        # the intervals over seeds say at how many diameters there are seeds to resample
        partly = dict(diameter_law=dict(law["diameter_law"], runs_per_D=[2, 1, 1, 1]))
        self.assertIn("(intervals over seeds; two or more at 1 of 4 diameters)",
                      verdicts.verdict("porediameter", partly, 5, 8)[0])
        every = dict(diameter_law=dict(law["diameter_law"], runs_per_D=[2, 2, 2, 2]))
        self.assertIn("(intervals over seeds)", verdicts.verdict("porediameter", every, 8, 8)[0])
        one_d = dict(diameter_law=dict(K=[None] * 3, a=[None] * 3), K_excess=[0.7, 0.6, 0.8], finished=1)
        ours, judged = verdicts.verdict("porediameter", one_d, 1, 8)
        self.assertIn("over the bursts", ours)
        self.assertEqual(judged, "provisional (1 of 8 runs): no numbers: too few runs for the figure")
        drop = dict(excess_through_origin=[1.3, 1.1, 1.5], pearson=[0.95, 0.9, 0.99])
        self.assertEqual(verdicts.verdict("dropvol", drop, 5, 5)[1], "misses: Pearson 0.95 outside 0.5-0.9")
        few = dict(drop, intervals_over="runs", finished=2)  # a bootstrap over 2 runs says so
        self.assertIn("(intervals over 2 runs)", verdicts.verdict("dropvol", few, 2, 6)[0])
        self.assertNotIn("intervals over", verdicts.verdict("dropvol", dict(few, finished=5), 5, 6)[0])
        self.assertEqual(verdicts.verdict("conc", dict(onset=0.02), 6, 6)[1], "meets")
        self.assertEqual(verdicts.verdict("pvpflux", dict(threshold=0.5), 6, 6)[1],
                         "misses: threshold 0.5 outside 0.35 +- 0.1")

    def test_phase_diagram_verdicts(self):
        import verdicts
        self.assertAlmostEqual(verdicts.crossing([0.1, 0.05, 0.2], [0.4, 0.2, 0.8], 0.3), 0.075)
        self.assertIsNone(verdicts.crossing([0.1, 0.2], [0.1, 0.2], 0.3))
        # the contours' k_a the same at both k_c: no trend; a factor 4 apart: a trend
        flat = [dict(x=ka, y=kc, P_max=p) for kc in (1e-3, 1e-1)
                for ka, p in ((0.05, 0.1), (0.1, 0.5), (0.2, 0.9))]
        ours, judged = verdicts.verdict("phaseac", dict(points=flat), 6, 6)
        self.assertEqual(judged, "no trend in k_c; the contours' place in k_a not judged (the paper draws it only)")
        self.assertIn("0.3 P_out at k_a 0.075-0.075 over 2 k_c", ours)
        shifted = flat[:3] + [dict(pt, x=pt["x"] * 4) for pt in flat[3:]]
        self.assertTrue(verdicts.verdict("phaseac", dict(points=shifted), 6, 6)[1].startswith("misses"))
        rising = [dict(x=0.1, y=r, P_max=p) for r, p in ((0.2, 0.1), (0.3, 0.3), (0.4, 0.2), (0.5, 0.7))]
        self.assertAlmostEqual(verdicts.spearman([0.2, 0.3, 0.4, 0.5], [0.1, 0.3, 0.2, 0.7]), 0.8)
        self.assertEqual(verdicts.verdict("phasead", dict(points=rising), 4, 6)[1], "provisional (4 of 6 runs): meets")


if __name__ == "__main__":
    unittest.main()
