#include "abut/element/shell4.hpp"

#include <algorithm>

namespace abut {

Shell4Geometry shell4_geometry(const std::array<Vec3, 4>& p) {
  Shell4Geometry g;
  const Vec3 centroid = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  g.e3 = normalized(cross(p[2] - p[0], p[3] - p[1]));
  const Vec3 side = p[1] - p[0];
  g.e1 = normalized(side - dot(side, g.e3) * g.e3);
  g.e2 = cross(g.e3, g.e1);
  for (int a = 0; a < 4; ++a) {
    const Vec3 r = p[a] - centroid;
    g.x[a] = dot(r, g.e1);
    g.y[a] = dot(r, g.e2);
    g.z[a] = dot(r, g.e3);
  }
  const double x31 = g.x[2] - g.x[0], x42 = g.x[3] - g.x[1];
  const double y31 = g.y[2] - g.y[0], y42 = g.y[3] - g.y[1];
  g.area = 0.5 * (x31 * y42 - x42 * y31);
  if (!(g.area > 0.0)) return g;
  const double inv = 0.5 / g.area;
  g.b1 = {-y42 * inv, y31 * inv, y42 * inv, -y31 * inv};
  g.b2 = {x42 * inv, -x31 * inv, -x42 * inv, x31 * inv};
  const std::array<double, 4> h{1.0, -1.0, 1.0, -1.0};
  double hx = 0.0, hy = 0.0;
  for (int a = 0; a < 4; ++a) {
    hx += h[a] * g.x[a];
    hy += h[a] * g.y[a];
  }
  for (int a = 0; a < 4; ++a) g.gamma[a] = h[a] - hx * g.b1[a] - hy * g.b2[a];
  for (int a = 0; a < 4; ++a)
    g.longest_side = std::max(g.longest_side, norm(p[(a + 1) % 4] - p[a]));
  return g;
}

double shell4_critical_length(const Shell4Geometry& g, bool triangle) {
  return (triangle ? 2.0 : 1.0) * g.area / g.longest_side;
}

}  // namespace abut
