#pragma once
// Erosive bursts (paper Sec. III, Figs. 2-3 and "singlejump"): sudden falls of the pressure
// loss when the hydraulic load tears a deposit off. Detected online, one sample per fluid
// step, with memory bounded by the window (no history of the run is kept).
//
// Definition (examples/pore/plot_pressure.py replays the same rules on thermo rows):
//   - a peak is a sample with P > 0 that no sample of the `window` fluid steps before it
//     exceeds;
//   - a burst starts at the first sample that lies below (1 - fraction) P_peak, at most
//     `window` fluid steps after a peak and with no higher sample in between (the peak
//     taken is the highest sample of the last window that nothing since has exceeded);
//   - the burst is then followed to its minimum ("P after", the lowest sample since the
//     fall began) and recorded at the first sample that rises above the peak or that comes
//     more than `window` fluid steps after the fall last went on: a sample lower by more
//     than a resolution of fraction/10 of P_peak than the level where it last went on (so
//     noise on the floor of a fall does not prolong it, and a fall in stages is one burst
//     as long as each stage follows within a window);
//   - while a burst is followed no other starts, and the next peak must come after its
//     minimum;
//   - the deposit a burst tears off is the median of the deposited count, V_dep and L_dep
//     over the `window` fluid steps up to its peak: at the peak itself the deposit has often
//     begun to slide, and its particles, faster than the count's speed bound, drop out of
//     the count (a deposit of 29 particles read 2 at its peak in the paper's scene).
// Why noise does not split one burst into many: a wiggle during the fall is part of the
// burst being followed; a wiggle after the minimum is no peak while the old peak, higher,
// lies within its window, and even as a peak it starts a burst only if it is followed by a
// fall of more than `fraction` of it.
//
// Defaults, from the main example (examples/pore, thermo every 100 fluid steps): fraction
// 0.1 and window 1000 fluid steps. Before particles deposit its pressure loss never falls by
// more than 0.9 % within 1000 fluid steps (particles passing the pore), while its erosive
// burst falls by 10 % within 600 fluid steps of the peak and by 60 % in all (paper Fig.
// singlejump: falls of the order of the pressure loss itself). 1000 fluid steps is also the
// time released particles need to leave the pore (30 cells at a few 1e-2 cells per step);
// a decline slower than 10 % per 1000 fluid steps (slow erosion, a drive ramped down) is no
// burst. plot_pressure.py's default of 10 thermo rows is the same 1000 fluid steps there.
#include <cstdio>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace coupling {

struct BurstCriteria {
  double fraction = 0.1;    // relative fall from the peak that makes a burst
  long long window = 1000;  // fluid steps within which the fall must happen
};

// One sample of the run, taken after a fluid step. `fluid_step` is the detector's clock
// (the window is in fluid steps); `step` and `time` are the host's, copied into the records.
// Pressure, volume and length in whatever units the host uses (the fraction is relative).
struct PressureSample {
  long long fluid_step = 0;
  long long step = 0;
  double time = 0.0;
  double pressure_loss = 0.0;
  double deposited_volume = 0.0;  // V_dep
  double deposited_length = 0.0;  // L_dep
  long long deposited_count = 0;
  // The hold the paper's force balance asks about (its theory section: P pi D^2 / 4 carried
  // by the deposit's grip on the pore wall): the wall's total force on the particles along
  // the flow, the deposited particles that touch the wall, and P pi D^2 / 4 (force units).
  double wall_force = 0.0;
  long long deposited_on_wall = 0;
  double pressure_force = 0.0;
};

