#include "lbm/collide_stream.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "lbm/streaming_store.h"
#include "lbm/thread_team.h"

namespace lbm {

double equilibrium(int q, double rho, const std::array<double, 3>& u) {
  const double cu = D3Q19::c[q][0] * u[0] + D3Q19::c[q][1] * u[1] + D3Q19::c[q][2] * u[2];
  const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  return D3Q19::w[q] * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * uu);
}

double incompressible_equilibrium(int q, double rho, double rho0, const std::array<double, 3>& u) {
  const double cu = D3Q19::c[q][0] * u[0] + D3Q19::c[q][1] * u[1] + D3Q19::c[q][2] * u[2];
  const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  return D3Q19::w[q] * (rho + rho0 * (3.0 * cu + 4.5 * cu * cu - 1.5 * uu));
}

namespace {

using L = D3Q19;

// The kernel walks runs of consecutive cells: all owned rows of a y-z plane (or of a part
// of one, where there are fewer planes than threads) with the x padding between them, so a
// run is one stretch of memory per population. Pulling with the flat offsets is valid for
// every owned cell of a run; the ghost cells inside it (the x padding) are computed like
// solid nodes and get 0 written. No stage reads a ghost slot it has not written in the
// same step: the halo exchange rewrites, at periodic and rank-face ghosts, every population
// an owned node pulls (the five crossing each face, or all 19: halo_exchange.h, whose audit
// also covers the padding cells computed here), and at a closed or open edge (ghosts the
// exchange leaves untouched) static bounce-back and the open faces write every slot a fluid
// node pulls, each step
// (FluidSolver::step). Short rows (the paper's rank block: 45 nodes) then write no partial
// cache line at each row end and population, and the padding costs 2 computed cells a row.
//
// The solver runs the kernel in place (PopulationField: the AA pattern), src and dst two
// placements of one field: every node writes its 19 outputs into the 19 slots it pulled
// from, and no other node reads or writes them, so the chunks below need no order among
// nodes. A chunk reads all its nodes' inputs before it writes any output.
//
// A run is processed in chunks of kChunk nodes: the populations are pulled straight from
// the source array and collided. With plain stores (always in place, and for two arrays
// the cache holds) the results go straight into the destination. With streaming stores
// (two arrays larger than the cache: no write-allocate, 2 x 19 values moved per update, not
// 3 x 19) they are gathered in a small L1/L2-resident SoA buffer (19 contiguous streams)
// and written out from it: the tail of a chunk's output that does not fill a cache line is
// held back and stored with the next chunk's head (streaming_store_keep_tail), so inside a
// run every line of every population is one vector store. The arithmetic is vectorised
// across the chunk's nodes: it reads the node types as a double mask, since GCC does not
// vectorise a loop that mixes byte and double lanes.
// The chunk length depends on the stores. Streamed to memory, longer bursts per population
// pay: the memory serves 38 streams (19 pulled, 19 written) far below its one-stream copy
// bandwidth, and less so the longer each write burst (measured on a 2-core AMD EPYC KVM
// guest, 32 MiB L3: 128^3 on one thread 56 -> 86-90 MLUPS from 128 to 320 nodes, the
// paper's rank block of 90 x 20 x 40 on two concurrent processes 50 -> 64-69; 512 and more
// fall back). With plain stores 128 (in place: 256 and 512 no faster at 64^3, 128^3 or on
// the paper's rank block, 2 interleaved rounds). Measure with bench_lbm (doc/performance.md).
constexpr int kChunkStreaming = 320;
constexpr int kChunkPlain = 128;
// Nodes per block of a chunk with pull corrections (a multiple of the vector width).
constexpr int kCorrectedBlock = 32;
// Room for the held-back tail before a chunk's values: less than a line.
constexpr int kHeldBack = int(detail::kCacheLine / sizeof(Real));
// Streaming stores pay where the arrays do not stay in the cache between steps (128^3:
// 670 MB); where they do, they send the output to memory, from where the next step reads
// it back, and plain stores are faster (paper's rank block, 25 MB, in a 480 MB L3: 1.6x the
// rows with streamed bodies; 64^3: 1.3x; 128^3: 0.78x; bench_lbm, doc/performance.md). Plain
// stores when both population arrays take at most this share of the last-level cache, so
// that a second rank and the coupling's data fit beside them.
constexpr double kPlainStoresUpToCacheShare = 0.25;
// In place (the AA pattern, PopulationField) always plain stores, written straight from the
// arithmetic into the field: a plain store writes a line that has just been read, so it
// costs no write-allocate, and the 19 memcpy calls per chunk of the buffered path are gone.
// Measured with bench_lbm (2 interleaved pairs, in place, plain against streamed beyond half
// the L3): 128^3 on one thread 104-106 against 78 MLUPS, on two 132-147 against 117-118;
// 64^3 105-113 against 68-70 on one thread. (Plain stores through the buffer were no faster
// than streamed ones out of the cache.)
// The q loops carry "GCC unroll 19": GCC peels at most 16 iterations by default, and only a
// fully unrolled loop turns the velocity components into constants (a 2.5x speed-up).

// Cells [first, first + length) of one plane, starting at x = x0 of a row (0 for a whole
// plane, anywhere in an owned row for a span); rows are `pitch` cells apart, of which the
// first `row` are owned.
struct Run {
  std::size_t first;
  int length;
  int pitch;
  int row;
  int x0;
};

// fluid_mask[i] = 1 for the fluid nodes among run positions [start, start + m), 0 for the
// other nodes and for the x padding (ghost cells, whatever their type).
void fill_fluid_mask(const std::uint8_t* __restrict type, const Run& run, int start, int m,
                     double* __restrict fluid_mask) {
  for (int i = 0; i < m; ++i) fluid_mask[i] = type[run.first + start + i] == kFluid ? 1.0 : 0.0;
  const int from = start + run.x0;  // counted from x = 0 of the run's first row
  for (int row_start = from - from % run.pitch; row_start < from + m; row_start += run.pitch) {
    const int pad_first = row_start + run.row > from ? row_start + run.row : from;
    const int pad_end = row_start + run.pitch < from + m ? row_start + run.pitch : from + m;
    for (int p = pad_first; p < pad_end; ++p) fluid_mask[p - from] = 0.0;
  }
}

// One thread's share of the pull corrections' preparation (PullPreparation): the cells
// [begin, end) from its first run to the next thread's (the first thread's from 0, the last's
// to kNoCell), so that the shares cover every node once. The nodes within a reach of either
// end at once (before the barrier that precedes every thread's first block), then the
// others at least a reach ahead of each block it computes, kPreparedBatch cells at a time
// (before every block, a call per 32 nodes: no faster, the same bits).
constexpr std::size_t kNoCell = ~std::size_t(0);
constexpr std::size_t kPreparedBatch = 1024;
class PreparedCells {
 public:
  PreparedCells() = default;  // nothing to prepare
  PreparedCells(const PullPreparation& p, std::size_t begin, std::size_t end) : p_(p) {
    if (!p_.prepare || begin >= end) return;
    next_ = std::min(end, begin + p_.reach);
    stop_ = std::max(next_, end - std::min(end, p_.reach));
    p_.prepare(p_.context, begin, next_);
    if (stop_ < end) p_.prepare(p_.context, stop_, end);
  }
  // Before the kernel computes cells below `end`.
  void before(std::size_t end) {
    if (end + p_.reach <= next_) return;
    const std::size_t to = std::min(stop_, end + p_.reach + kPreparedBatch);
    if (to <= next_) return;
    p_.prepare(p_.context, next_, to);
    next_ = to;
  }

