// *MERGE_DUPLICATED_NODES: components that touch become one connected mesh, node sets and *NODE
// constraints follow the new numbering, a merge is reported in the notes, and every error of the
// command points at its file:line and field.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "abut/solver/simulation.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;
using testing::read;

// Two 2x2x2 boxes, part 1 on [0,1]^3 and part 2 next to it on x in [1,2]. Line 13 is the row of
// *MERGE_DUPLICATED_NODES.
const std::string kBoxes = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 1.0, 1.0, 1.0
*COMPONENT_BOX
2, 2, 2, 2, 2
1.0, 0.0, 0.0, 2.0, 1.0, 1.0
*MERGE_DUPLICATED_NODES
)";
const std::string kParts = R"(
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
*PART
2, 1
)";

std::set<std::int32_t> nodes_of_part(const Mesh& mesh, std::int64_t part) {
  std::set<std::int32_t> nodes;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h)
    if (mesh.hex_part[h] == part) nodes.insert(mesh.hexes[h].begin(), mesh.hexes[h].end());
  for (std::size_t s = 0; s < mesh.shell_count(); ++s)
    if (mesh.shell_part[s] == part) nodes.insert(mesh.shells[s].begin(), mesh.shells[s].end());
  return nodes;
}

void expect_error_at(const std::string& deck, std::size_t line, const std::string& field,
                     const std::string& message) {
  const InputError e = error_of(deck);
  EXPECT_EQ(e.where().file, "t.k") << e.what();
  EXPECT_EQ(e.where().line, line) << e.what();
  EXPECT_EQ(e.where().field, field) << e.what();
  EXPECT_THAT(e.message(), HasSubstr(message)) << e.what();
}

TEST(DeckMerge, TwoBoxesFaceToFaceBecomeOneMesh) {
  const DeckResult r = read(kBoxes + "P, 2, P, 1, 1.0e-6" + kParts);
  const Mesh& mesh = r.model.mesh;
  // 27 + 27 nodes, of which the 3 x 3 of the common face are now shared.
  EXPECT_EQ(mesh.nodes.size(), 45u);
  EXPECT_EQ(mesh.hex_count(), 16u);
  const std::set<std::int32_t> a = nodes_of_part(mesh, 1), b = nodes_of_part(mesh, 2);
  std::vector<std::int32_t> shared;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(shared));
  ASSERT_EQ(shared.size(), 9u);
  for (const std::int32_t n : shared) EXPECT_EQ(mesh.nodes.x[static_cast<std::size_t>(n)], 1.0);
  // The nodes of box 1 (ids 1 to 27) stay; the face nodes of box 2 are gone.
  for (const std::int32_t n : shared) EXPECT_LE(mesh.nodes.id[static_cast<std::size_t>(n)], 27);
  for (const Hex8& h : mesh.hexes)
    for (const std::int32_t n : h) EXPECT_LT(static_cast<std::size_t>(n), mesh.nodes.size());
  EXPECT_THAT(r.notes, ::testing::Contains("*MERGE_DUPLICATED_NODES at t.k:12 merged 9 nodes"));
  EXPECT_EQ(r.model.vx0.size(), 45u);
}

TEST(DeckMerge, RefinementAfterTheMergeSharesTheNewInterfaceNodes) {
  // Merged first, refined after: the two boxes become one 8 x 4 x 4 lattice.
  const DeckResult r = read(kBoxes + "P, 2, P, 1, 1.0e-6\n*CHANGE_P-ORDER\nALL, , 2" + kParts);
  EXPECT_EQ(r.model.mesh.hex_count(), 128u);
  EXPECT_EQ(r.model.mesh.nodes.size(), 9u * 5u * 5u);
}

TEST(DeckMerge, DefaultToleranceAndAllNodesOfOtherEntities) {
  // tol empty: 1e-6 of the model's diagonal. ALL as m: every node of s is also in m and stays.
  EXPECT_EQ(model_of(kBoxes + "P, 2, P, 1" + kParts).mesh.nodes.size(), 45u);
  EXPECT_EQ(model_of(kBoxes + "P, 2, ALL, , 1.0e-6" + kParts).mesh.nodes.size(), 54u);
  // A tolerance below the gap between the boxes merges nothing, and says so.
  const DeckResult apart = read(R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 1.0, 1.0, 1.0
*COMPONENT_BOX
2, 2, 2, 2, 2
1.001, 0.0, 0.0, 2.0, 1.0, 1.0
*MERGE_DUPLICATED_NODES
PS, 7, P, 1, 1.0e-4
P, 2, P, 1, 1.0e-4
*SET_PART
7
3
)" + kParts + "*PART\n3, 1\n");
  EXPECT_EQ(apart.model.mesh.nodes.size(), 54u);
  EXPECT_THAT(apart.notes,
              ::testing::Contains("*MERGE_DUPLICATED_NODES at t.k:12: PS 7 has no nodes"));
  EXPECT_THAT(apart.notes,
              ::testing::Contains("*MERGE_DUPLICATED_NODES at t.k:13 merged no nodes: no node of P "
                                  "2 lies within 0.0001 of a node of P 1"));
}

