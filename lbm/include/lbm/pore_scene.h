#pragma once
#include "lbm/voxel_geometry.h"

namespace lbm {

// The paper's scene (Jäger et al., Fig. 1), flow along +x, all lengths in lattice cells:
//   [inlet region I][free region III][solid block with a cylindrical pore IV][outlet region II]
// The cross-section is width x width; the pore of diameter D is centred on the x axis of the box.
struct PoreSceneSpec {
  int inlet_length = 20;   // region I: particles are inserted here
  int free_length = 20;    // region III: free flow towards the pore
  int pore_length = 30;    // region IV: length L of the constriction (solid block thickness)
  int outlet_length = 20;  // region II: particles leaving it are removed
  int width = 40;          // cross-section side (cells)
  double pore_diameter = 25.0;  // D in cells
};

// x-ranges [begin, end) of the four regions, for inserting/removing particles and diagnostics.
struct PoreSceneRegions {
  int inlet_begin, inlet_end, free_end, pore_begin, pore_end, outlet_begin, outlet_end;
  double axis_y, axis_z;  // pore axis position in cell coordinates
  double pore_radius;
};

// Throws InputError naming the offending field when the spec is inconsistent
// (non-positive lengths, pore wider than the box).
void validate(const PoreSceneSpec& spec);
PoreSceneRegions regions_of(const PoreSceneSpec& spec);
// The pore of an arbitrary geometry along x: its narrowest open cross-section, as the
// diameter of the circle of equal area, sqrt(4 A / pi) (cells). Sections without fluid (the
// solid end layers of a closed box) are walls, not the pore, and are skipped; 0 when every
// section is solid.
double narrowest_section_diameter(const VoxelGeometry& geometry);
VoxelGeometry make_pore_scene(const PoreSceneSpec& spec, double spacing = 1.0,
                              std::array<double, 3> origin = {0.0, 0.0, 0.0});

}  // namespace lbm