 private:
  PullPreparation p_;
  std::size_t next_ = 0, stop_ = 0;
};

// kIncompressible: He & Luo's equilibrium, the momentum rho0 u and rho only in the zeroth
// order (a compile-time choice, so the standard kernel's arithmetic is untouched).
// kMoments: the outputs' moments into moments, four per cell (CollideStreamArgs::moments).
// The pull corrections (CollideStreamArgs::pull_corrections) of a block of a chunk's nodes
// are prepared (`prepared`) and written into their slots just before the block pulls them.
template <int kChunk, bool kForce, bool kIncompressible, bool kMoments>
void collide_stream_run(const Real* const* src, Real* const* dst,
                        const std::uint8_t* __restrict type, const Run& run,
                        const std::ptrdiff_t* off, double omega_plus,
                        double omega_minus, double fx, double fy, double fz, double rho0,
                        double* moments, const PullCorrections& corrections,
                        PreparedCells& prepared) {
  constexpr bool streaming = kChunk == kChunkStreaming;
  using Out = std::conditional_t<streaming, double, Real>;
  const double source_even = 1.0 - 0.5 * omega_plus;
  const double source_odd = 1.0 - 0.5 * omega_minus;
  // The streaming stores' buffer (plain stores write straight into dst).
  constexpr int kBuffer = streaming ? kHeldBack + kChunk : 1;
  alignas(64) double f[L::Q][kBuffer];
  alignas(64) double fluid_mask[kChunk];
  int held[L::Q] = {};  // values of each population held back at the head of f[q]
  for (int start = 0; start < run.length; start += kChunk) {
    const int m = run.length - start < kChunk ? run.length - start : kChunk;
    const std::size_t first = run.first + start;
    const Real* pull[L::Q];
    // Plain stores go straight into the field (in place or not, a node's outputs are slots
    // no other node of the chunk reads); streaming stores into the buffer, whose lines
    // streaming_store_keep_tail writes whole.
    Out* out[L::Q];
    #pragma GCC unroll 19
    for (int q = 0; q < L::Q; ++q) {
      pull[q] = src[q] + first - off[q];
      if constexpr (streaming) out[q] = f[q] + held[q];
      else out[q] = dst[q] + first;
    }
    fill_fluid_mask(type, run, start, m, fluid_mask);
    // With pull corrections, the chunk in blocks of kCorrectedBlock nodes, each block's
    // corrections written into the slots it is about to pull (each node's slots are its own):
    // lines the hardware has just prefetched for the streams, a few ahead of them.
    const bool corrected = corrections.count != 0;
    for (int i0 = 0; i0 < m; i0 += corrected ? kCorrectedBlock : m) {
      const int i1 = corrected && i0 + kCorrectedBlock < m ? i0 + kCorrectedBlock : m;
      if (corrected) {
        prepared.before(first + std::size_t(i1));
        Real* slots[L::Q];
        #pragma GCC unroll 19
        for (int q = 0; q < L::Q; ++q) slots[q] = const_cast<Real*>(pull[q]) + i0;
        apply_pull_corrections(corrections, first + std::size_t(i0), first + std::size_t(i1), slots);
      }
#pragma omp simd
      for (int i = i0; i < i1; ++i) {
        const double fluid = fluid_mask[i];
        double fin[L::Q];
        [[maybe_unused]] double post[L::Q];
        #pragma GCC unroll 19
        for (int q = 0; q < L::Q; ++q) fin[q] = pull[q][i];
        double rho = 0.0, jx = 0.0, jy = 0.0, jz = 0.0;
        #pragma GCC unroll 19
        for (int q = 0; q < L::Q; ++q) {
          rho += fin[q];
          jx += fin[q] * L::c[q][0];
          jy += fin[q] * L::c[q][1];
          jz += fin[q] * L::c[q][2];
        }
        // Non-fluid nodes are computed on a harmless state (rho = 1, u = 0) and zeroed
        // below, so the loop needs no branch.
        rho = fluid * rho + (1.0 - fluid);
        const double inv_rho = kIncompressible ? 1.0 / rho0 : 1.0 / rho;
        double ux = fluid * jx * inv_rho, uy = fluid * jy * inv_rho, uz = fluid * jz * inv_rho;
        if (kForce) {
          ux += 0.5 * fx * inv_rho;
          uy += 0.5 * fy * inv_rho;
          uz += 0.5 * fz * inv_rho;
        }
        const double uu = 1.5 * (ux * ux + uy * uy + uz * uz);
        const double uf = kForce ? (ux * fx + uy * fy + uz * fz) : 0.0;
        {  // Rest population: purely even.
          const double feq =
              kIncompressible ? L::w[0] * (rho - rho0 * uu) : L::w[0] * rho * (1.0 - uu);
          double result = fin[0] - omega_plus * (fin[0] - feq);
          if (kForce) result += source_even * L::w[0] * (-3.0 * uf);
          out[0][i] = static_cast<Out>(fluid * result);
          if (kMoments) post[0] = static_cast<Real>(fluid * result);
        }
        // Pairs (q, q+1) are opposite: split into symmetric and antisymmetric parts.
        #pragma GCC unroll 19
        for (int q = 1; q < L::Q; q += 2) {
          const double cu = L::c[q][0] * ux + L::c[q][1] * uy + L::c[q][2] * uz;
          const double w = L::w[q];
          const double eq_plus = kIncompressible ? w * (rho + rho0 * (4.5 * cu * cu - uu))
                                                 : w * rho * (1.0 + 4.5 * cu * cu - uu);
          const double eq_minus = w * (kIncompressible ? rho0 : rho) * 3.0 * cu;
          const double a = fin[q], b = fin[q + 1];
          const double relax_plus = omega_plus * (0.5 * (a + b) - eq_plus);
          const double relax_minus = omega_minus * (0.5 * (a - b) - eq_minus);
          double source_plus = 0.0, source_minus = 0.0;
          if (kForce) {
            const double cf = L::c[q][0] * fx + L::c[q][1] * fy + L::c[q][2] * fz;
            source_plus = source_even * w * (9.0 * cu * cf - 3.0 * uf);
            source_minus = source_odd * w * 3.0 * cf;
          }
          out[q][i] = static_cast<Out>(fluid * (a - relax_plus - relax_minus + source_plus + source_minus));
          out[q + 1][i] = static_cast<Out>(fluid * (b - relax_plus + relax_minus + source_plus - source_minus));
          if (kMoments) {
            post[q] = static_cast<Real>(fluid * (a - relax_plus - relax_minus + source_plus + source_minus));
            post[q + 1] = static_cast<Real>(fluid * (b - relax_plus + relax_minus + source_plus - source_minus));
          }
        }
        if (kMoments) {
          // node_moments (macroscopic.cpp) of the stored values, in its order: rho and j
          // summed over q = 0..18, the terms with c = 0 left out, c = -1 subtracted.
          double m_rho = 0.0, m_j[3] = {0.0, 0.0, 0.0};
          #pragma GCC unroll 19
          for (int q = 0; q < L::Q; ++q) {
            m_rho += post[q];
            #pragma GCC unroll 3
            for (int a = 0; a < 3; ++a) {
              if (L::c[q][a] == 1) m_j[a] += post[q];
              if (L::c[q][a] == -1) m_j[a] -= post[q];
            }
          }
          m_rho += 1.0 - fluid;  // exact for fluid nodes (+0), 1 elsewhere
          double* const kept = moments + 4 * (first + std::size_t(i));
          kept[0] = m_rho;
          kept[1] = (m_j[0] - 0.5 * fx) / m_rho;
          kept[2] = (m_j[1] - 0.5 * fy) / m_rho;
          kept[3] = (m_j[2] - 0.5 * fz) / m_rho;
        }
      }
    }
    if constexpr (!streaming) continue;
    const bool last = start + m == run.length;
    #pragma GCC unroll 19
    for (int q = 0; q < L::Q; ++q) {
      Real* to = dst[q] + first - held[q];
      const int count = held[q] + m;
      const int kept = detail::streaming_store_keep_tail(to, f[q], count, last);
      for (int i = 0; i < kept; ++i) f[q][i] = f[q][count - kept + i];
      held[q] = kept;
    }
  }
}

// The size of the last-level cache the calling core sees, in bytes; 0 when unknown.
// Linux's sysfs describes the cache the core shares (lscpu reads it); sysconf may report
// the whole package instead: on a 2-core AMD EPYC KVM guest it gave 384 MiB where the
// core's L3 holds 32 MiB, and the paper's rank blocks (2 x 26 MB) got plain stores that
// spilled to memory (collide-stream 2.0 ms per fluid step, 1.2 ms streamed).
long last_level_cache_bytes() {
  long size = 0;
  for (int index = 0; index < 8; ++index) {
    const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index);
    std::ifstream level_file(dir + "/level"), type_file(dir + "/type"), size_file(dir + "/size");
    int level = 0;
    std::string type, text;
    if (!(level_file >> level) || !(type_file >> type) || !(size_file >> text)) break;
    if (type == "Instruction" || text.empty()) continue;
    const long unit = text.back() == 'K' ? 1024L : text.back() == 'M' ? 1024L * 1024 : 1;
    size = std::max(size, std::atol(text.c_str()) * unit);  // the largest level wins
  }
#ifdef _SC_LEVEL3_CACHE_SIZE
  if (size <= 0) size = sysconf(_SC_LEVEL3_CACHE_SIZE);
  if (size <= 0) size = sysconf(_SC_LEVEL2_CACHE_SIZE);
#endif
  return size;
}

