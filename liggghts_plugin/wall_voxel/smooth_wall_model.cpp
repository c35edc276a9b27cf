#include "smooth_wall_model.h"

#include <algorithm>

namespace lbm_pore {

namespace {
// Contacts of consecutive steps are the same contact when their normals are this close
// (cos 25 deg): a sphere rolling over an edge turns its normal slowly.
constexpr double kSameContactCosine = 0.9;
}  // namespace

SmoothWallModel::SmoothWallModel(const contact::WallContactParams& params,
                                 std::shared_ptr<const lbm::VoxelGeometry> geometry)
    : params_(params), geometry_(std::move(geometry)), surface_(*geometry_) {}

WallForce SmoothWallModel::apply(int i, const WallParticle& particle) {
  WallForce out;
  double* history = &history_[static_cast<std::size_t>(i) * kStride];
  const double reach = contact::wall_contact_reach(params_, particle.radius);
  surface_.find(particle.centre, reach, points_, candidates_[i]);
  if (points_.empty()) {
    std::fill(history, history + kStride, 0.0);
    return out;
  }
  out.touching = true;
  const contact::WallParticleTerms terms =
      contact::wall_particle_terms(params_, particle.radius, particle.mass);
  double fresh[kStride] = {};
  bool used[kMaxContacts] = {};
  int stored = 0;
  for (const contact::SurfacePoint& point : points_) {
    contact::WallContactInput in;
    in.normal = point.normal;
    in.gap = point.distance - particle.radius;
    in.radius = particle.radius;
    in.mass = particle.mass;
    in.velocity = particle.velocity;
    in.dt = particle.dt;
    // The same contact as last step: the stored normal that points the same way.
    for (int s = 0; s < kMaxContacts; ++s) {
      const double* slot = history + s * kHistoryPerContact;
      const contact::Vec3 old_normal{slot[0], slot[1], slot[2]};
      if (!used[s] && contact::dot(old_normal, point.normal) > kSameContactCosine) {
        used[s] = true;
        in.spring = {slot[3], slot[4], slot[5]};
        break;
      }
    }
    const contact::WallContactResult result = contact::wall_contact_force(params_, terms, in);
    out.force += result.force;
    if (in.gap < 0.0) out.max_overlap_ratio = std::max(out.max_overlap_ratio, -in.gap / in.radius);
    if (!result.active) continue;
    ++out.contacts;
    if (stored == kMaxContacts) {
      ++out.springs_dropped;
      continue;
    }
    double* slot = fresh + stored * kHistoryPerContact;
    slot[0] = point.normal.x; slot[1] = point.normal.y; slot[2] = point.normal.z;
    slot[3] = result.spring.x; slot[4] = result.spring.y; slot[5] = result.spring.z;
    ++stored;
  }
  std::copy(fresh, fresh + kStride, history);
  return out;
}

TimeStepFinding SmoothWallModel::time_step(double mass, double /*radius*/) const {
  TimeStepFinding found;
  found.stiffness_name = contact::wall_tangential_spring_is_stiffer(params_) ? "kt" : "kw";
  found.stiffness = contact::wall_stiffest_spring(params_).k_n;
  found.lightest_mass = mass;
  found.limit = contact::wall_time_step_limit(params_, mass);
  return found;
}

void SmoothWallModel::grow(int nmax) {
  history_.resize(static_cast<std::size_t>(nmax) * kStride, 0.0);
  candidates_.resize(nmax);
}

void SmoothWallModel::copy(int from, int to) {
  std::copy_n(&history_[static_cast<std::size_t>(from) * kStride], kStride,
              &history_[static_cast<std::size_t>(to) * kStride]);
}

void SmoothWallModel::pack(int i, double* buffer) const {
  std::copy_n(&history_[static_cast<std::size_t>(i) * kStride], kStride, buffer);
}

bool SmoothWallModel::unpack(int i, const double* buffer) {
  std::copy_n(buffer, kStride, &history_[static_cast<std::size_t>(i) * kStride]);
  return true;
}

}  // namespace lbm_pore
