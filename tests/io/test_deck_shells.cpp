// Shells in the deck: *ELEMENT_SHELL, *PART h, *PART_SHELL, *COMPONENT_SHELL_PLATE and
// *COMPONENT_SHELL_TUBE read right, and every error at its file:line and field.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "abut/mesh/shell_generators.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::deck_path;
using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;

// Line numbers below count from here: line 1 is *UNIT_SYSTEM, the *PART row is line 8.
const std::string kHead = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1, , 0.002
*NODE
1, 0.0, 0.0, 0.0
2, 1.0, 0.0, 0.0
3, 1.0, 1.0, 0.0
4, 0.0, 1.0, 0.0
5, 2.0, 0.0, 0.0
6, 3.0, 0.0, 0.0
)";
// The first *ELEMENT_SHELL row is on line 17.
const std::string kShells = kHead + "*ELEMENT_SHELL\n";

void expect_error_at(const std::string& deck, std::size_t line, const std::string& field,
                     const std::string& message) {
  const InputError e = error_of(deck);
  EXPECT_EQ(e.where().line, line) << e.what();
  EXPECT_EQ(e.where().field, field) << e.what();
  EXPECT_THAT(e.message(), HasSubstr(message)) << e.what();
}

TEST(DeckShells, QuadsAndTrianglesInTheirThreeForms) {
  const Model m = model_of(kShells + "7, 1, 1, 2, 3, 4\n8, 1, 2, 5, 3\n9, 1, 2, 5, 3, 0\n" +
                           "10, 1, 2, 5, 3, 3\n");
  ASSERT_EQ(m.mesh.shell_count(), 4u);
  EXPECT_EQ(m.mesh.shells[0], (Quad4{0, 1, 2, 3}));
  for (std::size_t s = 1; s < 4; ++s) EXPECT_EQ(m.mesh.shells[s], (Quad4{1, 4, 2, 2}));
  EXPECT_EQ(m.mesh.shell_id[3], 10);
  EXPECT_EQ(m.mesh.shell_part[0], 1);
  EXPECT_DOUBLE_EQ(m.parts.at(0).thickness, 0.002);
  EXPECT_EQ(m.parts.at(0).shell_points, 5);
  EXPECT_DOUBLE_EQ(m.parts.at(0).shell_hourglass, 0.01);
  EXPECT_EQ(m.mesh.hex_count(), 0u);
}

TEST(DeckShells, ShellIdsAreTheirOwnNamespace) {
  // A shell and a hex may carry the same id (as in LS-DYNA).
  const Model m = model_of(kShells + "1, 1, 1, 2, 3, 4\n*COMPONENT_BOX\n1, 2, 1, 1, 1\n" +
                           "5, 5, 5, 6, 6, 6\n*PART\n2, 1\n");
  EXPECT_EQ(m.mesh.hex_id.at(0), 1);
  EXPECT_EQ(m.mesh.shell_id.at(0), 1);
}

TEST(DeckShells, RepeatedNodesOtherThanTheTriangleAreErrors) {
  expect_error_at(kShells + "7, 1, 1, 2, 1, 4\n", 17, "n3", "node 1 repeats n1");
  expect_error_at(kShells + "7, 1, 1, 2, 3, 2\n", 17, "n4", "node 2 repeats n2");
  expect_error_at(kShells + "7, 1, 1, 1, 3, 4\n", 17, "n2", "repeats n1");
}

TEST(DeckShells, UnknownNodeDuplicateIdAndZeroArea) {
  expect_error_at(kShells + "7, 1, 1, 2, 99, 4\n", 17, "n3", "node 99 does not exist");
  expect_error_at(kShells + "7, 1, 1, 2, 3, 4\n7, 1, 2, 5, 3\n", 18, "",
                  "shell 7 is already defined");
  // Nodes 2, 5 and 6 lie on the x axis.
  expect_error_at(kShells + "7, 1, 1, 2, 3, 4\n8, 1, 2, 5, 6\n", 18, "", "shell 8 has zero area");
  expect_error_at(kShells + "7, 3, 1, 2, 3, 4\n", 17, "pid", "part 3 does not exist");
}

