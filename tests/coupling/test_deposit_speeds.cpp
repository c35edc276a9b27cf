// The deposit's speed survey: the count under scaled thresholds and the speed distribution
// of the particles in the deposit region, by kind of bond.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "cases/serial_flow.h"
#include "coupling/diagnostics/deposit_speeds.h"
#include "coupling/diagnostics/pore_diagnostics.h"
#include "coupling/sphere_coupling.h"

using namespace coupling;

namespace {
PoreRegion test_pore() {
  PoreRegion pore;
  pore.axis = 0;
  pore.start = 5;
  pore.end = 20;
  pore.centre = {5, 5};
  pore.diameter = 8;
  return pore;
}
}  // namespace

// Speeds 1e-5, 3e-5, 1e-4 (bonded, in the pore) against a threshold of 2e-5: the scaled
// thresholds 5e-6, 1e-5, 4e-5, 8e-5, 1.6e-4, 3.2e-4 count 0, 0, 2, 2, 3, 3 (strictly
// slower); a particle outside the region or unbonded counts under none.
TEST(DepositSpeeds, CountUnderEachScaledThreshold) {
  ParticleSet p;
  p.add(1, {10, 5, 5}, {1e-5, 0, 0}, 2.0);
  p.add(2, {12, 5, 5}, {0, 3e-5, 0}, 2.0);
  p.add(3, {14, 5, 5}, {0, 0, 1e-4}, 2.0);
  p.add(4, {30, 5, 5}, {0, 0, 0}, 2.0);  // beyond the pore's end
  p.add(5, {11, 5, 5}, {0, 0, 0}, 2.0);  // not bonded
  const std::vector<char> bonded{1, 1, 1, 1, 0};
  DepositionCriteria criteria;
  criteria.speed_threshold = 2e-5;
  const Deposition d = deposited(p.view(), bonded, test_pore(), criteria, lbm::Communicator{});
  EXPECT_EQ(d.count, 1);
  const std::array<long long, 6> expected{0, 0, 2, 2, 3, 3};
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(d.count_at_scaled_threshold[i], expected[i]) << "factor " << kDepositSpeedLadder[i];
}

TEST(DepositSpeeds, BinsAreTenthsOfADecade) {
  using H = DepositSpeedHistogram;
  EXPECT_EQ(H::bin(0.0), 0);
  EXPECT_EQ(H::bin(9.9e-9), 0);
  EXPECT_EQ(H::bin(1.0001e-8), 1);
  EXPECT_EQ(H::bin(1.3e-4), 1 + 4 * 10 + 1);  // 10^-4.0 <= 1.3e-4 < 10^-3.9
  EXPECT_EQ(H::bin(0.99), H::kBins - 2);
  EXPECT_EQ(H::bin(5.0), H::kBins - 1);
  EXPECT_EQ(H::bin(std::nan("")), 0);
  EXPECT_DOUBLE_EQ(H::lower_edge(0), 0.0);
  EXPECT_NEAR(H::lower_edge(41), 1e-4, 1e-16);
  for (int b = 1; b < H::kBins; ++b) EXPECT_EQ(H::bin(H::lower_edge(b) * 1.000001), b);
}

// Each particle in the region adds one count per call to its kind's bin; take() returns the
// sums and starts again.
TEST(DepositSpeeds, HistogramCountsByKindAndStartsAgainAfterTake) {
  using H = DepositSpeedHistogram;
  ParticleSet p;
  p.add(1, {10, 5, 5}, {1e-6, 0, 0}, 2.0);  // bonded, on the wall
  p.add(2, {12, 5, 5}, {1e-3, 0, 0}, 2.0);  // bonded to another particle only
  p.add(3, {14, 5, 5}, {0.02, 0, 0}, 2.0);  // not bonded
  p.add(4, {30, 5, 5}, {1e-6, 0, 0}, 2.0);  // outside: not counted
  const std::vector<char> bonded{1, 1, 0, 1}, on_wall{1};
  H histogram;
  histogram.add(p.view(), bonded, on_wall, test_pore());
  histogram.add(p.view(), bonded, on_wall, test_pore());
  const std::vector<double> counts = histogram.take(lbm::Communicator{});
  ASSERT_EQ(counts.size(), std::size_t(H::kKinds * H::kBins));
  double total = 0.0;
  for (double c : counts) total += c;
  EXPECT_EQ(total, 6.0);
  EXPECT_EQ(counts[std::size_t(H::kOnWall * H::kBins + H::bin(1e-6))], 2.0);
  EXPECT_EQ(counts[std::size_t(H::kCohesiveOnly * H::kBins + H::bin(1e-3))], 2.0);
  EXPECT_EQ(counts[std::size_t(H::kUnbonded * H::kBins + H::bin(0.02))], 2.0);
  const std::vector<double> again = histogram.take(lbm::Communicator{});
  for (double c : again) EXPECT_EQ(c, 0.0);
}

TEST(DepositSpeeds, FileHasAHeaderAndOneRowPerKind) {
  using H = DepositSpeedHistogram;
  const std::string path = ::testing::TempDir() + "deposit_speeds_test.txt";
  std::vector<double> counts(std::size_t(H::kKinds * H::kBins), 0.0);
  counts[5] = 3.0;
  counts[std::size_t(2 * H::kBins + 7)] = 4.0;
  {
    DepositSpeedFileWriter writer(path, 7.1, 1.0, /*append=*/false);
    writer.write(1, 2000, counts);
  }
  {
    DepositSpeedFileWriter writer(path, 7.1, 1.0, /*append=*/true);  // a resumed run: no second header
    writer.write(2001, 4000, counts);
  }
  std::ifstream in(path);
  std::string line;
  int header = 0, rows = 0;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) { ++header; continue; }
    std::istringstream words(line);
    long long first = 0, last = 0;
    int kind = -1;
    words >> first >> last >> kind;
    std::vector<double> n(std::size_t(H::kBins));
    for (double& x : n) words >> x;
    ASSERT_TRUE(bool(words)) << line;
    EXPECT_EQ(kind, rows % 3);
    EXPECT_EQ(first, rows < 3 ? 1 : 2001);
    EXPECT_EQ(n[kind == 0 ? 5 : 7], kind == 1 ? 0.0 : kind == 0 ? 3.0 : 4.0);
    ++rows;
  }
  EXPECT_EQ(header, 5);
  EXPECT_EQ(rows, 6);
  std::remove(path.c_str());
  EXPECT_THROW(DepositSpeedFileWriter("/nonexistent-dir/x.txt", 7.1, 1.0, false), std::runtime_error);
}
