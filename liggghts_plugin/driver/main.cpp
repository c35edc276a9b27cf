// liggghts-lbm: a drop-in for Debian's `liggghts` executable that also knows this project's
// styles. Same command line (-in, -var, -log, -echo, -screen, -partition, ...), parsed by
// LAMMPS_NS::LAMMPS itself; serial or under mpirun. Differences to LIGGGHTS's own main():
// register_lbm_pore_styles() before the input runs, the project's version under LIGGGHTS's in
// the header of the screen and log, stop signals that fix lbm/pore takes at a fluid step
// (plugin_common/stop_signals.h), and an error that stays the last line of the output
// (line-buffered stdout, no Open MPI abort notice, no LIGGGHTS-PUBLIC joke line: its restart
// files stay LIGGGHTS's own all the same, plugin_common/restart_version.h).
#include <mpi.h>

#include <cstdio>
#include <cstdlib>

#include <unistd.h>

#include "input.h"
#include "lammps.h"
#include "plugin_common/restart_version.h"
#include "plugin_common/stop_run.h"
#include "plugin_common/stop_signals.h"
#include "registry/style_registry.h"
#include "universe.h"

namespace {

// The line under LIGGGHTS's "LIGGGHTS (Version ...)", where LIGGGHTS writes that: the screen
// and log of the run, or of the universe and of each partition with -partition.
void print_project_version(LAMMPS_NS::LAMMPS* lammps) {
  const char* line = "liggghts-lbm " LBM_PORE_VERSION
                     " (lbm-pore: fix lbm/pore, fix wall/voxel, pair_style lbm/dashdot, "
                     "compute lbm/bonds, fix insert/pack/gap)\n";
  LAMMPS_NS::Universe* universe = lammps->universe;
  if (universe->me == 0 && universe->nworlds > 1)
    lbm_pore::print_to_screen_and_log(universe->uscreen, universe->ulogfile, line);
  int rank = 0;
  MPI_Comm_rank(lammps->world, &rank);
  if (rank == 0) lbm_pore::print_to_screen_and_log(lammps->screen, lammps->logfile, line);
}

// On ranks other than 0, LIGGGHTS 3.8's screen is stdout too, written only for errors
// (Error::one), while its read_restart also printf()s "version 3 8" on every rank, which
// mpirun may forward after rank 0's ERROR line. The screen keeps the terminal through its
// own FILE; plain stdout, where only such stray prints land, goes to /dev/null.
void drop_stray_output_of_other_ranks(LAMMPS_NS::LAMMPS* lammps) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) return;
  FILE* terminal = fdopen(dup(STDOUT_FILENO), "w");
  if (!terminal) return;
  std::setvbuf(terminal, nullptr, _IOLBF, BUFSIZ);
  if (lammps->screen == stdout) lammps->screen = terminal;
  if (lammps->universe->uscreen == stdout) lammps->universe->uscreen = terminal;
  if (!std::freopen("/dev/null", "w", stdout)) std::fputs("liggghts-lbm: stdout kept\n", stderr);
}

}  // namespace

int main(int argc, char** argv) {
  // As in LIGGGHTS's main: SIGINT/SIGTERM ask for a clean stop, SIGUSR1 for a restart file
  // (LIGGGHTS's handlers; a rank's late copy of an agreed stop is not a second one).
  lbm_pore::install_stop_signal_handlers();

  // MPI's helper threads start blocking them: a signal sent to the process is taken by the
  // main thread, which fix lbm/pore lets take it only at a fluid step (stop_signals.h).
  lbm_pore::block_stop_signals();
  // Open MPI prints its "MPI_ABORT was invoked" notice from the aborting process after the
  // error that caused it; quiet (unless the user set it) so the project's ERROR is the last
  // line. mpirun's own notices on a non-zero exit need `mpirun -q`
  // (liggghts_plugin/doc/liggghts_lbm.txt).
  setenv("OMPI_MCA_orte_execute_quiet", "1", /*overwrite=*/0);
  // The fluid's halo messages between ranks on one node are 70-600 kB a step (the paper's
  // lattice). Open MPI sends such messages by its single-copy mechanism (CMA), which pins
  // the pages on every message; its copy through the shared-memory buffers took 30 % less
  // time in the halo stage on the paper scene (2 ranks; doc/performance.md, "Running on
  // several cores").
  // Unless the user chose otherwise.
  setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", /*overwrite=*/0);
  MPI_Init(&argc, &argv);
  lbm_pore::unblock_stop_signals();
  // An error on one rank ends in MPI_Abort, which does not flush stdio: line buffering lets
  // LIGGGHTS's "ERROR on proc N" reach a redirected screen (a batch job's output file).
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  auto* lammps = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  print_project_version(lammps);
  drop_stray_output_of_other_ranks(lammps);
  lbm_pore::register_lbm_pore_styles(lammps);
  lbm_pore::keep_restart_files_stock(lammps);
  lammps->input->file();
  delete lammps;
  MPI_Finalize();
  return 0;
}
