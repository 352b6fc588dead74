// Energies that overflow stop a run as unstable, or refuse the deck when they do at the start
// (issue 28: runs ended "completed" with an infinite or negative kinetic energy).
//
// A rigid 1 m^3 box of density 1e300 kg/m^3 (mass M = 1e300 kg, finite) driven at v = 1e5 t m/s:
// its kinetic energy (1/2) M v^2 passes the largest double, 1.797e308, at v = 18960 m/s, between
// t = 0.18 s (1.62e308 J) and t = 0.19 s (1.805e308 J); its coordinates and forces stay finite, so
// only the energies show it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "abut/core/error.hpp"
#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

const char* kDeck = R"(*UNIT_SYSTEM
SI
*TIME
1.0, 0.9, 0, 0.01
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 1.0, 1.0, 1.0
*MAT_RIGID
1, 1.0e300
*PART
"dense block"
1, 1
*CURVE
1
0.0, 0.0
1.0, 1.0e5
*BC_MOTION
P, 1, YZ, XYZ
V, X, 1
)";

TEST(EnergyOverflow, KineticEnergyBeyondTheLargestDoubleStopsTheRun) {
  const Model model = read_deck_string(std::string(kDeck) + "*END\n", "dense_block.k");
  Simulation sim(model);
  std::string message;
  try {
    while (!sim.finished()) {
      sim.advance();
      const Energies e = sim.energies();
      ASSERT_TRUE(std::isfinite(e.kinetic) && std::isfinite(e.external_work)) << sim.time();
      const double v = 1e5 * sim.time();
      EXPECT_NEAR(e.kinetic, 0.5 * 1e300 * (v * v), 1e-12 * 0.5 * 1e300 * (v * v));
    }
  } catch (const InstabilityError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("kinetic energy is inf"), std::string::npos) << message;
  EXPECT_NEAR(sim.last_good_time(), 0.18, 1e-12);
}

TEST(EnergyOverflow, InitialKineticEnergyBeyondTheLargestDoubleIsRefusedAtThePart) {
  const Model model = read_deck_string(
      std::string(kDeck) + "*INITIAL_VELOCITY\nP, 1, 1.0e5, 0.0, 0.0\n*END\n", "dense_block.k");
  try {
    Simulation sim(model);
    FAIL() << "a kinetic energy of (1/2) 1e300 (1e5)^2 J at the start was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 12u) << e.what();  // the part's row under *PART
    EXPECT_NE(std::string(e.what()).find("kinetic energy inf"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace abut
