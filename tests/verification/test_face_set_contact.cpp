// Contact on a face set (*SET_FACE, entity FS; issue 33): a block pressed onto a plate whose
// contact surface is only a marked patch of its top (the faces with x < 0) transmits the force
// through that patch alone. References, chosen before the runs (statics of the contact as a set
// of facets, no closed form needed):
//   - every plate node outside the patch (not a corner of a marked face) gets no contact force,
//     exactly 0 at every cycle: the rest of the plate feels nothing;
//   - the contact forces on the block and on the patch are equal and opposite (to round-off);
//   - the patch does carry the block once it touches (force > 0), and only where the block is
//     over it: the block's nodes further than one element beyond the patch's edge (x > 5 mm on a
//     matched mesh) get nothing either.
// Matrix: surface-to-surface symmetric and one way, node to surface one way and symmetric; the
// face set as surface 2 (main) and as surface 1 (secondary); block mesh matched to the plate and
// offset by fractions of an element (7 mm of 5 mm elements shifted 0.37 and 0.61 of an element).
// The plate is rigid (held), the block elastic, driven down at 1 m/s into it.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

constexpr double kStep = 0.005;  // plate element size [m]
constexpr int kCells = 8;        // plate: 8 x 8 x 1 elements over [-20, 20]^2 x [-5, 0] mm

std::int64_t plate_node(int i, int j, int k) { return 1 + i + 9 * j + 81 * k; }

std::string plate_cards() {
  std::string deck = "*NODE\n";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j <= kCells; ++j)
      for (int i = 0; i <= kCells; ++i)
        deck += fmt::format("{}, {}, {}, {}\n", plate_node(i, j, k), -0.02 + kStep * i,
                            -0.02 + kStep * j, -kStep * (1 - k));
  deck += "*ELEMENT_SOLID\n";
  int e = 0;
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i)
      deck += fmt::format("{}, 2, {}, {}, {}, {}, {}, {}, {}, {}\n", ++e, plate_node(i, j, 0),
                          plate_node(i + 1, j, 0), plate_node(i + 1, j + 1, 0),
                          plate_node(i, j + 1, 0), plate_node(i, j, 1), plate_node(i + 1, j, 1),
                          plate_node(i + 1, j + 1, 1), plate_node(i, j + 1, 1));
  // The patch: the top faces with x < 0, as 4 corner node ids each.
  deck += "*SET_FACE\n\"patch\"\n11\n";
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells / 2; ++i)
      deck += fmt::format("{}, {}, {}, {}\n", plate_node(i, j, 1), plate_node(i + 1, j, 1),
                          plate_node(i + 1, j + 1, 1), plate_node(i, j + 1, 1));
  return deck;
}

struct Cell {
  const char* name;
  const char* method;       // *CONTACT_DISCRETIZATION method
  const char* symmetric;    // its symmetric field
  bool patch_is_main;       // the face set is surface 2 (else surface 1)
  double shift_x, shift_y;  // of the block, in elements
};

std::string deck_of(const Cell& c) {
  const double x0 = -0.01 + c.shift_x * kStep, y0 = -0.01 + c.shift_y * kStep;
  const std::string surfaces = c.patch_is_main ? "P, 1, FS, 11" : "FS, 11, P, 1";
  return "*UNIT_SYSTEM\nSI\n*TIME\n2.0e-4\n" + plate_cards() +
         fmt::format(R"(*COMPONENT_BOX
1, 1, 4, 4, 2
{}, {}, 1.0e-5, {}, {}, 0.01001
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*MAT_RIGID
2, 7800.0
*PART
"block"
1, 1
"plate"
2, 2
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, -1.0
*BC_MOTION
P, 2, XYZ, XYZ
*CONTACT
"block on the patch"
1
{}, 0.0, 1.0e13
*CONTACT_DISCRETIZATION
1, {}, {}
*END
)",
                     x0, y0, x0 + 0.02, y0 + 0.02, surfaces, c.method, c.symmetric);
}

class FaceSetContact : public ::testing::TestWithParam<Cell> {};

TEST_P(FaceSetContact, TheForceGoesThroughThePatchAlone) {
  const Cell& c = GetParam();
  const Model model = read_deck_string(deck_of(c), "patch.k");
  ASSERT_EQ(model.face_sets.size(), 1u);
  ASSERT_EQ(model.face_sets[0].faces.size(), static_cast<std::size_t>(kCells * kCells / 2));
  const Mesh& mesh = model.mesh;
  // Plate nodes: the first 162; the patch's are the top nodes with x <= 0.
  std::vector<int> role(mesh.nodes.size(), 0);  // 1 patch, 2 rest of the plate, 3 block far
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    const double x = mesh.nodes.x[n], z = mesh.nodes.z[n];
    if (n < 162) {
      role[n] = (z > -1e-9 && x < 1e-9) ? 1 : 2;
    } else if (c.shift_x == 0.0 && x > kStep + 1e-9) {
      role[n] = 3;
    }
  }
  Simulation sim(model);
  std::vector<double> force, pressure, wear;
  double most = 0.0;
  int cycles_in_contact = 0;
  while (!sim.finished()) {
    sim.advance();
    sim.contact_fields(force, pressure, wear);
    Vec3 on_patch, on_block;
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
      const Vec3 f{force[3 * n], force[3 * n + 1], force[3 * n + 2]};
      if (role[n] == 2 || role[n] == 3) {
        ASSERT_EQ(norm(f), 0.0) << c.name << ": node " << mesh.nodes.id[n] << " (x "
                                << mesh.nodes.x[n] << ") at t = " << sim.time();
      }
      (n < 162 ? on_patch : on_block) += f;
    }
    ASSERT_NEAR(on_patch.z, -on_block.z, 1e-9 * std::max(1.0, std::abs(on_block.z)));
    if (on_block.z > 0.0) ++cycles_in_contact;
    most = std::max(most, on_block.z);
  }
  // The block reached the patch and was pushed back (about 10 kN at the end).
  EXPECT_GT(cycles_in_contact, 10) << c.name;
  EXPECT_GT(most, 1e3) << c.name;
  std::cout << c.name << ": largest push " << most << " N over " << cycles_in_contact
            << " cycles\n";
}

INSTANTIATE_TEST_SUITE_P(
    Matrix, FaceSetContact,
    ::testing::Values(Cell{"S2S_symmetric_main", "S2S", "1", true, 0.0, 0.0},
                      Cell{"S2S_one_way_main", "S2S", "0", true, 0.0, 0.0},
                      Cell{"N2S_one_way_main", "N2S", "0", true, 0.0, 0.0},
                      Cell{"N2S_symmetric_main", "N2S", "1", true, 0.0, 0.0},
                      Cell{"S2S_symmetric_secondary", "S2S", "1", false, 0.0, 0.0},
                      Cell{"S2S_one_way_secondary", "S2S", "0", false, 0.0, 0.0},
                      Cell{"N2S_one_way_secondary", "N2S", "0", false, 0.0, 0.0},
                      Cell{"S2S_symmetric_main_offset", "S2S", "1", true, 0.37, 0.61},
                      Cell{"N2S_one_way_main_offset", "N2S", "0", true, 0.37, 0.61},
                      Cell{"S2S_one_way_secondary_offset", "S2S", "0", false, 0.37, 0.61}),
    [](const ::testing::TestParamInfo<Cell>& cell) { return std::string(cell.param.name); });

}  // namespace
}  // namespace abut
