#include "lbm/halo_exchange.h"

#include <algorithm>
#include <array>
#include <string>
#include <type_traits>

#include "lbm/d3q19.h"
#include "lbm/input_error.h"

namespace lbm {

namespace {
// Tags of the two directions of a sweep along `axis`; distinct, so the two messages cannot
// be confused when one rank is both neighbours (two ranks on a periodic axis). The base
// keeps clear of the small tags a host (LIGGGHTS) uses on the same communicator.
constexpr int kTagBase = 0x4c42;
int tag_up(int axis) { return kTagBase + 2 * axis; }
int tag_down(int axis) { return kTagBase + 2 * axis + 1; }

// Below this many values the periodic ghost copies stay on one thread.
constexpr std::size_t kMinParallelCopy = 16384;

// The two axes other than `axis`, in increasing order; for the y and z sweeps the inner
// one is x, so packing walks memory contiguously.
std::array<int, 2> other_axes(int axis) {
  return axis == 0 ? std::array<int, 2>{1, 2}
                   : (axis == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1});
}

// Visits the cells of the padded plane with local index `plane` normal to `axis`, the
// full padded extent of the other two axes (ghosts included), in a fixed order that the
// sender and the receiver share.
template <class Visit>
void for_plane(const BlockLayout& layout, int axis, int plane, Visit visit) {
  const std::array<std::size_t, 3> stride{1, std::size_t(layout.padded(0)),
                                          std::size_t(layout.padded(0)) * layout.padded(1)};
  const auto [b, c] = other_axes(axis);
  const std::size_t base = std::size_t(plane + BlockLayout::kGhost) * stride[axis];
  std::size_t n = 0;
  for (int v = 0; v < layout.padded(c); ++v)
    for (int u = 0; u < layout.padded(b); ++u, ++n) visit(n, base + v * stride[c] + u * stride[b]);
}
}  // namespace

HaloExchange::HaloExchange(const Decomposition& decomposition, const BlockLayout& layout)
    : decomposition_(decomposition), layout_(layout) {
  for (int a = 0; a < 3; ++a)
    if (layout_.owned().lo[a] != decomposition_.owned.lo[a] ||
        layout_.owned().hi[a] != decomposition_.owned.hi[a])
      throw InputError("halo exchange: the block layout is not the decomposition's owned box");
  // Along an axis this rank owns entirely there is no other rank to talk to: the neighbour
  // is this rank if the axis is periodic, none otherwise. Deriving it here keeps the halo
  // consistent with `periodic` even if the caller left `neighbor` at its default.
  const int self = decomposition_.comm.rank();
  for (int a = 0; a < 3; ++a)
    if (decomposition_.owned.lo[a] == decomposition_.global.lo[a] &&
        decomposition_.owned.hi[a] == decomposition_.global.hi[a])
      decomposition_.neighbor[a] =
          decomposition_.periodic[a] ? std::array<int, 2>{self, self} : std::array<int, 2>{-1, -1};
  std::size_t largest_plane = 0;
  for (int a = 0; a < 3; ++a) {
    const auto [b, c] = other_axes(a);
    largest_plane = std::max(largest_plane, std::size_t(layout_.padded(b)) * layout_.padded(c));
  }
  // Sized for 19 populations; the crossing five and exchange_scalar use a slice of them.
  const std::size_t capacity = largest_plane * D3Q19::Q;
  send_low_.assign(capacity, 0.0);
  send_high_.assign(capacity, 0.0);
  recv_low_.assign(capacity, 0.0);
  recv_high_.assign(capacity, 0.0);
  check_neighbours();
  collect_sent_cells();
  collect_crossing();
}