// Whether a block's two population arrays are larger than their share of the last-level
// cache (streaming stores pay); where the cache size is unknown, they are.
bool output_exceeds_cache(std::size_t cells) {
  static const long cache = last_level_cache_bytes();  // asked once: files, or cpuid in a VM
  const double bytes = 2.0 * L::Q * double(cells) * sizeof(Real);
  return cache <= 0 || bytes > kPlainStoresUpToCacheShare * double(cache);
}

using RunKernel = void (*)(const Real* const*, Real* const*, const std::uint8_t*, const Run&,
                          const std::ptrdiff_t*, double, double, double, double, double, double,
                          double*, const PullCorrections&, PreparedCells&);

template <int kChunk, bool kMoments>
RunKernel run_kernel(bool incompressible, bool forced) {
  return incompressible ? (forced ? collide_stream_run<kChunk, true, true, kMoments>
                                  : collide_stream_run<kChunk, false, true, kMoments>)
                        : (forced ? collide_stream_run<kChunk, true, false, kMoments>
                                  : collide_stream_run<kChunk, false, false, kMoments>);
}

template <int kChunk>
RunKernel run_kernel(bool incompressible, bool forced, bool moments) {
  return moments ? run_kernel<kChunk, true>(incompressible, forced)
                 : run_kernel<kChunk, false>(incompressible, forced);
}

}  // namespace

