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
// the run stops at 1.045 ms, the stress down by about a third, before any reversed yield. The width contracts freely,
// so the stress is uniaxial. Quasi-static: the element's wave transit time is 1.8 us.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
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
  std::vector<double> q, ep;
  double previous_epsp = 0.0;
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
    } else if (s.time() > 0.001025) {  // the velocity has turned: unloading
      const double elastic = sigma_turn - 210e9 * (eps_turn - eps);
      worst_unload = std::max(worst_unload, std::abs(q[0] - elastic) / sigma_turn);
      ++unloading_cycles;
    }
    previous_epsp = ep[0];
  });
  EXPECT_GT(unloading_cycles, 10);
  EXPECT_LT(q[0], 0.7 * sigma_turn);  // unloaded by a third, still in tension
  std::cout << "flowing: |q - sigma_y(epsp)| / sigma_y <= " << worst_flow
            << ", |eps - q/E - epsp| E / q <= " << worst_split << "; unloading: |q - elastic| / q <= "
            << worst_unload << " (turn at eps " << eps_turn << ", epsp " << epsp_turn << ")\n";
  EXPECT_GT(epsp_turn, 0.08);
  EXPECT_LT(worst_flow, 0.005);
  EXPECT_LT(worst_split, 0.005);
  EXPECT_LT(worst_unload, 0.005);
}

}  // namespace
}  // namespace abut