TEST(DeckShells, ShellPartsNeedTheirThickness) {
  const std::string no_h = R"(*TIME
1.0e-3
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
*COMPONENT_SHELL_PLATE
1, 1, 2, 2
0, 0, 0, 1, 0, 0
0, 1, 0
)";
  expect_error_at(no_h, 6, "h", "part 1 has shells: give their thickness h");
  expect_error_at(kShells + "7, 1, 1, 2, 3, 4\n*PART\n2, 1, , 0\n", 19, "h",
                  "expected a thickness h > 0");
}

TEST(DeckShells, HexahedraIgnoreTheThickness) {
  const Model m = model_of(std::string(testing::kBoxModel) + "*PART\n2, 1, , 0.5\n");
  EXPECT_DOUBLE_EQ(m.parts.at(1).thickness, 0.5);
}

TEST(DeckShells, ShellMaterialsAndPartsOfOneElementKind) {
  const std::string rubber = kShells + "7, 1, 1, 2, 3, 4\n*MAT_MOONEY_RIVLIN\n2, 1100, 2e9\n" +
                             "0.5e6, 0.1e6\n*PART\n2, 2, , 0.01\n";
  expect_error_at(rubber + "*ELEMENT_SHELL\n8, 2, 2, 5, 3\n", 22, "mid",
                  "*MAT_MOONEY_RIVLIN on shells (part 2) is not supported yet");
  for (const char* material : {"*MAT_RIGID\n2, 7800\n", "*MAT_JC\n2, 7800, 210e9, 0.3\n300e6\n"}) {
    const Model m = model_of(kShells + "7, 1, 1, 2, 3, 4\n" + material + "*PART\n2, 2, , 0.01\n" +
                             "*ELEMENT_SHELL\n8, 2, 2, 5, 3\n");
    EXPECT_EQ(m.mesh.shell_count(), 2u);
  }
  expect_error_at(kShells + "7, 1, 1, 2, 3, 4\n*COMPONENT_BOX\n1, 1, 1, 1, 1\n5, 5, 5, 6, 6, 6\n",
                  8, "", "part 1 holds both hexahedra and shells");
}

TEST(DeckShells, PartShellSetsPointsAndHourglass) {
  const Model m = model_of(kShells + "7, 1, 1, 2, 3, 4\n*PART_SHELL\n1, 3, 0.1\n");
  EXPECT_EQ(m.parts.at(0).shell_points, 3);
  EXPECT_DOUBLE_EQ(m.parts.at(0).shell_hourglass, 0.1);
  const Model d = model_of(kShells + "7, 1, 1, 2, 3, 4\n*PART_SHELL\n1\n");
  EXPECT_EQ(d.parts.at(0).shell_points, 5);
  EXPECT_DOUBLE_EQ(d.parts.at(0).shell_hourglass, 0.01);
}

TEST(DeckShells, PartShellErrors) {
  const std::string deck = kShells + "7, 1, 1, 2, 3, 4\n*PART_SHELL\n";
  expect_error_at(deck + "1, 4\n", 19, "nip", "expected an odd number");
  expect_error_at(deck + "1, 11\n", 19, "nip", "1 to 9");
  expect_error_at(deck + "1, 5, -0.1\n", 19, "q_hg", "expected a hourglass coefficient >= 0");
  expect_error_at(deck + "4, 5\n", 19, "pid", "part 4 does not exist");
  expect_error_at(deck + "1, 5\n1, 3\n", 20, "pid", "is already defined at t.k:19");
}

