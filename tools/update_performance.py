#!/usr/bin/env python3
"""Runs lbm-pore's benchmarks and rewrites their tables, doc/performance/<benchmark>.md.

    tools/update_performance.py                      # every benchmark (about 20 minutes on 2 cores)
    tools/update_performance.py bench_lbm bench_coupled       # only these
    tools/update_performance.py --build-dir build-native bench_lbm
    build/tests/bench/lbm/bench_lbm | tools/update_performance.py --from-log - bench_lbm

Each benchmark (a CMake target `bench_<what>`, tests/bench/) prints `BENCH <name> <value>
<unit> [note]` lines. The script configures ./build if it is not configured yet (Release),
builds each benchmark's target (the targets bench_paper_run, bench_coupled, bench_dem_substep
and bench_features run their benchmark as they are built; bench_lbm and bench_contact are
programs, run after the build), collects the BENCH lines and writes doc/performance/<benchmark>.md:
the command, the date, the machine and one row per figure, so every table holds one run of
one benchmark on one machine (doc/performance.md says what each figure measures and links
the pages). Figures the run did not print (Palabos not found, one core only, no baseline)
keep a row with "—". Run it on an
otherwise idle machine: the figures are timings.

To record the BENCH lines of one run already made (the same format: a saved log, or `-` for
standard input); --machine and --date describe a run made on another machine or day:

    tools/update_performance.py --from-log run.txt --machine "2-core ... guest, GCC 12.2, Release" \\
        --date 2026-12-02 bench_lbm

--dry-run prints the new blocks instead of writing the page.
"""
import argparse
import datetime
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "doc", "performance.md")  # what each figure measures
TABLES = os.path.join(ROOT, "doc", "performance")  # one generated page per benchmark


def table_page(name):
    return os.path.join(TABLES, f"{name}.md")
BENCH_LINE = re.compile(r"^BENCH (\S+) (\S+) (\S+)(.*)$")

# Goals the benchmarks are held to (their scripts print the same).
GOALS = {
    "paper_run_projected_hours": "<= 0.75",
    "paper_run_steady_projected_hours": "<= 0.75",
    "paper_run_clogged_projected_hours": "<= 0.75",
    "paper_run_paper_projected_hours": "<= 1.0",
    "coupling_fluid_cell_updates_per_link": "<= 3",
    "paper_run_steady_coupling_fluid_cell_updates_per_link": "<= 3",
    "paper_run_clogged_coupling_fluid_cell_updates_per_link": "<= 3",
    "paper_run_paper_coupling_fluid_cell_updates_per_link": "<= 3",
    "coupling_stages_fluid_cell_updates_per_link": "<= 3",
    "coupled_vs_pure_fluid": "<= 1.3",
    "dem_substep_ratio": "<= 1.5",
    "lbm_roofline_ratio": ">= 0.85",
    "lbm_paper_rank_block_1t_roofline_ratio": ">= 0.6",
    "lbm_vs_palabos": ">= 4",
    "no_particles_vs_pure_fluid": "<= 1.1",
    "contact_vs_gran_hooke": "<= 1.2",
}


def lbm_figures():
    figures = [("bytes_per_cell_update", "bytes")]
    for t in (1, 2):
        figures += [(f"stream_copy_bandwidth_{t}t", "GB/s"), (f"stream_copy_streaming_bandwidth_{t}t", "GB/s"),
                    (f"stream_update_bandwidth_{t}t", "GB/s"), (f"lbm_roofline_{t}t", "MLUPS"),
                    (f"stream_copy_19_arrays_bandwidth_{t}t", "GB/s")]
        if t == 1:
            figures.append(("lattice_bytes_per_node", "bytes"))
        for n in (64, 128):
            figures += [(f"lbm_{n}_{t}t", "MLUPS"), (f"lbm_{n}_{t}t_roofline_ratio", "ratio")]
            if n == 128:
                figures.append((f"lbm_128_{t}t_19_array_copy_ratio", "ratio"))
        if t == 1:
            figures += [("lbm_paper_rank_block_1t", "MLUPS"), ("lbm_paper_rank_block_1t_roofline_ratio", "ratio")]
    figures += [("lbm_roofline_ratio", "ratio"), ("palabos_same_case_velocity_difference", "relative"),
                ("lbm_128_1t_palabos_case", "MLUPS"), ("palabos_128_1t", "MLUPS"),
                ("lbm_vs_palabos_min", "ratio"), ("lbm_vs_palabos_max", "ratio"), ("lbm_vs_palabos", "ratio")]
    return figures


