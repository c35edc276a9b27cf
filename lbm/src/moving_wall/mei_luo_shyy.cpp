#include "lbm/moving_wall/mei_luo_shyy.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <optional>

#include "lbm/collide_stream.h"
#include "lbm/fluid_solver.h"
#include "lbm/node_type.h"
#include "lbm/thread_team.h"
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

// KernelLinks (link_sweep.h) lives here so that the scheme's formula is inlined into the
// kernel's preparation as into the sweep, under this file's options (the same roundings).
// Allocated once; each step's part is rebuilt in place.
struct KernelLinks::State {
  // What the kernel's preparation reads in one step.
  struct Step {
    const LinkSweep& order;
    std::size_t num_links;
    MeiLuoShyy scheme;
    DirectionOffsets offsets;
    LinkSlots slots;
    LinkMassRestorer restorer;
    PopulationField* f;
    LinkPopulations* populations;
    double* defect;

    Step(const LinkSweep& order, std::size_t num_links, const MeiLuoShyy& scheme,
         FluidSolver& solver, LinkPopulations* populations, double* defect, double* deferred)
        : order(order),
          num_links(num_links),
          scheme(scheme),
          offsets(solver.layout()),
          slots(offsets, solver.populations()),
          restorer(solver.layout(), solver.node_types(), solver.populations(), {order.ids(), deferred}),
          f(&solver.populations()),
          populations(populations),
          defect(defect) {}

    // The nodes at sorted positions [i, end) that are (`open`) or are not next to an open face.
    void apply(std::size_t i, std::size_t end, bool open) const {
      apply_nodes(order, i, end, open, scheme, offsets, slots, scheme.rho0, restorer, *f,
                  populations, defect);
    }
  };
  std::optional<Step> step;
  // Seconds each thread spent in prepare in this step (a line each: written concurrently).
  struct alignas(64) ThreadSeconds {
    double value = 0.0;
  };
  mutable std::vector<ThreadSeconds> seconds;

  // PullPreparation::prepare: the nodes in cells [from, to) away from the open faces.
  static void prepare(const void* context, std::size_t from, std::size_t to) {
    const State& s = *static_cast<const State*>(context);
    const auto start = std::chrono::steady_clock::now();
    const std::uint32_t* const cells = s.step->order.sorted_cells();
    const std::uint32_t* const end = cells + s.step->num_links;
    const auto below = [](std::uint32_t cell, std::size_t bound) { return cell < bound; };
    const std::uint32_t* const lo = std::lower_bound(cells, end, from, below);
    const std::uint32_t* const hi = std::lower_bound(lo, end, to, below);
    s.step->apply(std::size_t(lo - cells), std::size_t(hi - cells), false);
    const std::size_t t = std::size_t(team_member().index);
    if (t < s.seconds.size())
      s.seconds[t].value += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
};

KernelLinks::KernelLinks() = default;
KernelLinks::~KernelLinks() = default;

double KernelLinks::prepared_seconds() const {
  double longest = 0.0;
  if (state_)
    for (const State::ThreadSeconds& s : state_->seconds) longest = std::max(longest, s.value);
  return longest;
}

void KernelLinks::begin(const std::vector<BoundaryLink>& links, FluidSolver& solver,
                        const NodeMomentField& field, LinkSweep& order,
                        std::vector<LinkPopulations>& populations, std::vector<double>& per_link) {
  const std::size_t n = links.size();
  order.sort(links, solver.layout());
  populations.resize(n);
  per_link.resize(n);
  order.deferred_defects().resize(n);
  const MeiLuoShyy scheme{solver.parameters().rho0, 1.0 / solver.trt().omega_plus,
                          solver.parameters().body_force, &solver.node_types(), nullptr, 0, &field};
  if (!state_) state_ = std::make_unique<State>();
  state_->step.emplace(order, n, scheme, solver, populations.data(), per_link.data(),
                       order.deferred_defects().data());
  state_->seconds.assign(std::size_t(max_threads()), State::ThreadSeconds{});
  state_->step->apply(0, n, true);
  // What a node's links read and write lies within one link of it (x + c_q, x - c_q).
  std::size_t reach = 0;
  for (const std::ptrdiff_t of : state_->step->offsets.of) reach = std::max(reach, std::size_t(std::abs(of)));
  solver.correct_pulls_in_next_step(order.sorted_cells(), order.deferred_defects().data(), n,
                                    PullPreparation{&State::prepare, state_.get(), reach});
}

}  // namespace lbm::moving_wall
