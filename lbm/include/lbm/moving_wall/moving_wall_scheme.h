#pragma once
// The family of moving-wall schemes (waLBerla's momentum_exchange_method/boundary/): how the
// population that returns from a wall cutting a lattice link is rebuilt. One file per
// scheme (bounce_back.h, bouzidi.h, mei_luo_shyy.h), each a small struct of its resolved
// parameters with the same member
//   double returning_population(const BoundaryLink& link, std::ptrdiff_t offset,
//                               const PopulationField& f) const;
// = f_{-q}(x, t+1) for the link leaving fluid node x = link.fluid_cell in direction q, from
// the post-collision state f*(t); `offset` is the cell-index step of c_q, so x + offset is
// the wall node and x - offset the second fluid node. link_boundary.h picks the scheme
// by this enum once per call; moving_wall::apply runs the chosen one over all links.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/population_field.h"

namespace lbm {

struct BoundaryLink;

// The two populations of a link as the moving-wall stage leaves them: f*_q(x), travelling
// into the wall, and f_{-q}(x, t+1), the one the scheme returned, as stored (in Real). The
// later stages (momentum exchange, the link mass defect) read them here, in link order,
// instead of gathering them again from two of the 19 population arrays.
struct LinkPopulations {
  double out = 0.0;
  double back = 0.0;
};

enum class MovingWallScheme {
  kBounceBack,  // moving_wall/bounce_back.h
  kBouzidi,     // moving_wall/bouzidi.h
  kMeiLuoShyy,  // moving_wall/mei_luo_shyy.h
};

namespace moving_wall {

// The spelling of fix lbm/pore's `boundary` keyword: "bounce_back", "bouzidi", "mls".
const char* name(MovingWallScheme scheme);
// Inverse of name(); any other word is an InputError that lists the allowed ones.
MovingWallScheme parse(const std::string& word);
// For reports and tables: "bounce-back", "Bouzidi", "Mei-Luo-Shyy".
const char* label(MovingWallScheme scheme);

// The moving-wall momentum term 6 w_q rho0 c_q.u_w that every scheme subtracts (Ladd 1994).
inline double wall_term(int q, double rho0, const std::array<double, 3>& wall_velocity) {
  using L = D3Q19;
  const double cu =
      L::c[q][0] * wall_velocity[0] + L::c[q][1] * wall_velocity[1] + L::c[q][2] * wall_velocity[2];
  return 6.0 * L::w[q] * rho0 * cu;
}

// Writes, for every link, scheme.returning_population(...) into the slot it is pulled from
// (direction -q at the wall node x + c_q). If `momentum` is non-null it receives, per link,
// the momentum the fluid gives the wall during the step: c_q (f*_q(x) + f_{-q}(x, t+1))
// (momentum exchange, Ladd 1994; Mei et al. 2002, paper Eq. 2); if `populations` is
// non-null, the link's two populations (LinkPopulations). Instantiated in each scheme's
// source file, with that file's compile options.
// With threads > 1 the links are split into that many contiguous blocks, one per OpenMP
// thread, each running for_thread(scheme, t). The result is the same for any number of
// threads: every link writes its own slot (direction -q at its wall node, a non-fluid node)
// and reads only fluid nodes' populations, which no link writes; the links must be distinct
// and leave fluid nodes (as the sphere and wall links are).
template <class Scheme>
void apply(const std::vector<BoundaryLink>& links, const Scheme& scheme, const BlockLayout& layout,
           PopulationField& f, std::vector<std::array<double, 3>>* momentum, int threads = 1,
           std::vector<LinkPopulations>* populations = nullptr);

}  // namespace moving_wall
}  // namespace lbm