def paper_run_figures():
    figures = [("paper_run_projected_hours", "hours"), ("coupling_fluid_cell_updates_per_link", "ratio")]
    parts = ["mapping", "refill", "halo", "static_walls", "moving_walls", "force", "open_faces",
             "collide_stream", "lubrication", "diagnostics", "dem_and_rest"]
    for state in ("steady", "clogged", "paper"):
        name = f"paper_run_{state}"
        figures += [(f"{name}_particles", "count"), (f"{name}_deposited", "count")]
        figures += [(f"{name}_fluid_step_ms{m}", "ms") for m in ("", "_min", "_max")]
        figures += [(f"{name}_{part}_ms", "ms") for part in parts]
        figures += [(f"{name}_links_per_step", "count"), (f"{name}_ns_per_link", "ns"),
                    (f"{name}_links_busiest_rank_vs_mean", "ratio"), (f"{name}_coupling_busiest_rank_vs_mean", "ratio"),
                    (f"{name}_coupling_fluid_cell_updates_per_link", "ratio")]
        figures += [(f"{name}_projected_hours{m}", "hours") for m in ("", "_min", "_max")]
        figures += [(f"{name}_projected_hours{v}", "hours")
                    for v in ("_n_dem_20", "_5_cells_per_d", "_5_cells_per_d_n_dem_20")]
        figures += [(f"{name}_vs_baseline{m}", "ratio") for m in ("", "_min", "_max")]
        if state == "paper":
            figures += [(f"{name}_one_rank_two_threads_vs_two_ranks{m}", "ratio") for m in ("", "_min", "_max")]
            figures += [(f"{name}_side_by_side_runs_per_hour_vs_one_two_rank_run{m}", "ratio")
                        for m in ("", "_min", "_max")]
    return figures


def coupling_stages_figures():
    figures = [(f"coupling_stages_{part}_ms", "ms") for part in
               ("fluid_step", "mapping", "refill", "halo", "moving_walls", "force", "collide_stream")]
    figures.append(("coupling_stages_links_per_step", "count"))
    figures += [(f"coupling_stages_ns_per_link{m}", "ns") for m in ("", "_min", "_max")]
    figures += [(f"coupling_stages_fluid_cell_updates_per_link{m}", "ratio") for m in ("", "_min", "_max")]
    return figures


def coupled_figures():
    seconds = ["pure_fluid_step_s", "coupled_step_s", "coupled_fluid_s", "coupled_coupling_s", "coupled_dem_s",
               "warmup_pure_fluid_step_s"]
    ratios = ["coupled_vs_pure_fluid_min", "coupled_vs_pure_fluid_max", "coupled_vs_pure_fluid",
              "coupled_dem_vs_pure_fluid", "coupled_fluid_and_coupling_vs_pure_fluid"]
    return [(n, "s") for n in seconds] + [("particles", "count")] + [(n, "ratio") for n in ratios]


def dem_substep_figures():
    figures = []
    for case in ("stock", "stock_touching", "lbm", "smooth"):
        figures.append((f"dem_substep_{case}_us", "us"))
        parts = ["pair", "neigh", "comm", "output", "modify_other"] + (["lubrication"] if not case.startswith("stock") else [])
        figures += [(f"dem_substep_{case}_{part}_us", "us") for part in parts]
        figures.append((f"dem_substep_{case}_pair_contacts", "count"))
    for suffix in ("_smooth", "_fewer_contacts", ""):
        figures += [(f"dem_substep_ratio{suffix}{m}", "ratio") for m in ("_min", "_max", "")]
    return figures


