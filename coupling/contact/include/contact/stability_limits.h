#pragma once
// Where the linear contact stops being resolved (doc/stability.md), the same for the pair
// style and the wall fix: a time step too long for the contact time t_c of the dash-dot
// oscillator (paper Eq. 1), and an overlap too deep for the stiffness. The styles turn these
// into LIGGGHTS errors and warnings (liggghts_plugin/plugin_common/contact_guards.h).
#include "contact/dash_dot.h"

namespace contact {

// At least this many steps must resolve a contact (doc/references.md: dt <= t_c / 10).
constexpr double kMinStepsPerContact = 10.0;

// Overlap / R (the smaller radius of a pair) above which the stiffness is too soft for the
// forces of the scene, and above which the bodies pass through each other.
constexpr double kWarnOverlapRatio = 0.05;
constexpr double kStopOverlapRatio = 0.5;

struct TimeStepLimit {
  double contact_time = 0.0;   // t_c of contact_duration()
  double max_time_step = 0.0;  // t_c / kMinStepsPerContact
};

// The limit for the spring `params` on the effective mass m_eff.
TimeStepLimit time_step_limit(const DashDotParams& params, double effective_mass);

enum class OverlapSeverity {
  kResolved,        // up to kWarnOverlapRatio
  kTooSoft,         // above it: warn
  kPassingThrough,  // above kStopOverlapRatio: stop
};

OverlapSeverity overlap_severity(double overlap_ratio);

}  // namespace contact
