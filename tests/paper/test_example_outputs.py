"""What the main example writes (tools/run_example.sh), checked on small synthetic runs with
known answers (ctest paper_example_outputs; seconds, no liggghts-lbm run):
  - plot_pressure.py draws the pressure loss and the deposit on two panels sharing the time
    axis, the deposit not over the trace, the burst file's bursts marked where they are;
  - render_snapshot.py --at peak takes the VTK frame nearest the highest P / P_out once
    particles are in (not the particle-free start-up overshoot), with the particle file of the
    same step, and colours the particles by |f_pore[1-3]| / mass;
  - summarize_run.py prints one line per burst with its fluid step, pressures and the deposit
    by each measure, labelled.

Usage: test_example_outputs.py <source root>   (or python3 -m unittest with LBM_PORE_REPO set)
"""
import contextlib
import io
import math
import os
import re
import sys
import tempfile
import unittest

REPO = os.environ.get("LBM_PORE_REPO") or (sys.argv.pop(1) if len(sys.argv) > 1 else
                                           os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "examples", "pore"))
sys.path.insert(0, os.path.join(REPO, "examples", "paper"))

import numpy as np  # noqa: E402

import plot_pressure  # noqa: E402
import render_snapshot  # noqa: E402
import summarize_run  # noqa: E402

# As LIGGGHTS prints the header of in.pore's thermo_style (f_ and c_ dropped).
HEADER = ("Step Atoms pore[1] pore[6] pore[7] pore[8] pore[4] pore[5] pore[10] bonds walls[1] "
          "pore[16] pore[17] pore[18]").split()
SETUP = ("fix lbm/pore: lattice 8 x 4 x 4 nodes (dx = 1), tau = 1, nu_lattice = 0.166667, "
         "dt_lbm = 1 (n_dem = 100 x dt_dem = 0.01), dx = 1\n")
FIX_LINE = ("fix             pore all lbm/pore dx 1 rho 1 nu 0.16 n_dem 100 scene pore inlet 2 "
            "burst_file bursts.txt burst_drop 0.1 burst_window 1000 burst_deposits 1 vtk 200 fluid_vtk\n")
BURST_HEADER = ("# step time[s] P_peak[P_out] P_after[P_out] delta_P[P_out] delta_t[s] V_dep[m^3] "
                "L_dep[m] count_before count_after wall_F[N] on_wall P_pi_D2_4[N] deposit_count "
                "deposit_V[m^3] deposit_L[m]\n")


def write_log(path, blocks):
    """A log of in.pore's form: the setup line, the fix command and one thermo block per
    list of row dicts (missing columns 0)."""
    with open(path, "w") as f:
        f.write(SETUP)
        f.write(FIX_LINE)
        for rows in blocks:
            f.write("    " + " ".join(HEADER) + " \n")
            for row in rows:
                f.write(" ".join(f"{row.get(name, 0.0):.10g}" for name in HEADER) + "\n")
            f.write("Loop time of 1 on 1 procs\n")


def thermo_run():
    """A warm-up (no particles, a start-up overshoot to P 0.5) and a particle run of 10 000
    DEM steps per row: P / P_out rises to 0.4 at step 730 000 and falls; the deposit grows
    before it."""
    warm = [{"Step": s, "pore[16]": 0.5 if s == 10000 else 0.1} for s in range(0, 100001, 10000)]
    run = []
    for s in range(110000, 1000001, 10000):
        p = 0.1 + 0.3 * max(0.0, 1.0 - abs(s - 730000) / 80000.0)
        count = 0 if s < 500000 else (3 if s < 700000 else 1)
        run.append({"Step": s, "Atoms": 10, "pore[16]": p, "pore[7]": count,
                    "pore[6]": 0.5 * count, "pore[8]": 0.1 * count})
    return warm, run


