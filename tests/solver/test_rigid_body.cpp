// Rigid parts (*MAT_RIGID): torque-free rotation about a principal axis keeps the kinetic energy
// and turns the body rigidly (Euler's equations with omega along a principal axis: omega stays
// constant; e.g. Goldstein, Classical Mechanics, ch. 5); a prescribed velocity moves it exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

std::size_t nearest(const Model& m, double x, double y, double z) {
  std::size_t best = 0;
  double d_best = 1e300;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    const double d =
        std::hypot(m.mesh.nodes.x[i] - x, m.mesh.nodes.y[i] - y, m.mesh.nodes.z[i] - z);
    if (d < d_best) {
      d_best = d;
      best = i;
    }
  }
  return best;
}

TEST(RigidBody, TorqueFreeRotationAboutAPrincipalAxis) {
  // A quarter turn at 10 rad/s about z takes pi/20 s; the step comes from dt_max (no elements
  // of a rigid part limit it).
  const Model model = read_deck_string(R"(
*TIME
[3.141592653589793 / 20.0], 0.9, 0, 1.0e-4
*COMPONENT_BOX
1, 1, 2, 2, 2
-0.1, -0.1, -0.05, 0.1, 0.1, 0.05
*MAT_RIGID
1, 7800.0
*PART
1, 1
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, 0.0, 0.0, 0.0, 10.0
0.0, 0.0, 0.0
*END
)",
                                       "rigid_spin.k");
  Simulation sim(model);
  const double kinetic0 = sim.energies().kinetic;
  const std::size_t corner = nearest(model, 0.1, 0.1, 0.05);
  while (!sim.finished()) sim.advance();
  // The kinetic energy is the body's (1/2) omega . I omega at the end (issue 28), not that of the
  // nodes' secant velocities, which are short of omega r by the chord factor 1 - (omega dt)^2 / 24.
  EXPECT_NEAR(sim.energies().kinetic, kinetic0, 1e-12 * kinetic0);
  EXPECT_NEAR(sim.x()[corner], -0.1, 1e-9);
  EXPECT_NEAR(sim.y()[corner], 0.1, 1e-9);
  EXPECT_NEAR(sim.z()[corner], 0.05, 1e-12);
}

TEST(RigidBody, PrescribedVelocityMovesThePartExactly) {
  const Model model = read_deck_string(R"(
*TIME
0.01, 0.9, 0, 1.0e-4
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 0.1, 0.1, 0.1
*MAT_RIGID
1, 7800.0
*PART
1, 1
*CURVE
1
0.0, 2.0
1.0, 2.0
*BC_MOTION
P, 1, XY, XYZ
V, Z, 1
*END
)",
                                       "rigid_motion.k");
  Simulation sim(model);
  while (!sim.finished()) sim.advance();
  const std::size_t n = nearest(model, 0.1, 0.1, 0.1);
  EXPECT_NEAR(sim.z()[n], 0.1 + 2.0 * 0.01, 1e-12);
  EXPECT_NEAR(sim.x()[n], 0.1, 1e-15);
  EXPECT_NEAR(sim.part_states()[0].velocity.z, 2.0, 1e-12);
}

TEST(RigidBody, ANodeConstraintOnARigidPartIsAnError) {
  const Model model = read_deck_string(R"(
*TIME
0.01
*NODE
1, 0, 0, 0, XYZ
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT_SOLID
1, 1, 1, 2, 3, 4, 5, 6, 7, 8
*MAT_RIGID
1, 7800.0
*PART
1, 1
*END
)",
                                       "rigid_node_bc.k");
  EXPECT_THROW(Simulation sim(model), InputError);
}

}  // namespace
}  // namespace abut
