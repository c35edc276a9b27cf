#include "lbm/moving_wall/link_mass.h"

#include <cmath>

#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

namespace lbm::moving_wall {

namespace {
using L = D3Q19;
}  // namespace

LinkMassDefect link_mass_defect(const std::vector<BoundaryLink>& links, double rho0,
                                const std::vector<LinkPopulations>& populations,
                                std::vector<double>* per_link) {
  if (per_link) per_link->resize(links.size());
  LinkMassDefect total;
  for (std::size_t l = 0; l < links.size(); ++l) {
    const double d = link_defect(links[l], rho0, populations[l]);
    if (per_link) (*per_link)[l] = d;
    total.add(d);
  }
  return total;
}

LinkMassDefect sum_link_defects(const std::vector<double>& per_link) {
  LinkMassDefect total;
  for (const double d : per_link) total.add(d);
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
  const LinkMassRestorer restorer(layout, node_type, f);
  for (std::size_t l = 0; l < links.size(); ++l) restorer.remove(links[l].fluid_cell, per_link[l]);
}

}  // namespace lbm::moving_wall