class PressurePlot(unittest.TestCase):
    def test_two_panels_sharing_time_with_the_bursts_marked(self):
        warm, run = thermo_run()
        with tempfile.TemporaryDirectory() as work:
            log = os.path.join(work, "log.liggghts")
            write_log(log, [warm, run])
            bursts = os.path.join(work, "bursts.txt")
            with open(bursts, "w") as f:
                f.write(BURST_HEADER)
                f.write("730000 7300 0.4 0.15 0.25 60 1.5 0.3 3 1 0 2 0.01 3 1.5 0.3\n")
                f.write("250000 2500 0.2 0.17 0.03 40 0 0 0 0 0 0 0.01 0 0 0\n")
            out = os.path.join(work, "pressure_loss.png")
            with contextlib.redirect_stdout(io.StringIO()) as printed:
                fig = plot_pressure.main([log, "--fix", "pore", "--bursts", bursts, "--out", out])
            self.assertTrue(os.path.getsize(out) > 10000)
            self.assertIn("BURST step 730000 peak 0.4 after 0.15 drop 0.625", printed.getvalue())
            top, bottom, volume_axis = fig.axes
            self.assertTrue(top.get_shared_x_axes().joined(top, bottom))
            self.assertLess(bottom.get_position().y1, top.get_position().y0)  # below, not over
            self.assertIs(volume_axis.get_shared_x_axes().joined(volume_axis, bottom), True)
            rows = warm + run
            time = [r["Step"] * 0.01 for r in rows]
            (trace,) = [line for line in top.lines if line.get_label() == "pressure loss"]
            np.testing.assert_allclose(trace.get_xdata(), time)
            np.testing.assert_allclose(trace.get_ydata(), [r["pore[16]"] for r in rows])
            # The deposit is on the lower panel alone: the count there, V_dep on its right axis.
            self.assertFalse([line for line in top.lines if "deposit" in line.get_label()])
            (count,) = bottom.lines
            np.testing.assert_allclose(count.get_ydata(), [r.get("pore[7]", 0) for r in rows])
            (volume,) = volume_axis.lines
            np.testing.assert_allclose(volume.get_ydata(), [r.get("pore[6]", 0) for r in rows])
            # The bursts in step order, each shaded from its peak to its minimum (peak + delta_t)
            # on both panels, a marker on the file's own peak.
            for ax in (top, bottom):
                spans = sorted((min(p.get_xy()[:, 0]), max(p.get_xy()[:, 0])) for p in ax.patches)
                np.testing.assert_allclose(spans, [(2500, 2540), (7300, 7360)])
            markers = [(line.get_xdata()[0], line.get_ydata()[0]) for line in top.lines
                       if line.get_marker() == "v"]
            np.testing.assert_allclose(markers, [(2500, 0.2), (7300, 0.4)])
            self.assertEqual(top.get_title(), "2 erosive burst(s) recorded by fix lbm/pore")

    def test_bursts_found_on_the_thermo_rows_without_a_burst_file(self):
        warm, run = thermo_run()
        with tempfile.TemporaryDirectory() as work:
            log = os.path.join(work, "log.liggghts")
            write_log(log, [warm, run])
            data = plot_pressure.load(log)
        # The peak row at 730 000, followed to the last row at the bottom of the fall (0.1).
        self.assertEqual([b["step"] for b in data["bursts"] if b["step"] > 100000], [730000])
        peak = [b for b in data["bursts"] if b["step"] == 730000][0]
        self.assertAlmostEqual(peak["P_peak"], 0.4)
        self.assertAlmostEqual(peak["P_after"], 0.1)
        self.assertAlmostEqual(peak["x_peak"], 7300.0)


def write_fluid(path, speed):
    """A fluid file of 8 x 4 x 4 nodes moving at `speed` along x, the first layer solid."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
    image = vtkImageData()
    image.SetDimensions(8, 4, 4)
    image.SetSpacing(1.0, 1.0, 1.0)
    n = 8 * 4 * 4
    velocity = np.zeros((n, 3))
    velocity[:, 0] = speed
    node_type = np.zeros(n, dtype=np.int32)
    node_type[:8 * 4] = 1
    for name, values in (("velocity", velocity), ("node_type", node_type)):
        array = numpy_to_vtk(values, deep=True)
        array.SetName(name)
        image.GetPointData().AddArray(array)
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def write_particles(path, particles):
    """A particle file of (x, y, z, radius, mass, force) tuples, as in.pore's dump writes."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    poly = vtkPolyData()
    points = vtkPoints()
    for p in particles:
        points.InsertNextPoint(*p[:3])
    poly.SetPoints(points)
    for name, values in (("radius", [p[3] for p in particles]), ("mass", [p[4] for p in particles]),
                         ("f_pore[1-3]", [p[5] for p in particles])):
        array = numpy_to_vtk(np.asarray(values, float), deep=True)
        array.SetName(name)
        poly.GetPointData().AddArray(array)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(poly)
    writer.Write()


