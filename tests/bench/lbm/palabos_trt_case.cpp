// The side-by-side case in Palabos 1.5 (Debian's libplb-dev), written against its public API:
// MultiBlockLattice3D with TRTdynamics, all axes periodic, initialised at equilibrium node by
// node, advanced by collideAndStream(). Palabos is MPI-parallel (no threads): this is its
// one-process figure. Only the generic-code headers this case needs are included (the whole
// palabos3D.hh does not compile with GCC 12: multiGrid/).
#include "palabos_trt_case.h"

#include <palabos3D.h>
// Generic (template) code of the parts used here; the library holds the rest.
#include <atomicBlock/headers3D.hh>
#include <basicDynamics/headers3D.hh>
#include <boundaryCondition/headers3D.hh>
#include <coProcessors/headers3D.hh>
#include <complexDynamics/headers3D.hh>
#include <core/headers3D.hh>
#include <dataProcessors/headers3D.hh>
#include <latticeBoltzmann/headers3D.hh>
#include <multiBlock/headers3D.hh>
#include <parallelism/headers3D.hh>

namespace {

template <typename T>
using D3Q19 = plb::descriptors::D3Q19Descriptor<T>;

// Palabos's initializeAtEquilibrium calls this for every node of the box.
struct EquilibriumOf {
  const NodeState* state;
  void operator()(plb::plint i, plb::plint j, plb::plint k, double& rho,
                  plb::Array<double, 3>& u) const {
    const std::array<double, 4> s = (*state)(int(i), int(j), int(k));
    rho = s[0];
    u = plb::Array<double, 3>(s[1], s[2], s[3]);
  }
};

class PalabosLattice final : public PalabosTrtCase {
 public:
  PalabosLattice(int n, double tau, const NodeState& state)
      : lattice_(n, n, n, new plb::TRTdynamics<double, D3Q19>(1.0 / tau)) {
    lattice_.periodicity().toggleAll(true);
    plb::initializeAtEquilibrium(lattice_, lattice_.getBoundingBox(), EquilibriumOf{&state});
    lattice_.initialize();
  }
  void step() override { lattice_.collideAndStream(); }
  std::array<double, 3> velocity(int i, int j, int k) const override {
    plb::Array<double, 3> u;
    // get() is not const in Palabos; reading a cell's moments does not change it.
    const_cast<plb::MultiBlockLattice3D<double, D3Q19>&>(lattice_).get(i, j, k).computeVelocity(u);
    return {u[0], u[1], u[2]};
  }

 private:
  plb::MultiBlockLattice3D<double, D3Q19> lattice_;
};

// Palabos starts MPI itself (the library is built with it) and ends it at exit.
void start_palabos_once() {
  static bool started = false;
  if (started) return;
  started = true;
  static int argc = 1;
  static char name[] = "bench_lbm";
  static char* args[] = {name, nullptr};
  static char** argv = args;
  plb::plbInit(&argc, &argv);
}

}  // namespace

bool palabos_available() { return true; }

// TRTdynamics::sMinus is private: its value, 1.1, is set in complexDynamics/trtDynamics.hh.
double palabos_trt_omega_minus() { return 1.1; }

std::unique_ptr<PalabosTrtCase> make_palabos_trt_case(int n, double tau, const NodeState& state) {
  start_palabos_once();
  return std::make_unique<PalabosLattice>(n, tau, state);
}
