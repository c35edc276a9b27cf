#pragma once
#include <array>
#include <cstdint>
#include <vector>
// How the population returning from a moving sphere to a fluid node is reconstructed
// (waLBerla's momentum_exchange_method/boundary/). The scheme is chosen once per call; each
// is a loop of its own with no per-link branching on the option.
#include "coupling/boundary/sphere_links.h"
#include "lbm/fluid_solver.h"

namespace coupling {

enum class MovingWallScheme {
  // Half-way bounce-back with the moving-wall term (Ladd 1994); ignores the fraction.
  kBounceBack,
  // Linear interpolation of Bouzidi, Firdaouss & Lallemand (2001) with the q-dependent
  // wall term (lbm::apply_links).
  kBouzidi,
  // Mei, Luo & Shyy (1999), J. Comput. Phys. 155:307, with the Delta < 1/2 branch of
  // Mei, Shyy, Yu & Luo (2000), J. Comput. Phys. 161:680 (the paper's scheme): the
  // returning population mixes the outgoing one with a fictitious equilibrium at the
  // wall node,
  //   f_{-q}(x, t+1) = (1 - chi) f*_q(x) + chi f^(*)_q(x_b) - 6 w_q rho0 c_q.u_w,
  //   f^(*)_q(x_b) = f^eq_q(rho_f, u_f) + 3 w_q rho_f c_q.(u_bf - u_f),
  //   Delta >= 1/2: u_bf = (1 - 3/(2 Delta)) u_f + 3/(2 Delta) u_w, chi = (2 Delta - 1)/(tau + 1/2)
  //   Delta <  1/2: u_bf = u(x - c_q),                            chi = (2 Delta - 1)/(tau - 2)
  // The derivation is for BGK. With TRT we use tau = tau_plus = 1/omega_plus, the
  // relaxation time that sets the viscosity, because chi balances the viscous (even)
  // non-equilibrium part of f (Mei et al. 1999, Sec. 3); for Lambda = 3/16 and tau = 1 the
  // odd rate differs (tau_minus = 0.875), which the drag tests measure. Where x - c_q is not
  // fluid, the Delta < 1/2 branch uses u_bf = u_f. tau near 2 is rejected (chi diverges).
  kMeiLuoShyy,
};

const char* to_string(MovingWallScheme scheme);

// Density and velocity of fluid nodes, computed at most once per node per call. A node next
// to a sphere has several links (about five) and each Mei-Luo-Shyy link reads the moments of
// one or two nodes: 19 loads from 19 arrays each, the scheme's main cost. Reused between
// calls so its arrays are allocated once; a generation counter invalidates it in O(1).
class FluidMomentCache {
 public:
  // Starts a new call: every cached value is stale.
  void begin(std::size_t num_cells);
  // rho, u_x, u_y, u_z at `cell` (velocity with the body-force shift -F/2).
  const std::array<double, 4>& moments(const lbm::PopulationField& f, std::size_t cell,
                                       const std::array<double, 3>& body_force);

 private:
  std::vector<std::uint32_t> stamp_;
  std::vector<std::array<double, 4>> value_;
  std::uint32_t generation_ = 0;
};

// Writes the returning population of every link into the wall node's slot. `cache` may be
// null (a temporary one is used); pass a long-lived one when calling every step.
void apply_moving_walls(const SphereLinks& links, MovingWallScheme scheme, lbm::FluidSolver& solver,
                        FluidMomentCache* cache = nullptr);

}  // namespace coupling
