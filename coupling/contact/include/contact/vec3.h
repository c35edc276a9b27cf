#pragma once
#include <array>
#include <cmath>

namespace contact {

// A plain 3-vector for the contact laws; the LIGGGHTS styles copy double[3] in and out.
struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;

  double& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
  double operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3 operator*(Vec3 a, double s) { return s * a; }
inline Vec3& operator+=(Vec3& a, Vec3 b) { a = a + b; return a; }
inline Vec3& operator-=(Vec3& a, Vec3 b) { a = a - b; return a; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
// The part of v perpendicular to the unit vector n.
inline Vec3 tangential_part(Vec3 v, Vec3 n) { return v - dot(v, n) * n; }

}  // namespace contact
