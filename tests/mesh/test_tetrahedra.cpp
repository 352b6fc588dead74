// *CHANGE_TO_TETRAHEDRA: hexahedra cut into tetrahedra with every quadrilateral face cut along
// the diagonal through its lowest node (Dompierre et al. 1999, see mesh/tetrahedra.hpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <numeric>

#include "abut/core/error.hpp"
#include "abut/mesh/generators.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/mesh/tetrahedra.hpp"

namespace abut {
namespace {

using ::testing::HasSubstr;

constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

int volume6(const std::array<std::int8_t, 4>& t) {  // 6 x volume on the unit cube, exact
  int d[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) d[r][c] = kCorner[t[r + 1]][c] - kCorner[t[0]][c];
  return d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
         d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
         d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
}

// The cube face a triangle lies on (0..5 as axis * 2 + side), or -1 inside the cube.
int cube_face(std::array<int, 3> tri) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      if (std::all_of(tri.begin(), tri.end(), [&](int n) { return kCorner[n][axis] == side; }))
        return axis * 2 + side;
  return -1;
}

// Every one of the 8! orders of a hex's nodes: the tetrahedra are positive and fill the cube
// (their volumes add up to 1 exactly), inner triangles are shared by two tetrahedra, and each
// cube face is covered by two triangles that both hold the face's lowest node (the diagonal
// through it), so that a neighbour ranking the same four nodes cuts it alike.
TEST(HexTetrahedra, EveryNodeOrderFillsTheCubeAndCutsEachFaceThroughItsLowestNode) {
  std::array<std::int32_t, 8> rank;
  std::iota(rank.begin(), rank.end(), 0);
  int orders = 0, five = 0;
  do {
    const HexTetrahedra cut = hex_tetrahedra(rank);
    ASSERT_TRUE(cut.count == 5 || cut.count == 6);
    five += cut.count == 5;
    int volume = 0;
    std::map<std::array<int, 3>, int> triangles;
    for (int t = 0; t < cut.count; ++t) {
      const auto& tet = cut.tets[static_cast<std::size_t>(t)];
      ASSERT_GT(volume6(tet), 0);
      volume += volume6(tet);
      for (int skip = 0; skip < 4; ++skip) {
        std::array<int, 3> tri;
        for (int a = 0, k = 0; a < 4; ++a)
          if (a != skip) tri[static_cast<std::size_t>(k++)] = tet[a];
        std::sort(tri.begin(), tri.end());
        ++triangles[tri];
      }
    }
    ASSERT_EQ(volume, 6);
    std::array<int, 6> on_face{};
    for (const auto& [tri, uses] : triangles) {
      const int face = cube_face(tri);
      if (face < 0) {
        ASSERT_EQ(uses, 2);
        continue;
      }
      ASSERT_EQ(uses, 1);
      ++on_face[static_cast<std::size_t>(face)];
      int lowest = -1;  // the face's lowest node
      for (int n = 0; n < 8; ++n)
        if (kCorner[n][face / 2] == face % 2 && (lowest < 0 || rank[n] < rank[lowest])) lowest = n;
      ASSERT_NE(std::find(tri.begin(), tri.end(), lowest), tri.end());
    }
    for (const int n : on_face) ASSERT_EQ(n, 2);
    ++orders;
  } while (std::next_permutation(rank.begin(), rank.end()));
  EXPECT_EQ(orders, 40320);
  // The 5-tetrahedron cut happens when no face through the far corner D is cut through it,
  // i.e. each such face's lowest node is one of its two nodes that are neither D nor on an edge
  // from the lowest node O. Among the 7 nodes other than O the lowest must then be one of the 3
  // face-diagonal neighbours of O (it settles two faces: 3/7), and the third face's lowest of its
  // 4 nodes one of its 2 such nodes (1/2): 3/14 of the orders.
  EXPECT_EQ(five, 40320 * 3 / 14);
}

// Triangles used by the tetrahedra of a mesh: (sorted corner nodes) -> number of uses.
std::map<std::array<std::int32_t, 3>, int> triangle_uses(const Mesh& mesh) {
  std::map<std::array<std::int32_t, 3>, int> uses;
  for (const CellBlock& block : mesh.cells) {
    for (std::size_t c = 0; c < block.size(); ++c) {
      const auto cell = block.cell(c);
      for (int skip = 0; skip < 4; ++skip) {
        std::array<std::int32_t, 3> tri;
        for (int a = 0, k = 0; a < 4; ++a)
          if (a != skip) tri[static_cast<std::size_t>(k++)] = cell[static_cast<std::size_t>(a)];
        std::sort(tri.begin(), tri.end());
        ++uses[tri];
      }
    }
  }
  return uses;
}

double volume_of_solids(const Mesh& mesh) {
  double v = 0.0;
  for (std::size_t e = 0; e < mesh.solid_count(); ++e) {
    const double ve = solid_volume(mesh, e);
    EXPECT_GT(ve, 0.0);
    v += ve;
  }
  return v;
}

Mesh sphere(int n, double radius) {  // the O-grid of 7 blocks: neighbours numbered differently
  SphereComponent s;
  s.part_id = 1;
  s.density = n;
  s.outer_radius = radius;
  Mesh mesh;
  generate_sphere(mesh, s);
  return mesh;
}

TetrahedraChange change(std::int64_t part, CellType type) {
  TetrahedraChange c;
  c.parts = {part};
  c.type = type;
  return c;
}

// The generated sphere (7 structured blocks meeting at differently oriented faces) cut into
// tetrahedra: conforming (every inner triangle shared by two tetrahedra; the exterior triangles
// are exactly two per exterior quadrilateral of the hexahedra), no inverted tetrahedron, the
// corner nodes unchanged. With 10 nodes the midside nodes lie on the exact sphere, so the volume
// error falls from the chordal one of the flat faces (reference: 4/3 pi R^3; the bound, a tenth
// of the 4-node error, chosen before the run).
TEST(Tetrahedra, GeneratedSphereConformsAndTenNodesFollowTheSphere) {
  constexpr double kR = 0.01;
  const double exact = 4.0 / 3.0 * std::numbers::pi * kR * kR * kR;
  const Mesh hexes = sphere(4, kR);
  const std::size_t exterior_quads = exterior_faces(hexes, false).size();
  double error[2] = {};
  for (const CellType type : {CellType::tet4, CellType::tet10}) {
    SCOPED_TRACE(topology(type).name);
    Mesh mesh = hexes;
    const auto notes = change_to_tetrahedra(mesh, {change(1, type)});
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_THAT(notes[0], HasSubstr(std::to_string(hexes.hex_count()) + " hexes cut into"));
    EXPECT_EQ(mesh.hex_count(), 0u);
    ASSERT_EQ(mesh.cells.size(), 1u);
    EXPECT_EQ(mesh.cells[0].type, type);
    EXPECT_GE(mesh.cells[0].size(), 5 * hexes.hex_count());
    EXPECT_LE(mesh.cells[0].size(), 6 * hexes.hex_count());
    std::size_t outer = 0;
    for (const auto& [tri, uses] : triangle_uses(mesh)) {
      ASSERT_LE(uses, 2);
      outer += uses == 1;
    }
    EXPECT_EQ(outer, 2 * exterior_quads);
    const double v = volume_of_solids(mesh);
    error[type == CellType::tet10] = (v - exact) / exact;
    if (type == CellType::tet10) {  // midside nodes on the sphere: |x| = R
      for (std::size_t n = hexes.nodes.size(); n < mesh.nodes.size(); ++n) {
        const double r = norm(mesh.nodes.position(n));
        if (std::abs(r - kR) < 0.02 * kR) {
          EXPECT_NEAR(r, kR, 1e-15);
        }
      }
    }
  }
  std::cout << "sphere N = 4: volume error tet4 " << 100.0 * error[0] << "%, tet10 "
            << 100.0 * error[1] << "%\n";
  EXPECT_LT(std::abs(error[1]), 0.1 * std::abs(error[0]));
}

// A box: the tetrahedra fill it exactly, 10-node midside nodes halve the edges, ids follow the
// largest id, boundary conditions carry over to midside nodes between two fixed nodes.
TEST(Tetrahedra, BoxVolumeIdsAndFixedMidsideNodes) {
  BoxComponent box;
  box.part_id = 3;
  box.nx = 3;
  box.ny = 2;
  box.nz = 2;
  box.corner1 = {0.0, 0.0, 0.0};
  box.corner2 = {3.0, 2.0, 1.0};
  Mesh mesh;
  generate_box(mesh, box);
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    if (mesh.nodes.x[n] == 0.0) mesh.nodes.fixed[n] = kFixX | kFixY;
  const std::int64_t next_id = mesh.next_hex_id();
  const std::size_t corner_nodes = mesh.nodes.size();
  change_to_tetrahedra(mesh, {change(3, CellType::tet10)});
  EXPECT_NEAR(volume_of_solids(mesh), 6.0, 1e-13);
  const CellBlock& tets = mesh.cells.at(0);
  EXPECT_EQ(tets.id.front(), next_id);
  EXPECT_EQ(tets.id.back(), next_id + static_cast<std::int64_t>(tets.size()) - 1);
  EXPECT_TRUE(std::all_of(tets.part.begin(), tets.part.end(), [](auto p) { return p == 3; }));
  for (std::size_t c = 0; c < tets.size(); ++c) {
    const auto cell = tets.cell(c);
    for (const EdgeTopology& e : topology(CellType::tet10).edges) {
      const auto a = static_cast<std::size_t>(cell[static_cast<std::size_t>(e.a)]),
                 b = static_cast<std::size_t>(cell[static_cast<std::size_t>(e.b)]),
                 m = static_cast<std::size_t>(cell[static_cast<std::size_t>(e.mid)]);
      ASSERT_GE(m, corner_nodes);
      EXPECT_LT(
          norm(mesh.nodes.position(m) - 0.5 * (mesh.nodes.position(a) + mesh.nodes.position(b))),
          1e-15);
      EXPECT_EQ(mesh.nodes.fixed[m], mesh.nodes.fixed[a] & mesh.nodes.fixed[b]);
    }
  }
}

// Half a body cut and half kept would leave triangles against quadrilaterals: refused.
TEST(Tetrahedra, PartlyCutBodyIsRefused) {
  BoxComponent box;
  box.part_id = 1;
  box.nx = 2;
  box.corner2 = {2.0, 1.0, 1.0};
  Mesh mesh;
  generate_box(mesh, box);
  TetrahedraChange c = change(1, CellType::tet4);
  c.region = Geometry{GeometryBox{{-1.0, -1.0, -1.0}, {1.0, 2.0, 2.0}}};
  try {
    change_to_tetrahedra(mesh, {c});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.message(), HasSubstr("would not conform"));
    EXPECT_THAT(e.message(), HasSubstr("kept"));
  }
}

}  // namespace
}  // namespace abut
