#include "lbm/pore_scene.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lbm/input_error.h"

namespace lbm {

void validate(const PoreSceneSpec& s) {
  auto positive = [](int v, const char* name, int min) {
    if (v < min)
      throw InputError(std::string("pore scene: ") + name + " = " + std::to_string(v) +
                       " cells, must be >= " + std::to_string(min));
  };
  positive(s.inlet_length, "inlet_length", 1);
  positive(s.free_length, "free_length", 0);
  positive(s.pore_length, "pore_length", 1);
  positive(s.outlet_length, "outlet_length", 1);
  positive(s.width, "width", 3);
  if (!(s.pore_diameter >= 1.0) || s.pore_diameter > s.width)
    throw InputError("pore scene: pore_diameter = " + std::to_string(s.pore_diameter) +
                     " cells, must be in [1, width = " + std::to_string(s.width) + "]");
}

PoreSceneRegions regions_of(const PoreSceneSpec& s) {
  PoreSceneRegions r{};
  r.inlet_begin = 0;
  r.inlet_end = s.inlet_length;
  r.free_end = r.inlet_end + s.free_length;
  r.pore_begin = r.free_end;
  r.pore_end = r.pore_begin + s.pore_length;
  r.outlet_begin = r.pore_end;
  r.outlet_end = r.outlet_begin + s.outlet_length;
  // Nodes sit at integer positions; the box spans [-0.5, width-0.5] so its centre is:
  r.axis_y = 0.5 * (s.width - 1);
  r.axis_z = 0.5 * (s.width - 1);
  r.pore_radius = 0.5 * s.pore_diameter;
  return r;
}

VoxelGeometry make_pore_scene(const PoreSceneSpec& s, double spacing, std::array<double, 3> origin) {
  validate(s);
  const PoreSceneRegions r = regions_of(s);
  VoxelGeometry g({r.outlet_end, s.width, s.width}, spacing, origin);
  const double r2 = r.pore_radius * r.pore_radius;
  for (int k = 0; k < s.width; ++k)
    for (int j = 0; j < s.width; ++j) {
      const double dy = j - r.axis_y, dz = k - r.axis_z;
      // A node is fluid if its centre lies inside the cylinder: the voxelised pore's
      // cross-section then approximates pi D^2/4 to within the staircase error.
      const bool in_pore = dy * dy + dz * dz < r2;
      if (in_pore) continue;
      for (int i = r.pore_begin; i < r.pore_end; ++i) g.set_solid(i, j, k, true);
    }
  return g;
}

double narrowest_section_diameter(const VoxelGeometry& geometry) {
  const auto& d = geometry.dims();
  double narrowest = 1e300;
  for (int i = 0; i < d[0]; ++i) {
    int open = 0;
    for (int k = 0; k < d[2]; ++k)
      for (int j = 0; j < d[1]; ++j) open += !geometry.is_solid(i, j, k);
    // A section without fluid is a closing wall (the end layers of a closed box), not a pore.
    if (open > 0) narrowest = std::min(narrowest, double(open));
  }
  if (narrowest == 1e300) return 0.0;  // all solid
  return std::sqrt(4.0 * narrowest / M_PI);
}

}  // namespace lbm