TEST(DeckShells, PartEntitiesIncludeShellNodes) {
  const Model m = model_of(kShells + "7, 1, 1, 2, 3, 4\n8, 1, 2, 5, 3\n" +
                           "*INITIAL_VELOCITY\nP, 1, 0, 0, -20\n");
  EXPECT_EQ(m.nodes_of({EntityType::Part, 1, {}}).size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(m.vz0[i], -20.0);
  EXPECT_DOUBLE_EQ(m.vz0[5], 0.0);  // node 6 is in no shell
}

TEST(DeckShells, ShellPartsAreContactSurfaces) {
  const std::string deck = kShells + "7, 1, 1, 2, 3, 4\n*COMPONENT_BOX\n1, 2, 1, 1, 1\n" +
                           "5, 5, 5, 6, 6, 6\n*PART\n2, 1\n*CONTACT\n1\n";
  for (const char* surfaces : {"P, 1, P, 2\n", "ALL, 0, ALL, 0\n", "P, 2, P, 1\n"})
    EXPECT_EQ(model_of(deck + surfaces).contacts.size(), 1u) << surfaces;
}

TEST(DeckShells, ShellNodesAsSecondaryNodesOfANodeToSurfaceContact) {
  const Model m = model_of(kShells + "7, 1, 1, 2, 3, 4\n*COMPONENT_BOX\n1, 2, 1, 1, 1\n" +
                           "5, 5, 5, 6, 6, 6\n*PART\n2, 1\n*SET_NODE\n9\n1, 2, 3, 4\n" +
                           "*CONTACT\n1\nNS, 9, P, 2\n*CONTACT_DISCRETIZATION\n1, N2S\n" +
                           "*BC_MOTION\nP, 1, XYZ\n");
  EXPECT_EQ(m.contacts.at(0).surface1.type, EntityType::NodeSet);
  EXPECT_EQ(m.nodes_of(m.motions.at(0).entity), (std::vector<std::int32_t>{0, 1, 2, 3}));
}

TEST(DeckShells, RefiningShellPartsIsNotSupportedYet) {
  const std::string deck = kShells + "7, 1, 1, 2, 3, 4\n";
  expect_error_at(deck + "*CHANGE_P-ORDER\nP, 1, 2\n", 19, "enid",
                  "*CHANGE_P-ORDER of shell parts (part 1) is not supported yet");
  // Hexes elsewhere may be refined with ALL; shells keep their nodes.
  const Model m = model_of(deck + "*COMPONENT_BOX\n1, 2, 1, 1, 1\n5, 5, 5, 6, 6, 6\n*PART\n2, 1\n" +
                           "*CHANGE_P-ORDER\nALL, 0, 2\n*SMOOTH_MESH\nALL, 0, 30\n");
  EXPECT_EQ(m.mesh.hex_count(), 8u);
  EXPECT_EQ(m.mesh.shells.at(0), (Quad4{0, 1, 2, 3}));
  expect_error_at(deck + "*SMOOTH_MESH\nP, 1, 30\n", 19, "enid",
                  "surface smoothing of shell parts (part 1) is not supported yet");
  // A hex that shares nodes with a shell is not refined: the shell would lose its connection.
  const std::string attached = deck + "*ELEMENT_SOLID\n1, 2, 1, 2, 3, 4, 5, 6, 7, 8\n" +
                               "*NODE\n7, 2, 1, 1\n8, 0, 0, 1\n*PART\n2, 1\n";
  expect_error_at(attached + "*CHANGE_P-ORDER\nP, 2, 2\n", 26, "enid",
                  "hexahedron 1 of part 2 shares nodes with shells");
}

TEST(DeckShells, IncludeOffsetsAndMirrorKeepTheNormalsImage) {
  const Model m = read_deck(deck_path("include_shells.k"));
  ASSERT_EQ(m.mesh.shell_count(), 2u);
  EXPECT_EQ(m.mesh.shell_id[0], 1001);
  EXPECT_EQ(m.mesh.shell_id[1], 1002);
  const auto ids = [&m](const Quad4& q) {
    std::array<std::int64_t, 4> id{};
    for (std::size_t k = 0; k < 4; ++k) id[k] = m.mesh.nodes.id[static_cast<std::size_t>(q[k])];
    return id;
  };
  // Mirrored in z, the node order is reversed: the normals become -z, the mirror image of +z.
  EXPECT_EQ(ids(m.mesh.shells[0]), (std::array<std::int64_t, 4>{101, 104, 103, 102}));
  EXPECT_EQ(ids(m.mesh.shells[1]), (std::array<std::int64_t, 4>{102, 103, 105, 105}));
  for (const Quad4& q : m.mesh.shells) EXPECT_LT(shell_area_vector(m.mesh.nodes, q).z, 0.0);
}

const std::string kComponentHead = R"(*TIME
1.0e-3
*MAT_METAL
1, 7800.0, 210.0e9, 0.3
7
*CURVE
7
0, 300e6
1, 500e6
*PART
2, 1, , 0.0015
)";

