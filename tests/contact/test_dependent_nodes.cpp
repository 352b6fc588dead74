// Dependent nodes of the contact library (dependent_nodes.hpp): a facet corner that is a fixed
// combination of host nodes. Its position is that combination, and a weight on it becomes the
// same combination of weights on the host nodes, merged with those the element already has, so
// that the work of a force is the same either way (the map and its transpose).
#include <gtest/gtest.h>

#include <vector>

#include "abut/contact/dependent_nodes.hpp"

namespace abut {
namespace {

TEST(DependentNodes, PositionAndWeightsAreTheSameCombination) {
  DependentNodes d;
  d.first = 8;  // host nodes 0-7
  const std::int32_t nodes[] = {0, 1, 2};
  const double weights[] = {-0.25, 0.5, 0.75};
  EXPECT_EQ(d.add(nodes, weights), 8);
  const std::vector<double> x{1, 2, 4, 0, 0, 0, 0, 0}, y{0, 1, 0, 0, 0, 0, 0, 0},
      z{2, 2, 2, 0, 0, 0, 0, 0};
  std::vector<double> ex, ey, ez;
  d.extend(x, y, z, ex, ey, ez);
  ASSERT_EQ(ex.size(), 9u);
  EXPECT_DOUBLE_EQ(ex[8], -0.25 + 1.0 + 3.0);
  EXPECT_DOUBLE_EQ(ey[8], 0.5);
  EXPECT_DOUBLE_EQ(ez[8], 2.0);  // the weights sum to 1: a plane stays a plane

  ContactWeights w;
  w.add(1, 0.5);   // a host node the dependent node also depends on
  w.add(8, 0.4);   // the dependent node
  w.add(7, -1.0);  // another host node
  const ContactWeights e = d.expand(w);
  ASSERT_EQ(e.count, 4);
  std::vector<double> by_node(8, 0.0);
  for (int k = 0; k < e.count; ++k) by_node[static_cast<std::size_t>(e.nodes[k])] = e.weights[k];
  EXPECT_DOUBLE_EQ(by_node[0], -0.1);
  EXPECT_DOUBLE_EQ(by_node[1], 0.5 + 0.2);
  EXPECT_DOUBLE_EQ(by_node[2], 0.3);
  EXPECT_DOUBLE_EQ(by_node[7], -1.0);

  EXPECT_THROW(d.extend(std::vector<double>{1, 2}, y, z, ex, ey, ez), std::invalid_argument);
}

}  // namespace
}  // namespace abut
