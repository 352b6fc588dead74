// A body under constant gravity: central differences integrate constant acceleration exactly,
// z(t) = z0 - g t^2 / 2 (Belytschko, Liu & Moran 2000, box 6.1, with a constant step), and the
// work of gravity becomes kinetic energy (energy balance). Gravity along -z with *LOAD_GRAVITY
// direction Z and value -9.81 (issue 3).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "run_to.hpp"

namespace abut {
namespace {

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
0.01
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 1.0, 0.1, 0.1, 1.1
*MAT_ELASTIC
1, 2700.0, 70.0e9, 0.33
*PART
"block"
1, 1
*CURVE
1
0.0, -9.81
1.0, -9.81
*LOAD_GRAVITY
Z, 1
*END
)";

TEST(FreeFall, ConstantAccelerationIsIntegratedExactly) {
  const Model model = read_deck_string(kDeck, "free_fall.k");
  Simulation sim(model);
  const std::size_t corner = verification::node_near(model, 0.0, 0.0, 1.0);
  verification::run_to(sim, model.time.end_time);
  const double t = sim.time();
  std::cout << "free fall: z error " << sim.z()[corner] - (1.0 - 0.5 * 9.81 * t * t)
            << " m, balance error " << sim.energy_balance_error() << "\n";
  EXPECT_NEAR(sim.z()[corner], 1.0 - 0.5 * 9.81 * t * t, 1e-9);
  EXPECT_NEAR(sim.vz()[corner], -9.81 * t, 1e-6 * 9.81 * t);
  const Energies e = sim.energies();
  EXPECT_GT(e.external_work, 0.0);
  EXPECT_NEAR(e.kinetic, e.external_work, 1e-3 * e.external_work);
  EXPECT_LT(std::abs(sim.energy_balance_error()), 1e-3);
}

}  // namespace
}  // namespace abut
