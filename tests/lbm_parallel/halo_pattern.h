#pragma once
// A known field for halo tests: population q at global node g holds
// ((q * 32 + gx) * 32 + gy) * 32 + gz, exact in float as long as every axis has < 32
// nodes. Ghosts start at a sentinel; after an exchange a ghost must hold the value of its
// periodic image, or still the sentinel beyond a non-periodic face.
#include <array>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/decomposition.h"
#include "lbm/halo_exchange.h"
#include "lbm/population_field.h"

namespace lbm_parallel_test {

constexpr double kSentinel = -7.0;

inline double pattern(int q, const std::array<int, 3>& g) {
  return ((q * 32.0 + g[0]) * 32.0 + g[1]) * 32.0 + g[2];
}

// The value a cell must hold after an exchange (owned cells keep theirs).
inline double expected(int q, const lbm::Decomposition& d, const lbm::BlockLayout& layout, int i,
                       int j, int k) {
  std::array<int, 3> g = layout.to_global(i, j, k);
  for (int a = 0; a < 3; ++a) {
    if (g[a] >= d.global.lo[a] && g[a] < d.global.hi[a]) continue;
    if (!d.periodic[a]) return kSentinel;
    const int n = d.global.size(a);
    g[a] = (g[a] - d.global.lo[a] + n) % n + d.global.lo[a];
  }
  return pattern(q, g);
}

inline void fill(lbm::PopulationField& f, const lbm::BlockLayout& layout) {
  for (int k = -1; k <= layout.size(2); ++k)
    for (int j = -1; j <= layout.size(1); ++j)
      for (int i = -1; i <= layout.size(0); ++i)
        for (int q = 0; q < lbm::D3Q19::Q; ++q)
          f.at(q, layout.cell(i, j, k)) = static_cast<lbm::Real>(
              layout.is_owned(i, j, k) ? pattern(q, layout.to_global(i, j, k)) : kSentinel);
}

// Number of cells x populations that differ from expected().
inline long long mismatches(const lbm::PopulationField& f, const lbm::Decomposition& d,
                            const lbm::BlockLayout& layout) {
  long long bad = 0;
  for (int k = -1; k <= layout.size(2); ++k)
    for (int j = -1; j <= layout.size(1); ++j)
      for (int i = -1; i <= layout.size(0); ++i)
        for (int q = 0; q < lbm::D3Q19::Q; ++q)
          if (double(f.at(q, layout.cell(i, j, k))) != expected(q, d, layout, i, j, k)) ++bad;
  return bad;
}

// Same for one scalar per cell, holding pattern(0, g) + 0.5.
inline std::vector<double> scalar_field(const lbm::BlockLayout& layout) {
  std::vector<double> v(layout.num_cells(), kSentinel);
  for (int k = 0; k < layout.size(2); ++k)
    for (int j = 0; j < layout.size(1); ++j)
      for (int i = 0; i < layout.size(0); ++i)
        v[layout.cell(i, j, k)] = pattern(0, layout.to_global(i, j, k)) + 0.5;
  return v;
}

inline long long scalar_mismatches(const std::vector<double>& v, const lbm::Decomposition& d,
                                   const lbm::BlockLayout& layout) {
  long long bad = 0;
  for (int k = -1; k <= layout.size(2); ++k)
    for (int j = -1; j <= layout.size(1); ++j)
      for (int i = -1; i <= layout.size(0); ++i) {
        const double e = expected(0, d, layout, i, j, k);
        if (v[layout.cell(i, j, k)] != (e == kSentinel ? e : e + 0.5)) ++bad;
      }
  return bad;
}

// An interleaved field of `width` values per cell (HaloExchange::exchange_interleaved, the
// node moments' field): value k of an owned cell holds pattern(k, g), ghosts the sentinel.
// After the exchange along every axis each value must be what exchange() gives population
// k; an exchange along no axis must change nothing. Counts the values that differ.
inline long long interleaved_mismatches(lbm::HaloExchange& halo, const lbm::Decomposition& d,
                                        const lbm::BlockLayout& layout, int width) {
  std::vector<double> v(layout.num_cells() * std::size_t(width), kSentinel);
  for (int k = 0; k < layout.size(2); ++k)
    for (int j = 0; j < layout.size(1); ++j)
      for (int i = 0; i < layout.size(0); ++i)
        for (int m = 0; m < width; ++m)
          v[layout.cell(i, j, k) * std::size_t(width) + std::size_t(m)] = pattern(m, layout.to_global(i, j, k));
  const std::vector<double> before = v;
  long long bad = 0;
  halo.exchange_interleaved(v.data(), width, {false, false, false});
  bad += v == before ? 0 : 1;
  halo.exchange_interleaved(v.data(), width, {true, true, true});
  for (int k = -1; k <= layout.size(2); ++k)
    for (int j = -1; j <= layout.size(1); ++j)
      for (int i = -1; i <= layout.size(0); ++i)
        for (int m = 0; m < width; ++m)
          if (v[layout.cell(i, j, k) * std::size_t(width) + std::size_t(m)] != expected(m, d, layout, i, j, k)) ++bad;
  return bad;
}

// The refill's exchange (FluidSolver::exchange_ghost_densities): the density of every cell
// in halo.sent_cells(), carried by exchange_scalar(), must equal at every ghost
// is_exchanged_ghost() names the density of the populations exchange() puts there, and
// exchange() must leave every other ghost alone. `f` as fill() left it (sentinel ghosts);
// the scalar field starts at a value no density takes. Counts the cells that differ.
inline long long density_mismatches(lbm::HaloExchange& halo, const lbm::PopulationField& f,
                                    const lbm::BlockLayout& layout) {
  auto density = [](const lbm::PopulationField& p, std::size_t cell) {
    double rho = 0.0;
    for (int q = 0; q < lbm::D3Q19::Q; ++q) rho += p.at(q, cell);
    return rho;
  };
  std::vector<double> rho(layout.num_cells(), 1e30);
  for (std::size_t cell : halo.sent_cells()) rho[cell] = density(f, cell);
  halo.exchange_scalar(rho);
  lbm::PopulationField g = f;
  halo.exchange(g);
  long long bad = 0;
  for (int k = -1; k <= layout.size(2); ++k)
    for (int j = -1; j <= layout.size(1); ++j)
      for (int i = -1; i <= layout.size(0); ++i) {
        const std::size_t cell = layout.cell(i, j, k);
        if (layout.is_owned(i, j, k)) {
          bad += halo.is_exchanged_ghost(cell);
          continue;
        }
        if (halo.is_exchanged_ghost(cell)) {
          bad += rho[cell] != density(g, cell);
          continue;
        }
        for (int q = 0; q < lbm::D3Q19::Q; ++q) bad += g.at(q, cell) != f.at(q, cell);
      }
  return bad;
}

// The crossing-populations exchange (HaloPopulations::crossing()) against the full one:
// every value an owned node pulls, f_q(x - c_q) for all q (the pull stream, the open faces,
// Bouzidi and the link mass correction read no other ghost slot), must be the same bit for
// bit. `f` as fill() left it. Counts the owned cells x populations that differ.
inline long long pull_mismatches(lbm::HaloExchange& halo, const lbm::PopulationField& f,
                                 const lbm::BlockLayout& layout) {
  lbm::PopulationField all = f, crossing = f;
  halo.exchange(all);
  halo.exchange(crossing, lbm::HaloPopulations::crossing());
  long long bad = 0;
  for (int k = 0; k < layout.size(2); ++k)
    for (int j = 0; j < layout.size(1); ++j)
      for (int i = 0; i < layout.size(0); ++i)
        for (int q = 0; q < lbm::D3Q19::Q; ++q) {
          const auto& c = lbm::D3Q19::c[q];
          const std::size_t from = layout.cell(i - c[0], j - c[1], k - c[2]);
          bad += all.at(q, from) != crossing.at(q, from);
        }
  return bad;
}

// And it sends only those: at a ghost of a face plane (not an edge) beyond the low face of
// axis a, every q with c_q[a] != +1 (beyond the high face: != -1) keeps its value. Counts
// the ghost populations the crossing exchange changed that it should have left.
inline long long non_crossing_written(lbm::HaloExchange& halo, const lbm::PopulationField& f,
                                      const lbm::BlockLayout& layout) {
  lbm::PopulationField g = f;
  halo.exchange(g, lbm::HaloPopulations::crossing());
  long long bad = 0;
  for (int k = -1; k <= layout.size(2); ++k)
    for (int j = -1; j <= layout.size(1); ++j)
      for (int i = -1; i <= layout.size(0); ++i) {
        const std::array<int, 3> c{i, j, k};
        int ghost_axis = -1, ghost_axes = 0;
        for (int a = 0; a < 3; ++a)
          if (c[a] < 0 || c[a] >= layout.size(a)) ghost_axis = a, ++ghost_axes;
        if (ghost_axes != 1) continue;
        const int inward = c[ghost_axis] < 0 ? +1 : -1;
        const std::size_t cell = layout.cell(i, j, k);
        for (int q = 0; q < lbm::D3Q19::Q; ++q)
          if (lbm::D3Q19::c[q][ghost_axis] != inward) bad += g.at(q, cell) != f.at(q, cell);
      }
  return bad;
}

}  // namespace lbm_parallel_test
