"""The test harness shared by the integration checks that run liggghts-lbm on tiny input
scripts (tests/dem_integration/dem_check.py, tests/coupled_runs/coupled_check.py,
tests/stiff/stiff_check.py): run a script with -var arguments under a timeout, read its
thermo rows by column name, and check each measured figure against its bound, printing one
uniform line per check:

    PASS <name>: measured <figure>, bound <bound>
    FAIL <name>: measured <figure>, bound <bound>

A run that should succeed but stops with an error prints the end of its output and an
`ERROR liggghts-lbm failed ...` line, and the check exits 1. CTest puts this folder on
PYTHONPATH (tests/harness/liggghts_checks.cmake); by hand:

    PYTHONPATH=tests/harness python3 tests/stiff/stiff_check.py --driver build/.../liggghts-lbm \
        --scripts tests/stiff near_pore
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

_failures = []


class Run:
    """One finished liggghts-lbm run: exit code, stdout then stderr, and its folder."""

    def __init__(self, code, output, work):
        self.code, self.output, self.work = code, output, work


class Harness:
    """Runs liggghts-lbm for one check case. Every run gets a fresh folder below the case's
    temporary folder (removed at the end) unless the caller names one (a restart reads what
    an earlier run wrote)."""

    def __init__(self, driver, scripts, mpirun, work, liggghts=None):
        self.driver, self.scripts, self.mpirun, self.work = driver, scripts, mpirun, work
        self.liggghts = liggghts  # Debian's liggghts, for the checks against it (or None)
        self._runs = 0

    def run(self, script, variables, ranks=1, cwd=None, expect_error=False, timeout=240,
            program=None):
        """Runs `script` (a file of the scripts folder) with `-var dir <scripts>` and one
        `-var name value` per variable, on `ranks` MPI ranks, with liggghts-lbm or `program`.
        Raises subprocess.TimeoutExpired after `timeout` s. Unless `expect_error`, an exit code
        other than 0 or an ERROR in the output ends the check with exit status 1."""
        if cwd is None:
            self._runs += 1
            cwd = os.path.join(self.work, f"run{self._runs}")
            os.makedirs(cwd)
        cmd = [program or self.driver, "-in", os.path.join(self.scripts, script),
               "-log", os.path.join(cwd, "log.liggghts"), "-var", "dir", self.scripts]
        for name, value in variables.items():
            cmd += ["-var", name, str(value)]
        if ranks > 1:
            cmd = [self.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
        shown = cmd[cmd.index("-in") + 1:]
        if program:
            shown = [f"({os.path.basename(program)})"] + shown
        print("run:", " ".join(shown), flush=True)
        result = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, errors="replace",
                                timeout=timeout, env=mpi_environment())
        run = Run(result.returncode, result.stdout + result.stderr, cwd)
        if not expect_error and (run.code != 0 or "ERROR" in run.output):
            print(run.output[-3000:])
            sys.exit(f"ERROR {os.path.basename(cmd[0])} failed (exit {run.code}): {script} "
                     f"{variables}")
        return run


def mpi_environment(extra=None):
    """The environment of a launch: Open MPI's ranks give the core up while they wait
    (mpi_yield_when_idle). More ranks than cores on a loaded machine otherwise spin on each
    other: measured here, 3 ranks of in.transit on 2 cores beside two study runs did not finish
    in 300 s without it, twice, and took 132 s with it (14 s on idle cores)."""
    return dict(os.environ, OMPI_MCA_mpi_yield_when_idle="1", **(extra or {}))


def thermo_rows(output):
    """All thermo rows of all runs in `output`, each a dict keyed by its block's column names
    without LIGGGHTS's v_/f_/c_ prefixes (it prints some headers with them, some without)."""
    rows, header = [], None
    for line in output.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header = [re.sub(r"^[vfc]_", "", w) for w in words]
            continue
        if header and words and words[0] == "Loop":
            header = None
            continue
        if header and len(words) == len(header):
            try:
                values = [float(w) for w in words]
            except ValueError:
                continue
            rows.append(dict(zip(header, values)))
    return rows


def at_step(rows, step):
    """The first row of `step`."""
    return next(r for r in rows if r["Step"] == step)


def error_line(output):
    """The first line that starts with ERROR, or ''."""
    return next((line for line in output.splitlines() if line.startswith("ERROR")), "")


def has_nan(output):
    return re.search(r"\bnan\b", output, re.IGNORECASE) is not None


def relative_difference(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def check(name, ok, measured, bound):
    """Prints `PASS|FAIL name: measured X, bound Y` and records a failure; returns `ok`.
    The caller computes `ok`, so each check keeps its own comparison (< or <=, relative or
    absolute) next to the text of its bound."""
    ok = bool(ok)
    print(f"{'PASS' if ok else 'FAIL'} {name}: measured {measured}, bound {bound}", flush=True)
    if not ok:
        _failures.append(name)
    return ok


def main(cases, description):
    """Command line of every check script: --driver, --scripts, [--mpirun] and one case name
    out of `cases` (name -> function of a Harness). Exits 1 when any check failed."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--driver", required=True, help="the liggghts-lbm executable")
    parser.add_argument("--scripts", required=True, help="the folder of the input scripts")
    parser.add_argument("--mpirun", default="mpirun", help="for the runs on 2 ranks")
    parser.add_argument("--liggghts", help="Debian's liggghts, for the checks against it")
    parser.add_argument("case", choices=sorted(cases))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix=f"{args.case}_") as work:
        cases[args.case](Harness(os.path.abspath(args.driver), os.path.abspath(args.scripts),
                                 args.mpirun, work, args.liggghts))
    if _failures:
        sys.exit(f"{len(_failures)} check(s) failed: {', '.join(_failures)}")
