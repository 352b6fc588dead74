// *CONTACT gid_0 (seed 000): faces whose centroid lies outside the geometry gid_0 at t = 0 never
// take part in the contact.
//
// Model: two rigid blocks (parts 1 and 2, surface 1 = part set {1, 2}) move down at 1 m/s onto
// a fixed rigid plate (surface 2), no gravity. gid_0 is the box x <= 0, which holds block 1 and
// the plate facets under it but not block 2. Block 1 must bounce; block 2 must pass through the
// plate with its velocity untouched (exactly -1 m/s) and no force on its nodes, ever.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

const char* kDeck = R"(
*TIME
0.03
*COMPONENT_BOX
1, 1, 1, 1, 1
-0.15, -0.05, 0.001, -0.05, 0.05, 0.021
*COMPONENT_BOX
2, 2, 1, 1, 1
0.05, -0.05, 0.001, 0.15, 0.05, 0.021
*COMPONENT_BOX
3, 3, 6, 2, 1
-0.2, -0.1, -0.02, 0.2, 0.1, 0.0
*MAT_RIGID
1, 7800.0
*PART
"inside gid_0"
1, 1
"outside gid_0"
2, 1
"plate"
3, 1
*SET_PART
1
1, 2
*INITIAL_VELOCITY
PS, 1, 0.0, 0.0, -1.0
*BC_MOTION
P, 3, XYZ, XYZ
*GEOMETRY_BOX
7
-1.0, -1.0, -1.0, 0.0, 1.0, 1.0
*CONTACT
1
PS, 1, P, 3, 0.0, 1.0e9
0, 0.1, 7
*END
)";

TEST(ContactInitialRegion, FacesOutsideGidZeroNeverContact) {
  const Model model = read_deck_string(kDeck, "gid0.k");
  Simulation sim(model);
  std::vector<int> outside_nodes;  // the nodes of block 2 (part 2)
  for (std::size_t e = 0; e < model.mesh.hex_count(); ++e)
    if (model.mesh.hex_part[e] == 2)
      outside_nodes.insert(outside_nodes.end(), model.mesh.hexes[e].begin(),
                           model.mesh.hexes[e].end());
  double largest_force_outside = 0.0, lowest_z2 = 1.0;
  std::vector<double> force, pressure, wear;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    s.contact_fields(force, pressure, wear);
    for (int i : outside_nodes)
      largest_force_outside = std::max({largest_force_outside, std::abs(force[3 * i]),
                                        std::abs(force[3 * i + 1]), std::abs(force[3 * i + 2])});
    lowest_z2 = std::min(lowest_z2, s.part_states()[1].centre_of_mass.z);
  });
  const auto parts = sim.part_states();
  std::cout << "block inside gid_0: v_z " << parts[0].velocity.z
            << " m/s after the impact; block outside: v_z " << parts[1].velocity.z
            << " m/s, centre down to z = " << lowest_z2 << " m, largest contact force on its nodes "
            << largest_force_outside << " N\n";
  EXPECT_GT(parts[0].velocity.z, 0.5);  // bounced
  EXPECT_EQ(parts[1].velocity.z, -1.0);
  EXPECT_LT(lowest_z2, -0.005);  // its centre went below the plate's surface
  EXPECT_EQ(largest_force_outside, 0.0);
}

}  // namespace
}  // namespace abut
