// The static contact of the contact library alone (static_contact.hpp): a node above a square
// facet, with the initial-gap treatments the static solver takes from OptiStruct (CLEARANCE),
// Radioss (Inacti = 5, -1) and seed 000 (delta0_offset, delta0_max), and OptiStruct's STICK. The
// references are the definitions of those options (docs/deck-reference.md, *CONTACT_NORMAL and
// *CONTACT_INITIAL): the pressure is k times the penetration that the option leaves.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "abut/contact/static_contact.hpp"

namespace abut {
namespace {

constexpr double kPenalty = 1000.0;

// Nodes 0-3: the main facet [-1, 1]^2 at z = 0 (normal +z). Node 4: the secondary node at
// (0, 0, z0), with nodes 5-7 its facet (0.2 x 0.2, facing -z) for its tributary area 0.01.
struct NodeOnFacet {
  std::vector<double> x{-1, 1, 1, -1, 0, 0, 0.2, 0.2}, y{-1, -1, 1, 1, 0, 0.2, 0.2, 0},
      z{0, 0, 0, 0, 0, 0, 0, 0};
  StaticContact contact;

  static StaticContact make(StaticContactSettings s, double z0, NodeOnFacet& self) {
    for (int n = 4; n < 8; ++n) self.z[n] = z0;
    ContactSurface main, secondary;
    main.add({0, 1, 2, 3}, 1, 0.0, 1.0);
    secondary.add({4, 5, 6, 7}, 2, 0.0, 1.0);
    s.node_to_surface = true;
    s.penalty = kPenalty;
    s.depth = 0.5;
    s.search_distance = 0.5;
    const std::vector<std::int32_t> nodes{4};
    return StaticContact(s, secondary, main, nodes, {self.x, self.y, self.z, {}, {}, {}, 0, 0, {}});
  }
  NodeOnFacet(const StaticContactSettings& s, double z0) : contact(make(s, z0, *this)) {}

  // Moves the secondary facet to height z (and node 4 sideways by dx); the pressure of node 4.
  const StaticContactPoint& at(double z_now, double dx = 0.0) {
    for (int n = 4; n < 8; ++n) z[n] = z_now;
    x[4] = dx;
    contact.evaluate({x, y, z, {}, {}, {}, 0, 0, {}});
    return contact.points()[0];
  }
};

TEST(StaticContactInitial, ForcePushesWithTheWholeInitialPenetration) {
  NodeOnFacet c({}, -0.02);  // InitialPenetration::Force is the default (CalculiX)
  EXPECT_NEAR(c.at(-0.02).pressure, kPenalty * 0.02, 1e-12);
  EXPECT_NEAR(c.contact.points()[0].area, 0.01, 1e-12);
}

// OptiStruct CLEARANCE: the opening at the start is the clearance, whatever the distance.
TEST(StaticContactInitial, ClearanceReplacesTheInitialGap) {
  StaticContactSettings s;
  s.clearance = 0.0;
  NodeOnFacet c(s, 0.1);  // 0.1 apart, but touching by the clearance
  EXPECT_TRUE(c.at(0.1).active);
  EXPECT_EQ(c.at(0.1).pressure, 0.0);
  EXPECT_NEAR(c.at(0.09).pressure, kPenalty * 0.01, 1e-12);
  StaticContactSettings interference;
  interference.clearance = -0.005;  // negative: an interference fit
  NodeOnFacet d(interference, 0.1);
  EXPECT_NEAR(d.at(0.1).pressure, kPenalty * 0.005, 1e-12);
  EXPECT_NEAR(d.at(0.1).gap, -0.005, 1e-12);
}

// Radioss Inacti = 5: the initial penetration is subtracted until the point separates.
TEST(StaticContactInitial, ShiftHoldsUntilTheFirstSeparation) {
  StaticContactSettings s;
  s.initial_penetration = InitialPenetration::Shift;
  NodeOnFacet c(s, -0.02);
  EXPECT_EQ(c.at(-0.02).pressure, 0.0);
  EXPECT_NEAR(c.at(-0.03).pressure, kPenalty * 0.01, 1e-12);
  c.at(0.05);  // separated, and accepted as converged
  c.contact.commit();
  EXPECT_NEAR(c.at(-0.03).pressure, kPenalty * 0.03, 1e-12);
}

// Seed 000: subtracted up to delta0_offset; released for good beyond delta0_max.
TEST(StaticContactInitial, OffsetSubtractsUpToItsValueAndReleasesDeepPoints) {
  StaticContactSettings s;
  s.initial_penetration = InitialPenetration::Offset;
  s.initial_offset = 0.002;
  s.initial_max = 0.01;
  NodeOnFacet shallow(s, -0.005);
  EXPECT_NEAR(shallow.at(-0.005).pressure, kPenalty * 0.003, 1e-12);
  NodeOnFacet deep(s, -0.02);
  EXPECT_FALSE(deep.at(-0.02).active);
  EXPECT_FALSE(deep.at(-0.05).active);
}

// OptiStruct STICK: no sliding while closed, however large the tangential force; may open.
TEST(StaticContactInitial, StickNeverSlides) {
  StaticContactSettings s;
  s.stick = true;
  s.stick_slope = 500.0;
  NodeOnFacet c(s, 0.0);
  c.at(0.0);
  c.contact.commit();
  const StaticContactPoint& p = c.at(-0.001, 0.3);  // slides 0.3 under a tiny pressure
  EXPECT_FALSE(p.slipping);
  EXPECT_NEAR(p.traction.x, -500.0 * 0.3, 1e-9);
  EXPECT_TRUE(c.contact.symmetric());
  EXPECT_FALSE(c.at(0.01, 0.3).active);  // opens
}

}  // namespace
}  // namespace abut
