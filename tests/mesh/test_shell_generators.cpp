// *COMPONENT_SHELL_PLATE and *COMPONENT_SHELL_TUBE: counts, ids, areas against closed forms,
// outward normals, and the tube closed around without duplicate nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include "abut/core/error.hpp"
#include "abut/mesh/shell_generators.hpp"

namespace abut {
namespace {

double total_area(const Mesh& mesh) {
  double a = 0.0;
  for (const Quad4& q : mesh.shells) a += norm(shell_area_vector(mesh.nodes, q));
  return a;
}

Vec3 centre(const Mesh& mesh, const Quad4& q) {
  Vec3 c;
  for (const std::int32_t n : q) c += 0.25 * mesh.nodes.position(static_cast<std::size_t>(n));
  return c;
}

// Every edge of a closed tube is shared by two shells that run along it in opposite directions
// (consistent orientation), except the edges of the two end sections.
std::size_t free_edges(const Mesh& mesh) {
  std::map<std::pair<std::int32_t, std::int32_t>, int> directed;
  for (const Quad4& q : mesh.shells)
    for (int k = 0; k < 4; ++k) ++directed[{q[k], q[(k + 1) % 4]}];
  std::size_t free = 0;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge used twice in the same direction: orientations disagree";
    if (!directed.count({edge.second, edge.first})) ++free;
  }
  return free;
}

TEST(GenerateShellPlate, ParallelogramAreaCountsAndNormal) {
  Mesh mesh;
  ShellPlateComponent c;
  c.part_id = 3;
  c.n1 = 4;
  c.n2 = 3;
  c.p0 = {1, 0, 0};
  c.p1 = {3, 0, 1};
  c.p2 = {1.5, 2, 0};
  generate_shell_plate(mesh, c);
  EXPECT_EQ(mesh.nodes.size(), 5u * 4u);
  ASSERT_EQ(mesh.shell_count(), 12u);
  const Vec3 normal = cross(c.p1 - c.p0, c.p2 - c.p0);
  EXPECT_NEAR(total_area(mesh), norm(normal), 1e-12);
  for (std::size_t s = 0; s < mesh.shell_count(); ++s) {
    EXPECT_EQ(mesh.shell_part[s], 3);
    EXPECT_FALSE(is_triangle(mesh.shells[s]));
    const Vec3 n = shell_area_vector(mesh.nodes, mesh.shells[s]);
    EXPECT_NEAR(dot(n, normal), norm(n) * norm(normal), 1e-12);  // parallel, same sense
  }
  // The far corner p1 + p2 - p0 is a node.
  const Vec3 far = c.p1 + c.p2 - c.p0;
  bool found = false;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    found = found || norm(mesh.nodes.position(i) - far) < 1e-12;
  EXPECT_TRUE(found);
}

TEST(GenerateShellPlate, IdsContinueAfterHexesAndShells) {
  Mesh mesh;
  mesh.nodes.add(40, {0, 0, 0});
  mesh.add_hex(70, 1, Hex8{});
  ShellPlateComponent c;
  c.p1 = {1, 0, 0};
  c.p2 = {0, 1, 0};
  generate_shell_plate(mesh, c);
  EXPECT_EQ(mesh.nodes.id[1], 41);
  EXPECT_EQ(mesh.shell_id.front(), 71);
  generate_shell_plate(mesh, c);
  EXPECT_EQ(mesh.shell_id.back(), 72);
  EXPECT_EQ(mesh.nodes.id.back(), 48);
}

TEST(GenerateShellPlate, RejectsParallelEdgesAndCounts) {
  Mesh mesh;
  ShellPlateComponent c;
  c.p1 = {1, 0, 0};
  c.p2 = {2, 0, 0};
  EXPECT_THROW(generate_shell_plate(mesh, c), InputError);
  c.p2 = {0, 1, 0};
  c.n2 = 0;
  EXPECT_THROW(generate_shell_plate(mesh, c), InputError);
}

ShellTubeComponent tube(TubeSection section, int n_circ) {
  ShellTubeComponent c;
  c.part_id = 2;
  c.n_axial = 5;
  c.n_circ = n_circ;
  c.section = section;
  c.end1 = {0.5, -1, 2};
  c.end2 = {1.5, 2, 0};  // an axis along no global direction
  c.radius = 0.3;
  return c;
}

TEST(GenerateShellTube, RoundTubeIsAClosedPolygonWithOutwardNormals) {
  Mesh mesh;
  const ShellTubeComponent c = tube(TubeSection::Round, 24);
  generate_shell_tube(mesh, c);
  const double length = norm(c.end2 - c.end1);
  EXPECT_EQ(mesh.nodes.size(), 24u * 6u);  // no node repeated where the tube closes
  ASSERT_EQ(mesh.shell_count(), 24u * 5u);
  const double polygon = 24 * std::sin(std::numbers::pi / 24) / std::numbers::pi;
  EXPECT_NEAR(total_area(mesh), 2 * std::numbers::pi * c.radius * length * polygon, 1e-12);
  EXPECT_EQ(free_edges(mesh), 2u * 24u);  // only the two end sections
  const Vec3 axis = (c.end2 - c.end1) / length;
  for (const Quad4& q : mesh.shells) {
    const Vec3 m = centre(mesh, q);
    const Vec3 radial = (m - c.end1) - dot(m - c.end1, axis) * axis;
    EXPECT_GT(dot(shell_area_vector(mesh.nodes, q), radial), 0.0) << "normal points inward";
  }
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const Vec3 d = mesh.nodes.position(i) - c.end1;
    EXPECT_NEAR(norm(d - dot(d, axis) * axis), c.radius, 1e-12);
  }
}