// The planes sweep() packs (or, for a periodic axis owned alone, copies from): plane 0 when
// the lower side has a neighbour, plane n - 1 when the upper one has, the whole padded plane.
void HaloExchange::collect_sent_cells() {
  for (int a = 0; a < 3; ++a) {
    const auto& nb = decomposition_.neighbor[a];
    auto add = [&](std::size_t, std::size_t cell) { sent_planes_[a].push_back(cell); };
    auto ghost = [&](std::size_t, std::size_t cell) { ghost_planes_[a].push_back(cell); };
    if (nb[0] >= 0) {
      for_plane(layout_, a, 0, add);
      for_plane(layout_, a, -1, ghost);
    }
    if (nb[1] >= 0) {
      for_plane(layout_, a, layout_.size(a) - 1, add);
      for_plane(layout_, a, layout_.size(a), ghost);
    }
    sent_cells_.insert(sent_cells_.end(), sent_planes_[a].begin(), sent_planes_[a].end());
  }
  std::sort(sent_cells_.begin(), sent_cells_.end());
  sent_cells_.erase(std::unique(sent_cells_.begin(), sent_cells_.end()), sent_cells_.end());
}

// Face neighbours must share this rank's extent in the other two axes and touch it along
// the sweep axis, otherwise packed planes would not line up; a host that builds the
// decomposition by hand gets a message instead of silently wrong ghosts.
void HaloExchange::check_neighbours() const {
  const Decomposition& d = decomposition_;
  const int self = d.comm.rank();
  double mine[6], below[6], above[6];
  for (int a = 0; a < 3; ++a) {
    mine[a] = d.owned.lo[a];
    mine[3 + a] = d.owned.hi[a];
  }
  for (int a = 0; a < 3; ++a) {
    const int lo = d.neighbor[a][0], hi = d.neighbor[a][1];
    if (lo == self && hi == self) continue;
    std::fill(below, below + 6, -1.0);
    std::fill(above, above + 6, -1.0);
    d.comm.sendrecv(mine, 6, hi, below, 6, lo, tag_up(a));
    d.comm.sendrecv(mine, 6, lo, above, 6, hi, tag_down(a));
    const int n = d.global.size(a);
    for (int side = 0; side < 2; ++side) {
      const int other = d.neighbor[a][side];
      if (other < 0) continue;
      const double* box = side == 0 ? below : above;
      // Along `a` the neighbour's box ends where ours starts (or wraps around periodically).
      const int expected = side == 0 ? d.owned.lo[a] : d.owned.hi[a];
      const int touching = side == 0 ? int(box[3 + a]) : int(box[a]);
      bool ok = touching == expected || (touching - expected) % n == 0;
      const auto [b, c] = other_axes(a);
      for (int t : {b, c}) ok = ok && box[t] == mine[t] && box[3 + t] == mine[3 + t];
      if (!ok)
        throw InputError("halo exchange: rank " + std::to_string(self) + " and its " +
                         (side == 0 ? "lower" : "upper") + " neighbour rank " +
                         std::to_string(other) + " along " + std::string(1, "xyz"[a]) +
                         " do not share a face (face neighbours must touch and have the "
                         "same extent in the other two axes)");
    }
  }
}

