#include "coupling/diagnostics/burst_detector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace coupling {

std::vector<double> BurstRecord::row() const {
  return {double(step),         time,
          peak_pressure,        pressure_after,
          pressure_drop,        duration,
          deposited_volume,     deposited_length,
          double(count_before), double(count_after),
          wall_force,           double(on_wall),
          pressure_force,       double(deposit_count),
          deposit_volume,       deposit_length};
}

std::string BurstRecord::announcement() const {
  char text[400];
  std::snprintf(text, sizeof text,
                "erosive burst: the pressure loss fell from %.4g to %.4g P_out (%.0f %%) within %g "
                "time units after step %lld; it tore off a deposit of %lld particles (%lld counted "
                "at the peak, %lld after)\n",
                peak_pressure, pressure_after, 100.0 * pressure_drop / peak_pressure, duration, step,
                deposit_count, count_before, count_after);
  return text;
}

BurstDetector::BurstDetector(const BurstCriteria& criteria) : criteria_(criteria) {
  if (!(criteria.fraction > 0.0 && criteria.fraction < 1.0))
    throw std::invalid_argument("burst fraction must be in (0, 1)");
  if (criteria.window < 1) throw std::invalid_argument("burst window must be >= 1 fluid step");
}

BurstRecord BurstDetector::record() const {
  BurstRecord r;
  r.step = peak_.step;
  r.time = peak_.time;
  r.peak_pressure = peak_.pressure_loss;
  r.pressure_after = minimum_.pressure_loss;
  r.pressure_drop = peak_.pressure_loss - minimum_.pressure_loss;
  r.duration = minimum_.time - peak_.time;
  r.deposited_volume = peak_.deposited_volume;
  r.deposited_length = peak_.deposited_length;
  r.count_before = peak_.deposited_count;
  r.count_after = minimum_.deposited_count;
  r.wall_force = peak_.wall_force;
  r.on_wall = peak_.deposited_on_wall;
  r.pressure_force = peak_.pressure_force;
  r.deposit_count = static_cast<long long>(std::nearbyint(peak_deposit_.count));  // ties to even, as numpy
  r.deposit_volume = peak_deposit_.volume;
  r.deposit_length = peak_deposit_.length;
  return r;
}

namespace {
// The median of `values` (the mean of the middle two of an even number); 0 for none.
double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t half = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + half, values.end());
  const double upper = values[half];
  if (values.size() % 2) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + half));
}
}  // namespace

// The medians over the samples of [fluid_step - window, fluid_step], as the calibration's
// analysis takes them from thermo rows (figures/calibration.py, deposit_before).
BurstDetector::Deposit BurstDetector::deposit_up_to(long long fluid_step) const {
  std::vector<double> count, volume, length;
  for (const Deposit& d : recent_)
    if (d.fluid_step >= fluid_step - criteria_.window && d.fluid_step <= fluid_step) {
      count.push_back(d.count);
      volume.push_back(d.volume);
      length.push_back(d.length);
    }
  return {fluid_step, median(count), median(volume), median(length)};
}

std::optional<BurstRecord> BurstDetector::add(const PressureSample& sample) {
  const double p = sample.pressure_loss;
  largest_ = std::max(largest_, p);
  recent_.push_back({sample.fluid_step, double(sample.deposited_count), sample.deposited_volume,
                     sample.deposited_length});
  while (sample.fluid_step - recent_.front().fluid_step > 2 * criteria_.window) recent_.pop_front();

  std::optional<BurstRecord> done;
  if (falling_) {
    if (p > peak_.pressure_loss || sample.fluid_step - floor_.fluid_step > criteria_.window) {
      done = record();
      bursts_.push_back(*done);
      falling_ = false;
      // The next peak comes after the minimum.
      for (auto& c : candidates_)
        if (c.sample.fluid_step <= minimum_.fluid_step) c.is_peak = false;
    } else {
      if (p < minimum_.pressure_loss) minimum_ = sample;
      if (p < floor_.pressure_loss - 0.1 * criteria_.fraction * peak_.pressure_loss)
        floor_ = sample;
    }
  }

  // The candidates: samples of the last window not exceeded since, highest first. The
  // front is the highest sample of the window; a new sample is a peak if nothing of the
  // window before it is higher, i.e. if it removes every candidate.
  while (!candidates_.empty() &&
         sample.fluid_step - candidates_.front().sample.fluid_step > criteria_.window)
    candidates_.pop_front();
  while (!candidates_.empty() && candidates_.back().sample.pressure_loss <= p)
    candidates_.pop_back();
  candidates_.push_back({sample, candidates_.empty() && p > 0.0});

  // Only the front can be a peak: any later candidate arrived while the front, higher, was
  // within its window.
  const Candidate& front = candidates_.front();
  if (!falling_ && candidates_.size() > 1 && front.is_peak &&
      p < (1.0 - criteria_.fraction) * front.sample.pressure_loss) {
    falling_ = true;
    peak_ = front.sample;
    peak_deposit_ = deposit_up_to(peak_.fluid_step);
    minimum_ = floor_ = sample;
  }
  return done;
}