def features_figures():
    figures = []
    for feature in ("cohesion", "adhesion", "friction", "lubrication", "fluid_output"):
        figures += [(f"{feature}_off_step", "s"), (f"{feature}_on_step", "s"), (f"{feature}_on_vs_off", "ratio")]
    return figures + [("pure_fluid_step", "s"), ("no_particles_fluid_step", "s"),
                      ("no_particles_vs_pure_fluid", "ratio")]


def contact_figures():
    return [("particles", "count"), ("steps", "count"), ("ranks", "count"),
            ("lbm_dashdot_step", "ns/particle-step"), ("gran_hooke_step", "ns/particle-step"),
            ("lbm_dashdot_pair", "ns/particle-step"), ("gran_hooke_pair", "ns/particle-step"),
            ("wall_voxel_search", "ns/particle-step"), ("contact_vs_gran_hooke", "ratio"),
            ("contact_vs_gran_hooke_pair_only", "ratio")]


# name -> (figures, program to run after the build (relative to the build folder) or None
# when building the target runs the benchmark)
BENCHMARKS = {
    "bench_lbm": (lbm_figures(), "tests/bench/lbm/bench_lbm"),
    "bench_paper_run": (paper_run_figures(), None),
    "bench_coupled": (coupled_figures(), None),
    "bench_dem_substep": (dem_substep_figures(), None),
    "bench_features": (features_figures(), None),
    "bench_contact": (contact_figures(), "tests/bench/contact/bench_contact"),
    "bench_coupling_stages": (coupling_stages_figures(), "tests/bench/coupling_stages/bench_coupling_stages"),
}


def command_of(name):
    program = BENCHMARKS[name][1]
    build = f"cmake --build build --target {name}"
    return f"{build} && build/{program}" if program else build


def run_logged(cmd, env):
    """Runs cmd, echoing its output, and returns the output."""
    print("+ " + " ".join(cmd), flush=True)
    proc = subprocess.Popen(cmd, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, errors="replace")
    lines = []
    for line in proc.stdout:
        sys.stdout.write(line)
        lines.append(line)
    if proc.wait() != 0:
        sys.exit(f"update_performance: {' '.join(cmd)} failed (exit {proc.returncode})")
    return "".join(lines)


def run_benchmark(name, build_dir):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    out = run_logged(["cmake", "--build", build_dir, "--target", name], env)
    program = BENCHMARKS[name][1]
    if program:
        out = run_logged([os.path.join(build_dir, program)], env)
    return out


def parse(text):
    """BENCH lines -> {name: (value, unit, note)}; a later line of the same name wins."""
    figures = {}
    for line in text.splitlines():
        m = BENCH_LINE.match(line.strip())
        if m:
            figures[m[1]] = (m[2], m[3], m[4].strip())
    return figures


def cache_value(build_dir, key):
    try:
        with open(os.path.join(build_dir, "CMakeCache.txt")) as f:
            for line in f:
                if line.startswith(key + ":"):
                    return line.split("=", 1)[1].strip()
    except OSError:
        pass
    return ""


def describe_machine(build_dir):
    """CPU model, cores, virtualisation, last-level cache; compiler and build settings."""
    model = ""
    hypervisor = False
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name") and not model:
                    model = line.split(":", 1)[1].strip()
                if line.startswith("flags") and " hypervisor" in line:
                    hypervisor = True
    except OSError:
        pass
    virt = ""
    try:
        kind = subprocess.run(["systemd-detect-virt"], capture_output=True, text=True).stdout.strip()
        virt = f", {kind.upper()} guest" if kind and kind != "none" else ""
    except OSError:
        virt = ", virtual machine" if hypervisor else ""
    cache = ""
    index3 = "/sys/devices/system/cpu/cpu0/cache/index3/size"
    if os.path.exists(index3):
        with open(index3) as f:
            cache = f", {f.read().strip()} L3"
    compiler = cache_value(build_dir, "CMAKE_CXX_COMPILER")
    version = ""
    if compiler:
        try:
            version = subprocess.run([compiler, "-dumpfullversion"], capture_output=True,
                                     text=True).stdout.strip()
        except OSError:
            pass
    build = cache_value(build_dir, "CMAKE_BUILD_TYPE") or "?"
    native = ", -march=native" if cache_value(build_dir, "LBM_PORE_NATIVE") in ("ON", "TRUE", "1") else ""
    single = ", single precision" if cache_value(build_dir, "LBM_PORE_SINGLE_PRECISION") == "ON" else ""
    return (f"{model or 'unknown CPU'} ({os.cpu_count()} cores{virt}{cache}); "
            f"{os.path.basename(compiler) or 'compiler'} {version}, {build}{native}{single}")


