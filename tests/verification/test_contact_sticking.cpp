// *CONTACT sigma_stick (seed 000): surfaces that touch stick together, in tension too, until the
// traction exceeds sigma_stick; then the contact is an ordinary (compression-only) one.
//
// Model: a rigid block (contact area A = 0.01 m^2) resting on a fixed rigid plate is lifted at
// v = 0.01 m/s from t = 0 (*BC_MOTION velocity). Each point's tie is a spring pfac * area (no
// damping: xi = 0), so the pull on the block grows as F = pfac A v t; the traction F / A
// reaches sigma_stick = 1e5 Pa at t_f = sigma_stick / (pfac v) = 1 ms, where the tie must fail,
// and no force may act afterwards. Without sigma_stick the lifted block feels no force at all.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kPfac = 1.0e10, kArea = 0.01, kV = 0.01, kStick = 1.0e5;

std::string lifted_block_deck(const std::string& sigma_stick) {
  return R"(
*TIME
0.002, 0.9, 0.0, 1.0e-5
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 0.1, 0.1, 0.02
*COMPONENT_BOX
2, 2, 6, 6, 1
-0.1, -0.1, -0.02, 0.2, 0.2, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
"plate"
2, 1
*CURVE
1
0.0, 0.01
1.0, 0.01
*BC_MOTION
P, 1, XY, XYZ
V, Z, 1
*BC_MOTION
P, 2, XYZ, XYZ
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e10
0, 0.0
, , , , 0, 0, )" +
         sigma_stick + R"(
*END
)";
}

TEST(ContactSticking, TiedUntilTheTractionExceedsSigmaStick) {
  const Model model = read_deck_string(lifted_block_deck("1.0e5"), "sticking.k");
  Simulation sim(model);
  const double t_fail = kStick / (kPfac * kV);
  double worst_pull = 0.0, largest_pull = 0.0, failed_at = -1.0, previous_t = sim.time();
  int tied_cycles = 0, forces_after = 0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const ContactStats& stats = s.contact_reports()[0].stats;
    const double t = s.time();
    const double pull = -stats.force.z;  // the plate pulls the block (surface 1) down
    if (failed_at < 0.0 && stats.active_points > 0) {
      ++tied_cycles;
      const double expected = kPfac * kArea * kV * t;
      worst_pull = std::max(worst_pull, std::abs(pull - expected) / expected);
      largest_pull = std::max(largest_pull, pull);
    } else if (failed_at < 0.0) {
      failed_at = 0.5 * (previous_t + t);
    } else if (stats.active_points > 0 || stats.force.z != 0.0) {
      ++forces_after;
    }
    previous_t = t;
  });
  std::cout << "tie: pull = pfac A v t within " << worst_pull << " (relative) over " << tied_cycles
            << " cycles, largest pull " << largest_pull << " N (sigma_stick A = " << kStick * kArea
            << " N); failed at " << failed_at << " s (sigma_stick / (pfac v) = " << t_fail
            << " s); cycles with a force after: " << forces_after << "\n";
  EXPECT_GT(tied_cycles, 50);
  EXPECT_LT(worst_pull, 1e-6);
  ASSERT_GT(failed_at, 0.0);
  EXPECT_NEAR(failed_at, t_fail, 1e-5);  // within the step
  EXPECT_LE(largest_pull, kStick * kArea * (1.0 + 1e-9));
  EXPECT_GT(largest_pull, 0.98 * kStick * kArea);
  EXPECT_EQ(forces_after, 0);
}

TEST(ContactSticking, WithoutSigmaStickALiftedBlockFeelsNoForce) {
  const Model model = read_deck_string(lifted_block_deck(""), "no_sticking.k");
  Simulation sim(model);
  int cycles_with_force = 0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const ContactStats& stats = s.contact_reports()[0].stats;
    if (stats.active_points > 0 || stats.force.z != 0.0) ++cycles_with_force;
  });
  std::cout << "without sigma_stick: cycles with a contact force " << cycles_with_force << "\n";
  EXPECT_EQ(cycles_with_force, 0);
}

}  // namespace
}  // namespace abut
