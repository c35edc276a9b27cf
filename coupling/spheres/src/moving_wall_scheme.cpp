#include "coupling/boundary/moving_wall_scheme.h"

#include "lbm/collide_stream.h"
#include "lbm/d3q19.h"
#include "lbm/node_type.h"

namespace coupling {

const char* to_string(MovingWallScheme scheme) {
  switch (scheme) {
    case MovingWallScheme::kBounceBack: return "bounce-back";
    case MovingWallScheme::kBouzidi: return "Bouzidi";
    case MovingWallScheme::kMeiLuoShyy: return "Mei-Luo-Shyy";
  }
  return "?";
}

namespace {

using L = lbm::D3Q19;

// rho and u at a cell from the post-collision populations, the Guo half-force removed.
void moments(const lbm::PopulationField& f, std::size_t cell, const std::array<double, 3>& F,
             double& rho, Vec3& u) {
  double j[3] = {0.0, 0.0, 0.0};
  rho = 0.0;
  for (int q = 0; q < L::Q; ++q) {
    const double v = f.at(q, cell);
    rho += v;
    j[0] += v * L::c[q][0];
    j[1] += v * L::c[q][1];
    j[2] += v * L::c[q][2];
  }
  for (int a = 0; a < 3; ++a) u[a] = (j[a] - 0.5 * F[a]) / rho;
}

void apply_mei_luo_shyy(const SphereLinks& sl, lbm::FluidSolver& solver, FluidMomentCache& cache) {
  const auto& layout = solver.layout();
  const auto& type = solver.node_types();
  lbm::PopulationField& f = solver.populations();
  const double tau = 1.0 / solver.trt().omega_plus;
  const double rho0 = solver.parameters().rho0;
  const auto& F = solver.parameters().body_force;
  for (const lbm::BoundaryLink& link : sl.links) {
    const int q = link.q, qo = L::opposite(q);
    const std::ptrdiff_t off = layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
    const std::size_t x = link.fluid_cell;
    const double delta = link.fraction;
    const Vec3& uw = link.wall_velocity;
    const auto& m = cache.moments(f, x, F);
    const double rho_f = m[0];
    const Vec3 u_f{m[1], m[2], m[3]};
    Vec3 u_bf;
    double chi;
    if (delta >= 0.5) {
      const double b = 1.5 / delta;
      for (int a = 0; a < 3; ++a) u_bf[a] = (1.0 - b) * u_f[a] + b * uw[a];
      chi = (2.0 * delta - 1.0) / (tau + 0.5);
    } else {
      const std::size_t xff = x - off;
      if (type[xff] == lbm::kFluid) {
        const auto& mff = cache.moments(f, xff, F);
        u_bf = {mff[1], mff[2], mff[3]};
      } else {
        u_bf = u_f;
      }
      chi = (2.0 * delta - 1.0) / (tau - 2.0);
    }
    const double cu_bf = L::c[q][0] * (u_bf[0] - u_f[0]) + L::c[q][1] * (u_bf[1] - u_f[1]) +
                         L::c[q][2] * (u_bf[2] - u_f[2]);
    const double f_star = lbm::equilibrium(q, rho_f, u_f) + 3.0 * L::w[q] * rho_f * cu_bf;
    const double cuw = L::c[q][0] * uw[0] + L::c[q][1] * uw[1] + L::c[q][2] * uw[2];
    const double out = f.at(q, x);
    const double back = (1.0 - chi) * out + chi * f_star - 6.0 * L::w[q] * rho0 * cuw;
    f.at(qo, x + off) = static_cast<lbm::Real>(back);
  }
}

}  // namespace

void FluidMomentCache::begin(std::size_t num_cells) {
  if (stamp_.size() != num_cells || generation_ == UINT32_MAX) {
    stamp_.assign(num_cells, 0);
    value_.resize(num_cells);
    generation_ = 0;
  }
  ++generation_;
}

const std::array<double, 4>& FluidMomentCache::moments(const lbm::PopulationField& f, std::size_t cell,
                                                       const std::array<double, 3>& body_force) {
  auto& v = value_[cell];
  if (stamp_[cell] != generation_) {
    stamp_[cell] = generation_;
    Vec3 u;
    coupling::moments(f, cell, body_force, v[0], u);
    v[1] = u[0];
    v[2] = u[1];
    v[3] = u[2];
  }
  return v;
}

void apply_moving_walls(const SphereLinks& links, MovingWallScheme scheme, lbm::FluidSolver& solver,
                        FluidMomentCache* cache) {
  switch (scheme) {
    case MovingWallScheme::kBounceBack:
      lbm::apply_links(links.links, lbm::LinkScheme::kBounceBack, solver.parameters().rho0,
                       solver.layout(), solver.node_types(), solver.populations());
      break;
    case MovingWallScheme::kBouzidi:
      lbm::apply_links(links.links, lbm::LinkScheme::kBouzidi, solver.parameters().rho0,
                       solver.layout(), solver.node_types(), solver.populations());
      break;
    case MovingWallScheme::kMeiLuoShyy: {
      FluidMomentCache local;
      FluidMomentCache& c = cache ? *cache : local;
      c.begin(solver.layout().num_cells());
      apply_mei_luo_shyy(links, solver, c);
      break;
    }
  }
}

}  // namespace coupling
