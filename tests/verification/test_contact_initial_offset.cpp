// *CONTACT delta0_offset (seed 000): an initial penetration up to delta0_offset is subtracted
// from the penetration, so an initially penetrating pair starts without a force jump.
//
// Model: a rigid block 0.1 x 0.1 m sunk 0.1 mm into a rigid plate (within the default
// delta0_max, 4% of the 20 mm element thickness), no gravity, plate meshed so that its facet
// edges meet the block's edges. With delta0_offset = 0.2 mm the contact force is zero at t = 0
// and stays zero (the block stays at rest). With delta0_offset = 0 the penalty law gives
// (seed 000; symmetric contact: both surfaces' points penetrate d0 over the area A, half
// weight each) F = pfac A d0 at t = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kPfac = 1.0e10, kArea = 0.01, kD0 = 1e-4;

std::string sunk_block_deck(const std::string& offset) {
  return R"(
*TIME
0.01
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, -0.0001, 0.1, 0.1, 0.0199
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
*BC_MOTION
P, 2, XYZ, XYZ
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e10
0, 0.1, , , )" +
         offset + R"(
*END
)";
}

TEST(ContactInitialOffset, NoForceAtTimeZeroForAnInitialPenetration) {
  const Model model = read_deck_string(sunk_block_deck("0.0002"), "offset.k");
  Simulation sim(model);
  const ContactStats at_start = sim.contact_reports().at(0).stats;
  double largest_force = std::abs(at_start.force.z);
  for (int i = 0; i < 100; ++i) {
    sim.advance();
    largest_force = std::max(largest_force, std::abs(sim.contact_reports()[0].stats.force.z));
  }
  const double speed = norm(sim.part_states()[0].velocity);
  std::cout << "delta0_offset 0.2 mm: force at t = 0 " << at_start.force.z
            << " N, largest over 100 cycles " << largest_force << " N, block speed after them "
            << speed << " m/s\n";
  EXPECT_EQ(at_start.force.z, 0.0);
  EXPECT_EQ(at_start.normal_force, 0.0);
  EXPECT_EQ(largest_force, 0.0);
  EXPECT_EQ(speed, 0.0);
}

TEST(ContactInitialOffset, WithoutOffsetTheInitialPenetrationPushesAtOnce) {
  const Model model = read_deck_string(sunk_block_deck(""), "no_offset.k");
  Simulation sim(model);
  const ContactReport report = sim.contact_reports().at(0);
  const double expected = kPfac * kArea * kD0;
  std::cout << "delta0_offset 0: force at t = 0 " << report.stats.force.z
            << " N, pfac A d0 = " << expected << " N, relative error "
            << (report.stats.force.z - expected) / expected << "\n";
  EXPECT_EQ(report.released_points, 0u);
  EXPECT_NEAR(report.stats.force.z, expected, 1e-6 * expected);  // pushes surface 1 (the block) up
}

}  // namespace
}  // namespace abut
