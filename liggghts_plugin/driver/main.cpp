// liggghts-lbm: a drop-in for Debian's `liggghts` executable that also knows this project's
// styles. Same command line (-in, -var, -log, -echo, -screen, -partition, ...), parsed by
// LAMMPS_NS::LAMMPS itself; serial or under mpirun. The only difference to LIGGGHTS's own
// main() is the call to register_lbm_pore_styles() before the input runs.
#include <mpi.h>

#include <csignal>
#include <cstring>

#include "input.h"
#include "lammps.h"
#include "registry/style_registry.h"
#include "signal_handling.h"

int main(int argc, char** argv) {
  // As in LIGGGHTS's main: SIGINT/SIGTERM ask for a clean stop, SIGUSR1 for a restart file.
  struct sigaction int_action, usr1_action;
  std::memset(&int_action, 0, sizeof(int_action));
  std::memset(&usr1_action, 0, sizeof(usr1_action));
  int_action.sa_handler = LAMMPS_NS::SignalHandler::int_handler;
  sigaction(SIGINT, &int_action, nullptr);
  sigaction(SIGTERM, &int_action, nullptr);
  usr1_action.sa_handler = LAMMPS_NS::SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &usr1_action, nullptr);

  MPI_Init(&argc, &argv);
  auto* lammps = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  lbm_pore::register_lbm_pore_styles(lammps);
  lammps->input->file();
  delete lammps;
  MPI_Finalize();
  return 0;
}
