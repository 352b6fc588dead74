// Closest-point projection on bilinear quads and the integration rules of the facets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "abut/contact/integration.hpp"
#include "abut/contact/quad.hpp"
#include "fixtures.hpp"

namespace abut {
namespace {

const QuadCorners kWarped = {Vec3{0, 0, 0}, Vec3{2, 0, 0.3}, Vec3{2.2, 1.5, -0.2},
                             Vec3{-0.1, 1.2, 0.25}};

// Reference: the closest point by dense sampling of the facet (then local refinement).
double brute_force_distance(const QuadCorners& c, const Vec3& p) {
  double best = 1e300, bx = 0, by = 0;
  const int n = 400;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double xi = -1.0 + 2.0 * i / n, eta = -1.0 + 2.0 * j / n;
      const double d = norm(quad_point(c, xi, eta) - p);
      if (d < best) best = d, bx = xi, by = eta;
    }
  for (double h = 2.0 / n; h > 1e-12; h *= 0.5)
    for (int k = 0; k < 9; ++k) {
      const double xi = std::clamp(bx + h * (k % 3 - 1), -1.0, 1.0),
                   eta = std::clamp(by + h * (k / 3 - 1), -1.0, 1.0);
      const double d = norm(quad_point(c, xi, eta) - p);
      if (d < best) best = d, bx = xi, by = eta;
    }
  return best;
}

TEST(QuadProjection, MatchesBruteForceOnAWarpedFacet) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 3.0), h(-0.8, 0.8);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p{u(rng), u(rng) * 0.7, h(rng)};
    const QuadProjection q = project_onto_quad(kWarped, p);
    EXPECT_NEAR(q.distance, brute_force_distance(kWarped, p), 1e-9) << "point " << k;
    EXPECT_LE(std::abs(q.xi), 1.0);
    EXPECT_LE(std::abs(q.eta), 1.0);
  }
}

// Distance from p to the triangle a, b, c: the foot in its plane where its area coordinates are
// all >= 0, else the nearest of its three edges (segments).
double triangle_distance(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  const Vec3 n = cross(b - a, c - a);
  const Vec3 foot = p - n * (dot(p - a, n) / dot(n, n));
  const double l0 = dot(cross(c - b, foot - b), n), l1 = dot(cross(a - c, foot - c), n),
               l2 = dot(cross(b - a, foot - a), n);
  if (l0 >= 0.0 && l1 >= 0.0 && l2 >= 0.0) return norm(p - foot);
  auto segment = [&](const Vec3& s, const Vec3& t) {
    const double r = std::clamp(dot(p - s, t - s) / dot(t - s, t - s), 0.0, 1.0);
    return norm(p - (s + (t - s) * r));
  };
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

// A triangle is a quad whose fourth node repeats the third (tetrahedra's and wedges' faces,
// triangular shells): the bilinear map collapses its edge eta = 1 into that corner. Points all
// around it, many near the collapsed corner, from any start: the closest point of the triangle.
TEST(QuadProjection, TriangleFindsItsClosestPointAlsoNearTheCollapsedCorner) {
  const Vec3 a{0, 0, 0}, b{2, 0.2, 0.3}, c{0.7, 1.6, -0.4};
  const QuadCorners tri{a, b, c, c};
  const Vec3 normal = normalized(cross(b - a, c - a));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 3.0), h(-0.8, 0.8), near(-0.3, 0.3),
      start(-1.0, 1.0);
  for (int k = 0; k < 400; ++k) {
    const Vec3 p =
        k % 2 == 0 ? Vec3{u(rng), u(rng) * 0.8, h(rng)} : c + Vec3{near(rng), near(rng), near(rng)};
    const QuadProjection q =
        k % 4 < 2 ? project_onto_quad(tri, p) : project_onto_quad(tri, p, start(rng), start(rng));
    EXPECT_NEAR(q.distance, triangle_distance(a, b, c, p), 1e-9) << "point " << k;
    EXPECT_NEAR(norm(quad_point(tri, q.xi, q.eta) - q.point), 0.0, 1e-12);
    EXPECT_NEAR(dot(q.normal, normal), 1.0, 1e-9) << "point " << k;
  }
}

