// Nagata's edge curve (Nagata, CAGD 22 (2005) 327-347): x(t) = (1-t) x0 + t x1 - c t (1-t)
// with tangents x'(0) = d - c and x'(1) = d + c perpendicular to the end normals n0 and n1.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../../src/mesh/surface_smoothing.hpp"

namespace abut::detail {
namespace {

TEST(NagataCurvature, TangentsArePerpendicularToTheEndNormals) {
  const Vec3 x0{0.1, -0.2, 0.3}, x1{1.2, 0.4, 0.1};
  const Vec3 n0 = normalized(Vec3{0.1, 0.2, 1.0}), n1 = normalized(Vec3{-0.3, 0.1, 0.9});
  const Vec3 c = nagata_curvature(x0, x1, n0, n1);
  const Vec3 d = x1 - x0;
  EXPECT_NEAR(dot(d - c, n0), 0.0, 1e-14);
  EXPECT_NEAR(dot(d + c, n1), 0.0, 1e-14);
}

// Chord of a unit circle between angles -a and +a, normals radial: the midpoint of the Nagata
// curve lies at radius cos(a) (1 + tan(a)^2 / 2) (c = -2 tan(a)^2 cos(a) e_x, midpoint
// x(1/2) = cos(a) e_x - c/4), within O(a^4) of the circle.
TEST(NagataCurvature, CircleArcMidpoint) {
  const double a = 15.0 * std::numbers::pi / 180.0;
  const Vec3 x0{std::cos(a), -std::sin(a), 0}, x1{std::cos(a), std::sin(a), 0};
  const Vec3 c = nagata_curvature(x0, x1, x0, x1);
  const Vec3 mid = 0.5 * (x0 + x1) - 0.25 * c;
  EXPECT_NEAR(norm(mid), std::cos(a) * (1.0 + 0.5 * std::tan(a) * std::tan(a)), 1e-15);
  EXPECT_LT(std::abs(norm(mid) - 1.0), 0.1 * (1.0 - std::cos(a)));  // vs the flat chord
}

TEST(NagataCurvature, ParallelNormalsGiveAStraightEdge) {
  const Vec3 n{0, 0, 1};
  const Vec3 c = nagata_curvature({0, 0, 0}, {1, 0, 0}, n, n);
  EXPECT_EQ(norm(c), 0.0);
}

}  // namespace
}  // namespace abut::detail