def block(name, figures, date, machine):
    lines = [f"<!-- performance:{name}:begin (written by tools/update_performance.py) -->",
             f"`{command_of(name)}`: measured {date} on {machine}.", "",
             "| figure | value [min, max of the rounds] | unit | goal | note |", "|---|---|---|---|---|"]
    known = BENCHMARKS[name][0]
    names = [n for n, _ in known] + [n for n in figures if n not in dict(known)]
    units = dict(known)
    # A figure's spread (<figure>_min, <figure>_max) goes into its own row.
    spread = {n for n in names if n.endswith(("_min", "_max")) and n[:-4] in names}
    for n in names:
        if n in spread:
            continue
        value, unit, note = figures.get(n, ("—", units.get(n, ""), ""))
        low, high = (figures.get(n + m, ("—",))[0] for m in ("_min", "_max"))
        if n + "_min" in spread and (low, high) != ("—", "—"):
            value = f"{value} [{low}, {high}]"
        note = note.strip("() ")
        if note.startswith("goal"):
            note = ""  # the goal column says it
        lines.append(f"| `{n}` | {value} | {unit} | {GOALS.get(n, '')} | {note} |")
    lines.append(f"<!-- performance:{name}:end -->")
    return "\n".join(lines)


def write_table(name, new):
    """The benchmark's page: a title, the way back to what its figures measure, the table."""
    os.makedirs(TABLES, exist_ok=True)
    with open(table_page(name), "w") as f:
        f.write(f"# `{name}`: its figures\n\nWhat each figure measures, and the findings drawn from "
                f"them: [../performance.md](../performance.md). This page is written by "
                f"`tools/update_performance.py`.\n\n{new}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("benchmarks", nargs="*", help=f"default: all of {', '.join(BENCHMARKS)}")
    parser.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    parser.add_argument("--from-log", help="take the BENCH lines from this file ('-': standard input) "
                                           "instead of running")
    parser.add_argument("--machine", help="machine description (default: read from this machine)")
    parser.add_argument("--date", help="date of the measurement (default: today, UTC)")
    parser.add_argument("--dry-run", action="store_true", help="print the blocks, do not write the page")
    args = parser.parse_args()
    names = args.benchmarks or list(BENCHMARKS)
    unknown = [n for n in names if n not in BENCHMARKS]
    if unknown:
        sys.exit(f"update_performance: unknown benchmark(s) {unknown}; known: {list(BENCHMARKS)}")
    build_dir = os.path.abspath(args.build_dir)
    if args.from_log and len(names) != 1:
        sys.exit("update_performance: --from-log takes the lines of one benchmark; name it")
    if args.from_log == "-":
        logged = sys.stdin.read()
    elif args.from_log:
        with open(args.from_log) as f:
            logged = f.read()
    elif not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        run_logged(["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release"], dict(os.environ))
    date = args.date or datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d")
    machine = args.machine or describe_machine(build_dir)
    for name in names:
        text = logged if args.from_log else run_benchmark(name, build_dir)
        figures = parse(text)
        if not figures:
            sys.exit(f"update_performance: {name} printed no BENCH line")
        new = block(name, figures, date, machine)
        if args.dry_run:
            print(new)
        else:  # after each benchmark, so a later failure loses nothing
            write_table(name, new)
            print(f"update_performance: {name}: {len(figures)} figures written to "
                  f"{os.path.relpath(table_page(name), ROOT)}")


if __name__ == "__main__":
    main()
