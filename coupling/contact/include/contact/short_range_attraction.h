#pragma once
// Short-range van-der-Waals-like attraction of the paper, both linear in the gap h:
//   cohesion  (particle-particle, Eq. 2): F_c = h k_c RiRj/(Ri+Rj)  for 0 <= h <= 0.03 (Ri+Rj)
//   adhesion  (particle-wall,     Eq. 4): F_a = h k_a R_i           for 0 <= h <= 0.03 R_i
// Values are magnitudes of an attractive force (pulling the bodies together).
//
// Inside an overlap (h < 0) both are zero: the paper defines them for gaps only, and the
// dash-dot repulsion takes over there. Since F_c(0) = 0 and F_n(0) = 0, the total normal
// force is continuous through contact. Beyond the range the force drops to zero: the largest
// attraction, and so the load a bond holds, is the value at the range:
//   F_c,max = 0.03 k_c Ri Rj,   F_a,max = 0.03 k_a R_i^2.

namespace contact {

// The paper's range factor 0.03 (of Ri+Rj for cohesion, of R_i for adhesion).
constexpr double kAttractionRangeFactor = 0.03;

struct CohesionParams {
  double k_c = 0.1;  // paper table
  double range_factor = kAttractionRangeFactor;
};

struct AdhesionParams {
  double k_a = 0.1;  // paper table
  double range_factor = kAttractionRangeFactor;
};

// Inline: the pair style's and the wall fix's inner loops call them.
inline double cohesion_range(const CohesionParams& params, double radius_i, double radius_j) {
  return params.range_factor * (radius_i + radius_j);
}

// F_c = h k_c a* with the reduced radius a* = RiRj/(Ri+Rj), in that order of operations (the
// order pair_style lbm/dashdot has always used, so its results stay bit-identical).
inline double cohesion_force(const CohesionParams& params, double gap, double radius_i,
                             double radius_j) {
  if (gap < 0.0 || gap > cohesion_range(params, radius_i, radius_j)) return 0.0;
  const double reduced_radius = radius_i * radius_j / (radius_i + radius_j);
  return gap * params.k_c * reduced_radius;
}

inline double adhesion_range(const AdhesionParams& params, double radius) {
  return params.range_factor * radius;
}

inline double adhesion_force(const AdhesionParams& params, double gap, double radius) {
  if (gap < 0.0 || gap > adhesion_range(params, radius)) return 0.0;
  return gap * params.k_a * radius;
}

double max_cohesion_force(const CohesionParams& params, double radius_i, double radius_j);
double max_adhesion_force(const AdhesionParams& params, double radius);

}  // namespace contact
