// D3Q19 constants and isotropy, and the moments of the equilibrium.
#include <gtest/gtest.h>

#include "lbm/collide_stream.h"
#include "lbm/d3q19.h"
#include "lbm/trt.h"

using lbm::D3Q19;

TEST(Lattice, WeightsSumToOneAndVelocitiesAreAntisymmetric) {
  double sum = 0.0;
  for (int q = 0; q < D3Q19::Q; ++q) {
    sum += D3Q19::w[q];
    const int o = D3Q19::opposite(q);
    EXPECT_EQ(D3Q19::opposite(o), q);
    EXPECT_DOUBLE_EQ(D3Q19::w[q], D3Q19::w[o]);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(D3Q19::c[q][a], -D3Q19::c[o][a]);
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);
}

TEST(Lattice, SecondAndFourthOrderIsotropy) {
  const double cs2 = D3Q19::cs2;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double first = 0.0, second = 0.0, third = 0.0;
      for (int q = 0; q < D3Q19::Q; ++q) {
        first += D3Q19::w[q] * D3Q19::c[q][a];
        second += D3Q19::w[q] * D3Q19::c[q][a] * D3Q19::c[q][b];
        third += D3Q19::w[q] * D3Q19::c[q][a] * D3Q19::c[q][b] * D3Q19::c[q][b];
      }
      EXPECT_NEAR(first, 0.0, 1e-15);
      EXPECT_NEAR(second, a == b ? cs2 : 0.0, 1e-15);
      EXPECT_NEAR(third, 0.0, 1e-15);  // odd moments vanish
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d) {
          double fourth = 0.0;
          for (int q = 0; q < D3Q19::Q; ++q)
            fourth += D3Q19::w[q] * D3Q19::c[q][a] * D3Q19::c[q][b] * D3Q19::c[q][c] *
                      D3Q19::c[q][d];
          const double expected =
              cs2 * cs2 * ((a == b && c == d) + (a == c && b == d) + (a == d && b == c));
          EXPECT_NEAR(fourth, expected, 1e-15) << a << b << c << d;
        }
    }
}

TEST(Equilibrium, MomentsAreDensityMomentumAndStress) {
  const double rho = 1.07;
  const std::array<double, 3> u{0.03, -0.02, 0.05};
  double m0 = 0.0, m1[3] = {0, 0, 0}, m2[3][3] = {};
  for (int q = 0; q < D3Q19::Q; ++q) {
    const double feq = lbm::equilibrium(q, rho, u);
    m0 += feq;
    for (int a = 0; a < 3; ++a) {
      m1[a] += feq * D3Q19::c[q][a];
      for (int b = 0; b < 3; ++b) m2[a][b] += feq * D3Q19::c[q][a] * D3Q19::c[q][b];
    }
  }
  EXPECT_NEAR(m0, rho, 1e-15);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(m1[a], rho * u[a], 1e-15);
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(m2[a][b], rho * (a == b) * D3Q19::cs2 + rho * u[a] * u[b], 1e-15);
  }
}

TEST(Trt, MagicParameterDefinesOmegaMinus) {
  const auto p = lbm::TrtParameters::from_tau(0.8, 3.0 / 16.0);
  EXPECT_NEAR((1.0 / p.omega_plus - 0.5) * (1.0 / p.omega_minus - 0.5), 3.0 / 16.0, 1e-14);
  EXPECT_NEAR(lbm::TrtParameters::viscosity(1.0), 1.0 / 6.0, 1e-15);
}

TEST(Trt, BadTauAndMagicNameTheKeywordAndRange) {
  try {
    lbm::TrtParameters::from_tau(0.5, 0.25);
    FAIL() << "tau = 0.5 accepted";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tau"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("> 0.5"), std::string::npos);
  }
  EXPECT_THROW(lbm::TrtParameters::from_tau(1.0, -1.0), lbm::InputError);
}
