#include "contact/stability_limits.h"

namespace contact {

TimeStepLimit time_step_limit(const DashDotParams& params, double effective_mass) {
  TimeStepLimit limit;
  limit.contact_time = contact_duration(params, effective_mass);
  limit.max_time_step = limit.contact_time / kMinStepsPerContact;
  return limit;
}

OverlapSeverity overlap_severity(double overlap_ratio) {
  if (overlap_ratio > kStopOverlapRatio) return OverlapSeverity::kPassingThrough;
  if (overlap_ratio > kWarnOverlapRatio) return OverlapSeverity::kTooSoft;
  return OverlapSeverity::kResolved;
}

}  // namespace contact