// The contact starts each projection on last step's partner where the point lay then: any start
// in the facet must find the same closest point.
TEST(QuadProjection, AnyStartInTheFacetFindsTheSameClosestPoint) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 3.0), h(-0.8, 0.8), start(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p{u(rng), u(rng) * 0.7, h(rng)};
    const QuadProjection q = project_onto_quad(kWarped, p, start(rng), start(rng));
    EXPECT_NEAR(q.distance, brute_force_distance(kWarped, p), 1e-9) << "point " << k;
  }
}

// Inside the facet the closest point is stationary: x - p is normal to both tangents. Newton
// stops once the step it would take next is below 1e-13 (predicted in closed form for the
// bilinear facet), so the tangential residual is of that order, far below the brute force's reach.
TEST(QuadProjection, InsideTheFacetTheClosestPointIsStationary) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.2, 1.8), h(-0.5, 0.5), start(-1.0, 1.0);
  int inside = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 p{u(rng), u(rng) * 0.7, h(rng)};
    const QuadProjection q = k % 2 ? project_onto_quad(kWarped, p, start(rng), start(rng))
                                   : project_onto_quad(kWarped, p);
    if (q.crossed_edges != 0) continue;
    ++inside;
    Vec3 d_xi, d_eta;
    quad_tangents(kWarped, q.xi, q.eta, d_xi, d_eta);
    const Vec3 d = quad_point(kWarped, q.xi, q.eta) - p;
    EXPECT_LT(std::abs(dot(d, d_xi)) / dot(d_xi, d_xi), 1e-12) << "point " << k;
    EXPECT_LT(std::abs(dot(d, d_eta)) / dot(d_eta, d_eta), 1e-12) << "point " << k;
  }
  EXPECT_GT(inside, 300);
}

// Far beyond an edge Newton's iterate is held at its clamp (xi or eta = 2) while the other
// coordinate settles: the closest point is then found on the edges.
TEST(QuadProjection, FarBeyondAnEdgeTheClosestPointIsOnTheEdge) {
  const QuadCorners side = {Vec3{0.03, -0.03, 0}, Vec3{0.03, 0, 0}, Vec3{0.03, 0, 0.01},
                            Vec3{0.03, -0.03, 0.01}};  // a block's side, as in the seed deck
  for (const Vec3& p :
       {Vec3{0.0073, 0.00037, 0.0232}, Vec3{0.007, -0.003, 0.0236}, Vec3{0.5, -0.01, -2.0}}) {
    const QuadProjection q = project_onto_quad(side, p);
    EXPECT_NEAR(q.distance, brute_force_distance(side, p), 1e-12);
    EXPECT_NE(q.crossed_edges, 0);
  }
}

TEST(QuadProjection, GapSignEdgesAndCorners) {
  const QuadCorners flat = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}};
  QuadProjection q = project_onto_quad(flat, {0.25, 0.5, -0.1});
  EXPECT_NEAR(q.gap, -0.1, 1e-14);  // behind the facet (normal +z)
  EXPECT_NEAR(q.xi, -0.5, 1e-14);
  EXPECT_EQ(q.crossed_edges, 0);
  q = project_onto_quad(flat, {1.3, 0.5, 0.2});  // beyond edge 1 (xi = +1)
  EXPECT_EQ(q.crossed_edges, 2);
  EXPECT_NEAR(q.overshoot, 0.3, 1e-14);
  EXPECT_NEAR(q.gap, 0.2, 1e-14);
  q = project_onto_quad(flat, {-0.5, -0.5, 0.0});  // beyond corner 0: edges 3 and 0
  EXPECT_EQ(q.crossed_edges, 1 | 8);
  EXPECT_NEAR(q.distance, std::sqrt(0.5), 1e-14);
}

