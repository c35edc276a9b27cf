"""The paper's studies as lists of runs: one entry per figure of Jaeger, Mendoza & Herrmann,
each a set of runs of examples/pore/in.pore (the paper's scene and table, lengths in particle
diameters d) that differ in a seed or a swept knob, in three sizes:

  tiny   seconds per run: the CTest of the machinery (nothing physical to read from it)
  quick  2 cores, at most ~30 minutes per study: 5 cells per d instead of 7.1 (drag on a
         resolved sphere about 6 % low, doc/accuracy.md table 2, against 2.6 % at 8 cells),
         fewer seeds and points, 2-4 % of the paper's run length. in.pore coarsens by
         acoustic scaling (its header): the fluid step grows to 1.42, tau to 0.852, so the
         viscosity, the inlet speed, P_out and the DEM step stay the paper's
  paper  the paper's resolution (7.1 cells per d) and run length (10^6 fluid steps), in the
         regime the calibration chose (PAPER_REGIME), on seeds the examples do not use
         (STUDY_SEEDS); the phase diagrams and conc as long, by their length rule
         (PHASE_DIAGRAM_STEPS); N_DEM 100 DEM steps per fluid step for porediameter and
         dropvol, STUDY_N_DEM for the studies begun after the settings study's verdict.
         The counts are what two cores can afford, at least those doc/paper.md's criteria
         need, not the paper's (80 runs for porediameter alone, some 950 core-hours)

A run is (name, knobs): the knobs are in.pore's -var names with their values. Lengths go
through `scene`, which rounds them to whole cells of 1 / cells_per_d, as fix lbm/pore needs.
"""
import math

# The paper's scene (Fig. 1, appendix): D = 3.52, L = 4.23; the inlet, free and outlet regions
# and the width are this project's (in.pore's header): W / D keeps inlet area / pore area 3.3.
PAPER = dict(D=3.52, Lp=4.23, Li=2.82, Lf=2.82, Lo=2.82, W_over_D=5.63 / 3.52)

# The paper's lists (appendix; Results)
PORE_LENGTHS = [0.14, 0.70, 1.41, 2.11, 2.82, 3.52, 4.23, 4.93, 5.63, 6.34, 7.04, 7.75]
PORE_DIAMETERS = [1.76, 2.11, 2.82, 3.52, 4.23, 5.28, 6.34, 7.04]

# The regime the calibration chose for the paper-size runs (doc/calibration.md, "The choice"):
# the paper's Eq. 2 read literally (the reference pressure kept) and the inlet velocity at
# which its deposits grow to the paper's 20-40 particles and are held as its force balance
# says; in.pore's defaults are this regime too. The tiny and quick sizes are smoke tests of
# the machinery: they run at u_lattice 0.02 with the reference pressure removed, where a run
# of minutes clogs the pore and bursts (deposits of a few particles, not the paper's).
PAPER_REGIME = dict(u_lattice=0.0025, reference_pressure="keep")
SMOKE_REGIME = dict(u_lattice=0.02, reference_pressure="remove")

SIZES = {
    # cells per d, DEM steps with particles, warm-up DEM steps, thermo and VTK intervals
    # tiny: the burst detector flags falls of 0.3 % within 20 fluid steps, without a deposit
    # (burst_deposits 0), so that seconds-long runs have burst rows for the analyses to read
    # (not erosive bursts: flow wiggles)
    "tiny": dict(cells_per_d=4, steps=30000, warmup=2000, thermo_every=500, vtk_every=100,
                 burst_drop=0.003, burst_window=20, burst_deposits=0, **SMOKE_REGIME),
    # quick and paper: 2000 fluid steps of warm-up, past the start-up transient of the flow
    "quick": dict(cells_per_d=5, steps=2000000, warmup=200000, thermo_every=2000, vtk_every=0,
                  **SMOKE_REGIME),
    "paper": dict(cells_per_d=7.1, steps=100000000, warmup=200000, thermo_every=1000,
                  vtk_every=0, **PAPER_REGIME),
}

