// *NODE, *ELEMENT_SOLID, *ELEMENT_SHELL, *COMPONENT_BOX, *COMPONENT_SPHERE, *COMPONENT_CYLINDER,
// *COMPONENT_SHELL_PLATE, *COMPONENT_SHELL_TUBE, *CHANGE_P-ORDER, *SMOOTH_MESH,
// *MERGE_DUPLICATED_NODES.
#include <algorithm>

#include "abut/mesh/generators.hpp"
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

Vec3 point(const Row& r, std::size_t first) {
  return {r.number(first), r.number(first + 1), r.number(first + 2)};
}

// Component line 1 starts `coid, pid`: the component id is checked for uniqueness.
std::int64_t component_part(DeckReader& d, const Row& r) {
  d.claim_id("component", d.other_id(r, 0), r.where(0));
  return d.part_id(r, 1);
}

int element_count(const Row& r, std::size_t i) {
  const std::int64_t n = r.integer(i);
  r.require(n >= 1 && n <= 100000, i, "expected a number of elements in [1, 100000]");
  return static_cast<int>(n);
}

// Every other *INCLUDE placement turns a sphere into an ellipsoid, which a component cannot be.
double uniform_scale(const DeckReader& d, const SourceLocation& where, const std::string& shape) {
  const auto s = d.frame().transform.uniform_scale();
  if (!s) {
    throw InputError(
        where, "a " + shape +
                   " inside an *INCLUDE with unequal scale factors is not supported yet by abut");
  }
  return *s;
}

std::optional<IdReference> region(const DeckReader& d, const Row& r, std::size_t i) {
  if (const auto gid = d.optional_other_id(r, i)) return IdReference{*gid, r.where(i)};
  return std::nullopt;
}

}  // namespace

void read_node(DeckReader& d, Block& b) {
  while (!b.done()) {
    const Row r = b.row({"nid", "x", "y", "z", "bc"});
    const std::uint8_t fixed = parse_dof_mask(r, 4);
    if (fixed != 0) d.require_unrotated(r.where(4), "a nodal constraint");
    d.add_node(d.node_id(r, 0), d.frame().transform.point(point(r, 1)), fixed, r.where());
  }
}

// The degenerate forms of an 8-node row (LS-DYNA's convention, Keyword User's Manual,
// *ELEMENT_SOLID): n4 = n5 = n6 = n7 = n8 is the tetrahedron n1 n2 n3 n4; n5 = n6 and n7 = n8 the
// pentahedron whose triangles are n1 n2 n5 and n4 n3 n7 (of a hexahedron of positive volume
// with its top face collapsed to the edge 5-7). Each becomes the C3D4 or C3D6 of those nodes, in
// that order's orientation. Returns false for a plain hexahedron.
bool add_degenerate_solid(DeckReader& d, const Row& r, const std::array<std::int64_t, 8>& n) {
  const auto distinct = [](std::vector<std::int64_t> v) {
    std::sort(v.begin(), v.end());
    return std::adjacent_find(v.begin(), v.end()) == v.end();
  };
  if (n[4] == n[3] && n[5] == n[3] && n[6] == n[3] && n[7] == n[3]) {
    r.require(distinct({n[0], n[1], n[2], n[3]}), 2,
              "a tetrahedron (n4 = n5 = n6 = n7 = n8) needs four different nodes n1-n4");
    d.add_cell(d.element_id(r, 0), d.part_id(r, 1), CellType::tet4, {n[0], n[1], n[2], n[3]},
               {1, 2, 3, 4}, "*ELEMENT_SOLID", r.where());
    return true;
  }
  if (n[5] == n[4] && n[7] == n[6]) {
    r.require(distinct({n[0], n[1], n[2], n[3], n[4], n[6]}), 2,
              "a pentahedron (n5 = n6, n7 = n8) needs six different nodes n1-n5, n7");
    d.add_cell(d.element_id(r, 0), d.part_id(r, 1), CellType::wedge6,
               {n[0], n[4], n[1], n[3], n[6], n[2]}, {1, 5, 2, 4, 7, 3}, "*ELEMENT_SOLID",
               r.where());
    return true;
  }
  return false;
}

