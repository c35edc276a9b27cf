#include "coupling/reconstruction/refill.h"

#include "lbm/collide_stream.h"
#include "lbm/d3q19.h"
#include "lbm/node_type.h"

namespace coupling {

MassChange refill_uncovered(const MappingChange& change, const SphereMapping& mapping,
                            const ParticleView& view, RefillScheme scheme, lbm::FluidSolver& solver,
                            const std::vector<double>* ghost_density) {
  using L = lbm::D3Q19;
  MassChange mass;
  const auto& layout = solver.layout();
  const auto& type = solver.node_types();
  lbm::PopulationField& f = solver.populations();
  const double rho0 = solver.parameters().rho0;
  for (std::size_t cell : change.covered) {
    const auto c = layout.coords(cell);
    if (!layout.is_owned(c[0], c[1], c[2])) continue;
    mass.covered += solver.density(cell);
    ++mass.num_covered;
  }
  for (std::size_t n = 0; n < change.uncovered.size(); ++n) {
    const std::size_t cell = change.uncovered[n];
    const auto c = layout.coords(cell);
    if (!layout.is_owned(c[0], c[1], c[2])) continue;
    double rho = rho0;
    if (scheme == RefillScheme::kEquilibriumAveragedDensity) {
      double sum = 0.0;
      int count = 0;
      for (int q = 1; q < L::Q; ++q) {
        const std::size_t y = cell + layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
        if (type[y] != lbm::kFluid) continue;
        // Owned neighbours as they stand (one refilled earlier in this loop included).
        sum += ghost_density && solver.is_exchanged_ghost(y) ? (*ghost_density)[y]
                                                             : solver.density(y);
        ++count;
      }
      if (count > 0) rho = sum / count;
    }
    Vec3 u{0.0, 0.0, 0.0};
    const int p = change.uncovered_particle[n];
    if (p >= 0) {
      const Vec3 r = mapping.box().displacement(view.x(std::size_t(p)), mapping.node_position(cell));
      u = view.surface_velocity(std::size_t(p), r);
    }
    for (int q = 0; q < L::Q; ++q) f.at(q, cell) = static_cast<lbm::Real>(lbm::equilibrium(q, rho, u));
    mass.refilled += rho;
    ++mass.num_refilled;
  }
  return mass;
}

}  // namespace coupling
