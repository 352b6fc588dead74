// One-way versus symmetric contact (seed 000, *CONTACT one_way): with one_way = 1 only surface 2
// defines the contact surface, so without friction every contact force lies along surface 2's
// normal; symmetric contact (the default) also uses surface 2's points against surface 1, whose
// forces lie along surface 1's normal.
//
// Model: a rigid hexahedron whose bottom face is tilted by 10 degrees about y (surface 1) is
// driven down at 1 m/s (*BC_MOTION, no rotation) into a flat rigid plate z <= 0 (surface 2):
// its low edge digs in (by 7 mm at the end). The force on surface 1 must be exactly along z with
// one_way = 1, and have an x component with symmetric contact, up to tan(10 deg) of f_z.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kSlope = 0.0176327 / 0.1;  // of the bottom face: tan(10 deg) to 6 digits

std::string tilted_block_deck(int one_way) {
  return R"(
*TIME
0.008
*NODE
1, 0.0, 0.0, 0.001
2, 0.1, 0.0, 0.0186327
3, 0.1, 0.1, 0.0186327
4, 0.0, 0.1, 0.001
5, 0.0, 0.0, 0.051
6, 0.1, 0.0, 0.0686327
7, 0.1, 0.1, 0.0686327
8, 0.0, 0.1, 0.051
*ELEMENT_SOLID
1, 1, 1, 2, 3, 4, 5, 6, 7, 8
*COMPONENT_BOX
1, 2, 20, 20, 1
-0.05, -0.05, -0.01, 0.15, 0.15, 0.0
*MAT_RIGID
1, 7800.0
*PART
"tilted block"
1, 1
"plate"
2, 1
*CURVE
1
0.0, 1.0
1.0, 1.0
*BC_MOTION
P, 1, XY, XYZ
V, Z, 1, -1.0
*BC_MOTION
P, 2, XYZ, XYZ
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e10
0, 0.0
, , , , )" +
         std::to_string(one_way) + R"(
*END
)";
}

// Largest |f_x| / f_z of the force on surface 1 over the run, and the largest f_z.
struct ForceDirection {
  double max_ratio = 0.0, max_fz = 0.0;
  bool exactly_normal = true;  // f_x and f_y exactly 0 at every cycle
};

ForceDirection run(int one_way) {
  const Model model = read_deck_string(tilted_block_deck(one_way), "one_way.k");
  Simulation sim(model);
  ForceDirection r;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const Vec3 f = s.contact_reports()[0].stats.force;
    if (f.x != 0.0 || f.y != 0.0) r.exactly_normal = false;
    if (f.z > 0.0) r.max_ratio = std::max(r.max_ratio, std::abs(f.x) / f.z);
    r.max_fz = std::max(r.max_fz, f.z);
  });
  return r;
}

TEST(ContactOneWay, FrictionlessForceIsExactlyNormalToSurfaceTwo) {
  const ForceDirection one_way = run(1);
  const ForceDirection symmetric = run(0);
  const auto precision = std::cout.precision(9);
  std::cout << "one-way: largest |fx|/fz " << one_way.max_ratio << " (fz up to " << one_way.max_fz
            << " N); symmetric: largest |fx|/fz " << symmetric.max_ratio << " (fz up to "
            << symmetric.max_fz << " N), bottom face slope " << kSlope << "\n";
  std::cout.precision(precision);
  EXPECT_GT(one_way.max_fz, 100.0);  // the block did dig in
  EXPECT_TRUE(one_way.exactly_normal);
  EXPECT_GT(symmetric.max_fz, 100.0);
  EXPECT_FALSE(symmetric.exactly_normal);
  // Surface 1's normal shows; the force is never more tilted than surface 1's own normal (it
  // is exactly that while only the plate's points touch, before the block's points dig in).
  EXPECT_GT(symmetric.max_ratio, 0.02);
  EXPECT_LE(symmetric.max_ratio, kSlope * (1.0 + 1e-9));
}

}  // namespace
}  // namespace abut
