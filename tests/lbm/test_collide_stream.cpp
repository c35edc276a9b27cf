// The collide-stream kernel (lbm/src/collide_stream.cpp) on its own, on blocks whose rows
// are shorter than, as long as and longer than its chunk, with every node type mixed in:
// each owned fluid node gets the TRT collision (Guo forcing split into its even and odd
// parts) of what it pulls, every owned non-fluid node zeros, for all four variants
// (force or not, standard or He & Luo's incompressible equilibrium). The kernel walks runs
// of several rows with the x padding inside; a wrong offset or a misplaced padding cell
// shows here as a node off its reference; both ways of storing (streaming and plain) are
// checked. Its output on the owned nodes is also the same bit for bit on one and two
// threads and whatever the destination held before, and in place (the AA pattern of
// lbm::PopulationField, both placements) the same bit for bit as into a second array.
#include <gtest/gtest.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <array>
#include <cstring>
#include <random>
#include <vector>

#include "lbm/collide_stream.h"
#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "lbm/population_field.h"

namespace {

using L = lbm::D3Q19;

// The 19 arrays of a flat SoA vector of 19 x n values.
std::array<lbm::Real*, L::Q> arrays_of(std::vector<lbm::Real>& v, std::size_t n) {
  std::array<lbm::Real*, L::Q> a{};
  for (int q = 0; q < L::Q; ++q) a[std::size_t(q)] = v.data() + std::size_t(q) * n;
  return a;
}

struct KernelCase {
  lbm::BlockLayout layout;
  std::vector<lbm::Real> src;
  std::vector<std::uint8_t> type;
  lbm::CollideStreamArgs args(bool forced, bool incompressible) const {
    lbm::CollideStreamArgs a;
    for (int q = 0; q < L::Q; ++q) a.src[std::size_t(q)] = src.data() + std::size_t(q) * layout.num_cells();
    a.node_type = type.data();
    a.layout = layout;
    a.omega_plus = 1.0 / 0.8;
    a.omega_minus = 1.1;
    if (forced) a.force = {1e-5, -2e-5, 3e-6};
    a.incompressible = incompressible;
    a.rho0 = 1.0;
    return a;
  }
};

// Populations near rest (density about 1), node types at random: 70 % fluid, the rest
// solid, moving and open, ghosts included.
KernelCase random_case(std::array<int, 3> dims, unsigned seed) {
  lbm::Box box;
  box.hi = dims;
  KernelCase c{lbm::BlockLayout(box), {}, {}};
  const std::size_t n = c.layout.num_cells();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(0.01, 0.1);
  std::uniform_int_distribution<int> kind(0, 9);
  c.src.resize(L::Q * n);
  for (auto& v : c.src) v = static_cast<lbm::Real>(value(rng));
  c.type.resize(n);
  const std::uint8_t other[3] = {lbm::kSolid, lbm::kMoving, lbm::kOpen};
  for (auto& t : c.type) {
    const int r = kind(rng);
    t = r < 7 ? std::uint8_t(lbm::kFluid) : other[r - 7];
  }
  return c;
}

// The collided populations of one fluid node, written out formula by formula: the
// equilibria from lbm::equilibrium, split into even and odd parts.
std::array<double, L::Q> reference_node(const KernelCase& c, const lbm::CollideStreamArgs& a,
                                        std::size_t cell) {
  const std::size_t n = c.layout.num_cells();
  double fin[L::Q], rho = 0.0, j[3] = {0.0, 0.0, 0.0};
  for (int q = 0; q < L::Q; ++q) {
    fin[q] = c.src[q * n + cell - c.layout.offset(L::c[q][0], L::c[q][1], L::c[q][2])];
    rho += fin[q];
    for (int d = 0; d < 3; ++d) j[d] += fin[q] * L::c[q][d];
  }
  const double m = a.incompressible ? a.rho0 : rho;  // momentum density (He & Luo: rho0)
  std::array<double, 3> u;
  for (int d = 0; d < 3; ++d) u[d] = (j[d] + 0.5 * a.force[d]) / m;
  double feq[L::Q];
  for (int q = 0; q < L::Q; ++q)
    feq[q] = a.incompressible ? lbm::incompressible_equilibrium(q, rho, a.rho0, u)
                              : lbm::equilibrium(q, rho, u);
  const double uf = u[0] * a.force[0] + u[1] * a.force[1] + u[2] * a.force[2];
  std::array<double, L::Q> out;
  for (int q = 0; q < L::Q; ++q) {
    const int o = L::opposite(q);
    const double cu = L::c[q][0] * u[0] + L::c[q][1] * u[1] + L::c[q][2] * u[2];
    const double cf = L::c[q][0] * a.force[0] + L::c[q][1] * a.force[1] + L::c[q][2] * a.force[2];
    const double source_even = (1.0 - 0.5 * a.omega_plus) * L::w[q] * (9.0 * cu * cf - 3.0 * uf);
    const double source_odd = (1.0 - 0.5 * a.omega_minus) * L::w[q] * 3.0 * cf;
    out[q] = fin[q] - a.omega_plus * (0.5 * (fin[q] + fin[o]) - 0.5 * (feq[q] + feq[o])) -
             a.omega_minus * (0.5 * (fin[q] - fin[o]) - 0.5 * (feq[q] - feq[o])) + source_even +
             source_odd;
  }
  return out;
}

template <class Visit>
void for_owned(const lbm::BlockLayout& g, Visit visit) {
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i) visit(g.cell(i, j, k));
}