# Measured on a 2-core VM shared with other jobs, two runs at a time, one core each: the 22
# finished runs of the quick studies (5 cells per d, 142 DEM substeps per fluid
# step, 30-180 particles) took 0.7e-7 to 2.8e-7 core-seconds per lattice cell and fluid step,
# 1.8e-7 over all of them (the DEM substeps included: the more particles, the dearer); the
# paper's scene (90 x 40 x 40 at 7.1 cells per d) then costs about 7 core-hours per 10^6
# fluid steps, as bench_paper_run measured then (its current figure: doc/performance.md).
CORE_SECONDS_PER_CELL_STEP = 1.8e-7
N_DEM = 100  # DEM steps per fluid step at the paper's resolution (in.pore's n_dem)
# The share of that cost the DEM substeps take at N_DEM: the settings study's runs at the
# paper size cost a median 0.66 as much at N_DEM 20 as at 100 (0.73 against 1.10 core-hours
# per 2 x 10^5 fluid steps), so the cost is 0.57 + 0.43 n_dem / N_DEM of N_DEM's.
DEM_COST_SHARE = 0.43
# The DEM substeps per fluid step of the studies at the paper size, by the settings study's
# rule (doc/paper.md, "The studies' settings"): over five seeds N_DEM 20's burst counts,
# deposits and P_max lay within N_DEM 100's spread. porediameter and the runs dropvol takes
# beside its own were made at N_DEM 100 before the verdict and keep it: a fit mixes no N_DEM.
STUDY_N_DEM = 20
PAPER_CELLS_PER_D = 7.1


def dem_steps_per_fluid_step(cells_per_d, n_dem=N_DEM):
    """in.pore's n_dem_used: the fluid step is 7.1 / cells_per_d of the paper's (acoustic
    scaling), the DEM step stays 1 / n_dem of the paper's fluid step."""
    return int(math.floor(float(n_dem) * PAPER_CELLS_PER_D / float(cells_per_d) + 0.5))


def run_dem_steps_per_fluid_step(knobs):
    """dem_steps_per_fluid_step of a run's knobs (in.pore's n_dem knob, N_DEM if not set)."""
    return dem_steps_per_fluid_step(knobs["cells_per_d"], knobs.get("n_dem", N_DEM))


def cells(length, cells_per_d):
    return max(1, int(round(length * cells_per_d)))


def scene(cells_per_d, D=PAPER["D"], Lp=PAPER["Lp"], W=None):
    """in.pore's length knobs for a pore of diameter D and length Lp, every length a whole
    number of cells; W scales with D (inlet area / pore area as in the default scene)."""
    W = PAPER["W_over_D"] * D if W is None else W
    lengths = dict(D=D, Lp=Lp, W=W, Li=PAPER["Li"], Lf=PAPER["Lf"], Lo=PAPER["Lo"])
    return {k: f"{cells(v, cells_per_d) / cells_per_d:.10g}" for k, v in lengths.items()}


def lattice_cells(knobs):
    c = float(knobs["cells_per_d"])
    x = sum(cells(float(knobs[k]), c) for k in ("Li", "Lf", "Lp", "Lo"))
    return x * cells(float(knobs["W"]), c) ** 2


def core_hours(runs, ranks_per_run=1):
    """Estimated cost of the runs in core-hours, from CORE_SECONDS_PER_CELL_STEP (a run on
    more ranks costs about the same core-hours, a little more for the halo exchange)."""
    total = 0.0
    for _, knobs in runs:
        n_dem = run_dem_steps_per_fluid_step(knobs)
        fluid_steps = (int(knobs["steps"]) + int(knobs["warmup"])) / n_dem
        dem_factor = 1.0 - DEM_COST_SHARE + DEM_COST_SHARE * float(knobs.get("n_dem", N_DEM)) / N_DEM
        total += fluid_steps * lattice_cells(knobs) * CORE_SECONDS_PER_CELL_STEP * dem_factor
    return total / 3600.0


