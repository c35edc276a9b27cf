// The online erosive-burst detector on synthetic pressure signals (one sample per fluid step,
// default criteria: a fall of 10 % within 1000 fluid steps) and its restart state and file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>

#include "coupling/diagnostics/burst_detector.h"

using namespace coupling;

namespace {

// A signal: pressure loss and deposited count at each fluid step. The host step is
// 100 x the fluid step and the host time half the fluid step, so records show which is which.
struct Signal {
  std::function<double(long long)> pressure;
  std::function<long long(long long)> count = [](long long) { return 0LL; };
  PressureSample at(long long t) const {
    PressureSample s;
    s.fluid_step = t;
    s.step = 100 * t;
    s.time = 0.5 * t;
    s.pressure_loss = pressure(t);
    s.deposited_count = count(t);
    s.deposited_volume = 1000.0 * s.deposited_count;
    s.deposited_length = 2.0 * s.deposited_count;
    // The holds: the wall's force against the flow, deposits on the wall and P pi D^2 / 4.
    s.wall_force = -0.5 * s.deposited_count;
    s.deposited_on_wall = s.deposited_count / 2;
    s.pressure_force = 7.0 * s.pressure_loss;
    return s;
  }
};

std::vector<BurstRecord> detect(const Signal& signal, long long steps, BurstDetector& detector,
                                long long first = 0) {
  for (long long t = first; t < steps; ++t) detector.add(signal.at(t));
  return detector.bursts();
}

std::vector<BurstRecord> detect(const Signal& signal, long long steps) {
  BurstDetector detector;
  return detect(signal, steps, detector);
}

// A ramp from 0.01 that rises by 1e-5 per step up to `peak_step`, then falls linearly by
// `drop` (fraction) over `fall_steps`, then stays flat.
double ramp_and_drop(long long t, long long peak_step, double drop, long long fall_steps) {
  const double peak = 0.01 + 1e-5 * peak_step;
  if (t <= peak_step) return 0.01 + 1e-5 * t;
  const double progress = std::min(1.0, double(t - peak_step) / fall_steps);
  return peak * (1.0 - drop * progress);
}

}  // namespace

TEST(BurstDetector, RampThenSharpDropIsOneBurst) {
  Signal signal;
  signal.pressure = [](long long t) { return ramp_and_drop(t, 3000, 0.4, 200); };
  signal.count = [](long long t) { return t <= 3000 ? 10LL : 3LL; };
  BurstDetector detector;
  const auto bursts = detect(signal, 6000, detector);
  ASSERT_EQ(bursts.size(), 1u);
  const BurstRecord& b = bursts[0];
  const double peak = 0.01 + 1e-5 * 3000;
  EXPECT_EQ(b.step, 300000);  // host step of the peak
  EXPECT_DOUBLE_EQ(b.time, 1500.0);
  EXPECT_DOUBLE_EQ(b.peak_pressure, peak);
  EXPECT_NEAR(b.pressure_after, 0.6 * peak, 1e-15);
  EXPECT_NEAR(b.pressure_drop, 0.4 * peak, 1e-15);
  EXPECT_DOUBLE_EQ(b.duration, 0.5 * 200);  // peak to minimum, host time
  EXPECT_DOUBLE_EQ(b.deposited_volume, 10000.0);
  EXPECT_DOUBLE_EQ(b.deposited_length, 20.0);
  EXPECT_EQ(b.count_before, 10);
  EXPECT_EQ(b.count_after, 3);
  // The holds are the peak's (10 deposited): the wall's force, those on the wall, P pi D^2/4.
  EXPECT_DOUBLE_EQ(b.wall_force, -5.0);
  EXPECT_EQ(b.on_wall, 5);
  EXPECT_DOUBLE_EQ(b.pressure_force, 7.0 * peak);
  EXPECT_DOUBLE_EQ(detector.largest_pressure_loss(), peak);
  const auto row = b.row();
  ASSERT_EQ(row.size(), std::size_t(BurstRecord::kColumns));
  EXPECT_EQ(row[0], 300000.0);
  EXPECT_EQ(row[9], 3.0);
  EXPECT_EQ(row[10], -5.0);
  EXPECT_EQ(row[11], 5.0);
  EXPECT_DOUBLE_EQ(row[12], 7.0 * peak);
}

