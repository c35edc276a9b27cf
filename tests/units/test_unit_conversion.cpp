#include <gtest/gtest.h>

#include <cmath>

#include "coupling/unit_conversion.h"
#include "lbm/input_error.h"

using coupling::UnitConversion;
using coupling::UnitInputs;

TEST(UnitConversion, PaperLatticeUnitsGiveTauOne) {
  UnitInputs in;  // dx = rho = 1, nu = 1/6, dt_dem = 0.01, n_dem = 100: dt_lbm = 1
  const UnitConversion u(in);
  EXPECT_NEAR(u.tau(), 1.0, 1e-14);
  EXPECT_NEAR(u.dt_lbm(), 1.0, 1e-14);
  EXPECT_NEAR(u.force_unit(), 1.0, 1e-14);
}

TEST(UnitConversion, SiWaterRoundTrips) {
  UnitInputs in;
  in.dx = 1e-6;       // 1 micron
  in.rho = 1000.0;    // water
  in.nu = 1e-6;       // m^2/s
  in.n_dem = 100;
  in.dt_dem = 1e-9;   // dt_lbm = 1e-7 s -> nu_lat = 0.1, tau = 0.8
  const UnitConversion u(in);
  EXPECT_NEAR(u.tau(), 0.8, 1e-12);
  EXPECT_NEAR(u.velocity_to_physical(u.velocity_to_lattice(0.37)), 0.37, 1e-15);
  // A lattice force of 1 is rho dx^4 / dt^2 = 1000 * 1e-24 / 1e-14 = 1e-7 N.
  EXPECT_NEAR(u.force_to_physical(1.0) / 1e-7, 1.0, 1e-12);
  EXPECT_NEAR(u.pressure_to_lattice(u.pressure_to_physical(0.01)), 0.01, 1e-15);
}

TEST(UnitConversion, TauOutOfRangeNamesTheKeywordsAndRange) {
  UnitInputs in;
  in.nu = 1e-9;  // tau -> 0.5
  try {
    UnitConversion u(in);
    FAIL() << "tau ~ 0.5 accepted";
  } catch (const lbm::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("tau"), std::string::npos);
    EXPECT_NE(m.find("(0.5, 10]"), std::string::npos);
  }
  in = UnitInputs{};
  in.n_dem = 0;
  EXPECT_THROW(UnitConversion u(in), lbm::InputError);
  in = UnitInputs{};
  in.dx = -1;
  try {
    UnitConversion u(in);
    FAIL();
  } catch (const lbm::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("dx", 0), 0u);
  }
}

#include "coupling/lattice_frame.h"

TEST(LatticeFrame, SubdomainBoxesTileTheLattice) {
  coupling::LatticeFrame frame;
  frame.origin = {0.05, -1.0, 0.0};
  frame.dx = 0.1;
  frame.dims = {37, 5, 5};
  // Three uneven subdomains along x, cut at arbitrary positions (one exactly on a node).
  const double cuts[4] = {0.0, 1.05, 2.3333, 3.7};
  int next = 0;
  for (int p = 0; p < 3; ++p) {
    const double lo[3] = {cuts[p], -1.05, -0.05}, hi[3] = {cuts[p + 1], -0.5, 0.45};
    const bool at_lower[3] = {p == 0, true, true}, at_upper[3] = {p == 2, true, true};
    const lbm::Box box = frame.owned_box(lo, hi, at_lower, at_upper);
    EXPECT_EQ(box.lo[0], next) << "rank " << p;
    next = box.hi[0];
    // Every owned node lies inside the subdomain (up to the end ranks' extension).
    if (p > 0) {
      EXPECT_GE(frame.origin[0] + box.lo[0] * frame.dx, cuts[p] - 1e-9);
    }
    if (p < 2) {
      EXPECT_LT(frame.origin[0] + (box.hi[0] - 1) * frame.dx, cuts[p + 1]);
    }
  }
  EXPECT_EQ(next, 37);
}
