#include "lbm/moving_wall/links_ahead.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "link_loop.h"

namespace lbm::moving_wall {

namespace {
double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

struct LinksAhead::Slots {
  DirectionOffsets offsets;
  LinkSlots slots;
  Slots(const BlockLayout& layout, PopulationField& f) : offsets(layout), slots(offsets, f) {}
};

LinksAhead::~LinksAhead() = default;

LinksAhead::LinksAhead(const std::vector<BoundaryLink>& links, const LinkSweep& order,
                       const MeiLuoShyy& scheme, const BlockLayout& layout, double rho0,
                       PopulationField& f, const std::vector<std::uint8_t>& node_type,
                       std::vector<LinkPopulations>& populations, std::vector<double>& per_link)
    : order_(order),
      scheme_(scheme),
      layout_(layout),
      rho0_(rho0),
      f_(f),
      restorer_(layout, node_type, f),
      done_(links.size(), 0),
      per_link_(&per_link),
      slots_(std::make_unique<Slots>(layout, f)) {
  populations.resize(links.size());
  per_link.resize(links.size());
  pops_ = populations.data();
  defect_ = per_link.data();
  std::ptrdiff_t reach = 0;
  for (int q = 0; q < D3Q19::Q; ++q)
    reach = std::max(reach, std::abs(layout.offset(D3Q19::c[q][0], D3Q19::c[q][1], D3Q19::c[q][2])));
  reach_ = std::size_t(reach) + 1;
}

std::size_t LinksAhead::node(std::size_t i) {
  const std::size_t n = done_.size();
  const BoundaryLink* const link = order_.sorted_links();
  const std::size_t x = link[i].fluid_cell;
  if (done_[i]) {
    while (i < n && link[i].fluid_cell == x) ++i;
    return i;
  }
  done_[i] = 1;
  const std::size_t end =
      apply_node(order_, i, n, scheme_, slots_->offsets, slots_->slots, rho0_, f_, pops_, defect_);
  restorer_.remove_node(x, defect_, order_.ids() + i, order_.ids() + end);
  return end;
}

std::size_t LinksAhead::nodes_below(std::size_t i, std::size_t end, std::size_t to) {
  const BoundaryLink* const link = order_.sorted_links();
  while (i < end && link[i].fluid_cell < to) i = node(i);
  return i;
}

std::size_t LinksAhead::position_of(std::size_t cell) const {
  // The first position whose cell is at or after `cell`: its block's first, then on.
  const std::size_t block = std::min(cell >> LinkSweep::kBlockShift, order_.num_blocks());
  std::size_t i = order_.first(block);
  const std::size_t n = done_.size();
  while (i < n && order_.link(i).fluid_cell < cell) ++i;
  return i;
}

void LinksAhead::nodes_in_end_planes(int axis) {
  const std::size_t n = done_.size();
  for (std::size_t i = 0; i < n;) {
    const std::size_t x = order_.link(i).fluid_cell;
    const int c = layout_.coords(x)[std::size_t(axis)];
    if (c == 0 || c == layout_.size(axis) - 1) {
      i = node(i);
      continue;
    }
    while (i < n && order_.link(i).fluid_cell == x) ++i;
  }
}

void LinksAhead::begin(int t, int threads, std::size_t first, std::size_t last) {
  const double start = now();
#pragma omp single
  shares_.assign(std::size_t(threads), Share{});
  // (the single's barrier: every thread sees the shares)
  Share& share = shares_[std::size_t(t)];
  if (first < last) {
    const std::size_t head = std::min(last, first + reach_), tail = std::max(head, last > reach_ ? last - reach_ : 0);
    const std::size_t head_end = nodes_below(position_of(first), done_.size(), head);
    const std::size_t tail_start = position_of(tail);
    nodes_below(tail_start, done_.size(), last);
    share.next = head_end;
    share.stop = tail_start;
  }
  if (t == 0) seconds_ += now() - start;
}

void LinksAhead::before(int t, std::size_t cell) {
  Share& share = shares_[std::size_t(t)];
  if (share.next >= share.stop) return;
  const double start = t == 0 ? now() : 0.0;
  share.next = nodes_below(share.next, share.stop, cell + reach_);
  if (t == 0) seconds_ += now() - start;
}

LinkMassDefect LinksAhead::defect() const {
  LinkMassDefect total;
  for (const double d : *per_link_) total.add(d);
  return total;
}

}  // namespace lbm::moving_wall
