#pragma once
// The one clock of a coupled run's timing. SphereCoupling adds the seconds of its stages
// (StageTimes) with it and a host's coupling::RunTimer measures the rest of the run with it,
// so the stage times and the run's parts are on one time base and add up in one report.
#include <chrono>

namespace coupling {

// Seconds on the monotonic wall clock (steady_clock: never set back, unlike the time of day).
inline double clock_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Adds the seconds from its construction to its end to `total`: one stage of a step.
class StageTimer {
 public:
  explicit StageTimer(double& total) : total_(total), start_(clock_seconds()) {}
  ~StageTimer() { total_ += clock_seconds() - start_; }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  double& total_;
  double start_;
};

}  // namespace coupling