// *ELEMENT_SOLID_TET10 and *ELEMENT_SOLID_H20: eid, pid and the nodes in the Abaqus/CalculiX
// order of C3D10 and C3D20 (mesh/topology.hpp).
void read_element_cells(DeckReader& d, Block& b, CellType type, const char* keyword) {
  const int count = topology(type).nodes;
  std::vector<std::string> names = {"eid", "pid"};
  for (int k = 1; k <= count; ++k) names.push_back("n" + std::to_string(k));
  while (!b.done()) {
    const Row r = b.row(names);
    std::vector<std::int64_t> nodes;
    std::vector<std::size_t> fields;
    for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
      nodes.push_back(d.node_id(r, k + 2));
      fields.push_back(k + 1);
    }
    for (std::size_t k = 1; k < nodes.size(); ++k)
      for (std::size_t j = 0; j < k; ++j)
        r.require(nodes[k] != nodes[j], k + 2,
                  "node " + std::to_string(nodes[k]) + " repeats n" + std::to_string(j + 1) +
                      ": the nodes of a " + std::string(element_label(type)) +
                      " element are all different");
    d.add_cell(d.element_id(r, 0), d.part_id(r, 1), type, std::move(nodes), std::move(fields),
               keyword, r.where());
  }
}

void read_element_solid(DeckReader& d, Block& b) {
  while (!b.done()) {
    const Row r = b.row({"eid", "pid", "n1", "n2", "n3", "n4", "n5", "n6", "n7", "n8"});
    std::array<std::int64_t, 8> nodes{};
    for (std::size_t k = 0; k < 8; ++k) nodes[k] = d.node_id(r, k + 2);
    if (add_degenerate_solid(d, r, nodes)) continue;
    // A mirrored hex is inside out; exchanging its bottom and top faces turns it right side out.
    if (d.frame().transform.mirrors()) std::rotate(nodes.begin(), nodes.begin() + 4, nodes.end());
    d.add_element(d.element_id(r, 0), d.part_id(r, 1), nodes, r.where());
  }
}

void read_element_solid_tet10(DeckReader& d, Block& b) {
  read_element_cells(d, b, CellType::tet10, "*ELEMENT_SOLID_TET10");
}

void read_element_solid_h20(DeckReader& d, Block& b) {
  read_element_cells(d, b, CellType::hex20, "*ELEMENT_SOLID_H20");
}

void read_element_shell(DeckReader& d, Block& b) {
  while (!b.done()) {
    const Row r = b.row({"eid", "pid", "n1", "n2", "n3", "n4"});
    std::array<std::int64_t, 4> nodes{};
    for (std::size_t k = 0; k < 3; ++k) nodes[k] = d.node_id(r, k + 2);
    // A triangle: n4 empty, 0 or n3.
    const bool triangle = !r.given(5) || r.integer(5) == 0;
    nodes[3] = triangle ? nodes[2] : d.node_id(r, 5);
    for (std::size_t k = 1; k < 4; ++k) {
      for (std::size_t j = 0; j < k; ++j) {
        const bool triangle_form = k == 3 && j == 2;
        r.require(nodes[k] != nodes[j] || triangle_form, k + 2,
                  "node " + std::to_string(nodes[k]) + " repeats n" + std::to_string(j + 1) +
                      ": a shell has 4 different nodes, or 3 with n4 empty, 0 or equal to n3 "
                      "(triangle)");
      }
    }
    // Mirrored, the node order is reversed so that the shell normal is the mirror image of the
    // given one (a closed surface keeps its outward normals).
    if (d.frame().transform.mirrors()) {
      nodes = nodes[3] == nodes[2] ? std::array{nodes[0], nodes[2], nodes[1], nodes[1]}
                                   : std::array{nodes[0], nodes[3], nodes[2], nodes[1]};
    }
    d.add_shell(d.element_id(r, 0), d.part_id(r, 1), nodes, r.where());
  }
}

void read_component_box(DeckReader& d, Block& b) {
  b.title();
  const Row r1 = b.row({"coid", "pid", "N_x", "N_y", "N_z", "csysid"});
  const Row r2 = b.row({"x1", "y1", "z1", "x2", "y2", "z2"});
  BoxComponent c;
  c.part_id = component_part(d, r1);
  c.nx = element_count(r1, 2);
  c.ny = element_count(r1, 3);
  c.nz = element_count(r1, 4);
  r1.global_coordinates_only(5);
  if (!d.frame().transform.axis_aligned()) {
    throw InputError(b.where(),
                     "a box inside an *INCLUDE that rotates its axes is not supported yet by abut");
  }
  const Vec3 p1 = d.frame().transform.point(point(r2, 0));
  const Vec3 p2 = d.frame().transform.point(point(r2, 3));
  for (int k = 0; k < 3; ++k) {
    r2.require(
        p1[k] != p2[k], static_cast<std::size_t>(k + 3),
        "expected a box of non-zero size along " + std::string(1, static_cast<char>('x' + k)));
    c.corner1[k] = std::min(p1[k], p2[k]);
    c.corner2[k] = std::max(p1[k], p2[k]);
  }
  d.generate([&] { generate_box(d.model.mesh, c); }, b.where(), box_size(c));
}

