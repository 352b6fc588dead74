// Axial crushing of a thin-walled square tube (issue 9): the crash benchmark that works only with
// shell self contact, because the folds lie on each other.
//
// A mild-steel tube, side c = 50 mm (mid-surface), wall h = 1.5 mm, 120 mm long, elastic-perfectly
// plastic (sigma_0 = 300 MPa, rate-independent), clamped at its foot; a rigid plate of 50 kg
// closing its top end hits it at 8 m/s (1.6 kJ). A quarter of the tube is modelled (symmetry
// planes x = 0 and y = 0 through the middle of the walls: no normal translation, no rotation about
// the in-plane axes), with 3.125 mm shells; the plate of the quarter carries 12.5 kg.
//
// Reference: Abramowicz & Jones (1984), "Dynamic axial crushing of square tubes", Int. J. Impact
// Eng. 2:179-208: the mean crushing force of the symmetric folding mode, from Wierzbicki &
// Abramowicz's (1983) folding mechanism, P_m = 9.56 sigma_0 h^(5/3) c^(1/3), divided by the
// effective crushing distance 0.73 (a fold of height 2H flattens to 0.73 2H):
//   P_m = 13.06 sigma_0 h^(5/3) c^(1/3) = 28.4 kN.
// Their dynamic factor 1 + (0.33 V / (c D))^(1/q) (Cowper-Symonds D, q) is 1 here: the material
// has no strain-rate term. The test asks for the issue's 15%; measured 31.2 kN (+10.0%), with M_0 =
// sigma_0 h^2/4 (uniaxial): a von Mises shell bent in plane strain holds 2/sqrt(3) of that, which
// is where most of the difference comes from. The mean force is the energy the tube took from the
// plate divided by the crush, as the drop-hammer tests measure it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kSide = 0.05, kWall = 0.0015, kYield = 300.0e6;

const char* const kQuarterTube = R"(
*TITLE
Quarter of a square tube crushed axially by a rigid plate
*UNIT_SYSTEM
SI
*PARAMETER
%b = 0.05
%L = 0.12
%n = 8
%m = 38
*TIME
0.0125
*COMPONENT_SHELL_PLATE
1, 1, %n, %m
[%b / 2], 0.0, 0.0, [%b / 2], [%b / 2], 0.0
[%b / 2], 0.0, %L
*COMPONENT_SHELL_PLATE
2, 3, %m, %n
0.0, [%b / 2], 0.0, 0.0, [%b / 2], %L
[%b / 2], [%b / 2], 0.0
*COMPONENT_SHELL_PLATE
3, 2, %n, %n
0.0, 0.0, %L, [%b / 2], 0.0, %L
0.0, [%b / 2], %L
*MERGE_DUPLICATED_NODES
P, 3, P, 1, 1.0e-6
P, 2, P, 1, 1.0e-6
P, 2, P, 3, 1.0e-6
*MAT_JC
1, 7850.0, 210.0e9, 0.3
300.0e6, 0.0, 0.5
*MAT_RIGID
2, [12.5 / (%b * %b / 4 * 0.005)]
*PART
"wall x = b/2"
1, 1, , 0.0015
"plate"
2, 2, , 0.005
"wall y = b/2"
3, 1, , 0.0015
*SET_PART
1
1, 3
*GEOMETRY_BOX
1
-1.0, -1.0, -0.001, 1.0, 1.0, 0.001
*GEOMETRY_BOX
2
-0.000001, -1.0, 0.0005, 0.000001, 1.0, [%L - 0.0005]
*GEOMETRY_BOX
3
-1.0, -0.000001, 0.0005, 1.0, 0.000001, [%L - 0.0005]
*BC_MOTION
G, 1, XYZ, XYZ
*BC_MOTION
G, 2, X, YZ
*BC_MOTION
G, 3, Y, XZ
*BC_MOTION
P, 2, XY, XYZ
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, -8.0
*CONTACT
"tube self contact"
1
PS, 1, PS, 1
*END
)";

TEST(TubeCrush, MeanCrushingForceIsAbramowiczAndJones) {
  const Model model = read_deck_string(kQuarterTube, "quarter_tube.k");
  Simulation sim(model);
  const std::size_t plate = 1;  // parts in id order: 1, 2, 3
  ASSERT_EQ(sim.part_states()[plate].part_id, 2);
  const double z0 = sim.part_states()[plate].centre_of_mass.z;
  const double kinetic0 = sim.part_states()[plate].kinetic;
  double crush = 0.0, kinetic_at_crush = kinetic0, penetration = 0.0;
  verification::run_to(sim, model.time.end_time, [&](const Simulation& s) {
    const PartState p = s.part_states()[plate];  // a copy: part_states() returns a new vector
    if (z0 - p.centre_of_mass.z > crush) {
      crush = z0 - p.centre_of_mass.z;
      kinetic_at_crush = p.kinetic;
    }
    for (const ContactReport& c : s.contact_reports())
      penetration = std::max(penetration, c.stats.max_penetration);
  });
  const double mean_force = 4.0 * (kinetic0 - kinetic_at_crush) / crush;  // four quarters
  const double reference = 13.06 * kYield * std::pow(kWall, 5.0 / 3.0) * std::cbrt(kSide);
  std::cout << "crush " << crush * 1e3 << " mm, mean force " << mean_force / 1e3
            << " kN (Abramowicz & Jones " << reference / 1e3 << " kN), largest penetration "
            << penetration * 1e6 << " um, energy balance " << sim.energy_balance_error() << "\n";
  EXPECT_NEAR(mean_force / reference, 1.0, 0.15);
  // The plate stopped: the tube took its energy over a progressive crush of several folds
  // (a fold takes 0.73 2H, H = 0.99 (c^2 h)^(1/3) = 15.4 mm: about 22 mm).
  EXPECT_LT(kinetic_at_crush, 0.02 * kinetic0);
  EXPECT_GT(crush, 2.0 * 0.73 * 2.0 * 0.99 * std::cbrt(kSide * kSide * kWall));
  // The folds never pass through each other: the contact surfaces (h/2 on either side of the
  // mid-surface) interpenetrate by a small fraction of the wall.
  EXPECT_LT(penetration, 0.05 * kWall);
  EXPECT_LT(std::abs(sim.energy_balance_error()), 0.02);
}

}  // namespace
}  // namespace abut
