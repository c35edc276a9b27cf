#pragma once
// The keywords of `fix ID group wall/voxel ...` (fix_wall_voxel.h lists them): where the
// geometry comes from, and the contact coefficients. No LIGGGHTS dependency, so the parser is
// unit-tested and fuzzed (tests/fuzz) on its own; the fix looks up 'lbm <fix-ID>' and turns
// the errors into LIGGGHTS errors.
#include <string>
#include <vector>

#include "contact/wall_contact.h"
#include "wall_geometry_source.h"

namespace lbm_pore {

struct WallVoxelArguments {
  WallGeometrySource source;  // 'file <path>' or 'pore' with its lengths
  std::string lbm_fix_id;     // 'lbm <fix-ID>': the geometry of that fix lbm/pore ("" if not given)
  bool voxel_sum = false;     // 'model voxel_sum' (the paper's sum over voxels); default smooth
  contact::WallContactParams
      params;  // kt and tangential_damping follow kw and damping unless given
};

// words: the arguments after 'wall/voxel'. Throws lbm::InputError "fix wall/voxel: ..." naming
// the keyword and its range, an unknown keyword, a missing value, a keyword given twice, two
// geometries ('lbm', 'file', 'pore') or none.
WallVoxelArguments parse_wall_voxel_arguments(const std::vector<std::string>& words);

}  // namespace lbm_pore
