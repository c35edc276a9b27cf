#include "atom_coupling_state.h"

namespace lbm_pore {

namespace {
// Walks a flat buffer in one fixed order, so pack and unpack cannot disagree.
template <class Visit>
void visit_fields(AtomCouplingState& s, Visit visit) {
  for (double& v : s.load.force) visit(v);
  for (double& v : s.load.torque) visit(v);
  visit(s.load.coefficient);
  for (double& v : s.load.step_velocity) visit(v);
  for (double& v : s.load.previous_force) visit(v);
  for (double& v : s.load.previous_velocity) visit(v);
  for (double& v : s.motion.position) visit(v);
  double has = s.motion.has_position ? 1.0 : 0.0;
  visit(has);
  s.motion.has_position = has > 0.0;
  for (double& v : s.fluid_velocity) visit(v);
  visit(s.tag);
  for (double& v : s.wall.normal) visit(v);
  visit(s.wall.distance);
  double known = s.wall.known ? 1.0 : 0.0;
  visit(known);
  s.wall.known = known > 0.0;
  for (double& v : s.wall.searched_from) visit(v);
  // Fields added later go last: a shorter buffer of an earlier layout is a prefix.
  for (double& v : s.motion.last_velocity) visit(v);
  double has_last = s.motion.has_last_velocity ? 1.0 : 0.0;
  visit(has_last);
  s.motion.has_last_velocity = has_last > 0.0;
}
}  // namespace

void AtomCouplingState::pack(double* buf) const {
  AtomCouplingState copy = *this;
  int m = 0;
  visit_fields(copy, [&](double& v) { buf[m++] = v; });
}

void AtomCouplingState::unpack(const double* buf, int count) {
  *this = AtomCouplingState{};
  int m = 0;
  visit_fields(*this, [&](double& v) {
    if (m < count) v = buf[m];
    ++m;
  });
}

void AtomCouplingState::pack_summed(double* buf) const {
  for (int a = 0; a < 3; ++a) buf[a] = load.force[a];
  for (int a = 0; a < 3; ++a) buf[3 + a] = load.torque[a];
  buf[6] = load.coefficient;
}

void AtomCouplingState::add_summed(const double* buf) {
  for (int a = 0; a < 3; ++a) load.force[a] += buf[a];
  for (int a = 0; a < 3; ++a) load.torque[a] += buf[3 + a];
  load.coefficient += buf[6];
}

}  // namespace lbm_pore