def _is_prime(n):
    return n > 1 and all(n % f for f in range(2, int(math.isqrt(n)) + 1))


def _seeds(n, first=100003):
    """n insertion seeds: the first prime at or above first + 1000 k (LIGGGHTS's insertion
    fixes want primes above 10000)."""
    seeds = []
    for k in range(n):
        s = first + 1000 * k
        while not _is_prime(s):
            s += 1
        seeds.append(s)
    return seeds


def _base(size, **extra):
    knobs = dict(SIZES[size])
    knobs.update(scene(knobs["cells_per_d"]))
    knobs.update(extra)
    return knobs


def _counts(size, tiny, quick, paper):
    return {"tiny": tiny, "quick": quick, "paper": paper}[size]


def singlejump(size):
    return [("seed_100003", _base(size, seed=100003))]


def collection(size):
    # the run of singlejump with fluid and particle VTK files (about 60 of each per run). At
    # the paper size these are 20 000 fluid steps apart, too far to catch a peak: the
    # repository's figure is drawn from a window of a porediameter run replayed with files
    # every 250 fluid steps (replay_window.py; doc/paper.md, "The studies")
    every = {"tiny": 100, "quick": 400, "paper": 20000}[size]
    return [("snapshot", _base(size, seed=100003, vtk_every=every))]


# The paper size's seeds, none of which the examples, the calibration or the settings study
# use (those: 100003 and 101009, 200003-204007, 300007 and 300017): each study its own block.
STUDY_SEEDS = dict(porediameter=400009, porelength=410009, dropvol=420013, phase=430019)

# The phase diagrams' and conc's run at the paper size, in DEM steps after the warm-up: the
# shortest length whose P_max came within 10 % of the paper length's on every paper-length
# run (doc/paper.md, "The studies' settings"; run_length.py). 2.5 x 10^5 fluid steps were
# enough at the default pore, 5 x 10^5 at D 2.11 d; at D 2.82 d P_max still grew after
# 5 x 10^5 (0.75 of its final value), so they run the whole paper length.
PHASE_DIAGRAM_STEPS = 100000000


def _study_seeds(size, study, tiny, quick, paper):
    """The seeds of a study: at the paper size from its STUDY_SEEDS block, else the quick
    sizes' (from 100003)."""
    n = _counts(size, tiny, quick, paper)
    return _seeds(n, first=STUDY_SEEDS[study]) if size == "paper" else _seeds(n)


# The runs of other studies at dropvol's scene, which it takes beside its own seeds at the
# paper size (analyze.py --with; their knobs differ from its plan only in NOT_THE_SCENE's):
# the calibration's paper-length run (seed 100003) and porediameter's two runs at the
# default pore. With them, dropvol's two new seeds make the five seeds its criterion asks.
DROPVOL_BESIDE = ("doc/calibration/paper_run", "doc/paper/porediameter/runs/D_3.52_seed_400009",
                  "doc/paper/porediameter/runs/D_3.52_seed_401017")


def dropvol(size):
    """Every burst at the default pore over seeds; at the paper size two new seeds beside
    the runs of DROPVOL_BESIDE."""
    return [(f"seed_{s}", _base(size, seed=s)) for s in _study_seeds(size, "dropvol", 2, 6, 2)]


def _at_study_n_dem(size, knobs):
    """A run of a study begun after the settings verdict: at the paper size STUDY_N_DEM DEM
    substeps per fluid step, the same physical run."""
    return with_n_dem(knobs, STUDY_N_DEM) if size == "paper" else knobs


