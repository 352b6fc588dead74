#pragma once
// Geometry of a bilinear quad facet x(xi, eta) = sum_a N_a(xi, eta) x_a on [-1, 1]^2, with
// corners a = 0..3 at (-1,-1), (1,-1), (1,1), (-1,1). Edge e joins corners e and e+1 (mod 4):
// edge 0 is eta = -1, edge 1 xi = +1, edge 2 eta = +1, edge 3 xi = -1.
#include <array>
#include <cstdint>
#include <span>

#include "abut/core/vec3.hpp"

namespace abut {

using QuadCorners = std::array<Vec3, 4>;

// The corners of a facet from nodal coordinate arrays.
inline QuadCorners quad_corners(const std::array<std::int32_t, 4>& nodes, std::span<const double> x,
                                std::span<const double> y, std::span<const double> z) {
  QuadCorners c;
  for (int a = 0; a < 4; ++a) c[a] = {x[nodes[a]], y[nodes[a]], z[nodes[a]]};
  return c;
}

inline std::array<double, 4> quad_shape(double xi, double eta) {
  return {0.25 * (1.0 - xi) * (1.0 - eta), 0.25 * (1.0 + xi) * (1.0 - eta),
          0.25 * (1.0 + xi) * (1.0 + eta), 0.25 * (1.0 - xi) * (1.0 + eta)};
}

inline Vec3 quad_point(const QuadCorners& c, double xi, double eta) {
  const auto n = quad_shape(xi, eta);
  return c[0] * n[0] + c[1] * n[1] + c[2] * n[2] + c[3] * n[3];
}

// Tangent vectors dx/dxi and dx/deta.
inline void quad_tangents(const QuadCorners& c, double xi, double eta, Vec3& d_xi, Vec3& d_eta) {
  d_xi = ((c[1] - c[0]) * (1.0 - eta) + (c[2] - c[3]) * (1.0 + eta)) * 0.25;
  d_eta = ((c[3] - c[0]) * (1.0 - xi) + (c[2] - c[1]) * (1.0 + xi)) * 0.25;
}

// Unit outward normal at (xi, eta) and the area density |dx/dxi x dx/deta| (area per unit
// reference area). At a collapsed corner the normal of the diagonals is used.
inline Vec3 quad_normal(const QuadCorners& c, double xi, double eta, double& jacobian) {
  Vec3 d_xi, d_eta;
  quad_tangents(c, xi, eta, d_xi, d_eta);
  const Vec3 n = cross(d_xi, d_eta);
  jacobian = norm(n);
  if (jacobian > 0.0) return n / jacobian;
  return normalized(cross(c[2] - c[0], c[3] - c[1]));
}

// Area-weighted normal from the diagonals: exact area for planar quads.
inline Vec3 quad_centre_normal(const QuadCorners& c) {
  return normalized(cross(c[2] - c[0], c[3] - c[1]));
}

// Closest point of the facet to a point p.
struct QuadProjection {
  double xi = 0.0, eta = 0.0;  // on the facet, in [-1, 1]^2
  Vec3 point;                  // x(xi, eta)
  Vec3 normal;                 // unit outward normal at (xi, eta)
  double gap = 0.0;            // (p - point) . normal: negative = p is behind the facet
  double distance = 0.0;       // |p - point|
  // The normal projection of p misses the facet: which edges it passes (bit e = edge e) and how
  // far beyond them p lies, measured in the facet's tangent plane. Both 0 inside the facet.
  std::uint8_t crossed_edges = 0;
  double overshoot = 0.0;
};

// Newton iteration on the stationarity of |x(xi, eta) - p|^2 from (xi, eta): the centre, or
// where the point lay on this facet a step before (fewer iterations); if the stationary point
// lies outside [-1, 1]^2 the closest point is on the boundary and is found exactly on the four
// straight edges.
QuadProjection project_onto_quad(const QuadCorners& c, const Vec3& p, double xi = 0.0,
                                 double eta = 0.0);

}  // namespace abut
