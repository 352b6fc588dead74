// Joining coincident nodes: which node replaces which (nearest within tolerance, main nodes
// stay), and the compaction that follows (element connectivity, ids, constraints, new indices).
#include <gtest/gtest.h>

#include <vector>

#include "abut/mesh/generators.hpp"
#include "abut/mesh/node_removal.hpp"

namespace abut {
namespace {

Nodes line_of_nodes(const std::vector<double>& xs) {
  Nodes nodes;
  for (std::size_t i = 0; i < xs.size(); ++i)
    nodes.add(static_cast<std::int64_t>(10 + i), {xs[i], 0.0, 0.0});
  return nodes;
}

TEST(CoincidentReplacements, NearestMainNodeWithinTolerance) {
  // 0 and 1 are secondary; 2, 3, 4 are main. Node 0 has 2 and 3 within tolerance: 3 is nearer.
  const Nodes nodes = line_of_nodes({1.0, 5.0, 1.08, 1.03, 2.0});
  const std::vector<std::int32_t> r = coincident_replacements(nodes, {0, 1}, {2, 3, 4}, 0.1);
  EXPECT_EQ(r, (std::vector<std::int32_t>{3, -1, -1, -1, -1}));
}

TEST(CoincidentReplacements, TiesGoToTheLowestIndexAndSharedNodesStay) {
  // Node 0 is as far from 1 as from 2; node 3 is in both entities and stays.
  const Nodes nodes = line_of_nodes({1.0, 1.5, 0.5, 3.0});
  const std::vector<std::int32_t> r = coincident_replacements(nodes, {0, 3}, {2, 1, 3}, 0.6);
  EXPECT_EQ(r[0], 1);
  EXPECT_EQ(r[3], -1);
}

TEST(CoincidentReplacements, NothingBeyondTheTolerance) {
  const Nodes nodes = line_of_nodes({0.0, 0.2});
  const std::vector<std::int32_t> r = coincident_replacements(nodes, {0}, {1}, 0.1);
  EXPECT_EQ(r, (std::vector<std::int32_t>{-1, -1}));
  EXPECT_THROW(coincident_replacements(nodes, {0}, {1}, 0.0), std::invalid_argument);
}

TEST(CoincidentReplacements, EachPairWithinTheSmallerOfItsTwoTolerances) {
  // Node 0 (secondary, tolerance 0.1) and main nodes 1 (0.05 away, tolerance 0.01) and 2 (0.08
  // away, tolerance 1): 1 is nearer but beyond its own tolerance, so 2 takes the place.
  const Nodes nodes = line_of_nodes({1.0, 1.05, 0.92, 1.5});
  const std::vector<double> tol{0.1, 0.01, 1.0, 1.0};
  EXPECT_EQ(coincident_replacements(nodes, {0}, {1, 2}, tol),
            (std::vector<std::int32_t>{2, -1, -1, -1}));
  // Node 3 has a large tolerance, but node 0's own is the smaller of the pair.
  EXPECT_EQ(coincident_replacements(nodes, {3}, {0}, tol),
            (std::vector<std::int32_t>{-1, -1, -1, -1}));
  EXPECT_THROW(coincident_replacements(nodes, {0}, {1}, std::vector<double>{0.1, 0.0, 1.0, 1.0}),
               std::invalid_argument);
  EXPECT_THROW(coincident_replacements(nodes, {0}, {1}, std::vector<double>{0.1}),
               std::invalid_argument);
}

TEST(RemoveNodes, TwoBoxesShareTheirCommonFace) {
  Mesh mesh;
  BoxComponent a;
  a.part_id = 1;
  a.nx = a.ny = a.nz = 1;
  a.corner1 = {0, 0, 0};
  a.corner2 = {1, 1, 1};
  BoxComponent b = a;
  b.part_id = 2;
  b.corner1 = {1, 0, 0};
  b.corner2 = {2, 1, 1};
  generate_box(mesh, a);
  generate_box(mesh, b);
  ASSERT_EQ(mesh.nodes.size(), 16u);
  mesh.nodes.fixed[8] = kFixX;  // a node of box b at x = 1
  std::vector<std::int32_t> secondary, main;
  for (std::int32_t i = 0; i < 8; ++i) main.push_back(i);
  for (std::int32_t i = 8; i < 16; ++i) secondary.push_back(i);
  const std::vector<std::int32_t> replacement =
      coincident_replacements(mesh.nodes, secondary, main, 1e-6);
  const std::int32_t survivor_of_8 = replacement[8];
  ASSERT_GE(survivor_of_8, 0);
  mesh.nodes.fixed[static_cast<std::size_t>(survivor_of_8)] = kFixY;
  const std::vector<std::int64_t> ids = mesh.nodes.id;

  const std::vector<std::int32_t> new_index = remove_nodes(mesh, replacement);
  ASSERT_EQ(mesh.nodes.size(), 12u);
  ASSERT_EQ(new_index.size(), 16u);
  // The kept nodes keep their order, ids and coordinates; a removed node maps to its survivor.
  for (std::size_t i = 0; i < 16; ++i) {
    const std::int32_t kept = replacement[i] < 0 ? static_cast<std::int32_t>(i) : replacement[i];
    const auto n = static_cast<std::size_t>(new_index[i]);
    EXPECT_EQ(mesh.nodes.id[n], ids[static_cast<std::size_t>(kept)]);
  }
  EXPECT_EQ(mesh.nodes.fixed[static_cast<std::size_t>(new_index[8])], kFixX | kFixY);
  // The two hexes share the four nodes of the face x = 1, and every index is in range.
  int shared = 0;
  for (const std::int32_t p : mesh.hexes[0])
    for (const std::int32_t q : mesh.hexes[1]) shared += p == q;
  EXPECT_EQ(shared, 4);
  for (const Hex8& h : mesh.hexes) {
    for (const std::int32_t n : h) {
      EXPECT_GE(n, 0);
      EXPECT_LT(n, 12);
    }
  }
  for (std::size_t h = 0; h < 2; ++h) {
    for (std::size_t k = 0; k < 8; ++k) {
      EXPECT_EQ(mesh.nodes.position(static_cast<std::size_t>(mesh.hexes[h][k])).x,
                h == 0 ? (k == 1 || k == 2 || k == 5 || k == 6 ? 1.0 : 0.0)
                       : (k == 1 || k == 2 || k == 5 || k == 6 ? 2.0 : 1.0));
    }
  }
}

TEST(RemoveNodes, ShellsFollowAndAReplacementMustStay) {
  Mesh mesh;
  for (int i = 0; i < 6; ++i)
    mesh.nodes.add(i + 1, {static_cast<double>(i % 3), i < 3 ? 0.0 : 1.0, 0});
  mesh.nodes.add(7, {2.0, 0.0, 0.0});  // a copy of node index 2
  mesh.add_shell(1, 1, {0, 1, 4, 3});
  mesh.add_shell(2, 1, {1, 6, 5, 4});
  std::vector<std::int32_t> replacement(7, -1);
  replacement[6] = 2;
  const std::vector<std::int32_t> new_index = remove_nodes(mesh, replacement);
  EXPECT_EQ(new_index, (std::vector<std::int32_t>{0, 1, 2, 3, 4, 5, 2}));
  EXPECT_EQ(mesh.shells[1], (Quad4{1, 2, 5, 4}));
  EXPECT_EQ(mesh.nodes.size(), 6u);

  std::vector<std::int32_t> chained(6, -1);
  chained[0] = 1;
  chained[1] = 2;  // node 1 goes too: it cannot take node 0's place
  EXPECT_THROW(remove_nodes(mesh, chained), std::invalid_argument);
  EXPECT_THROW(remove_nodes(mesh, std::vector<std::int32_t>(5, -1)), std::invalid_argument);
}

}  // namespace
}  // namespace abut
