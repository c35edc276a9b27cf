#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/pull_correction.h"
#include "lbm/real.h"

namespace lbm {

// Consecutive cells the kernel computes: `length` cells from `first`, an owned cell; the
// x padding it crosses between rows is computed as a ghost (zeros).
struct KernelSpan {
  std::size_t first = 0;
  int length = 0;
};

// Everything the fused stream-collide kernel reads, resolved before the loop (no options
// are looked up per cell). src holds post-collision populations f*(t) with the boundary
// slots already filled, population q of cell c at src[q][c]; dst receives f*(t+1) the same
// way. They may be two placements of one field (PopulationField: the AA pattern), where
// every node's output slots are the slots its input was pulled from, each node's its own.
struct CollideStreamArgs {
  std::array<const Real*, D3Q19::Q> src{};
  std::array<Real*, D3Q19::Q> dst{};
  // dst's slots are src's (in place): plain stores, the lines have just been read.
  bool in_place = false;
  const std::uint8_t* node_type = nullptr;
  BlockLayout layout;
  double omega_plus = 1.0;
  double omega_minus = 1.0;
  std::array<double, 3> force{0.0, 0.0, 0.0};  // body force per unit volume
  // He & Luo's incompressible equilibrium with reference density rho0 (FluidParameters).
  bool incompressible = false;
  double rho0 = 1.0;
  // How the output reaches memory (the values are the same): non-temporal stores for
  // separate arrays larger than the cache, plain ones for arrays the cache holds between
  // steps and in place.
  enum class Stores { kByCacheSize, kStreaming, kPlain };
  Stores stores = Stores::kByCacheSize;
  // The cells to compute, disjoint: spans_without_solid's, which leave the static walls
  // out; where null, every owned cell.
  const KernelSpan* spans = nullptr;
  std::size_t num_spans = 0;
  // Where non-null, the moments of every computed node's output, written while the kernel
  // holds the values, the four of cell c at moments[4 c] (NodeMomentField): rho and u with
  // the half force removed, exactly (bit for bit) lbm::node_moments of the stored
  // populations, so that the moving walls of the next step read four values per node
  // instead of gathering 19 populations from 19 arrays. Non-fluid nodes get rho = 1 and
  // u = -F/2.
  double* moments = nullptr;
  // Densities taken off the populations some nodes pull before they collide, written into
  // those slots in the pass that reads them (lbm/pull_correction.h): the moving walls' link
  // mass correction, bit for bit as the moving walls' sweep writes it. Nodes outside the
  // computed cells must have none.
  PullCorrections pull_corrections;
};

// Pull stream + TRT collision (Guo forcing split into its even and odd parts) on every
// owned node (or every node of args.spans): f_q(x) = src_q(x - c_q), then relax. Fluid
// nodes get the collided values; every other computed node gets zeros (its slots are
// rewritten by the boundary stages before they are read). A pure function of arrays: the
// same loop ports to a GPU.
void collide_stream(const CollideStreamArgs& args);

// Gaps of at least this many cells split a span (shorter ones are computed as zeros: a new
// span costs a chunk that starts afresh).
constexpr int kMinSkippedCells = 16;
// The spans that cover every owned cell except the static walls (kSolid): in the paper's
// scene a quarter of the lattice, the solid around the pore. Nothing reads a static wall's
// slots but those the wall bounce-back writes before each step (FluidSolver), so the
// kernel neither reads nor writes the rest: the field's lines there stay out of the cache.
// Gaps shorter than kMinSkippedCells stay in a span.
std::vector<KernelSpan> spans_without_solid(const BlockLayout& layout, const std::uint8_t* node_type);

// The equilibrium of D3Q19 to second order in u, for one direction.
double equilibrium(int q, double rho, const std::array<double, 3>& u);
// He & Luo's incompressible equilibrium: momentum rho0 u, rho only in the zeroth order.
double incompressible_equilibrium(int q, double rho, double rho0, const std::array<double, 3>& u);

}  // namespace lbm
