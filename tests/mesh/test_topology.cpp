// The cell topology table (mesh/topology.hpp): its faces are outward and close the cell, its
// midside nodes sit halfway along their edges, and its VTK orders are permutations.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

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
    if (!face_lattice(t.faces[0].type).empty()) continue;  // Lagrange: face and interior nodes
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
        if (f.size() > c && t.order == 2) {
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

// The Lagrange hexahedra: their nodes are the (p + 1)^3 lattice once each; each face node sits
// where the face's lattice puts it (corner 0 plus s/p of the way to corner 1 and t/p to corner
// 3); and the node order is VTK's. Reference places from VTK 9.1,
// vtkLagrangeHexahedron::PointIndexFromIJK(i, j, k, {p, p, p}) (printed with VTK's Python
// module): lattice place (i, j, k) of node index.
TEST(Topology, LagrangeHexahedraAreTheLatticeInVtkOrder) {
  struct Place {
    int node, i, j, k;
  };
  const std::vector<Place> hex27 = {{8, 1, 0, 0},  {10, 1, 2, 0}, {16, 0, 0, 1},
                                    {18, 2, 2, 1}, {20, 0, 1, 1}, {22, 1, 0, 1},
                                    {24, 1, 1, 0}, {25, 1, 1, 2}, {26, 1, 1, 1}};
  const std::vector<Place> hex64 = {{9, 2, 0, 0},  {12, 1, 3, 0}, {15, 0, 2, 0}, {25, 0, 0, 2},
                                    {29, 3, 3, 2}, {30, 0, 3, 1}, {33, 0, 2, 1}, {34, 0, 1, 2},
                                    {41, 2, 0, 1}, {47, 2, 3, 2}, {49, 2, 1, 0}, {55, 2, 2, 3},
                                    {56, 1, 1, 1}, {61, 2, 1, 2}, {63, 2, 2, 2}};
  for (const auto& [type, places] : {std::pair{CellType::hex27, hex27}, {CellType::hex64, hex64}}) {
    const CellTopology& t = topology(type);
    SCOPED_TRACE(std::string(t.name));
    const double p = t.order;
    ASSERT_EQ(t.nodes, (t.order + 1) * (t.order + 1) * (t.order + 1));
    std::set<std::array<double, 3>> lattice(t.natural.begin(), t.natural.end());
    EXPECT_EQ(static_cast<int>(lattice.size()), t.nodes);
    for (const auto& x : t.natural)
      for (const double c : x) EXPECT_EQ(std::round((c + 1) * p / 2) * 2 / p - 1, c);
    for (const Place& q : places) {
      const Vec3 x = natural(t, q.node);
      EXPECT_EQ(x.x, -1 + 2 * q.i / p) << "node " << q.node;
      EXPECT_EQ(x.y, -1 + 2 * q.j / p) << "node " << q.node;
      EXPECT_EQ(x.z, -1 + 2 * q.k / p) << "node " << q.node;
    }
    for (const FaceTopology& f : t.faces) {
      const auto st = face_lattice(f.type);
      ASSERT_EQ(static_cast<int>(st.size()), f.size());
      const Vec3 c0 = natural(t, f.nodes[0]), c1 = natural(t, f.nodes[1]),
                 c3 = natural(t, f.nodes[3]);
      for (int a = 0; a < f.size(); ++a) {
        const Vec3 expected = c0 + (c1 - c0) * (st[a][0] / p) + (c3 - c0) * (st[a][1] / p);
        EXPECT_NEAR(norm(natural(t, f.nodes[a]) - expected), 0.0, 1e-15);
      }
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