def porelength(size):
    # paper: every other of the paper's lengths from 0.70 d (0.70, 2.11, ... 7.75), one seed
    lengths = _counts(size, PORE_LENGTHS[5:7], PORE_LENGTHS[1::2], PORE_LENGTHS[1::2])
    seed, = _study_seeds(size, "porelength", 1, 1, 1)
    runs = []
    for L in lengths:
        knobs = _base(size, seed=seed)
        knobs.update(scene(knobs["cells_per_d"], Lp=L))
        runs.append((f"L_{L:.2f}", _at_study_n_dem(size, knobs)))
    return runs


def porediameter(size):
    # paper: D = 2.11, 2.82, 3.52, 4.23 d, two seeds each, seed-major so that a study cut
    # short has every diameter once (the slope per D, then the slopes against D, needs them)
    diameters = _counts(size, PORE_DIAMETERS[3:5], PORE_DIAMETERS[1::2], PORE_DIAMETERS[1:5])
    seeds = _study_seeds(size, "porediameter", 1, 1, 2)
    runs = []
    for s in seeds:
        for D in diameters:
            # the appendix's L = 4.22 d; in.pore's f_walls[2] (the wall's hold on the
            # particles) gives f_a
            knobs = _base(size, seed=s)
            knobs.update(scene(knobs["cells_per_d"], D=D, Lp=4.22))
            runs.append((f"D_{D:.2f}_seed_{s}", knobs))
    return runs


def _phase_base(size, **knobs):
    """A run of a phase diagram or of conc: at the paper size PHASE_DIAGRAM_STEPS long (in DEM
    steps at N_DEM) and at STUDY_N_DEM, on the phase block's seed."""
    seed, = _study_seeds(size, "phase", 1, 1, 1)
    extra = dict(steps=PHASE_DIAGRAM_STEPS) if size == "paper" else {}
    return _at_study_n_dem(size, _base(size, seed=seed, **extra, **knobs))


def phaseac(size):
    # paper: 3 x 3, k_c over two decades around the table's 0.1
    ka = _counts(size, [0.05, 0.1], [0.03, 0.1, 0.3], [0.03, 0.1, 0.3])
    kc = _counts(size, [0.1], [0.01, 1.0], [0.01, 0.1, 1.0])
    runs = []
    for a in ka:
        for c in kc:
            knobs = _phase_base(size, ka=a, kc=c)
            knobs.update(scene(knobs["cells_per_d"], Lp=6.45))
            runs.append((f"ka_{a:g}_kc_{c:g}", knobs))
    return runs


def phasead(size):
    """The caption's sweep: "since we change here the particle diameter", at L = 1.2 D. The
    pore stays the default's D; the particles' mean diameter d_particle (in the table's unit d,
    which keeps the table's coefficients) is d / D times D."""
    ka = _counts(size, [0.1], [0.03, 0.1, 0.3], [0.03, 0.1])
    d_over_D = _counts(size, [0.25, 0.3], [0.2, 0.36], [0.2, 0.28, 0.36])
    runs = []
    for a in ka:
        for r in d_over_D:
            knobs = _phase_base(size, ka=a, d_particle=f"{r * PAPER['D']:.6g}")
            knobs.update(scene(knobs["cells_per_d"], Lp=1.2 * PAPER["D"]))
            runs.append((f"ka_{a:g}_d_over_D_{r:g}", knobs))
    return runs


def conc(size):
    # paper: around the paper's onset, 0.013, by factors of about two
    values = _counts(size, [0.02, 0.05], [0.0, 0.01, 0.02, 0.05, 0.1],
                     [0.0, 0.005, 0.01, 0.02, 0.05, 0.1])
    # f_pore[12], the particle volume through the inlet plane: the concentration each run
    # realised (figures/conc.py)
    return [(f"c_in_{c:g}", _phase_base(size, c_in=c, thermo_extra="f_pore[12]")) for c in values]


