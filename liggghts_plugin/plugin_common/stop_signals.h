#pragma once
// A stop request (SIGINT/SIGTERM, what batch schedulers send before the wall-time kill;
// SIGUSR1 for a restart without stopping) taken at a fluid step, by every rank at the same
// step. The mechanism is LIGGGHTS 3.8's own (signal_handling.h): its handler sets
// SignalHandler::request_quit / request_write_restart, Neighbor::decide reads them at the
// start of the next DEM step, Output then writes restart_forced_liggghts_<step>.data (our
// fix's write_restart adds the fluid checkpoint) and Verlet stops. Two things it does not
// do for a coupled MPI run, and what this adds:
//  - each rank reads its own flags: ranks that receive the signal a step apart disagree
//    about reneighbouring and hang in the restart's collective writes. Here the signals are
//    blocked in every thread and delivered only at one point of a fluid step, after which
//    the ranks agree on the flags (one MPI_Allreduce);
//  - a restart between fluid steps resumes the particles' substep loads and mapping from
//    another state than the uninterrupted run had; at a fluid step it does not.
#include <mpi.h>

namespace lbm_pore {

// Installs the handlers, as LIGGGHTS's main does: LIGGGHTS's own for SIGUSR1, and for
// SIGINT/SIGTERM LIGGGHTS's own behind one filter. mpirun (and a batch system) signals every
// rank, a few milliseconds apart: a rank that already agreed to the stop another rank
// requested (take_stop_requests) must not take its own copy of that signal for a second one,
// which LIGGGHTS's handler answers with _Exit(1) and no restart. So the first SIGINT/SIGTERM
// a process receives after its stop flag was set by agreement is that same request, and is
// dropped; any later one force-quits as in LIGGGHTS.
void install_stop_signal_handlers();

// Blocks SIGINT, SIGTERM and SIGUSR1 in the calling thread (and so in every thread it
// starts afterwards: MPI's helper threads when called before MPI_Init, OpenMP's workers).
void block_stop_signals();
void unblock_stop_signals();

// Delivers the stop signals that arrived since they were blocked (LIGGGHTS's handler runs
// here, in this thread) and makes every rank of `world` hold the same request flags (a rank's
// request counts for all). Collective.
void take_stop_requests(MPI_Comm world);

}  // namespace lbm_pore