std::optional<BurstRecord> BurstDetector::flush() {
  if (!falling_) return std::nullopt;
  falling_ = false;
  bursts_.push_back(record());
  for (auto& c : candidates_)
    if (c.sample.fluid_step <= minimum_.fluid_step) c.is_peak = false;
  return bursts_.back();
}

namespace {

// 2: samples and records with the wall's hold; 3: the deposit before the peak and the
// recent deposits it is taken from.
constexpr double kStateVersion = 3.0;
constexpr int kSampleSize = 10, kDepositSize = 4, kHead = 6;

void put(std::vector<double>& out, const PressureSample& s) {
  out.insert(out.end(), {double(s.fluid_step), double(s.step), s.time, s.pressure_loss,
                         s.deposited_volume, s.deposited_length, double(s.deposited_count),
                         s.wall_force, double(s.deposited_on_wall), s.pressure_force});
}

PressureSample take(const double* in) {
  PressureSample s;
  s.fluid_step = static_cast<long long>(in[0]);
  s.step = static_cast<long long>(in[1]);
  s.time = in[2];
  s.pressure_loss = in[3];
  s.deposited_volume = in[4];
  s.deposited_length = in[5];
  s.deposited_count = static_cast<long long>(in[6]);
  s.wall_force = in[7];
  s.deposited_on_wall = static_cast<long long>(in[8]);
  s.pressure_force = in[9];
  return s;
}

BurstRecord take_record(const double* in) {
  BurstRecord r;
  r.step = static_cast<long long>(in[0]);
  r.time = in[1];
  r.peak_pressure = in[2];
  r.pressure_after = in[3];
  r.pressure_drop = in[4];
  r.duration = in[5];
  r.deposited_volume = in[6];
  r.deposited_length = in[7];
  r.count_before = static_cast<long long>(in[8]);
  r.count_after = static_cast<long long>(in[9]);
  r.wall_force = in[10];
  r.on_wall = static_cast<long long>(in[11]);
  r.pressure_force = in[12];
  r.deposit_count = static_cast<long long>(in[13]);
  r.deposit_volume = in[14];
  r.deposit_length = in[15];
  return r;
}

// A state of version 1 (samples of 7 values, records of 10: before the wall's hold was
// recorded) as version 2, the hold 0. Throws on a state that is not one.
std::vector<double> upgraded_from_version_1(const std::vector<double>& old) {
  constexpr std::size_t kOldSample = 7, kOldColumns = 10, kOldHead = 5 + 3 * kOldSample, kColumns = 13;
  if (old.size() < kOldHead) throw std::invalid_argument("burst detector state: version 1 but too short");
  const auto candidates = static_cast<std::size_t>(old[3]);
  const auto bursts = static_cast<std::size_t>(old[4]);
  if (old.size() != kOldHead + candidates * (kOldSample + 1) + bursts * kOldColumns)
    throw std::invalid_argument("burst detector state: wrong size");
  std::vector<double> out{2.0, old[1], old[2], old[3], old[4]};
  const double* in = old.data() + 5;
  const auto sample = [&](const double* s) {
    out.insert(out.end(), s, s + kOldSample);
    out.insert(out.end(), kSampleSize - kOldSample, 0.0);
  };
  for (int k = 0; k < 3; ++k, in += kOldSample) sample(in);
  for (std::size_t i = 0; i < candidates; ++i, in += kOldSample + 1) {
    sample(in);
    out.push_back(in[kOldSample]);
  }
  for (std::size_t i = 0; i < bursts; ++i, in += kOldColumns) {
    out.insert(out.end(), in, in + kOldColumns);
    out.insert(out.end(), kColumns - kOldColumns, 0.0);
  }
  return out;
}

// A state of version 2 (no recent deposits kept) as version 3. Its records and the burst
// being followed, if any, take the deposit counted at their own peak (the best there is);
// the deposits of the next window are then gathered from the samples to come.
std::vector<double> upgraded_from_version_2(const std::vector<double>& old) {
  constexpr std::size_t kOldColumns = 13, kOldHead = 5 + 3 * kSampleSize;
  if (old.size() < kOldHead) throw std::invalid_argument("burst detector state: version 2 but too short");
  const auto candidates = static_cast<std::size_t>(old[3]);
  const auto bursts = static_cast<std::size_t>(old[4]);
  if (old.size() != kOldHead + candidates * (kSampleSize + 1) + bursts * kOldColumns)
    throw std::invalid_argument("burst detector state: wrong size");
  std::vector<double> out{kStateVersion, old[1], old[2], old[3], old[4], 0.0};
  const double* in = old.data() + 5;
  out.insert(out.end(), in, in + 3 * kSampleSize);
  const PressureSample peak = take(in);
  out.insert(out.end(), {double(peak.fluid_step), double(peak.deposited_count), peak.deposited_volume,
                         peak.deposited_length});
  in += 3 * kSampleSize;
  out.insert(out.end(), in, in + candidates * (kSampleSize + 1));
  in += candidates * (kSampleSize + 1);
  for (std::size_t i = 0; i < bursts; ++i, in += kOldColumns) {
    out.insert(out.end(), in, in + kOldColumns);
    out.insert(out.end(), {in[8], in[6], in[7]});  // count_before, V_dep, L_dep at the peak
  }
  return out;
}

}  // namespace