def pvpflux(size):
    """The imposed pressure loss as a ceiling on in.pore's inlet velocity (P_max: the pore fills
    at u_in, the loss is then held at P_max): the loss alone through the empty pore, 0.0093 P_out
    at u_in at the paper size, would drive it 11-54 times faster, past the lattice's limit
    (doc/paper.md, "pvpflux"). f_pore[37] is the inlet velocity the ceiling leaves."""
    pressures = _counts(size, [0.1, 0.4], [0.1, 0.2, 0.3, 0.35, 0.4, 0.5],
                        [0.1, 0.2, 0.3, 0.35, 0.4, 0.5])
    return [(f"P_{p:g}", _phase_base(size, ka=0.05, P_max=p,
                               thermo_extra="f_pore[3] f_pore[13] f_pore[37]")) for p in pressures]


def with_n_dem(knobs, n_dem):
    """The same run with n_dem DEM steps per fluid step instead of N_DEM: the DEM step is
    N_DEM / n_dem times longer, so the DEM step counts (run length, warm-up, thermo interval)
    shrink by n_dem / N_DEM for the same physical time and the same thermo rows."""
    out = dict(knobs, n_dem=n_dem)
    for key in ("steps", "warmup", "thermo_every"):
        out[key] = int(knobs[key]) * n_dem // N_DEM
    return out


def calibration(size):
    """The inlet velocity, which the paper does not give: the table's scene at the paper's
    resolution, u_lattice from 0.02 down, two seeds each (seed-major order, so that a study
    cut short has every velocity once). Thermo rows every 10 fluid steps, with in.pore's
    wall force along the flow (f_walls[2]) and the fluid's on the particles (f_pore[14]), to
    read the hold at each pressure peak. quick: 2 x 10^5 fluid steps per run, and u_lattice
    0.00125 over 4 x 10^5; paper: 10^6.
    Beside them (quick and paper), the runs at u_lattice 0.005 again with N_DEM = 20 DEM
    substeps per fluid step instead of 100 (names ending in _n_dem_20): whether the
    statistics depend on N_DEM, which the paper sets for stability and cost only; and at 5
    cells per d instead of 7.1 (_5_cells_per_d, also at u_lattice 0.0025, where the deposits
    come nearest the paper's): whether the quick studies' resolution keeps them. And, at 5
    cells per d (a third of the cost; the deposits as at 7.1), the model's
    open points each switched alone (MODEL_TWINS: names ending in _5_cells_per_d_<point>),
    to choose their defaults by measurement."""
    velocities = _counts(size, [0.02, 0.005], [0.02, 0.01, 0.005, 0.0025], [0.02, 0.01, 0.005, 0.0025])
    seeds = _seeds(_counts(size, 1, 2, 2))
    lengths = {"tiny": {}, "quick": dict(cells_per_d=7.1, steps=20000000, warmup=200000),
               "paper": dict(cells_per_d=7.1)}[size]
    runs = []
    for seed in seeds:
        for u in velocities:
            # the deposit bound these runs were made with, a tenth of each one's inlet velocity
            # (d per time unit: u_in = u_lattice / 7.1), so that the tables repeat
            knobs = _base(size, seed=seed, u_lattice=u,
                          deposit_speed=f"{0.1 * u / PAPER_CELLS_PER_D:.6g}", **lengths)
            knobs.update(scene(knobs["cells_per_d"]))
            if size != "tiny":
                knobs["thermo_every"] = 1000
            runs.append((f"u_{u:g}_seed_{seed}", knobs))
    # Slower still (quick), at the particle load through the pore of 2 x 10^5 fluid steps at
    # 0.0025 (the inlet flux is proportional to u_in): whether the deposits grow longer before
    # they tear off, as they did from 0.005 to 0.0025.
    for seed in seeds:
        for u in _counts(size, [], [0.00125], []):
            knobs = next(k for name, k in runs if name == f"u_0.0025_seed_{seed}")
            runs.append((f"u_{u:g}_seed_{seed}", dict(knobs, u_lattice=u, steps=2 * knobs["steps"],
                                                      deposit_speed=f"{0.1 * u / PAPER_CELLS_PER_D:.6g}")))

    def coarse(u, seed):
        """The same physical run at 5 cells per d (in.pore's acoustic scaling keeps the DEM
        step counts): the quick studies' resolution."""
        knobs = dict(next(k for name, k in runs if name == f"u_{u:g}_seed_{seed}"), cells_per_d=5)
        knobs.update(scene(5))
        return knobs

    for seed in seeds:
        for u in _counts(size, [], [0.005], [0.005]):
            knobs = dict(next(k for name, k in runs if name == f"u_{u:g}_seed_{seed}"))
            runs.append((f"u_{u:g}_seed_{seed}_n_dem_20", with_n_dem(knobs, 20)))
            runs.append((f"u_{u:g}_seed_{seed}_5_cells_per_d", coarse(u, seed)))
            for point, change in MODEL_TWINS:
                runs.append((f"u_{u:g}_seed_{seed}_5_cells_per_d_{point}", dict(coarse(u, seed), **change)))
    # The resolution again at the velocity whose deposits come nearest the paper's.
    for seed in seeds:
        for u in _counts(size, [], [0.0025], [0.0025]):
            runs.append((f"u_{u:g}_seed_{seed}_5_cells_per_d", coarse(u, seed)))
    return runs


