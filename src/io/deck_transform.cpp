#include "deck_transform.hpp"

#include <cmath>

namespace abut::deck {
namespace {
constexpr double kTolerance = 1e-12;

double largest_entry(const std::array<Vec3, 3>& a) {
  double m = 0.0;
  for (const auto& r : a)
    m = std::fmax(m, std::fmax(std::fabs(r.x), std::fmax(std::fabs(r.y), std::fabs(r.z))));
  return m;
}
}  // namespace

bool Transform::axis_aligned() const {
  const double tol = kTolerance * largest_entry(rows);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (i != j && std::fabs(rows[i][j]) > tol) return false;
    }
  }
  return true;
}

bool Transform::keeps_directions() const {
  return axis_aligned() && rows[0].x > 0.0 && rows[1].y > 0.0 && rows[2].z > 0.0;
}

std::optional<double> Transform::uniform_scale() const {
  // A^T A = s^2 I  <=>  the columns of A are orthogonal with equal length.
  const Vec3 c0{rows[0].x, rows[1].x, rows[2].x};
  const Vec3 c1{rows[0].y, rows[1].y, rows[2].y};
  const Vec3 c2{rows[0].z, rows[1].z, rows[2].z};
  const double s2 = dot(c0, c0);
  const double tol = 1e-10 * s2;
  if (std::fabs(dot(c1, c1) - s2) > tol || std::fabs(dot(c2, c2) - s2) > tol ||
      std::fabs(dot(c0, c1)) > tol || std::fabs(dot(c0, c2)) > tol ||
      std::fabs(dot(c1, c2)) > tol) {
    return std::nullopt;
  }
  return std::sqrt(s2);
}

Transform Transform::after(const Transform& inner) const {
  Transform t;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      t.rows[i][j] = rows[i][0] * inner.rows[0][j] + rows[i][1] * inner.rows[1][j] +
                     rows[i][2] * inner.rows[2][j];
    }
  }
  t.shift = point(inner.shift);
  return t;
}

Transform include_transform(const Vec3& scale, const Vec3& from, const Vec3& to, const Vec3& x_axis,
                            const Vec3& y_axis, bool mirror) {
  const Vec3 ex = normalized(x_axis);
  const Vec3 ey = normalized(y_axis);
  const Vec3 ez = mirror ? -cross(ex, ey) : cross(ex, ey);
  Transform t;
  for (int i = 0; i < 3; ++i) t.rows[i] = Vec3{ex[i] * scale.x, ey[i] * scale.y, ez[i] * scale.z};
  const Vec3 r_from{dot(Vec3{ex.x, ey.x, ez.x}, from), dot(Vec3{ex.y, ey.y, ez.y}, from),
                    dot(Vec3{ex.z, ey.z, ez.z}, from)};
  t.shift = to - r_from;
  return t;
}

}  // namespace abut::deck
