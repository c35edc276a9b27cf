#pragma once
#include <array>
#include <functional>
#include <memory>
// The case bench_lbm times, run in Palabos for the side-by-side figure BENCH lbm_vs_palabos:
// a fully periodic n^3 D3Q19 box in double precision with Palabos's own TRT dynamics. Our own
// driver written against Palabos's public API (Palabos is GPL: nothing of it is copied here).
// palabos_trt_case.cpp holds it when CMake finds Debian's libplb-dev; without it,
// palabos_trt_case_absent.cpp makes make_palabos_trt_case() return nullptr.

// State of a node at equilibrium: (i, j, k) -> {rho, ux, uy, uz}, like
// lbm::FluidSolver::initialise_equilibrium.
using NodeState = std::function<std::array<double, 4>(int, int, int)>;

class PalabosTrtCase {
 public:
  virtual ~PalabosTrtCase() = default;
  virtual void step() = 0;  // one collide-and-stream of the whole box
  virtual std::array<double, 3> velocity(int i, int j, int k) const = 0;
};

// Whether this bench_lbm was built with Palabos.
bool palabos_available();

// Palabos 1.5's TRT relaxes the odd moments at a fixed rate (TRTdynamics::sMinus = 1.1); the
// magic parameter of our side of the comparison is the one that gives the same rate.
double palabos_trt_omega_minus();

// Periodic n^3 box, omega+ = 1/tau, every node at the equilibrium of state. nullptr when the
// benchmark was built without Palabos.
std::unique_ptr<PalabosTrtCase> make_palabos_trt_case(int n, double tau, const NodeState& state);
