#pragma once
// 3x3 matrix (row-major) for rigid-body kinematics and small tensor algebra.
#include <array>
#include <cmath>

#include "abut/core/vec3.hpp"

namespace abut {

struct Mat3 {
  std::array<double, 9> a{};  // a[3*i + j] = row i, column j

  static constexpr Mat3 identity() { return Mat3{{1, 0, 0, 0, 1, 0, 0, 0, 1}}; }
  constexpr double operator()(int i, int j) const { return a[3 * i + j]; }
  constexpr double& operator()(int i, int j) { return a[3 * i + j]; }
};

constexpr Vec3 operator*(const Mat3& m, const Vec3& v) {
  return {m(0, 0) * v.x + m(0, 1) * v.y + m(0, 2) * v.z,
          m(1, 0) * v.x + m(1, 1) * v.y + m(1, 2) * v.z,
          m(2, 0) * v.x + m(2, 1) * v.y + m(2, 2) * v.z};
}

constexpr Mat3 operator*(const Mat3& p, const Mat3& q) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = p(i, 0) * q(0, j) + p(i, 1) * q(1, j) + p(i, 2) * q(2, j);
  return r;
}

constexpr Mat3 transpose(const Mat3& m) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = m(j, i);
  return r;
}

constexpr double determinant(const Mat3& m) {
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
         m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

// Inverse by cofactors; the caller guarantees a non-singular matrix.
constexpr Mat3 inverse(const Mat3& m) {
  const double d = determinant(m);
  Mat3 r;
  r(0, 0) = (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) / d;
  r(0, 1) = (m(0, 2) * m(2, 1) - m(0, 1) * m(2, 2)) / d;
  r(0, 2) = (m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1)) / d;
  r(1, 0) = (m(1, 2) * m(2, 0) - m(1, 0) * m(2, 2)) / d;
  r(1, 1) = (m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0)) / d;
  r(1, 2) = (m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2)) / d;
  r(2, 0) = (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0)) / d;
  r(2, 1) = (m(0, 1) * m(2, 0) - m(0, 0) * m(2, 1)) / d;
  r(2, 2) = (m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0)) / d;
  return r;
}

// Rotation by the rotation vector theta (axis * angle), Rodrigues' formula.
inline Mat3 rotation_from_vector(const Vec3& theta) {
  const double angle = norm(theta);
  if (angle < 1e-300) return Mat3::identity();
  const Vec3 k = theta / angle;
  const double c = std::cos(angle), s = std::sin(angle), v = 1.0 - c;
  return Mat3{{c + k.x * k.x * v, k.x * k.y * v - k.z * s, k.x * k.z * v + k.y * s,
               k.y * k.x * v + k.z * s, c + k.y * k.y * v, k.y * k.z * v - k.x * s,
               k.z * k.x * v - k.y * s, k.z * k.y * v + k.x * s, c + k.z * k.z * v}};
}

}  // namespace abut