// Gauss rules: n points integrate polynomials of degree 2n-1 per direction exactly.
TEST(FacetRule, IntegratesPolynomialsExactly) {
  for (int level : {1, 2, 3}) {
    for (bool refine : {false, true}) {
      const auto rule = facet_rule(level, refine, 0x0F);
      double area = 0.0, second = 0.0, fourth = 0.0;
      for (const FacetPoint& p : rule) {
        area += p.weight;
        second += p.weight * p.xi * p.xi * p.eta * p.eta;
        fourth += p.weight * std::pow(p.xi, 4);
      }
      EXPECT_NEAR(area, 4.0, 1e-14);
      if (level >= 2) {
        EXPECT_NEAR(second, 4.0 / 9.0, 1e-14);  // int xi^2 eta^2 = (2/3)^2
      }
      if (level >= 3) {
        EXPECT_NEAR(fourth, 0.8, 1e-14);  // int xi^4 = 2/5 * 2
      }
    }
  }
  EXPECT_EQ(facet_rule(1, false, 0).size(), 1u);
  EXPECT_EQ(facet_rule(2, false, 0).size(), 4u);
  EXPECT_EQ(facet_rule(5, false, 0).size(), 9u);
}

TEST(FacetRule, EdgeRefinementAddsPointsAlongSharpEdges) {
  const auto plain = facet_rule(2, true, 0);
  const auto one_edge = facet_rule(2, true, 2);  // edge 1: xi = +1
  EXPECT_EQ(plain.size(), 4u);
  ASSERT_EQ(one_edge.size(), 8u);
  int near_edge = 0;
  for (const FacetPoint& p : one_edge) near_edge += p.xi > 0.5;
  EXPECT_EQ(near_edge, 4);  // 2 x 2 Gauss points inside the strip next to the sharp edge
  EXPECT_EQ(facet_rule(2, false, 2).size(), 4u);  // without accuracy_edge nothing changes
}

TEST(SharpEdges, CubeEdgesAreSharpAndFlatInteriorEdgesAreNot) {
  testing::World w;
  // A 2x2 flat plate: its outer edges are free (sharp), the inner ones smooth.
  const ContactSurface plate = testing::add_plate(w, 2, 2, 0, 0, 2, 2, 0, true, 1.0);
  const auto sharp = sharp_edges(plate, w.x, w.y, w.z, 20.0);
  // Facet 0 (lower left) has free edges 0 (eta=-1) and 3 (xi=-1).
  EXPECT_EQ(sharp[0], 1 | 8);
  EXPECT_EQ(sharp[3], 2 | 4);
  // Bend the plate along x = 1 by 30 degrees: the fold is sharp at 20, smooth at 40.
  for (std::size_t i = 0; i < w.x.size(); ++i)
    if (w.x[i] > 1.5) w.z[i] = std::tan(30.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(sharp_edges(plate, w.x, w.y, w.z, 20.0)[0], 1 | 2 | 8);
  EXPECT_EQ(sharp_edges(plate, w.x, w.y, w.z, 40.0)[0], 1 | 8);
}

TEST(SharpEdges, AShellsTwoSidesDoNotMakeItsEdgesSharp) {
  testing::World w;
  const ContactSurface facets = testing::add_plate(w, 2, 2, 0, 0, 2, 2, 0, true, 1.0);
  ContactSurface shells;
  for (const auto& f : facets.facets) shells.add_shell(f, 1, 1.0, 0.1);
  ASSERT_EQ(shells.size(), 8u);
  EXPECT_EQ(shells.twin[0], 1);
  EXPECT_EQ(shells.twin[1], 0);
  std::vector<std::uint8_t> free;
  auto sharp = sharp_edges(shells, w.x, w.y, w.z, 20.0, &free);
  // Shell 0 (lower left): top facet 0 as the plain plate; its bottom facet 1 runs the nodes
  // backwards (n4, n3, n2, n1), so the free edges eta = -1 and xi = -1 are its edges 2 and 3.
  EXPECT_EQ(sharp[0], 1 | 8);
  EXPECT_EQ(sharp[1], 4 | 8);
  EXPECT_EQ(free[0], 1 | 8);
  EXPECT_EQ(free[1], 4 | 8);
  for (std::size_t i = 0; i < w.x.size(); ++i)
    if (w.x[i] > 1.5) w.z[i] = std::tan(30.0 * std::numbers::pi / 180.0);
  sharp = sharp_edges(shells, w.x, w.y, w.z, 20.0, &free);
  EXPECT_EQ(sharp[0], 1 | 2 | 8);  // the fold, on both sides
  EXPECT_EQ(sharp[1], 2 | 4 | 8);
  EXPECT_EQ(free[0], 1 | 8);  // a fold is no free edge
}

}  // namespace
}  // namespace abut
