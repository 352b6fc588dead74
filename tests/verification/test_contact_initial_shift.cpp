// Initial penetration modes and the detection depth (issue 7), on a rigid block sunk into a rigid
// plate, 0.1 x 0.1 m (A = 0.01 m^2), pfac = 1e10 Pa/m, no gravity; references from the penalty law
// p = pfac d (seed 000) and the seed pages:
// - Radioss Inacti = 5 (*CONTACT_INITIAL SHIFT, seed 004 comment 9): the initial penetration P0 is
//   subtracted, P' = P - P0: no force at t = 0 however deep, and pressing on by delta gives
//   pfac A delta. Seed 000's default instead releases points deeper than delta0_max (4% of the
//   element thickness): no force at all (control). Inacti = -1 (FORCE): pfac A P0 at once.
// - Detection depth (Metafor PROF_CONT, OptiStruct SRCHDIS; *CONTACT_NORMAL depth): a point is in
//   contact only within the depth of the surface it meets. Surface 1's points alone (one-way),
//   1.5 mm deep in a 2 mm plate: beyond the default depth (half the plate's thickness) they feel
//   nothing; with a depth of 5 mm they push with pfac A d0.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kPfac = 1.0e10, kArea = 0.01;

// Block sunk `depth` into a plate `plate` thick; the block is pushed down at `speed`.
std::string sunk(double depth, double plate, double speed, const std::string& contact_line4,
                 const std::string& keywords) {
  const std::string d = std::to_string(-depth), top = std::to_string(0.02 - depth),
                    p = std::to_string(-plate);
  return R"(
*TIME
0.01
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, )" +
         d + ", 0.1, 0.1, " + top + R"(
*COMPONENT_BOX
2, 2, 6, 6, 1
-0.1, -0.1, )" +
         p + R"(, 0.2, 0.2, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
"plate"
2, 1
*BC_MOTION
P, 2, XYZ, XYZ
*BC_MOTION
P, 1, XY, XYZ
V, Z, 1
*CURVE
1
0.0, )" + std::to_string(-speed) +
         R"(
1.0, )" + std::to_string(-speed) +
         R"(
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e10
0, 0.0
)" + contact_line4 +
         "\n" + keywords + "*END\n";
}

struct Forces {
  double at_start = 0.0, at_end = 0.0, travel = 0.0;
};

Forces run(const std::string& deck) {
  const Model model = read_deck_string(deck, "sunk.k");
  Simulation sim(model);
  Forces f;
  f.at_start = sim.contact_reports().at(0).stats.force.z;
  const double z0 = sim.part_states().at(0).centre_of_mass.z;
  verification::run_to(sim, sim.end_time());
  f.at_end = sim.contact_reports()[0].stats.force.z;
  f.travel = z0 - sim.part_states()[0].centre_of_mass.z;
  return f;
}

TEST(ContactInitialShift, RadiossInacti5MeasuresPenetrationFromTheInitialOne) {
  const double d0 = 0.002;  // beyond seed 000's delta0_max = 0.8 mm
  const Forces shift = run(sunk(d0, 0.02, 0.01, "", "*CONTACT_INITIAL\n1, SHIFT\n"));
  const double expected_end = kPfac * kArea * shift.travel;
  std::cout << "SHIFT: force at t = 0 " << shift.at_start << " N; after pressing on by "
            << shift.travel << " m " << shift.at_end << " N (pfac A delta = " << expected_end
            << " N, error " << 100.0 * (shift.at_end - expected_end) / expected_end << "%)\n";
  EXPECT_EQ(shift.at_start, 0.0);
  EXPECT_NEAR(shift.at_end, expected_end, 1e-6 * expected_end);

  const Forces offset = run(sunk(d0, 0.02, 0.01, "", ""));  // seed 000 default: released
  std::cout << "OFFSET (default): force at t = 0 " << offset.at_start << " N, at the end "
            << offset.at_end << " N\n";
  EXPECT_EQ(offset.at_start, 0.0);
  EXPECT_EQ(offset.at_end, 0.0);

  const Forces force = run(sunk(d0, 0.02, 0.0, "", "*CONTACT_INITIAL\n1, FORCE\n"));
  std::cout << "FORCE: force at t = 0 " << force.at_start
            << " N (pfac A d0 = " << kPfac * kArea * d0 << " N)\n";
  EXPECT_NEAR(force.at_start, kPfac * kArea * d0, 1e-6 * kPfac * kArea * d0);
}

TEST(ContactDetectionDepth, PointsBeyondTheDepthFeelNothing) {
  const double d0 = 0.0015, plate = 0.002;
  const std::string one_way = ", , , , 1";
  const Forces shallow = run(sunk(d0, plate, 0.0, one_way, "*CONTACT_INITIAL\n1, FORCE\n"));
  const Forces deep =
      run(sunk(d0, plate, 0.0, one_way,
               "*CONTACT_INITIAL\n1, FORCE\n*CONTACT_NORMAL\n1, LINEAR, , , 0.005\n"));
  std::cout << "default depth (1 mm): force at t = 0 " << shallow.at_start
            << " N; depth 5 mm: " << deep.at_start << " N (pfac A d0 = " << kPfac * kArea * d0
            << " N)\n";
  EXPECT_EQ(shallow.at_start, 0.0);
  EXPECT_NEAR(deep.at_start, kPfac * kArea * d0, 1e-6 * kPfac * kArea * d0);
}

}  // namespace
}  // namespace abut