// Layout: version, largest, falling, #candidates, #bursts, #recent deposits, peak, minimum,
// floor, the peak's deposit, candidates (sample + is_peak each), bursts (BurstRecord::row()
// each), recent deposits (fluid step, count, volume, length each). Integers are exact in a
// double up to 2^53.
std::vector<double> BurstDetector::state() const {
  std::vector<double> out{kStateVersion,          largest_,
                          falling_ ? 1.0 : 0.0,   double(candidates_.size()),
                          double(bursts_.size()), double(recent_.size())};
  put(out, peak_);
  put(out, minimum_);
  put(out, floor_);
  const auto put_deposit = [&](const Deposit& d) {
    out.insert(out.end(), {double(d.fluid_step), d.count, d.volume, d.length});
  };
  put_deposit(peak_deposit_);
  for (const auto& c : candidates_) {
    put(out, c.sample);
    out.push_back(c.is_peak ? 1.0 : 0.0);
  }
  for (const auto& b : bursts_) {
    const auto row = b.row();
    out.insert(out.end(), row.begin(), row.end());
  }
  for (const auto& d : recent_) put_deposit(d);
  return out;
}

void BurstDetector::restore(const std::vector<double>& state) {
  if (!state.empty() && state[0] == 1.0) return restore(upgraded_from_version_1(state));
  if (!state.empty() && state[0] == 2.0) return restore(upgraded_from_version_2(state));
  const std::size_t head = kHead + 3 * kSampleSize + kDepositSize;
  if (state.size() < head || state[0] != kStateVersion)
    throw std::invalid_argument("burst detector state: not written by this version");
  const auto candidates = static_cast<std::size_t>(state[3]);
  const auto bursts = static_cast<std::size_t>(state[4]);
  const auto recent = static_cast<std::size_t>(state[5]);
  if (state.size() !=
      head + candidates * (kSampleSize + 1) + bursts * BurstRecord::kColumns + recent * kDepositSize)
    throw std::invalid_argument("burst detector state: wrong size");
  const auto take_deposit = [](const double* in) {
    return Deposit{static_cast<long long>(in[0]), in[1], in[2], in[3]};
  };
  largest_ = state[1];
  falling_ = state[2] != 0.0;
  const double* in = state.data() + kHead;
  peak_ = take(in);
  minimum_ = take(in + kSampleSize);
  floor_ = take(in + 2 * kSampleSize);
  peak_deposit_ = take_deposit(in + 3 * kSampleSize);
  in += 3 * kSampleSize + kDepositSize;
  candidates_.clear();
  for (std::size_t i = 0; i < candidates; ++i, in += kSampleSize + 1)
    candidates_.push_back({take(in), in[kSampleSize] != 0.0});
  bursts_.clear();
  for (std::size_t i = 0; i < bursts; ++i, in += BurstRecord::kColumns) bursts_.push_back(take_record(in));
  recent_.clear();
  for (std::size_t i = 0; i < recent; ++i, in += kDepositSize) recent_.push_back(take_deposit(in));
}

std::string BurstFileWriter::header(const BurstUnits& u) {
  return "# step time[" + u.time + "] P_peak[" + u.pressure + "] P_after[" + u.pressure +
         "] delta_P[" + u.pressure + "] delta_t[" + u.time + "] V_dep[" + u.volume + "] L_dep[" +
         u.length + "] count_before count_after wall_F[" + u.force + "] on_wall P_pi_D2_4[" +
         u.force + "] deposit_count deposit_V[" + u.volume + "] deposit_L[" + u.length + "]\n";
}

BurstFileWriter::BurstFileWriter(const std::string& path, const BurstUnits& units, bool append) {
  file_ = std::fopen(path.c_str(), append ? "a" : "w");
  if (!file_) throw std::runtime_error("cannot open the burst file " + path + " for writing");
  std::fseek(file_, 0, SEEK_END);
  if (std::ftell(file_) == 0) {
    std::fputs(header(units).c_str(), file_);
    std::fflush(file_);
  }
}

BurstFileWriter::~BurstFileWriter() {
  if (file_) std::fclose(file_);
}

void BurstFileWriter::write(const BurstRecord& r) {
  std::fprintf(file_, "%lld %.10g %.10g %.10g %.10g %.10g %.10g %.10g %lld %lld %.10g %lld %.10g %lld %.10g %.10g\n",
               r.step, r.time, r.peak_pressure, r.pressure_after, r.pressure_drop, r.duration, r.deposited_volume,
               r.deposited_length, r.count_before, r.count_after, r.wall_force, r.on_wall, r.pressure_force,
               r.deposit_count, r.deposit_volume, r.deposit_length);
  std::fflush(file_);
}

}  // namespace coupling
