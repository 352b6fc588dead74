// A bar under an end pressure (*LOAD_PRESSURE): an elastic steel bar, 100 x 10 x 10 mm, on
// rollers at x = 0 (and on the symmetry planes y = 0, z = 0, so that it contracts freely
// sideways), loaded on its end face x = L by a pressure p raised smoothly to 100 MPa over 2 ms,
// more than a hundred times the bar's wave transit time L/c = 19 us. The state is then
// uniaxial stress: sigma_xx = -p in every element and the end moves by -p L / E (elementary bar
// theory, e.g. Timoshenko & Goodier, Theory of Elasticity, 3rd ed., 1970, §1-§3; Gere &
// Goodno, Mechanics of Materials, ch. 2). The pressure's work becomes strain energy: p^2 A L /
// (2 E), and the energy balance closes.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "abut/core/parallel.hpp"
#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kP = 1.0e8, kE = 210.0e9, kL = 0.1, kB = 0.01;

// The pressure rises as p (1 - cos(pi t / T)) / 2 (zero rate at both ends, so the bar is left
// with almost no vibration) and stays at p after T = 2 ms.
const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
2.0e-3
*COMPONENT_BOX
1, 1, 10, 2, 2
0.0, 0.0, 0.0, 0.1, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"bar"
1, 1
*GEOMETRY_BOX
1
-1.0e-4, -1, -1, 1.0e-4, 1, 1
*GEOMETRY_BOX
2
-1, -1.0e-4, -1, 1, 1.0e-4, 1
*GEOMETRY_BOX
3
-1, -1, -1.0e-4, 1, 1, 1.0e-4
*GEOMETRY_BOX
4
0.0999, -1, -1, 0.1001, 1, 1
*BC_MOTION
G, 1, X
G, 2, Y
G, 3, Z
*FUNCTION
1
1.0e8 * 0.5 * (1 - cosr(pi * min(t, 2.0e-3) / 2.0e-3))
*LOAD_PRESSURE
G, 4, 1
*END
)";

TEST(PressureBar, UniaxialStressUnderAnEndPressure) {
  const Model model = read_deck_string(kDeck, "pressure_bar.k");
  Simulation sim(model);
  // The balance error is relative to the energies, so it is measured once they are above
  // round-off: in the first cycles (energies ~1e-16 J) the half step between the work's mid-step
  // velocity and the kinetic energy (1/2) m v^{n-1/2} . v^{n+1/2} is of their own size, as for
  // any load that starts from rest; it falls below 1% by cycle 16 and 1e-5 by cycle 250.
  const double strain_energy = kP * kP * kB * kB * kL / (2.0 * kE);
  double worst_balance = 0.0;
  verification::run_to(sim, model.time.end_time, [&](const Simulation& s) {
    if (s.energies().external_work > 1e-6 * strain_energy)
      worst_balance = std::max(worst_balance, std::abs(s.energy_balance_error()));
  });
  ASSERT_NEAR(sim.time(), 2.0e-3, 1e-12);

  // Uniaxial stress sigma_xx = -p: element pressure p/3 and von Mises stress p.
  std::vector<double> pressure, von_mises;
  sim.pressure(pressure);
  sim.von_mises_stress(von_mises);
  double worst_stress = 0.0;
  for (std::size_t e = 0; e < pressure.size(); ++e) {
    worst_stress = std::max(worst_stress, std::abs(3.0 * pressure[e] - kP) / kP);
    worst_stress = std::max(worst_stress, std::abs(von_mises[e] - kP) / kP);
  }
  // Every node of the loaded end moves by -p L / E.
  const double expected = -kP * kL / kE;
  double worst_end = 0.0;
  for (std::size_t i = 0; i < sim.node_count(); ++i) {
    if (std::abs(model.mesh.nodes.x[i] - kL) > 1e-9) continue;
    worst_end = std::max(worst_end, std::abs((sim.x()[i] - kL) - expected) / std::abs(expected));
  }
  const Energies e = sim.energies();
  std::cout << "pressure bar: stress error " << worst_stress << ", end displacement error "
            << worst_end << ", internal energy " << e.internal << " J (p^2 A L / 2E "
            << strain_energy << " J), external work " << e.external_work
            << " J, worst balance error " << worst_balance << " (final "
            << sim.energy_balance_error() << "), kinetic " << e.kinetic << " J, cycles "
            << sim.cycle() << "\n";
  EXPECT_LT(worst_stress, 0.01);
  EXPECT_LT(worst_end, 0.01);
  EXPECT_NEAR(e.internal, strain_energy, 0.01 * strain_energy);
  EXPECT_NEAR(e.external_work, strain_energy, 0.01 * strain_energy);
  EXPECT_LT(worst_balance, 0.01);
}

// The pressure forces are summed face by face on one thread: runs are bitwise identical for any
// thread count. A finer mesh of the bar (3321 nodes), above the size where the node loops of the
// time step go parallel.
TEST(PressureBar, ThreadCountDoesNotChangeTheResult) {
  std::string deck = kDeck;
  deck.replace(deck.find("1, 1, 10, 2, 2"), 14, "1, 1, 40, 8, 8");
  const auto run = [&deck](int threads) {
    omp_set_num_threads(threads);
    const Model model = read_deck_string(deck, "pressure_bar.k");
    EXPECT_GE(static_cast<std::int64_t>(model.mesh.nodes.size()), kParallelMinimum);
    Simulation sim(model);
    for (int i = 0; i < 150; ++i) sim.advance();
    std::vector<double> out = sim.x();
    out.insert(out.end(), sim.vx().begin(), sim.vx().end());
    out.push_back(sim.energies().external_work);
    return out;
  };
  const std::vector<double> one = run(1), two = run(2);
  omp_set_num_threads(1);
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace abut
