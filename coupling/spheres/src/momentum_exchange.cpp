#include "coupling/force/momentum_exchange.h"

#include "lbm/d3q19.h"

namespace coupling {

namespace {
template <bool kGalilean>
void sum_links(const SphereLinks& sl, const lbm::FluidSolver& solver, HydrodynamicLoads& loads) {
  using L = lbm::D3Q19;
  const auto& layout = solver.layout();
  const lbm::PopulationField& f = solver.populations();
  const double rho0 = solver.parameters().rho0;
  for (std::size_t l = 0; l < sl.links.size(); ++l) {
    const lbm::BoundaryLink& link = sl.links[l];
    const int q = link.q;
    const std::size_t wall = link.fluid_cell + layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
    const double out = f.at(q, link.fluid_cell);
    const double back = f.at(L::opposite(q), wall);
    // The reference pressure's share 2 w_q rho0 is removed per link: over a closed link set
    // it sums to zero exactly (as many links along +c_q as along -c_q), but where a sphere
    // touches a wall or another sphere and its covered nodes lose their fluid neighbours
    // it would act as the pressure p0 = rho0/3 on one side only ("void as vacuum").
    const double sum = out + back - 2.0 * L::w[q] * rho0;
    Vec3 F{sum * L::c[q][0], sum * L::c[q][1], sum * L::c[q][2]};
    if (kGalilean) {
      const double diff = out - back;
      for (int a = 0; a < 3; ++a) F[a] -= link.wall_velocity[a] * diff;
    }
    const int p = sl.particle[l];
    Vec3& force = loads.force[p];
    for (int a = 0; a < 3; ++a) force[a] += F[a];
    // Isotropic part of 6 w_q rho0 c_q c_q: trace / 3 = 2 w_q rho0 |c_q|^2.
    loads.velocity_coefficient[p] += 2.0 * L::w[q] * rho0 *
                                     (L::c[q][0] * L::c[q][0] + L::c[q][1] * L::c[q][1] + L::c[q][2] * L::c[q][2]);
    const Vec3 t = cross(sl.arm[l], F);
    Vec3& torque = loads.torque[p];
    for (int a = 0; a < 3; ++a) torque[a] += t[a];
  }
}
}  // namespace

void add_momentum_exchange(const SphereLinks& links, MomentumExchange method,
                           const lbm::FluidSolver& solver, HydrodynamicLoads& loads) {
  if (method == MomentumExchange::kGalileanInvariant)
    sum_links<true>(links, solver, loads);
  else
    sum_links<false>(links, solver, loads);
}

}  // namespace coupling