// `up` are the arrays whose values travel upward along `axis` (the highest owned plane to
// the low ghost plane of the block above), `down` those travelling downward; for the
// populations they are the five crossing each face into the receiving block, or all 19.
template <class Array>
void HaloExchange::sweep(int axis, const Array* up, int num_up, const Array* down, int num_down) {
  using T = std::remove_reference_t<decltype(up[0][0])>;
  const Decomposition& d = decomposition_;
  const int n = layout_.size(axis);
  const int self = d.comm.rank();
  const int lo = d.neighbor[axis][0], hi = d.neighbor[axis][1];
  if (lo == self && hi == self) {
    // Periodic axis owned by this rank alone: ghosts are copies of the opposite face.
    // Distance between a ghost plane and the owned plane it copies.
    const std::ptrdiff_t shift =
        std::ptrdiff_t(n) * layout_.offset(axis == 0, axis == 1, axis == 2);
    // Plain copies from owned planes into ghost planes: the arrays may go to any thread.
    const auto [b, c] = other_axes(axis);
    const bool split = std::size_t(layout_.padded(b)) * layout_.padded(c) * (num_up + num_down) >=
                       kMinParallelCopy;
#pragma omp parallel for schedule(static) if (split)
    for (int m = 0; m < num_up + num_down; ++m) {
      if (m < num_up) {
        const Array f = up[m];
        for_plane(layout_, axis, -1,
                  [&](std::size_t, std::size_t ghost) { f[ghost] = f[ghost + shift]; });
      } else {
        const Array f = down[m - num_up];
        for_plane(layout_, axis, n,
                  [&](std::size_t, std::size_t ghost) { f[ghost] = f[ghost - shift]; });
      }
    }
    return;
  }
  // A non-periodic axis this rank owns entirely has nobody to talk to: both ghost planes
  // stay as they are (boundary conditions own them), so there is nothing to pack or send.
  // Only this rank takes that decision, and no other rank expects a message from it.
  if (lo < 0 && hi < 0) return;
  const auto [b, c] = other_axes(axis);
  const std::size_t plane = std::size_t(layout_.padded(b)) * layout_.padded(c);
  // Pack: the lowest owned plane goes down, the highest owned plane goes up; a plane whose
  // side has no neighbour goes to MPI_PROC_NULL, so it is not packed.
  if (lo >= 0)
    for (int m = 0; m < num_down; ++m) {
      const Array f = down[m];
      double* low = send_low_.data() + m * plane;
      for_plane(layout_, axis, 0, [&](std::size_t i, std::size_t cell) { low[i] = double(f[cell]); });
    }
  if (hi >= 0)
    for (int m = 0; m < num_up; ++m) {
      const Array f = up[m];
      double* high = send_high_.data() + m * plane;
      for_plane(layout_, axis, n - 1,
                [&](std::size_t i, std::size_t cell) { high[i] = double(f[cell]); });
    }
  // Both ends count the same: num_up and num_down follow from flags all ranks share.
  const int count_up = int(plane) * num_up, count_down = int(plane) * num_down;
  // Upward: our top plane to the rank above, the low ghost from the rank below; then down.
  d.comm.sendrecv(send_high_.data(), count_up, hi, recv_low_.data(), count_up, lo, tag_up(axis));
  d.comm.sendrecv(send_low_.data(), count_down, lo, recv_high_.data(), count_down, hi,
                  tag_down(axis));
  // Unpack, leaving ghosts at a non-periodic domain edge (no neighbour) untouched.
  if (lo >= 0)
    for (int m = 0; m < num_up; ++m) {
      const Array f = up[m];
      const double* low = recv_low_.data() + m * plane;
      for_plane(layout_, axis, -1, [&](std::size_t i, std::size_t cell) { f[cell] = T(low[i]); });
    }
  if (hi >= 0)
    for (int m = 0; m < num_down; ++m) {
      const Array f = down[m];
      const double* high = recv_high_.data() + m * plane;
      for_plane(layout_, axis, n, [&](std::size_t i, std::size_t cell) { f[cell] = T(high[i]); });
    }
}

// Which populations cross the faces of `axis`: c_q[axis] = +1 (they enter a block through
// its low face, so they travel up) and c_q[axis] = -1 (down), in q order.
void HaloExchange::collect_crossing() {
  for (int a = 0; a < 3; ++a) {
    int up = 0, down = 0;
    for (int q = 0; q < D3Q19::Q; ++q) {
      if (D3Q19::c[q][a] == +1) crossing_up_[a][up++] = q;
      if (D3Q19::c[q][a] == -1) crossing_down_[a][down++] = q;
    }
    num_crossing_[a] = up;  // 5 each way in D3Q19
  }
}

void HaloExchange::exchange(PopulationField& field) { exchange(field, HaloPopulations::every()); }

