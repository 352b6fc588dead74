// *CONTACT_RELEASE_BC (Radioss /INTER/TYPE25 IBCX, IBCY, IBCZ, seed 004): the fixed directions of
// a contact's secondary nodes are released when each node first touches.
//
// Model: an elastic slab (0.1 x 0.1 x 0.02 m, 8 x 8 x 2 hexahedra, E = 10 MPa) with its bottom
// nodes fixed and every top node held in z (*BC_MOTION Z). A rigid punch over the centre of the
// slab (0.03 to 0.07 m in x and y: 3 x 3 top nodes below it) starts 1 mm above the top and moves
// down at 1 m/s, so it meets the top at t = 1 ms and has gone 4 mm further at 5 ms. Node-to-surface
// contact, the top nodes against the punch, penalty 1e11 Pa/m. References, chosen before running:
//  - released in z (IBCZ = 1): the 9 nodes under the punch follow it: at 5 ms each has moved down
//    by the punch's travel beyond the top (4 mm) less its penetration, which is at most the
//    contact's deepest penetration (ContactStats::max_penetration);
//  - the held top nodes beside the punch never touch it: they keep their z exactly;
//  - without the release, the nodes under the punch keep their z exactly too (the constraint wins
//    and the punch sinks into them);
//  - the constraints' reactions stop doing work when they are released: the energy balance stays
//    within 1% (the bound of the other contact verification problems).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kTravel = 0.004;  // punch travel beyond the slab's top at the end time

std::string slab_deck(const std::string& top_ids, const std::string& bottom_ids,
                      const std::string& extra) {
  return R"(*TIME
0.005
*COMPONENT_BOX
1, 1, 8, 8, 2
0.0, 0.0, 0.0, 0.1, 0.1, 0.02
*COMPONENT_BOX
2, 2, 1, 1, 1
0.03, 0.03, 0.021, 0.07, 0.07, 0.031
*MAT_ELASTIC
1, 1000.0, 1.0e7, 0.3
*MAT_RIGID
2, 7800.0
*PART
"slab"
1, 1
"punch"
2, 2
*SET_NODE
1
)" + top_ids +
         R"(
*SET_NODE
2
)" + bottom_ids +
         R"(
*BC_MOTION
NS, 2, XYZ
*BC_MOTION
NS, 1, Z
*BC_MOTION
P, 2, XY, XYZ
V, Z, 1
*CURVE
1
0.0, -1.0
1.0, -1.0
*CONTACT
"punch on slab"
1
NS, 1, P, 2, 0.0, 1.0e11
*CONTACT_DISCRETIZATION
1, N2S
)" + extra +
         "*END\n";
}

struct Result {
  double worst_balance = 0.0, final_balance = 0.0, max_penetration = 0.0;
  double under_min = 0.0, under_max = 0.0;  // displacement in z of the nodes under the punch
  double beside_max = 0.0;                  // largest |displacement in z| of the other top nodes
  int under = 0;
  std::vector<double> z;  // final positions
};

Result run(bool release) {
  // The generator numbers the nodes: find the top and bottom ones in a first read.
  const Model probe = read_deck_string(slab_deck("1", "1", ""), "probe.k");
  std::string top, bottom;
  const auto& n = probe.mesh.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (n.z[i] > 0.02 - 1e-9 && n.z[i] < 0.02 + 1e-9) top += std::to_string(n.id[i]) + ", ";
    if (std::abs(n.z[i]) < 1e-9) bottom += std::to_string(n.id[i]) + ", ";
  }
  top.resize(top.size() - 2);
  bottom.resize(bottom.size() - 2);
  const Model model = read_deck_string(
      slab_deck(top, bottom, release ? "*CONTACT_RELEASE_BC\n1, 0, 0, 1\n" : ""), "release.k");
  Simulation sim(model);
  Result r;
  // The punch's work is of the order of 1 J (a few kN over a few mm): the balance counts from
  // 1e-3 J on.
  r.worst_balance = verification::worst_energy_balance(sim, 1.0);
  r.final_balance = sim.energy_balance_error();
  r.z = sim.z();
  r.max_penetration = sim.contact_reports()[0].stats.max_penetration;
  r.under_min = 1.0;
  r.under_max = -1.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!(n.z[i] > 0.02 - 1e-9 && n.z[i] < 0.02 + 1e-9)) continue;
    const double u = sim.z()[i] - n.z[i];
    const bool below = n.x[i] > 0.03 && n.x[i] < 0.07 && n.y[i] > 0.03 && n.y[i] < 0.07;
    if (below) {
      ++r.under;
      r.under_min = std::min(r.under_min, u);
      r.under_max = std::max(r.under_max, u);
    } else {
      r.beside_max = std::max(r.beside_max, std::abs(u));
    }
  }
  return r;
}

TEST(ContactReleaseBc, NodesUnderThePunchFollowItWhileTheHeldNeighboursStay) {
  const Result released = run(true), held = run(false);
  std::cout << "released: " << released.under << " nodes under the punch moved "
            << released.under_min << " to " << released.under_max << " m (punch travel " << -kTravel
            << " m, deepest penetration " << released.max_penetration
            << " m); held neighbours moved at most " << released.beside_max
            << " m; worst energy balance " << 100.0 * released.worst_balance << "%, at the end "
            << 100.0 * released.final_balance << "%\n"
            << "held: nodes under the punch moved " << held.under_min << " to " << held.under_max
            << " m, deepest penetration " << held.max_penetration << " m; worst energy balance "
            << 100.0 * held.worst_balance << "%, at the end " << 100.0 * held.final_balance
            << "%\n";
  EXPECT_EQ(released.under, 9);
  EXPECT_GE(released.under_min, -kTravel - 1e-12);
  // The deepest node meets this bound exactly: allow the round-off of z - z0.
  EXPECT_LE(released.under_max, -kTravel + released.max_penetration + 1e-12);
  EXPECT_EQ(released.beside_max, 0.0);
  EXPECT_LT(released.worst_balance, 0.01);
  EXPECT_LT(std::abs(released.final_balance), 0.01);
  EXPECT_EQ(held.under_min, 0.0);
  EXPECT_EQ(held.under_max, 0.0);
  EXPECT_EQ(held.beside_max, 0.0);
}

// The release is decided serially after the contact's forces: 1 and 2 threads agree bit for bit.
TEST(ContactReleaseBc, OneAndTwoThreadsGiveBitwiseIdenticalResults) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const Result one = run(true);
  omp_set_num_threads(2);
  const Result two = run(true);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.z.size(), two.z.size());
  EXPECT_EQ(std::memcmp(one.z.data(), two.z.data(), one.z.size() * sizeof(double)), 0);
}

}  // namespace
}  // namespace abut
