#include "plugin_common/stop_signals.h"

#include <pthread.h>

#include <csignal>

#include "signal_handling.h"

namespace lbm_pore {
namespace {

sigset_t stop_signal_set() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGUSR1);
  return set;
}

}  // namespace

void block_stop_signals() {
  const sigset_t set = stop_signal_set();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

void unblock_stop_signals() {
  const sigset_t set = stop_signal_set();
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

void take_stop_requests(MPI_Comm world) {
  // A signal pending on the process is delivered to this thread, the only one that does
  // not block it, before pthread_sigmask returns.
  unblock_stop_signals();
  block_stop_signals();
  namespace handler = LAMMPS_NS::SignalHandler;
  int flags[2] = {handler::request_quit ? 1 : 0, handler::request_write_restart ? 1 : 0};
  MPI_Allreduce(MPI_IN_PLACE, flags, 2, MPI_INT, MPI_MAX, world);
  handler::request_quit = flags[0] != 0;
  handler::request_write_restart = flags[1] != 0;
}

}  // namespace lbm_pore
