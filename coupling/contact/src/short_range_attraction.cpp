#include "contact/short_range_attraction.h"

namespace contact {

double max_cohesion_force(const CohesionParams& params, double radius_i, double radius_j) {
  return params.range_factor * params.k_c * radius_i * radius_j;
}

double max_adhesion_force(const AdhesionParams& params, double radius) {
  return params.range_factor * params.k_a * radius * radius;
}

}  // namespace contact