TEST(DeckMerge, PlateClosesTheEndOfASquareTube) {
  // Tube along z with a 1 x 1 square section of 8 elements around; the plate of 2 x 2 shells
  // covers its end z = 2 with the same spacing, so its 8 boundary nodes lie on the end section.
  const Model m = model_of(R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1, , 0.002
*PART
2, 1, , 0.002
*COMPONENT_SHELL_TUBE
1, 1, 4, 8, SQUARE
0.0, 0.0, 0.0, 0.0, 0.0, 2.0
0.5
*COMPONENT_SHELL_PLATE
2, 2, 2, 2
-0.5, -0.5, 2.0, 0.5, -0.5, 2.0
-0.5, 0.5, 2.0
*MERGE_DUPLICATED_NODES
P, 2, P, 1, 1.0e-6
)");
  const Mesh& mesh = m.mesh;
  EXPECT_EQ(mesh.nodes.size(), 8u * 5u + 9u - 8u);
  EXPECT_EQ(mesh.shell_count(), 32u + 4u);
  const std::set<std::int32_t> tube = nodes_of_part(mesh, 1), plate = nodes_of_part(mesh, 2);
  std::vector<std::int32_t> shared;
  std::set_intersection(tube.begin(), tube.end(), plate.begin(), plate.end(),
                        std::back_inserter(shared));
  ASSERT_EQ(shared.size(), 8u);
  for (const std::int32_t n : shared) EXPECT_EQ(mesh.nodes.z[static_cast<std::size_t>(n)], 2.0);
  // The one plate node left of its own is the centre of the end.
  std::vector<std::int32_t> own;
  std::set_difference(plate.begin(), plate.end(), tube.begin(), tube.end(),
                      std::back_inserter(own));
  ASSERT_EQ(own.size(), 1u);
  EXPECT_NEAR(mesh.nodes.x[static_cast<std::size_t>(own[0])], 0.0, 1e-12);
  EXPECT_NEAR(mesh.nodes.y[static_cast<std::size_t>(own[0])], 0.0, 1e-12);
}

// Two unit cubes given node by node; nodes 11, 14, 15, 18 of the second duplicate 2, 3, 6, 7.
const std::string kCubes = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*NODE
1, 0.0, 0.0, 0.0
2, 1.0, 0.0, 0.0, X
3, 1.0, 1.0, 0.0
4, 0.0, 1.0, 0.0
5, 0.0, 0.0, 1.0
6, 1.0, 0.0, 1.0
7, 1.0, 1.0, 1.0
8, 0.0, 1.0, 1.0
11, 1.0, 0.0, 0.0, YZ
12, 2.0, 0.0, 0.0, Z
13, 2.0, 1.0, 0.0
14, 1.0, 1.0, 0.0
15, 1.0, 0.0, 1.0
16, 2.0, 0.0, 1.0
17, 2.0, 1.0, 1.0
18, 1.0, 1.0, 1.0
*ELEMENT_SOLID
1, 1, 1, 2, 3, 4, 5, 6, 7, 8
2, 1, 11, 12, 13, 14, 15, 16, 17, 18
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
*SET_NODE
5
11, 12, 13, 14, 15, 16, 17, 18
*SET_NODE
6
1, 2, 3, 4, 5, 6, 7, 8
*SET_NODE
7
11, 12, 2
*MERGE_DUPLICATED_NODES
NS, 5, NS, 6, 0.01
)";

std::int32_t index_of(const Model& m, std::int64_t id) {
  const auto& ids = m.mesh.nodes.id;
  const auto it = std::find(ids.begin(), ids.end(), id);
  return it == ids.end() ? -1 : static_cast<std::int32_t>(it - ids.begin());
}