TEST(DeckShells, PlateComponent) {
  const Model m = model_of(kComponentHead + "*NODE\n50, 9, 9, 9\n*COMPONENT_SHELL_PLATE\n" +
                           "\"plate\"\n1, 2, 4, 2\n0, 0, 0, 0.4, 0, 0\n0, 0.1, 0.1\n");
  EXPECT_EQ(m.mesh.nodes.size(), 1u + 15u);
  ASSERT_EQ(m.mesh.shell_count(), 8u);
  EXPECT_EQ(m.mesh.nodes.id[1], 51);
  EXPECT_EQ(m.mesh.shell_id[0], 1);
  double area = 0.0;
  for (const Quad4& q : m.mesh.shells) {
    const Vec3 a = shell_area_vector(m.mesh.nodes, q);
    area += norm(a);
    EXPECT_GT(dot(a, Vec3{0, -1, 1}), 0.0);  // (p1 - p0) x (p2 - p0) = 0.04 (0, -1, 1)
  }
  EXPECT_NEAR(area, 0.04 * std::sqrt(2.0), 1e-15);
}

TEST(DeckShells, TubeComponent) {
  const Model round = model_of(kComponentHead + "*COMPONENT_SHELL_TUBE\n1, 2, 10, 16\n" +
                               "0, 0, 0, 0, 0, 0.5\n0.05\n");
  EXPECT_EQ(round.mesh.nodes.size(), 16u * 11u);
  EXPECT_EQ(round.mesh.shell_count(), 160u);
  const Model square = model_of(kComponentHead + "*COMPONENT_SHELL_TUBE\n1, 2, 10, 8, square\n" +
                                "0, 0, 0, 0, 0, 0.5\n0.05\n");
  double area = 0.0;
  for (const Quad4& q : square.mesh.shells) area += norm(shell_area_vector(square.mesh.nodes, q));
  EXPECT_NEAR(area, 8 * 0.05 * 0.5, 1e-14);
}

TEST(DeckShells, ComponentErrors) {
  const std::string tube = kComponentHead + "*COMPONENT_SHELL_TUBE\n";  // data from line 13
  expect_error_at(tube + "1, 2, 10, 6, SQUARE\n0, 0, 0, 0, 0, 1\n0.1\n", 13, "n_circ",
                  "multiple of 4");
  expect_error_at(tube + "1, 2, 10, 6, OVAL\n0, 0, 0, 0, 0, 1\n0.1\n", 13, "shape",
                  "expected ROUND or SQUARE");
  expect_error_at(tube + "1, 2, 10, 2\n0, 0, 0, 0, 0, 1\n0.1\n", 13, "n_circ", "at least 3");
  expect_error_at(tube + "1, 2, 10, 8\n0, 0, 0, 0, 0, 1\n0\n", 15, "r", "expected a radius > 0");
  expect_error_at(tube + "1, 2, 10, 8\n0, 0, 1, 0, 0, 1\n0.1\n", 14, "x2", "differ");
  const std::string plate = kComponentHead + "*COMPONENT_SHELL_PLATE\n";
  const InputError e = error_of(plate + "1, 2, 2, 2\n0, 0, 0, 1, 0, 0\n2, 0, 0\n");
  EXPECT_EQ(e.where().line, 12u) << e.what();
  EXPECT_THAT(e.message(), HasSubstr("must not be parallel"));
  expect_error_at(plate + "1, 2, 2, 2\n0, 0, 0, 1, 0, 0\n0, 1, 0\n*COMPONENT_SHELL_PLATE\n" +
                      "1, 2, 2, 2\n0, 0, 1, 1, 0, 1\n0, 1, 1\n",
                  17, "coid", "component 1 is already defined");
}

}  // namespace
}  // namespace abut
