#include "lbm/moving_wall/link_mass.h"

#include <cmath>

#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

namespace lbm::moving_wall {

namespace {
using L = D3Q19;

// The cell offsets of the 19 directions, computed once per call (not once per slot).
struct LinkOffsets {
  std::ptrdiff_t of[L::Q];
  explicit LinkOffsets(const BlockLayout& layout) {
    for (int q = 0; q < L::Q; ++q) of[q] = layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
  }
};

// delta_l: what the link returned minus what half-way bounce-back would have returned.
double defect_of(const BoundaryLink& link, double rho0, const LinkOffsets& offsets,
                 const PopulationField& f) {
  const int q = link.q;
  const std::size_t x = link.fluid_cell;
  const double out = f.at(q, x);  // f*_q(x): travelling into the wall
  const double back = f.at(L::opposite(q), x + offsets.of[q]);
  return back - (out - wall_term(q, rho0, link.wall_velocity));
}
}  // namespace

LinkMassDefect link_mass_defect(const std::vector<BoundaryLink>& links, double rho0,
                                const BlockLayout& layout, const PopulationField& f,
                                std::vector<double>* per_link) {
  if (per_link) per_link->resize(links.size());
  const LinkOffsets offsets(layout);
  LinkMassDefect total;
  for (std::size_t l = 0; l < links.size(); ++l) {
    const double d = defect_of(links[l], rho0, offsets, f);
    if (per_link) (*per_link)[l] = d;
    total.net += d;
    total.absolute += std::abs(d);
  }
  return total;
}

double moving_surface_mass(const std::vector<BoundaryLink>& links, double rho0) {
  double mass = 0.0;
  for (const BoundaryLink& link : links) mass -= wall_term(link.q, rho0, link.wall_velocity);
  return mass;
}

void restore_link_mass(const std::vector<BoundaryLink>& links, const BlockLayout& layout,
                       const std::vector<std::uint8_t>& node_type,
                       const std::vector<double>& per_link, PopulationField& f) {
  // The defects are all measured before any is removed: removing one writes slots that
  // another link of the same node reads as its returned population.
  const LinkOffsets offsets(layout);
  for (std::size_t l = 0; l < links.size(); ++l) {
    const std::size_t x = links[l].fluid_cell;
    double at_rest = 0.0;
    // Population p reaches x from x - c_p in the next (pull) streaming.
    for (int p = 0; p < L::Q; ++p) {
      const std::size_t from = x - offsets.of[p];
      // A ghost beyond an open face is written after this stage (the open boundary fills
      // it): its share goes on x's own rest population, so that x's mass changes by the
      // whole defect and the budget's books (PoreMonitor) stay exact.
      if (node_type[from] == kOpen) {
        at_rest += L::w[p] * per_link[l];
        continue;
      }
      Real& slot = f.at(p, from);
      slot = static_cast<Real>(slot - L::w[p] * per_link[l]);
    }
    if (at_rest != 0.0) f.at(0, x) = static_cast<Real>(f.at(0, x) - at_rest);
  }
}

}  // namespace lbm::moving_wall