TEST(GenerateShellTube, SquareTubeHasItsCornersAndOutwardNormals) {
  Mesh mesh;
  const ShellTubeComponent c = tube(TubeSection::Square, 12);
  generate_shell_tube(mesh, c);
  const double length = norm(c.end2 - c.end1);
  EXPECT_EQ(mesh.nodes.size(), 12u * 6u);
  EXPECT_NEAR(total_area(mesh), 8 * c.radius * length, 1e-12);
  EXPECT_EQ(free_edges(mesh), 2u * 12u);
  const Vec3 axis = (c.end2 - c.end1) / length;
  std::size_t corners = 0;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const Vec3 d = mesh.nodes.position(i) - c.end1;
    const double r = norm(d - dot(d, axis) * axis);
    EXPECT_LE(r, std::sqrt(2.0) * c.radius * (1 + 1e-12));
    EXPECT_GE(r, c.radius * (1 - 1e-12));
    if (std::abs(r - std::sqrt(2.0) * c.radius) < 1e-12) ++corners;
  }
  EXPECT_EQ(corners, 4u * 6u);
  for (const Quad4& q : mesh.shells) {
    const Vec3 m = centre(mesh, q);
    const Vec3 radial = (m - c.end1) - dot(m - c.end1, axis) * axis;
    const Vec3 n = shell_area_vector(mesh.nodes, q);
    EXPECT_GT(dot(n, radial), 0.0);
    EXPECT_NEAR(std::abs(dot(n, radial)), norm(n) * c.radius, 1e-12);  // normal to a side
  }
}

TEST(GenerateShellTube, SideDirectionTurnsTheSquare) {
  Mesh mesh;
  ShellTubeComponent c = tube(TubeSection::Square, 4);
  c.end1 = {0, 0, 0};
  c.end2 = {0, 0, 1};
  c.side_direction = {1, 1, 0};
  generate_shell_tube(mesh, c);
  // The first node is the corner radius * (e1 - e2) with e1 = (1, 1, 0) / sqrt(2).
  EXPECT_NEAR(mesh.nodes.x[0], c.radius * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(mesh.nodes.y[0], 0.0, 1e-12);
}

TEST(GenerateShellTube, RejectsBadCountsRadiusAndAxis) {
  Mesh mesh;
  ShellTubeComponent c = tube(TubeSection::Square, 10);
  EXPECT_THROW(generate_shell_tube(mesh, c), InputError);  // not a multiple of 4
  c = tube(TubeSection::Round, 2);
  EXPECT_THROW(generate_shell_tube(mesh, c), InputError);
  c = tube(TubeSection::Round, 8);
  c.radius = 0.0;
  EXPECT_THROW(generate_shell_tube(mesh, c), InputError);
  c = tube(TubeSection::Round, 8);
  c.end2 = c.end1;
  EXPECT_THROW(generate_shell_tube(mesh, c), InputError);
  EXPECT_EQ(mesh.shell_count(), 0u);
}

}  // namespace
}  // namespace abut
