#pragma once
// Floating-point type of the lattice populations. Double by default; the CMake option
// LBM_PORE_SINGLE_PRECISION switches the populations (not the diagnostics) to float.
namespace lbm {
#ifdef LBM_PORE_SINGLE_PRECISION
using Real = float;
#else
using Real = double;
#endif
}  // namespace lbm