class PeakSnapshot(unittest.TestCase):
    def make_run(self, work):
        warm, run = thermo_run()
        write_log(os.path.join(work, "log.liggghts"), [warm, run])
        os.makedirs(os.path.join(work, "fluid_vtk"))
        os.makedirs(os.path.join(work, "particles_vtk"))
        for frame in range(0, 10001, 2000):  # fluid steps; 0 ... 10 000, the peak at 7300
            write_fluid(os.path.join(work, "fluid_vtk", f"fluid_{frame:06d}.vti"), 0.01 * (1 + frame / 2000))
            # The frame before the peak holds a particle of larger drag: it must not be read.
            drag = [(3.0, 4.0, 0.0), (0.0, 0.0, 1.0)] if frame == 8000 else [(90.0, 0.0, 0.0)]
            write_particles(os.path.join(work, "particles_vtk", f"particles_{frame * 100}.vtp"),
                            [(3.0, 2.0, 2.0, 0.5, 2.0 if k == 0 else 0.5, f) for k, f in enumerate(drag)])

    def test_the_frame_nearest_the_highest_peak_with_particles(self):
        with tempfile.TemporaryDirectory() as work:
            self.make_run(work)
            # The start-up overshoot (0.5 at step 10 000, no particles) is not the peak.
            self.assertEqual(render_snapshot.highest_peak(work), (730000, 0.4))
            out = os.path.join(work, "snapshot_peak.png")
            with contextlib.redirect_stdout(io.StringIO()) as printed:
                shown = render_snapshot.render_peak(work, out)
            self.assertTrue(os.path.getsize(out) > 10000)
        # Frames at 6000 and 8000 fluid steps: 8000 is 700 from the peak at 7300, 6000 is 1300.
        self.assertEqual(shown["frame"], 8000)
        self.assertAlmostEqual(shown["peak_step"], 7300)
        self.assertAlmostEqual(shown["peak_P"], 0.4)
        self.assertAlmostEqual(shown["distance"], 700)
        # Its particles: |(3, 4, 0)| / 2 = 2.5 and |(0, 0, 1)| / 0.5 = 2.
        self.assertEqual(shown["particles"], 2)
        self.assertAlmostEqual(shown["drag_max"], 2.5)
        # P at the frame's thermo row (step 800 000, on the peak's flank): 0.1 + 0.3 x 1 / 8,
        # more than 10 % below the peak, which the renderer says.
        self.assertAlmostEqual(shown["frame_P"], 0.1375)
        self.assertIn("the frame misses the peak", printed.getvalue())

    def test_the_collection_without_a_burst_takes_the_same_peak(self):
        with tempfile.TemporaryDirectory() as work:
            self.make_run(work)
            with contextlib.redirect_stdout(io.StringIO()):
                times = render_snapshot.render(work, os.path.join(work, "collection.png"))
        # (1) the frame before the peak at the lowest P with particles in (0.1 from 0 to 6000),
        # of those the latest with the least deposited: none before the first deposit (step
        # 500 000: fluid step 5000); (2) the frame nearest the highest peak with particles,
        # (3) the run's last frame.
        self.assertEqual(tuple(times), (4000, 8000, 10000))


class ThermoBlocks(unittest.TestCase):
    def test_a_block_with_fewer_columns_keeps_its_rows(self):
        # A run resumed by a scene that prints a column more: its earlier rows stay, NaN in
        # the new column; a block with a column the last lacks is left out.
        with tempfile.TemporaryDirectory() as work:
            log = os.path.join(work, "log.liggghts")
            with open(log, "w") as f:
                f.write("Step Atoms pore[16]\n100 1 0.1\n200 1 0.2\n")
                f.write("Step Atoms pore[9]\n250 1 7\n")
                f.write("Step Atoms pore[16] pore[35]\n300 1 0.3 -0.5\n")
            header, rows = plot_pressure.read_thermo(log)
        self.assertEqual(header, ["Step", "Atoms", "pore[16]", "pore[35]"])
        self.assertEqual([r[:3] for r in rows], [[100, 1, 0.1], [200, 1, 0.2], [300, 1, 0.3]])
        self.assertTrue(math.isnan(rows[0][3]) and math.isnan(rows[1][3]))
        self.assertEqual(rows[2][3], -0.5)

    def test_a_message_as_long_as_the_header_does_not_end_the_block(self):
        with tempfile.TemporaryDirectory() as work:
            log = os.path.join(work, "log.liggghts")
            with open(log, "w") as f:
                f.write("Step Atoms pore[16]\n100 1 0.1\n")
                f.write("note: three words\n")  # as many words as the header, not numbers
                f.write("200 1 0.2\nLoop time of 1 on 1 procs\n")
            header, rows = plot_pressure.read_thermo(log)
        self.assertEqual(header, ["Step", "Atoms", "pore[16]"])
        self.assertEqual(rows, [[100.0, 1.0, 0.1], [200.0, 1.0, 0.2]])


