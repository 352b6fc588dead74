// *CONTACT t_beg / t_end (seed 000): the contact acts only between t_beg and t_end.
//
// Model: a rigid block (1.56 kg) resting on a rigid plate under gravity (-9.81 m/s^2 along z),
// contact window [10 ms, 30 ms]. Before t_beg the block must fall freely through the plate's
// surface (v_z = -g t exactly, no contact force: it sinks by g t_beg^2 / 2 = 0.49 mm, well within
// the detection depth); inside the window the contact throws it back up; after t_end it must
// fall freely again (acceleration -g, no contact force).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kG = 9.81, kBegin = 0.01, kEnd = 0.03;

const char* kDeck = R"(
*TIME
0.05
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 0.1, 0.1, 0.02
*COMPONENT_BOX
2, 2, 3, 3, 1
-0.1, -0.1, -0.02, 0.2, 0.2, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
"plate"
2, 1
*BC_MOTION
P, 2, XYZ, XYZ
*CURVE
1
0.0, -9.81
1.0, -9.81
*LOAD_GRAVITY
Z, 1
*CONTACT
"window"
1
P, 1, P, 2, 0.0, 1.0e9, 0.01, 0.03
*END
)";

TEST(ContactTimeWindow, NoForceBeforeTBeginNorAfterTEnd) {
  const Model model = read_deck_string(kDeck, "time_window.k");
  Simulation sim(model);
  int forces_outside = 0, active_inside = 0;
  double worst_free_fall = 0.0;          // |v_z + g t| / (g t) before t_beg
  double t_after = -1.0, v_after = 0.0;  // first state after t_end
  double v_at_end = 0.0;                 // last state inside the window
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const ContactStats& stats = s.contact_reports()[0].stats;
    const double t = s.time(), vz = s.part_states()[0].velocity.z;
    const bool force = stats.active_points > 0 || stats.normal_force != 0.0 || stats.force.z != 0.0;
    if (t < kBegin || t > kEnd) {
      if (force) ++forces_outside;
    } else if (stats.active_points > 0) {
      ++active_inside;
    }
    if (t < kBegin) worst_free_fall = std::max(worst_free_fall, std::abs(vz + kG * t) / (kG * t));
    if (t <= kEnd) v_at_end = vz;
    if (t > kEnd && t_after < 0.0) {
      t_after = t;
      v_after = vz;
    }
  });
  const double v_end = sim.part_states()[0].velocity.z;
  const double acceleration_after = (v_end - v_after) / (sim.time() - t_after);
  std::cout << "cycles with contact force outside the window: " << forces_outside
            << "; active cycles inside: " << active_inside << ", block v_z at t_end " << v_at_end
            << " m/s; free fall before t_beg: worst relative error of v_z " << worst_free_fall
            << "; acceleration after t_end " << acceleration_after << " m/s^2\n";
  EXPECT_EQ(forces_outside, 0);
  EXPECT_GT(active_inside, 0);
  EXPECT_GT(v_at_end, 0.0);  // pushed back out of the plate
  EXPECT_LT(worst_free_fall, 1e-9);
  ASSERT_GT(t_after, 0.0);
  EXPECT_NEAR(acceleration_after, -kG, 1e-9 * kG);
}

}  // namespace
}  // namespace abut