void set_threads(int threads) {
#ifdef _OPENMP
  omp_set_num_threads(threads);
#else
  (void)threads;
#endif
}

// Rows of 1, 9, 45 (the paper's rank block), 64, 128 (one chunk) and 200 nodes; a single
// row, a single plane, planes fewer than threads.
const std::array<int, 3> kBlocks[] = {{45, 12, 6}, {13, 7, 5}, {200, 3, 2}, {128, 4, 3},
                                      {64, 9, 2},  {1, 5, 5},  {9, 1, 3},   {3, 50, 1}};

}  // namespace

TEST(CollideStream, EveryOwnedNodeGetsItsCollisionOrZero) {
  // In single precision the kernel rounds each value once, at the store.
  const double tolerance = sizeof(lbm::Real) == sizeof(double) ? 1e-14 : 1e-7;
  unsigned seed = 1;
  for (const auto& dims : kBlocks) {
    const KernelCase c = random_case(dims, seed++);
    const std::size_t n = c.layout.num_cells();
    for (int variant = 0; variant < 8; ++variant) {
      lbm::CollideStreamArgs base = c.args(variant & 1, variant & 2);
      base.stores = variant & 4 ? lbm::CollideStreamArgs::Stores::kPlain
                                : lbm::CollideStreamArgs::Stores::kStreaming;
      std::vector<lbm::Real> dst(L::Q * n, lbm::Real(-3.0));
      lbm::CollideStreamArgs a = base;
      a.dst = arrays_of(dst, n);
      lbm::collide_stream(a);
      int wrong = 0;
      for_owned(c.layout, [&](std::size_t cell) {
        const bool fluid = c.type[cell] == lbm::kFluid;
        const auto expected = fluid ? reference_node(c, a, cell) : std::array<double, L::Q>{};
        for (int q = 0; q < L::Q; ++q) {
          const double got = dst[q * n + cell];
          if (fluid ? std::abs(got - expected[q]) > tolerance : got != 0.0) ++wrong;
        }
      });
      EXPECT_EQ(wrong, 0) << "block " << dims[0] << " x " << dims[1] << " x " << dims[2]
                          << ", variant " << variant;
    }
  }
}