void read_component_sphere(DeckReader& d, Block& b) {
  b.title();
  const Row r1 = b.row({"coid", "pid", "N", "N_c", "csysid", "alpha_c"});
  const Row r2 = b.row({"x0", "y0", "z0", "R1", "R2"});
  SphereComponent c;
  c.part_id = component_part(d, r1);
  c.density = element_count(r1, 2);
  // N_c only counts elements around a sector (alpha_c < 360), which abut does not build.
  if (r1.given(3)) element_count(r1, 3);
  r1.global_coordinates_only(4);
  r1.unsupported_unless(5, 360.0, "a sphere sector (alpha_c other than 360)");
  const double r_1 = r2.number(3);
  r2.require(r_1 > 0.0, 3, "expected a radius > 0");
  const double r_2 = r2.number_or(4, 0.0);
  r2.require(r_2 == 0.0 || r_2 > r_1, 4,
             "expected 0 (solid sphere) or an outer radius > R1 (hollow sphere)");
  const double s = uniform_scale(d, b.where(), "sphere");
  c.centre = d.frame().transform.point(point(r2, 0));
  c.inner_radius = r_2 > 0.0 ? s * r_1 : 0.0;
  c.outer_radius = s * (r_2 > 0.0 ? r_2 : r_1);
  d.generate([&] { generate_sphere(d.model.mesh, c); }, b.where(), sphere_size(c));
}

void read_component_cylinder(DeckReader& d, Block& b) {
  b.title();
  const Row r1 = b.row({"coid", "pid", "N_1", "N_2", "csysid", "symmetry"});
  const Row r2 = b.row({"x1", "y1", "z1", "x2", "y2", "z2", "R1", "R2"});
  CylinderComponent c;
  c.part_id = component_part(d, r1);
  c.n_axial = element_count(r1, 2);
  c.density = element_count(r1, 3);
  r1.global_coordinates_only(4);
  const std::int64_t symmetry = r1.integer_or(5, 0);
  r1.require(symmetry >= 0 && symmetry <= 2, 5, "expected 0 (full), 1 (half) or 2 (quarter)");
  c.symmetry = static_cast<int>(symmetry);
  if (c.symmetry != 0) d.require_unrotated(r1.where(5), "a half or quarter cylinder");
  const double r_1 = r2.number(6);
  r2.require(r_1 > 0.0, 6, "expected a radius > 0");
  const double r_2 = r2.number_or(7, r_1);
  r2.require(r_2 > 0.0, 7, "expected a radius > 0 (empty: R1)");
  const Vec3 e1 = point(r2, 0);
  const Vec3 e2 = point(r2, 3);
  r2.require(norm(e2 - e1) > 0.0, 3, "expected the second end centre to differ from the first");
  const double s = uniform_scale(d, b.where(), "cylinder");
  c.end1 = d.frame().transform.point(e1);
  c.end2 = d.frame().transform.point(e2);
  c.radius1 = s * r_1;
  c.radius2 = s * r_2;
  d.generate([&] { generate_cylinder(d.model.mesh, c); }, b.where(), cylinder_size(c));
}

void read_component_shell_plate(DeckReader& d, Block& b) {
  b.title();
  const Row r1 = b.row({"coid", "pid", "n1", "n2"});
  const Row r2 = b.row({"x0", "y0", "z0", "x1", "y1", "z1"});
  const Row r3 = b.row({"x2", "y2", "z2"});
  ShellPlateComponent c;
  c.part_id = component_part(d, r1);
  c.n1 = element_count(r1, 2);
  c.n2 = element_count(r1, 3);
  c.p0 = d.frame().transform.point(point(r2, 0));
  c.p1 = d.frame().transform.point(point(r2, 3));
  c.p2 = d.frame().transform.point(point(r3, 0));
  // Mirrored, p1 and p2 exchange so that the normal is the mirror image of the given one.
  if (d.frame().transform.mirrors()) {
    std::swap(c.p1, c.p2);
    std::swap(c.n1, c.n2);
  }
  const double n1 = c.n1, n2 = c.n2;
  d.generate([&] { generate_shell_plate(d.model.mesh, c); }, b.where(),
             {n1 * n2, (n1 + 1) * (n2 + 1)});
}

