// The cell topology table (mesh/topology.hpp): its faces are outward and close the cell, its
// midside nodes sit halfway along their edges, and its VTK orders are permutations.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "abut/core/vec3.hpp"
#include "abut/mesh/topology.hpp"

namespace abut {
namespace {

Vec3 natural(const CellTopology& t, int a) {
  const auto& x = t.natural[static_cast<std::size_t>(a)];
  return {x[0], x[1], x[2]};
}

TEST(Topology, TableFollowsTheEnumeration) {
  for (const CellType type : kCellTypes) EXPECT_EQ(topology(type).type, type);
  const CellTopology& hex = topology(CellType::hex8);
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(hex.faces[f].nodes[k], kHexFaces[f][k]);
}

TEST(Topology, MidsideNodesHalfwayAlongTheirEdges) {
  for (const CellType type : kCellTypes) {
    const CellTopology& t = topology(type);
    SCOPED_TRACE(std::string(t.name));
    int midsides = 0;
    for (const EdgeTopology& e : t.edges) {
      EXPECT_LT(e.a, t.corners);
      EXPECT_LT(e.b, t.corners);
      if (e.mid < 0) continue;
      ++midsides;
      const Vec3 m = (natural(t, e.a) + natural(t, e.b)) * 0.5;
      EXPECT_EQ(natural(t, e.mid).x, m.x);
      EXPECT_EQ(natural(t, e.mid).y, m.y);
      EXPECT_EQ(natural(t, e.mid).z, m.z);
    }
    EXPECT_EQ(t.corners + midsides, t.nodes);
  }
}

// Each face's right-hand normal points away from the cell's centroid, the face's midside nodes
// are those of its corner edges, and the faces close the cell: every edge of a face is shared by
// exactly two faces, in opposite directions.
TEST(Topology, FacesAreOutwardAndCloseTheCell) {
  for (const CellType type : kCellTypes) {
    const CellTopology& t = topology(type);
    SCOPED_TRACE(std::string(t.name));
    Vec3 centre{};
    for (int a = 0; a < t.corners; ++a) centre += natural(t, a);
    centre = centre * (1.0 / t.corners);
    std::map<std::pair<int, int>, int> directed;
    for (const FaceTopology& f : t.faces) {
      const int c = face_corner_count(f.type);
      Vec3 mid{};
      for (int k = 0; k < c; ++k) mid += natural(t, f.nodes[k]);
      mid = mid * (1.0 / c);
      const Vec3 n = cross(natural(t, f.nodes[1]) - natural(t, f.nodes[0]),
                           natural(t, f.nodes[c - 1]) - natural(t, f.nodes[0]));
      EXPECT_GT(dot(n, mid - centre), 0.0);
      for (int k = 0; k < c; ++k) {
        const int a = f.nodes[k], b = f.nodes[(k + 1) % c];
        ++directed[{a, b}];
        if (f.size() > c) {
          const auto e =
              std::find_if(t.edges.begin(), t.edges.end(), [&](const EdgeTopology& edge) {
                return (edge.a == a && edge.b == b) || (edge.a == b && edge.b == a);
              });
          ASSERT_NE(e, t.edges.end());
          EXPECT_EQ(f.nodes[c + k], e->mid);
        }
      }
    }
    EXPECT_EQ(directed.size(), 2 * t.edges.size());
    for (const auto& [edge, count] : directed) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
    }
  }
}

TEST(Topology, VtkOrderIsAPermutation) {
  for (const CellType type : kCellTypes) {
    const CellTopology& t = topology(type);
    ASSERT_EQ(static_cast<int>(t.vtk_order.size()), t.nodes);
    std::set<int> seen(t.vtk_order.begin(), t.vtk_order.end());
    EXPECT_EQ(static_cast<int>(seen.size()), t.nodes);
    EXPECT_EQ(*seen.rbegin(), t.nodes - 1);
  }
}

}  // namespace
}  // namespace abut
