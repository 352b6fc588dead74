// 1D elastic wave: a bar moving at v hits a fixed end. Elementary 1D wave theory (e.g. Kolsky,
// "Stress Waves in Solids", 1963; Graff, "Wave Motion in Elastic Solids", 1975, ch. 2): a
// compressive front runs back at c = sqrt(E/rho) (Poisson's ratio 0: no lateral coupling),
// behind it the bar is at rest with stress sigma = -rho c v; the front reaches the free end at
// t = L/c, where the free end's velocity reverses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kRho = 7800.0, kE = 210e9, kV = 10.0, kL = 1.0;

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
2.5e-4
*COMPONENT_BOX
1, 1, 100, 1, 1
0.0, 0.0, 0.0, 1.0, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.0
*PART
"bar"
1, 1
*INITIAL_VELOCITY
P, 1, 10.0, 0.0, 0.0
*GEOMETRY_BOX
1
0.999, -1.0, -1.0, 1.001, 1.0, 1.0
*BC_MOTION
G, 1, XYZ
*END
)";

TEST(ElasticWaveBar, StressBehindTheFrontIsRhoCV) {
  const Model model = read_deck_string(kDeck, "wave_bar.k");
  Simulation sim(model);
  const double c = std::sqrt(kE / kRho);
  verification::run_to(sim, 0.5 * kL / c);  // front near x = L/2

  std::vector<double> mises;
  sim.von_mises_stress(mises);
  const double expected = kRho * c * kV;
  const Nodes& nodes = model.mesh.nodes;
  // The discrete front is spread by the bulk viscosity and rings behind it (the dispersion of
  // the lumped-mass chain); the plateau is checked from 15 elements behind the front on, and
  // ahead of the front from 10 elements on.
  int behind = 0, ahead = 0;
  double worst_behind = 0.0, worst_ahead = 0.0;
  const double front = kL - c * sim.time();
  for (std::size_t e = 0; e < model.mesh.hex_count(); ++e) {
    const double xc = 0.5 * (nodes.x[model.mesh.hexes[e][0]] + nodes.x[model.mesh.hexes[e][6]]);
    if (xc > front + 0.15 && xc < 0.95) {
      worst_behind = std::max(worst_behind, std::abs(mises[e] - expected) / expected);
      ++behind;
    } else if (xc < front - 0.1) {
      worst_ahead = std::max(worst_ahead, mises[e] / expected);
      ++ahead;
    }
  }
  std::cout << "plateau stress error " << 100.0 * worst_behind << "%, ahead of the front "
            << 100.0 * worst_ahead << "% of rho c v\n";
  EXPECT_LT(worst_behind, 0.02);
  EXPECT_LT(worst_ahead, 0.02);
  EXPECT_GT(behind, 20);
  EXPECT_GT(ahead, 20);
}

TEST(ElasticWaveBar, FrontReachesTheFreeEndAtLOverC) {
  const Model model = read_deck_string(kDeck, "wave_bar.k");
  Simulation sim(model);
  const std::size_t free_end = verification::node_near(model, 0.0, 0.0, 0.0);
  const double c = std::sqrt(kE / kRho);
  double arrival = -1.0, previous_t = sim.time(), previous_v = sim.vx()[free_end];
  verification::run_to(sim, 1.3 * kL / c, [&](const Simulation& s) {
    const double v = s.vx()[free_end];
    if (arrival < 0.0 && previous_v > 0.0 && v <= 0.0)  // the end velocity reverses
      arrival = previous_t + (s.time() - previous_t) * previous_v / (previous_v - v);
    previous_t = s.time();
    previous_v = v;
  });
  ASSERT_GT(arrival, 0.0);
  std::cout << "front arrival at the free end " << arrival << " s, L/c = " << kL / c << " s, error "
            << 100.0 * (arrival - kL / c) / (kL / c) << "%\n";
  EXPECT_NEAR(arrival, kL / c, 0.02 * kL / c);
}

}  // namespace
}  // namespace abut
