// Block sliding on a plane with Coulomb friction under gravity (elementary mechanics, e.g.
// Meriam & Kraige, "Engineering Mechanics: Dynamics", ch. 3): the friction force mu m g
// decelerates the block uniformly, so from v0 it stops after t = v0 / (mu g) having slid
// d = v0^2 / (2 mu g), and static friction then holds it.
//
// Model: v0 = 1 m/s, mu = 0.5, g = 9.81 m/s^2 (*LOAD_GRAVITY Z with a curve of -9.81): 0.102 m
// in 0.204 s. Both bodies are *MAT_RIGID, so only the contact springs limit the step: a steel
// block 0.1 x 0.1 x 0.02 m (2 x 2 x 1 elements, 1.56 kg) starting in touch with a 0.5 x 0.2 m
// plane (10 x 4 elements) held by *BC_MOTION. pfac = 6.2e9 Pa/m gives the block a vertical
// frequency sqrt(pfac A / m) of about 1 kHz, far above the 5 Hz of the stopping time scale, and
// a static penetration m g / (pfac A) of 0.25 um; the run takes about 4000 cycles. The block
// starts with no normal force and settles under the default contact damping (xi = 0.1): the
// normal force oscillates about m g meanwhile, and so does the friction force mu F_n, whose
// mean is therefore mu m g from the start. Symmetric contact (the default): the plane's
// integration points that enter and leave the block's footprint while it slides are within
// the tolerance (measured error below 1e-5).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kV0 = 1.0, kMu = 0.5, kG = 9.81;

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
0.3
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, -0.05, 0.0, 0.1, 0.05, 0.02
*COMPONENT_BOX
2, 2, 10, 4, 1
-0.05, -0.1, -0.02, 0.45, 0.1, 0.0
*MAT_RIGID
1, 7800.0
*MAT_RIGID
2, 7800.0
*PART
"block"
1, 1
"plane"
2, 2
*INITIAL_VELOCITY
P, 1, 1.0, 0.0, 0.0
*BC_MOTION
P, 2, XYZ, XYZ
*CURVE
1
0.0, -9.81
1.0, -9.81
*LOAD_GRAVITY
Z, 1
*CONTACT
"block on plane"
1
P, 1, P, 2, 0.5, 6.2e9
*END
)";

TEST(ContactSlidingBlock, StopsAfterVSquaredOverTwoMuG) {
  const Model model = read_deck_string(kDeck, "sliding_block.k");
  Simulation sim(model);
  const double x0 = sim.part_states().at(0).centre_of_mass.x;
  double t_stop = -1.0, t_previous = sim.time(), v_previous = kV0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double v = s.part_states()[0].velocity.x;
    if (t_stop < 0.0 && v <= 0.0)
      t_stop = t_previous + (s.time() - t_previous) * v_previous / (v_previous - v);
    t_previous = s.time();
    v_previous = v;
  });
  const PartState block = sim.part_states()[0];
  const double distance = block.centre_of_mass.x - x0;
  const double expected_distance = kV0 * kV0 / (2.0 * kMu * kG), expected_time = kV0 / (kMu * kG);
  std::cout << "stopping distance " << distance << " m, v0^2/(2 mu g) = " << expected_distance
            << " m, error " << 100.0 * (distance - expected_distance) / expected_distance
            << "%; stopped at " << t_stop << " s, v0/(mu g) = " << expected_time << " s, error "
            << 100.0 * (t_stop - expected_time) / expected_time << "%; " << sim.cycle()
            << " cycles\n";
  EXPECT_NEAR(distance, expected_distance, 0.01 * expected_distance);
  ASSERT_GT(t_stop, 0.0);
  EXPECT_NEAR(t_stop, expected_time, 0.01 * expected_time);
  EXPECT_LT(std::abs(block.velocity.x), 1e-3 * kV0);  // held by static friction at the end
}

}  // namespace
}  // namespace abut
