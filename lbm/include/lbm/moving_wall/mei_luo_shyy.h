#pragma once
// Mei, Luo & Shyy (1999), J. Comput. Phys. 155:307, with the Delta < 1/2 branch of Mei, Shyy,
// Yu & Luo (2000), J. Comput. Phys. 161:680 (the paper's scheme): the returning population
// mixes the outgoing one with a fictitious equilibrium at the wall node,
//   f_{-q}(x, t+1) = (1 - chi) f*_q(x) + chi f^(*)_q(x_b) - 6 w_q rho0 c_q.u_w,
//   f^(*)_q(x_b) = f^eq_q(rho_f, u_f) + 3 w_q rho_f c_q.(u_bf - u_f),
//   Delta >= 1/2: u_bf = (1 - 3/(2 Delta)) u_f + 3/(2 Delta) u_w, chi = (2 Delta - 1)/(tau + 1/2)
//   Delta <  1/2: u_bf = u(x - c_q),                            chi = (2 Delta - 1)/(tau - 2)
// with Delta the link fraction and rho_f, u_f the moments at the fluid node x. The derivation
// is for BGK. With TRT we use tau = tau_plus = 1/omega_plus, the relaxation time that sets the
// viscosity, because chi balances the viscous (even) non-equilibrium part of f (Mei et al.
// 1999, Sec. 3); for Lambda = 3/16 and tau = 1 the odd rate differs (tau_minus = 0.875),
// which the drag tests measure. Where x - c_q is not fluid, the Delta < 1/2 branch uses
// u_bf = u_f. tau near 2 must be rejected by the caller (chi diverges).
#include <cstdint>
#include <vector>

#include "lbm/moving_wall/link_boundary.h"
#include "lbm/node_moment_field.h"
#include "lbm/moving_wall/moment_cache.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

namespace lbm::moving_wall {

struct MeiLuoShyy {
  double rho0 = 1.0;                                     // reference density of the wall term
  double tau = 1.0;                                      // tau_plus = 1/omega_plus
  std::array<double, 3> body_force{0.0, 0.0, 0.0};       // removed from the moments (Guo)
  const std::vector<std::uint8_t>* node_type = nullptr;  // to tell whether x - c_q is fluid
  MomentCache* cache = nullptr;                          // begun for the populations of this call
  int table = 0;                                         // the cache table of this thread
  // Where non-null, the moments of every node that a link reads, read from here instead
  // of the cache: the solver's node_moment_field (FluidSolver::keep_node_moments), with the
  // ghosts' moments received into it.
  const NodeMomentField* field = nullptr;

  double returning_population(const BoundaryLink& link, std::ptrdiff_t offset,
                              const PopulationField& f) const;

  // The node-major sweep (link_sweep.h) gathers the moments of a fluid node once for all
  // its links: node_state, then returning_population with them (the same value as above).
  NodeMoments node_state(const PopulationField& f, std::size_t x) const;
  double returning_population(const BoundaryLink& link, std::ptrdiff_t offset,
                              const PopulationField& f, const NodeMoments& at_x) const;
  // Asks for the moments the link will read (the field's, where it has one).
  void prefetch(const BoundaryLink& link, std::ptrdiff_t offset) const {
    if (!field) return;
    __builtin_prefetch(field->at(link.fluid_cell));
    if (link.fraction < 0.5) __builtin_prefetch(field->at(link.fluid_cell - offset));
  }
};

// The copy of `scheme` that thread t of moving_wall::apply runs: its own cache table.
inline MeiLuoShyy for_thread(const MeiLuoShyy& scheme, int t) {
  MeiLuoShyy mine = scheme;
  mine.table = t;
  return mine;
}

}  // namespace lbm::moving_wall
