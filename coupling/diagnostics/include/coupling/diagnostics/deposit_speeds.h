#pragma once
// The speed distribution of the particles in the deposit region (paper Sec. III: a deposited
// particle is in a cohesive or adhesive bond, "at zero or very low velocity, such that moving
// flocks of particles are not counted", inside the pore radius). The paper gives no speed
// bound; the distribution shows where resting deposits and moving flocks separate, which is
// where the bound belongs (doc/paper.md, "The deposit").
//
// Speeds in lattice units (cells per fluid step), counted once per particle and fluid step
// in log-spaced bins, apart for three kinds of particle in the region: bonded and touching
// the wall (adhesive), bonded to other particles only (cohesive), not bonded. Each rank
// counts its owned particles; take() sums over the ranks and starts the next interval.
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "coupling/diagnostics/pore_diagnostics.h"
#include "coupling/particle_view.h"
#include "lbm/communicator.h"

namespace coupling {

class DepositSpeedHistogram {
 public:
  // Bins of 1/kBinsPerDecade decade from 10^kLog10Low to 10^kLog10High, an underflow bin
  // before them (slower, at rest included) and an overflow bin after.
  static constexpr int kLog10Low = -8, kLog10High = 0, kBinsPerDecade = 10;
  static constexpr int kBins = (kLog10High - kLog10Low) * kBinsPerDecade + 2;
  enum Kind { kOnWall, kCohesiveOnly, kUnbonded, kKinds };

  static int bin(double speed);
  // Lower edge of bin b (0 for the underflow bin).
  static double lower_edge(int b);

  // This rank's owned particles in the region (indexed like the view; on_wall may be shorter
  // than the view, missing entries read as not on the wall).
  void add(const ParticleView& view, const std::vector<char>& bonded, const std::vector<char>& on_wall,
           const PoreRegion& region);
  // Another histogram's counts added to these; clear() starts from zero.
  void add(const DepositSpeedHistogram& other);
  void clear();
  // The counts since the last take() summed over the ranks (every rank gets them), kind by
  // kind, kBins each; this rank's counts start again from zero. Collective.
  std::vector<double> take(const lbm::Communicator& comm);

 private:
  std::array<std::vector<double>, kKinds> counts_{std::vector<double>(kBins, 0.0), std::vector<double>(kBins, 0.0),
                                                  std::vector<double>(kBins, 0.0)};
};

// One row per interval and kind: "first_fluid_step last_fluid_step kind n_0 ... n_{kBins-1}",
// under a header that gives the bins' edges, and the lattice cells per length unit and the
// time units per fluid step of the script to convert them to its units. A fresh
// run starts the file anew, a resumed run appends. Rank 0 only; throws std::runtime_error
// naming the file when it cannot be opened.
class DepositSpeedFileWriter {
 public:
  DepositSpeedFileWriter(const std::string& path, double cells_per_unit_length, double time_per_fluid_step,
                         bool append);
  ~DepositSpeedFileWriter();
  DepositSpeedFileWriter(const DepositSpeedFileWriter&) = delete;
  DepositSpeedFileWriter& operator=(const DepositSpeedFileWriter&) = delete;

  void write(long long first_fluid_step, long long last_fluid_step, const std::vector<double>& counts);

 private:
  std::FILE* file_ = nullptr;
};

}  // namespace coupling
