#include "abut/contact/quad.hpp"

#include <algorithm>
#include <cmath>

namespace abut {
namespace {

constexpr double kInsideTolerance = 1e-10;  // reference coordinates
constexpr int kMaxIterations = 25;
constexpr double kStepTolerance = 1e-13;  // reference coordinates

// Completes a projection from its facet coordinates.
void finish(const QuadCorners& c, const Vec3& p, QuadProjection& r) {
  double jacobian = 0.0;
  r.point = quad_point(c, r.xi, r.eta);
  r.normal = quad_normal(c, r.xi, r.eta, jacobian);
  const Vec3 d = p - r.point;
  r.gap = dot(d, r.normal);
  r.distance = norm(d);
  if (r.crossed_edges != 0) r.overshoot = norm(d - r.normal * r.gap);
}

}  // namespace

QuadProjection project_onto_quad(const QuadCorners& c, const Vec3& p, double xi, double eta) {
  QuadProjection r;
  // x(xi, eta) = x0 + xi a + eta b + xi eta h, so x_xi_xi = x_eta_eta = 0 and x_xi_eta = h.
  const Vec3 x0 = (c[0] + c[1] + c[2] + c[3]) * 0.25;
  const Vec3 a = (c[1] - c[0] + c[2] - c[3]) * 0.25;
  const Vec3 b = (c[3] - c[0] + c[2] - c[1]) * 0.25;
  const Vec3 h = (c[0] - c[1] + c[2] - c[3]) * 0.25;
  const Vec3 from = x0 - p;
  const double hh = dot(h, h);
  for (int it = 0; it < kMaxIterations; ++it) {
    const Vec3 d_xi = a + h * eta, d_eta = b + h * xi;
    const Vec3 res = from + a * xi + d_eta * eta;
    const double g0 = dot(d_xi, res), g1 = dot(d_eta, res);
    const double a00 = dot(d_xi, d_xi), a11 = dot(d_eta, d_eta);
    double a01 = dot(d_xi, d_eta) + dot(h, res);
    double det = a00 * a11 - a01 * a01;
    const bool newton = det > 1e-14 * a00 * a11;
    if (!newton) {  // indefinite Hessian far off a warped facet: Gauss-Newton
      a01 = dot(d_xi, d_eta);
      det = a00 * a11 - a01 * a01;
      if (!(det > 0.0)) break;
    }
    const double inverse = 1.0 / det;
    const double dxi = (a01 * g1 - a11 * g0) * inverse;
    const double deta = (a01 * g0 - a00 * g1) * inverse;
    // Iterates far outside the facet only tell that the closest point is on the boundary.
    const double next_xi = std::clamp(xi + dxi, -2.0, 2.0);
    const double next_eta = std::clamp(eta + deta, -2.0, 2.0);
    const bool clamped = next_xi != xi + dxi || next_eta != eta + deta;
    // Converged, or held at the clamp (a point far beyond a flat facet's edge) where further
    // iterations only repeat this one.
    const double moved = std::abs(next_xi - xi) + std::abs(next_eta - eta);
    xi = next_xi;
    eta = next_eta;
    if (moved < kStepTolerance) break;
    // x is bilinear, so the gradient after a full Newton step is known in closed form:
    //   g0' = 2 (x_xi . h) dxi deta + (x_eta . h) deta^2 + (h . h) dxi deta^2,
    //   g1' = 2 (x_eta . h) dxi deta + (x_xi . h) dxi^2 + (h . h) dxi^2 deta.
    // When the step it asks for (with this Hessian) is below the tolerance, the next iteration
    // would stop there: stop now. A parallelogram (h = 0) takes one iteration.
    if (newton && !clamped) {
      const double xh = dot(d_xi, h), eh = dot(d_eta, h);
      const double r0 = (2.0 * xh * dxi + eh * deta + hh * dxi * deta) * deta;
      const double r1 = (2.0 * eh * deta + xh * dxi + hh * dxi * deta) * dxi;
      if ((std::abs(a01 * r1 - a11 * r0) + std::abs(a01 * r0 - a00 * r1)) * inverse <
          kStepTolerance)
        break;
    }
  }
  if (std::abs(xi) <= 1.0 + kInsideTolerance && std::abs(eta) <= 1.0 + kInsideTolerance) {
    r.xi = std::clamp(xi, -1.0, 1.0);
    r.eta = std::clamp(eta, -1.0, 1.0);
    finish(c, p, r);
    return r;
  }

  // Closest point on the boundary: the edges are straight segments.
  constexpr double ref[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  double best = -1.0;
  for (int e = 0; e < 4; ++e) {
    const Vec3& start = c[e];
    const Vec3 along = c[(e + 1) % 4] - start;
    const double len2 = dot(along, along);
    const double t = len2 > 0.0 ? std::clamp(dot(p - start, along) / len2, 0.0, 1.0) : 0.0;
    const Vec3 q = start + along * t;
    const double d2 = dot(p - q, p - q);
    if (best < 0.0 || d2 < best) {
      best = d2;
      r.xi = ref[e][0] + (ref[(e + 1) % 4][0] - ref[e][0]) * t;
      r.eta = ref[e][1] + (ref[(e + 1) % 4][1] - ref[e][1]) * t;
      // At a corner the point passes both edges that meet there.
      r.crossed_edges = static_cast<std::uint8_t>(1u << e);
      if (t == 0.0) r.crossed_edges |= static_cast<std::uint8_t>(1u << ((e + 3) % 4));
      if (t == 1.0) r.crossed_edges |= static_cast<std::uint8_t>(1u << ((e + 1) % 4));
    }
  }
  finish(c, p, r);
  return r;
}

}  // namespace abut
