// A rigid part moved by *BC_MOTION has the velocity and kinetic energy of its prescription at
// every output, including at the end time after a shortened last step (issue 28).
//
// Two rigid 1 kg cubes start at rest and follow v(t) = -a t, one by its displacement
// u(t) = -a t^2 / 2 (D) and one by its velocity (V); gravity pulls both along +x, so the
// prescription has to override a force. Only rigid parts: the step is dt_max = 0.03 s and the
// end time 0.1 s leaves a last step of 0.01 s. Closed form at every t: v = -a t for each cube
// (the derivative of the prescribed u), kinetic energy (1/2) M v^2 each, M (a t)^2 in all.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

constexpr double kA = 25.0;    // m/s^2
constexpr double kMass = 1.0;  // 1000 kg/m^3 times (0.1 m)^3

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
0.1, 0.9, 0, 0.03
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 0.1, 0.1, 0.1
*COMPONENT_BOX
2, 2, 1, 1, 1
0.0, 0.5, 0.0, 0.1, 0.6, 0.1
*MAT_RIGID
1, 1000.0
*PART
"displaced"
1, 1
"driven"
2, 1
*FUNCTION
1
-12.5 * t * t
*FUNCTION
2
-25.0 * t
*CURVE
3
0.0, 9.81
1.0, 9.81
*LOAD_GRAVITY
X, 3
*BC_MOTION
P, 1, YZ, XYZ
D, X, 1
*BC_MOTION
P, 2, YZ, XYZ
V, X, 2
*END
)";

TEST(RigidPrescribedMotion, VelocityAndKineticEnergyAreExactAtEveryOutput) {
  const Model model = read_deck_string(kDeck, "rigid_prescribed.k");
  Simulation sim(model);
  double worst_velocity = 0.0, worst_kinetic = 0.0, last_step = 0.0;
  const auto record = [&](const Simulation& s) {
    const double v = -kA * s.time(), kinetic = 0.5 * kMass * v * v;
    for (const PartState& p : s.part_states()) {
      worst_velocity = std::max(worst_velocity, std::abs(p.velocity.x - v));
      worst_kinetic = std::max(worst_kinetic, std::abs(p.kinetic - kinetic));
    }
    worst_kinetic = std::max(worst_kinetic, std::abs(s.energies().kinetic - 2.0 * kinetic));
    EXPECT_GE(s.energies().kinetic, 0.0) << "t = " << s.time();
  };
  record(sim);
  while (!sim.finished()) {
    const double before = sim.time();
    sim.advance();
    last_step = sim.time() - before;
    record(sim);
  }
  const double v_end = kA * 0.1;
  std::cout << "prescribed rigid motion: last step " << last_step << " s; worst |v - (-a t)| "
            << worst_velocity << " m/s, worst kinetic energy error " << worst_kinetic
            << " J; at the end v = " << sim.part_states()[0].velocity.x << ", "
            << sim.part_states()[1].velocity.x << " m/s, kinetic " << sim.energies().kinetic
            << " J\n";
  EXPECT_NEAR(sim.time(), 0.1, 1e-15);
  EXPECT_NEAR(last_step, 0.01, 1e-12);  // shortened: the step is 0.03 s
  EXPECT_LT(worst_velocity, 1e-12 * v_end);
  EXPECT_LT(worst_kinetic, 1e-12 * kMass * v_end * v_end);
}

}  // namespace
}  // namespace abut
