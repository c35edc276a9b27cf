#include "contact/short_range_attraction.h"

namespace contact {

double cohesion_range(const CohesionParams& params, double radius_i, double radius_j) {
  return params.range_factor * (radius_i + radius_j);
}

double cohesion_force(const CohesionParams& params, double gap, double radius_i, double radius_j) {
  if (gap < 0.0 || gap > cohesion_range(params, radius_i, radius_j)) return 0.0;
  return gap * params.k_c * radius_i * radius_j / (radius_i + radius_j);
}

double max_cohesion_force(const CohesionParams& params, double radius_i, double radius_j) {
  return params.range_factor * params.k_c * radius_i * radius_j;
}

double adhesion_range(const AdhesionParams& params, double radius) {
  return params.range_factor * radius;
}

double adhesion_force(const AdhesionParams& params, double gap, double radius) {
  if (gap < 0.0 || gap > adhesion_range(params, radius)) return 0.0;
  return gap * params.k_a * radius;
}

double max_adhesion_force(const AdhesionParams& params, double radius) {
  return params.range_factor * params.k_a * radius * radius;
}

}  // namespace contact
