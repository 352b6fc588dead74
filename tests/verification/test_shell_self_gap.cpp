// Radioss Igap = 2 (*CONTACT_GAP igap 2; seed 004, comment 3): in self contact a point ignores the
// facets that had a node within twice the pair's gap of it at t = 0 (abut measures the straight
// distance where Radioss takes the curvilinear one), so a shell folded on itself does not meet
// its own other leg near the fold.
//
// Model: an elastic steel shell folded into a V of 30 degrees, each leg 50 mm (5 elements of 10 mm)
// by 40 mm, 10 mm thick (g = g_s + g_m = 10 mm), at rest, no load, no support, self contact with
// every initial penetration pushing (*CONTACT_INITIAL FORCE, Radioss Inacti = -1). Near the fold
// the legs are closer than g (r = 10 mm from the fold: 5.2 mm apart), so with igap 1 the nodes
// there start 4.8 mm deep in the other leg's contact surface and are pushed: the V springs open.
// With igap 2 those facets had the fold's nodes within 2 g = 20 mm of the points, so nothing
// touches: a free body at rest without load stays at rest (Newton's first law), its kinetic
// energy zero to round-off over the run.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

std::string folded_shell(int igap) {
  constexpr double kPi = 3.14159265358979323846, half = 15.0 * kPi / 180.0;
  std::string nodes, shells;
  // Node (i along the fold, j from the fold, leg): the fold line's nodes are shared.
  const auto id = [](int i, int j, int leg) {
    return j == 0 ? 1 + i : 1 + 5 + (leg * 5 + (j - 1)) * 5 + i;
  };
  for (int i = 0; i < 5; ++i)
    nodes += std::to_string(id(i, 0, 0)) + ", " + std::to_string(0.01 * i) + ", 0.0, 0.0\n";
  for (int leg = 0; leg < 2; ++leg)
    for (int j = 1; j <= 5; ++j)
      for (int i = 0; i < 5; ++i) {
        const double r = 0.01 * j, side = leg == 0 ? 1.0 : -1.0;
        nodes += std::to_string(id(i, j, leg)) + ", " + std::to_string(0.01 * i) + ", " +
                 std::to_string(r * std::cos(half)) + ", " +
                 std::to_string(side * r * std::sin(half)) + "\n";
      }
  int e = 0;
  for (int leg = 0; leg < 2; ++leg)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 4; ++i) {
        // Counter-clockwise about the outward normal of each leg (the V's outside).
        const int a = id(i, j, leg), b = id(i + 1, j, leg), c = id(i + 1, j + 1, leg),
                  d = id(i, j + 1, leg);
        shells += std::to_string(++e) + ", 1, " +
                  (leg == 0 ? std::to_string(a) + ", " + std::to_string(d) + ", " +
                                  std::to_string(c) + ", " + std::to_string(b)
                            : std::to_string(a) + ", " + std::to_string(b) + ", " +
                                  std::to_string(c) + ", " + std::to_string(d)) +
                  "\n";
      }
  return "*UNIT_SYSTEM\nSI\n*TIME\n0.002\n*NODE\n" + nodes + "*ELEMENT_SHELL\n" + shells +
         R"(*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"folded shell"
1, 1, , 0.01
*CONTACT
1
P, 1, P, 1, 0.0, 1.0e10
*CONTACT_INITIAL
1, FORCE
*CONTACT_GAP
1, )" + std::to_string(igap) +
         "\n*END\n";
}

TEST(ShellSelfContact, Igap2IgnoresTheFoldsOwnOtherLeg) {
  double kinetic[3] = {};
  for (const int igap : {1, 2}) {
    const Model model = read_deck_string(folded_shell(igap), "folded_shell.k");
    Simulation sim(model);
    double largest = 0.0;
    verification::run_to(sim, model.time.end_time, [&](const Simulation& s) {
      largest = std::max(largest, s.energies().kinetic);
    });
    kinetic[igap] = largest;
    std::cout << "igap " << igap << ": largest kinetic energy " << largest << " J\n";
  }
  EXPECT_GT(kinetic[1], 1e-3);   // igap 1: the fold's legs push each other (the V opens)
  EXPECT_LT(kinetic[2], 1e-20);  // igap 2: at rest
}

}  // namespace
}  // namespace abut
