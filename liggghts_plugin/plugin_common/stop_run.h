#pragma once
// Stopping a run from one rank (LIGGGHTS's Error::one) so the message is not lost: Error::one
// aborts MPI at once, its text may sit in a buffered screen and never reaches the log file,
// and ranks other than 0 have no screen. So write the text to screen (or stderr) and log,
// flush both, then call Error::one. Also the plain screen-and-log print of setup summaries.
#include <cstdio>

namespace LAMMPS_NS {
class Error;
}

namespace lbm_pore {

// Writes text (with its own newlines) to the screen and the log file, where they are open.
void print_to_screen_and_log(FILE* screen, FILE* logfile, const char* text);

[[noreturn]] void stop_on_this_rank(LAMMPS_NS::Error* error, int rank, FILE* screen, FILE* logfile,
                                    const char* text);

}  // namespace lbm_pore
