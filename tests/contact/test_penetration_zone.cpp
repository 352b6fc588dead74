// outside_penetration_zone (penetration_zone.hpp): a point it declares outside must not be a
// penetrating partner of the facet for the narrow phase itself (find_partner), on random warped
// and turned facets with random gaps, depths, edge rules and points all around. The band must
// also be of use: on a flat or slightly warped facet it lets through points just above it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "abut/contact/narrow_phase.hpp"
#include "abut/contact/penetration_zone.hpp"

namespace abut {
namespace {

struct OneFacet {
  std::vector<std::array<std::int32_t, 4>> nodes{{0, 1, 2, 3}};
  std::vector<std::uint8_t> sharp{0}, active{1}, free_edges{0};
  std::vector<double> depth{0.0}, gap{0.0}, min_edge{1.0};
  std::vector<std::int32_t> twin{-1};
  std::vector<double> x = std::vector<double>(4), y = x, z = x;
  TargetFacets view() const {
    return {nodes, sharp, active, depth, twin, free_edges, gap, min_edge, x, y, z};
  }
  void set(const QuadCorners& c) {
    for (int a = 0; a < 4; ++a) x[a] = c[a].x, y[a] = c[a].y, z[a] = c[a].z;
  }
};

bool penetrates(const OneFacet& facet, const Vec3& x, const PartnerRules& rules) {
  const std::int32_t candidate = 0;
  const Partner p = find_partner(facet.view(), {&candidate, 1}, {9, 9, 9, 9}, x, {}, rules);
  return p.facet >= 0 && p.gap < 0.0;
}

Vec3 random_in_ball(std::mt19937& rng, double radius) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    const Vec3 v{u(rng), u(rng), u(rng)};
    if (dot(v, v) <= 1.0) return v * radius;
  }
}

// Rotation of v about the unit axis k by angle t (Rodrigues).
Vec3 turn(const Vec3& v, const Vec3& k, double t) {
  return v * std::cos(t) + cross(k, v) * std::sin(t) + k * (dot(k, v) * (1.0 - std::cos(t)));
}

// A facet of size 0.5 to 1.5, its corners moved by up to `warp` of its size, turned at random,
// with random depth, gaps, sharp edges, edge tolerance and smooth-edge reach.
struct Case {
  double size = 0.0;
  QuadCorners corners;
  OneFacet facet;
  PartnerRules rules;
};
Case random_case(std::mt19937& rng, double warp) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Case k;
  k.size = 0.5 + u(rng);
  const double size = k.size;
  QuadCorners& c = k.corners;
  c = {Vec3{0, 0, 0}, Vec3{size, 0, 0}, Vec3{size, size, 0}, Vec3{0, size, 0}};
  for (auto& corner : c) corner = corner + random_in_ball(rng, warp * size);
  const Vec3 axis = normalized(random_in_ball(rng, 1.0) + Vec3{0, 0, 1e-3});
  const double angle = u(rng) * std::numbers::pi;
  for (auto& corner : c) corner = turn(corner, axis, angle);
  k.facet.set(c);
  k.facet.depth[0] = size * (0.1 + 0.6 * u(rng));
  k.facet.gap[0] = u(rng) < 0.5 ? 0.0 : 0.05 * size * u(rng);
  k.facet.sharp[0] = u(rng) < 0.5 ? 0 : 0xF;
  k.rules.point_gap = u(rng) < 0.5 ? 0.0 : 0.05 * size * u(rng);
  k.rules.edge_tolerance = 0.1 * size * u(rng);
  k.rules.smooth_reach = std::tan(1.2 * u(rng));
  // A shell's free border (Radioss Ishape): cut, square or round, for shell facets only.
  const double shape = u(rng);
  k.rules.border = shape < 1.0 / 3.0   ? GapSettings::Border::Cut
                   : shape < 2.0 / 3.0 ? GapSettings::Border::Square
                                       : GapSettings::Border::Round;
  return k;
}

// A point within `radius` facet sizes of the facet's centre.
Vec3 point_near(const Case& k, std::mt19937& rng, double radius) {
  const QuadCorners& c = k.corners;
  return (c[0] + c[1] + c[2] + c[3]) * 0.25 + random_in_ball(rng, radius * k.size);
}

TEST(PenetrationZone, APointOutsideIsNeverAPenetratingPartner) {
  std::mt19937 rng(2026);
  int outside = 0, inside = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    Case k = random_case(rng, trial % 2 ? 0.02 : 0.2);
    if (trial % 4 == 0) {  // a side of a shell with free edges (the Ishape rules act there)
      k.facet.twin[0] = 0;
      k.facet.free_edges[0] = 0xF;
    }
    const QuadCorners& c = k.corners;
    const OneFacet& facet = k.facet;
    const PartnerRules& rules = k.rules;
    const PairReach pr = pair_reach(facet.view(), 0, rules);
    const Vec3 x = point_near(k, rng, 1.5);  // above, below, beside, within reach or not
    if (!outside_penetration_zone(c, x, pr.gap, pr.below, pr.reach)) {
      ++inside;
      continue;
    }
    ++outside;
    EXPECT_FALSE(penetrates(facet, x, rules)) << "trial " << trial;
  }
  // Not vacuous: both outcomes are frequent.
  EXPECT_GT(outside, 50000);
  EXPECT_GT(inside, 20000);
}