class BurstSummary(unittest.TestCase):
    def run_summary(self, work, burst_rows, header=BURST_HEADER):
        warm, run = thermo_run()
        log = os.path.join(work, "log.liggghts")
        write_log(log, [warm, run])
        with open(os.path.join(work, "bursts.txt"), "w") as f:
            f.write(header)
            f.writelines(row + "\n" for row in burst_rows)
        with contextlib.redirect_stdout(io.StringIO()) as printed:
            summarize_run.main([log])
        return printed.getvalue().splitlines()

    def test_a_line_per_burst_with_each_deposit_measure(self):
        with tempfile.TemporaryDirectory() as work:
            lines = self.run_summary(work, [
                "730000 7300 0.4 0.15 0.25 60 1.5 0.3 3 1 0 2 0.01 2 1 0.2",
                "950000 9500 0.12 0.1 0.02 40 0.5 0.1 1 0 0 1 0.01 1 0.5 0.1",
                # a resumed run's second record of the first burst replaces it
                "730000 7300 0.4 0.125 0.275 70 1.5 0.3 3 1 0 2 0.01 2 1 0.2",
            ])
        self.assertIn("erosive bursts", lines[1])
        self.assertIn("window: the 1000 fluid steps up to the peak", lines[1])
        bursts = [line for line in lines if line.startswith("burst ")]
        self.assertEqual(len(bursts), 2)
        pattern = (r"burst (\d+): fluid step (\d+), P_peak (\S+) P_out, P_after (\S+) P_out "
                   r"\(fell (\d+) %\); deposit torn off: window largest (\S+), (\S+) \| window median (\S+), (\S+) \| "
                   r"at the peak (\S+), (\S+); at the minimum (\S+) particles$")
        values = [[float(v) for v in re.match(pattern, line).groups()] for line in bursts]
        # The window before 730 000 (630 000 ... 730 000) has 3 deposited at most (V 1.5) until
        # 700 000; before 950 000 (850 000 ... 950 000) 1 (V 0.5).
        self.assertEqual(values[0], [1, 7300, 0.4, 0.125, 69, 3, 1.5, 2, 1, 3, 1.5, 1])
        self.assertEqual(values[1], [2, 9500, 0.12, 0.1, 17, 1, 0.5, 1, 0.5, 1, 0.5, 0])

    def test_an_older_burst_file_says_the_median_is_not_recorded(self):
        old_header = BURST_HEADER.split(" deposit_count")[0] + "\n"
        with tempfile.TemporaryDirectory() as work:
            lines = self.run_summary(work, ["730000 7300 0.4 0.15 0.25 60 1.5 0.3 3 1 0 2 0.01"],
                                     header=old_header)
        (burst,) = [line for line in lines if line.startswith("burst ")]
        self.assertIn("window median not recorded", burst)
        self.assertIn("window largest 3, 1.5 | window median not recorded", burst)

    def test_the_run_line_is_unchanged(self):
        with tempfile.TemporaryDirectory() as work:
            lines = self.run_summary(work, [])
        self.assertTrue(lines[0].endswith(
            "DEM steps 1000000, clean P/P_out 0.1, largest P/P_out with particles 0.4 (4.00 x clean), "
            "largest V_dep 1.5, deposited 3, most wall contacts 0, erosive bursts 0"), lines[0])
        self.assertIn("erosive bursts", lines[1])
        self.assertEqual(len(lines), 2)


if __name__ == "__main__":
    unittest.main()
