// *BC_MOTION on solid nodes: a prescribed displacement curve is met exactly at every step
// (the velocity is chosen as the secant to the next target), and a fixed node never moves.
#include <gtest/gtest.h>

#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

TEST(BoundaryMotion, PrescribedDisplacementIsFollowedExactly) {
  const Model model = read_deck_string(R"(
*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 4, 1, 1
0.0, 0.0, 0.0, 0.1, 0.01, 0.01
*MAT_ELASTIC
1, 2700.0, 70.0e9, 0.33
*PART
1, 1
*GEOMETRY_BOX
1
-0.001, -1, -1, 0.001, 1, 1
*GEOMETRY_BOX
2
0.099, -1, -1, 0.101, 1, 1
*FUNCTION
1
1.0e-4 * sinr(1000.0 * t)
*BC_MOTION
G, 1, XYZ
*BC_MOTION
G, 2, YZ
D, X, 1
*END
)",
                                       "pull.k");
  Simulation sim(model);
  std::vector<std::size_t> end_nodes, fixed_nodes;
  for (std::size_t i = 0; i < model.mesh.nodes.size(); ++i) {
    if (model.mesh.nodes.x[i] > 0.099) end_nodes.push_back(i);
    if (model.mesh.nodes.x[i] < 0.001) fixed_nodes.push_back(i);
  }
  ASSERT_EQ(end_nodes.size(), 4u);
  while (!sim.finished()) {
    sim.advance();
    for (const std::size_t i : end_nodes)
      ASSERT_NEAR(sim.x()[i] - 0.1, 1.0e-4 * std::sin(1000.0 * sim.time()), 1e-15);
    for (const std::size_t i : fixed_nodes) ASSERT_EQ(sim.x()[i], 0.0);
  }
  // The reaction did work on the bar: it went into the bar's kinetic and strain energy.
  EXPECT_GT(sim.energies().external_work, 0.0);
  EXPECT_LT(std::abs(sim.energy_balance_error()), 0.02);
}

}  // namespace
}  // namespace abut
