#pragma once
// Mass-conserving correction of the interpolated moving-wall schemes (Bouzidi, Mei-Luo-Shyy).
//
// Half-way bounce-back returns to the fluid node x, per link, what x sent into the wall
// less the moving-wall term (Ladd 1994):  f_{-q}(x, t+1) = f*_q(x) - 6 w_q rho0 c_q.u_w.
// Over a closed surface the wall terms are the mass the moving surface pushes from behind
// to ahead of it, so bounce-back conserves the fluid mass of fixed walls to round-off. The
// interpolated schemes return a different value: their per-link mass defect
//   delta_l = f_{-q}(x, t+1) - [f*_q(x) - 6 w_q rho0 c_q.u_w]
// is of the order of the population's gradient along the link (Bouzidi s < 1/2:
// (1 - 2 s)(f*_q(x - c_q) - f*_q(x)); s >= 1/2: (2 s - 1)/(2 s) (f*_{-q}(x) - f*_q(x) +
// 6 w_q rho0 c_q.u_w); Mei-Luo-Shyy: chi (f^(*)_q(x_b) - f*_q(x))), small where the flow is smooth but of one sign
// over a sphere in a dense array, so that mass grows without bound (doc/stability.md,
// "Mass conservation at interpolated walls").
//
// The correction, in the spirit of Bao, Yuan & Schaefer (2008), J. Comput. Phys. 227:8472
// (mass defect of each boundary node put back at that node each step): the defect of every
// link is taken back from the node x it wrote to, as a density change at rest, -delta_l w_p
// on each of the 19 populations that arrive at x in the next streaming (the slots
// f_p(x - c_p): the returned populations, x's own rest population, and the populations its
// fluid neighbours send it). The node's mass then changes exactly as with bounce-back; its
// momentum and the momentum exchanged with the wall are untouched (sum_p w_p c_p = 0), and
// the change is of the order of the scheme's own deviation from bounce-back, so the order
// of accuracy is kept (the accuracy tests measure it). Purely local: every slot it writes is
// pulled by x alone, so no halo exchange and no global sum; halo slots written are the
// copies x pulls.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/moving_wall/link_boundary.h"
#include "lbm/moving_wall/moving_wall_scheme.h"
#include "lbm/population_field.h"