TEST(CollideStream, OwnedOutputIsTheSameOnTwoThreadsAndOverAnyOldContent) {
  for (const auto& dims : kBlocks) {
    const KernelCase c = random_case(dims, 99);
    const std::size_t n = c.layout.num_cells();
    lbm::CollideStreamArgs a = c.args(true, false);
    a.stores = lbm::CollideStreamArgs::Stores::kStreaming;
    std::vector<lbm::Real> one(L::Q * n, lbm::Real(0.0)), two(L::Q * n, lbm::Real(5.0));
    set_threads(1);
    a.dst = arrays_of(one, n);
    lbm::collide_stream(a);
    set_threads(2);
    a.dst = arrays_of(two, n);
    lbm::collide_stream(a);
    set_threads(1);
    int differing = 0;
    for_owned(c.layout, [&](std::size_t cell) {
      for (int q = 0; q < L::Q; ++q)
        differing += std::memcmp(&one[q * n + cell], &two[q * n + cell], sizeof(lbm::Real)) != 0;
    });
    EXPECT_EQ(differing, 0) << "block " << dims[0] << " x " << dims[1] << " x " << dims[2];
  }
}

// In place: the field's populations are read under one placement and written under the
// other into the same slots (each node's output where its input was pulled from). Two
// steps, one from each placement, on one and two threads and with both ways of storing:
// every owned node's output is the same bit for bit as the kernel's into a second array,
// and the owned output of the first step survives as the second step's input (no node
// wrote into another node's slots).
TEST(CollideStream, InPlaceGivesTheSecondArrayResultUnderBothPlacements) {
  using Placement = lbm::PopulationField::Placement;
  for (const auto& dims : kBlocks) {
    for (int variant = 0; variant < 4; ++variant) {
      KernelCase c = random_case(dims, 7);
      const std::size_t n = c.layout.num_cells();
      lbm::PopulationField field(c.layout);
      for (std::size_t cell = 0; cell < n; ++cell)
        for (int q = 0; q < L::Q; ++q) field.at(q, cell) = c.src[std::size_t(q) * n + cell];
      set_threads(variant & 1 ? 2 : 1);
      int differing = 0;
      for (int step = 0; step < 2; ++step) {
        // The reference: the same input into a second array.
        lbm::CollideStreamArgs a = c.args(true, false);
        a.stores = variant & 2 ? lbm::CollideStreamArgs::Stores::kStreaming
                               : lbm::CollideStreamArgs::Stores::kByCacheSize;
        std::vector<lbm::Real> expected(L::Q * n, lbm::Real(0.0));
        a.dst = arrays_of(expected, n);
        lbm::collide_stream(a);
        // In place.
        const Placement from = field.placement(), to = lbm::other(from);
        const auto read = field.arrays(from);
        for (int q = 0; q < L::Q; ++q) a.src[std::size_t(q)] = read[std::size_t(q)];
        a.dst = field.arrays(to);
        a.in_place = true;
        lbm::collide_stream(a);
        field.set_placement(to);
        for_owned(c.layout, [&](std::size_t cell) {
          for (int q = 0; q < L::Q; ++q) {
            const lbm::Real got = field.at(q, cell);
            differing += std::memcmp(&got, &expected[std::size_t(q) * n + cell], sizeof got) != 0;
          }
        });
        // The next step's input: this output, and at every other cell what the field holds
        // there now (the same cells as the reference pulls).
        for (std::size_t cell = 0; cell < n; ++cell)
          for (int q = 0; q < L::Q; ++q) c.src[std::size_t(q) * n + cell] = field.at(q, cell);
      }
      set_threads(1);
      EXPECT_EQ(differing, 0) << "block " << dims[0] << " x " << dims[1] << " x " << dims[2]
                              << ", variant " << variant;
    }
  }
}

namespace {
// A random case with a static wall across it: the solid slab x in [nx/4, nx/2) (a stretch
// long enough to split a span where the rows are) and the random types elsewhere.
KernelCase walled_case(std::array<int, 3> dims, unsigned seed) {
  KernelCase c = random_case(dims, seed);
  for (int k = -1; k <= dims[2]; ++k)
    for (int j = -1; j <= dims[1]; ++j)
      for (int i = dims[0] / 4; i < dims[0] / 2; ++i) c.type[c.layout.cell(i, j, k)] = lbm::kSolid;
  return c;
}
}  // namespace

