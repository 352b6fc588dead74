// Radioss Ishape (seed 004, /INTER/TYPE25, comment 4): at a shell surface's free border "the gap
// never extends more than the secondary node gap out of the surface external border"; Ishape 1
// makes that gap square (the push along the facet's normal), Ishape 2 round. abut's reading
// (GapSettings::Border): the facet's slab of half thickness g_m ends square at the border and the
// point's own gap g_s widens it by a cube (square) or a ball (round) of radius g_s.
//
// One side of a shell: the unit square at z = 0, its four edges free, g_m = 0.05; a point with
// g_s = 0.03, so the pair's gap is g = 0.08. Closed-form gaps, chosen before the run:
//  - above the facet at height 0.07: gap 0.07 - 0.08 = -0.01 whatever the rule;
//  - 0.02 beyond the border, at height 0.07: cut: no partner (0.02 is more than kOnBorder of the
//    facet's diagonal, 0.0141); square: -0.01 along +z; round: the slab's edge is at height 0.05,
//    distance sqrt(0.02^2 + 0.02^2) = 0.028284, gap 0.028284 - 0.03 = -0.0017157 along (1, 0,
//    1)/sqrt 2;
//  - 0.02 beyond, at height 0.04 (beside the slab's end): square -0.04, round 0.02 - 0.03 = -0.01
//    along +x;
//  - 0.04 beyond (more than g_s): no partner for either rule.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "abut/contact/narrow_phase.hpp"

namespace abut {
namespace {

struct ShellSide {
  std::vector<std::array<std::int32_t, 4>> nodes{{0, 1, 2, 3}};
  std::vector<std::uint8_t> sharp{0}, active{1}, free_edges{0xF};
  std::vector<double> depth{0.1}, gap{0.05}, min_edge{1.0};
  std::vector<std::int32_t> twin{0};  // a shell's side (its twin's index is not used here)
  std::vector<double> x{0.0, 1.0, 1.0, 0.0}, y{0.0, 0.0, 1.0, 1.0}, z{0.0, 0.0, 0.0, 0.0};
  TargetFacets view() const {
    return {nodes, sharp, active, depth, twin, free_edges, gap, min_edge, x, y, z};
  }
};

Partner partner_of(const Vec3& x, GapSettings::Border border) {
  const ShellSide facet;
  PartnerRules rules;
  rules.point_gap = 0.03;
  rules.point_depth = 0.1;
  rules.border = border;
  const std::int32_t candidate = 0;
  // A bare node (no normal of its own), as a node-to-surface point.
  return find_partner(facet.view(), {&candidate, 1}, {9, 9, 9, 9}, x, {}, rules);
}

constexpr double kTol = 1e-12;
using Border = GapSettings::Border;

TEST(ShellBorderGap, OnTheFacetEveryRuleGivesThePairsGap) {
  for (const Border b : {Border::Cut, Border::Square, Border::Round}) {
    const Partner p = partner_of({0.9, 0.5, 0.07}, b);
    ASSERT_EQ(p.facet, 0);
    EXPECT_NEAR(p.gap, -0.01, kTol);
    EXPECT_NEAR(p.normal.z, 1.0, kTol);
  }
}

TEST(ShellBorderGap, CutEndsTheSurfaceAtTheBorder) {
  EXPECT_EQ(partner_of({1.02, 0.5, 0.07}, Border::Cut).facet, -1);
}

TEST(ShellBorderGap, SquareReachesTheNodesGapBeyondTheBorderAlongTheNormal) {
  Partner p = partner_of({1.02, 0.5, 0.07}, Border::Square);
  ASSERT_EQ(p.facet, 0);
  EXPECT_NEAR(p.gap, -0.01, kTol);
  EXPECT_NEAR(p.normal.z, 1.0, kTol);
  p = partner_of({1.02, 0.5, 0.04}, Border::Square);
  ASSERT_EQ(p.facet, 0);
  EXPECT_NEAR(p.gap, -0.04, kTol);
  EXPECT_EQ(partner_of({1.04, 0.5, 0.07}, Border::Square).facet, -1);
  EXPECT_EQ(partner_of({0.5, -0.04, 0.07}, Border::Square).facet, -1);
}

TEST(ShellBorderGap, RoundPushesAwayFromTheSlabsEdge) {
  Partner p = partner_of({1.02, 0.5, 0.07}, Border::Round);
  ASSERT_EQ(p.facet, 0);
  EXPECT_NEAR(p.gap, std::sqrt(2.0) * 0.02 - 0.03, kTol);
  EXPECT_NEAR(p.normal.x, 1.0 / std::sqrt(2.0), kTol);
  EXPECT_NEAR(p.normal.z, 1.0 / std::sqrt(2.0), kTol);
  p = partner_of({1.02, 0.5, 0.04}, Border::Round);
  ASSERT_EQ(p.facet, 0);
  EXPECT_NEAR(p.gap, -0.01, kTol);
  EXPECT_NEAR(p.normal.x, 1.0, kTol);
  // Across the border edge y = 0 as well.
  p = partner_of({0.5, -0.02, 0.04}, Border::Round);
  ASSERT_EQ(p.facet, 0);
  EXPECT_NEAR(p.normal.y, -1.0, kTol);
  EXPECT_EQ(partner_of({1.04, 0.5, 0.05}, Border::Round).facet, -1);
}

// The round gap is continuous across the border: just beyond it, it equals the facet's gap.
TEST(ShellBorderGap, RoundIsContinuousAtTheBorder) {
  for (const double height : {0.06, 0.07, 0.075}) {
    const Partner inside = partner_of({1.0 - 1e-9, 0.5, height}, Border::Round);
    const Partner beyond = partner_of({1.0 + 1e-6, 0.5, height}, Border::Round);
    ASSERT_EQ(inside.facet, 0);
    ASSERT_EQ(beyond.facet, 0);
    EXPECT_NEAR(beyond.gap, inside.gap, 1e-6);
    EXPECT_NEAR(inside.gap, height - 0.08, kTol);
  }
}

}  // namespace
}  // namespace abut