TEST(DeckMerge, NodeSetsConstraintsAndVelocitiesFollowTheRemap) {
  const Model m = model_of(kCubes + "*INITIAL_VELOCITY\nNS, 7, 3.0\n");
  ASSERT_EQ(m.mesh.nodes.size(), 12u);
  for (const std::int64_t gone : {11, 14, 15, 18}) EXPECT_EQ(index_of(m, gone), -1);
  const std::int32_t n2 = index_of(m, 2), n12 = index_of(m, 12);
  EXPECT_EQ(m.mesh.hexes[1], (Hex8{n2, n12, index_of(m, 13), index_of(m, 3), index_of(m, 6),
                                   index_of(m, 16), index_of(m, 17), index_of(m, 7)}));
  // Set 7 was {11, 12, 2}: node 11 is node 2 now.
  const auto set7 = std::find_if(m.node_sets.begin(), m.node_sets.end(),
                                 [](const NodeSet& s) { return s.id == 7; });
  ASSERT_NE(set7, m.node_sets.end());
  EXPECT_EQ(set7->nodes, (std::vector<std::int32_t>{n2, n12}));
  // The constraints of both copies of node 2 add up; node 12 keeps its own.
  EXPECT_EQ(m.mesh.nodes.fixed[static_cast<std::size_t>(n2)], kFixX | kFixY | kFixZ);
  EXPECT_EQ(m.mesh.nodes.fixed[static_cast<std::size_t>(n12)], kFixZ);
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    const bool moving = static_cast<std::int32_t>(i) == n2 || static_cast<std::int32_t>(i) == n12;
    EXPECT_EQ(m.vx0[i], moving ? 3.0 : 0.0) << "node " << m.mesh.nodes.id[i];
  }
}

TEST(DeckMerge, ANodeThatIsGoneCannotBeNamed) {
  expect_error_at(kCubes + "*INITIAL_VELOCITY\nN, 14, 3.0\n", 41, "enid",
                  "node 14 was merged into node 3 by *MERGE_DUPLICATED_NODES at t.k:39");
}

TEST(DeckMerge, Errors) {
  const std::string deck = kBoxes;  // the data line is line 12
  expect_error_at(deck + "P, 2, P, 1, 0.0" + kParts, 12, "tol", "expected a distance tol > 0");
  expect_error_at(deck + "P, 2, P, 1, -1.0e-6" + kParts, 12, "tol", "tol > 0");
  expect_error_at(deck + "P, 2, P, 1, 1.0e-6, 1" + kParts, 12, "refine", "not supported yet");
  expect_error_at(deck + "G, 2, P, 1, 1.0e-6" + kParts, 12, "entype_s", "not supported yet");
  expect_error_at(deck + "P, 2, NS, 4, 1.0e-6" + kParts, 12, "enid_m", "node set 4 does not exist");
  expect_error_at(deck + "P, 9, P, 1, 1.0e-6" + kParts, 12, "enid_s", "part 9 does not exist");
  // A tolerance as large as an element joins its corners.
  expect_error_at(deck + "P, 2, P, 1, 0.6" + kParts, 12, "tol",
                  "would join two corners of hexahedron");
  expect_error_at(kBoxes, 11, "", "missing data line");
  // refine = 0 is the default.
  EXPECT_EQ(model_of(deck + "P, 2, P, 1, 1.0e-6, 0" + kParts).mesh.nodes.size(), 45u);
}

// A bar of two boxes end to end along x, the first moving at 10 m/s: only when their nodes are
// merged does the compression wave cross into the second box and reach its far end.
std::string bar(bool merged) {
  return std::string(R"(*UNIT_SYSTEM
SI
*TIME
4.0e-4
*COMPONENT_BOX
1, 1, 10, 1, 1
0.0, 0.0, 0.0, 1.0, 0.1, 0.1
*COMPONENT_BOX
2, 2, 10, 1, 1
1.0, 0.0, 0.0, 2.0, 0.1, 0.1
*INITIAL_VELOCITY
P, 1, 10.0
)") + (merged ? "*MERGE_DUPLICATED_NODES\nP, 2, P, 1, 1.0e-6\n" : "") +
         kParts;
}

double far_end_velocity(bool merged) {
  const Model model = model_of(bar(merged));
  Simulation sim(model);
  while (!sim.finished()) sim.advance();
  double v = 0.0;
  for (std::size_t i = 0; i < sim.node_count(); ++i)
    if (model.mesh.nodes.x[i] > 2.0 - 1e-9) v = std::max(v, std::abs(sim.vx()[i]));
  return v;
}

TEST(DeckMerge, MergedBarCarriesTheWaveAcrossTheFormerInterface) {
  // c = sqrt(E / rho) = 5189 m/s: the front reaches x = 2 after 0.19 ms and doubles there.
  EXPECT_GT(far_end_velocity(true), 2.0);
  EXPECT_EQ(far_end_velocity(false), 0.0);
}

}  // namespace
}  // namespace abut
