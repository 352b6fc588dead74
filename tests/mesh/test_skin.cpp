#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "../element/cell_grid.hpp"
#include "abut/core/error.hpp"
#include "abut/mesh/shape_functions.hpp"
#include "abut/mesh/skin.hpp"

namespace abut {
namespace {

// A structured nx*ny*nz box of hexes with spacing (hx, hy, hz), origin at `o`, in part `part`.
// Nodes are shared with existing nodes at the same position so that stacked boxes are merged.
void add_box(Mesh& mesh, std::int64_t part, int nx, int ny, int nz, Vec3 o, Vec3 h) {
  std::map<std::array<long, 3>, std::int32_t> at;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    at[{std::lround(mesh.nodes.x[i] * 1e6), std::lround(mesh.nodes.y[i] * 1e6),
        std::lround(mesh.nodes.z[i] * 1e6)}] = static_cast<std::int32_t>(i);
  auto node = [&](int i, int j, int k) {
    const Vec3 p{o.x + i * h.x, o.y + j * h.y, o.z + k * h.z};
    const std::array<long, 3> key{std::lround(p.x * 1e6), std::lround(p.y * 1e6), std::lround(p.z * 1e6)};
    auto it = at.find(key);
    if (it != at.end()) return it->second;
    const std::int32_t n = mesh.nodes.add(mesh.next_node_id(), p);
    at[key] = n;
    return n;
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        mesh.hexes.push_back({node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                              node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                              node(i, j + 1, k + 1)});
        mesh.hex_id.push_back(mesh.next_hex_id());
        mesh.hex_part.push_back(part);
        mesh.hex_shape.push_back(-1);
      }
}

Vec3 centroid(const Mesh& m, const SkinFace& f) {
  Vec3 c;
  for (auto n : f.nodes) c += m.nodes.position(n) * 0.25;
  return c;
}

Vec3 normal(const Mesh& m, const SkinFace& f) {
  const Vec3 a = m.nodes.position(f.nodes[0]), b = m.nodes.position(f.nodes[1]),
             c = m.nodes.position(f.nodes[2]), d = m.nodes.position(f.nodes[3]);
  return normalized(cross(c - a, d - b));
}

TEST(Skin, BoxHasOutwardExteriorFacesWithElementThickness) {
  Mesh mesh;
  add_box(mesh, 7, 2, 3, 4, {0, 0, 0}, {0.5, 0.25, 0.1});
  const auto faces = exterior_faces(mesh, false);
  // Exterior faces of an nx*ny*nz block: 2(nx ny + ny nz + nz nx) = 2(6 + 12 + 8) = 52.
  ASSERT_EQ(faces.size(), 52u);
  const Vec3 body_centre{0.5, 0.375, 0.2};
  for (const SkinFace& f : faces) {
    EXPECT_EQ(f.part, 7);
    const Vec3 n = normal(mesh, f);
    const Vec3 c = centroid(mesh, f);
    EXPECT_GT(dot(n, c - body_centre), 0.0) << "face of hex " << f.solid << " points inward";
    // Thickness = element edge along the normal (hx, hy or hz).
    const double expected = std::abs(n.x) * 0.5 + std::abs(n.y) * 0.25 + std::abs(n.z) * 0.1;
    EXPECT_NEAR(f.thickness, expected, 1e-12);
  }
}

TEST(Skin, HexVolumeAndQuadAreaOfAParallelepiped) {
  Mesh mesh;
  add_box(mesh, 1, 1, 1, 1, {0, 0, 0}, {2.0, 3.0, 0.5});
  // Shear the top face: a parallelepiped keeps volume base * height = 6 * 0.5 = 3.
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) mesh.nodes.x[i] += 0.7 * mesh.nodes.z[i];
  EXPECT_NEAR(hex_volume(mesh.nodes, mesh.hexes[0]), 3.0, 1e-12);
  EXPECT_NEAR(quad_area(mesh.nodes, {0, 1, 2, 3}), 6.0, 1e-12);
}

TEST(Skin, MergedPartsOnlyExposeTheirInterfaceWithMerge) {
  Mesh mesh;
  add_box(mesh, 1, 1, 1, 1, {0, 0, 0}, {1, 1, 1});
  add_box(mesh, 2, 1, 1, 1, {0, 0, 1}, {1, 1, 1});  // stacked on top, sharing 4 nodes
  ASSERT_EQ(mesh.nodes.size(), 12u);
  const std::int64_t part1[] = {1};
  const std::int64_t both[] = {1, 2};
  // Without merge the shared face is interior: each part shows its 5 free faces.
  EXPECT_EQ(exterior_faces(mesh, part1, false).size(), 5u);
  EXPECT_EQ(exterior_faces(mesh, both, false).size(), 10u);
  // With merge the shared face counts once for each selected side, each oriented outward
  // from its own hex.
  const auto one = exterior_faces(mesh, part1, true);
  ASSERT_EQ(one.size(), 6u);
  const auto all = exterior_faces(mesh, both, true);
  ASSERT_EQ(all.size(), 12u);
  int up = 0, down = 0;
  for (const SkinFace& f : all) {
    if (std::abs(centroid(mesh, f).z - 1.0) > 1e-12) continue;
    const Vec3 n = normal(mesh, f);
    if (f.part == 1) { EXPECT_NEAR(n.z, 1.0, 1e-12); ++up; }
    if (f.part == 2) { EXPECT_NEAR(n.z, -1.0, 1e-12); ++down; }
  }
  EXPECT_EQ(up, 1);
  EXPECT_EQ(down, 1);
}

TEST(Skin, InvertedHexIsAnInputError) {
  Mesh mesh;
  add_box(mesh, 1, 1, 1, 1, {0, 0, 0}, {1, 1, 1});
  const Hex8 h = mesh.hexes[0];
  mesh.hexes[0] = {h[4], h[5], h[6], h[7], h[0], h[1], h[2], h[3]};  // top and bottom swapped: mirrored
  EXPECT_THROW(exterior_faces(mesh, false), InputError);
}

// Every cell type: the skin of a box of 2 x 3 x 2 cells whose inner grid nodes are moved by
// random fractions of a cell (fixed seed; the box's faces stay plane). Reference values are the
// box's own: the facets close (vector areas sum to 0), cover the faces (their areas sum to
// 2(ab + bc + ca)), enclose its volume (divergence theorem, (1/3) sum of x_c . A, exact for plane
// facets), and point out of it; every facet's nodes lie on the face it names, and its thickness
// is its cell's volume over that face's area.
class SkinOfCells : public ::testing::TestWithParam<CellType> {};

TEST_P(SkinOfCells, ClosesCoversAndEnclosesTheBox) {
  const CellType type = GetParam();
  const Vec3 size{1.0, 1.5, 0.8};
  std::uint64_t seed = 12345;
  const auto random = [&seed] {  // in [-0.5, 0.5)
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
  };
  const auto move = [&](int i, int j, int k, Vec3 p) {
    if (i == 0 || j == 0 || k == 0 || i == 2 || j == 3 || k == 2) return p;
    return p + Vec3{0.3 * random() * 0.5, 0.3 * random() * 0.5, 0.3 * random() * 0.4};
  };
  const test::CellGrid g = test::cell_grid(type, 2, 3, 2, size, move);
  Mesh mesh;
  mesh.nodes = g.nodes;
  for (std::size_t c = 0; c < g.cells.size(); ++c) {
    const auto id = static_cast<std::int64_t>(c) + 1;
    if (type == CellType::hex8) {
      Hex8 h;
      std::copy(g.cells[c].begin(), g.cells[c].end(), h.begin());
      mesh.add_hex(id, 3, h);
    } else {
      mesh.add_cell(type, id, 3, g.cells[c]);
    }
  }
  const auto faces = exterior_faces(mesh, false);
  const CellTopology& t = topology(type);
  // Boundary faces per cube face: 1 (hexahedra), 2 triangles (tetrahedra, and the wedges' ends);
  // the wedges' sides are quadrilaterals.
  const int facets_per_face = static_cast<int>(linear_facets(t.faces[0].type).size());
  const int cube_faces = 2 * (2 * 3 + 3 * 2 + 2 * 2);
  std::size_t expected = 0;
  if (t.corners == 8) expected = static_cast<std::size_t>(cube_faces * facets_per_face);
  if (t.corners == 4) expected = static_cast<std::size_t>(2 * cube_faces * facets_per_face);
  if (type == CellType::wedge6) expected = 2 * 2 * 3 * 2 + 2 * (2 * 2 + 3 * 2);  // ends, sides
  EXPECT_EQ(faces.size(), expected);
  Vec3 closure;
  double area = 0.0, volume = 0.0;
  const Vec3 centre = size * 0.5;
  for (const SkinFace& f : faces) {
    const Vec3 a = mesh.nodes.position(f.nodes[0]), b = mesh.nodes.position(f.nodes[1]),
               c = mesh.nodes.position(f.nodes[2]), d = mesh.nodes.position(f.nodes[3]);
    const Vec3 vector_area = cross(c - a, d - b) * 0.5;  // (a, b, c, c) for a triangle
    closure += vector_area;
    area += norm(vector_area);
    const Vec3 xc = f.nodes[2] == f.nodes[3] ? (a + b + c) / 3.0 : (a + b + c + d) * 0.25;
    volume += dot(xc, vector_area) / 3.0;
    EXPECT_GT(dot(vector_area, xc - centre), 0.0) << "a facet of cell " << f.solid << " points in";
    // The facet lies on the face it names, and its thickness is volume / face area.
    const SolidRef cell = mesh.solid(static_cast<std::size_t>(f.solid));
    const FaceTopology& face = t.faces[static_cast<std::size_t>(f.face)];
    std::vector<double> x, X;
    std::vector<std::int32_t> on_face;
    for (int k = 0; k < face.size(); ++k) {
      on_face.push_back(cell.nodes[static_cast<std::size_t>(face.nodes[k])]);
      const Vec3 p = mesh.nodes.position(on_face.back());
      x.insert(x.end(), {p.x, p.y, p.z});
    }
    for (const std::int32_t n : cell.nodes) {
      const Vec3 p = mesh.nodes.position(n);
      X.insert(X.end(), {p.x, p.y, p.z});
    }
    for (const std::int32_t n : f.nodes)
      EXPECT_NE(std::find(on_face.begin(), on_face.end(), n), on_face.end());
    EXPECT_NEAR(f.thickness, cell_volume(type, X) / face_area(face.type, x), 1e-12);
  }
  EXPECT_NEAR(norm(closure), 0.0, 1e-12);
  EXPECT_NEAR(area, 2.0 * (size.x * size.y + size.y * size.z + size.z * size.x), 1e-12);
  EXPECT_NEAR(volume, size.x * size.y * size.z, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Types, SkinOfCells, ::testing::ValuesIn(kCellTypes),
                         [](const ::testing::TestParamInfo<CellType>& p) {
                           return std::string(topology(p.param).name);
                         });

}  // namespace
}  // namespace abut
