#include "lbm/collide_stream.h"

#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "lbm/streaming_store.h"

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

// Rows are processed in chunks of kChunk nodes: the populations are pulled straight from
// the source array, collided, and the results gathered in a small L1-resident SoA buffer
// (19 contiguous streams) that is written out with streaming stores (no write-allocate:
// 2 x 19 values moved per update, not 3 x 19). Splitting the arithmetic from the stores
// lets the compiler vectorise it across the chunk's nodes: it reads the node types as a
// double mask, since GCC does not vectorise a loop that mixes byte and double lanes.
// 128 nodes: a row of the 128^3 benchmark is one chunk, so each population's output range
// has two lines shared with neighbouring rows (its head and tail) instead of three or four;
// 64 was 10 % slower, 256 (a 39 KB buffer, most of L1) 7 % slower.
constexpr int kChunk = 128;
// Rows at least this long write their ends (the lines shared with the neighbouring rows)
// with non-temporal stores too (streaming_store.h): +35 % at 128^3 and +10 % at 64^3,
// where the ends are 2 of 17 or 9 lines, but -16 % for the paper's rank block (rows of 45:
// 2 of 6 lines), whose row ends the x halo exchange reads right after, from the cache
// when they were written with plain stores.
constexpr int kStreamEdgesFromRow = 64;
// The q loops carry "GCC unroll 19": GCC peels at most 16 iterations by default, and only a
// fully unrolled loop turns the velocity components into constants (a 2.5x speed-up).

// kIncompressible: He & Luo's equilibrium, the momentum rho0 u and rho only in the zeroth
// order (a compile-time choice, so the standard kernel's arithmetic is untouched).
template <bool kForce, bool kIncompressible>
void collide_stream_row(const Real* __restrict src, Real* __restrict dst,
                        const std::uint8_t* __restrict type, std::size_t n, std::size_t base,
                        int length, const std::ptrdiff_t* off, double omega_plus,
                        double omega_minus, double fx, double fy, double fz, double rho0) {
  const double source_even = 1.0 - 0.5 * omega_plus;
  const double source_odd = 1.0 - 0.5 * omega_minus;
  const bool stream_edges = length >= kStreamEdgesFromRow;
  alignas(64) double f[L::Q][kChunk];
  alignas(64) double fluid_mask[kChunk];
  for (int start = 0; start < length; start += kChunk) {
    const int m = length - start < kChunk ? length - start : kChunk;
    const std::size_t first = base + start;
    const Real* pull[L::Q];
    #pragma GCC unroll 19
    for (int q = 0; q < L::Q; ++q) pull[q] = src + q * n + first - off[q];
    for (int i = 0; i < m; ++i) fluid_mask[i] = type[first + i] == kFluid ? 1.0 : 0.0;
#pragma omp simd
    for (int i = 0; i < m; ++i) {
      const double fluid = fluid_mask[i];
      double fin[L::Q];
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
        double out = fin[0] - omega_plus * (fin[0] - feq);
        if (kForce) out += source_even * L::w[0] * (-3.0 * uf);
        f[0][i] = fluid * out;
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
        f[q][i] = fluid * (a - relax_plus - relax_minus + source_plus + source_minus);
        f[q + 1][i] = fluid * (b - relax_plus + relax_minus + source_plus - source_minus);
      }
    }
    #pragma GCC unroll 19
    for (int q = 0; q < L::Q; ++q) detail::streaming_store(dst + q * n + first, f[q], m, stream_edges);
  }
}

}  // namespace

void collide_stream(const CollideStreamArgs& a) {
  const BlockLayout& g = a.layout;
  std::ptrdiff_t off[L::Q];
  #pragma GCC unroll 19
  for (int q = 0; q < L::Q; ++q) off[q] = g.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
  const std::size_t n = g.num_cells();
  const bool forced = a.force[0] != 0.0 || a.force[1] != 0.0 || a.force[2] != 0.0;
  // The row kernel of the options, chosen once (no option is looked up per cell).
  const auto row = a.incompressible
                       ? (forced ? collide_stream_row<true, true> : collide_stream_row<false, true>)
                       : (forced ? collide_stream_row<true, false> : collide_stream_row<false, false>);
  const int nx = g.size(0), ny = g.size(1), nz = g.size(2);
#pragma omp parallel
  {
#pragma omp for collapse(2) schedule(static) nowait
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j) {
        const std::size_t base = g.cell(0, j, k);
        row(a.src, a.dst, a.node_type, n, base, nx, off, a.omega_plus, a.omega_minus,
            a.force[0], a.force[1], a.force[2], a.rho0);
      }
    // Before the region's closing barrier: every thread's rows are in memory after it.
    detail::streaming_store_fence();
  }
}

}  // namespace lbm