void collide_stream(const CollideStreamArgs& a) {
  const BlockLayout& g = a.layout;
  std::ptrdiff_t off[L::Q];
  #pragma GCC unroll 19
  for (int q = 0; q < L::Q; ++q) off[q] = g.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
  const std::size_t n = g.num_cells();
  const bool forced = a.force[0] != 0.0 || a.force[1] != 0.0 || a.force[2] != 0.0;
  using Stores = CollideStreamArgs::Stores;
  const bool streaming = a.stores == Stores::kStreaming ||
                         (a.stores == Stores::kByCacheSize && !a.in_place && output_exceeds_cache(n));
  // The run kernel of the options, chosen once (no option is looked up per cell).
  const bool moments = a.moments != nullptr;
  const auto run = streaming ? run_kernel<kChunkStreaming>(a.incompressible, forced, moments)
                             : run_kernel<kChunkPlain>(a.incompressible, forced, moments);
  const int nx = g.size(0), ny = g.size(1), nz = g.size(2);
  if (nx <= 0 || ny <= 0 || nz <= 0) return;
  // Thread t of nt computes the t-th of nt contiguous shares of the spans or of the plane
  // runs, in ascending cells (each node on its own: the split changes no bit).
  const PullPreparation& preparation = a.pull_corrections.preparation;
  const bool prepare = preparation.prepare != nullptr && a.pull_corrections.count != 0;
  if (a.spans) {
    const std::size_t count = a.num_spans;
#pragma omp parallel
    {
      const auto [t, nt] = team_member();
      const std::size_t i0 = count * std::size_t(t) / std::size_t(nt);
      const std::size_t i1 = count * std::size_t(t + 1) / std::size_t(nt);
      PreparedCells prepared;
      if (prepare) {
        const auto start = [&](std::size_t i) { return i < count ? a.spans[i].first : kNoCell; };
        prepared = PreparedCells(preparation, t == 0 ? 0 : start(i0), start(i1));
#pragma omp barrier
      }
      for (std::size_t i = i0; i < i1; ++i) {
        const KernelSpan& span = a.spans[i];
        const Run r{span.first, span.length, g.padded(0), nx, g.coords(span.first)[0]};
        run(a.src.data(), a.dst.data(), a.node_type, r, off, a.omega_plus, a.omega_minus,
            a.force[0], a.force[1], a.force[2], a.rho0, a.moments, a.pull_corrections, prepared);
      }
      detail::streaming_store_fence();
    }
    return;
  }
  // Each plane is one run, or a few where there are fewer planes than threads; the runs
  // do not overlap, so no two threads write the same value.
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
#else
  const int threads = 1;
#endif
  const int parts = std::min(ny, (threads + nz - 1) / nz);
  const auto run_of = [&](int i) {  // run i of nz * parts, in ascending cells; empty: length 0
    const int k = i / parts, part = i % parts;
    const int j0 = part * ny / parts, j1 = (part + 1) * ny / parts;
    if (j0 == j1) return Run{g.cell(0, 0, k), 0, g.padded(0), nx, 0};
    return Run{g.cell(0, j0, k), (j1 - j0 - 1) * g.padded(0) + nx, g.padded(0), nx, 0};
  };
  const int count = nz * parts;
#pragma omp parallel
  {
    const auto [t, nt] = team_member();
    const int i0 = int(std::ptrdiff_t(count) * t / nt), i1 = int(std::ptrdiff_t(count) * (t + 1) / nt);
    PreparedCells prepared;
    if (prepare) {
      const auto start = [&](int i) { return i < count ? run_of(i).first : kNoCell; };
      prepared = PreparedCells(preparation, t == 0 ? 0 : start(i0), start(i1));
#pragma omp barrier
    }
    for (int i = i0; i < i1; ++i) {
      const Run r = run_of(i);
      if (r.length == 0) continue;
      run(a.src.data(), a.dst.data(), a.node_type, r, off, a.omega_plus, a.omega_minus,
          a.force[0], a.force[1], a.force[2], a.rho0, a.moments, a.pull_corrections, prepared);
    }
    // Before the region's closing barrier: every thread's runs are in memory after it.
    detail::streaming_store_fence();
  }
}

