#pragma once
// What fix lbm/pore keeps in LIGGGHTS's restart file besides the atoms: the pore monitor's
// state (the cumulative particle fluxes, the burst detector), the drive's state (the capped
// drive's inlet velocity; empty for a plain drive) and the path of the fluid's checkpoint
// (one file per rank, written beside it), as one block of bytes: kTagWithDrive (a negative
// double), the number of monitor values, the values, the number of drive values, the values,
// the path with its terminating zero. A record written before the drive had a state starts
// with the number of monitor values (>= 0) and has no drive block; it reads as an empty drive
// state. No LIGGGHTS dependency.
#include <string>
#include <vector>

#include "lbm_pore_options.h"

namespace lbm_pore {

struct RestartRecord {
  static constexpr double kTagWithDrive = -2.0;
  std::vector<double> monitor_state;
  std::string checkpoint;
  std::vector<double> drive_state;

  std::string bytes() const;
  static RestartRecord read(const char* bytes);
};

// The checkpoint's path at DEM step `step`: the 'checkpoint' keyword's prefix, else
// "<fix ID>.fluid", then ".<step>".
std::string checkpoint_prefix(const PoreOptions& options, const std::string& fix_id);
std::string checkpoint_path(const std::string& prefix, long long step);

}  // namespace lbm_pore
