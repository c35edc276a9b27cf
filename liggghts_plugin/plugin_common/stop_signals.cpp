#include "plugin_common/stop_signals.h"

#include <pthread.h>

#include <csignal>
#include <cstring>

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

// Signals this process received itself (the handler's only state: async-signal-safe).
volatile std::sig_atomic_t own_stop_signals = 0;

void filtered_int_handler(int signum) {
  const bool first_own = own_stop_signals == 0;
  own_stop_signals = own_stop_signals + 1;
  // The stop was already agreed from another rank's copy of this signal.
  if (first_own && LAMMPS_NS::SignalHandler::request_quit) return;
  LAMMPS_NS::SignalHandler::int_handler(signum);
}

void install(int signum, void (*handler)(int)) {
  struct sigaction action;
  std::memset(&action, 0, sizeof(action));
  action.sa_handler = handler;
  sigaction(signum, &action, nullptr);
}

}  // namespace

void install_stop_signal_handlers() {
  install(SIGINT, filtered_int_handler);
  install(SIGTERM, filtered_int_handler);
  install(SIGUSR1, LAMMPS_NS::SignalHandler::usr1_handler);
}

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
