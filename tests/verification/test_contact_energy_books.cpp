// Energy that contact springs let go of without doing work stays in the books (issue 27, item 5):
// the column contact_released of energy.csv (ContactStats::released_energy), so that
// kinetic + internal + hourglass + contact + friction + eroded + contact_released = E_0 + W
// at every output.
//  - An adhesive bond (Radioss IVIS2 = -1, seed 004, comment 12) pulls a point back with
//    F = SigMaxAdh A s / (Gap/2) for an opening s up to Gap/2, where it breaks: the spring's
//    energy at the break, (1/2) SigMaxAdh (Gap/2) A over the whole face, is let go of (the work of
//    separation of the bond; a linear traction-separation law, e.g. Dugdale-Barenblatt cohesive
//    zones). Before issue 27 the log reported a -99.85% balance for this correct run.
//  - A rigid punch perforating a target whose hexes erode: the springs of the facets that erode
//    under it vanish with them.
// The balance is checked at every cycle once the energies in play exceed 1e-3 of their expected
// size (before that, round-off over round-off). What is released is the energy the springs hold
// at the end of the step they let go in: last step's, less the work their force did over it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

struct Books {
  double worst = 0.0;     // largest |balance error| over the checked cycles
  double released = 0.0;  // contact_released at the end
};

// `scale`: the size of the energies in play, fixed beforehand (the impact's kinetic energy, the
// work of pulling); the balance is checked once the run's energies exceed 1e-3 of it.
Books run_books(const std::string& deck, const std::string& name, double scale) {
  const Model model = read_deck_string(deck, name);
  Simulation sim(model);
  Books b;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const Energies e = s.energies();
    if (std::max(std::abs(e.total()), std::abs(e.external_work)) > 1e-3 * scale)
      b.worst = std::max(b.worst, std::abs(s.energy_balance_error()));
  });
  b.released = sim.energies().contact_released;
  return b;
}

// The adhesion model of test_contact_ties.cpp: a rigid block (bottom 0.1 x 0.1 m) pressed 10 um
// into a fixed rigid plate by *BC_MOTION, then pulled off at 0.01 m/s through the adhesive zone
// (Gap = 0.2 mm, SigMaxAdh = 1e4 Pa: pull-off force 100 N), one way, no damping. The motion
// turns over 0.1 ms rather than at once: a prescribed velocity that flips sign within one step
// makes the kinetic energy (1/2) m v^{n-1/2} v^{n+1/2} negative at that output (issue 28, item 1).
TEST(ContactEnergyBooks, ABrokenAdhesiveBondReleasesItsEnergy) {
  const std::string deck = R"(
*TIME
0.014, 0.9, 0.0, 1e-05
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 0.1, 0.1, 0.02
*COMPONENT_BOX
2, 2, 5, 5, 1
-0.05, -0.05, -0.02, 0.15, 0.15, 0.0
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
P, 1, P, 2, 0.0, 1e9
0, 0.0
, , , , 1
*CONTACT_ADHESION
1, 2.0e-4, 1.0e4
*CURVE
3
0.0, -0.01
0.001, -0.01
0.0011, 0.01
1.0, 0.01
*BC_MOTION
P, 1, XY, XYZ
V, Z, 3
*END
)";
  const double bond = 0.5 * 1.0e4 * 1.0e-4 * 0.01;  // (1/2) SigMaxAdh (Gap/2) A = 5 mJ
  const Books b = run_books(deck, "adhesion_books.k", bond);
  std::cout << "adhesive bond: released " << b.released << " J, (1/2) SigMaxAdh (Gap/2) A = "
            << bond << " J, error " << 100.0 * (b.released - bond) / bond
            << "%; worst balance error " << 100.0 * b.worst << "%\n";
  EXPECT_NEAR(b.released, bond, 0.01 * bond);
  EXPECT_LT(b.worst, 0.01);
}

// The perforation model of test_contact_erosion.cpp (no_internal 0: the faces each eroded hex
// exposes join the contact, so the punch meets every layer).
TEST(ContactEnergyBooks, SpringsOfErodedFacetsAreReleased) {
  const std::string deck = R"(
*UNIT_SYSTEM
SI
*TIME
0.00045
*COMPONENT_BOX
1, 1, 1, 1, 1
-0.004, -0.004, 0.0405, 0.004, 0.004, 0.0505
*COMPONENT_BOX
2, 2, 3, 3, 4
-0.015, -0.015, 0.0, 0.015, 0.015, 0.04
*MAT_RIGID
1, 6.0e5
*MAT_JC
2, 7800.0, 210.0e9, 0.3
50.0e6, 0.0, 1.0
*PART
"punch"
1, 1
"target"
2, 2, , , , , 0.3
*BC_MOTION
P, 1, XY, XYZ
*GEOMETRY_BOX
1
-1.0, -1.0, -0.001, 1.0, 1.0, 0.001
*BC_MOTION
G, 1, XYZ
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, -100.0
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e13
0, 0.1
*END
)";
  const double impact = 0.5 * 6.0e5 * 0.008 * 0.008 * 0.01 * 100.0 * 100.0;  // 1920 J
  const Books b = run_books(deck, "erosion_books.k", impact);
  std::cout << "eroding target: released " << b.released << " J; worst balance error "
            << 100.0 * b.worst << "%\n";
  EXPECT_GT(b.released, 0.0);
  EXPECT_LT(b.worst, 0.01);
}

}  // namespace
}  // namespace abut