namespace lbm::moving_wall {

// Mass the links of one call created (sum of delta_l) and the sum of |delta_l|, before the
// correction; after it the fluid mass changes by the wall terms only.
struct LinkMassDefect {
  double net = 0.0;
  double absolute = 0.0;
  // One more link, in link order (inline: called once per link, per step).
  void add(double defect) {
    net += defect;
    absolute += std::abs(defect);
  }
};

// delta_l of one link from its populations (apply_links' `populations` output): what the
// link returned minus what half-way bounce-back would have returned,
//   back - (out - 6 w_q rho0 c_q.u_w).
// Inline, so that the sweeps keep the two values in registers (through memory, the 16-byte
// load of two 8-byte stores stalled every link). Its roundings are spelled out, so that every
// file that inlines it gives the bits it has always had, whatever its contraction flags:
// c_q.u_w is exact per product (c of 0 and +-1), and out - (6 w_q rho0) c_q.u_w is one fused
// rounding where the machine has FMA (as the kernel flags' contraction made it).
inline double link_defect(const BoundaryLink& link, double rho0, const LinkPopulations& populations) {
  const int q = link.q;
  const std::array<double, 3>& u = link.wall_velocity;
  const double cu = D3Q19::c[q][0] * u[0] + D3Q19::c[q][1] * u[1] + D3Q19::c[q][2] * u[2];
  const double weight = 6.0 * D3Q19::w[q] * rho0;
#ifdef __FMA__
  return populations.back - std::fma(-weight, cu, populations.out);
#else
  const double term = weight * cu;
  return populations.back - (populations.out - term);
#endif
}

// The defects of the links' populations as apply_links left them (its `populations`
// output: no lattice access); per link into `per_link` if non-null (kept by the caller so
// that it is allocated once). Call restore_link_mass after the momentum exchange has read
// the returned populations, before streaming.
LinkMassDefect link_mass_defect(const std::vector<BoundaryLink>& links, double rho0,
                                const std::vector<LinkPopulations>& populations,
                                std::vector<double>* per_link = nullptr);

// The total of per-link defects (link_mass_defect's `per_link`), summed in link order.
LinkMassDefect sum_link_defects(const std::vector<double>& per_link);

// Mass the moving-wall terms of the links give the fluid in one step: -sum_l 6 w_q rho0 c_q.u_w,
// what half-way bounce-back (and, with the correction above, every scheme) adds to the nodes
// next to a moving surface. Over the links of a sphere whose surface is all in the fluid it
// is zero for a translation (the terms of opposite faces cancel exactly) and small for a
// rotation; it is not zero where part of the surface meets no fluid node: a sphere leaving
// the lattice through an open end (its rear draws fluid in, its front is outside), or one in
// contact with a wall or another sphere. The fluid budget books it (doc/stability.md).
double moving_surface_mass(const std::vector<BoundaryLink>& links, double rho0);

// LinkMassRestorer's deferral: `ids` are the sorted link ids whose ranges remove_node
// receives; the defect of the link at sorted position i goes to defects[i] (zero for a node
// next to an open face, which remove_node corrects itself: a subtraction of zero changes no
// slot).
struct LinkMassDeferral {
  const std::uint32_t* ids = nullptr;
  double* defects = nullptr;
};

// The correction's writes, one link at a time: remove(x, delta_l) takes delta_l w_p from
// each slot f_p(x - c_p). The arrays' addresses and offsets are taken once, at construction
// (link_mass_restorer.cpp). With a `Deferral`, remove_node leaves the nodes away from the
// open faces to the collide-stream's pass (FluidSolver::correct_pulls_in_next_step, which
// performs the same operations): it copies their links' defects, in order, to the entries of
// their sorted positions.
class LinkMassRestorer {
 public:
  using Deferral = LinkMassDeferral;
  LinkMassRestorer(const BlockLayout& layout, const std::vector<std::uint8_t>& node_type,
                   PopulationField& f, Deferral deferral = {});
  void remove(std::size_t fluid_cell, double defect) const;
  // remove(x, defect[*l]) for each link id l in [first, last), all of node x, in that order,
  // with each of the 19 slots read and written once (the same roundings).
  void remove_node(std::size_t fluid_cell, const double* defect, const std::uint32_t* first,
                   const std::uint32_t* last) const;
  // Whether node x pulls a population from a ghost beyond an open face: the open boundary
  // writes what x pulls before the kernel, so x's links and correction cannot wait for it.
  bool next_to_open(std::size_t fluid_cell) const;

 private:
  // Slot f_p(x - c_p) is slot_[p][x], the node it belongs to x + from_[p].
  Real* rest_;
  Real* slot_[D3Q19::Q];
  std::ptrdiff_t from_[D3Q19::Q];
  std::ptrdiff_t row_[4];   // +- e_2, +- e_3: the rows beside x along the first axis
  std::ptrdiff_t edge_[4];  // +- e_2 +- e_3
  const std::uint8_t* type_;
  Deferral deferral_;

  void remove_next_to_open(std::size_t fluid_cell, double defect) const;
};

// Removes the measured defects as described above; per_link from link_mass_defect.
// Slots in a ghost beyond an open face (rewritten by the open boundary stage after this one)
// are not written; their share goes on x's rest population.
void restore_link_mass(const std::vector<BoundaryLink>& links, const BlockLayout& layout,
                       const std::vector<std::uint8_t>& node_type,
                       const std::vector<double>& per_link, PopulationField& f);

}  // namespace lbm::moving_wall