TEST(BurstDetector, RecordedAWindowAfterTheFallEnds) {
  Signal signal;
  signal.pressure = [](long long t) { return ramp_and_drop(t, 3000, 0.4, 200); };
  BurstDetector detector;
  // The fall ends at fluid step 3200; the burst closes a window (1000) later, give or take
  // the resolution (1 % of the peak: 5 steps of this fall).
  long long closed = -1;
  for (long long t = 0; t <= 5000 && closed < 0; ++t)
    if (detector.add(signal.at(t))) closed = t;
  EXPECT_GE(closed, 3200 - 5 + 1000);
  EXPECT_LE(closed, 3200 + 1001);
  // ... or at once when the pressure loss rises above the peak.
  signal.pressure = [](long long t) { return t < 3300 ? ramp_and_drop(t, 3000, 0.4, 200) : 1.0; };
  BurstDetector rising;
  for (long long t = 0; t < 3300; ++t) EXPECT_FALSE(rising.add(signal.at(t)).has_value());
  EXPECT_TRUE(rising.add(signal.at(3300)).has_value());
}

TEST(BurstDetector, OnePercentNoiseOnARampIsNoBurst) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  std::vector<double> values(20000);
  for (std::size_t t = 0; t < values.size(); ++t)  // a ramp, then a plateau
    values[t] = (0.01 + 1e-6 * std::min<double>(t, 10000)) * (1.0 + noise(random));
  Signal signal;
  signal.pressure = [&](long long t) { return values[t]; };
  EXPECT_TRUE(detect(signal, values.size()).empty());
}

TEST(BurstDetector, NoisyDropWithAWiggleIsOneBurst) {
  // A 40 % drop over 600 steps with 1 % noise and a 5 % bump half-way down.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  std::vector<double> values(8000);
  for (std::size_t t = 0; t < values.size(); ++t) {
    const long long s = t;
    const double bump = (s > 3300 && s < 3400) ? 1.05 : 1.0;
    values[t] = ramp_and_drop(s, 3000, 0.4, 600) * bump * (1.0 + noise(random));
  }
  Signal signal;
  signal.pressure = [&](long long t) { return values[t]; };
  const auto bursts = detect(signal, values.size());
  ASSERT_EQ(bursts.size(), 1u);
  const double peak = 0.01 + 1e-5 * 3000;
  EXPECT_NEAR(bursts[0].peak_pressure, peak, 0.011 * peak);
  EXPECT_NEAR(bursts[0].pressure_after, 0.6 * peak, 0.011 * peak);
  // The lowest noise dip on the floor (within a window of the fall's end) is the minimum.
  EXPECT_GE(bursts[0].duration, 0.5 * 550);
  EXPECT_LE(bursts[0].duration, 0.5 * (600 + 1000));
}

