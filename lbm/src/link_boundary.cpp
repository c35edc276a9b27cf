#include "lbm/link_boundary.h"

#include "lbm/d3q19.h"
#include "lbm/node_type.h"

namespace lbm {

void apply_links(const std::vector<BoundaryLink>& links, LinkScheme scheme, double rho0,
                 const BlockLayout& layout, const std::vector<std::uint8_t>& node_type,
                 PopulationField& f, std::vector<std::array<double, 3>>* momentum) {
  using L = D3Q19;
  if (momentum) momentum->resize(links.size());
  for (std::size_t l = 0; l < links.size(); ++l) {
    const BoundaryLink& link = links[l];
    const int q = link.q, qo = L::opposite(q);
    const std::ptrdiff_t off = layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
    const std::size_t x = link.fluid_cell;
    const std::size_t wall_node = x + off;
    const double cu = L::c[q][0] * link.wall_velocity[0] + L::c[q][1] * link.wall_velocity[1] +
                      L::c[q][2] * link.wall_velocity[2];
    const double wall_term = 6.0 * L::w[q] * rho0 * cu;
    const double out = f.at(q, x);  // f*_q(x): the population travelling into the wall
    double back;
    const double s = link.fraction;
    if (scheme == LinkScheme::kBouzidi && s < 0.5 && node_type[x - off] == kFluid) {
      back = 2.0 * s * out + (1.0 - 2.0 * s) * f.at(q, x - off) - wall_term;
    } else if (scheme == LinkScheme::kBouzidi && s >= 0.5) {
      back = (out + (2.0 * s - 1.0) * f.at(qo, x) - wall_term) / (2.0 * s);
    } else {
      back = out - wall_term;
    }
    f.at(qo, wall_node) = static_cast<Real>(back);
    if (momentum) {
      const double m = out + back;
      (*momentum)[l] = {m * L::c[q][0], m * L::c[q][1], m * L::c[q][2]};
    }
  }
}

}  // namespace lbm
