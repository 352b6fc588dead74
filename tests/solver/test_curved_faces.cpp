// Contact on the faces of quadratic solids (curved_faces.hpp): a face of n x n facets whose
// corners off the face's nodes are dependent nodes. A uniform contact pressure p on such a face
// (the face pressed flat into a large plate, surface to surface) must load the face's nodes with
// the face's consistent load f_a = p int N_a dA (face_pressure_forces of shape_functions.hpp,
// exact: the reference, computed from the face's own shape functions). With the facets' faces
// (facet_parent.hpp), as the static solver builds them, the overlaps integrate the N_a themselves:
// to round-off for every n. Through the dependent corners alone the facets interpolate each N_a
// bilinearly (linearly on triangles), an O(h^2) error: the largest nodal error must fall at least
// 3 times per halving of the facets (4 times asymptotically), and the total force is p A for
// every n (the interpolants sum to 1). The faces are not affine images of their reference (a
// general quadrilateral; triangles of a split cube), so that no cancellation of a regular grid
// helps.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "../element/cell_grid.hpp"
#include "abut/contact/static_contact.hpp"
#include "abut/mesh/shape_functions.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "abut/solver/curved_faces.hpp"

namespace abut {
namespace {

constexpr double kPenalty = 1.0e6, kDepth = 1.0e-3;  // p = 1000

// One cell of `type` over the general quadrilateral below (straight edges, not a parallelogram;
// `affine`: a parallelogram), z in [0, 1], and a plate whose top face is kDepth above z = 0 (into
// the cell's bottom).
Mesh pressed_cell(CellType type, bool affine) {
  const auto map = [affine](Vec3 p) {  // bilinear map of the unit square
    const double x = p.x, y = p.y;
    if (affine) return Vec3{1.2 * x + 0.3 * y, 0.1 * x + 0.9 * y, p.z};
    return Vec3{x * (1 - y) * 1.2 + x * y * 1.0 + (1 - x) * y * -0.1,
                x * y * 0.9 + (1 - x) * y * 1.1, p.z};
  };
  const test::CellGrid g = test::cell_grid(type, 1, 1, 1, {1.0, 1.0, 1.0}, {}, map);
  Mesh mesh;
  mesh.nodes = g.nodes;
  for (std::size_t c = 0; c < g.cells.size(); ++c)
    mesh.add_cell(type, static_cast<std::int64_t>(c) + 1, 1, g.cells[c]);
  Hex8 plate;
  const double xs[2] = {-1.0, 3.0}, zs[2] = {-1.0, kDepth};
  for (int k = 0; k < 2; ++k)
    for (int c = 0; c < 4; ++c) {
      const double x = xs[(c == 1 || c == 2) ? 1 : 0], y = xs[(c >= 2) ? 1 : 0];
      plate[static_cast<std::size_t>(4 * k + c)] =
          mesh.nodes.add(mesh.next_node_id(), {x, y, zs[k]});
    }
  mesh.add_hex(100, 2, plate);
  return mesh;
}

// The plate's nodes come after the cell's: its 8 are the last.
std::int32_t plate_first_node(const Mesh& mesh) {
  return static_cast<std::int32_t>(mesh.nodes.size()) - 8;
}

struct Loads {
  std::map<std::int32_t, double> contact, consistent;  // z forces on the cell's bottom nodes
  double total_contact = 0.0, total_consistent = 0.0;
};

Loads loads(CellType type, int divisions, bool with_faces, bool affine = false) {
  const Mesh mesh = pressed_cell(type, affine);
  std::vector<SkinFace> bottom, top;
  const std::int64_t cell_part[] = {1}, plate_part[] = {2};
  for (const SkinFace& f : exterior_faces(mesh, cell_part, false)) {
    bool on_bottom = true;
    for (const std::int32_t n : f.nodes) on_bottom = on_bottom && mesh.nodes.z[n] == 0.0;
    if (on_bottom) bottom.push_back(f);
  }
  for (const SkinFace& f : exterior_faces(mesh, plate_part, false))
    if (f.face == 1) top.push_back(f);  // S2: the plate's top
  Loads out;
  // The reference: each bottom face's consistent load.
  std::map<std::pair<std::int32_t, int>, bool> seen;
  for (const SkinFace& f : bottom) {
    if (!seen.emplace(std::make_pair(f.solid, f.face), true).second) continue;
    const SolidRef cell = mesh.solid(static_cast<std::size_t>(f.solid));
    const FaceTopology& face = topology(type).faces[static_cast<std::size_t>(f.face)];
    std::vector<double> x, force(3 * static_cast<std::size_t>(face.size()));
    for (int a = 0; a < face.size(); ++a) {
      const Vec3 p = mesh.nodes.position(cell.nodes[static_cast<std::size_t>(face.nodes[a])]);
      x.insert(x.end(), {p.x, p.y, p.z});
    }
    face_pressure_forces(face.type, x, kPenalty * kDepth, force);
    for (int a = 0; a < face.size(); ++a) {
      out.consistent[cell.nodes[static_cast<std::size_t>(face.nodes[a])]] +=
          force[3 * static_cast<std::size_t>(a) + 2];
      out.total_consistent += force[3 * static_cast<std::size_t>(a) + 2];
    }
  }
  CurvedFaces curved(mesh, divisions);
  const auto unit = [](const SkinFace&) { return 1.0; };
  std::vector<FacetParent> bottom_faces, top_faces;
  const std::vector<SkinFace> bottom_facets = curved.facets(bottom, &bottom_faces);
  const std::vector<SkinFace> top_facets = curved.facets(top, &top_faces);
  if (!with_faces) bottom_faces.clear(), top_faces.clear();
  const auto both = ContactSpec::ShellSides::Both;
  ContactSurface secondary = contact_surface(mesh, bottom_facets, unit, {}, both, bottom_faces);
  ContactSurface main = contact_surface(mesh, top_facets, unit, {}, both, top_faces);
  StaticContactSettings s;
  s.penalty = kPenalty;
  s.depth = 0.3;
  s.search_distance = 0.3;
  const ContactInput at{mesh.nodes.x, mesh.nodes.y, mesh.nodes.z, {}, {}, {}, 0.0, 0.0, {}};
  StaticContact contact(s, std::move(secondary), std::move(main), {}, at, curved.dependents());
  contact.evaluate(at);
  for (const StaticContactElement& e : contact.elements()) {
    std::vector<double> force(3 * static_cast<std::size_t>(e.count));
    e.add_forces(force.data());
    for (int a = 0; a < e.count; ++a) {
      EXPECT_LT(e.nodes[a], static_cast<std::int32_t>(mesh.nodes.size()));  // host nodes only
      if (e.nodes[a] < plate_first_node(mesh)) {                            // a node of the cell
        out.contact[e.nodes[a]] += force[3 * static_cast<std::size_t>(a) + 2];
        out.total_contact += force[3 * static_cast<std::size_t>(a) + 2];
      }
    }
  }
  return out;
}

double largest_error(const Loads& l) {
  double error = 0.0, largest = 0.0;
  for (const auto& [node, f] : l.consistent) {
    const auto it = l.contact.find(node);
    error = std::max(error, std::abs((it == l.contact.end() ? 0.0 : it->second) - f));
    largest = std::max(largest, std::abs(f));
  }
  return error / largest;
}

class CurvedFaceLoads : public ::testing::TestWithParam<CellType> {};

// The static contact integrates the face's own shape functions over each overlap (the facets
// know their face): on a parallelogram face, the consistent load to round-off whatever the
// subdivision (the rule is exact there); on the general quadrilateral (and the tet10's faces,
// whose shared midside node the bilinear map takes off the straight diagonal) the plane's
// integrand is no polynomial: the error must be far below the corners' (at least 10 times).
TEST_P(CurvedFaceLoads, AreTheConsistentLoadWithTheFacesShapeFunctions) {
  for (const int n : {1, 2, 4}) {
    SCOPED_TRACE(n);
    const Loads exact = loads(GetParam(), n, true, true);
    EXPECT_NEAR(exact.total_contact, exact.total_consistent, 1e-9 * exact.total_consistent);
    EXPECT_LT(largest_error(exact), 1e-12);
    const Loads general = loads(GetParam(), n, true);
    EXPECT_NEAR(general.total_contact, general.total_consistent, 1e-9 * general.total_consistent);
    const double error = largest_error(general);
    std::cout << topology(GetParam()).name << " n = " << n
              << ", the face's shape functions: " << error << "\n";
    if (n > 1) {
      EXPECT_LT(10.0 * error, largest_error(loads(GetParam(), n, false)));
    }
  }
}

// Through the dependent corners alone (node-to-surface points, tied pairs): the interpolated
// shape functions, second order in the facet size.
TEST_P(CurvedFaceLoads, ConvergeToTheConsistentLoadAtSecondOrderThroughTheCorners) {
  double previous = 0.0;
  for (const int n : {2, 4, 8}) {
    SCOPED_TRACE(n);
    const Loads l = loads(GetParam(), n, false);
    EXPECT_NEAR(l.total_contact, l.total_consistent, 1e-9 * std::abs(l.total_consistent));
    const double error = largest_error(l);
    std::cout << topology(GetParam()).name << " n = " << n << ": largest nodal error " << error
              << " of the largest consistent nodal force\n";
    if (n > 2) {
      EXPECT_GT(previous / error, 3.0);
    }
    previous = error;
  }
}

INSTANTIATE_TEST_SUITE_P(Quadratic, CurvedFaceLoads,
                         ::testing::Values(CellType::hex20, CellType::tet10),
                         [](const ::testing::TestParamInfo<CellType>& p) {
                           return std::string(topology(p.param).name);
                         });

}  // namespace
}  // namespace abut