// surely_behind: every point it puts behind the facet, anywhere around it, projects onto the
// facet with a negative gap.
TEST(PenetrationZone, APointSurelyBehindProjectsBehindTheFacet) {
  std::mt19937 rng(7);
  int behind = 0, not_behind = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const Case k = random_case(rng, trial % 2 ? 0.02 : 0.2);
    const QuadCorners& c = k.corners;
    const Vec3 x = point_near(k, rng, 1.5);
    if (!surely_behind(facet_band(c), x)) {
      ++not_behind;
      continue;
    }
    ++behind;
    EXPECT_LT(project_onto_quad(c, x).gap, 0.0) << "trial " << trial;
  }
  EXPECT_GT(behind, 30000);
  EXPECT_GT(not_behind, 30000);
}

// The narrow phase with this step's bands (box and facing tests before the projection) finds the
// same partner as without them, for random facets, points, point normals and contact senses.
TEST(PenetrationZone, BandsLeaveTheNarrowPhaseUnchanged) {
  std::mt19937 rng(11);
  int found = 0, facing_away = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    Case k = random_case(rng, trial % 2 ? 0.02 : 0.2);
    const QuadCorners& c = k.corners;
    const OneFacet& facet = k.facet;
    k.rules.from_behind = trial % 3 == 0;
    if (trial % 5 < 2) {  // a side of a shell, its edges free (rounded) or shared
      k.facet.twin[0] = 0;
      k.facet.free_edges[0] = trial % 5 == 0 ? 0xF : 0;
    }
    const PartnerRules& rules = k.rules;
    const Vec3 x = point_near(k, rng, 0.8);
    // Point normals near the facet's own (facing away from it) and anywhere.
    const Vec3 own = normalized(cross(c[2] - c[0], c[3] - c[1]));
    const Vec3 n =
        normalized(trial % 2 ? own + random_in_ball(rng, 0.3) : random_in_ball(rng, 1.0));
    const std::int32_t candidate = 0;
    const Partner plain = find_partner(facet.view(), {&candidate, 1}, {9, 9, 9, 9}, x, n, rules);
    const std::vector<FacetBand> bands{facet_band(c)};
    TargetFacets banded = facet.view();
    banded.bands = bands;
    const Partner with = find_partner(banded, {&candidate, 1}, {9, 9, 9, 9}, x, n, rules);
    ASSERT_EQ(plain.facet, with.facet) << "trial " << trial;
    if (plain.facet < 0) {
      facing_away += dot(n, own) > 0.5;
      continue;
    }
    ++found;
    EXPECT_EQ(plain.xi, with.xi);
    EXPECT_EQ(plain.eta, with.eta);
    EXPECT_EQ(plain.gap, with.gap);
  }
  EXPECT_GT(found, 5000);
  EXPECT_GT(facing_away, 5000);
}

// Of use where it matters: a point 0.5 mm above a flat 1 cm facet of a solid whose detection
// depth, 5 mm, puts it within the narrow phase's reach is outside; 0.5 mm below it is inside.
// With the corners warped by 0.1 mm, a point 2 mm above is still outside.
TEST(PenetrationZone, LetsThroughPointsJustAboveAFacet) {
  QuadCorners c = {Vec3{0, 0, 0}, Vec3{0.01, 0, 0}, Vec3{0.01, 0.01, 0}, Vec3{0, 0.01, 0}};
  EXPECT_TRUE(outside_penetration_zone(c, {0.005, 0.005, 5e-4}, 0.0, 0.005, 0.005));
  EXPECT_FALSE(outside_penetration_zone(c, {0.005, 0.005, -5e-4}, 0.0, 0.005, 0.005));
  EXPECT_FALSE(outside_penetration_zone(c, {0.005, 0.005, 0.0}, 0.0, 0.005, 0.005));  // touching
  // A shell pair's gap of 1 mm: 0.5 mm above the mid-surface is inside.
  EXPECT_FALSE(outside_penetration_zone(c, {0.005, 0.005, 5e-4}, 0.001, 0.005, 0.006));
  c[0].z = c[2].z = 1e-4;
  EXPECT_TRUE(outside_penetration_zone(c, {0.005, 0.005, 0.002}, 0.0, 0.005, 0.005));
}

}  // namespace
}  // namespace abut
