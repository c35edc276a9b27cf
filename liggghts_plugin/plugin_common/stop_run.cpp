#include "plugin_common/stop_run.h"

#include <cstdlib>

#include "error.h"

namespace lbm_pore {

void print_to_screen_and_log(FILE* screen, FILE* logfile, const char* text) {
  if (screen) std::fputs(text, screen);
  if (logfile) std::fputs(text, logfile);
}

void stop_on_this_rank(LAMMPS_NS::Error* error, int rank, FILE* screen, FILE* logfile,
                       const char* text) {
  FILE* out = screen ? screen : stderr;
  std::fprintf(out, "ERROR on proc %d: %s\n", rank, text);
  std::fflush(out);
  if (logfile) {
    std::fprintf(logfile, "ERROR on proc %d: %s\n", rank, text);
    std::fflush(logfile);
  }
  error->one(__FILE__, __LINE__, text);
  std::abort();  // not reached: Error::one aborts MPI
}

}  // namespace lbm_pore
