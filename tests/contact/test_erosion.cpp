// ContactInterface::erode (issue 9): what element erosion does to a contact, on two unit facets
// pressed together by d (the flat-pair reference of test_interface.cpp: F = pfac A d).
//  - A facet of an eroded element leaves; its nodes, now free, stay as point masses with their
//    tributary areas (Abaqus/Explicit without nodal erosion, seed 001), so the same flat overlap
//    still carries pfac A d through the four nodes, or leave with keep_free_nodes off (nodal
//    erosion; Radioss Idel 1/2, seed 004).
//  - An internal face takes part only once the element on its other side has eroded (IMPETUS
//    no_internal = 0, seed 000).
#include <gtest/gtest.h>

#include "fixtures.hpp"

namespace abut {
namespace {

using testing::add_plate;
using testing::World;

constexpr double kPfac = 3e6, kDepth = 0.01;

struct PressedPair {
  World w;
  ContactSurface lower, upper;
  std::int32_t upper_first = 0;
  PressedPair() {
    lower = add_plate(w, 1, 1, 0, 0, 1, 1, 0.0, true, kPfac, 1.0, 1.0, 2);
    upper_first = static_cast<std::int32_t>(w.x.size());
    upper = add_plate(w, 1, 1, 0, 0, 1, 1, -kDepth, false, kPfac, 1.0, 1.0, 1);
  }
  double force_on_upper(ContactInterface& c) {
    w.clear_forces();
    ContactForces out = w.forces();
    c.apply(w.input(0.0, 1e-6), out);
    double f = 0.0;
    for (std::size_t i = static_cast<std::size_t>(upper_first); i < w.fz.size(); ++i) f += w.fz[i];
    return f;
  }
};

ContactSettings one_way(bool keep_free_nodes) {
  ContactSettings s;
  s.damping = 0.0;
  s.one_way = true;
  s.initial_penetration = InitialPenetration::Force;
  s.erosion.keep_free_nodes = keep_free_nodes;
  return s;
}

TEST(ContactErosion, FreeNodesStayAsPointMassesOrLeave) {
  for (const bool keep : {true, false}) {
    PressedPair pair;
    pair.upper.element = {0};  // the upper facet belongs to element 0
    ContactInterface c(one_way(keep), pair.upper, pair.lower, pair.w.mass, pair.w.input());
    EXPECT_NEAR(pair.force_on_upper(c), kPfac * kDepth, 1e-9 * kPfac * kDepth);
    const std::vector<std::uint8_t> eroded{1};
    c.erode(eroded);
    const double expected = keep ? kPfac * kDepth : 0.0;  // four nodes of a quarter area each
    EXPECT_NEAR(pair.force_on_upper(c), expected, 1e-9 * kPfac * kDepth) << "keep " << keep;
    EXPECT_EQ(c.point_count(), keep ? 4u + 4u : 4u);
  }
}

TEST(ContactErosion, InternalFaceJoinsWhenItsNeighbourErodes) {
  PressedPair pair;
  pair.lower.element = {1};
  pair.lower.exposed_by = {0};  // the top of element 1, under element 0
  ContactInterface c(one_way(true), pair.upper, pair.lower, pair.w.mass, pair.w.input());
  EXPECT_EQ(pair.force_on_upper(c), 0.0);
  c.erode(std::vector<std::uint8_t>{0, 0});
  EXPECT_EQ(pair.force_on_upper(c), 0.0);
  c.erode(std::vector<std::uint8_t>{1, 0});  // element 0 gone: the face is exposed
  EXPECT_NEAR(pair.force_on_upper(c), kPfac * kDepth, 1e-9 * kPfac * kDepth);
  c.erode(std::vector<std::uint8_t>{1, 1});  // and then its own element
  EXPECT_EQ(pair.force_on_upper(c), 0.0);
}

TEST(ContactErosion, KeptFacetsOfErodedElements) {
  PressedPair pair;
  pair.upper.element = {0};
  ContactSettings s = one_way(true);
  s.erosion.remove_facets = false;  // Radioss Idel 1000
  ContactInterface c(s, pair.upper, pair.lower, pair.w.mass, pair.w.input());
  c.erode(std::vector<std::uint8_t>{1});
  EXPECT_NEAR(pair.force_on_upper(c), kPfac * kDepth, 1e-9 * kPfac * kDepth);
  EXPECT_EQ(c.point_count(), 4u);
}

}  // namespace
}  // namespace abut
