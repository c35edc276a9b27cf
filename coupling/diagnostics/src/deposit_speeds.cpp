#include "coupling/diagnostics/deposit_speeds.h"

#include <cmath>
#include <stdexcept>

namespace coupling {

int DepositSpeedHistogram::bin(double speed) {
  if (!(speed >= std::pow(10.0, kLog10Low))) return 0;  // slower, at rest, or NaN
  const int b = 1 + int(std::floor((std::log10(speed) - kLog10Low) * kBinsPerDecade));
  return b < kBins - 1 ? b : kBins - 1;
}

double DepositSpeedHistogram::lower_edge(int b) {
  if (b <= 0) return 0.0;
  return std::pow(10.0, kLog10Low + double(b - 1) / kBinsPerDecade);
}

void DepositSpeedHistogram::add(const ParticleView& view, const std::vector<char>& bonded,
                                const std::vector<char>& on_wall, const PoreRegion& region) {
  for (std::size_t p = 0; p < view.num_owned; ++p) {
    if (!in_pore_region(view.x(p), region)) continue;
    const bool is_bonded = p < bonded.size() && bonded[p];
    const bool touches_wall = p < on_wall.size() && on_wall[p];
    const Kind kind = !is_bonded ? kUnbonded : touches_wall ? kOnWall : kCohesiveOnly;
    const Vec3 v = view.v(p);
    counts_[kind][std::size_t(bin(std::sqrt(dot(v, v))))] += 1.0;
  }
}

void DepositSpeedHistogram::add(const DepositSpeedHistogram& other) {
  for (int kind = 0; kind < kKinds; ++kind)
    for (int b = 0; b < kBins; ++b) counts_[kind][std::size_t(b)] += other.counts_[kind][std::size_t(b)];
}

void DepositSpeedHistogram::clear() {
  for (auto& counts : counts_) std::fill(counts.begin(), counts.end(), 0.0);
}

std::vector<double> DepositSpeedHistogram::take(const lbm::Communicator& comm) {
  std::vector<double> all;
  all.reserve(std::size_t(kKinds * kBins));
  for (const auto& counts : counts_) all.insert(all.end(), counts.begin(), counts.end());
  clear();
  comm.sum(all.data(), int(all.size()));
  return all;
}

DepositSpeedFileWriter::DepositSpeedFileWriter(const std::string& path, double cells_per_unit_length,
                                               double time_per_fluid_step, bool append) {
  file_ = std::fopen(path.c_str(), append ? "a" : "w");
  if (!file_) throw std::runtime_error("cannot open the deposit speed file " + path + " for writing");
  std::fseek(file_, 0, SEEK_END);
  if (std::ftell(file_) != 0) return;
  using H = DepositSpeedHistogram;
  std::fprintf(file_,
               "# Speeds of the particles in the deposit region, counted once per particle and fluid step.\n"
               "# Speed in lattice cells per fluid step; %.10g cells per length unit and %.10g time units per "
               "fluid step of the script.\n"
               "# Bin 0: below 1e%d; bin b in 1..%d: [10^(%d + (b-1)/%d), 10^(%d + b/%d)); bin %d: 1e%d and above.\n"
               "# kind 0: bonded, touching the wall; 1: bonded to other particles only; 2: not bonded.\n"
               "# first_fluid_step last_fluid_step kind n_0 ... n_%d\n",
               cells_per_unit_length, time_per_fluid_step, H::kLog10Low, H::kBins - 2, H::kLog10Low, H::kBinsPerDecade, H::kLog10Low,
               H::kBinsPerDecade, H::kBins - 1, H::kLog10High, H::kBins - 1);
  std::fflush(file_);
}

DepositSpeedFileWriter::~DepositSpeedFileWriter() {
  if (file_) std::fclose(file_);
}

void DepositSpeedFileWriter::write(long long first, long long last, const std::vector<double>& counts) {
  using H = DepositSpeedHistogram;
  for (int kind = 0; kind < H::kKinds; ++kind) {
    std::fprintf(file_, "%lld %lld %d", first, last, kind);
    for (int b = 0; b < H::kBins; ++b) std::fprintf(file_, " %.0f", counts[std::size_t(kind * H::kBins + b)]);
    std::fputc('\n', file_);
  }
  std::fflush(file_);
}

}  // namespace coupling
