#include "lbm/moving_wall/mei_luo_shyy.h"

#include "lbm/collide_stream.h"
#include "lbm/node_type.h"
#include "link_loop.h"

namespace lbm::moving_wall {

double MeiLuoShyy::returning_population(const BoundaryLink& link, std::ptrdiff_t offset,
                                        const PopulationField& f) const {
  return returning_population(link, offset, f, cache->moments(f, link.fluid_cell, body_force, table));
}

NodeMoments MeiLuoShyy::node_state(const PopulationField& f, std::size_t x) const {
  if (field) {
    const double* const m = field->at(x);
    return NodeMoments{m[0], {m[1], m[2], m[3]}};
  }
  return cache->moments(f, x, body_force, table);
}

double MeiLuoShyy::returning_population(const BoundaryLink& link, std::ptrdiff_t offset,
                                        const PopulationField& f, const NodeMoments& m) const {
  using L = D3Q19;
  using Vec3 = std::array<double, 3>;
  const int q = link.q;
  const std::size_t x = link.fluid_cell;
  const double delta = link.fraction;
  const Vec3& uw = link.wall_velocity;
  const double rho_f = m.rho;
  const Vec3 u_f = m.u;
  Vec3 u_bf;
  double chi;
  if (delta >= 0.5) {
    const double b = 1.5 / delta;
    for (int a = 0; a < 3; ++a) u_bf[a] = (1.0 - b) * u_f[a] + b * uw[a];
    chi = (2.0 * delta - 1.0) / (tau + 0.5);
  } else {
    const std::size_t xff = x - offset;
    u_bf = (*node_type)[xff] != kFluid ? u_f
           : field ? Vec3{field->at(xff)[1], field->at(xff)[2], field->at(xff)[3]}
                   : cache->moments(f, xff, body_force, table).u;
    chi = (2.0 * delta - 1.0) / (tau - 2.0);
  }
  const double cu_bf = L::c[q][0] * (u_bf[0] - u_f[0]) + L::c[q][1] * (u_bf[1] - u_f[1]) +
                       L::c[q][2] * (u_bf[2] - u_f[2]);
  const double f_star = equilibrium(q, rho_f, u_f) + 3.0 * L::w[q] * rho_f * cu_bf;
  const double out = f.at(q, x);  // f*_q(x): travelling into the wall
  return (1.0 - chi) * out + chi * f_star - wall_term(q, rho0, uw);
}

LBM_MOVING_WALL_INSTANTIATE_LOOPS(MeiLuoShyy);

}  // namespace lbm::moving_wall