void read_component_shell_tube(DeckReader& d, Block& b) {
  b.title();
  const Row r1 = b.row({"coid", "pid", "n_axial", "n_circ", "shape"});
  const Row r2 = b.row({"x1", "y1", "z1", "x2", "y2", "z2"});
  const Row r3 = b.row({"r"});
  ShellTubeComponent c;
  c.part_id = component_part(d, r1);
  c.n_axial = element_count(r1, 2);
  c.n_circ = element_count(r1, 3);
  c.section = word_choice<TubeSection>(
      r1, 4, TubeSection::Round, {{"ROUND", TubeSection::Round}, {"SQUARE", TubeSection::Square}},
      "ROUND or SQUARE");
  if (c.section == TubeSection::Square) {
    r1.require(c.n_circ % 4 == 0, 3,
               "a SQUARE tube needs a multiple of 4 elements around (a node at each corner)");
  } else {
    r1.require(c.n_circ >= 3, 3, "a ROUND tube needs at least 3 elements around");
  }
  const Vec3 e1 = point(r2, 0);
  const Vec3 e2 = point(r2, 3);
  r2.require(norm(e2 - e1) > 0.0, 3, "expected the second end centre to differ from the first");
  const double radius = r3.number(0);
  r3.require(radius > 0.0, 0, "expected a radius > 0");
  const double s = uniform_scale(d, b.where(), "shell tube");
  c.end1 = d.frame().transform.point(e1);
  c.end2 = d.frame().transform.point(e2);
  c.radius = s * radius;
  // The section's frame is chosen in the included file's own axes and then placed with it, so a
  // rotated include rotates a square tube with its content.
  c.side_direction = d.frame().transform.linear(tube_side_direction(normalized(e2 - e1), {}));
  const double n_axial = c.n_axial, n_circ = c.n_circ;
  d.generate([&] { generate_shell_tube(d.model.mesh, c); }, b.where(),
             {n_axial * n_circ, (n_axial + 1) * n_circ});
}

void read_change_p_order(DeckReader& d, Block& b) {
  if (b.done()) throw InputError(b.where(), "missing data line: expected entype, enid, order, gid");
  while (!b.done()) {
    const Row r = b.row({"entype", "enid", "order", "gid"});
    PendingOrder o;
    o.entity = d.entity(r, 0, 1, {EntityType::Part, EntityType::PartSet, EntityType::All});
    const std::int64_t order = r.integer(2);
    r.require(order >= 1 && order <= 3, 2, "expected an order of 1, 2 or 3");
    o.order = static_cast<int>(order);
    o.region = region(d, r, 3);
    d.orders.push_back(o);
  }
}

void read_change_to_tetrahedra(DeckReader& d, Block& b) {
  if (b.done()) throw InputError(b.where(), "missing data line: expected entype, enid, nodes, gid");
  while (!b.done()) {
    const Row r = b.row({"entype", "enid", "nodes", "gid"});
    PendingTetrahedra t;
    t.entity = d.entity(r, 0, 1, {EntityType::Part, EntityType::PartSet, EntityType::All});
    const std::int64_t nodes = r.integer(2);
    r.require(nodes == 4 || nodes == 10, 2, "expected 4 or 10 (nodes per tetrahedron)");
    t.type = nodes == 4 ? CellType::tet4 : CellType::tet10;
    t.region = region(d, r, 3);
    d.tetrahedra.push_back(t);
  }
}

void read_smooth_mesh(DeckReader& d, Block& b) {
  b.title();
  do {
    const Row r = b.row({"entype", "enid", "alpha_max", "internal", "gid"});
    PendingSmoothing s;
    s.entity = d.entity(r, 0, 1, {EntityType::Part, EntityType::PartSet, EntityType::All});
    s.max_angle = r.number(2);
    r.require(s.max_angle > 0.0 && s.max_angle <= 180.0, 2,
              "expected an angle in (0, 180] degrees");
    s.internal = r.flag(3);
    s.region = region(d, r, 4);
    d.smoothing.push_back(s);
    // Optional line 2 holds only csysid (a number); a new line 1 starts with an entity type.
    const auto next = b.peek_fields();
    if (!next.empty() && parse_number(next[0])) b.row({"csysid"}).global_coordinates_only(0);
  } while (!b.done());
}

void read_merge_duplicated_nodes(DeckReader& d, Block& b) {
  if (b.done()) {
    throw InputError(b.where(),
                     "missing data line: expected entype_s, enid_s, entype_m, enid_m, tol, refine");
  }
  while (!b.done()) {
    const Row r = b.row({"entype_s", "enid_s", "entype_m", "enid_m", "tol", "refine"});
    const std::initializer_list<EntityType> nodal = {EntityType::Node, EntityType::NodeSet,
                                                     EntityType::Part, EntityType::PartSet,
                                                     EntityType::All};
    PendingMerge m;
    m.secondary = d.entity(r, 0, 1, nodal);
    m.main = d.entity(r, 2, 3, nodal);
    if (r.given(4)) {
      const double tol = r.number(4);
      r.require(tol > 0.0, 4, "expected a distance tol > 0");
      // A length: scaled with the included file's content, which must keep its shape.
      m.tolerance = tol * uniform_scale(d, r.where(4), "merge tolerance");
    }
    r.unsupported_unless(5, 0.0, "refine (refining the mesh where nodes are merged)");
    m.where = r.where();
    d.merges.push_back(m);
    d.entity_references.push_back(m.secondary);
    d.entity_references.push_back(m.main);
  }
}

}  // namespace abut::deck