def settings(size):
    """The studies' settings measured in the chosen regime (in.pore's defaults: u_lattice
    0.0025, the reference pressure kept): N_DEM = 100 DEM substeps per fluid step (the
    paper's) against 20, on five seeds the examples do not use, 2 x 10^5 fluid steps each at
    the paper size (three first; three seeds' spread proved narrower than one seed's own
    variation, doc/paper.md). If the largest deposits, the highest pressure peaks and the
    burst counts agree within the seeds' spread, the studies may use the cheaper
    (figures/settings.py)."""
    lengths = {"tiny": {}, "quick": dict(steps=2000000),
               "paper": dict(steps=20000000 - 200000)}[size]
    runs = []
    for seed in _seeds(_counts(size, 1, 2, 5), first=200003):
        knobs = _base(size, seed=seed, **lengths)
        runs.append((f"seed_{seed}", knobs))
        runs.append((f"seed_{seed}_n_dem_20", with_n_dem(knobs, 20)))
    return runs


# The model's open points (doc/calibration.md), each as the knobs that switch it from in.pore's
# default. deposit_region and deposit_speed change what counts, not the physics: their twins
# repeat the base run's trajectory and count the deposits inside the pore alone, or every
# bonded particle slower than half of u_in (in.pore's default: 0.1408 d per 1000 time units).
# (in.pore inserts with the paper's min_gap 0.25; its twin inserts without a distance. Study
# folders made while the default was 0 hold the other way round: a base at 0 and a twin
# `_min_gap` at 0.25.)
MODEL_TWINS = (("no_gap", {"min_gap": 0}),
               ("keep_pressure", {"reference_pressure": "keep"}),
               ("fraction", {"substep_force": "fraction"}),
               ("pore_deposits", {"deposit_region": "pore"}),
               # half the inlet velocity at u_lattice 0.005 (the twins' velocity), in d per time
               # unit: u_in = u_lattice / 7.1 at any cells per d (in.pore's acoustic scaling)
               ("slow_deposits", {"deposit_speed": 0.5 * 0.005 / PAPER_CELLS_PER_D}))


STUDIES = {f.__name__: f for f in (singlejump, collection, dropvol, porelength, porediameter,
                                   phaseac, phasead, conc, pvpflux, calibration, settings)}


def runs_of(study, size):
    if study not in STUDIES:
        raise KeyError(f"unknown study {study!r}; known: {', '.join(STUDIES)}")
    if size not in SIZES:
        raise KeyError(f"unknown size {size!r}; known: {', '.join(SIZES)}")
    return STUDIES[study](size)


def pore_area(knobs):
    return math.pi * float(knobs["D"]) ** 2 / 4