TEST(BurstDetector, TwoSeparatedBurstsAreTwo) {
  Signal signal;
  signal.pressure = [](long long t) {
    if (t < 5000) return ramp_and_drop(t, 3000, 0.4, 200);
    return ramp_and_drop(t - 5000, 4000, 0.3, 100) + 0.6 * 0.04 - 0.01;  // rises again from the low
  };
  const auto bursts = detect(signal, 12000);
  ASSERT_EQ(bursts.size(), 2u);
  EXPECT_EQ(bursts[0].step, 300000);
  EXPECT_EQ(bursts[1].step, 900000);
  EXPECT_NEAR(bursts[1].peak_pressure, 0.064, 1e-12);
  EXPECT_NEAR(bursts[1].pressure_drop, 0.3 * 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(bursts[1].duration, 0.5 * 100);
}

TEST(BurstDetector, SlowDeclineBelowTheThresholdRateIsNoBurst) {
  // A fall by half, but spread over 20 windows: 2.5 % per window < 10 %.
  Signal signal;
  signal.pressure = [](long long t) { return ramp_and_drop(t, 3000, 0.5, 20000); };
  EXPECT_TRUE(detect(signal, 30000).empty());
  // The same fall within one window is a burst.
  signal.pressure = [](long long t) { return ramp_and_drop(t, 3000, 0.5, 900); };
  EXPECT_EQ(detect(signal, 30000).size(), 1u);
}

TEST(BurstDetector, StateSaveAndRestoreGivesTheSameRecords) {
  Signal signal;
  signal.pressure = [](long long t) {
    if (t < 5000) return ramp_and_drop(t, 3000, 0.4, 200);
    return ramp_and_drop(t - 5000, 4000, 0.3, 100) + 0.014;
  };
  signal.count = [](long long t) { return (t / 700) % 5; };
  BurstDetector whole;
  const auto uninterrupted = detect(signal, 12000, whole);
  const double uninterrupted_largest = whole.largest_pressure_loss();
  ASSERT_EQ(uninterrupted.size(), 2u);
  EXPECT_NEAR(uninterrupted_largest, 0.064, 1e-12);
  // Splits before, during and after each fall, and while a burst is being followed.
  for (long long split : {1000LL, 3000LL, 3100LL, 3500LL, 4300LL, 9050LL, 9500LL, 11000LL}) {
    BurstDetector first;
    detect(signal, split, first);
    const std::vector<double> state = first.state();
    BurstDetector resumed;
    resumed.restore(state);
    EXPECT_EQ(resumed.state(), state);
    const auto bursts = detect(signal, 12000, resumed, split);
    ASSERT_EQ(bursts.size(), uninterrupted.size()) << "split " << split;
    for (std::size_t i = 0; i < bursts.size(); ++i)
      EXPECT_EQ(bursts[i].row(), uninterrupted[i].row()) << "split " << split << " burst " << i;
    EXPECT_EQ(resumed.largest_pressure_loss(), uninterrupted_largest);
  }
  BurstDetector other;
  EXPECT_THROW(other.restore({2.0, 1.0}), std::invalid_argument);
}

namespace {
// Today's state (version 3) as version 2 wrote it: without the deposit before the peak and
// the recent deposits it is taken from; records of 13 columns.
std::vector<double> as_version_2(const std::vector<double>& today) {
  constexpr std::size_t kSample = 10, kDeposit = 4, kOldColumns = 13;
  const auto candidates = static_cast<std::size_t>(today[3]), bursts = static_cast<std::size_t>(today[4]);
  std::vector<double> old{2.0, today[1], today[2], today[3], today[4]};
  const double* in = today.data() + 6;
  old.insert(old.end(), in, in + 3 * kSample);
  in += 3 * kSample + kDeposit;
  old.insert(old.end(), in, in + candidates * (kSample + 1));
  in += candidates * (kSample + 1);
  for (std::size_t i = 0; i < bursts; ++i, in += BurstRecord::kColumns) old.insert(old.end(), in, in + kOldColumns);
  return old;
}

// A signal whose deposit of 29 particles slides in the last 50 fluid steps before the peak
// at 3000 (counted 2 there), then a new rise from 5000.
Signal sliding_deposit() {
  Signal signal;
  signal.pressure = [](long long t) { return ramp_and_drop(t, 3000, 0.4, 200) + (t > 5000 ? 0.05 : 0.0); };
  signal.count = [](long long t) { return t < 2000 ? t / 100 : t < 2950 ? 29LL : t <= 3000 ? 2LL : 1LL; };
  return signal;
}
}  // namespace

// The deposit a burst tore off is the median over the window up to its peak, not the count
// at the peak, where a sliding deposit has dropped out of the count.
TEST(BurstDetector, TheDepositIsTakenOverTheWindowBeforeThePeak) {
  const auto sliding = detect(sliding_deposit(), 4500);
  ASSERT_EQ(sliding.size(), 1u);
  EXPECT_EQ(sliding[0].count_before, 2);
  EXPECT_EQ(sliding[0].deposit_count, 29);  // 950 of the window's 1001 samples hold 29
  EXPECT_DOUBLE_EQ(sliding[0].deposit_volume, 29000.0);
  EXPECT_DOUBLE_EQ(sliding[0].deposit_length, 58.0);
  EXPECT_DOUBLE_EQ(sliding[0].deposited_volume, 2000.0);  // at the peak, as before
  // A deposit growing through the window: the median is the count half a window before.
  Signal growing;
  growing.pressure = [](long long t) { return ramp_and_drop(t, 3000, 0.4, 200); };
  growing.count = [](long long t) { return t / 100; };
  const auto grown = detect(growing, 4500);
  ASSERT_EQ(grown.size(), 1u);
  EXPECT_EQ(grown[0].count_before, 30);
  EXPECT_EQ(grown[0].deposit_count, 25);
  EXPECT_DOUBLE_EQ(grown[0].deposit_length, 50.0);
  const auto row = grown[0].row();
  ASSERT_EQ(row.size(), std::size_t(BurstRecord::kColumns));
  EXPECT_EQ(row[13], 25.0);
  EXPECT_EQ(row[15], 50.0);
}

// A state written before the deposit before the peak was kept (version 2) restores with each
// record's and the followed burst's deposit taken at its own peak, and runs on.
TEST(BurstDetector, VersionTwoStateRestoresWithTheDepositAtThePeak) {
  const Signal signal = sliding_deposit();
  BurstDetector today;
  detect(signal, 3100, today);  // the fall found, being followed
  ASSERT_TRUE(today.bursts().empty());
  BurstDetector resumed;
  resumed.restore(as_version_2(today.state()));
  const auto bursts = detect(signal, 4500, resumed, 3100);
  ASSERT_EQ(bursts.size(), 1u);
  EXPECT_EQ(bursts[0].deposit_count, 2);  // the peak's own count: the window was not kept
  EXPECT_DOUBLE_EQ(bursts[0].deposit_volume, 2000.0);
  EXPECT_EQ(bursts[0].peak_pressure, detect(signal, 4500)[0].peak_pressure);
  // A recorded burst keeps its columns and takes its peak's deposit.
  BurstDetector later;
  detect(signal, 5100, later);
  BurstDetector upgraded;
  upgraded.restore(as_version_2(later.state()));
  ASSERT_EQ(upgraded.bursts().size(), 1u);
  EXPECT_EQ(upgraded.bursts()[0].deposit_count, upgraded.bursts()[0].count_before);
  EXPECT_EQ(upgraded.bursts()[0].wall_force, later.bursts()[0].wall_force);
  std::vector<double> short_state = as_version_2(later.state());
  short_state.pop_back();
  EXPECT_THROW(BurstDetector().restore(short_state), std::invalid_argument);
}

// A state written before the burst records carried the wall's hold (version 1: samples of
// 7 values, records of 10) restores as version 2 would, with the hold 0.
TEST(BurstDetector, VersionOneStateRestoresWithoutTheHold) {
  Signal signal;
  signal.pressure = [](long long t) { return ramp_and_drop(t, 3000, 0.4, 200) + (t > 5000 ? 0.05 : 0.0); };
  signal.count = [](long long t) { return t <= 3000 ? 10LL : 3LL; };
  BurstDetector today;
  detect(signal, 5100, today);  // one burst recorded, candidates of the new rise in the window
  ASSERT_EQ(today.bursts().size(), 1u);
  const std::vector<double> two = as_version_2(today.state());
  // The same state as version 1 wrote it, and version 2's with the hold zeroed.
  constexpr std::size_t kSample = 10, kOldSample = 7, kColumns = 13, kOldColumns = 10;
  const auto candidates = static_cast<std::size_t>(two[3]), bursts = static_cast<std::size_t>(two[4]);
  std::vector<double> old{1.0, two[1], two[2], two[3], two[4]}, expected(two.begin(), two.begin() + 5);
  const double* in = two.data() + 5;
  auto sample = [&](const double* s, bool flag) {
    old.insert(old.end(), s, s + kOldSample);
    expected.insert(expected.end(), s, s + kOldSample);
    expected.insert(expected.end(), kSample - kOldSample, 0.0);
    if (flag) {
      old.push_back(s[kSample]);
      expected.push_back(s[kSample]);
    }
  };
  for (int k = 0; k < 3; ++k, in += kSample) sample(in, false);
  for (std::size_t i = 0; i < candidates; ++i, in += kSample + 1) sample(in, true);
  for (std::size_t i = 0; i < bursts; ++i, in += kColumns) {
    old.insert(old.end(), in, in + kOldColumns);
    expected.insert(expected.end(), in, in + kOldColumns);
    expected.insert(expected.end(), kColumns - kOldColumns, 0.0);
  }
  ASSERT_GT(candidates, 0u);
  BurstDetector resumed, resumed_two;
  resumed.restore(old);
  resumed_two.restore(expected);
  EXPECT_EQ(resumed.state(), resumed_two.state());
  EXPECT_EQ(resumed.bursts()[0].wall_force, 0.0);
  EXPECT_EQ(resumed.bursts()[0].count_before, 10);
  EXPECT_EQ(resumed.bursts()[0].deposit_count, 10);
  old.pop_back();
  EXPECT_THROW(BurstDetector().restore(old), std::invalid_argument);
}

TEST(BurstDetector, FlushRecordsABurstStillBeingFollowed) {
  Signal signal;
  signal.pressure = [](long long t) { return ramp_and_drop(t, 3000, 0.4, 200); };
  BurstDetector detector;
  detect(signal, 3500, detector);
  EXPECT_TRUE(detector.bursts().empty());
  const auto b = detector.flush();
  ASSERT_TRUE(b.has_value());
  EXPECT_DOUBLE_EQ(b->duration, 100.0);
  EXPECT_FALSE(detector.flush().has_value());
}

TEST(BurstFileWriter, HeaderOnceThenOneRowPerBurst) {
  const std::string path = ::testing::TempDir() + "bursts_test.txt";
  std::remove(path.c_str());
  BurstUnits units{"fs", "Pa", "um^3", "um", "nN"};
  BurstRecord r;
  r.step = 42;
  r.time = 1.5;
  r.peak_pressure = 2.0;
  r.pressure_after = 1.0;
  r.pressure_drop = 1.0;
  r.duration = 0.25;
  r.deposited_volume = 300.0;
  r.deposited_length = 4.0;
  r.count_before = 7;
  r.count_after = 2;
  r.wall_force = -3.5;
  r.on_wall = 4;
  r.pressure_force = 6.25;
  r.deposit_count = 9;
  r.deposit_volume = 450.0;
  r.deposit_length = 6.0;
  { BurstFileWriter(path, units, false).write(r); }  // a stale file of an earlier run
  { BurstFileWriter(path, units, false).write(r); }  // a fresh run starts the file anew
  { BurstFileWriter(path, units, true).write(r); }   // a restarted run appends, no second header
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "# step time[fs] P_peak[Pa] P_after[Pa] delta_P[Pa] delta_t[fs] V_dep[um^3] "
            "L_dep[um] count_before count_after wall_F[nN] on_wall P_pi_D2_4[nN] deposit_count "
            "deposit_V[um^3] deposit_L[um]\n"
            "42 1.5 2 1 1 0.25 300 4 7 2 -3.5 4 6.25 9 450 6\n"
            "42 1.5 2 1 1 0.25 300 4 7 2 -3.5 4 6.25 9 450 6\n");
  EXPECT_THROW(BurstFileWriter("/nonexistent/dir/bursts.txt", units, false), std::runtime_error);
}

// The line a host prints when a burst is recorded, from the record's own numbers.
TEST(BurstRecord, AnnouncementGivesThePeakTheFallAndTheDeposits) {
  BurstRecord r;
  r.step = 123400;
  r.peak_pressure = 0.5;
  r.pressure_after = 0.375;
  r.pressure_drop = 0.125;
  r.duration = 7.5;
  r.count_before = 12;
  r.count_after = 9;
  r.deposit_count = 20;
  EXPECT_EQ(r.announcement(),
            "erosive burst: the pressure loss fell from 0.5 to 0.375 P_out (25 %) within 7.5 time units "
            "after step 123400; it tore off a deposit of 20 particles (12 counted at the peak, 9 after)\n");
}
