// A stress-free elastic cube spinning about its axis is a rigid rotation plus the tiny
// centrifugal stretch: strain of order rho (omega R)^2 / E ~ 1e-8 here. An objective stress
// update keeps the strain energy at that level; a non-objective one would produce strain of the
// order of the rotation angle (Belytschko, Liu & Moran 2000, sec. 5.7). After a quarter turn
// the corners must be where the rotation puts them.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "run_to.hpp"

namespace abut {
namespace {

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
[90.0 / 180.0 * 3.141592653589793 / 20.0]
*COMPONENT_BOX
1, 1, 4, 4, 4
-0.05, -0.05, -0.05, 0.05, 0.05, 0.05
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"cube"
1, 1
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, 0.0, 0.0, 0.0, 20.0
0.0, 0.0, 0.0
*END
)";

TEST(RigidRotation, NoSpuriousStrainEnergyAfterAQuarterTurn) {
  const Model model = read_deck_string(kDeck, "rotation.k");
  Simulation sim(model);
  const double kinetic0 = sim.energies().kinetic;
  // The initial field is v = omega x r: kinetic energy (1/2) omega^2 sum m_i (x_i^2 + y_i^2) of
  // the lumped masses (which exceeds the continuum's (1/2)(m a^2/6) omega^2 by the factor
  // 1 + 2/n^2 of lumping on n = 4 elements per side).
  double inertia = 0.0;
  for (std::size_t i = 0; i < sim.node_count(); ++i)
    inertia += sim.nodal_mass()[i] * (sim.x()[i] * sim.x()[i] + sim.y()[i] * sim.y()[i]);
  EXPECT_NEAR(kinetic0, 0.5 * inertia * 400.0, 1e-9 * kinetic0);
  const double mass = 7800.0 * 0.1 * 0.1 * 0.1;
  EXPECT_NEAR(inertia, mass * 0.01 / 6.0 * (1.0 + 2.0 / 16.0), 1e-9 * inertia);

  verification::run_to(sim, model.time.end_time);
  const Energies e = sim.energies();
  std::cout << "after a quarter turn: internal energy " << e.internal / kinetic0
            << " of the kinetic energy, kinetic energy change " << (e.kinetic - kinetic0) / kinetic0
            << "\n";
  EXPECT_LT(e.internal, 1e-4 * kinetic0);
  EXPECT_LT(std::abs(e.hourglass), 1e-4 * kinetic0);
  EXPECT_NEAR(e.kinetic, kinetic0, 1e-3 * kinetic0);

  // Corner (0.05, 0.05, 0.05) turns by 90 degrees about z to (-0.05, 0.05, 0.05).
  const std::size_t corner = verification::node_near(model, 0.05, 0.05, 0.05);
  EXPECT_NEAR(sim.x()[corner], -0.05, 2e-4);
  EXPECT_NEAR(sim.y()[corner], 0.05, 2e-4);
  EXPECT_NEAR(sim.z()[corner], 0.05, 1e-6);
}

}  // namespace
}  // namespace abut
