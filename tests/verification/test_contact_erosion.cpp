// Erosion seen by the contact (issue 9): a rigid punch (8 x 8 mm, 100 m/s) perforates a target of
// four layers of 10 mm hexes (3 x 3 per layer, perfectly plastic, eroding at a geometric strain of
// 0.3). IMPETUS *CONTACT no_internal (seed 000): with 0 the faces that an eroded element exposes
// become contact faces, so the punch meets each layer in turn and slows at each; with 1 only the
// target's original exterior takes part, so once the first layer has eroded under it the punch
// flies through the rest at constant speed. Reference: the rigid-body momentum balance itself
// (no force, constant velocity, to round-off) and the ordering of the layers.
//
// Nodal erosion (Abaqus/Explicit, seed 001: without it, nodes whose faces have all eroded stay in
// the contact domain as free point masses): a hex that erodes at once (dt_erode above its step)
// flies at a rigid wall. Its eight free nodes bounce off the wall (*CONTACT_EROSION free nodes
// KEEP, the default) or pass through it (REMOVE): momentum reversed or kept exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

std::string target_deck(int no_internal) {
  return R"(
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
, , , , , )" +
         std::to_string(no_internal) + "\n*END\n";
}

struct Perforation {
  std::vector<double> t, z, vz;  // the punch, every cycle
  std::size_t eroded = 0;
  double balance = 0.0;
};

Perforation perforate(int no_internal) {
  const Model model = read_deck_string(target_deck(no_internal), "layered_target.k");
  Simulation sim(model);
  Perforation r;
  verification::run_to(sim, model.time.end_time, [&r](const Simulation& s) {
    r.t.push_back(s.time());
    r.z.push_back(s.part_states()[0].centre_of_mass.z);
    r.vz.push_back(s.part_states()[0].velocity.z);
  });
  const auto eroded = sim.eroded_solids();
  r.eroded = static_cast<std::size_t>(std::count(eroded.begin(), eroded.end(), 1));
  r.balance = sim.energy_balance_error();
  std::cout << "no_internal " << no_internal << ": punch at " << r.vz.back() << " m/s, " << r.eroded
            << " hexes eroded, energy balance " << r.balance << "\n";
  return r;
}

// The punch's speed when its centre passes height z (its face 5 mm below).
double speed_at(const Perforation& r, double z) {
  for (std::size_t k = 0; k < r.z.size(); ++k)
    if (r.z[k] <= z) return -r.vz[k];
  return -r.vz.back();
}

TEST(ContactErosion, ExposedFacesStopThePunchLayerByLayer) {
  const Perforation r = perforate(0);
  // Between layers (face 1 mm above the next layer's original top) the punch flies freely; it
  // loses speed in every layer it crosses.
  const double after1 = speed_at(r, 0.036), after2 = speed_at(r, 0.026),
               after3 = speed_at(r, 0.016);
  EXPECT_LT(after1, 90.0);
  EXPECT_LT(after2, after1 - 5.0);
  EXPECT_LT(after3, after2 - 5.0);
  EXPECT_GE(r.eroded, 3u);
}

// The energy books (issue 27, item 5): the springs of facets that erode under the punch vanish
// with them; their energy goes to contact_released, so the balance closes at every cycle (against
// the impact's 1920 J).
TEST(ContactErosion, TheSpringsOfErodedFacetsStayInTheBooks) {
  const double impact = 0.5 * 6.0e5 * 0.008 * 0.008 * 0.01 * 100.0 * 100.0;
  const Model model = read_deck_string(target_deck(0), "layered_target_books.k");
  Simulation sim(model);
  const double worst = verification::worst_energy_balance(sim, impact);
  std::cout << "eroding target: released " << sim.energies().contact_released
            << " J; worst balance error " << 100.0 * worst << "%\n";
  EXPECT_GT(sim.energies().contact_released, 0.0);
  EXPECT_LT(worst, 0.01);
}

TEST(ContactErosion, WithoutInternalFacesThePunchFliesThroughAfterTheFirstLayer) {
  const Perforation r = perforate(1);
  // From the moment the first layer has eroded under it, nothing touches the punch: constant
  // velocity to round-off until the end (its face then 10 mm inside the target).
  const double after1 = speed_at(r, 0.036);
  EXPECT_LT(after1, 90.0);  // the first layer did stop it somewhat
  for (std::size_t k = 0; k < r.z.size(); ++k) {
    if (r.z[k] <= 0.036) {
      EXPECT_NEAR(-r.vz[k], after1, 1e-9 * after1) << "t = " << r.t[k];
    }
  }
  EXPECT_LT(r.z.back(), 0.02);
}

std::string free_nodes_deck(const std::string& free_nodes) {
  return R"(
*UNIT_SYSTEM
SI
*TIME
0.0016
*COMPONENT_BOX
1, 1, 2, 2, 1
-0.02, -0.02, -0.01, 0.02, 0.02, 0.0
*COMPONENT_BOX
2, 2, 1, 1, 1
-0.005, -0.005, 0.002, 0.005, 0.005, 0.012
*MAT_RIGID
1, 7800.0
*MAT_ELASTIC
2, 7800.0, 210.0e9, 0.3
*PART
"wall"
1, 1
"eroding hex"
2, 2, , , , 1.0
*BC_MOTION
P, 1, XYZ, XYZ
*INITIAL_VELOCITY
P, 2, 0.0, 0.0, -10.0
*CONTACT
1
P, 2, P, 1, 0.0, 1.0e12
*CONTACT_EROSION
1, , )" + free_nodes +
         "\n*END\n";
}

TEST(ContactErosion, FreeNodesBounceOffTheWallUnlessNodalErosionRemovesThem) {
  for (const std::string free_nodes : {"KEEP", "REMOVE"}) {
    const Model model = read_deck_string(free_nodes_deck(free_nodes), "free_nodes.k");
    Simulation sim(model);
    verification::run_to(sim, model.time.end_time);
    const auto eroded = sim.eroded_solids();
    ASSERT_EQ(eroded.back(), 1) << "the hex erodes at once";
    double vz = 0.0, z_min = 1.0;
    for (std::size_t i = 18; i < 26; ++i) {  // the hex's nodes, after the wall's 18
      vz += sim.vz()[i] / 8.0;
      z_min = std::min(z_min, sim.z()[i]);
    }
    std::cout << free_nodes << ": mean node velocity " << vz << " m/s, lowest node " << z_min
              << " m\n";
    if (free_nodes == "KEEP") {
      EXPECT_GT(vz, 5.0);       // every node bounced (xi = 0.1: restitution about 0.73)
      EXPECT_GT(z_min, -1e-3);  // none far into the wall
    } else {
      EXPECT_NEAR(vz, -10.0, 1e-9);  // no force at all: the initial momentum, exactly
      EXPECT_LT(z_min, -0.013);      // 2 mm to the wall, then 14 mm through it
    }
  }
}

}  // namespace
}  // namespace abut
