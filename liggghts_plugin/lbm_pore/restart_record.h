#pragma once
// What fix lbm/pore keeps in LIGGGHTS's restart file besides the atoms: the pore monitor's
// state (the cumulative particle fluxes, the burst detector) and the path of the fluid's
// checkpoint (one file per rank, written beside it), as one block of bytes: the number of
// values (a double), the values, the path with its terminating zero. No LIGGGHTS dependency.
#include <string>
#include <vector>

#include "lbm_pore_options.h"

namespace lbm_pore {

struct RestartRecord {
  std::vector<double> monitor_state;
  std::string checkpoint;

  std::string bytes() const;
  static RestartRecord read(const char* bytes);
};

// The checkpoint's path at DEM step `step`: the 'checkpoint' keyword's prefix, else
// "<fix ID>.fluid", then ".<step>".
std::string checkpoint_prefix(const PoreOptions& options, const std::string& fix_id);
std::string checkpoint_path(const std::string& prefix, long long step);

}  // namespace lbm_pore