// x, then y, then z: each later sweep carries the ghosts the earlier ones filled, so edge
// ghosts arrive without diagonal messages. With the crossing populations only, an edge
// ghost g = x - c_q that an owned x pulls from lies beyond the faces of exactly the axes
// where c_q is non-zero, and c_q points into the block on each of them, so q is in the
// crossing set of every sweep that writes g: it arrives through the same sweeps as with all
// 19 (e.g. (1,1,0) travels up in the x and in the y sweep). D3Q19 has no corner direction,
// so no corner ghost is pulled. A population outside a sweep's set keeps, at that sweep's
// ghosts, whatever it held (a stale or intermediate value that nothing reads, see the
// audit in halo_exchange.h).
void HaloExchange::exchange(PopulationField& field, const HaloPopulations& which) {
  if (field.num_cells() != layout_.num_cells())
    throw InputError("halo exchange: population field does not match the block layout");
  Real* up[D3Q19::Q];
  Real* down[D3Q19::Q];
  for (int axis = 0; axis < 3; ++axis) {
    int num = D3Q19::Q;
    if (which.all[axis]) {
      for (int q = 0; q < D3Q19::Q; ++q) up[q] = down[q] = field.q(q);
    } else {
      num = num_crossing_[axis];
      for (int m = 0; m < num; ++m) {
        up[m] = field.q(crossing_up_[axis][m]);
        down[m] = field.q(crossing_down_[axis][m]);
      }
    }
    sweep(axis, up, num, down, num);
  }
}

void HaloExchange::exchange_scalar(std::vector<double>& values) {
  if (values.size() != layout_.num_cells())
    throw InputError("halo exchange: scalar field does not match the block layout");
  double* arrays[1] = {values.data()};
  // The same sweeps as exchange(), so edge ghosts arrive the same way.
  exchange_scalars(arrays, 1, {true, true, true});
}

void HaloExchange::exchange_scalars(double* const* fields, int count, const std::array<bool, 3>& axes) {
  if (count > D3Q19::Q) throw InputError("halo exchange: more than 19 fields in one exchange");
  for (int axis = 0; axis < 3; ++axis)
    if (axes[axis]) sweep(axis, fields, count, fields, count);
}

namespace {
// Value k of every cell of an interleaved field, indexed by cell like an array.
struct Interleaved {
  double* first;  // value k of cell 0
  std::ptrdiff_t width;
  double& operator[](std::size_t cell) const { return first[width * std::ptrdiff_t(cell)]; }
};
}  // namespace

void HaloExchange::exchange_interleaved(double* values, int width, const std::array<bool, 3>& axes) {
  if (width > D3Q19::Q) throw InputError("halo exchange: more than 19 values per cell in one exchange");
  Interleaved fields[D3Q19::Q];
  for (int k = 0; k < width; ++k) fields[k] = {values + k, width};
  for (int axis = 0; axis < 3; ++axis)
    if (axes[axis]) sweep(axis, fields, width, fields, width);
}

bool HaloExchange::exchanges_face(int axis, int side) const {
  return decomposition_.neighbor[axis][side] >= 0;
}

bool HaloExchange::borders_exchanged_ghost(std::size_t cell) const {
  const auto c = layout_.coords(cell);
  if (!layout_.is_owned(c[0], c[1], c[2])) return false;
  for (int a = 0; a < 3; ++a)
    if ((c[a] == 0 && decomposition_.neighbor[a][0] >= 0) ||
        (c[a] == layout_.size(a) - 1 && decomposition_.neighbor[a][1] >= 0))
      return true;
  return false;
}

bool HaloExchange::is_exchanged_ghost(std::size_t cell) const {
  const auto c = layout_.coords(cell);
  if (layout_.is_owned(c[0], c[1], c[2])) return false;
  for (int a = 0; a < 3; ++a)
    if ((c[a] == -1 && decomposition_.neighbor[a][0] >= 0) ||
        (c[a] == layout_.size(a) && decomposition_.neighbor[a][1] >= 0))
      return true;
  return false;
}

}  // namespace lbm
