// Prints the compressibility error of a pressure-driven plane channel against the
// incompressible Poiseuille solution for the density differences of the paper's regime
// (doc/stability.md, "Compressibility error of a pressure drive"). Not part of ctest:
// build the target lbm_compressibility_table and run it (about a minute on one core).
//   usage: lbm_compressibility_table [height length]
#include <cstdio>
#include <cstdlib>

#include "lbm/stability.h"
#include "pressure_channel.h"

int main(int argc, char** argv) {
  pressure_channel::Setup setup;
  if (argc == 3) {
    setup.height = std::atoi(argv[1]);
    setup.length = std::atoi(argv[2]);
  }
  for (bool incompressible : {false, true}) {
    setup.incompressible = incompressible;
    std::printf("channel H = %d, L = %d, tau = %.2f, %s equilibrium\n", setup.height, setup.length,
                setup.tau, incompressible ? "He-Luo incompressible" : "standard");
    std::printf("%6s %6s %7s %8s %10s %10s %10s %10s %10s %9s\n", "drho", "finite", "steps", "Mach",
                "flux", "u_inlet", "u_middle", "u_outlet", "|u|_max", "estimate");
    for (double drho : {0.01, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6}) {
      setup.density_difference = drho;
      const auto r = pressure_channel::run(setup);
      std::printf("%6.2f %6s %7ld %8.4f %+10.4f %+10.4f %+10.4f %+10.4f %10.4f %9.4f\n", drho,
                  r.finite ? "yes" : "NO", r.steps, r.mach, r.mass_flux_error,
                  r.inlet_velocity_error, r.middle_velocity_error, r.outlet_velocity_error,
                  r.largest_velocity_error, lbm::compressibility_error_estimate(drho));
    }
  }
  return 0;
}