// One erosive burst: the peak and the minimum after it.
struct BurstRecord {
  long long step = 0;             // host step of the peak
  double time = 0.0;              // host time of the peak
  double peak_pressure = 0.0;     // P_peak
  double pressure_after = 0.0;    // P after: the minimum reached
  double pressure_drop = 0.0;     // Delta P = P_peak - P after
  double duration = 0.0;          // Delta t: peak to minimum (host time)
  double deposited_volume = 0.0;  // V_dep at the peak
  double deposited_length = 0.0;  // L_dep at the peak
  long long count_before = 0;     // deposited particles at the peak
  long long count_after = 0;      // ... at the minimum
  double wall_force = 0.0;        // the wall's force on the particles along the flow, at the peak
  long long on_wall = 0;          // deposited particles touching the wall, at the peak
  double pressure_force = 0.0;    // P_peak pi D^2 / 4 in force units: what the holds must carry
  // The deposit the burst tore off: medians over the window up to the peak (see above).
  long long deposit_count = 0;
  double deposit_volume = 0.0;
  double deposit_length = 0.0;

  static constexpr int kColumns = 16;
  // The record as kColumns numbers, in the order above (a row of the fix's array).
  std::vector<double> row() const;
  // One line, ending in a newline, for a host to announce the burst as it is recorded:
  // "erosive burst: the pressure loss fell from <peak> to <after> P_out (<drop> %) within
  // <duration> time units after step <step>; it tore off a deposit of <deposit> particles
  // (<before> counted at the peak, <after> after)".
  std::string announcement() const;
};

class BurstDetector {
 public:
  explicit BurstDetector(const BurstCriteria& criteria = {});

  // Feeds one sample (fluid steps increasing). Returns the burst that this sample completes,
  // if any; it is also appended to bursts().
  std::optional<BurstRecord> add(const PressureSample& sample);
  // At the very end of a simulation: records a burst whose fall was found but whose window
  // has not ended yet (with the minimum so far). Not for the end of every run of a script.
  std::optional<BurstRecord> flush();

  const std::vector<BurstRecord>& bursts() const { return bursts_; }
  // Largest pressure loss of all samples so far (0 before the first, or if none is positive).
  double largest_pressure_loss() const { return largest_; }
  const BurstCriteria& criteria() const { return criteria_; }

  // The whole state (recent samples and deposits, the burst being followed, the records, the
  // largest pressure loss) as a flat vector for a restart file, and back; restore() throws
  // std::invalid_argument on a vector that state() did not write.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

 private:
  // A sample that may still become the peak of a burst: the samples of the last window
  // that no later sample exceeds, in order (decreasing pressure loss).
  struct Candidate {
    PressureSample sample;
    bool is_peak = false;  // no sample of the window before it exceeded it
  };
  // The deposit of one sample, kept for the two windows before the newest sample: a fall
  // starts at most a window after its peak, and the deposit is taken over the window before.
  struct Deposit {
    long long fluid_step = 0;
    double count = 0.0, volume = 0.0, length = 0.0;
  };
  BurstRecord record() const;
  Deposit deposit_up_to(long long fluid_step) const;

  BurstCriteria criteria_;
  std::deque<Candidate> candidates_;
  bool falling_ = false;  // a burst's fall was found; following it to its minimum
  PressureSample peak_, minimum_;
  PressureSample floor_;  // where the fall last went on by more than the resolution
  Deposit peak_deposit_;  // the deposit over the window up to peak_
  std::deque<Deposit> recent_;
  std::vector<BurstRecord> bursts_;
  double largest_ = 0.0;
};

// Writes burst records to a text file, one row per burst, under a header line that names
// the columns and their units (the host's unit names). A fresh run starts the file anew; a
// run resumed from a restart file appends (`append`), and the header is written only when
// the file is new or empty, so the restarted run continues the same file. Rank 0 only.
struct BurstUnits {
  std::string time = "time", pressure = "pressure", volume = "volume", length = "length",
              force = "force";
};

class BurstFileWriter {
 public:
  // Throws std::runtime_error naming the file when it cannot be opened.
  BurstFileWriter(const std::string& path, const BurstUnits& units, bool append);
  ~BurstFileWriter();
  BurstFileWriter(const BurstFileWriter&) = delete;
  BurstFileWriter& operator=(const BurstFileWriter&) = delete;

  void write(const BurstRecord& record);  // one row, flushed

  static std::string header(const BurstUnits& units);

 private:
  std::FILE* file_ = nullptr;
};

}  // namespace coupling
