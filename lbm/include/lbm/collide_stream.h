#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "lbm/block_layout.h"
#include "lbm/real.h"

namespace lbm {

// Everything the fused stream-collide kernel reads, resolved before the loop (no options
// are looked up per cell). src holds post-collision populations f*(t) with the boundary
// slots already filled; dst receives f*(t+1). Both are SoA arrays of 19 * num_cells.
struct CollideStreamArgs {
  const Real* src = nullptr;
  Real* dst = nullptr;
  const std::uint8_t* node_type = nullptr;
  BlockLayout layout;
  double omega_plus = 1.0;
  double omega_minus = 1.0;
  std::array<double, 3> force{0.0, 0.0, 0.0};  // body force per unit volume
  // He & Luo's incompressible equilibrium with reference density rho0 (FluidParameters).
  bool incompressible = false;
  double rho0 = 1.0;
  // How the output reaches memory (the values are the same): non-temporal stores for
  // arrays larger than the cache, plain ones for arrays the cache holds between steps.
  enum class Stores { kByCacheSize, kStreaming, kPlain };
  Stores stores = Stores::kByCacheSize;
};

// Pull stream + TRT collision (Guo forcing split into its even and odd parts) on every
// owned node: f_q(x) = src_q(x - c_q), then relax. Fluid nodes get the collided values;
// every other node gets zeros (its slots are rewritten by the boundary stages before they
// are read). A pure function of arrays: the same loop ports to a GPU.
void collide_stream(const CollideStreamArgs& args);

// The equilibrium of D3Q19 to second order in u, for one direction.
double equilibrium(int q, double rho, const std::array<double, 3>& u);
// He & Luo's incompressible equilibrium: momentum rho0 u, rho only in the zeroth order.
double incompressible_equilibrium(int q, double rho, double rho0, const std::array<double, 3>& u);

}  // namespace lbm
