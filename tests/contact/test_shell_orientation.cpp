// OptiStruct MORIENT OVERLAP (seed 003; shell_orientation.hpp): which way each shell facet pushes,
// from the secondary nodes that lie through it at the start.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "abut/contact/shell_orientation.hpp"

namespace abut {
namespace {

// A strip of three unit facets along x at z = 0, normals +z (nodes counter-clockwise seen from
// +z), nodes 0-7; secondary nodes from 8 on.
struct Strip {
  std::vector<double> x, y, z;
  std::vector<std::array<std::int32_t, 4>> facets;
  std::vector<std::int32_t> secondary;
  Strip() {
    for (std::int32_t row = 0; row < 2; ++row)
      for (std::int32_t i = 0; i < 4; ++i) x.push_back(i), y.push_back(row), z.push_back(0.0);
    for (std::int32_t i = 0; i < 3; ++i) facets.push_back({i, i + 1, i + 5, i + 4});
  }
  void node(double px, double py, double pz) {
    secondary.push_back(static_cast<std::int32_t>(x.size()));
    x.push_back(px), y.push_back(py), z.push_back(pz);
  }
  std::vector<std::uint8_t> reversed() const {
    return overlap_push_reversed(facets, x, y, z, secondary);
  }
};

TEST(OverlapOrientation, NodesThroughTheFacetFromItsNormalSideArePushedBack) {
  Strip s;
  s.node(0.5, 0.5, 0.01);  // over facet 0, on the side of its normal
  EXPECT_EQ(s.reversed(), (std::vector<std::uint8_t>{1, 1, 1}));  // the others follow facet 0
  Strip t;
  t.node(0.5, 0.5, -0.01);  // behind facet 0
  EXPECT_EQ(t.reversed(), (std::vector<std::uint8_t>{0, 0, 0}));
}

TEST(OverlapOrientation, TheNearestNodeOnTheFacetDecides) {
  Strip s;
  s.node(0.5, 0.5, 0.01);    // facet 0: near, in front
  s.node(0.5, 0.5, -0.5);    // facet 0: far, behind (the body's other side)
  s.node(2.5, 0.5, -0.02);   // facet 2: behind
  s.node(1.5, 5.0, -0.001);  // projects beyond facet 1's border: decides nothing
  EXPECT_EQ(s.reversed(), (std::vector<std::uint8_t>{1, 1, 0}));  // facet 1: first reached from 0
}

TEST(OverlapOrientation, AFlippedNeighbourPushesTheSameWayInSpace) {
  Strip s;
  s.facets[1] = {1, 5, 6, 2};  // normal -z
  s.node(0.5, 0.5, 0.01);
  EXPECT_EQ(s.reversed(), (std::vector<std::uint8_t>{1, 0, 1}));  // every push -z
}

TEST(OverlapOrientation, APatchThatSeesNoNodePushesAlongItsNormals) {
  Strip s;
  s.node(10.0, 0.5, 0.01);
  EXPECT_EQ(s.reversed(), (std::vector<std::uint8_t>{0, 0, 0}));
}

}  // namespace
}  // namespace abut
