#include "mesh/hex_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace abut::detail {

bool point_in_hex(const HexPoints& x, const Vec3& p) {
  Vec3 lo = x[0], hi = x[0];
  for (const Vec3& q : x) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], q[a]);
      hi[a] = std::max(hi[a], q[a]);
    }
  }
  const double size = norm(hi - lo);
  const double slack = 1e-12 * size;
  for (int a = 0; a < 3; ++a) {
    if (p[a] < lo[a] - slack || p[a] > hi[a] + slack) return false;
  }
  Vec3 s{0.5, 0.5, 0.5};
  for (int iteration = 0; iteration < 30; ++iteration) {
    // Residual and Jacobian columns d x / d(u, v, w) of the trilinear map.
    const Vec3 r = trilinear(x, s.x, s.y, s.z) - p;
    Vec3 column[3];
    for (int a = 0; a < 8; ++a) {
      const int* c = kHexCorner[a];
      const double f[3][2] = {{1.0 - s.x, s.x}, {1.0 - s.y, s.y}, {1.0 - s.z, s.z}};
      const double sign[2] = {-1.0, 1.0};
      column[0] += (sign[c[0]] * f[1][c[1]] * f[2][c[2]]) * x[a];
      column[1] += (f[0][c[0]] * sign[c[1]] * f[2][c[2]]) * x[a];
      column[2] += (f[0][c[0]] * f[1][c[1]] * sign[c[2]]) * x[a];
    }
    const double det = dot(column[0], cross(column[1], column[2]));
    if (!(std::abs(det) > 1e-14 * size * size * size)) return false;  // degenerate hex
    // Cramer's rule for J * step = r.
    const Vec3 step{dot(r, cross(column[1], column[2])) / det,
                    dot(column[0], cross(r, column[2])) / det,
                    dot(column[0], cross(column[1], r)) / det};
    s -= step;
    if (norm(step) < 1e-13) break;
  }
  constexpr double kLocalTolerance = 1e-10;
  for (int a = 0; a < 3; ++a) {
    if (!(s[a] >= -kLocalTolerance && s[a] <= 1.0 + kLocalTolerance)) return false;
  }
  return norm(trilinear(x, s.x, s.y, s.z) - p) <= 1e-9 * size;  // Newton converged
}

}  // namespace abut::detail
