#pragma once
// Registration of this project's LIGGGHTS styles into a LAMMPS instance.
//
// LIGGGHTS 3.8 has no plugin loader: `pair_style`, `fix` and `compute` look a style name up
// in Force::pair_map, Modify::fix_map and Modify::compute_map. register_lbm_pore_styles()
// inserts our creators there after the LAMMPS instance is built and before any input runs.
// The list of styles is in style_registry.cpp (one line per style).
namespace LAMMPS_NS {
class LAMMPS;
}

namespace lbm_pore {

// Adds every style of style_registry.cpp. Stock styles keep working; a name clash with a
// stock style is a programming error and aborts with a message.
void register_lbm_pore_styles(LAMMPS_NS::LAMMPS* lmp);

}  // namespace lbm_pore
