#include <gtest/gtest.h>

#include <cmath>
#include <string>

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

// The paper's width 5.63 d at 7.1 cells per d is 40 cells, 5.6338 d: within half a cell of
// the box, but as a periodic length LIGGGHTS's images of a particle would lie 0.027 cells
// from the lattice's, and two ranks sharing that face would disagree on which nodes a
// sphere there covers (a NaN in long runs). The periodic axes must match to round-off.
TEST(LatticeFrame, PeriodicBoxMustBeTheLatticePeriod) {
  coupling::LatticeFrame frame;
  frame.dx = 1.0 / 7.1;
  frame.dims = {90, 40, 40};
  for (int a = 0; a < 3; ++a) frame.origin[a] = 0.5 * frame.dx;
  const int periodic[3] = {0, 1, 1};
  const double lo[3] = {0.0, 0.0, 0.0};
  const double paper_width[3] = {12.69, 5.63, 5.63};
  EXPECT_NO_THROW(frame.check_fills_box(lo, paper_width));  // not periodic: half a cell
  try {
    frame.check_fills_box(lo, paper_width, periodic);
    ADD_FAILURE() << "a periodic width of 5.63 with 40 cells of 1/7.1 was accepted";
  } catch (const lbm::InputError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("periodic along y"), std::string::npos) << text;
    EXPECT_NE(text.find("5.63380281690141"), std::string::npos) << text;  // the length to set
  }
  // Lengths of whole cells as in.pore writes them (round(W * cells_per_d) / cells_per_d,
  // 15 digits): accepted, on every axis, periodic or not.
  const double whole[3] = {90 / 7.1, 5.63380281690141, 5.63380281690141};
  EXPECT_NO_THROW(frame.check_fills_box(lo, whole, periodic));
  const int all_periodic[3] = {1, 1, 1};
  EXPECT_NO_THROW(frame.check_fills_box(lo, whole, all_periodic));
}

// The units of the loads a fluid step hands the particles, and the factors a host converts
// whole particle arrays with: the same numbers as the arithmetic written out, to the bit.
TEST(UnitConversion, LoadUnitsAndArrayFactors) {
  UnitInputs in;
  in.dx = 0.140845;
  in.rho = 1.3;
  in.nu = 0.02;
  in.dt_dem = 0.01;
  in.n_dem = 100;
  const UnitConversion u(in);
  const double dt = u.dt_lbm();
  EXPECT_EQ(u.torque_unit(), u.force_unit() * in.dx);
  EXPECT_EQ(u.torque_unit(), u.torque_to_physical(1.0));
  EXPECT_EQ(u.velocity_coefficient_unit(), u.force_unit() * dt / in.dx);
  EXPECT_NEAR(u.velocity_coefficient_unit(), u.force_unit() / u.velocity_to_physical(1.0), 1e-12 * u.force_unit());
  EXPECT_EQ(u.velocity_to_lattice_factor(), dt / in.dx);
  EXPECT_NEAR(0.37 * u.velocity_to_lattice_factor(), u.velocity_to_lattice(0.37), 1e-15);
  EXPECT_EQ(u.angular_velocity_to_lattice_factor(), dt);
}

TEST(UnitConversion, TauIsFixedOnceTheLatticeExists) {
  UnitInputs in;
  const UnitConversion first(in);
  EXPECT_NO_THROW(first.check_same_tau(UnitConversion(in)));
  in.dt_dem = 0.02;
  in.n_dem = 50;  // the same fluid step: the same tau
  EXPECT_NO_THROW(first.check_same_tau(UnitConversion(in)));
  in.n_dem = 100;
  try {
    first.check_same_tau(UnitConversion(in));
    FAIL() << "a doubled fluid step was accepted";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(tau 1.000000 -> 1.500000)"), std::string::npos) << e.what();
  }
}