std::vector<KernelSpan> spans_without_solid(const BlockLayout& g, const std::uint8_t* node_type) {
  std::vector<KernelSpan> spans;
  const int nx = g.size(0), ny = g.size(1), nz = g.size(2);
  if (nx <= 0 || ny <= 0 || nz <= 0) return spans;
  const int pitch = g.padded(0);
  for (int k = 0; k < nz; ++k) {
    // A plane's owned rows and the x padding between them, one stretch of memory; a cell
    // to compute is an owned one that is not a static wall.
    const std::size_t plane = g.cell(0, 0, k);
    const int length = (ny - 1) * pitch + nx;
    const auto computed = [&](int p) { return p % pitch < nx && node_type[plane + p] != kSolid; };
    int p = 0;
    while (p < length) {
      while (p < length && !computed(p)) ++p;
      if (p == length) break;
      const int begin = p;
      int end = p;  // one past the last computed cell of the span
      while (p < length) {
        if (computed(p)) {
          end = ++p;
          continue;
        }
        int gap_end = p;
        while (gap_end < length && !computed(gap_end)) ++gap_end;
        if (gap_end == length || gap_end - p >= kMinSkippedCells) break;
        p = gap_end;  // a short gap is computed (zeros) rather than splitting the span
      }
      spans.push_back({plane + std::size_t(begin), end - begin});
      p = end;
    }
  }
  return spans;
}

}  // namespace lbm
