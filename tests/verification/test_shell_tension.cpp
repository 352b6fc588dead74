// Single-shell uniaxial tension of *MAT_METAL (plane-stress return through the material-point
// seam), loaded into the plastic range and unloaded.
//
// Reference: as for the hexahedron (test_metal_tension.cpp; Simo & Hughes, "Computational
// Inelasticity", 1998, sec. 1.4 and box 3.2): under uniaxial stress sigma the logarithmic strain
// splits as eps = sigma / E + eps_p, and while the point flows sigma = sigma_y(eps_p); unloading is
// elastic with slope E. Tolerance 0.5% of the flow stress (issue 8).
//
// Model: one 10 mm x 10 mm shell, 1 mm thick, in the x-y plane; E = 210 GPa, nu = 0.3, flow stress
// 300 MPa + 500 MPa epsp^0.5. Node 1 is held in X and Y, node 4 in X, all nodes in Z and in
// rotation (a membrane state); nodes 2 and 3 move at 1 m/s in X (strain rate 100 /s, after a
// 0.05 ms ramp) until t = 1 ms (eps ~ 0.095); the velocity then turns to -1 m/s over 0.05 ms and
// the run stops at 1.045 ms, the stress down by about a third, before any reversed yield. The width
// contracts freely, so the stress is uniaxial. Quasi-static: the element's wave transit time is 1.8
// us.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

const char* kDeck = R"(
*UNIT_SYSTEM
SI
*TIME
0.001045
*NODE
1, 0.0, 0.0, 0.0, XYZ
2, 0.01, 0.0, 0.0, Z
3, 0.01, 0.01, 0.0, Z
4, 0.0, 0.01, 0.0, XZ
*ELEMENT_SHELL
1, 1, 1, 2, 3, 4
*MAT_METAL
1, 7800.0, 210.0e9, 0.3
5
*FUNCTION
5
300e6 + 500e6 * epsp^0.5
*PART
"sheet"
1, 1, , 0.001
*SET_NODE
2
2, 3
*CURVE
6
0.0, 0.0
5e-5, 1.0
0.001, 1.0
0.00105, -1.0
1.0, -1.0
*BC_MOTION
ALL, 0, 0, XYZ
*BC_MOTION
NS, 2
V, X, 6
*END
)";

TEST(ShellMetalTension, StressFollowsTheFlowCurveAndUnloadsElastically) {
  const Model model = read_deck_string(kDeck, "shell_tension.k");
  Simulation sim(model);
  const auto flow = [](double epsp) { return 300e6 + 500e6 * std::sqrt(epsp); };
  double worst_flow = 0.0, worst_split = 0.0;
  double sigma_turn = 0.0, eps_turn = 0.0, epsp_turn = 0.0, worst_unload = 0.0;
  std::vector<double> q, ep, rate;
  double previous_epsp = 0.0, worst_rate = 0.0;
  int unloading_cycles = 0;
  verification::run_to(sim, model.time.end_time, [&](const Simulation& s) {
    s.shell_von_mises_stress(q);
    s.shell_plastic_strain(ep);
    const double eps = std::log(s.x()[1] / 0.01);
    if (ep[0] > previous_epsp) {  // flowing in this cycle
      if (ep[0] > 0.002) {
        worst_flow = std::max(worst_flow, std::abs(q[0] - flow(ep[0])) / flow(ep[0]));
        worst_split = std::max(worst_split, std::abs(eps - q[0] / 210e9 - ep[0]) * 210e9 / q[0]);
      }
      sigma_turn = q[0], eps_turn = eps, epsp_turn = ep[0];
      if (s.time() > 5e-4 && s.time() < 9.5e-4) {
        // Plastic strain rate in steady flow at 1 m/s: eps' = v / L splits into the plastic
        // rate and sigma' / E = H eps_p' / E, H = d sigma_y / d epsp = 250 MPa / sqrt(epsp).
        s.shell_plastic_strain_rate(rate);
        const double hardening = 250e6 / std::sqrt(ep[0]);
        const double expected = (1.0 / s.x()[1]) / (1.0 + hardening / 210e9);
        worst_rate = std::max(worst_rate, std::abs(rate[0] - expected) / expected);
      }
    } else if (s.time() > 0.001025) {  // the velocity has turned: unloading
      const double elastic = sigma_turn - 210e9 * (eps_turn - eps);
      worst_unload = std::max(worst_unload, std::abs(q[0] - elastic) / sigma_turn);
      ++unloading_cycles;
    }
    previous_epsp = ep[0];
  });
  EXPECT_GT(unloading_cycles, 10);
  std::cout << "plastic strain rate in steady flow within " << worst_rate << " of (v/L)/(1 + H/E)\n";
  EXPECT_LT(worst_rate, 0.01);
  EXPECT_LT(q[0], 0.7 * sigma_turn);  // unloaded by a third, still in tension
  std::cout << "flowing: |q - sigma_y(epsp)| / sigma_y <= " << worst_flow
            << ", |eps - q/E - epsp| E / q <= " << worst_split
            << "; unloading: |q - elastic| / q <= " << worst_unload << " (turn at eps " << eps_turn
            << ", epsp " << epsp_turn << ")\n";
  EXPECT_GT(epsp_turn, 0.08);
  EXPECT_LT(worst_flow, 0.005);
  EXPECT_LT(worst_split, 0.005);
  EXPECT_LT(worst_unload, 0.005);
}

// Johnson-Cook failure (*PROP_DAMAGE_JC, Johnson & Cook 1985): under uniaxial stress the
// triaxiality is 1/3 throughout, so the damage D = epsp / eps_f reaches 1 when the plastic
// strain reaches eps_f = d1 + d2 exp(d3 / 3) (no rate term: d4 = 0), here 0.02 + 0.1 exp(-0.5)
// = 0.0807. All five thickness points strain alike, fail together and the shell erodes in that
// cycle: the test reads the plastic strain of the last cycle before the erosion and requires the
// failure strain to lie between it and one cycle's increment more. The eroded energy is what the
// element held.
TEST(ShellMetalTension, JohnsonCookFailureErodesTheShellAtTheFailureStrain) {
  std::string deck = kDeck;
  deck.replace(deck.find("1, 7800.0, 210.0e9, 0.3\n5"), 25, "1, 7800.0, 210.0e9, 0.3, 3\n5");
  deck.replace(deck.find("*END"), 4, "*PROP_DAMAGE_JC\n3, 0.02, 0.1, -1.5\n*END");
  const Model model = read_deck_string(deck, "shell_failure.k");
  Simulation sim(model);
  const double eps_f = 0.02 + 0.1 * std::exp(-0.5);
  std::vector<double> ep;
  double before = 0.0, increment = 0.0, internal_before = 0.0;
  bool eroded = false;
  verification::run_to(sim, 0.001, [&](const Simulation& s) {
    if (eroded) return;
    if (s.eroded_shells()[0]) {
      eroded = true;
      EXPECT_NEAR(s.energies().eroded, internal_before, 0.01 * internal_before);
      return;
    }
    s.shell_plastic_strain(ep);
    increment = ep[0] - before;
    before = ep[0];
    internal_before = s.energies().internal;
  });
  ASSERT_TRUE(eroded);
  std::cout << "eroded after epsp = " << before << " (+" << increment
            << " per cycle), eps_f = " << eps_f << "\n";
  EXPECT_LE(before, eps_f);
  EXPECT_GE(before + 1.5 * increment, eps_f);
}

}  // namespace
}  // namespace abut
