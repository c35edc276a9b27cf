"""The realised inlet concentration of the paper's scene (examples/pore/in.pore).

The paper inserts particles at volume fraction c_in; in.pore tops its inlet region I up to c_in
with LIGGGHTS's insert/pack once per time the flow takes to cross the region. The particles
then leave region I at concentration c_in: the particle volume that crosses the inlet plane
(the end of region I, f_pore[12]) per unit time, over u_in W^2, is c_in. The window is a whole
number of top-up periods, starting one period after the first top-up (when the first fill has
crossed the plane), so that it holds whole fills. Topped up every 100 time units instead (as
in.pore did before), the same measure gave twice c_in: the bound below tells the two apart.

Runs at 4 cells per d with n_dem 10 (the insertion is the DEM's; the fluid only carries the
particles at u_in) and c_in 0.1, for 9 periods after a short warm-up.

Usage: PYTHONPATH=tests/harness python3 tests/inlet/inlet_check.py --driver liggghts-lbm \
           --scripts examples/pore concentration_one_rank
"""
import os
import re

import liggghts_run as h

C_IN = 0.1
PERIODS = 8          # whole fills in the window
WARMUP = 3600        # DEM steps of clean flow (200 fluid steps)
THERMO_EVERY = 90    # DEM steps: 5 fluid steps of 18 (n_dem 10 at 4 cells per d)
# Relative. A fill holds about 17 particles whose sizes are drawn (sigma 0.1 d, so about 30 %
# in volume): its volume scatters by about 7 % about c_in's, the mean of 8 fills by 2.5 %.
BOUND = 0.1


def measure(harness, ranks, procs):
    scripts = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "pore")
    # u_lattice 0.02: eight times in.pore's default, so eight fills pass in seconds (the
    # concentration delivered does not depend on the velocity)
    base = dict(cells_per_d=4, n_dem=10, c_in=C_IN, warmup=WARMUP, vtk_every=0, u_lattice=0.02,
                thermo_every=THERMO_EVERY, procs=procs, thermo_extra="f_pore[12] v_u_in v_dt v_W_c")
    # The period in DEM steps is in.pore's own; a short run prints it.
    first = harness.run(os.path.join(scripts, "in.pore"), dict(base, steps=THERMO_EVERY), ranks=ranks)
    match = re.search(r"^insertion: region I topped up to c_in \S+ every (\d+) DEM steps", first.output, re.M)
    if not match:
        h.check("in.pore prints its insertion period", False, "no 'insertion:' line", "the line")
        return
    period = int(match[1])
    run = harness.run(os.path.join(scripts, "in.pore"), dict(base, steps=(PERIODS + 1) * period),
                      ranks=ranks, timeout=560)
    rows = h.thermo_rows(run.output)
    start, end = WARMUP + period, WARMUP + (PERIODS + 1) * period

    def nearest(step):
        return min(rows, key=lambda r: abs(r["Step"] - step))

    a, b = nearest(start), nearest(end)
    elapsed = (b["Step"] - a["Step"]) * a["dt"]
    realised = (b["pore[12]"] - a["pore[12]"]) / (elapsed * a["u_in"] * a["W_c"] ** 2)
    print(f"{ranks} rank(s), procs {procs}: top-up every {period} DEM steps; "
          f"{b['pore[4]'] - a['pore[4]']:.0f} particles, volume {b['pore[12]'] - a['pore[12]']:.3f} "
          f"crossed the inlet plane in {elapsed:.0f} time units")
    h.check(f"realised inlet concentration over c_in ({ranks} rank(s))",
            abs(realised / C_IN - 1.0) <= BOUND, f"{realised:.4f} / {C_IN} = {realised / C_IN:.3f}",
            f"1 +- {BOUND}")


def concentration_one_rank(harness):
    measure(harness, 1, "1 1 1")


def concentration_two_ranks(harness):
    # Split across the flow: both ranks insert into their half of region I.
    measure(harness, 2, "1 * 1")


def bad_knobs(harness):
    """A negative insertion period or minimum gap, or a deposit speed not above 0, stops
    in.pore with an error naming the knob and its range, before any step."""
    scripts = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "pore")
    for knob, bad, rule, fix in (("insert_period", -1, ">= 0", "at_least_0"), ("min_gap", -1, ">= 0", "at_least_0"),
                                 ("deposit_speed", 0, "> 0", "above_0")):
        run = harness.run(os.path.join(scripts, "in.pore"),
                          {"cells_per_d": 4, "warmup": 100, "steps": 100, "vtk_every": 0, knob: bad},
                          expect_error=True, timeout=60)
        error = h.error_line(run.output)
        said = f"in.pore: {knob} must be {rule}" in run.output and f"{knob}_must_be_{fix}" in error
        h.check(f"negative {knob} is refused", run.code != 0 and said, error or "no ERROR line",
                f"an ERROR naming {knob}, its range printed, exit status not 0")


if __name__ == "__main__":
    h.main({"concentration_one_rank": concentration_one_rank,
            "concentration_two_ranks": concentration_two_ranks, "bad_knobs": bad_knobs}, __doc__)
