// Free axial vibration of a free-free elastic bar in its first mode: v(X, 0) = v0 cos(pi X / L)
// is the exact first mode shape, period T = 2 L / c (Graff, "Wave Motion in Elastic Solids",
// 1975, sec. 2.3). The explicit scheme must keep total energy constant (drift < 0.5% over ten
// periods, the issue's bound) and reproduce the period (1%: the lumped-mass discretisation error
// for 20 elements is about (pi/20)^2/24 = 0.1%).
//
// The energy the scheme conserves has the kinetic energy (1/2) v^{n-1/2} M v^{n+1/2}: the energy
// balance measures it. The kinetic energy column, (1/2) v^n M v^n with v^n the mean of the two,
// exceeds it by (1/8) dv M dv, dv = dt M^-1 f: in a mode of frequency omega that is (omega dt)^2/4
// of the mode's energy at its turning points (issue 28), here 0.5% (omega = pi c / L, dt =
// 0.9 h / c with h = L / 20, the step of a cube of side h with nu = 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*PARAMETER
%L = 1.0
%periods = 10
*TIME
[%periods * 2 * %L / sqrt(210.0e9 / 7800.0)]
*COMPONENT_BOX
1, 1, 20, 1, 1
0.0, 0.0, 0.0, %L, 0.05, 0.05
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.0
*PART
"bar"
1, 1
*FUNCTION
1
2.0 * cos(180.0 * X / %L)
*INITIAL_VELOCITY
P, 1, fcn(1), 0.0, 0.0
*END
)";

TEST(FreeVibration, TotalEnergyIsConservedOverTenPeriods) {
  const Model model = read_deck_string(kDeck, "vibration.k");
  Simulation sim(model);
  const double e0 = sim.energies().total();
  ASSERT_GT(e0, 0.0);
  double worst = 0.0, worst_columns = 0.0;
  verification::run_to(sim, model.time.end_time, [&](const Simulation& s) {
    worst = std::max(worst, std::abs(s.energy_balance_error()));
    worst_columns = std::max(worst_columns, std::abs(s.energies().total() - e0) / e0);
  });
  const double omega_dt = 0.9 * std::numbers::pi / 20.0;
  std::cout << "largest total-energy deviation over ten periods " << 100.0 * worst
            << "%; of the total of the energy columns " << 100.0 * worst_columns << "%\n";
  EXPECT_LT(worst, 0.005);
  EXPECT_LT(worst_columns, 0.005 + omega_dt * omega_dt / 4.0);
  EXPECT_NEAR(sim.time(), model.time.end_time, 1e-12);
}

TEST(FreeVibration, PeriodIsTwoLOverC) {
  const Model model = read_deck_string(kDeck, "vibration.k");
  Simulation sim(model);
  const std::size_t end = verification::node_near(model, 0.0, 0.0, 0.0);
  std::vector<double> crossings;  // the end velocity changes sign twice a period
  double previous_t = sim.time(), previous_v = sim.vx()[end];
  verification::run_to(sim, model.time.end_time, [&](const Simulation& s) {
    const double v = s.vx()[end];
    if ((previous_v > 0.0) != (v > 0.0))
      crossings.push_back(previous_t + (s.time() - previous_t) * previous_v / (previous_v - v));
    previous_t = s.time();
    previous_v = v;
  });
  ASSERT_GE(crossings.size(), 10u);
  const double period =
      2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double expected = 2.0 * 1.0 / std::sqrt(210.0e9 / 7800.0);
  std::cout << "period " << period << " s, 2L/c = " << expected << " s, error "
            << 100.0 * (period - expected) / expected << "%\n";
  EXPECT_NEAR(period, expected, 0.01 * expected);
}

}  // namespace
}  // namespace abut
