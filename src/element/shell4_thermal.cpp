// Heat conduction in the 4-node shell and the triangle: see shell4_thermal.hpp.
#include "abut/element/shell4_thermal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "abut/core/vec3.hpp"

namespace abut {
namespace {

Vec3 node(const double X[4][3], int a) { return {X[a][0], X[a][1], X[a][2]}; }

// Adds k h A grad N_a . grad N_b of the linear triangle on nodes 0, 1, 2.
double triangle(const double X[4][3], double kh, double K[16]) {
  const Vec3 x[3] = {node(X, 0), node(X, 1), node(X, 2)};
  const Vec3 n2 = cross(x[1] - x[0], x[2] - x[0]);  // 2 A times the unit normal
  const double twice_area = norm(n2);
  if (!(twice_area > 0.0)) return 0.0;
  const Vec3 n = n2 / twice_area;
  Vec3 grad[3];
  for (int i = 0; i < 3; ++i) grad[i] = cross(n, x[(i + 2) % 3] - x[(i + 1) % 3]) / twice_area;
  const double area = 0.5 * twice_area;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) K[4 * a + b] = kh * area * dot(grad[a], grad[b]);
  return area;
}

// The same for the bilinear quadrilateral, 2 x 2 Gauss points.
double quadrilateral(const double X[4][3], double kh, double K[16]) {
  static constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0}, kEta[4] = {-1.0, -1.0, 1.0, 1.0};
  const double g = 1.0 / std::sqrt(3.0);
  double area = 0.0;
  for (int p = 0; p < 4; ++p) {
    const double xi = kXi[p] * g, eta = kEta[p] * g;
    double dxi[4], deta[4];
    for (int a = 0; a < 4; ++a) {
      dxi[a] = 0.25 * kXi[a] * (1.0 + kEta[a] * eta);
      deta[a] = 0.25 * kEta[a] * (1.0 + kXi[a] * xi);
    }
    Vec3 g1, g2;
    for (int a = 0; a < 4; ++a) {
      g1 += node(X, a) * dxi[a];
      g2 += node(X, a) * deta[a];
    }
    const double g11 = dot(g1, g1), g12 = dot(g1, g2), g22 = dot(g2, g2);
    const double det = g11 * g22 - g12 * g12;  // |g1 x g2|^2
    if (!(det > 0.0)) continue;
    const double da = std::sqrt(det);  // Gauss weight 1
    area += da;
    // G^ij: the inverse metric.
    const double i11 = g22 / det, i12 = -g12 / det, i22 = g11 / det;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        K[4 * a + b] +=
            kh * da *
            (dxi[a] * (i11 * dxi[b] + i12 * deta[b]) + deta[a] * (i12 * dxi[b] + i22 * deta[b]));
  }
  return area;
}

}  // namespace

void shell4_conduction(const double X[4][3], bool is_triangle, double thickness,
                       double conductivity, double volumetric_capacity, Shell4Conduction& out) {
  std::fill(out.conductance, out.conductance + 16, 0.0);
  const double kh = conductivity * thickness;
  out.area = is_triangle ? triangle(X, kh, out.conductance) : quadrilateral(X, kh, out.conductance);
  const int nodes = is_triangle ? 3 : 4;
  const double c = volumetric_capacity * thickness * out.area / nodes;
  double lambda = 0.0;
  for (int a = 0; a < 4; ++a) {
    out.capacity[a] = a < nodes ? c : 0.0;
    if (a >= nodes || !(c > 0.0)) continue;
    double row = 0.0;
    for (int b = 0; b < 4; ++b) row += std::abs(out.conductance[4 * a + b]);
    lambda = std::max(lambda, row / c);
  }
  out.stable_step = lambda > 0.0 ? 2.0 / lambda : std::numeric_limits<double>::infinity();
}

}  // namespace abut
