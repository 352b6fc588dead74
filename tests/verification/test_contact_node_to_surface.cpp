// Node-to-surface against surface-to-surface contact on a matched mesh (issue 7): an elastic block
// held at its top and pressed slowly (0.5 m/s, 40 wave transits over the run) by a rigid plate
// whose facets coincide with the block's bottom facets; the plate reaches one element beyond the
// block. With a penetration bilinear over each facet the nodal (trapezoidal) and the 2x2 Gauss
// integration of the penalty pressure agree exactly, so both discretisations must give the same
// total force history. Reference: the S2S run of the same model (itself verified against 2L/c
// and Hertz); tolerance 2% of the peak force at every cycle. Both runs take the same fixed step
// (dt_max), so they are compared cycle by cycle, and both are one-way, the block's points on the
// plate: a plate node under the block's border would otherwise carry the whole tributary area of
// a plate node, partly outside the block.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

std::string block_on_plate(const std::string& method, const std::string& nodes_entity) {
  return R"(
*UNIT_SYSTEM
SI
*TIME
2.0e-4, 0.9, 0.0, 5.0e-7
*COMPONENT_BOX
1, 1, 4, 4, 2
0.0, 0.0, 0.0, 0.04, 0.04, 0.02
*COMPONENT_BOX
2, 2, 6, 6, 1
-0.01, -0.01, -0.01, 0.05, 0.05, 0.0
*SET_NODE
9
51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63
64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75
*SET_PART
1
1
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*MAT_RIGID
2, 7800.0
*PART
"block"
1, 1
"plate"
2, 2
*BC_MOTION
NS, 9, XYZ
*BC_MOTION
P, 2, XY, XYZ
V, Z, 1
*CURVE
1
0.0, 0.5
1.0, 0.5
*CONTACT
"block on plate"
1
)" + nodes_entity +
         R"(, P, 2, 0.0, 2.0e13
0, 0.0
, , , , 1
*CONTACT_DISCRETIZATION
1, )" + method +
         R"(
*END
)";
}

std::vector<double> force_history(const std::string& deck) {
  const Model model = read_deck_string(deck, "block_on_plate.k");
  Simulation sim(model);
  std::vector<double> force;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    force.push_back(s.contact_reports()[0].stats.force.z);
  });
  return force;
}

TEST(ContactNodeToSurface, SameForceHistoryAsSurfaceToSurfaceOnAMatchedMesh) {
  const std::vector<double> s2s = force_history(block_on_plate("S2S", "P, 1"));
  for (const std::string entity : {"P, 1", "PS, 1"}) {
    const std::vector<double> n2s = force_history(block_on_plate("N2S", entity));
    ASSERT_EQ(n2s.size(), s2s.size());  // same stable step: same cycles
    double peak = 0.0, worst = 0.0;
    for (double f : s2s) peak = std::max(peak, std::abs(f));
    for (std::size_t k = 0; k < s2s.size(); ++k) worst = std::max(worst, std::abs(n2s[k] - s2s[k]));
    std::cout << "N2S (" << entity << ") vs S2S: peak force " << peak << " N, largest difference "
              << 100.0 * worst / peak << "% of the peak over " << s2s.size() << " cycles\n";
    ASSERT_GT(peak, 0.0);
    EXPECT_LT(worst, 0.02 * peak);
  }
}

// A node group (entype NS) is a secondary side of its own: its nodes, one-way, against the plate.
// The block's bottom nodes as a node set carry the block like the nodes of its whole surface.
// (Both one-way: only the block's nodes act.)
TEST(ContactNodeToSurface, NodeSetCarriesTheBlockLikeItsSurface) {
  std::string deck = block_on_plate("N2S", "NS, 7");
  // The bottom layer of the block: the 5 x 5 nodes at z = 0 (generator order: x fastest).
  std::string set = "*SET_NODE\n7\n";
  for (int k = 1; k <= 25; ++k) set += std::to_string(k) + (k % 8 == 0 || k == 25 ? "\n" : ", ");
  deck.insert(deck.find("*CONTACT\n"), set);
  const Model model = read_deck_string(deck, "node_set.k");
  const NodeSet& bottom = model.node_sets.at(1);
  ASSERT_EQ(bottom.id, 7);
  ASSERT_EQ(bottom.nodes.size(), 25u);
  for (auto i : bottom.nodes) ASSERT_NEAR(model.mesh.nodes.z[i], 0.0, 1e-12);
  const std::vector<double> surface = force_history(block_on_plate("N2S", "P, 1"));
  Simulation sim(model);
  double peak = 0.0, worst = 0.0;
  std::size_t k = 0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double f = s.contact_reports()[0].stats.force.z;
    if (k < surface.size()) {
      peak = std::max(peak, std::abs(surface[k]));
      worst = std::max(worst, std::abs(f - surface[k]));
    }
    ++k;
  });
  std::cout << "N2S node set vs block surface: largest difference " << 100.0 * worst / peak
            << "% of the peak\n";
  EXPECT_LT(worst, 0.02 * peak);
}

}  // namespace
}  // namespace abut