// The spans cover every owned cell that is not a static wall exactly once and nothing
// beyond the owned rows and their x padding; what they leave out are static walls only,
// in gaps of at least kMinSkippedCells cells.
TEST(CollideStream, SpansCoverEveryOwnedCellButStaticWallsOnce) {
  for (const auto& dims : kBlocks) {
    const KernelCase c = walled_case({dims[0] * 2, dims[1], dims[2]}, 3);
    const auto spans = lbm::spans_without_solid(c.layout, c.type.data());
    std::vector<int> covered(c.layout.num_cells(), 0);
    for (const lbm::KernelSpan& s : spans) {
      const auto first = c.layout.coords(s.first), last = c.layout.coords(s.first + s.length - 1);
      EXPECT_TRUE(c.layout.is_owned(first[0], first[1], first[2]) &&
                  c.layout.is_owned(last[0], last[1], last[2]));
      EXPECT_NE(c.type[s.first], lbm::kSolid);
      EXPECT_NE(c.type[s.first + s.length - 1], lbm::kSolid);
      for (int p = 0; p < s.length; ++p) {
        const auto ijk = c.layout.coords(s.first + p);
        // Inside a plane's rows: owned, or the x padding between two rows.
        EXPECT_TRUE(ijk[1] >= 0 && ijk[1] < c.layout.size(1) && ijk[2] >= 0 && ijk[2] < c.layout.size(2));
        ++covered[s.first + p];
      }
    }
    int wrong = 0;
    for_owned(c.layout, [&](std::size_t cell) {
      if (covered[cell] > 1 || (covered[cell] == 0 && c.type[cell] != lbm::kSolid)) ++wrong;
    });
    EXPECT_EQ(wrong, 0) << "block " << dims[0] * 2 << " x " << dims[1] << " x " << dims[2];
    // Consecutive spans of a plane are at least kMinSkippedCells apart.
    for (std::size_t i = 1; i < spans.size(); ++i) {
      const std::size_t end = spans[i - 1].first + spans[i - 1].length;
      if (c.layout.coords(end - 1)[2] == c.layout.coords(spans[i].first)[2]) {
        EXPECT_GE(spans[i].first - end, std::size_t(lbm::kMinSkippedCells));
      }
    }
  }
}

// With spans, every computed node gets exactly what the whole-block kernel gives it, and a
// left-out static wall keeps what its slots held (the kernel neither reads nor writes it).
TEST(CollideStream, SpansGiveTheWholeBlockResultAndLeaveWallsAlone) {
  for (const auto& dims : kBlocks) {
    const KernelCase c = walled_case({dims[0] * 2, dims[1], dims[2]}, 5);
    const std::size_t n = c.layout.num_cells();
    const auto spans = lbm::spans_without_solid(c.layout, c.type.data());
    std::vector<int> covered(n, 0);
    for (const lbm::KernelSpan& s : spans)
      for (int p = 0; p < s.length; ++p) covered[s.first + p] = 1;
    for (int threads = 1; threads <= 2; ++threads) {
      set_threads(threads);
      lbm::CollideStreamArgs a = c.args(true, false);
      std::vector<lbm::Real> whole(L::Q * n, lbm::Real(-3.0)), part(L::Q * n, lbm::Real(-3.0));
      a.dst = arrays_of(whole, n);
      lbm::collide_stream(a);
      a.dst = arrays_of(part, n);
      a.spans = spans.data();
      a.num_spans = spans.size();
      lbm::collide_stream(a);
      int wrong = 0;
      for_owned(c.layout, [&](std::size_t cell) {
        for (int q = 0; q < L::Q; ++q) {
          const std::size_t i = std::size_t(q) * n + cell;
          if (covered[cell] ? std::memcmp(&whole[i], &part[i], sizeof(lbm::Real)) != 0
                            : part[i] != lbm::Real(-3.0))
            ++wrong;
        }
      });
      EXPECT_EQ(wrong, 0) << "block " << dims[0] * 2 << " x " << dims[1] << " x " << dims[2]
                          << ", " << threads << " threads";
    }
    set_threads(1);
  }
}
